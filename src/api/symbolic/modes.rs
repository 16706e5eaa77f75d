//! `modes` over $\mathbb{Q}(p)$: the modes as formulas. $\det(sI - A)$ is factored over
//! $\mathbb{Q}(p)$ ([`factor_over_qp`], verified by multiplying back); per irreducible factor
//!
//! | factor | reported |
//! |---|---|
//! | $s + a$ | a real pole $s = -a$ (`pole`) |
//! | $s^2 + b s + c$ | $\omega_n^2 = c$, $2 \zeta \omega_n = b$, $\zeta^2 = b^2 / (4c)$ and the discriminant $b^2 - 4c$: a complex pair where it is $< 0$ (the sign condition of the real form) |
//! | degree $\ge 3$ | the factor (no closed form over $\mathbb{Q}(p)$ in general) |
//!
//! For the mass–spring–damper $m s^2 + c s + k$: $\omega_n^2 = k/m$, $2\zeta\omega_n = c/m$,
//! $\zeta^2 = c^2/(4 k m)$, i.e. $\omega_n = \sqrt{k/m}$, $\zeta = c / (2\sqrt{k m})$.

use crate::field::ElemDisplay;
use crate::field::Field;
use crate::poly::Poly;
use crate::ratfunc::RatFuncField;
use crate::report::{Report, Value};
use crate::structure::factor_qp::factor_over_qp;

/// The modal table over $\mathbb{Q}(p)$ of the state matrix `a` (see the module docs).
///
/// # Errors
/// As [`factor_over_qp`] and the characteristic polynomial.
pub(super) fn modes_report(a: &crate::matrix::Matrix<RatFuncField>) -> crate::Result<Report> {
    let k = a.field().clone();
    let cp = a.charpoly()?;
    let fs = factor_over_qp(&cp)?;
    let items = fs
        .iter()
        .map(|(g, e)| Value::Obj(mode(&k, g, *e)))
        .collect();
    Ok(Report::titled("modes over Q(p)")
        .str("characteristic_polynomial", cp.to_string_var("s"))
        .list("modes", items))
}

/// One row of the table: a monic irreducible factor `g` of multiplicity `e`.
fn mode(k: &RatFuncField, g: &Poly<RatFuncField>, e: usize) -> Report {
    let f = |x: &<RatFuncField as Field>::Elem| k.fmt_elem(x);
    let r = Report::new()
        .str("factor", g.to_string_var("s"))
        .int("multiplicity", e);
    match g.deg() {
        1 => r
            .str("kind", "real pole")
            .str("pole", f(&k.neg(&g.coeff(0)))),
        2 => {
            let (b, c) = (g.coeff(1), g.coeff(0));
            let disc = k.sub(&k.mul(&b, &b), &k.mul(&k.from_i64(4), &c));
            let zeta2 = k.div_unrecorded(&k.mul(&b, &b), &k.mul(&k.from_i64(4), &c));
            let kind = match k.sign(&disc) {
                Some(std::cmp::Ordering::Less) => "complex pair",
                Some(_) => "two real poles",
                None => "complex pair where the discriminant is < 0",
            };
            let mut r = r
                .str("kind", kind)
                .str("omega_n_squared", f(&c))
                .str("two_zeta_omega_n", f(&b))
                .str("discriminant", f(&disc));
            if let Some(z) = zeta2 {
                r = r.str("zeta_squared", f(&z));
            }
            r
        }
        _ => r.str("kind", "factor of degree >= 3 (no closed form)"),
    }
}
