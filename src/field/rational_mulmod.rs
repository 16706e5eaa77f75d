//! $\mathbb{Q}$'s kernel for the product in $\mathbb{Q}\[t\]/(m)$
//! ([`super::Field::mul_mod_poly`]): for an integral monic $m$ the product of the scaled
//! integer polynomials is reduced modulo $m$ in integers, with one division at the end.

use super::{Rational, lehmer};
use num_bigint::BigInt;
use num_traits::{One, Zero};

/// `a * b` modulo an integral monic `m` (coefficients low degree first): $(s_a a)(s_b b)$
/// with the lcms $s_a, s_b$ of the denominators is an integer polynomial, reduced modulo $m$
/// in integers, and each coefficient is divided by $s_a s_b$ once (one Lehmer gcd), instead
/// of normalising a rational after every multiply-add.
pub(super) fn mul_integral(m: &[Rational], a: &[Rational], b: &[Rational]) -> Vec<Rational> {
    let (sa, ia) = integer_scaled(a);
    let (sb, ib) = integer_scaled(b);
    let mut v = vec![BigInt::zero(); ia.len() + ib.len() - 1];
    for (i, x) in ia.iter().enumerate() {
        if x.is_zero() {
            continue;
        }
        for (j, y) in ib.iter().enumerate() {
            if !y.is_zero() {
                v[i + j] += x * y;
            }
        }
    }
    let d = m.len() - 1;
    while v.len() > d {
        let c = v.pop().expect("longer than d");
        if c.is_zero() {
            continue;
        }
        let off = v.len() - d;
        for (j, mj) in m.iter().enumerate().take(d) {
            if !mj.is_zero() {
                v[off + j] -= &c * mj.numer();
            }
        }
    }
    while v.last().is_some_and(|c| c.is_zero()) {
        v.pop();
    }
    let den = sa * sb;
    v.into_iter().map(|x| lehmer::fraction(x, &den)).collect()
}

/// The lcm $s$ of the denominators of `xs` and the integers $s x$.
fn integer_scaled(xs: &[Rational]) -> (BigInt, Vec<BigInt>) {
    let mut s = BigInt::one();
    for x in xs {
        if !x.denom().is_one() {
            let g = lehmer::gcd(&s, x.denom());
            s = &s / g * x.denom();
        }
    }
    let v = xs
        .iter()
        .map(|x| {
            if x.denom().is_one() {
                x.numer() * &s
            } else {
                x.numer() * (&s / x.denom())
            }
        })
        .collect();
    (s, v)
}
