//! Parsing multivariate polynomials and rational functions from text such as
//! `m*u^2 - 3*cr`, `(a*b + c^2 + 1)^3*(a - b + 2*c)^2`, `2/3*x - 0.5`, `(s + 1)/(m*s^2 + k)`.
//!
//! Identifiers are `[A-Za-z_][A-Za-z0-9_]*`; numbers are exact (`0.08` is $2/25$, `1.5e-3` is
//! $3/2000$); `^` and `**` take non-negative integer exponents; juxtaposition multiplies
//! (`2x`, `3(x + 1)`). Sizes are bounded (degrees, terms and coefficient bits of powers), so
//! no input can make the parser slow; errors carry the 1-based column.

use super::{MAX_VARS, MPoly, QPoly, max_exponent};
use crate::error::{Error, Result};
use crate::field::Rational;
use crate::field::scan::{Cursor, identifier_end, number_end, reserved_message};
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

/// Largest degree in any variable of a parsed expression.
const MAX_DEGREE: u32 = 10_000;
/// Bound on the estimated number of terms of a power.
const MAX_POWER_TERMS: u64 = 1 << 20;
/// Bound on the estimated coefficient bits of a power.
const MAX_POWER_BITS: u64 = 1 << 16;

/// Parses a polynomial over $\mathbb{Q}$; its variables are all identifiers that occur,
/// sorted. Returns the variable names and the polynomial.
///
/// # Errors
/// `Parse` (column of the first problem) for bad text, a division by a non-constant, more
/// than [`MAX_VARS`] variables or too large sizes. Never panics.
///
/// # Examples
/// ```
/// use exactlti::mpoly::parse_mpoly;
/// let (vars, f) = parse_mpoly("m*u^2 - 3*cr").unwrap();
/// assert_eq!(vars, ["cr", "m", "u"]);
/// assert_eq!(f.to_string_vars(&vars), "m*u^2 - 3*cr");
/// ```
pub fn parse_mpoly(text: &str) -> Result<(Vec<String>, QPoly)> {
    let vars = identifiers(text)?;
    let refs: Vec<&str> = vars.iter().map(|s| s.as_str()).collect();
    let f = parse_mpoly_in(text, &refs)?;
    Ok((vars, f))
}

/// Parses a polynomial over $\mathbb{Q}$ in the given variables (an unknown identifier is an
/// error).
pub fn parse_mpoly_in(text: &str, vars: &[&str]) -> Result<QPoly> {
    let (num, den) = parse_fraction_in(text, vars, false)?;
    let d = den.to_constant().expect("constant denominator");
    Ok(QPoly::new(Rational::new(BigInt::one(), d), num))
}

/// Parses a rational function: `(num, den)` over $\mathbb{Z}$ with `den != 0` (not reduced).
///
/// # Errors
/// As [`parse_mpoly`]; also a division by the zero polynomial.
pub fn parse_ratfunc_in(text: &str, vars: &[&str]) -> Result<(MPoly, MPoly)> {
    parse_fraction_in(text, vars, true)
}

/// All identifiers in `text`, sorted and deduplicated.
///
/// # Errors
/// `Parse` when there are more than [`MAX_VARS`].
pub fn identifiers(text: &str) -> Result<Vec<String>> {
    let s = text.as_bytes();
    let mut out: Vec<String> = Vec::new();
    let mut i = 0;
    while i < s.len() {
        let c = s[i];
        if c.is_ascii_alphabetic() || c == b'_' {
            let start = i;
            i = identifier_end(s, i);
            let name = String::from_utf8_lossy(&s[start..i]).into_owned();
            if let Some(msg) = reserved_message(&name) {
                return Err(Error::Parse {
                    line: 1,
                    col: start + 1,
                    msg,
                });
            }
            out.push(name);
        } else if c.is_ascii_digit() || c == b'.' {
            // a number, with its exponent marker (`1e-3` names nothing)
            i = number_end(s, i, usize::MAX);
        } else {
            i += 1;
        }
    }
    out.sort();
    out.dedup();
    if out.len() > MAX_VARS {
        return Err(Error::Parse {
            line: 1,
            col: 1,
            msg: format!("more than {MAX_VARS} variables"),
        });
    }
    Ok(out)
}

