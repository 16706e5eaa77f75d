//! Confirmation of a root $v_0$ of $\Delta_{n-1}$: is there a purely imaginary pair at $v_0$?
//!
//! With $P(x, v_0) = E(x^2) + x\,O(x^2)$, the pairs $\pm\lambda$ of eigenvalues are the
//! roots $u = \lambda^2$ of $g = \gcd(E, O)$ over $\mathbb{Q}(v_0)$; an imaginary pair
//! $\pm i\omega$ is a negative real root $u = -\omega^2$. The number of distinct negative
//! real roots of $g$ is decided exactly, by Sturm's theorem on $(-\infty, 0)$ with the
//! signs of the elements of $\mathbb{Q}(v_0)$ at the real embedding $v_0$ certified by
//! interval arithmetic ([`sign_at_root`]). So an imaginary pair that coincides with a real
//! pair ($g$ of degree $\ge 2$, e.g. the spectrum $\{\pm 2i, \pm 1\}$) or an undamped
//! point where every eigenvalue is paired is certified, not guessed from approximations.

use super::approx::{approx_elem, approx_roots};
use super::roots::{rational_near, sign_at_root};
use crate::algebraic::{AlgebraicNumber, NfElem, NumberField};
use crate::error::Result;
use crate::field::Field;
use crate::poly::{Poly, sign_variations};
use std::cmp::Ordering;

/// Is there a purely imaginary pair at $v_0$? `Ok((omega, certified))` with the smallest
/// crossing frequency (approximate; the existence is exact, `certified` is always true),
/// or `Err` with the reason (exact too).
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
    if g.degree().unwrap_or(0) == 0 {
        return Ok(Err("no pair adds up to zero".into()));
    }
    // u = 0 (a double zero eigenvalue) is no imaginary pair: divide it out
    let zeros = g.coeffs().iter().take_while(|c| k.is_zero(c)).count();
    let g = Poly::new(k.clone(), g.coeffs()[zeros..].to_vec());
    let v0 = &rational_near(r)?;
    if negative_roots(k, &g, r)? == 0 {
        return Ok(Err(match g.deg() {
            0 => "a double zero eigenvalue".into(),
            1 => {
                let u = k.neg(&g.monic().coeff(0));
                format!("a real pair +-{:.6}", approx_elem(k, &u, v0).sqrt())
            }
            _ => "pairs adding up to zero are not imaginary (real pairs or complex quadruples)"
                .into(),
        }));
    }
    let omega = match g.deg() {
        1 => (-approx_elem(k, &k.neg(&g.monic().coeff(0)), v0)).sqrt(),
        _ => {
            let us = approx_roots(k, &g, v0)?;
            let scale = us.iter().map(|u| u.norm()).fold(1e-300, f64::max);
            us.iter()
                .filter(|u| u.re < 0.0 && u.im.abs() <= 1e-6 * scale)
                .map(|u| (-u.re).sqrt())
                .fold(f64::INFINITY, f64::min)
        }
    };
    Ok(Ok((omega, true)))
}

/// The number of distinct negative real roots of `g` ($g(0) \ne 0$) at the real embedding
/// `r` of $\mathbb{Q}(v_0)$ ([`real_roots_by_sign`] with [`sign_at_root`]).
pub(super) fn negative_roots(
    k: &NumberField,
    g: &Poly<NumberField>,
    r: &AlgebraicNumber,
) -> Result<usize> {
    Ok(real_roots_by_sign(g, &|e| sign_at_root(k, e, r))?.0)
}

/// The numbers of distinct negative and positive real roots of `g` ($g(0) \ne 0$) over an
/// ordered field whose signs `sign` decides: $V(-\infty) - V(0)$ and $V(0) - V(+\infty)$
/// for the Sturm sequence $g, g', -\mathrm{rem}, \dots$ (valid for $g$ not square-free too,
/// as $\pm\infty$ and $0$ are not roots).
///
/// # Errors
/// From `sign`.
pub(crate) fn real_roots_by_sign<F: Field>(
    g: &Poly<F>,
    sign: &dyn Fn(&F::Elem) -> Result<Ordering>,
) -> Result<(usize, usize)> {
    if g.degree().unwrap_or(0) == 0 {
        return Ok((0, 0));
    }
    let seq = g.sturm_sequence();
    let (mut at_minus_inf, mut at_zero, mut at_inf) = (vec![], vec![], vec![]);
    for s in &seq {
        let lc = sign(&s.lc())?;
        at_minus_inf.push(if s.deg() % 2 == 1 { lc.reverse() } else { lc });
        at_inf.push(lc);
        at_zero.push(sign(&s.coeff(0))?);
    }
    let (vm, v0, vp) = (
        sign_variations(&at_minus_inf),
        sign_variations(&at_zero),
        sign_variations(&at_inf),
    );
    Ok((vm.saturating_sub(v0), v0.saturating_sub(vp)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::{Q, Rational};

    #[test]
    fn sturm_counts_negative_roots_over_a_real_quadratic_field() {
        // K = Q(t), t = sqrt 2 (the positive root); g = (u + t)(u - 1)(u + 3)(u^2 + 1)
        let f = Poly::<Q>::from_i64s(&[-2, 0, 1]);
        let (zero, two) = (
            Rational::from_integer(0.into()),
            Rational::from_integer(2.into()),
        );
        let r = super::super::roots::real_roots_in(&f, &zero, &two).unwrap()[0].clone();
        let k = r.to_number_field();
        let t = k.generator();
        let c = |x: i64| k.from_rational(&Rational::from_integer(x.into()));
        let lin = |a: NfElem| Poly::new(k.clone(), vec![a, k.one()]);
        let g = lin(t.clone())
            .mul(&lin(c(-1)))
            .mul(&lin(c(3)))
            .mul(&Poly::new(k.clone(), vec![c(1), c(0), c(1)]));
        assert_eq!(negative_roots(&k, &g, &r).unwrap(), 2);
        // squared: still two distinct negative roots
        assert_eq!(negative_roots(&k, &g.mul(&g), &r).unwrap(), 2);
        // (u - t)(u^2 + 1): none
        let h = lin(k.neg(&t)).mul(&Poly::new(k.clone(), vec![c(1), c(0), c(1)]));
        assert_eq!(negative_roots(&k, &h, &r).unwrap(), 0);
    }
}
