//! Rational functions in `s` written as text: `"(s^2 + 5*s + 7)/(s^2 + 5*s + 6)"`, with
//! exact decimal numbers and parameters given as exact rationals.
//!
//! Grammar ([`crate::field::expr`], the one reader; values are rational functions in lowest
//! terms):
//!
//! ```text
//! expr  := term (('+' | '-') term)*
//! term  := unary (('*' | '/') unary)*
//! unary := ('-' | '+') unary | power
//! power := atom ('^' unary)?        (the exponent must be an integer constant)
//! atom  := number | 's' | name | '(' expr ')'
//! ```
//!
//! Bounded work: exponents $|e| \le 64$, degrees $\le 512$, nesting $\le 256$, input
//! length $\le 10^4$ characters.

use crate::error::{Error, Result};
use crate::field::expr::{Algebra, Dialect, SyntaxError, error_at as at, evaluate, parse_number};
use crate::field::{Q, Rational};
use crate::poly::Poly;
use crate::system::transfer::RationalFunction;
use num_traits::{Signed, ToPrimitive};

const MAX_EXP: i64 = 64;
pub(super) const MAX_DEG: usize = 512;
const MAX_LEN: usize = super::expr::MAX_EXPR_LEN;

/// Parses a rational function in `s`; `params` gives the values of other names.
///
/// # Errors
/// `Parse` (1-based column) for bad syntax, unknown names, division by zero, non-integer or
/// too large exponents, too large degrees.
///
/// # Examples
/// ```
/// use exactlti::io::transfer_expr::parse_rational_function;
/// let g = parse_rational_function("(s^2 + 5*s + 7)/(s^2 + 5*s + 6) - 1", &[]).unwrap();
/// assert_eq!(g.to_string_var("s"), "(1)/(s^2 + 5*s + 6)");
/// ```
pub fn parse_rational_function(
    text: &str,
    params: &[(String, Rational)],
) -> Result<RationalFunction<Q>> {
    parse_rational_function_in(text, params, "s")
}

/// [`parse_rational_function`] in the variable `var` (`z` for a sampled system).
///
/// # Errors
/// As [`parse_rational_function`]; the other variable's name is an unknown name.
pub fn parse_rational_function_in(
    text: &str,
    params: &[(String, Rational)],
    var: &str,
) -> Result<RationalFunction<Q>> {
    check_length(text)?;
    evaluate(&InS { params, var }, text, Dialect::EXACT)
}

/// Refuses a text longer than the bound before reading it.
pub(super) fn check_length(text: &str) -> Result<()> {
    if text.len() > MAX_LEN {
        return Err(Error::Parse {
            line: 1,
            col: 1,
            msg: format!(
                "expression of {} characters (at most {MAX_LEN}): not read",
                text.chars().count()
            ),
        });
    }
    Ok(())
}

/// $\mathbb{Q}(s)$ with parameters of rational value.
pub(super) struct InS<'a> {
    pub(super) params: &'a [(String, Rational)],
    /// The variable's name: `s`, or `z` for a sampled system (a file with `dt`).
    pub(super) var: &'a str,
}

type RF = RationalFunction<Q>;

fn cst(q: Rational) -> RF {
    RationalFunction::new(Poly::constant(Q, q), Poly::one(Q))
}

fn check(v: RF, pos: usize) -> Result<RF> {
    if v.num.deg() > MAX_DEG || v.den.deg() > MAX_DEG {
        return Err(at(pos, "degree too large"));
    }
    Ok(v)
}

impl Algebra for InS<'_> {
    type Value = RF;
    type Error = Error;
    fn syntax(&self, e: SyntaxError) -> Error {
        e.to_error()
    }
    fn number(&self, s: &str, pos: usize) -> Result<RF> {
        parse_number(s).map(cst).map_err(|m| at(pos, &m))
    }
    fn name(&self, name: &str, pos: usize) -> Result<RF> {
        if name == self.var {
            return Ok(RationalFunction::new(Poly::x(Q), Poly::one(Q)));
        }
        match self.params.iter().find(|(n, _)| n == name) {
            Some((_, v)) => Ok(cst(v.clone())),
            None => Err(at(
                pos,
                &format!("unknown name '{name}' (the variable is {})", self.var),
            )),
        }
    }
    fn call(&self, f: &str, _: Vec<RF>, pos: usize) -> Result<RF> {
        Err(at(pos, &format!("unknown function '{f}'")))
    }
    fn neg(&self, a: RF, _: usize) -> Result<RF> {
        Ok(neg(&a))
    }
    fn add(&self, a: RF, b: RF, subtract: bool, _: usize) -> Result<RF> {
        Ok(add(&a, &if subtract { neg(&b) } else { b }))
    }
    fn mul(&self, a: RF, b: RF, divide: bool, pos: usize) -> Result<RF> {
        if !divide {
            return check(mul(&a, &b), pos);
        }
        if b.num.is_zero() {
            return Err(at(pos, "division by zero"));
        }
        check(mul(&a, &RationalFunction::new(b.den, b.num)), pos)
    }
    fn pow(&self, base: RF, e: RF, pos: usize) -> Result<RF> {
        let k = int_exponent(&e, pos)?;
        let (b, k) = if k < 0 {
            if base.num.is_zero() {
                return Err(at(pos, "division by zero"));
            }
            (RationalFunction::new(base.den, base.num), (-k) as u32)
        } else {
            (base, k as u32)
        };
        check(RationalFunction::new(b.num.pow(k), b.den.pow(k)), pos)
    }
}

/// The exponent `e` as an integer: a constant with $|e| \le 64$.
pub(super) fn int_exponent(e: &RF, pos: usize) -> Result<i64> {
    (e.den.is_one() && e.num.deg() == 0)
        .then(|| e.num.coeff(0))
        .filter(|q| q.is_integer() && q.abs() <= Rational::from_integer(MAX_EXP.into()))
        .and_then(|q| q.to_integer().to_i64())
        .ok_or_else(|| at(pos, "exponent must be an integer constant with |e| <= 64"))
}

fn neg(a: &RF) -> RF {
    RationalFunction::new(a.num.neg(), a.den.clone())
}
fn add(a: &RF, b: &RF) -> RF {
    RationalFunction::new(a.num.mul(&b.den).add(&b.num.mul(&a.den)), a.den.mul(&b.den))
}
fn mul(a: &RF, b: &RF) -> RF {
    RationalFunction::new(a.num.mul(&b.num), a.den.mul(&b.den))
}
