//! Real roots of a polynomial over $K = \mathbb{Q}(\sqrt d)$ or $\mathbb{Q}(i)$ and exact
//! signs.
//!
//! A real root $r$ of $c \in K[v]$ is a root of the norm $N(c) = c\,\sigma(c) \in
//! \mathbb{Q}[v]$; with $f$ the minimal polynomial of $r$ over $\mathbb{Q}$, its minimal
//! polynomial over $K$ is the irreducible factor $h$ of $f$ over $K$ that vanishes at $r$,
//! and $r$ is a root of $c$ iff $h \mid c$. Which factor vanishes at $r$ is decided exactly:
//! a factor with rational coefficients is $f$ itself; otherwise ($K$ real, $f = h\,\sigma(h)$
//! square-free) $h$ vanishes at $r$ iff it changes sign across the isolating interval of $r$,
//! whose rational end points give values in $K$ with exact signs. Over $\mathbb{Q}(i)$ an
//! $f$ with a real root is irreducible over $K$ ($f = h \bar h$ would make the real root
//! double).

use super::super::roots::real_roots_in;
use crate::algebraic::{AlgebraicNumber, NfElem, NumberField, factor_over_quadratic, norm_over_q};
use crate::error::Result;
use crate::field::{Field, Q, Quadratic, QuadraticField, Rational};
use crate::poly::Poly;
use num_traits::{Signed, Zero};
use std::cmp::Ordering;

fn sign_q(q: &Rational) -> Ordering {
    q.cmp(&Rational::from_integer(0.into()))
}

/// The sign of $a + b\sqrt d$ in a real quadratic field (exact).
pub fn sign_k(k: &QuadraticField, x: &Quadratic) -> Ordering {
    let (sa, sb) = (sign_q(&x.a), sign_q(&x.b));
    if sb == Ordering::Equal || sa == sb {
        return sa;
    }
    if sa == Ordering::Equal {
        return sb;
    }
    // opposite signs: compare a^2 with d b^2
    let d = Rational::from_integer(k.d().clone());
    match (&x.a * &x.a).cmp(&(&d * &x.b * &x.b)) {
        Ordering::Greater => sa,
        Ordering::Less => sb,
        Ordering::Equal => Ordering::Equal,
    }
}

/// The real roots of `c` in $[a, b]$, ascending, each with its minimal polynomial over $K$
/// (monic). A constant `c` has none.
///
/// # Errors
/// Factoring and root isolation.
pub fn real_roots_k(
    c: &Poly<QuadraticField>,
    a: &Rational,
    b: &Rational,
) -> Result<Vec<(AlgebraicNumber, Poly<QuadraticField>)>> {
    if c.degree().unwrap_or(0) == 0 {
        return Ok(vec![]);
    }
    let k = c.field().clone();
    let mut out = vec![];
    for r in real_roots_in(&norm_over_q(c), a, b)? {
        let f = r.minpoly().map(&k, |q| k.from_rational(q));
        for (h, _) in factor_over_quadratic(&f)? {
            if c.rem(&h).is_zero() && vanishes_at(&k, &h, &r)? {
                out.push((r.clone(), h.monic()));
                break;
            }
        }
    }
    Ok(out)
}

/// Does the irreducible factor `h` (over $K$) of the minimal polynomial of `r` vanish at
/// `r`? (See the module docs.)
fn vanishes_at(k: &QuadraticField, h: &Poly<QuadraticField>, r: &AlgebraicNumber) -> Result<bool> {
    if h.coeffs().iter().all(|c| c.b.is_zero()) {
        return Ok(true);
    }
    if let Some(q) = r.to_rational() {
        return Ok(k.is_zero(&h.eval(&k.from_rational(&q))));
    }
    if !k.is_real() {
        return Ok(false);
    }
    let (lo, hi) = r.interval().unwrap_or_default();
    let s = |x: &Rational| sign_k(k, &h.eval(&k.from_rational(x)));
    Ok(s(&lo) != s(&hi))
}

