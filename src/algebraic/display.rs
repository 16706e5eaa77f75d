//! Exact decimal rounding and closed-form display of algebraic numbers.
//!
//! | entry point | computes |
//! |---|---|
//! | [`round_sig`] | a rational rounded (half away from zero) to `n` significant digits |
//! | [`quadratic_string`] | `a + b sqrt(d)` as `(1 + sqrt(5))/2`, `-1 + i`, `sqrt(2)*i/2` |

use crate::field::Rational;
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};

/// `10^k` as a big integer.
fn pow10(k: usize) -> BigInt {
    num_traits::pow(BigInt::from(10), k)
}

/// The exact rounding of `q` to `n >= 1` significant digits (half away from zero), shown
/// positionally for exponents in `-5..15`, else as `d.ddde-7`.
pub fn round_sig(q: &Rational, n: usize) -> String {
    let n = n.max(1);
    if q.is_zero() {
        return "0".into();
    }
    let neg = q.is_negative();
    let a = q.abs();
    // exponent e with 10^e <= a < 10^(e+1)
    let mut e = (a.numer().to_string().len() as i64) - (a.denom().to_string().len() as i64);
    let pw = |k: i64| -> Rational {
        if k >= 0 {
            Rational::from_integer(pow10(k as usize))
        } else {
            Rational::new(BigInt::one(), pow10((-k) as usize))
        }
    };
    while a < pw(e) {
        e -= 1;
    }
    while a >= pw(e + 1) {
        e += 1;
    }
    // m = round(a * 10^(n - 1 - e))
    let scaled = &a * pw(n as i64 - 1 - e);
    let two = BigInt::from(2);
    let (qq, rr) = scaled.numer().div_rem(scaled.denom());
    let mut m = if &rr * &two >= *scaled.denom() {
        qq + 1
    } else {
        qq
    };
    if m == pow10(n) {
        m = pow10(n - 1);
        e += 1;
    }
    let digits = m.to_string();
    let body = if (-5..15).contains(&e) {
        if e >= n as i64 - 1 {
            format!("{digits}{}", "0".repeat((e - (n as i64 - 1)) as usize))
        } else if e >= 0 {
            let k = (e + 1) as usize;
            format!("{}.{}", &digits[..k], &digits[k..])
        } else {
            format!("0.{}{}", "0".repeat((-e - 1) as usize), digits)
        }
    } else if n == 1 {
        format!("{digits}e{e}")
    } else {
        format!("{}.{}e{e}", &digits[..1], &digits[1..])
    };
    if neg { format!("-{body}") } else { body }
}

/// `n = s^2 d` with `d` free of squares of primes below `2^16` and not a perfect square
/// cofactor; returns `(s, d)` (sign kept in `d`).
pub fn split_square(n: &BigInt) -> (BigInt, BigInt) {
    let sign = if n.is_negative() { -1 } else { 1 };
    let mut m = n.abs();
    let mut s = BigInt::one();
    let mut p: u64 = 2;
    while p < 65536 {
        let pp = BigInt::from(p * p);
        if pp > m {
            break;
        }
        let bp = BigInt::from(p);
        while (&m % &pp).is_zero() {
            m /= &pp;
            s *= &bp;
        }
        p += if p == 2 { 1 } else { 2 };
    }
    let r = num_integer::Roots::sqrt(&m);
    if &r * &r == m && !m.is_one() {
        s *= &r;
        m = BigInt::one();
    }
    (s, m * sign)
}

/// Display of `a + b*sqrt(d)` (`d` square-free, `d != 1`; `d = -1` is `i`).
pub fn quadratic_string(a: &Rational, b: &Rational, d: &BigInt) -> String {
    if b.is_zero() || d.is_zero() {
        return crate::field::fmt_rational(a);
    }
    let l = a.denom().lcm(b.denom());
    let an = (a * Rational::from_integer(l.clone())).to_integer();
    let bn = (b * Rational::from_integer(l.clone())).to_integer();
    let rad = if *d == BigInt::from(-1) {
        "i".to_string()
    } else if d.is_negative() {
        format!("sqrt({})*i", -d)
    } else {
        format!("sqrt({d})")
    };
    let term = if bn.abs().is_one() {
        rad
    } else {
        format!("{}*{rad}", bn.abs())
    };
    let num = if an.is_zero() {
        if bn.is_negative() {
            format!("-{term}")
        } else {
            term
        }
    } else {
        format!("{an} {} {term}", if bn.is_negative() { "-" } else { "+" })
    };
    if l.is_one() {
        num
    } else if an.is_zero() {
        format!("{num}/{l}")
    } else {
        format!("({num})/{l}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    fn r(n: i64, d: i64) -> Rational {
        Rational::new(n.into(), d.into())
    }
    #[test]
    fn rounding() {
        assert_eq!(round_sig(&r(2, 3), 4), "0.6667");
        assert_eq!(round_sig(&r(-1, 8), 2), "-0.13");
        assert_eq!(round_sig(&r(99999, 1), 3), "100000");
        assert_eq!(round_sig(&r(1, 1000000), 2), "1.0e-6");
        assert_eq!(round_sig(&r(3, 1), 1), "3");
        assert_eq!(round_sig(&r(12345, 100), 4), "123.5");
    }
    #[test]
    fn quadratics() {
        let b = BigInt::from;
        assert_eq!(
            quadratic_string(&r(1, 2), &r(1, 2), &b(5)),
            "(1 + sqrt(5))/2"
        );
        assert_eq!(quadratic_string(&r(-1, 1), &r(1, 1), &b(-1)), "-1 + i");
        assert_eq!(quadratic_string(&r(0, 1), &r(1, 2), &b(-2)), "sqrt(2)*i/2");
        assert_eq!(quadratic_string(&r(0, 1), &r(-1, 1), &b(-3)), "-sqrt(3)*i");
        assert_eq!(split_square(&b(-20)), (b(2), b(-5)));
        assert_eq!(split_square(&b(49)), (b(7), b(1)));
    }
}
