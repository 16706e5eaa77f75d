//! Exact expressions: `"-(a*cf - b*cr)/(Izz*u)"`, `"1 - sqrt(2)/2"`, `"2 + i"`, `"2^-3"`.
//!
//! Grammar ([`crate::field::expr`], the one reader; `^` right-associative and binding tighter than unary minus,
//! so `-2^2 = -4` and `2^3^2 = 2^9`):
//!
//! ```text
//! expr  := term (('+' | '-') term)*
//! term  := unary (('*' | '/') unary)*
//! unary := ('-' | '+') unary | power
//! power := atom ('^' unary)?
//! atom  := number | name | 'i' | 'sqrt' '(' expr ')' | '(' expr ')'
//! ```
//!
//! A number written directly before `i` (`2i`, `0.5i`) is an implicit multiplication that
//! binds exactly like the written-out `*`: `2i^2` is `2*i^2 = -2` and `1/2i` is
//! `1/2*i = i/2` (not `-4` and `-i/2`). No other implicit multiplication exists: `2x` and
//! `2 x` are errors.
//!
//! Numbers are exact decimals (`0.08`, `1.5e-3`, any number of digits). A value is
//! $a + b\sqrt d$ with $a, b \in \mathbb{Q}$ and at most one square-free radicand `d`
//! per expression: `i` is $\sqrt{-1}$, `sqrt(r)` of a rational `r` is reduced to
//! $s\sqrt f$ with $r = s^2 f$ (`sqrt(8) = 2*sqrt(2)`, `sqrt(9) = 3`,
//! `sqrt(1/2) = sqrt(2)/2`); a product of two square roots is one (`sqrt(3)*i` is
//! $\sqrt{-3}$, `sqrt(2)*sqrt(3)` is $\sqrt 6$), so every display of a quadratic number
//! ([`crate::report::display::quadratic_display`]: `-3/20 - sqrt(1991)*i/20`) reads back. `pi` is rejected (transcendental); `i`, `sqrt`, `pi` are
//! never parameter names.
//!
//! Every input gives a value or an [`Error::Invalid`] in time bounded by the input length:
//! expressions have at most [`MAX_EXPR_LEN`] characters (longer ones are refused before
//! parsing), exponents satisfy $|n| \le 10^4$ (also in literals such as `1e-3`), literals have at most
//! 4000 characters, intermediate numbers stay below $2^{14}$ bits (about 4900 digits),
//! nesting below 256 levels, radicands below $10^{18}$ (so the square-free split is exact).
//!
//! | entry point | computes |
//! |---|---|
//! | [`eval_expr`] | the exact value of one expression over given parameters |
//! | [`is_parameter_name`] | whether a string may name a parameter |

pub(crate) use super::value::{Value, err};
use super::{ExactScalar, Ground};
use crate::error::{Error, Result};
use crate::field::expr::{Algebra, Dialect, SyntaxError, evaluate};
use crate::field::{QuadraticField, Rational};
use num_bigint::BigInt;
use num_traits::{One, Zero};

/// Longest accepted expression (characters), checked before it is read: a longer entry is
/// refused at once (a 300 KB product took 20 s to reach the bit bound). Also the bound of
/// `G` entries and of symbolic entries.
pub const MAX_EXPR_LEN: usize = 10_000;

/// Names that are never parameters ([`crate::field::expr::RESERVED`]).
pub const RESERVED: [&str; 3] = crate::field::expr::RESERVED;

/// Is `s` usable as a parameter name: an identifier `[A-Za-z_][A-Za-z0-9_]*` that is not
/// one of [`RESERVED`]?
pub fn is_parameter_name(s: &str) -> bool {
    let mut cs = s.chars();
    matches!(cs.next(), Some(c) if c.is_ascii_alphabetic() || c == '_')
        && cs.all(|c| c.is_ascii_alphanumeric() || c == '_')
        && !RESERVED.contains(&s)
}

