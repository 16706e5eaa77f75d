//! Exact algebra on the imaginary axis: $p(j\omega)$ split into real polynomials, the
//! positive real roots of a polynomial over $\mathbb{Q}$ as algebraic numbers, the exact
//! sign of a polynomial at a real algebraic number, and the value of a rational function
//! there as an algebraic number (its minimal polynomial and isolating interval).
//!
//! With $p(s) = \sum_k c_k s^k$: $p(j\omega) = R(\omega) + j I(\omega)$ where
//! $R = \sum_{k \text{ even}} (-1)^{k/2} c_k \omega^k$ and
//! $I = \sum_{k \text{ odd}} (-1)^{(k-1)/2} c_k \omega^k$. The value $a(\omega)/b(\omega)$ at
//! a root $\omega$ of the irreducible $m$ is the class $h = a\,b^{-1}$ in
//! $\mathbb{Q}[t]/(m)$; its minimal polynomial is the irreducible factor $f$ of the
//! characteristic polynomial of multiplication by $h$ with $f(h) = 0$ in that field, and the
//! root of $f$ meant is the only one whose isolating interval meets the interval image of
//! $h$ on a refined interval of $\omega$ (interval Horner, exact rationals).

use crate::algebraic::isolate_real::{RealRoot, bisect, isolate_real_roots};
use crate::algebraic::number::Loc;
use crate::algebraic::{AlgebraicNumber, NumberField, factor_q};
use crate::error::{Error, Result};
use crate::field::{Field, Q, Rational};
use crate::matrix::Matrix;
use crate::poly::Poly;
use crate::poly::zslice as zp;
use num_traits::{Signed, Zero};
use std::cmp::Ordering;

/// Refinement steps before giving up on telling roots apart (each halves an interval; the
/// cases that need them are separated after a few dozen).
const MAX_STEPS: usize = 4000;

/// $(R, I)$ with $p(j\omega) = R(\omega) + j\,I(\omega)$.
pub fn split_imaginary_axis(p: &Poly<Q>) -> (Poly<Q>, Poly<Q>) {
    let n = p.coeffs().len();
    let mut re = vec![Rational::zero(); n];
    let mut im = vec![Rational::zero(); n];
    for (k, c) in p.coeffs().iter().enumerate() {
        match k % 4 {
            0 => re[k] = c.clone(),
            1 => im[k] = c.clone(),
            2 => re[k] = -c,
            _ => im[k] = -c,
        }
    }
    (Poly::new(Q, re), Poly::new(Q, im))
}

/// The positive real roots of a nonzero `p`, ascending, each once (multiplicities dropped).
///
/// # Errors
/// `Invalid` for the zero polynomial.
pub fn positive_roots(p: &Poly<Q>) -> Result<Vec<AlgebraicNumber>> {
    let (_, factors) = factor_q(p)?;
    let mut out = vec![];
    for (f, _) in factors {
        if f.deg() == 1 {
            let r = -f.coeff(0);
            if r.is_positive() {
                out.push(AlgebraicNumber::from_rational(&r));
            }
            continue;
        }
        let z = zp::from_poly_q(&f);
        for mut r in isolate_real_roots(&z) {
            // an irreducible f of degree >= 2 has no rational root: 0 is not a root, and an
            // interval straddling 0 splits after finitely many bisections
            while r.lo.is_negative() && r.hi.is_positive() {
                r = bisect(&z, &r);
            }
            if !r.lo.is_negative() && !r.is_exact() {
                out.push(AlgebraicNumber::from_parts(f.clone(), Loc::Real(r)));
            }
        }
    }
    out.sort_by(|a, b| {
        let (x, y) = (a.approx().0, b.approx().0);
        x.partial_cmp(&y).unwrap_or(Ordering::Equal)
    });
    Ok(out)
}

/// `p(q)` exactly.
fn eval_q(p: &Poly<Q>, x: &Rational) -> Rational {
    p.eval(x)
}

