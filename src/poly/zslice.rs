//! Kernels on the coefficient slice of a [`ZPoly`] (`&[BigInt]`, low degree first).
//!
//! The root-isolation loops (`algebraic::isolate_real`, `algebraic::isolate_complex`) work
//! on bare coefficient vectors to avoid re-normalizing after every Taylor shift; these are
//! the same integer polynomials as [`ZPoly`] (whose [`ZPoly::coeffs`] is such a slice), only
//! without the "no trailing zero" invariant. [`ZPoly`]'s own ring operations call into this
//! module where they coincide (this file does not depend on `zpoly`, so the two form no
//! cycle).
//!
//! [`ZPoly`]: super::zpoly::ZPoly
//! [`ZPoly::coeffs`]: super::zpoly::ZPoly::coeffs
//!
//! | function | computes |
//! |---|---|
//! | [`from_i64s`] | the coefficient vector of small integers |
//! | [`trim`] | the slice without trailing zeros |
//! | [`primitive`] | $p / \gcd(p_i)$, sign kept |
//! | [`mul`] | $a b$ (schoolbook) |
//! | [`derivative`] | $p'$ |
//! | [`eval_hom`] | $d^n p(n/d)$, $n = \deg p$ |
//! | [`from_poly_q`] | the primitive integer multiple of $p \in \mathbb{Q}[x]$ with $\operatorname{lc} > 0$ |
//! | [`to_monic_q`] | $p / \operatorname{lc}(p)$ in $\mathbb{Q}[x]$ |
//! | [`parity`] | $\pm 1$ for even / odd $p$, else $0$ |

use super::Poly;
use crate::field::rational::denominator_lcm;
use crate::field::{Q, Rational};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};

/// The coefficient vector of small integers, as given (trailing zeros kept).
pub fn from_i64s(cs: &[i64]) -> Vec<BigInt> {
    cs.iter().map(|&c| BigInt::from(c)).collect()
}

/// Without trailing zeros.
pub fn trim(p: &[BigInt]) -> &[BigInt] {
    let mut n = p.len();
    while n > 0 && p[n - 1].is_zero() {
        n -= 1;
    }
    &p[..n]
}

/// Divided by the gcd of its coefficients (sign kept).
pub fn primitive(p: &[BigInt]) -> Vec<BigInt> {
    let mut g = BigInt::zero();
    for c in p {
        g = g.gcd(c);
        if g.is_one() {
            return p.to_vec();
        }
    }
    if g.is_zero() {
        return p.to_vec();
    }
    p.iter().map(|c| c / &g).collect()
}

/// The product $a b$ (schoolbook; empty when either factor is empty).
pub fn mul(a: &[BigInt], b: &[BigInt]) -> Vec<BigInt> {
    if a.is_empty() || b.is_empty() {
        return vec![];
    }
    let mut v = vec![BigInt::zero(); a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        if x.is_zero() {
            continue;
        }
        for (j, y) in b.iter().enumerate() {
            v[i + j] += x * y;
        }
    }
    v
}

/// The derivative $p'$.
pub fn derivative(p: &[BigInt]) -> Vec<BigInt> {
    p.iter()
        .enumerate()
        .skip(1)
        .map(|(i, c)| c * BigInt::from(i))
        .collect()
}

/// $d^n p(n/d)$ for `n = deg p`: the homogenized value, an integer with the sign of $p(n/d)$
/// when $d > 0$.
pub fn eval_hom(p: &[BigInt], num: &BigInt, den: &BigInt) -> BigInt {
    let mut acc = BigInt::zero();
    let mut dpow = BigInt::one();
    for c in p.iter().rev() {
        acc = acc * num + c * &dpow;
        dpow *= den;
    }
    acc
}

/// The primitive integer polynomial with positive leading coefficient proportional to `p`
/// (as a coefficient vector; `ZPoly::from_poly_q` wraps it).
pub fn from_poly_q(p: &Poly<Q>) -> Vec<BigInt> {
    let l = denominator_lcm(p.coeffs());
    let v: Vec<BigInt> = p
        .coeffs()
        .iter()
        .map(|c| (c * Rational::from_integer(l.clone())).to_integer())
        .collect();
    let mut v = primitive(&v);
    if v.last().is_some_and(|c| c.is_negative()) {
        for c in v.iter_mut() {
            *c = -&*c;
        }
    }
    v
}

/// As a monic polynomial over Q (zero stays zero).
pub fn to_monic_q(p: &[BigInt]) -> Poly<Q> {
    Poly::new(
        Q,
        p.iter()
            .map(|c| Rational::from_integer(c.clone()))
            .collect(),
    )
    .monic()
}

/// `+1` when $p(-x) = p(x)$, `-1` when $p(-x) = -p(x)$, `0` otherwise.
pub fn parity(p: &[BigInt]) -> i8 {
    let p = trim(p);
    if p.is_empty() {
        return 1;
    }
    let n = p.len() - 1;
    if p.iter()
        .enumerate()
        .all(|(i, c)| (i + n).is_multiple_of(2) || c.is_zero())
    {
        if n.is_multiple_of(2) { 1 } else { -1 }
    } else {
        0
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::poly::zpoly::ZPoly;

    use super::from_i64s as z;

    #[test]
    fn slice_kernels_agree_with_zpoly() {
        let a = z(&[3, 0, -2, 5]);
        let b = z(&[-1, 4, 0]);
        let za = ZPoly::new(a.clone());
        let zb = ZPoly::new(b.clone());
        assert_eq!(ZPoly::new(mul(&a, &b)), &za * &zb);
        assert_eq!(ZPoly::new(derivative(&a)), za.derivative());
        assert_eq!(trim(&b), &b[..2]);
        // d^n p(n/d) = d^3 p(1/2) with p(1/2) = 3 - 1/2 + 5/8 = 25/8
        assert_eq!(
            eval_hom(&a, &BigInt::from(1), &BigInt::from(2)),
            BigInt::from(25)
        );
        assert_eq!(parity(&z(&[1, 0, 3])), 1);
        assert_eq!(parity(&z(&[0, 2, 0, -1, 0])), -1);
        assert_eq!(parity(&a), 0);
        assert_eq!(primitive(&z(&[-4, 6, 0])), z(&[-2, 3, 0]));
    }

    #[test]
    fn round_trip_through_q() {
        let p = Poly::new(
            Q,
            vec![
                Rational::new(1.into(), 2.into()),
                Rational::from_integer((-3).into()),
            ],
        );
        // 1/2 - 3x  ->  6x - 1 (primitive, positive leading coefficient)
        let zp = ZPoly::from_poly_q(&p);
        assert_eq!(zp, ZPoly::from_i64s(&[-1, 6]));
        assert_eq!(zp.to_monic_q(), p.monic());
    }
}