fn parse_fraction_in(text: &str, vars: &[&str], allow_div: bool) -> Result<(MPoly, MPoly)> {
    if vars.len() > MAX_VARS {
        return Err(Error::Parse {
            line: 1,
            col: 1,
            msg: format!("more than {MAX_VARS} variables"),
        });
    }
    let mut p = P {
        c: Cursor::new(text),
        vars,
        allow_div,
    };
    let f = p.expr()?;
    p.c.finish()?;
    let (mut num, mut den) = f;
    if den.lc().is_negative() {
        num = num.neg();
        den = den.neg();
    }
    Ok((num, den))
}

type Frac = (MPoly, MPoly);

struct P<'a> {
    c: Cursor<'a>,
    vars: &'a [&'a str],
    allow_div: bool,
}

impl P<'_> {
    fn n(&self) -> usize {
        self.vars.len()
    }
    fn err(&self, msg: &str) -> Error {
        self.c.err(msg)
    }
    fn check(&self, f: &Frac) -> Result<()> {
        let lim = MAX_DEGREE.min(max_exponent(self.n()) / 2);
        if f.0
            .degrees()
            .iter()
            .chain(f.1.degrees().iter())
            .any(|&d| d > lim)
        {
            return Err(self.err("degree too large"));
        }
        Ok(())
    }
    fn add(&self, a: &Frac, b: &Frac, neg: bool) -> Result<Frac> {
        let nb = if neg { b.0.neg() } else { b.0.clone() };
        let r = if a.1 == b.1 {
            (a.0.add(&nb), a.1.clone())
        } else {
            self.check_mul(&a.0, &b.1)?;
            self.check_mul(&a.1, &b.1)?;
            (a.0.mul(&b.1).add(&nb.mul(&a.1)), a.1.mul(&b.1))
        };
        self.check(&r)?;
        Ok(r)
    }
    fn check_mul(&self, a: &MPoly, b: &MPoly) -> Result<()> {
        let lim = MAX_DEGREE.min(max_exponent(self.n()) / 2);
        let (da, db) = (a.degrees(), b.degrees());
        if da.iter().zip(&db).any(|(x, y)| x + y > lim) {
            return Err(self.err("degree too large"));
        }
        if (a.len() as u64).saturating_mul(b.len() as u64) > MAX_POWER_TERMS * 4 {
            return Err(self.err("expression too large"));
        }
        Ok(())
    }
    fn mul(&self, a: &Frac, b: &Frac) -> Result<Frac> {
        self.check_mul(&a.0, &b.0)?;
        self.check_mul(&a.1, &b.1)?;
        let r = (a.0.mul(&b.0), a.1.mul(&b.1));
        self.check(&r)?;
        Ok(r)
    }
    fn div(&self, a: &Frac, b: &Frac) -> Result<Frac> {
        if b.0.is_zero() {
            return Err(self.err("division by zero"));
        }
        if !self.allow_div && !b.0.is_constant() {
            return Err(self.err("division only by a non-zero constant"));
        }
        self.mul(a, &(b.1.clone(), b.0.clone()))
    }
    fn expr(&mut self) -> Result<Frac> {
        let mut acc = match self.c.eat_any(b"+-") {
            Some(b'-') => {
                let t = self.term()?;
                (t.0.neg(), t.1)
            }
            _ => self.term()?,
        };
        while let Some(op) = self.c.eat_any(b"+-") {
            let t = self.term()?;
            acc = self.add(&acc, &t, op == b'-')?;
        }
        Ok(acc)
    }
    fn term(&mut self) -> Result<Frac> {
        let mut acc = self.power()?;
        loop {
            let op = self.c.eat_any(b"*/");
            let implicit = matches!(self.c.peek(), Some(b'(' | b'a'..=b'z' | b'A'..=b'Z' | b'_'));
            if op.is_none() && !implicit {
                return Ok(acc);
            }
            let f = self.power()?;
            acc = match op {
                Some(b'/') => self.div(&acc, &f)?,
                _ => self.mul(&acc, &f)?,
            };
        }
    }
    fn power(&mut self) -> Result<Frac> {
        // unary sign inside a product or after an operator: `a + -2*b`, `a*-b`
        let mut negate = false;
        while let Some(c) = self.c.eat_any(b"+-") {
            negate ^= c == b'-';
        }
        if negate {
            let f = self.power()?;
            return Ok((f.0.neg(), f.1));
        }
        let base = self.atom()?;
        if let Some(e) = self.c.power_exponent::<u32>()? {
            let lim = MAX_DEGREE.min(max_exponent(self.n()) / 2) as u64;
            for f in [&base.0, &base.1] {
                let degs = f.degrees();
                if degs.iter().any(|&d| d as u64 * e as u64 > lim) || e as u64 > lim {
                    return Err(self.err("degree too large"));
                }
                // terms of f^e at most prod_i (e deg_i + 1); bits about e (log2 |f|_inf + log2 len)
                let terms = degs
                    .iter()
                    .fold(1u64, |acc, &d| acc.saturating_mul(e as u64 * d as u64 + 1));
                let bits = (e as u64).saturating_mul(
                    f.max_norm().bits() + (f.len().max(1) as u64).ilog2() as u64 + 1,
                );
                if terms.min(binomial_bound(f.len() as u64, e as u64)) > MAX_POWER_TERMS
                    || bits > MAX_POWER_BITS
                {
                    return Err(self.err("power too large"));
                }
            }
            return Ok((base.0.pow(e), base.1.pow(e)));
        }
        Ok(base)
    }
    fn atom(&mut self) -> Result<Frac> {
        let n = self.n();
        match self.c.peek() {
            Some(b'(') => {
                self.c.open(200)?;
                let f = self.expr()?;
                self.c.close().map(|()| f)
            }
            Some(c) if c.is_ascii_alphabetic() || c == b'_' => {
                let start = self.c.pos;
                let name = self.c.identifier();
                if let Some(msg) = reserved_message(name) {
                    self.c.pos = start;
                    return Err(self.err(&msg));
                }
                let Some(i) = self.vars.iter().position(|v| *v == name) else {
                    self.c.pos = start;
                    return Err(self.err(&format!("unknown symbol '{name}'")));
                };
                Ok((MPoly::var(n, i), MPoly::one(n)))
            }
            Some(c) if c.is_ascii_digit() || c == b'.' => {
                let q = self.c.number(usize::MAX).map_err(|m| self.err(&m))?;
                if q.is_zero() {
                    return Ok((MPoly::zero(n), MPoly::one(n)));
                }
                Ok((
                    MPoly::constant(n, q.numer().clone()),
                    MPoly::constant(n, q.denom().clone()),
                ))
            }
            _ => Err(self.err("expected a number, a symbol or '('")),
        }
    }
}

