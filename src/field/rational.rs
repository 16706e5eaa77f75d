//! The rational field $\mathbb{Q}$ on num-rational's `BigRational`.
//!
//! Parsing is exact: `0.08` is $2/25$, `1.5e-3` is $3/2000$, `-3/7` is $-3/7$; no binary
//! floating point is ever involved.

use super::{Field, Kernels, RationalElems, lehmer};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, ToPrimitive, Zero};

/// An exact rational number (canonical: lowest terms, positive denominator).
pub type Rational = num_rational::BigRational;

/// The field $\mathbb{Q}$ (zero-sized domain value).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Q;

impl Q {
    /// Floating-point approximation `(a, 0)`; always defined (the field trait's
    /// [`Field::approx`] wraps it in `Some`).
    pub fn approx(&self, a: &Rational) -> (f64, f64) {
        (rational_to_f64(a), 0.0)
    }
}

impl Field for Q {
    type Elem = Rational;
    fn zero(&self) -> Rational {
        Rational::zero()
    }
    fn one(&self) -> Rational {
        Rational::one()
    }
    fn is_zero(&self, a: &Rational) -> bool {
        a.is_zero()
    }
    fn is_one(&self, a: &Rational) -> bool {
        a.is_one()
    }
    fn add(&self, a: &Rational, b: &Rational) -> Rational {
        lehmer::add(a, b)
    }
    fn sub(&self, a: &Rational, b: &Rational) -> Rational {
        lehmer::sub(a, b)
    }
    fn mul(&self, a: &Rational, b: &Rational) -> Rational {
        lehmer::mul(a, b)
    }
    fn neg(&self, a: &Rational) -> Rational {
        -a
    }
    fn inv(&self, a: &Rational) -> Option<Rational> {
        if a.is_zero() { None } else { Some(a.recip()) }
    }
    fn from_rational(&self, q: &Rational) -> Rational {
        q.clone()
    }
    fn to_rational(&self, a: &Rational) -> Option<Rational> {
        Some(a.clone())
    }
    fn mul_add_assign(&self, acc: &mut Rational, a: &Rational, b: &Rational) {
        if !a.is_zero() && !b.is_zero() {
            *acc = lehmer::add(acc, &lehmer::mul(a, b));
        }
    }
    fn mul_sub_assign(&self, acc: &mut Rational, a: &Rational, b: &Rational) {
        if !a.is_zero() && !b.is_zero() {
            *acc = lehmer::sub(acc, &lehmer::mul(a, b));
        }
    }
    fn approx(&self, a: &Rational) -> Option<(f64, f64)> {
        Some(Q::approx(self, a))
    }
    fn conj(&self, a: &Rational) -> Option<Rational> {
        Some(a.clone())
    }
    fn sign(&self, a: &Rational) -> Option<std::cmp::Ordering> {
        Some(a.cmp(&Rational::zero()))
    }
    fn mul_mod_poly(
        &self,
        m: &[Rational],
        a: &[Rational],
        b: &[Rational],
    ) -> Option<Vec<Rational>> {
        m.iter()
            .all(|c| c.is_integer())
            .then(|| super::rational_mulmod::mul_integral(m, a, b))
    }
    fn kernels(&self) -> Kernels<'_, Q> {
        Kernels::Rational(RationalElems::IDENTITY)
    }
}

/// Nearest-ish `f64` of an exact rational, robust for huge numerators and denominators.
pub fn rational_to_f64(a: &Rational) -> f64 {
    if let (Some(n), Some(d)) = (a.numer().to_f64(), a.denom().to_f64())
        && n.is_finite()
        && d.is_finite()
        && n.abs() < 9.0e15
        && d < 9.0e15
    {
        return n / d;
    }
    // scale both to ~60 significant bits
    let nb = a.numer().bits() as i64;
    let db = a.denom().bits() as i64;
    let shift = nb - db - 60;
    let q = if shift >= 0 {
        a.numer() / (a.denom() << (shift as usize))
    } else {
        (a.numer() << ((-shift) as usize)) / a.denom()
    };
    let qf = q.to_f64().unwrap_or(0.0);
    qf * 2f64.powi(shift.clamp(-2000, 2000) as i32)
}

