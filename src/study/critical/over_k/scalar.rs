//! Entries of a family over $K(v)$, $K = \mathbb{Q}(\theta)$ with $\theta^2 = d$
//! ($\theta = \sqrt d > 0$, or $\theta = i$ for $d = -1$): $a(v) + \theta\, b(v)$ with
//! $a, b \in \mathbb{Q}(v)$ ([`KRat`]), and the reader of system-file expressions into them
//! ([`KReader`], the one expression grammar of [`crate::field::expr`]).
//!
//! Arithmetic: $(a_1 + \theta b_1)(a_2 + \theta b_2) = (a_1 a_2 + d\, b_1 b_2) + \theta (a_1
//! b_2 + a_2 b_1)$, $(a + \theta b)^{-1} = (a - \theta b) / (a^2 - d b^2)$ (the norm is a
//! nonzero element of $\mathbb{Q}(v)$ for $(a, b) \ne 0$, as $\theta \notin \mathbb{Q}(v)$).

use crate::error::{Error, Result};
use crate::field::expr::{Algebra, Dialect, RESERVED, SyntaxError, evaluate, parse_number};
use crate::field::{Field, Q, QuadraticField, Rational};
use crate::study::family_read::ScalarReader;
use crate::study::ratfunc::{MAX_EXP, RatFunc, ratfunc_from_number};
use num_traits::One;

/// $a + \theta b$ with $a, b \in \mathbb{Q}(v)$.
#[derive(Clone, Debug, PartialEq)]
pub struct KRat {
    pub a: RatFunc,
    pub b: RatFunc,
}

impl KRat {
    /// The element $a$ of $\mathbb{Q}(v)$.
    pub fn real(a: RatFunc) -> Self {
        KRat {
            a,
            b: RatFunc::zero(),
        }
    }
    pub fn is_zero(&self) -> bool {
        self.a.is_zero() && self.b.is_zero()
    }
    /// Its value at `v0` in a field `e` holding $\theta$ as `theta` (`DivisionByZero` at a
    /// pole).
    ///
    /// # Errors
    /// `DivisionByZero` when a denominator vanishes at `v0`.
    pub fn eval_in<E: Field>(&self, e: &E, theta: &E::Elem, v0: &E::Elem) -> Result<E::Elem> {
        let a = crate::study::family::eval_in(e, &self.a, v0)?;
        let b = crate::study::family::eval_in(e, &self.b, v0)?;
        Ok(e.add(&a, &e.mul(theta, &b)))
    }
    /// The common denominator $\operatorname{lcm}$ of both parts (monic, in $\mathbb{Q}[v]$).
    pub fn den(&self) -> crate::poly::Poly<Q> {
        let (x, y) = (&self.a.den, &self.b.den);
        x.mul(y).quo(&x.gcd(y)).monic()
    }
}

/// Reads entries into $K(v)$ for the field `k` of the system file.
pub struct KReader {
    pub k: QuadraticField,
}

impl KReader {
    fn d(&self) -> RatFunc {
        RatFunc::constant(Rational::from_integer(self.k.d().clone()))
    }
    fn mul(&self, x: &KRat, y: &KRat) -> Result<KRat> {
        let a = x.a.mul(&y.a)?.add(&self.d().mul(&x.b.mul(&y.b)?)?)?;
        let b = x.a.mul(&y.b)?.add(&x.b.mul(&y.a)?)?;
        Ok(KRat {
            a: a.size_ok()?,
            b: b.size_ok()?,
        })
    }
    fn inv(&self, x: &KRat) -> Result<KRat> {
        let n = x.a.mul(&x.a)?.sub(&self.d().mul(&x.b.mul(&x.b)?)?)?;
        if n.is_zero() {
            return Err(Error::DivisionByZero);
        }
        Ok(KRat {
            a: x.a.div(&n)?.size_ok()?,
            b: x.b.neg().div(&n)?.size_ok()?,
        })
    }
}

impl ScalarReader for KReader {
    type Value = KRat;
    fn var(&self) -> KRat {
        KRat::real(RatFunc::var())
    }
    fn number(&self, s: &str) -> Result<KRat> {
        ratfunc_from_number(s).map(KRat::real)
    }
    fn eval(&self, text: &str, lookup: &dyn Fn(&str) -> Result<Option<KRat>>) -> Result<KRat> {
        evaluate(
            &InKv {
                r: self,
                text,
                lookup,
            },
            text,
            Dialect::EXACT,
        )
    }
}

struct InKv<'a> {
    r: &'a KReader,
    text: &'a str,
    lookup: &'a dyn Fn(&str) -> Result<Option<KRat>>,
}

impl InKv<'_> {
    fn bad<T>(&self, what: &str) -> Result<T> {
        Err(Error::Invalid(format!("{what} in '{}'", self.text)))
    }
    /// The rational constant `x` is, if it is one.
    fn constant(x: &KRat) -> Option<Rational> {
        (x.b.is_zero() && x.a.is_poly() && x.a.num.deg() == 0).then(|| x.a.num.coeff(0))
    }
    fn not_in_field<T>(&self, what: &str) -> Result<T> {
        Err(Error::Invalid(format!(
            "'{what}' in '{}' is not in the field of the system, {}",
            self.text, self.r.k
        )))
    }
}

