//! Lehmer's gcd for big integers, and canonical fractions built with it.
//!
//! num-bigint's gcd is binary (Stein), quadratic in the bit length with a large constant;
//! reducing thousands of reconstructed fractions $N_{ij}/d$ of several hundred bits to
//! lowest terms is dominated by it. Lehmer's algorithm (Knuth, TAOCP vol. 2, 4.5.2,
//! Algorithm L) simulates the Euclidean quotients on the leading 64 bits and applies them
//! in batches, one multi-precision linear combination per ~30 quotients.

use crate::field::Rational;
use num_bigint::{BigInt, BigUint, Sign};
use num_integer::Integer;
use num_traits::{One, ToPrimitive, Zero};

/// $\gcd(a, b)$ of non-negative big integers.
pub fn gcd_biguint(a: &BigUint, b: &BigUint) -> BigUint {
    let (mut a, mut b) = if a >= b {
        (a.clone(), b.clone())
    } else {
        (b.clone(), a.clone())
    };
    while b.bits() > 64 {
        let shift = a.bits() - 64;
        let mut x = (&a >> shift).to_u64().expect("64 bits") as i128;
        let mut y = (&b >> shift).to_u64().unwrap_or(0) as i128;
        let (mut ca, mut cb, mut cc, mut cd) = (1i128, 0i128, 0i128, 1i128);
        loop {
            if y + cc == 0 || y + cd == 0 {
                break;
            }
            let q = quot(x + ca, y + cc);
            if q != quot(x + cb, y + cd) {
                break;
            }
            (ca, cc) = (cc, ca - q * cc);
            (cb, cd) = (cd, cb - q * cd);
            (x, y) = (y, x - q * y);
        }
        if cb == 0 {
            let r = &a % &b;
            a = std::mem::replace(&mut b, r);
        } else {
            let na = combine(&a, &b, ca, cb);
            let nb = combine(&a, &b, cc, cd);
            a = na;
            b = nb;
        }
    }
    if b.is_zero() {
        return a;
    }
    let mut y = b.to_u64().expect("64 bits");
    let mut x = (&a % y).to_u64().expect("below y");
    while x != 0 {
        (x, y) = (y % x, x);
    }
    BigUint::from(y)
}

/// Truncated quotient, with word division whenever both operands fit a `u64`.
#[inline(always)]
fn quot(a: i128, b: i128) -> i128 {
    if a >= 0 && b > 0 && a <= u64::MAX as i128 && b <= u64::MAX as i128 {
        ((a as u64) / (b as u64)) as i128
    } else {
        a / b
    }
}

/// $s a + t b$ for cofactors of opposite signs (or one zero) whose result is non-negative.
fn combine(a: &BigUint, b: &BigUint, s: i128, t: i128) -> BigUint {
    let (us, ut) = (
        BigUint::from(s.unsigned_abs()),
        BigUint::from(t.unsigned_abs()),
    );
    if s >= 0 && t <= 0 {
        a * us - b * ut
    } else {
        b * ut - a * us
    }
}

/// $\gcd(a, b) \ge 0$ of big integers.
pub fn gcd(a: &BigInt, b: &BigInt) -> BigInt {
    BigInt::from_biguint(Sign::Plus, gcd_biguint(a.magnitude(), b.magnitude()))
}

/// The canonical fraction $n / d$ for $d \neq 0$ (lowest terms, positive denominator).
pub fn fraction(n: BigInt, d: &BigInt) -> Rational {
    if n.is_zero() {
        return Rational::zero();
    }
    let g = gcd(&n, d);
    let (n, d) = if g.is_one() {
        (n, d.clone())
    } else {
        (n.div_floor(&g), d.div_floor(&g))
    };
    if d.sign() == Sign::Minus {
        Rational::new_raw(-n, -d)
    } else {
        Rational::new_raw(n, d)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn matches_binary_gcd() {
        let mut x: u64 = 88172645463325252;
        let mut next = || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x
        };
        for round in 0..200 {
            let mk = |k: usize, next: &mut dyn FnMut() -> u64| {
                (0..k).fold(BigUint::zero(), |acc, _| (acc << 64u32) + next())
            };
            let g = mk(1 + round % 3, &mut next);
            let a = mk(round % 9, &mut next) * &g;
            let b = mk(round % 7, &mut next) * &g;
            assert_eq!(gcd_biguint(&a, &b), a.gcd(&b), "a = {a}, b = {b}");
        }
        let f = fraction(BigInt::from(-6), &BigInt::from(-4));
        assert_eq!(f, Rational::new(BigInt::from(3), BigInt::from(2)));
        assert_eq!(f.denom(), &BigInt::from(2));
    }
}