/// Parses an exact rational: integers of any size, `-3/7`, decimals `0.08`, `.5`, `2.`,
/// and scientific `1.5e-3`, `1E5`. Surrounding whitespace is allowed.
///
/// # Errors
/// A message describing the first offending character, or a zero denominator.
pub fn parse_rational(text: &str) -> Result<Rational, String> {
    let s = text.trim();
    if s.is_empty() {
        return Err("empty number".into());
    }
    if let Some((n, d)) = s.split_once('/') {
        let n = parse_decimal(n.trim())?;
        let d = parse_decimal(d.trim())?;
        if d.is_zero() {
            return Err(format!("zero denominator in '{s}'"));
        }
        return Ok(n / d);
    }
    parse_decimal(s)
}

fn parse_decimal(s: &str) -> Result<Rational, String> {
    let (neg, body) = match s.as_bytes().first() {
        Some(b'-') => (true, &s[1..]),
        Some(b'+') => (false, &s[1..]),
        _ => (false, s),
    };
    let (mant, exp) = match body.find(['e', 'E']) {
        Some(p) => (&body[..p], Some(&body[p + 1..])),
        None => (body, None),
    };
    let (int_part, frac_part) = match mant.split_once('.') {
        Some((a, b)) => (a, b),
        None => (mant, ""),
    };
    if int_part.is_empty() && frac_part.is_empty() {
        return Err(format!("'{s}' is not a number"));
    }
    if !int_part.bytes().all(|c| c.is_ascii_digit())
        || !frac_part.bytes().all(|c| c.is_ascii_digit())
    {
        return Err(format!("'{s}' is not a number"));
    }
    let digits = format!("{int_part}{frac_part}");
    let mut num: BigInt = if digits.is_empty() {
        BigInt::zero()
    } else {
        digits
            .parse()
            .map_err(|_| format!("'{s}' is not a number"))?
    };
    let mut e: i64 = -(frac_part.len() as i64);
    if let Some(ex) = exp {
        let ev: i64 = ex.parse().map_err(|_| format!("bad exponent in '{s}'"))?;
        if ev.abs() > 100_000 {
            return Err(format!("exponent too large in '{s}'"));
        }
        e += ev;
    }
    if neg {
        num = -num;
    }
    let ten = BigInt::from(10);
    let r = if e >= 0 {
        Rational::from_integer(num * num_traits::pow(ten, e as usize))
    } else {
        Rational::new(num, num_traits::pow(ten, (-e) as usize))
    };
    Ok(r)
}

/// Least common multiple of the denominators of `xs` (1 for an empty slice).
pub fn denominator_lcm<'a>(xs: impl IntoIterator<Item = &'a Rational>) -> BigInt {
    xs.into_iter().fold(BigInt::one(), |l, x| l.lcm(x.denom()))
}

#[cfg(test)]
mod tests {
    use super::*;
    fn r(n: i64, d: i64) -> Rational {
        Rational::new(n.into(), d.into())
    }
    #[test]
    fn parse_examples() {
        assert_eq!(parse_rational("0.08").unwrap(), r(2, 25));
        assert_eq!(parse_rational("1.5e-3").unwrap(), r(3, 2000));
        assert_eq!(parse_rational("-3/7").unwrap(), r(-3, 7));
        assert_eq!(parse_rational("0.").unwrap(), r(0, 1));
        assert_eq!(parse_rational(".5").unwrap(), r(1, 2));
        assert_eq!(parse_rational("1E2").unwrap(), r(100, 1));
        assert_eq!(
            parse_rational(" 12345678901234567890123 ")
                .unwrap()
                .numer()
                .to_string(),
            "12345678901234567890123"
        );
        assert!(parse_rational("1/0").is_err());
        assert!(parse_rational("abc").is_err());
        assert!(parse_rational("-").is_err());
        assert!(parse_rational("1e").is_err());
    }
    #[test]
    fn to_f64() {
        assert_eq!(rational_to_f64(&r(1, 4)), 0.25);
        let big = Rational::new(
            BigInt::from(10).pow(400u32) + 1,
            BigInt::from(10).pow(399u32),
        );
        assert!((rational_to_f64(&big) - 10.0).abs() < 1e-12);
    }
}