impl Algebra for InKv<'_> {
    type Value = KRat;
    type Error = Error;
    fn syntax(&self, e: SyntaxError) -> Error {
        Error::Invalid(e.msg)
    }
    fn number(&self, s: &str, _: usize) -> Result<KRat> {
        parse_number(s)
            .map(|q| KRat::real(RatFunc::constant(q)))
            .map_err(|m| Error::Invalid(format!("{m} in '{}'", self.text)))
    }
    fn name(&self, n: &str, _: usize) -> Result<KRat> {
        if n == "i" {
            if *self.r.k.d() != (-1).into() {
                return self.not_in_field("i");
            }
            return Ok(KRat {
                a: RatFunc::zero(),
                b: RatFunc::constant(Rational::one()),
            });
        }
        if RESERVED.contains(&n) {
            return self.bad(&format!("'{n}' is not a value"));
        }
        match (self.lookup)(n)? {
            Some(v) => Ok(v),
            None => self.bad(&format!("unknown parameter '{n}'")),
        }
    }
    fn call(&self, f: &str, mut args: Vec<KRat>, at: usize) -> Result<KRat> {
        if f != "sqrt" || args.len() != 1 {
            return self.name(f, at);
        }
        let Some(q) = args.pop().as_ref().and_then(Self::constant) else {
            return self.bad("sqrt of a value that is not a rational constant");
        };
        let (field, a, b) = QuadraticField::sqrt_of_rational(&q);
        match field {
            None => Ok(KRat::real(RatFunc::constant(a))),
            Some(f) if f.d() == self.r.k.d() => Ok(KRat {
                a: RatFunc::zero(),
                b: RatFunc::constant(b),
            }),
            Some(_) => self.not_in_field(&format!("sqrt({q})")),
        }
    }
    fn neg(&self, a: KRat, _: usize) -> Result<KRat> {
        Ok(KRat {
            a: a.a.neg(),
            b: a.b.neg(),
        })
    }
    fn add(&self, a: KRat, b: KRat, subtract: bool, _: usize) -> Result<KRat> {
        let b = if subtract { self.neg(b, 0)? } else { b };
        Ok(KRat {
            a: a.a.add(&b.a)?.size_ok()?,
            b: a.b.add(&b.b)?.size_ok()?,
        })
    }
    fn mul(&self, a: KRat, b: KRat, divide: bool, _: usize) -> Result<KRat> {
        if !divide {
            return self.r.mul(&a, &b);
        }
        if b.is_zero() {
            return self.bad("division by zero");
        }
        self.r.mul(&a, &self.r.inv(&b)?)
    }
    fn pow(&self, base: KRat, e: KRat, _: usize) -> Result<KRat> {
        let Some(n) = Self::constant(&e).filter(|n| n.is_integer()) else {
            return self.bad("exponent must be an integer constant");
        };
        if n.numer().magnitude() > &MAX_EXP.into() {
            return self.bad(&format!(
                "exponent must be an integer with |n| <= {MAX_EXP}"
            ));
        }
        let k: i64 = n.to_integer().try_into().unwrap_or(0);
        let mut acc = KRat::real(RatFunc::constant(Rational::one()));
        let mut sq = base;
        let mut m = k.unsigned_abs();
        while m > 0 {
            if m & 1 == 1 {
                acc = self.r.mul(&acc, &sq)?;
            }
            m >>= 1;
            if m > 0 {
                sq = self.r.mul(&sq, &sq)?;
            }
        }
        if k < 0 {
            if acc.is_zero() {
                return self.bad("division by zero");
            }
            return self.r.inv(&acc);
        }
        Ok(acc)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ev(d: i64, s: &str) -> Result<KRat> {
        let r = KReader {
            k: QuadraticField::new(d).unwrap(),
        };
        r.eval(s, &|n| Ok((n == "v").then(|| KRat::real(RatFunc::var()))))
    }

    #[test]
    fn reads_quadratic_rational_functions() {
        // (sqrt 2 v)^2 = 2 v^2; 1/(1 + sqrt 2) = sqrt 2 - 1
        let x = ev(2, "(sqrt(2)*v)^2").unwrap();
        assert_eq!(x.a.to_string(), "2*v^2");
        assert!(x.b.is_zero());
        let y = ev(2, "1/(1 + sqrt(8)/2)").unwrap();
        assert_eq!(
            (y.a.to_string(), y.b.to_string()),
            ("-1".into(), "1".into())
        );
        let z = ev(-1, "(v + i)^-1").unwrap();
        // (v - i)/(v^2 + 1)
        assert_eq!(z.a.to_string(), "(v)/(v^2 + 1)");
        assert_eq!(z.b.to_string(), "(-1)/(v^2 + 1)");
        assert!(ev(2, "i").is_err());
        assert!(ev(2, "sqrt(3)").is_err());
        assert!(ev(-1, "sqrt(v)").is_err());
        assert!(ev(2, "v/(v - v)").is_err());
        assert!(ev(2, "w").is_err());
    }
}
