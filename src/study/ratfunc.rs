//! Rational functions of one parameter, $\mathbb{Q}(v)$, and an evaluator of system-file
//! expressions into them.
//!
//! A [`RatFunc`] is `num / den` with `den` monic and $\gcd(num, den) = 1$ (canonical, so
//! `==` is equality of functions). [`eval_ratfunc`] reads the expression grammar of
//! [`crate::io::expr`] (`+ - * / ^`, exact decimals, parameter names, parentheses) with one
//! name standing for the symbol $v$; `sqrt` and `i` are refused (a parameter study needs a
//! real rational family). This is a one-parameter stand-in for the multivariate
//! $\mathbb{Q}(p_1, \dots, p_k)$ of the io layer; it can be replaced by it when that lands.
//!
//! Work is bounded: exponents $|n| \le 64$, degrees $\le 256$, nesting $\le 256$
//! ([`crate::field::expr`], the one reader).

use crate::error::{Error, Result};
use crate::field::expr::{Algebra, Dialect, RESERVED, SyntaxError, evaluate, parse_number};
use crate::field::{Field, Q, Rational};
use crate::poly::Poly;
use num_traits::{One, Zero};
use std::fmt;

/// Largest |exponent| accepted in an expression.
pub const MAX_EXP: u32 = 64;
/// Largest degree of a numerator or denominator.
pub const MAX_DEGREE: usize = 256;

/// A rational function $n(v)/d(v)$ over $\mathbb{Q}$ in lowest terms, `den` monic.
#[derive(Clone, Debug, PartialEq)]
pub struct RatFunc {
    pub num: Poly<Q>,
    pub den: Poly<Q>,
}

impl RatFunc {
    /// `num / den`, reduced.
    ///
    /// # Errors
    /// `DivisionByZero` when `den` is the zero polynomial.
    pub fn new(num: Poly<Q>, den: Poly<Q>) -> Result<Self> {
        if den.is_zero() {
            return Err(Error::DivisionByZero);
        }
        if num.is_zero() {
            return Ok(Self::zero());
        }
        let g = num.gcd(&den);
        let (n, d) = (num.quo(&g), den.quo(&g));
        let lc = d.lc();
        let inv = Q.inv(&lc).expect("nonzero leading coefficient");
        Ok(RatFunc {
            num: n.scale(&inv),
            den: d.scale(&inv),
        })
    }
    pub fn zero() -> Self {
        RatFunc {
            num: Poly::zero(Q),
            den: Poly::one(Q),
        }
    }
    pub fn constant(c: Rational) -> Self {
        RatFunc {
            num: Poly::constant(Q, c),
            den: Poly::one(Q),
        }
    }
    /// The symbol $v$.
    pub fn var() -> Self {
        RatFunc {
            num: Poly::x(Q),
            den: Poly::one(Q),
        }
    }
    pub fn is_zero(&self) -> bool {
        self.num.is_zero()
    }
    /// Is it a polynomial (denominator 1)?
    pub fn is_poly(&self) -> bool {
        self.den.is_one()
    }
    pub fn add(&self, o: &Self) -> Result<Self> {
        if self.den == o.den {
            return Self::new(self.num.add(&o.num), self.den.clone());
        }
        Self::new(
            self.num.mul(&o.den).add(&o.num.mul(&self.den)),
            self.den.mul(&o.den),
        )
    }
    pub fn neg(&self) -> Self {
        RatFunc {
            num: self.num.neg(),
            den: self.den.clone(),
        }
    }
    pub fn sub(&self, o: &Self) -> Result<Self> {
        self.add(&o.neg())
    }
    pub fn mul(&self, o: &Self) -> Result<Self> {
        Self::new(self.num.mul(&o.num), self.den.mul(&o.den))
    }
    /// # Errors
    /// `DivisionByZero` for the zero function.
    pub fn inv(&self) -> Result<Self> {
        if self.is_zero() {
            return Err(Error::DivisionByZero);
        }
        Self::new(self.den.clone(), self.num.clone())
    }
    pub fn div(&self, o: &Self) -> Result<Self> {
        self.mul(&o.inv()?)
    }
    /// Value at a rational `v`; `None` at a pole.
    pub fn eval(&self, v: &Rational) -> Option<Rational> {
        let d = self.den.eval(v);
        if d.is_zero() {
            return None;
        }
        Some(self.num.eval(v) / d)
    }
    /// Value at a float `v` (Horner on both parts).
    pub fn eval_f64(&self, v: f64) -> f64 {
        horner_f64(&self.num, v) / horner_f64(&self.den, v)
    }
    pub(crate) fn size_ok(self) -> Result<Self> {
        if self.num.deg() > MAX_DEGREE || self.den.deg() > MAX_DEGREE {
            return Err(Error::Limit(format!(
                "rational function of degree above {MAX_DEGREE}"
            )));
        }
        Ok(self)
    }
}

/// Horner evaluation of a rational polynomial in `f64`.
pub fn horner_f64(p: &Poly<Q>, v: f64) -> f64 {
    p.coeffs()
        .iter()
        .rev()
        .fold(0.0, |acc, c| acc * v + crate::field::rational_to_f64(c))
}

impl fmt::Display for RatFunc {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.is_poly() {
            write!(f, "{}", self.num.to_string_var("v"))
        } else {
            write!(
                f,
                "({})/({})",
                self.num.to_string_var("v"),
                self.den.to_string_var("v")
            )
        }
    }
}

/// $\mathbb{Q}(v)$ with names resolved by `lookup`; errors name the text.
struct InQv<'a> {
    text: &'a str,
    lookup: &'a dyn Fn(&str) -> Result<Option<RatFunc>>,
}

