//! Rational functions in `s` read AS WRITTEN: the text evaluated as a pair (numerator,
//! denominator) with python-control's and MATLAB's `tf` arithmetic, nothing cancelled:
//! $a/b + c/d = (ad + cb)/(bd)$, $(a/b)(c/d) = ac/(bd)$, $(a/b)/(c/d) = ad/(bc)$,
//! $(a/b)^k = a^k/b^k$ ($k < 0$: $b^{|k|}/a^{|k|}$). So `"(s+1)/((s+1)(s+2))"` keeps the
//! pole at $-1$. The denominator is made monic at the end (a constant factor only); the
//! pair equals [`super::transfer_expr::parse_rational_function`]'s value as a rational
//! function. Same grammar, errors and bounds.

use super::transfer_expr::{InS, MAX_DEG, check_length, int_exponent};
use crate::error::{Error, Result};
use crate::field::expr::{Algebra, Dialect, SyntaxError, error_at as at, evaluate};
use crate::field::{Field, Q, Rational};
use crate::poly::Poly;
use crate::system::transfer::RationalFunction;

/// A written fraction `(num, den)`, `den` non-zero.
type Pair = (Poly<Q>, Poly<Q>);

/// Parses a rational function in `s` as written; `params` gives the values of other names.
///
/// # Errors
/// As [`super::transfer_expr::parse_rational_function`].
///
/// # Examples
/// ```
/// use exactlti::io::transfer_written::parse_written_fraction;
/// let (n, d) = parse_written_fraction("(s+1)/((s+1)*(s+2))", &[]).unwrap();
/// assert_eq!((n.to_string_var("s"), d.to_string_var("s")), ("s + 1".into(), "s^2 + 3*s + 2".into()));
/// ```
pub fn parse_written_fraction(text: &str, params: &[(String, Rational)]) -> Result<Pair> {
    parse_written_fraction_in(text, params, "s")
}

/// [`parse_written_fraction`] in the variable `var` (`z` for a sampled system).
///
/// # Errors
/// As [`parse_written_fraction`].
pub fn parse_written_fraction_in(
    text: &str,
    params: &[(String, Rational)],
    var: &str,
) -> Result<Pair> {
    check_length(text)?;
    let (n, d) = evaluate(&Written(InS { params, var }), text, Dialect::EXACT)?;
    let li = Q.inv(&d.lc()).expect("non-zero denominator");
    Ok((n.scale(&li), d.scale(&li)))
}

struct Written<'a>(InS<'a>);

fn lift(f: RationalFunction<Q>) -> Pair {
    (f.num, f.den)
}

fn check(v: Pair, pos: usize) -> Result<Pair> {
    if v.0.deg() > MAX_DEG || v.1.deg() > MAX_DEG {
        return Err(at(pos, "degree too large"));
    }
    Ok(v)
}

impl Algebra for Written<'_> {
    type Value = Pair;
    type Error = Error;
    fn syntax(&self, e: SyntaxError) -> Error {
        e.to_error()
    }
    fn number(&self, s: &str, pos: usize) -> Result<Pair> {
        self.0.number(s, pos).map(lift)
    }
    fn name(&self, name: &str, pos: usize) -> Result<Pair> {
        self.0.name(name, pos).map(lift)
    }
    fn call(&self, f: &str, _: Vec<Pair>, pos: usize) -> Result<Pair> {
        Err(at(pos, &format!("unknown function '{f}'")))
    }
    fn neg(&self, a: Pair, _: usize) -> Result<Pair> {
        Ok((a.0.neg(), a.1))
    }
    fn add(&self, a: Pair, b: Pair, subtract: bool, pos: usize) -> Result<Pair> {
        let nb = if subtract { b.0.neg() } else { b.0 };
        check((a.0.mul(&b.1).add(&nb.mul(&a.1)), a.1.mul(&b.1)), pos)
    }
    fn mul(&self, a: Pair, b: Pair, divide: bool, pos: usize) -> Result<Pair> {
        if !divide {
            return check((a.0.mul(&b.0), a.1.mul(&b.1)), pos);
        }
        if b.0.is_zero() {
            return Err(at(pos, "division by zero"));
        }
        check((a.0.mul(&b.1), a.1.mul(&b.0)), pos)
    }
    fn pow(&self, base: Pair, e: Pair, pos: usize) -> Result<Pair> {
        let k = int_exponent(&RationalFunction::new(e.0, e.1), pos)?;
        let (b, k) = if k < 0 {
            if base.0.is_zero() {
                return Err(at(pos, "division by zero"));
            }
            ((base.1, base.0), k.unsigned_abs() as u32)
        } else {
            (base, k as u32)
        };
        check((b.0.pow(k), b.1.pow(k)), pos)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::transfer_expr::parse_rational_function;

    fn text(p: &Pair) -> (String, String) {
        (p.0.to_string_var("s"), p.1.to_string_var("s"))
    }

    #[test]
    fn keeps_what_is_written_and_equals_the_reduced_value() {
        let cases = [
            ("(s+1)/((s+1)*(s+2))", ("s + 1", "s^2 + 3*s + 2")),
            ("1/(s+1) + 1/(s+1)", ("2*s + 2", "s^2 + 2*s + 1")),
            ("s/s", ("s", "s")),
            ("(2*s+2)/(2*s^2+6*s+4)", ("s + 1", "s^2 + 3*s + 2")),
            ("(s+1)^-2*(s+1)", ("s + 1", "s^2 + 2*s + 1")),
            ("0/(s+3)", ("0", "s + 3")),
            ("3", ("3", "1")),
        ];
        for (t, want) in cases {
            let p = parse_written_fraction(t, &[]).unwrap();
            assert_eq!(text(&p), (want.0.to_string(), want.1.to_string()), "{t}");
            let r = parse_rational_function(t, &[]).unwrap();
            assert_eq!(RationalFunction::new(p.0, p.1), r, "{t}");
        }
    }

    #[test]
    fn errors_as_the_reduced_reader() {
        for t in [
            "1/(s-s)",
            "1/((s+1)/(s+1)-1)",
            "s^(1/2)",
            "s^65",
            "(s-s)^-1",
            "x+1",
            "1/",
        ] {
            assert!(parse_written_fraction(t, &[]).is_err(), "{t}");
        }
        let a = vec![("a".to_string(), Rational::from_integer(2.into()))];
        let p = parse_written_fraction("a/(s+a)", &a).unwrap();
        assert_eq!(text(&p), ("2".to_string(), "s + 2".to_string()));
    }
}
