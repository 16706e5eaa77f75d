//! Parsing polynomials over $\mathbb{Q}$ from text such as `x^4 + 4*x^2 + 1`,
//! `(s - 1)^2*(s + 2)`, `2/3*x - 0.5`. Any single-letter variable is accepted (one per text).

use super::Poly;
use crate::error::{Error, Result};
use crate::field::{Q, Rational, parse_rational};

struct P<'a> {
    s: &'a [u8],
    pos: usize,
    var: Option<u8>,
    depth: usize,
}

const MAX_DEGREE: usize = 10_000;
/// Bound on the total size in bits of a power $f^e$: keeps parsing fast.
const MAX_POWER_BITS: u64 = 1 << 24;

/// Parses a polynomial over $\mathbb{Q}$.
///
/// # Errors
/// `Parse` with the 1-based column of the first problem; never panics.
pub fn parse_poly_q(text: &str) -> Result<Poly<Q>> {
    let mut p = P {
        s: text.as_bytes(),
        pos: 0,
        var: None,
        depth: 0,
    };
    let f = p.expr()?;
    p.ws();
    if p.pos != p.s.len() {
        return Err(p.err("unexpected character"));
    }
    Ok(f)
}

impl P<'_> {
    fn err(&self, msg: &str) -> Error {
        Error::Parse {
            line: 1,
            col: self.pos + 1,
            msg: msg.into(),
        }
    }
    fn ws(&mut self) {
        while self.pos < self.s.len() && self.s[self.pos].is_ascii_whitespace() {
            self.pos += 1;
        }
    }
    fn peek(&mut self) -> Option<u8> {
        self.ws();
        self.s.get(self.pos).copied()
    }
    fn expr(&mut self) -> Result<Poly<Q>> {
        let mut acc = match self.peek() {
            Some(b'-') => {
                self.pos += 1;
                self.term()?.neg()
            }
            Some(b'+') => {
                self.pos += 1;
                self.term()?
            }
            _ => self.term()?,
        };
        loop {
            match self.peek() {
                Some(b'+') => {
                    self.pos += 1;
                    acc = acc.add(&self.term()?);
                }
                Some(b'-') => {
                    self.pos += 1;
                    acc = acc.sub(&self.term()?);
                }
                _ => return Ok(acc),
            }
        }
    }
    fn check_deg(&self, f: &Poly<Q>) -> Result<()> {
        if f.deg() > MAX_DEGREE {
            Err(self.err("degree too large"))
        } else {
            Ok(())
        }
    }
    fn term(&mut self) -> Result<Poly<Q>> {
        let mut acc = self.power()?;
        loop {
            match self.peek() {
                Some(b'*') => {
                    self.pos += 1;
                    let f = self.power()?;
                    if acc.deg() + f.deg() > MAX_DEGREE {
                        return Err(self.err("degree too large"));
                    }
                    acc = acc.mul(&f);
                }
                Some(b'/') => {
                    self.pos += 1;
                    let f = self.power()?;
                    if f.degree() != Some(0) {
                        return Err(self.err("division only by a non-zero constant"));
                    }
                    acc = acc.scale(&f.lc().recip());
                }
                Some(b'(') | Some(b'a'..=b'z') | Some(b'A'..=b'Z') => {
                    // implicit multiplication: 2x, 3(x+1)
                    let f = self.power()?;
                    acc = acc.mul(&f);
                    self.check_deg(&acc)?;
                }
                _ => return Ok(acc),
            }
        }
    }
    fn power(&mut self) -> Result<Poly<Q>> {
        let base = self.atom()?;
        if self.peek() == Some(b'^')
            || (self.peek() == Some(b'*') && self.s.get(self.pos + 1) == Some(&b'*'))
        {
            self.pos += if self.s[self.pos] == b'^' { 1 } else { 2 };
            self.ws();
            let start = self.pos;
            while self.pos < self.s.len() && self.s[self.pos].is_ascii_digit() {
                self.pos += 1;
            }
            let e: usize = std::str::from_utf8(&self.s[start..self.pos])
                .ok()
                .and_then(|t| t.parse().ok())
                .ok_or_else(|| self.err("expected a non-negative integer exponent"))?;
            if e.saturating_mul(base.deg()) > MAX_DEGREE || e > MAX_DEGREE {
                return Err(self.err("degree too large"));
            }
            // size of f^e: (e deg f + 1) coefficients of about e log2 |f|_1 bits each
            let l1_bits: u64 = base
                .coeffs()
                .iter()
                .map(|c| c.numer().bits() + c.denom().bits())
                .max()
                .unwrap_or(0)
                + (base.coeffs().len() as u64).ilog2() as u64
                + 1;
            let e64 = e as u64;
            let total = e64
                .saturating_mul(l1_bits)
                .saturating_mul(e64.saturating_mul(base.deg() as u64) + 1);
            if total > MAX_POWER_BITS {
                return Err(self.err("coefficients too large"));
            }
            return Ok(base.pow(e as u32));
        }
        Ok(base)
    }
    fn atom(&mut self) -> Result<Poly<Q>> {
        match self.peek() {
            Some(b'(') => {
                self.depth += 1;
                if self.depth > 200 {
                    return Err(self.err("nesting too deep"));
                }
                self.pos += 1;
                let f = self.expr()?;
                if self.peek() != Some(b')') {
                    return Err(self.err("expected ')'"));
                }
                self.pos += 1;
                self.depth -= 1;
                Ok(f)
            }
            Some(c) if c.is_ascii_alphabetic() => {
                if self
                    .s
                    .get(self.pos + 1)
                    .is_some_and(|d| d.is_ascii_alphanumeric())
                {
                    return Err(self.err("variable must be a single letter"));
                }
                match self.var {
                    None => self.var = Some(c),
                    Some(v) if v != c => return Err(self.err("only one variable is allowed")),
                    _ => {}
                }
                self.pos += 1;
                Ok(Poly::x(Q))
            }
            Some(c) if c.is_ascii_digit() || c == b'.' => {
                let start = self.pos;
                while self.pos < self.s.len() {
                    let c = self.s[self.pos];
                    let exp_sign = (c == b'-' || c == b'+')
                        && self.pos > start
                        && matches!(self.s[self.pos - 1], b'e' | b'E')
                        && self.s[start..self.pos - 1]
                            .iter()
                            .all(|d| d.is_ascii_digit() || *d == b'.');
                    let is_exp = (c == b'e' || c == b'E')
                        && self
                            .s
                            .get(self.pos + 1)
                            .is_some_and(|d| d.is_ascii_digit() || *d == b'-' || *d == b'+');
                    if c.is_ascii_digit() || c == b'.' || is_exp || exp_sign {
                        self.pos += 1;
                    } else {
                        break;
                    }
                }
                let t = std::str::from_utf8(&self.s[start..self.pos])
                    .map_err(|_| self.err("bad number"))?;
                let q: Rational = parse_rational(t).map_err(|m| self.err(&m))?;
                Ok(Poly::constant(Q, q))
            }
            _ => Err(self.err("expected a number, a variable or '('")),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn examples() {
        assert_eq!(
            parse_poly_q("x^4 + 4*x^2 + 1").unwrap().to_string(),
            "x^4 + 4*x^2 + 1"
        );
        assert_eq!(
            parse_poly_q("(s-1)^2*(s+2)").unwrap().to_string(),
            "x^3 - 3*x + 2"
        );
        assert_eq!(
            parse_poly_q("2/3*x - 0.5").unwrap().to_string(),
            "2/3*x - 1/2"
        );
        assert_eq!(parse_poly_q("2x**2").unwrap().to_string(), "2*x^2");
        assert!(parse_poly_q("x + y").is_err());
        assert!(parse_poly_q("x^").is_err());
        assert!(parse_poly_q("x/x").is_err());
        assert!(parse_poly_q("(x^1000)^1000").is_err());
        assert!(parse_poly_q("(123456789*x + 1)^9999").is_err());
        assert!(parse_poly_q("(x + 1)^500").is_ok());
        assert!(parse_poly_q("").is_err());
    }
}