impl InQv<'_> {
    fn bad<T>(&self, what: &str) -> Result<T> {
        Err(Error::Invalid(format!("{what} in '{}'", self.text)))
    }
}

impl Algebra for InQv<'_> {
    type Value = RatFunc;
    type Error = Error;
    fn syntax(&self, e: SyntaxError) -> Error {
        Error::Invalid(e.msg)
    }
    fn number(&self, s: &str, _: usize) -> Result<RatFunc> {
        parse_number(s)
            .map(RatFunc::constant)
            .map_err(|m| Error::Invalid(format!("{m} in '{}'", self.text)))
    }
    fn name(&self, n: &str, _: usize) -> Result<RatFunc> {
        if RESERVED.contains(&n) {
            return Err(Error::Unsupported(format!(
                "'{n}' in '{}': a parameter study needs rational entries",
                self.text
            )));
        }
        match (self.lookup)(n)? {
            Some(v) => Ok(v),
            None => self.bad(&format!("unknown parameter '{n}'")),
        }
    }
    fn call(&self, f: &str, _: Vec<RatFunc>, at: usize) -> Result<RatFunc> {
        self.name(f, at)
    }
    fn neg(&self, a: RatFunc, _: usize) -> Result<RatFunc> {
        Ok(a.neg())
    }
    fn add(&self, a: RatFunc, b: RatFunc, subtract: bool, _: usize) -> Result<RatFunc> {
        if subtract { a.sub(&b) } else { a.add(&b) }?.size_ok()
    }
    fn mul(&self, a: RatFunc, b: RatFunc, divide: bool, _: usize) -> Result<RatFunc> {
        if !divide {
            return a.mul(&b)?.size_ok();
        }
        if b.is_zero() {
            return self.bad("division by zero");
        }
        a.div(&b)?.size_ok()
    }
    fn pow(&self, base: RatFunc, e: RatFunc, _: usize) -> Result<RatFunc> {
        let Some(n) = e
            .is_poly()
            .then(|| e.num.coeff(0))
            .filter(|_| e.num.deg() == 0)
        else {
            return self.bad("exponent must be an integer constant");
        };
        if !n.is_integer() || n.numer().magnitude() > &MAX_EXP.into() {
            return self.bad(&format!(
                "exponent must be an integer with |n| <= {MAX_EXP}"
            ));
        }
        let k: i64 = n.to_integer().try_into().unwrap_or(0);
        let p = RatFunc {
            num: base.num.pow(k.unsigned_abs() as u32),
            den: base.den.pow(k.unsigned_abs() as u32),
        }
        .size_ok()?;
        if k < 0 {
            if p.is_zero() {
                return self.bad("division by zero");
            }
            p.inv()
        } else {
            Ok(p)
        }
    }
}

/// Value of the expression `text` in $\mathbb{Q}(v)$; names are resolved by `lookup`
/// (`Ok(None)`: unknown name).
///
/// # Errors
/// `Invalid` for syntax errors, unknown names, division by zero; `Unsupported` for
/// `sqrt`, `i`, `pi`; `Limit` beyond the size bounds.
///
/// # Examples
/// ```
/// use exactlti::field::{Rational, parse_rational};
/// use exactlti::study::ratfunc::{RatFunc, eval_ratfunc};
/// let two = RatFunc::constant(Rational::from_integer(2.into()));
/// let f = eval_ratfunc("9.81*k + v^2/(2*v)", &|n| {
///     Ok(match n {
///         "v" => Some(RatFunc::var()),
///         "k" => Some(two.clone()),
///         _ => None,
///     })
/// })
/// .unwrap();
/// // v/2 + 19.62, exactly
/// assert!(f.is_poly());
/// assert_eq!(f.eval(&parse_rational("4").unwrap()), Some(parse_rational("21.62").unwrap()));
/// ```
pub fn eval_ratfunc(
    text: &str,
    lookup: &dyn Fn(&str) -> Result<Option<RatFunc>>,
) -> Result<RatFunc> {
    evaluate(&InQv { text, lookup }, text, Dialect::EXACT)
}

/// A `RatFunc` from a plain number token (exact text).
pub fn ratfunc_from_number(s: &str) -> Result<RatFunc> {
    parse_number(s)
        .map(RatFunc::constant)
        .map_err(Error::Invalid)
}

/// Exact value `1`.
pub fn one() -> RatFunc {
    RatFunc::constant(Rational::one())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ev(s: &str) -> Result<String> {
        eval_ratfunc(s, &|n| {
            Ok(match n {
                "v" => Some(RatFunc::var()),
                "g" => Some(RatFunc::constant(Rational::new(981.into(), 100.into()))),
                _ => None,
            })
        })
        .map(|f| f.to_string())
    }

    #[test]
    fn examples() {
        assert_eq!(ev("g*2 + v^2").unwrap(), "v^2 + 981/50");
        assert_eq!(ev("(v^2 - 1)/(v - 1)").unwrap(), "v + 1");
        assert_eq!(ev("1/(2*v)").unwrap(), "(1/2)/(v)");
        assert_eq!(ev("-v^-2").unwrap(), "(-1)/(v^2)");
        assert_eq!(ev("1.5e-3").unwrap(), "3/2000");
    }

    #[test]
    fn errors() {
        assert!(ev("v/(v - v)").is_err());
        assert!(ev("v^100").is_err());
        assert!(ev("sqrt(2)").is_err());
        assert!(ev("w").is_err());
        assert!(ev("(v").is_err());
        assert!(ev("v v").is_err());
        assert!(ev("v^v").is_err());
    }
}
