//! Exact decimal rounding and closed-form display of algebraic numbers.
//!
//! | entry point | computes |
//! |---|---|
//! | [`round_sig`] | a rational rounded (half away from zero) to `n` significant digits |
//! | [`quadratic_string`] | `a + b sqrt(d)` as `1/2 + sqrt(5)/2`, `-1 + i`, `sqrt(2)*i/2` ([`crate::field::quadratic_display`]) |
//! | [`approx_text`], [`near_text`] | the `near` part of `root of P near X` (10 significant digits) |
//! | [`closed_form`] | the closed form of a root of an irreducible polynomial: degree 1, 2 and $x^4 + b x^2 + c$ |

use crate::field::{Q, QuadraticField, Rational, quadratic_display, rational_to_f64};
use crate::poly::Poly;
use num_bigint::BigInt;
use num_complex::Complex64;
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

/// The `near` part of `root of P near X`, from the decimal strings of the real and imaginary
/// parts: `1.259921050`, `1.931851653*i` (purely imaginary: `re` is `"0"`),
/// `-0.6299605249 - 1.091123636*i`; `real` drops the imaginary part.
pub fn near_text(re: &str, im: &str, real: bool) -> String {
    if real {
        re.to_string()
    } else if re == "0" {
        format!("{im}*i")
    } else if let Some(m) = im.strip_prefix('-') {
        format!("{re} - {m}*i")
    } else {
        format!("{re} + {im}*i")
    }
}

/// [`near_text`] of an `f64` approximation `(re, im)` to 10 significant digits (the exact
/// rounding of the `f64`s), as [`crate::algebraic::AlgebraicNumber::value_string`] writes its
/// certified digits: real when `im == 0`, purely imaginary when `re == 0`.
pub fn approx_text((re, im): (f64, f64)) -> String {
    let digits =
        |x: f64| Rational::from_float(x).map_or_else(|| format!("{x}"), |q| round_sig(&q, 10));
    near_text(&digits(re), &digits(im), im == 0.0)
}

/// `n = s^2 d` with `d` square-free (up to square factors of primes above `10^6` whose
/// cofactor is no perfect square); returns `(s, d)` (sign kept in `d`). The same split as
/// [`crate::field::quadratic::squarefree_split`], so every display of a quadratic number
/// names the same radicand.
pub fn split_square(n: &BigInt) -> (BigInt, BigInt) {
    crate::field::quadratic::squarefree_split(n)
}

/// Display of `a + b*sqrt(d)` (`d` square-free, `d != 1`; `d = -1` is `i`): the one display
/// of quadratic numbers, [`crate::field::quadratic_display`].
pub fn quadratic_string(a: &Rational, b: &Rational, d: &BigInt) -> String {
    if d.is_zero() {
        return crate::field::fmt_rational(a);
    }
    crate::field::quadratic_display(a, b, d)
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

/// The closed form of the root of the irreducible monic `p` nearest `approx`, the one used
/// by every report: the rational for degree 1, [`crate::field::quadratic_display`] for
/// degree 2 (the sign of the radical read off `approx`), and for $x^4 + b x^2 + c$ with a
/// real square root of the discriminant the nested radical `sqrt(u)` / `i*sqrt(-u)`
/// (`i*sqrt(2 - sqrt(3))`); `None` otherwise (the caller writes `root of p near ...`).
///
/// `approx` only chooses among the roots: it must be nearer the wanted root than half the
/// distance to the others (any certified approximation is).
pub fn closed_form(p: &Poly<Q>, approx: (f64, f64)) -> Option<String> {
    match p.deg() {
        1 => Some(crate::field::fmt_rational(&-p.coeff(0))),
        2 => {
            let (a0, s, f) = quadratic_roots(p)?;
            let positive = if f.is_negative() {
                approx.1 > 0.0
            } else {
                approx.0 > rational_to_f64(&a0)
            };
            let coef = if positive { s } else { -s };
            Some(quadratic_display(&a0, &coef, &f))
        }
        4 if p.coeff(1).is_zero() && p.coeff(3).is_zero() => {
            // theta^2 = u with u a root of y^2 + b y + c
            let q = Poly::new(Q, vec![p.coeff(0), p.coeff(2), Rational::one()]);
            let (a0, s, f) = quadratic_roots(&q)?;
            if !f.is_positive() {
                return None;
            }
            let z = Complex64::new(approx.0, approx.1);
            let u = z * z;
            let coef = if u.re > rational_to_f64(&a0) { s } else { -s };
            let u_pos = u.re > 0.0;
            let sign_neg = if u_pos {
                approx.0 < 0.0
            } else {
                approx.1 < 0.0
            };
            let (ua, ub) = if u_pos { (a0, coef) } else { (-a0, -coef) };
            let inner = quadratic_display(&ua, &ub, &f);
            let body = if u_pos {
                format!("sqrt({inner})")
            } else {
                format!("i*sqrt({inner})")
            };
            Some(if sign_neg { format!("-{body}") } else { body })
        }
        _ => None,
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
            "1/2 + sqrt(5)/2"
        );
        assert_eq!(quadratic_string(&r(-1, 1), &r(1, 1), &b(-1)), "-1 + i");
        assert_eq!(quadratic_string(&r(0, 1), &r(1, 2), &b(-2)), "sqrt(2)*i/2");
        assert_eq!(quadratic_string(&r(0, 1), &r(-1, 1), &b(-3)), "-sqrt(3)*i");
        assert_eq!(split_square(&b(-20)), (b(2), b(-5)));
        assert_eq!(split_square(&b(49)), (b(7), b(1)));
    }
}
