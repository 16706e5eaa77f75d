//! Real algebraic numbers for the parameter: the real roots of a condition polynomial in
//! $[a, b]$, signs of elements of $\mathbb{Q}(v_0)$ at a root, and rationals near or
//! between roots.

use crate::algebraic::{AlgebraicNumber, NfElem, NumberField, factor_q};
use crate::error::{Error, Result};
use crate::field::{Q, Rational};
use crate::poly::Poly;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;

/// Real roots of `p` in $[a, b]$, ascending, with their minimal polynomials.
pub(super) fn real_roots_in(
    p: &Poly<Q>,
    a: &Rational,
    b: &Rational,
) -> Result<Vec<AlgebraicNumber>> {
    if p.degree().unwrap_or(0) == 0 {
        return Ok(vec![]);
    }
    let (lo, hi) = (
        AlgebraicNumber::from_rational(a),
        AlgebraicNumber::from_rational(b),
    );
    let mut out = vec![];
    for (f, _) in factor_q(p)?.1 {
        for r in real_roots_of_irreducible(&f) {
            if r >= lo && r <= hi {
                out.push(r);
            }
        }
    }
    out.sort_by(|x, y| x.partial_cmp(y).unwrap_or(Ordering::Equal));
    Ok(out)
}

/// The real roots of the irreducible `f`, as algebraic numbers (no complex isolation).
fn real_roots_of_irreducible(f: &Poly<Q>) -> Vec<AlgebraicNumber> {
    use crate::algebraic::number::Loc;
    let m = f.monic();
    if m.deg() == 1 {
        return vec![AlgebraicNumber::from_rational(&-m.coeff(0))];
    }
    let z = crate::algebraic::zp::from_poly_q(&m);
    crate::algebraic::isolate_real::isolate_real_roots(&z)
        .into_iter()
        .map(|r| AlgebraicNumber::from_parts(m.clone(), Loc::Real(r)))
        .collect()
}

/// Sign of the element `e` of $\mathbb{Q}(r) = \mathbb{Q}[t]/(f)$ at the real root `r`
/// (`e` nonzero), by interval Horner on refined isolating intervals.
pub fn sign_at_root(k: &NumberField, e: &NfElem, r: &AlgebraicNumber) -> Result<Ordering> {
    let p = k.to_poly(e);
    if p.is_zero() {
        return Ok(Ordering::Equal);
    }
    if let Some(q) = r.to_rational() {
        return Ok(p.eval(&q).cmp(&Rational::zero()));
    }
    let mut r = r.clone();
    for _ in 0..80 {
        let (lo, hi) = r
            .interval()
            .ok_or_else(|| Error::Invalid("non-real root".into()))?;
        let (a, b) = interval_horner(&p, &lo, &hi);
        if a.is_positive() {
            return Ok(Ordering::Greater);
        }
        if b.is_negative() {
            return Ok(Ordering::Less);
        }
        let w = (&hi - &lo) / Rational::from_integer(256.into());
        r = r.refined(&w)?;
    }
    Err(Error::Limit(
        "sign of an algebraic number not decided".into(),
    ))
}

fn interval_horner(p: &Poly<Q>, lo: &Rational, hi: &Rational) -> (Rational, Rational) {
    let (mut a, mut b) = (Rational::zero(), Rational::zero());
    for c in p.coeffs().iter().rev() {
        let cands = [&a * lo, &a * hi, &b * lo, &b * hi];
        let mn = cands.iter().min().cloned().unwrap_or_default();
        let mx = cands.iter().max().cloned().unwrap_or_default();
        a = mn + c;
        b = mx + c;
    }
    (a, b)
}

/// A rational within $2^{-80}$ of the real algebraic number `r`.
pub(super) fn rational_near(r: &AlgebraicNumber) -> Result<Rational> {
    if let Some(q) = r.to_rational() {
        return Ok(q);
    }
    let w = Rational::new(1.into(), num_bigint::BigInt::one() << 80usize);
    let (lo, hi) = r.refined(&w)?.interval().unwrap_or_default();
    Ok((lo + hi) / Rational::from_integer(2.into()))
}

/// A rational strictly between the reals `a < b`.
pub fn rational_between(a: &AlgebraicNumber, b: &AlgebraicNumber) -> Result<Rational> {
    let (mut a, mut b) = (a.clone(), b.clone());
    for _ in 0..200 {
        let (_, ahi) = a
            .interval()
            .ok_or_else(|| Error::Invalid("non-real".into()))?;
        let (blo, _) = b
            .interval()
            .ok_or_else(|| Error::Invalid("non-real".into()))?;
        if ahi < blo {
            return Ok(simplest_between(&ahi, &blo));
        }
        let half = |x: &AlgebraicNumber| -> Result<AlgebraicNumber> {
            let (lo, hi) = x.interval().unwrap_or_default();
            if lo == hi {
                return Ok(x.clone());
            }
            x.refined(&((hi - lo) / Rational::from_integer(2.into())))
        };
        a = half(&a)?;
        b = half(&b)?;
    }
    Err(Error::Limit(
        "could not separate two critical values".into(),
    ))
}

/// A short rational in the open interval $(a, b)$: the continued-fraction simplest one.
fn simplest_between(a: &Rational, b: &Rational) -> Rational {
    let fl = a.floor();
    if &(&fl + Rational::one()) < b {
        return fl + Rational::one();
    }
    // a, b in [fl, fl + 1]; recurse on reciprocals of the fractional parts
    let (fa, fb) = (a - &fl, b - &fl);
    if fa.is_zero() {
        // (fl, b): choose fl + 1/m with 1/m < fb
        let m = (Rational::one() / &fb).floor() + Rational::one();
        return fl + Rational::one() / m;
    }
    fl + Rational::one() / simplest_between(&(Rational::one() / &fb), &(Rational::one() / &fa))
}