/// Exact value of `text` over `params`, whose values live in `ground`.
///
/// Returns the value and the field it needs: [`Ground::Rational`] when it is rational,
/// else the quadratic field of its radicand (which may differ from `ground` when the text
/// itself introduces `i` or a square root without using a non-rational parameter; checking
/// that all values of a file share one field is the caller's business).
///
/// # Examples
/// ```
/// use exactlti::io::{ExactScalar, Ground, eval_expr};
/// let p = vec![("m".to_string(), ExactScalar::from_i64(1500))];
/// let (x, g) = eval_expr("1/m + 0.08", &p, &Ground::Rational).unwrap();
/// assert_eq!(g.fmt_scalar(&x), "121/1500");
/// let (x, g) = eval_expr("1 - sqrt(8)/4", &[], &Ground::Rational).unwrap();
/// assert_eq!(g.fmt_scalar(&x), "1 - sqrt(2)/2");
/// assert_eq!(g.to_string(), "QQ(sqrt(2))");
/// ```
///
/// # Errors
/// Syntax errors (with the 1-based character position), unknown parameters, `pi`,
/// division by zero, `0` to a negative power, non-integer or too large exponents, two
/// different radicands in one expression, and the size limits of the module docs.
pub fn eval_expr(
    text: &str,
    params: &[(String, ExactScalar)],
    ground: &Ground,
) -> Result<(ExactScalar, Ground)> {
    let k = match ground {
        Ground::Rational | Ground::RatFunc(_) => None,
        Ground::Quadratic(k) => Some(k.clone()),
    };
    let lookup = |name: &str| {
        params.iter().find(|(n, _)| n == name).map(|(_, x)| {
            Value::new(
                x.a.clone(),
                x.b.clone(),
                if x.b.is_zero() { None } else { k.clone() },
            )
        })
    };
    let v = eval_with(text, &lookup)?;
    let g = match &v.k {
        None => Ground::Rational,
        Some(k) => Ground::Quadratic(k.clone()),
    };
    Ok((ExactScalar { a: v.a, b: v.b }, g))
}

pub(crate) use crate::field::expr::referenced_names;

/// Refuses an expression longer than [`MAX_EXPR_LEN`] characters (before any parsing).
///
/// # Errors
/// The length and the bound.
pub fn too_long(text: &str) -> Result<()> {
    let n = text.chars().count();
    if text.len() > MAX_EXPR_LEN && n > MAX_EXPR_LEN {
        return err(format!(
            "expression of {n} characters (at most {MAX_EXPR_LEN}): not read"
        ));
    }
    Ok(())
}

/// The value of a plain `[-]digits[/digits]` (at most 18 digits each, a non-zero
/// denominator, no spaces): the shape of a user's decimal data written as fractions,
/// read without the parser and with one word gcd (issue 29: 10^4 entries of a rational
/// matrix); `None` for every other text (the parser decides it, with its messages).
fn plain_fraction(text: &str) -> Option<Rational> {
    fn digits(s: &str) -> Option<i64> {
        let ok = !s.is_empty() && s.len() <= 18 && s.bytes().all(|b| b.is_ascii_digit());
        ok.then(|| s.parse().ok()).flatten()
    }
    let (neg, body) = match text.as_bytes().first()? {
        b'-' => (true, &text[1..]),
        _ => (false, text),
    };
    let (p, q) = match body.split_once('/') {
        Some((p, q)) => (digits(p)?, digits(q)?),
        None => (digits(body)?, 1),
    };
    if q == 0 {
        return None;
    }
    let g = num_integer::Integer::gcd(&p, &q);
    let p = if neg { -(p / g) } else { p / g };
    Some(Rational::new_raw(BigInt::from(p), BigInt::from(q / g)))
}

/// Evaluates `text`; `lookup` gives the value of a parameter name (`None`: unknown).
pub(crate) fn eval_with(text: &str, lookup: &dyn Fn(&str) -> Option<Value>) -> Result<Value> {
    too_long(text)?;
    if let Some(q) = plain_fraction(text) {
        return Ok(Value::rational(q));
    }
    evaluate(&Exact { lookup }, text, Dialect::EXACT)
}

/// The algebra of values $a + b\sqrt d$ ([`Value`]) with parameters from `lookup`.
struct Exact<'a> {
    lookup: &'a dyn Fn(&str) -> Option<Value>,
}

