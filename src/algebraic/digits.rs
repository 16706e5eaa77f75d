//! Exact decimal rounding (the certified digits of algebraic numbers) and the radicals of
//! quadratic roots; their displays are made in `report::display::algebraic`.
//!
//! | entry point | computes |
//! |---|---|
//! | [`round_sig`] | a rational rounded (half away from zero) to `n` significant digits |
//! | [`split_square`] | $n = s^2 d$ with $d$ square-free |
//! | [`quadratic_roots`] | the roots $a_0 \pm s\sqrt f$ of a monic quadratic |

use crate::field::{Q, QuadraticField, Rational};
use crate::poly::Poly;
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

/// `n = s^2 d` with `d` square-free (up to square factors of primes above `10^6` whose
/// cofactor is no perfect square); returns `(s, d)` (sign kept in `d`). The same split as
/// [`crate::field::quadratic::squarefree_split`], so every display of a quadratic number
/// names the same radicand.
pub fn split_square(n: &BigInt) -> (BigInt, BigInt) {
    crate::field::quadratic::squarefree_split(n)
}

/// For a monic quadratic $x^2 + b x + c$: roots $a_0 \pm s\sqrt f$ as `(a0, s, f)` with
/// `s > 0` and `f` square-free (`None` when the roots are rational).
pub fn quadratic_roots(p: &Poly<Q>) -> Option<(Rational, Rational, BigInt)> {
    let b = p.coeff(1);
    let c = p.coeff(0);
    let half = Rational::new(1.into(), 2.into());
    let a0 = -&b * &half;
    let disc4 = &a0 * &a0 - c; // (b^2 - 4c)/4
    let (field, _, s) = QuadraticField::sqrt_of_rational(&disc4);
    field.map(|k| (a0, s, k.d().clone()))
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
    fn square_free_parts() {
        let b = BigInt::from;
        assert_eq!(split_square(&b(-20)), (b(2), b(-5)));
        assert_eq!(split_square(&b(49)), (b(7), b(1)));
    }
}
