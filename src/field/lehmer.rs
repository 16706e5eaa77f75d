//! Lehmer's gcd for big integers, and canonical fractions built with it.
//!
//! num-bigint's gcd is binary (Stein), quadratic in the bit length with a large constant;
//! reducing thousands of reconstructed fractions $N_{ij}/d$ of several hundred bits to
//! lowest terms is dominated by it. Lehmer's algorithm (Knuth, TAOCP vol. 2, 4.5.2,
//! Algorithm L) simulates the Euclidean quotients on the leading 64 bits and applies them
//! in batches, one multi-precision linear combination per ~30 quotients.
//!
//! [`add`], [`sub`] and [`mul`] are the canonical rational operations on top of it
//! (Knuth, TAOCP vol. 2, 4.5.1: cross-cancel before multiplying, one gcd with the common
//! factor of the denominators after adding), with word-free fast paths for integers. They
//! return exactly what num-rational's operators return; the quadratic field's arithmetic,
//! whose coefficients grow to hundreds of bits in Jordan chains and polynomial remainders,
//! uses them.

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
    if a.magnitude().is_one() || b.magnitude().is_one() {
        return BigInt::one();
    }
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

/// `x * y`, canonical (same value and representation as `x * y` in num-rational).
pub fn mul(x: &Rational, y: &Rational) -> Rational {
    if x.is_zero() || y.is_zero() {
        return Rational::zero();
    }
    let (a, b) = (x.numer(), x.denom());
    let (c, d) = (y.numer(), y.denom());
    if b.is_one() && d.is_one() {
        return Rational::new_raw(a * c, BigInt::one());
    }
    // gcd(a, d) and gcd(c, b) cancel before the products; the result is in lowest terms
    let g1 = if d.is_one() { BigInt::one() } else { gcd(a, d) };
    let g2 = if b.is_one() { BigInt::one() } else { gcd(c, b) };
    let q = |x: &BigInt, g: &BigInt| if g.is_one() { x.clone() } else { x / g };
    Rational::new_raw(q(a, &g1) * q(c, &g2), q(b, &g2) * q(d, &g1))
}

/// `x + y`, canonical.
pub fn add(x: &Rational, y: &Rational) -> Rational {
    add_or_sub(x, y, false)
}

/// `x - y`, canonical.
pub fn sub(x: &Rational, y: &Rational) -> Rational {
    add_or_sub(x, y, true)
}

fn add_or_sub(x: &Rational, y: &Rational, minus: bool) -> Rational {
    let pm = |p: BigInt, q: BigInt| if minus { p - q } else { p + q };
    if y.is_zero() {
        return x.clone();
    }
    if x.is_zero() {
        return if minus { -y } else { y.clone() };
    }
    let (a, b) = (x.numer(), x.denom());
    let (c, d) = (y.numer(), y.denom());
    if b.is_one() && d.is_one() {
        return Rational::new_raw(pm(a.clone(), c.clone()), BigInt::one());
    }
    if b == d {
        // also the integer case b = d = 1, where `fraction` finds gcd(n, 1) = 1 at once
        return fraction(pm(a.clone(), c.clone()), b);
    }
    // one denominator 1: gcd(a d +- c, d) = gcd(c, d) = 1, already canonical
    if b.is_one() {
        return Rational::new_raw(pm(a * d, c.clone()), d.clone());
    }
    if d.is_one() {
        return Rational::new_raw(pm(a.clone(), c * b), b.clone());
    }
    let g = gcd(b, d);
    if g.is_one() {
        return Rational::new_raw(pm(a * d, c * b), b * d);
    }
    // b = g b1, d = g d1: x +- y = (a d1 +- c b1) / (g b1 d1); only g can share factors
    let (b1, d1) = (b / &g, d / &g);
    let t = pm(a * &d1, c * &b1);
    if t.is_zero() {
        return Rational::zero();
    }
    let g2 = gcd(&t, &g);
    if g2.is_one() {
        Rational::new_raw(t, b1 * d)
    } else {
        Rational::new_raw(t / &g2, b1 * (d / &g2))
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

    #[test]
    fn rational_ops_match_num_rational() {
        let mut x: u64 = 0x9E37_79B9_7F4A_7C15;
        let mut next = move || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x
        };
        let mut vals = vec![Rational::zero(), Rational::one(), -Rational::one()];
        let shared = BigInt::from(6_u64) * BigInt::from(next() | 1);
        for k in 0..60 {
            let words = 1 + k % 4;
            let mut n = (0..words).fold(BigInt::zero(), |acc, _| (acc << 64u32) + next());
            if k % 3 == 0 {
                n = -n;
            }
            let d = match k % 5 {
                0 => BigInt::one(),
                1 => shared.clone(),
                2 => shared.clone() * BigInt::from(next() % 1000 + 1),
                _ => BigInt::from(next() % 1_000_000 + 1) << (k % 70),
            };
            vals.push(Rational::new(n, d));
        }
        for x in &vals {
            for y in &vals {
                assert_eq!(mul(x, y), x * y, "{x} * {y}");
                assert_eq!(add(x, y), x + y, "{x} + {y}");
                let s = sub(x, y);
                assert_eq!(s, x - y, "{x} - {y}");
                // canonical representation: lowest terms, positive denominator
                assert!(s.denom().sign() == Sign::Plus && s.numer().gcd(s.denom()).is_one());
            }
        }
        // opposite values cancel to the canonical zero
        let h = Rational::new(BigInt::from(1), BigInt::from(6));
        assert_eq!(add(&h, &-h.clone()).denom(), &BigInt::one());
    }
}