impl Algebra for Exact<'_> {
    type Value = Value;
    type Error = Error;
    fn syntax(&self, e: SyntaxError) -> Error {
        e.into_invalid()
    }
    fn number(&self, s: &str, _: usize) -> Result<Value> {
        Value::rational(parse_number(s)?).checked()
    }
    fn name(&self, n: &str, _: usize) -> Result<Value> {
        match n {
            "pi" => err("pi is transcendental; give a rational approximation such as 355/113"),
            "i" => Ok(imaginary_unit()),
            "sqrt" => err("sqrt needs an argument in parentheses, e.g. sqrt(2)"),
            _ => (self.lookup)(n).ok_or_else(|| Error::Invalid(format!("unknown parameter '{n}'"))),
        }
    }
    fn call(&self, f: &str, mut args: Vec<Value>, _: usize) -> Result<Value> {
        match f {
            "pi" => err("pi is transcendental; give a rational approximation such as 355/113"),
            "sqrt" if args.len() == 1 => args.pop().expect("one argument").sqrt(),
            "sqrt" => err("sqrt takes one argument, e.g. sqrt(2)"),
            _ => err(format!("unknown function '{f}' (only sqrt is available)")),
        }
    }
    fn neg(&self, a: Value, _: usize) -> Result<Value> {
        Ok(a.neg())
    }
    fn add(&self, a: Value, b: Value, subtract: bool, _: usize) -> Result<Value> {
        a.add(&if subtract { b.neg() } else { b })
    }
    fn mul(&self, a: Value, b: Value, divide: bool, _: usize) -> Result<Value> {
        a.mul(&if divide { b.inv()? } else { b })
    }
    fn pow(&self, a: Value, e: Value, _: usize) -> Result<Value> {
        a.pow(&e)
    }
}

/// A number literal, within the size limits ([`crate::field::expr::parse_number`]).
pub(crate) fn parse_number(s: &str) -> Result<Rational> {
    crate::field::expr::parse_number(s).map_err(Error::Invalid)
}

