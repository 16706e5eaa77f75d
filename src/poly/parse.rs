//! Parsing polynomials over $\mathbb{Q}$ from text such as `x^4 + 4*x^2 + 1`,
//! `(s - 1)^2*(s + 2)`, `2/3*x - 0.5`. Any single-letter variable is accepted (one per text).

use super::Poly;
use crate::error::{Error, Result};
use crate::field::Q;
use crate::field::scan::Cursor;

struct P<'a> {
    c: Cursor<'a>,
    var: Option<u8>,
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
        c: Cursor::new(text),
        var: None,
    };
    let f = p.expr()?;
    p.c.finish()?;
    Ok(f)
}

impl P<'_> {
    fn err(&self, msg: &str) -> Error {
        self.c.err(msg)
    }
    fn expr(&mut self) -> Result<Poly<Q>> {
        let mut acc = match self.c.eat_any(b"+-") {
            Some(b'-') => self.term()?.neg(),
            _ => self.term()?,
        };
        while let Some(op) = self.c.eat_any(b"+-") {
            let t = self.term()?;
            acc = if op == b'+' { acc.add(&t) } else { acc.sub(&t) };
        }
        Ok(acc)
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
            match self.c.eat_any(b"*/") {
                Some(b'*') => {
                    let f = self.power()?;
                    if acc.deg() + f.deg() > MAX_DEGREE {
                        return Err(self.err("degree too large"));
                    }
                    acc = acc.mul(&f);
                }
                Some(_) => {
                    let f = self.power()?;
                    if f.degree() != Some(0) {
                        return Err(self.err("division only by a non-zero constant"));
                    }
                    acc = acc.scale(&f.lc().recip());
                }
                // implicit multiplication: 2x, 3(x+1)
                None if matches!(self.c.peek(), Some(b'(' | b'a'..=b'z' | b'A'..=b'Z')) => {
                    let f = self.power()?;
                    acc = acc.mul(&f);
                    self.check_deg(&acc)?;
                }
                None => return Ok(acc),
            }
        }
    }
    fn power(&mut self) -> Result<Poly<Q>> {
        let base = self.atom()?;
        if let Some(e) = self.c.power_exponent::<usize>()? {
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
                + (base.coeffs().len().max(1) as u64).ilog2() as u64
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
        match self.c.peek() {
            Some(b'(') => {
                self.c.open(200)?;
                let f = self.expr()?;
                self.c.close().map(|()| f)
            }
            Some(c) if c.is_ascii_alphabetic() => {
                if self
                    .c
                    .s
                    .get(self.c.pos + 1)
                    .is_some_and(|d| d.is_ascii_alphanumeric())
                {
                    return Err(self.err("variable must be a single letter"));
                }
                if let Some(msg) = crate::field::scan::reserved_message(&(c as char).to_string()) {
                    return Err(self.err(&msg));
                }
                match self.var {
                    None => self.var = Some(c),
                    Some(v) if v != c => return Err(self.err("only one variable is allowed")),
                    _ => {}
                }
                self.c.pos += 1;
                Ok(Poly::x(Q))
            }
            Some(c) if c.is_ascii_digit() || c == b'.' => {
                let q = self.c.number(usize::MAX).map_err(|m| self.err(&m))?;
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