/// An enclosure of `{p(x) : lo <= x <= hi}` (interval Horner).
pub fn range(p: &Poly<Q>, lo: &Rational, hi: &Rational) -> (Rational, Rational) {
    let mut a = (Rational::zero(), Rational::zero());
    for c in p.coeffs().iter().rev() {
        let prods = [&a.0 * lo, &a.0 * hi, &a.1 * lo, &a.1 * hi];
        let mn = prods.iter().min().cloned().unwrap_or_default();
        let mx = prods.iter().max().cloned().unwrap_or_default();
        a = (mn + c, mx + c);
    }
    a
}

/// The exact sign of `p(w)` for a real algebraic `w`.
///
/// # Errors
/// `Limit` when the interval image does not leave 0 within the refinement bound (it always
/// does when `p(w) != 0`, which is decided exactly first).
pub fn sign_at(p: &Poly<Q>, w: &AlgebraicNumber) -> Result<Ordering> {
    if let Some(q) = w.to_rational() {
        return Ok(eval_q(p, &q).cmp(&Rational::zero()));
    }
    let r = p.rem(w.minpoly());
    if r.is_zero() {
        return Ok(Ordering::Equal);
    }
    let mut w = w.clone();
    for _ in 0..MAX_STEPS {
        let (lo, hi) = w.interval().unwrap_or_default();
        let (a, b) = range(&r, &lo, &hi);
        if a.is_positive() {
            return Ok(Ordering::Greater);
        }
        if b.is_negative() {
            return Ok(Ordering::Less);
        }
        w = w.refined(&((&hi - &lo) / Rational::from_integer(2.into())))?;
    }
    Err(Error::Limit(
        "sign of a polynomial at an algebraic number".into(),
    ))
}

/// The value $a(w)/b(w)$ for a real algebraic `w` with $b(w) \ne 0$, as an algebraic number,
/// with the check that its minimal polynomial vanishes at the class of $a/b$ in
/// $\mathbb{Q}(w)$ and that $b \cdot h = a$ there.
///
/// # Errors
/// `DivisionByZero` when $b(w) = 0$; `Limit` when the roots are not told apart in bound.
pub fn value_at(a: &Poly<Q>, b: &Poly<Q>, w: &AlgebraicNumber) -> Result<(AlgebraicNumber, bool)> {
    if let Some(q) = w.to_rational() {
        let d = eval_q(b, &q);
        if d.is_zero() {
            return Err(Error::DivisionByZero);
        }
        return Ok((AlgebraicNumber::from_rational(&(eval_q(a, &q) / d)), true));
    }
    let m = w.minpoly();
    let k = NumberField::new_unchecked(m, w.approx());
    let bk = k.from_poly(b);
    let h = k.mul(&k.from_poly(a), &k.inv(&bk).ok_or(Error::DivisionByZero)?);
    let check = k.mul(&bk, &h) == k.from_poly(a);
    value_in_field(&k, &h, w, check)
}

