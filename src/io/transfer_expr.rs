//! Rational functions in `s` written as text: `"(s^2 + 5*s + 7)/(s^2 + 5*s + 6)"`, with
//! exact decimal numbers and parameters given as exact rationals.
//!
//! Grammar (as [`super::expr`]; values are rational functions in lowest terms):
//!
//! ```text
//! expr  := term (('+' | '-') term)*
//! term  := unary (('*' | '/') unary)*
//! unary := ('-' | '+') unary | power
//! power := atom ('^' unary)?        (the exponent must be an integer constant)
//! atom  := number | 's' | name | '(' expr ')'
//! ```
//!
//! Bounded work: exponents $|e| \le 64$, degrees $\le 512$, nesting $< 256$, input
//! length $\le 10^4$ characters.

use crate::error::{Error, Result};
use crate::field::scan::Cursor;
use crate::field::{Q, Rational};
use crate::poly::Poly;
use crate::system::transfer::RationalFunction;
use num_traits::{Signed, ToPrimitive};

const MAX_EXP: i64 = 64;
const MAX_DEG: usize = 512;
const MAX_DEPTH: usize = 256;
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
    let mut p = P {
        c: Cursor::new(text),
        params,
    };
    let v = p.expr()?;
    p.c.finish()?;
    Ok(v)
}

struct P<'a> {
    c: Cursor<'a>,
    params: &'a [(String, Rational)],
}

type RF = RationalFunction<Q>;

fn cst(q: Rational) -> RF {
    RationalFunction::new(Poly::constant(Q, q), Poly::one(Q))
}

impl P<'_> {
    fn err(&self, msg: &str) -> Error {
        self.c.err(msg)
    }
    fn check(&self, v: RF) -> Result<RF> {
        if v.num.deg() > MAX_DEG || v.den.deg() > MAX_DEG {
            return Err(self.err("degree too large"));
        }
        Ok(v)
    }
    fn expr(&mut self) -> Result<RF> {
        let mut acc = self.term()?;
        while let Some(c) = self.c.eat_any(b"+-") {
            let t = self.term()?;
            acc = if c == b'+' {
                add(&acc, &t)
            } else {
                add(&acc, &neg(&t))
            };
        }
        Ok(acc)
    }
    fn term(&mut self) -> Result<RF> {
        let mut acc = self.unary()?;
        while let Some(c) = self.c.eat_any(b"*/") {
            let t = self.unary()?;
            acc = if c == b'*' {
                self.check(mul(&acc, &t))?
            } else {
                if t.num.is_zero() {
                    return Err(self.err("division by zero"));
                }
                self.check(mul(
                    &acc,
                    &RationalFunction::new(t.den.clone(), t.num.clone()),
                ))?
            };
        }
        Ok(acc)
    }
    fn unary(&mut self) -> Result<RF> {
        self.c.enter(MAX_DEPTH)?;
        let v = match self.c.peek() {
            Some(b'-') => {
                self.c.pos += 1;
                neg(&self.unary()?)
            }
            Some(b'+') => {
                self.c.pos += 1;
                self.unary()?
            }
            _ => self.power()?,
        };
        self.c.depth -= 1;
        Ok(v)
    }
    fn power(&mut self) -> Result<RF> {
        let base = self.atom()?;
        if self.c.peek() != Some(b'^') {
            return Ok(base);
        }
        self.c.pos += 1;
        let at = self.c.pos;
        let e = self.unary()?;
        let exp = (e.den.is_one() && e.num.deg() == 0)
            .then(|| e.num.coeff(0))
            .filter(|q| q.is_integer() && q.abs() <= Rational::from_integer(MAX_EXP.into()))
            .and_then(|q| q.to_integer().to_i64());
        let Some(k) = exp else {
            self.c.pos = at;
            return Err(self.err("exponent must be an integer constant with |e| <= 64"));
        };
        let (b, k) = if k < 0 {
            if base.num.is_zero() {
                return Err(self.err("division by zero"));
            }
            (
                RationalFunction::new(base.den.clone(), base.num.clone()),
                (-k) as u32,
            )
        } else {
            (base, k as u32)
        };
        self.check(RationalFunction::new(b.num.pow(k), b.den.pow(k)))
    }
    fn atom(&mut self) -> Result<RF> {
        match self.c.peek() {
            Some(b'(') => {
                self.c.pos += 1;
                let v = self.expr()?;
                self.c.expect(b')')?;
                Ok(v)
            }
            Some(c) if c.is_ascii_digit() || c == b'.' => {
                // at most 4 exponent digits: `1e12345` is 1 followed by a name
                let start = self.c.pos;
                let q = self.c.number(4).map_err(|m| self.c.err_at(start, &m))?;
                Ok(cst(q))
            }
            Some(c) if c.is_ascii_alphabetic() || c == b'_' => {
                let start = self.c.pos;
                let name = self.c.identifier();
                if name == "s" {
                    return Ok(RationalFunction::new(Poly::x(Q), Poly::one(Q)));
                }
                match self.params.iter().find(|(n, _)| n == name) {
                    Some((_, v)) => Ok(cst(v.clone())),
                    None => {
                        self.c.pos = start;
                        Err(self.err(&format!("unknown name '{name}' (the variable is s)")))
                    }
                }
            }
            _ => Err(self.err("expected a number, s, a parameter or '('")),
        }
    }
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