/// The sign at the real root `r` of the element $A(t) + \sqrt d\, B(t)$ of $K(r)$ (`parts`:
/// $A, B \in \mathbb{Q}[t]$), $K$ real: exact, from the signs of elements of
/// $\mathbb{Q}(r)$ ([`super::super::sign_at_root`]).
///
/// # Errors
/// When a sign is not decided (refinement bound).
pub fn sign_at_real_root(
    k: &QuadraticField,
    parts: (&Poly<Q>, &Poly<Q>),
    r: &AlgebraicNumber,
) -> Result<Ordering> {
    let l: NumberField = r.to_number_field();
    let el = |p: &Poly<Q>| -> NfElem { l.from_poly(&p.rem(r.minpoly())) };
    let sign = |p: &Poly<Q>| super::super::sign_at_root(&l, &el(p), r);
    let (sa, sb) = (sign(parts.0)?, sign(parts.1)?);
    if sb == Ordering::Equal || sa == sb {
        return Ok(sa);
    }
    if sa == Ordering::Equal {
        return Ok(sb);
    }
    let d = Poly::constant(Q, Rational::from_integer(k.d().abs()));
    let n = parts.0.mul(parts.0).sub(&d.mul(&parts.1.mul(parts.1)));
    Ok(match sign(&n)? {
        Ordering::Greater => sa,
        Ordering::Less => sb,
        Ordering::Equal => Ordering::Equal,
    })
}

/// $A, B \in \mathbb{Q}[t]$ with $x = A(t) + \theta B(t)$ for coefficients `x` in $K$.
pub fn split_parts(x: &[Quadratic]) -> (Poly<Q>, Poly<Q>) {
    (
        Poly::new(Q, x.iter().map(|c| c.a.clone()).collect()),
        Poly::new(Q, x.iter().map(|c| c.b.clone()).collect()),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn signs_in_a_real_quadratic_field() {
        let k = QuadraticField::new(2).unwrap();
        let q = |a: i64, b: i64| {
            Quadratic::new(
                Rational::from_integer(a.into()),
                Rational::from_integer(b.into()),
            )
        };
        assert_eq!(sign_k(&k, &q(3, -2)), Ordering::Greater); // 3 - 2.83
        assert_eq!(sign_k(&k, &q(-3, 2)), Ordering::Less);
        assert_eq!(sign_k(&k, &q(1, -1)), Ordering::Less);
        assert_eq!(sign_k(&k, &q(0, 0)), Ordering::Equal);
    }

    #[test]
    fn roots_of_a_polynomial_over_k_not_its_conjugate() {
        // c = v^2 - sqrt 2 v - 4 over Q(sqrt 2): roots 2 sqrt 2, -sqrt 2; its conjugate
        // v^2 + sqrt 2 v - 4 has -2 sqrt 2, sqrt 2 (the norm has all four)
        let k = QuadraticField::new(2).unwrap();
        let q = |a: i64, b: i64| {
            Quadratic::new(
                Rational::from_integer(a.into()),
                Rational::from_integer(b.into()),
            )
        };
        let c = Poly::new(k.clone(), vec![q(-4, 0), q(0, -1), q(1, 0)]);
        let lo = Rational::from_integer((-5).into());
        let hi = Rational::from_integer(5.into());
        let rts = real_roots_k(&c, &lo, &hi).unwrap();
        let approx: Vec<f64> = rts.iter().map(|(r, _)| r.approx().0).collect();
        assert_eq!(approx.len(), 2);
        assert!((approx[0] + 2f64.sqrt()).abs() < 1e-9, "{approx:?}");
        assert!((approx[1] - 8f64.sqrt()).abs() < 1e-9, "{approx:?}");
        for (r, h) in &rts {
            assert_eq!(h.deg(), 1);
            // exact: h(r) = 0 in Q(r)(sqrt 2) -- the sign test agrees with the value
            let x = -r.approx().0;
            let (re, _) = k.approx(&h.coeff(0));
            assert!((re - x).abs() < 1e-9);
        }
    }
}
