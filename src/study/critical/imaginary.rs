//! Confirmation of a root of $\Delta_{n-1}$: is there a purely imaginary pair at $v_0$?

use super::approx::{approx_elem, approx_roots};
use super::roots::{rational_near, sign_at_root};
use crate::algebraic::{AlgebraicNumber, NfElem, NumberField};
use crate::error::Result;
use crate::field::Field;
use crate::poly::Poly;
use std::cmp::Ordering;

/// Is there a purely imaginary pair at $v_0$? `Some((omega, certified))` or `None` with the
/// reason.
pub(super) fn imaginary_pair_at(
    k: &NumberField,
    pk: &Poly<NumberField>,
    r: &AlgebraicNumber,
) -> Result<std::result::Result<(f64, bool), String>> {
    let cs = pk.coeffs();
    let even: Vec<NfElem> = cs.iter().step_by(2).cloned().collect();
    let odd: Vec<NfElem> = cs.iter().skip(1).step_by(2).cloned().collect();
    let e = Poly::new(k.clone(), even);
    let o = Poly::new(k.clone(), odd);
    let g = e.gcd(&o);
    let v0 = &rational_near(r)?;
    match g.degree() {
        None | Some(0) => Ok(Err("no pair adds up to zero".into())),
        Some(1) => {
            // u = x^2 = -g0/g1
            let g = g.monic();
            let u = k.neg(&g.coeff(0));
            match sign_at_root(k, &u, r)? {
                Ordering::Less => Ok(Ok(((-approx_elem(k, &u, v0)).sqrt(), true))),
                Ordering::Equal => Ok(Err("a double zero eigenvalue".into())),
                Ordering::Greater => Ok(Err(format!(
                    "a real pair +-{:.6}",
                    approx_elem(k, &u, v0).sqrt()
                ))),
            }
        }
        Some(_) => {
            let us = approx_roots(k, &g, v0)?;
            let scale = us.iter().map(|u| u.norm()).fold(1e-300, f64::max);
            match us
                .iter()
                .find(|u| u.re < -1e-9 * scale && u.im.abs() <= 1e-9 * scale)
            {
                Some(u) => Ok(Ok(((-u.re).sqrt(), false))),
                None => Ok(Err("pairs adding up to zero are not imaginary".into())),
            }
        }
    }
}
