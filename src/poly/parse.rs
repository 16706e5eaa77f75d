//! Parsing polynomials over $\mathbb{Q}$ from text such as `x^4 + 4*x^2 + 1`,
//! `(s - 1)^2*(s + 2)`, `2/3*x - 0.5`. Any single-letter variable is accepted (one per text).

use super::Poly;
use crate::error::{Error, Result};
use crate::field::expr::{
    Algebra, Dialect, SyntaxError, error_at as at, evaluate, parse_number, reserved_message,
};
use crate::field::{Field, Q};
use num_traits::{Signed, ToPrimitive};
use std::cell::Cell;

const MAX_DEGREE: usize = 10_000;
/// Bound on the total size in bits of a power $f^e$: keeps parsing fast.
const MAX_POWER_BITS: u64 = 1 << 24;

/// Parses a polynomial over $\mathbb{Q}$ (the grammar of [`crate::field::expr`], read in
/// [`Dialect::POLY`]: `2x`, `3(x + 1)`, `x**2`).
///
/// # Errors
/// `Parse` with the 1-based column of the first problem; never panics.
pub fn parse_poly_q(text: &str) -> Result<Poly<Q>> {
    evaluate(
        &Univariate {
            var: Cell::new(None),
        },
        text,
        Dialect::POLY,
    )
}

/// $\mathbb{Q}[x]$ with one single-letter variable, whichever letter the text uses first.
struct Univariate {
    var: Cell<Option<char>>,
}

fn check_deg(f: Poly<Q>, pos: usize) -> Result<Poly<Q>> {
    if f.deg() > MAX_DEGREE {
        return Err(at(pos, "degree too large"));
    }
    Ok(f)
}

impl Algebra for Univariate {
    type Value = Poly<Q>;
    type Error = Error;
    fn syntax(&self, e: SyntaxError) -> Error {
        e.to_error()
    }
    fn number(&self, s: &str, pos: usize) -> Result<Poly<Q>> {
        let q = parse_number(s).map_err(|m| at(pos, &m))?;
        Ok(Poly::constant(Q, q))
    }
    fn name(&self, n: &str, pos: usize) -> Result<Poly<Q>> {
        if let Some(msg) = reserved_message(n) {
            return Err(at(pos, &msg));
        }
        let mut cs = n.chars();
        let (Some(c), None) = (cs.next(), cs.next()) else {
            return Err(at(pos, "variable must be a single letter"));
        };
        match self.var.get() {
            None => self.var.set(Some(c)),
            Some(v) if v != c => return Err(at(pos, "only one variable is allowed")),
            _ => {}
        }
        Ok(Poly::x(Q))
    }
    fn call(&self, f: &str, _: Vec<Poly<Q>>, pos: usize) -> Result<Poly<Q>> {
        self.name(f, pos)
    }
    fn neg(&self, a: Poly<Q>, _: usize) -> Result<Poly<Q>> {
        Ok(a.neg())
    }
    fn add(&self, a: Poly<Q>, b: Poly<Q>, subtract: bool, _: usize) -> Result<Poly<Q>> {
        Ok(if subtract { a.sub(&b) } else { a.add(&b) })
    }
    fn mul(&self, a: Poly<Q>, b: Poly<Q>, divide: bool, pos: usize) -> Result<Poly<Q>> {
        if !divide {
            if a.deg() + b.deg() > MAX_DEGREE {
                return Err(at(pos, "degree too large"));
            }
            return check_deg(a.mul(&b), pos);
        }
        if b.degree() != Some(0) {
            return Err(at(pos, "division only by a non-zero constant"));
        }
        Ok(a.scale(&Q.inv(&b.lc()).expect("nonzero constant")))
    }
    fn pow(&self, base: Poly<Q>, e: Poly<Q>, pos: usize) -> Result<Poly<Q>> {
        let c = (e.deg() == 0).then(|| e.coeff(0));
        let Some(e) = c
            .filter(|c| c.is_integer() && !c.is_negative())
            .and_then(|c| c.to_integer().to_usize())
        else {
            return Err(at(pos, "expected a non-negative integer exponent"));
        };
        if e.saturating_mul(base.deg()) > MAX_DEGREE || e > MAX_DEGREE {
            return Err(at(pos, "degree too large"));
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
            return Err(at(pos, "coefficients too large"));
        }
        Ok(base.pow(e as u32))
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
