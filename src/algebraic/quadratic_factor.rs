//! Factorization over a quadratic field $K = \mathbb{Q}(\sqrt d)$ (and $\mathbb{Q}(i)$).
//!
//! $K$ is the number field $\mathbb{Q}\[t\]/(t^2 - d)$, $t \mapsto \sqrt d$ (or $i\sqrt{-d}$):
//! $a + b\sqrt d \leftrightarrow a + b t$ is a field isomorphism, so a polynomial over $K$ is
//! factored by Trager's norm method ([`super::factor_over_number_field`]) and mapped back.
//!
//! # Verification
//! [`factor_over_quadratic`] multiplies the factors back (times the leading coefficient)
//! and compares with the input exactly; a mismatch is a `Verification` error.
//!
//! | entry point | computes |
//! |---|---|
//! | [`factor_over_quadratic`] | monic irreducible factors over $K$ with multiplicities |
//! | [`norm_over_q`] | $N(p) = p \cdot \bar p \in \mathbb{Q}\[x\]$ ($\bar{\ }$ the Galois conjugation) |
//! | [`quadratic_as_number_field`] | $K$ as a [`NumberField`] marked at the field's embedding |

use super::{NfElem, NumberField, factor_over_number_field};
use crate::error::{Error, Result};
use crate::field::{Q, Quadratic, QuadraticField, Rational};
use crate::poly::Poly;
use num_traits::{Signed, ToPrimitive, Zero};

/// $K$ as $\mathbb{Q}\[t\]/(t^2 - d)$, marked at $\sqrt d > 0$ (or $i\sqrt{-d}$).
pub fn quadratic_as_number_field(k: &QuadraticField) -> NumberField {
    let d = k.d();
    let m = Poly::new(
        Q,
        vec![
            Rational::from_integer(-d.clone()),
            Rational::zero(),
            num_traits::One::one(),
        ],
    );
    let r = d.abs().to_f64().unwrap_or(f64::MAX).sqrt();
    let root = if d.is_negative() { (0.0, r) } else { (r, 0.0) };
    // t^2 - d is irreducible for a square-free d != 0, 1 (QuadraticField's invariant)
    NumberField::new_unchecked(&m, root)
}

fn to_nf(x: &Quadratic) -> NfElem {
    let mut v = vec![x.a.clone(), x.b.clone()];
    while v.last().is_some_and(|c| c.is_zero()) {
        v.pop();
    }
    crate::algebraic::ExtElem(v)
}

fn from_nf(x: &NfElem) -> Quadratic {
    let c = |i: usize| x.0.get(i).cloned().unwrap_or_else(Rational::zero);
    Quadratic::new(c(0), c(1))
}

/// Monic irreducible factors of `p` over its quadratic field with multiplicities, in the
/// order of [`factor_over_number_field`]: `p == lc(p) * prod(f_i^e_i)` (checked).
///
/// # Errors
/// `Invalid` for the zero polynomial; `Verification` when the product check fails; those of
/// [`factor_over_number_field`].
///
/// # Examples
/// ```
/// use exactlti::algebraic::factor_over_quadratic;
/// use exactlti::field::{Field, QuadraticField};
/// use exactlti::poly::Poly;
/// // s^2 + 1 = (s - i)(s + i) over Q(i)
/// let k = QuadraticField::gaussian();
/// let p = Poly::new(k.clone(), vec![k.one(), k.zero(), k.one()]);
/// let fs = factor_over_quadratic(&p).unwrap();
/// assert_eq!(fs.len(), 2);
/// ```
pub fn factor_over_quadratic(
    p: &Poly<QuadraticField>,
) -> Result<Vec<(Poly<QuadraticField>, usize)>> {
    if p.is_zero() {
        return Err(Error::Invalid(
            "factorization of the zero polynomial".into(),
        ));
    }
    let k = p.field().clone();
    if p.deg() == 0 {
        return Ok(vec![]);
    }
    let nf = quadratic_as_number_field(&k);
    let pn = p.map(&nf, to_nf);
    let fs: Vec<(Poly<QuadraticField>, usize)> = factor_over_number_field(&pn)?
        .into_iter()
        .map(|(f, e)| (f.map(&k, from_nf).monic(), e))
        .collect();
    let mut prod = Poly::new(k.clone(), vec![p.lc()]);
    for (f, e) in &fs {
        for _ in 0..*e {
            prod = prod.mul(f);
        }
    }
    if prod != *p {
        return Err(Error::Verification(format!(
            "factorization over {k}: the product of the factors differs from the polynomial"
        )));
    }
    Ok(fs)
}

/// The norm $N(p) = p \cdot \bar p$ of `p` over $\mathbb{Q}$, with $\bar p$ the Galois
/// conjugate ($\sqrt d \mapsto -\sqrt d$): a rational polynomial whose roots are those of
/// $p$ and of $\bar p$.
pub fn norm_over_q(p: &Poly<QuadraticField>) -> Poly<Q> {
    let k = p.field().clone();
    let conj = p.map(&k, |c| k.galois(c));
    let n = p.mul(&conj);
    n.to_rational_poly()
        .expect("p times its Galois conjugate is fixed by the Galois group")
}