/// Test helper: an integer polynomial in `a, b, c` from text (the content cleared).
#[cfg(test)]
pub(crate) fn abc(s: &str) -> MPoly {
    let f = parse_mpoly_in(s, &["a", "b", "c"]).unwrap();
    f.prim.scale(&f.content.to_integer())
}

/// Terms of $(t_1 + \dots + t_n)^e$ at most $\binom{n + e - 1}{e}$ (saturating).
fn binomial_bound(n: u64, e: u64) -> u64 {
    if n <= 1 {
        return 1;
    }
    let mut r: u64 = 1;
    for i in 0..e.min(n - 1) {
        let (num, den) = (n - 1 + e - i, i + 1);
        r = r.saturating_mul(num) / den;
        if r > MAX_POWER_TERMS * 16 {
            return u64::MAX;
        }
    }
    r
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn examples() {
        let (v, f) = parse_mpoly("m*u^2 - 3*cr").unwrap();
        assert_eq!(v, ["cr", "m", "u"]);
        assert_eq!(f.to_string_vars(&v), "m*u^2 - 3*cr");
        let (v, f) = parse_mpoly("2/3*x - 0.5*y").unwrap();
        assert_eq!(f.content, Rational::new(1.into(), 6.into()));
        assert_eq!(f.prim.display(&v).to_string(), "4*x - 3*y");
        assert!(parse_mpoly("x/y").is_err());
        assert!(parse_mpoly("(x+y+z+w)^1000").is_err());
        assert!(parse_mpoly("x^").is_err());
        assert_eq!(
            parse_mpoly("x + -2*y").unwrap().1,
            parse_mpoly("x - 2*y").unwrap().1
        );
        assert!(parse_mpoly("x + ").is_err());
        assert!(parse_mpoly("").is_err());
        assert!(parse_mpoly("(a + b)^20").is_ok());
        assert_eq!(identifiers("1e-3*x2 + e").unwrap(), ["e", "x2"]);
        let (n, d) = parse_ratfunc_in("(s + 1)/(-2*s)", &["s"]).unwrap();
        assert_eq!(n.display(&["s".to_string()]).to_string(), "-s - 1");
        assert_eq!(d.display(&["s".to_string()]).to_string(), "2*s");
    }
}