/// The element `h` of $k = \mathbb{Q}(w)$ (`k`'s generator is `w`) as an algebraic number:
/// its minimal polynomial is the factor of the characteristic polynomial of multiplication
/// by `h` that vanishes at `h`, the root the one meeting the interval image of `h`; `check`
/// is passed through, and-ed with nothing else.
///
/// # Errors
/// `Limit` when the roots are not told apart in bound.
pub fn value_in_field(
    k: &NumberField,
    h: &<NumberField as Field>::Elem,
    w: &AlgebraicNumber,
    check: bool,
) -> Result<(AlgebraicNumber, bool)> {
    let hp = k.to_poly(h);
    let (_, factors) = factor_q(&mult_matrix(k, h).charpoly()?)?;
    let f = factors
        .into_iter()
        .map(|(f, _)| f)
        .find(|f| {
            let mut acc = k.zero();
            for c in f.coeffs().iter().rev() {
                acc = k.add(&k.mul(&acc, h), &k.from_base(c));
            }
            k.is_zero(&acc)
        })
        .ok_or_else(|| Error::Verification("no factor of the norm vanishes at h".into()))?;
    if f.deg() == 1 {
        return Ok((AlgebraicNumber::from_rational(&-f.coeff(0)), check));
    }
    let zf = zp::from_poly_q(&f);
    let mut cands: Vec<RealRoot> = isolate_real_roots(&zf);
    let mut w = w.clone();
    for _ in 0..MAX_STEPS {
        let (lo, hi) = w.interval().unwrap_or_default();
        let (ylo, yhi) = range(&hp, &lo, &hi);
        cands.retain(|r| r.hi >= ylo && r.lo <= yhi);
        if cands.len() == 1 {
            let r = cands.pop().unwrap_or_else(|| unreachable!());
            return Ok((AlgebraicNumber::from_parts(f, Loc::Real(r)), check));
        }
        if cands.is_empty() {
            return Err(Error::Verification(
                "the value lies in no isolating interval".into(),
            ));
        }
        w = w.refined(&((&hi - &lo) / Rational::from_integer(2.into())))?;
        cands = cands.iter().map(|r| bisect(&zf, r)).collect();
    }
    Err(Error::Limit(
        "telling apart the roots of a value's minimal polynomial".into(),
    ))
}

/// The matrix over $\mathbb{Q}$ of multiplication by `h` on the basis $1, t, \dots, t^{d-1}$
/// of $k = \mathbb{Q}(t)$.
pub(super) fn mult_matrix(k: &NumberField, h: &<NumberField as Field>::Elem) -> Matrix<Q> {
    let d = k.degree();
    let mut mat = Matrix::zeros(Q, d, d);
    let mut col = h.clone();
    for j in 0..d {
        let cs = k.coeffs(&col);
        for i in 0..d {
            mat.set(i, j, cs.get(i).cloned().unwrap_or_default());
        }
        col = k.mul(&col, &k.generator());
    }
    mat
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_traits::One;
    #[test]
    fn split_and_values() {
        // p = s^3 + 2 s^2 + 3 s + 4: p(jw) = (4 - 2 w^2) + j (3 w - w^3)
        let p = Poly::<Q>::from_i64s(&[4, 3, 2, 1]);
        let (re, im) = split_imaginary_axis(&p);
        assert_eq!(re, Poly::from_i64s(&[4, 0, -2]));
        assert_eq!(im, Poly::from_i64s(&[0, 3, 0, -1]));
        // positive roots of w^3 - 3 w: sqrt(3)
        let r = positive_roots(&im).unwrap();
        assert_eq!(r.len(), 1);
        assert!((r[0].approx().0 - 3f64.sqrt()).abs() < 1e-12);
        // (4 - 2 w^2) at sqrt(3) = -2, and 1/(w^2 + w) at sqrt(3) = (3 - sqrt(3))/6, a root of
        // x^2 - x + 1/6
        let (v, ok) = value_at(&re, &Poly::one(Q), &r[0]).unwrap();
        assert!(ok && v.to_rational() == Some(Rational::from_integer((-2).into())));
        let (v, ok) = value_at(&Poly::one(Q), &Poly::from_i64s(&[0, 1, 1]), &r[0]).unwrap();
        assert!(ok);
        assert_eq!(
            v.minpoly(),
            &Poly::new(
                Q,
                vec![
                    Rational::new(1.into(), 6.into()),
                    -Rational::one(),
                    Rational::one()
                ]
            )
        );
        assert!((v.approx().0 - (3.0 - 3f64.sqrt()) / 6.0).abs() < 1e-12);
        assert_eq!(
            sign_at(&Poly::from_i64s(&[-2, 0, 1]), &r[0]).unwrap(),
            Ordering::Greater
        );
        assert_eq!(
            sign_at(&Poly::from_i64s(&[-3, 0, 1]), &r[0]).unwrap(),
            Ordering::Equal
        );
    }
}
