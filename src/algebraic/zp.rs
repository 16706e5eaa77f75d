//! Small dense integer-polynomial kernels (`Vec<BigInt>`, low degree first) used by the
//! isolation code, and conversions from and to `Poly<Q>`.

use crate::field::{Q, Rational};
use crate::poly::Poly;
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};

/// Integer polynomial, coefficients low degree first.
pub type ZP = Vec<BigInt>;

/// Without trailing zeros.
pub fn trim(p: &[BigInt]) -> &[BigInt] {
    let mut n = p.len();
    while n > 0 && p[n - 1].is_zero() {
        n -= 1;
    }
    &p[..n]
}

/// Divided by the gcd of its coefficients (sign kept).
pub fn primitive(p: &[BigInt]) -> ZP {
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

pub fn mul(a: &[BigInt], b: &[BigInt]) -> ZP {
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

pub fn derivative(p: &[BigInt]) -> ZP {
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

/// The primitive integer polynomial with positive leading coefficient proportional to `p`.
pub fn from_poly_q(p: &Poly<Q>) -> ZP {
    let mut l = BigInt::one();
    for c in p.coeffs() {
        l = l.lcm(c.denom());
    }
    let v: ZP = p
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
        .all(|(i, c)| (i + n) % 2 == 0 || c.is_zero())
    {
        if n % 2 == 0 { 1 } else { -1 }
    } else {
        0
    }
}