fn imaginary_unit() -> Value {
    Value::new(
        Rational::zero(),
        Rational::one(),
        Some(QuadraticField::gaussian()),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    fn ev(s: &str) -> std::result::Result<String, String> {
        eval_expr(s, &[], &Ground::Rational)
            .map(|(x, g)| g.fmt_scalar(&x))
            .map_err(|e| e.to_string())
    }
    /// The plain-fraction shortcut gives what the parser gives, on a generator of the
    /// shapes it takes (signs, zeros, long digit strings) and of near misses it leaves to the
    /// parser (spaces, a plus sign, a zero denominator, 19 digits, two slashes).
    #[test]
    fn plain_fractions_as_the_parser() {
        let parsed = |s: &str| {
            evaluate(&Exact { lookup: &|_| None }, s, Dialect::EXACT)
                .map(|v| v.a)
                .map_err(|e| e.to_string())
        };
        let mut g = crate::rng::SplitMix64(29);
        for _ in 0..500 {
            let p = g.next_u64() % 10u64.pow((g.next_u64() % 19) as u32);
            let q = g.next_u64() % 10u64.pow((g.next_u64() % 19) as u32);
            let sign = if g.next_u64().is_multiple_of(2) {
                "-"
            } else {
                ""
            };
            for s in [
                format!("{sign}{p}/{q}"),
                format!("{sign}{p}"),
                format!("{sign}0{p}"),
            ] {
                let want = parsed(&s);
                if let Some(x) = plain_fraction(&s) {
                    assert_eq!(Ok(x), want, "{s}");
                }
                assert_eq!(
                    eval_with(&s, &|_| None)
                        .map(|v| v.a)
                        .map_err(|e| e.to_string()),
                    want
                );
            }
            let s = format!("{sign}{p}/{q}");
            assert_eq!(
                plain_fraction(&s).is_some(),
                q != 0,
                "{s} takes the shortcut"
            );
        }
        for s in [
            "1 /2",
            "+1/2",
            "1/0",
            "1/2/3",
            "1234567890123456789/2",
            "-",
            "/2",
            "1/",
        ] {
            assert_eq!(plain_fraction(s), None, "{s}");
        }
        assert_eq!(ev("1/0").unwrap_err(), parsed("1/0").unwrap_err());
        assert_eq!(ev("-6/4").unwrap(), "-3/2");
    }

    #[test]
    fn examples() {
        assert_eq!(ev("1 + 2*3").unwrap(), "7");
        assert_eq!(ev("-2^2").unwrap(), "-4");
        assert_eq!(ev("2^3^2").unwrap(), "512");
        assert_eq!(ev("2^-2").unwrap(), "1/4");
        assert_eq!(ev("(1/2)^-3").unwrap(), "8");
        assert_eq!(ev("0^0").unwrap(), "1");
        assert_eq!(ev("sqrt(8)").unwrap(), "2*sqrt(2)");
        assert_eq!(ev("sqrt(9)").unwrap(), "3");
        assert_eq!(ev("sqrt(1/2)").unwrap(), "sqrt(2)/2");
        assert_eq!(ev("sqrt(-4)").unwrap(), "2*i");
        assert_eq!(ev("sqrt(2)*sqrt(2)").unwrap(), "2");
        assert_eq!(ev("(1+i)^2").unwrap(), "2*i");
        assert_eq!(ev("1/(1+i)").unwrap(), "1/2 - i/2");
        assert_eq!(ev("3i").unwrap(), "3*i");
        assert_eq!(ev("2i^2").unwrap(), ev("2*i^2").unwrap());
        assert_eq!(ev("2i^2").unwrap(), "-2");
        assert_eq!(ev("1/2i").unwrap(), ev("1/2*i").unwrap());
        assert_eq!(ev("1/2i").unwrap(), "i/2");
        assert_eq!(ev("-0.5i^3").unwrap(), "i/2");
        assert_eq!(ev("2i3").unwrap_err(), "'2i3' is not a number");
        assert_eq!(ev("i^2").unwrap(), "-1");
        assert_eq!(ev("1.5e-3").unwrap(), "3/2000");
        assert_eq!(ev("2e").unwrap_err(), "'2e' is not a number");
        assert_eq!(
            ev("2 e").unwrap_err(),
            "unexpected 'e' at position 3 in '2 e'"
        );
    }
    #[test]
    fn errors() {
        assert_eq!(ev("1/0").unwrap_err(), "division by zero");
        assert_eq!(ev("1/(2-2)").unwrap_err(), "division by zero");
        assert!(ev("0^-1").unwrap_err().starts_with("division by zero"));
        assert!(ev("2^10001").unwrap_err().contains("too large"));
        assert!(ev("10^10000^10000").unwrap_err().contains("too large"));
        assert!(ev("2^(1/2)").unwrap_err().contains("integer"));
        assert!(ev("pi").unwrap_err().starts_with("pi is transcendental"));
        assert!(ev("sqrt(2) + i").unwrap_err().contains("cannot be mixed"));
        assert!(
            ev("(1 + sqrt(2))*i")
                .unwrap_err()
                .contains("cannot be mixed")
        );
        // products of square roots are square roots
        assert_eq!(ev("sqrt(3)*i/2").unwrap(), "sqrt(3)*i/2");
        assert_eq!(ev("i*sqrt(3)").unwrap(), "sqrt(3)*i");
        assert_eq!(ev("sqrt(2)*sqrt(3)").unwrap(), "sqrt(6)");
        assert_eq!(ev("sqrt(6)*sqrt(-3)").unwrap(), "3*sqrt(2)*i");
        assert_eq!(ev("sqrt(-2)*sqrt(-3)").unwrap(), "-sqrt(6)");
        assert_eq!(ev("sqrt(2)*sqrt(-2)").unwrap(), "2*i");
        assert_eq!(
            ev("-3/20 - sqrt(1991)*i/20 + 3/20").unwrap(),
            "-sqrt(1991)*i/20"
        );
        assert_eq!(ev("(1+2").unwrap_err(), "missing ')' at the end of '(1+2'");
        assert_eq!(
            ev("1+2)").unwrap_err(),
            "unexpected ')' at position 4 in '1+2)'"
        );
        assert_eq!(ev("").unwrap_err(), "empty expression");
        assert_eq!(ev("1.2.3").unwrap_err(), "'1.2.3' is not a number");
        assert_eq!(ev("12abc").unwrap_err(), "'12abc' is not a number");
        assert!(ev("cos(1)").unwrap_err().contains("unknown function"));
        assert!(
            ev(&"(".repeat(1000))
                .unwrap_err()
                .contains("nested too deeply")
        );
        assert!(
            ev(&"-".repeat(1000))
                .unwrap_err()
                .contains("nested too deeply")
        );
        assert!(ev("sqrt(10^40+1)").unwrap_err().contains("too large"));
        assert!(ev("9999^9999").unwrap_err().contains("too large"));
        assert!(ev("1e-10001").unwrap_err().contains("too large"));
        assert!(
            ev(&"1".repeat(6000))
                .unwrap_err()
                .contains("more than 4000")
        );
        assert_eq!(ev("(-2/3)^-3").unwrap(), "-27/8");
        assert_eq!(ev("(-2/3)^3").unwrap(), "-8/27");
    }
    #[test]
    fn names() {
        assert!(is_parameter_name("cf"));
        assert!(is_parameter_name("I_zz2"));
        assert!(!is_parameter_name("i"));
        assert!(!is_parameter_name("pi"));
        assert!(!is_parameter_name("2a"));
        assert!(!is_parameter_name(""));
        assert_eq!(
            referenced_names("-(a*cf - b)/sqrt(a) + i"),
            ["a", "cf", "b"]
        );
    }
}
