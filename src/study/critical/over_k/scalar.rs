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
use crate::ratfunc::{RatFunc, RatFuncField};
use crate::study::family_read::ScalarReader;
use crate::study::qv::{MAX_EXP, den_q, eval_in, size_ok};

/// $a + \theta b$ with $a, b \in \mathbb{Q}(v)$.
#[derive(Clone, Debug, PartialEq)]
pub struct KRat {
    pub a: RatFunc,
    pub b: RatFunc,
}

impl KRat {
    /// The element $a$ of $\mathbb{Q}(v)$ = `q`.
    pub fn real(q: &RatFuncField, a: RatFunc) -> Self {
        KRat { a, b: q.zero() }
    }
    pub fn is_zero(&self) -> bool {
        self.a.num().is_zero() && self.b.num().is_zero()
    }
    /// $-x$.
    pub fn neg(&self, q: &RatFuncField) -> Self {
        KRat {
            a: q.neg(&self.a),
            b: q.neg(&self.b),
        }
    }
    /// Its value at `v0` in a field `e` holding $\theta$ as `theta` (`DivisionByZero` at a
    /// pole).
    ///
    /// # Errors
    /// `DivisionByZero` when a denominator vanishes at `v0`.
    pub fn eval_in<E: Field>(&self, e: &E, theta: &E::Elem, v0: &E::Elem) -> Result<E::Elem> {
        let a = eval_in(e, &self.a, v0)?;
        let b = eval_in(e, &self.b, v0)?;
        Ok(e.add(&a, &e.mul(theta, &b)))
    }
    /// The common denominator $\operatorname{lcm}$ of both parts (monic, in $\mathbb{Q}[v]$).
    pub fn den(&self) -> crate::poly::Poly<Q> {
        let (x, y) = (den_q(&self.a), den_q(&self.b));
        x.mul(&y).quo(&x.gcd(&y)).monic()
    }
}

/// Reads entries into $K(v)$ for the field `k` of the system file, $\mathbb{Q}(v)$ = `q`.
pub struct KReader {
    pub k: QuadraticField,
    pub q: RatFuncField,
}

impl KReader {
    fn d(&self) -> RatFunc {
        self.q
            .from_rational(&Rational::from_integer(self.k.d().clone()))
    }
    fn mul(&self, x: &KRat, y: &KRat) -> Result<KRat> {
        let q = &self.q;
        let a = q.add(&q.mul(&x.a, &y.a), &q.mul(&self.d(), &q.mul(&x.b, &y.b)));
        let b = q.add(&q.mul(&x.a, &y.b), &q.mul(&x.b, &y.a));
        Ok(KRat {
            a: size_ok(a)?,
            b: size_ok(b)?,
        })
    }
    fn inv(&self, x: &KRat) -> Result<KRat> {
        let q = &self.q;
        let n = q.sub(&q.mul(&x.a, &x.a), &q.mul(&self.d(), &q.mul(&x.b, &x.b)));
        let div = |y: &RatFunc| q.div_unrecorded(y, &n).ok_or(Error::DivisionByZero);
        Ok(KRat {
            a: size_ok(div(&x.a)?)?,
            b: size_ok(div(&q.neg(&x.b))?)?,
        })
    }
    fn constant(&self, c: Rational) -> KRat {
        KRat::real(&self.q, self.q.from_rational(&c))
    }
}

impl ScalarReader for KReader {
    type Value = KRat;
    fn var(&self) -> KRat {
        KRat::real(&self.q, self.q.var(0))
    }
    fn number(&self, s: &str) -> Result<KRat> {
        parse_number(s)
            .map(|c| self.constant(c))
            .map_err(Error::Invalid)
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
        x.b.num().is_zero().then(|| x.a.to_rational()).flatten()
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
            .map(|q| self.r.constant(q))
            .map_err(|m| Error::Invalid(format!("{m} in '{}'", self.text)))
    }
    fn name(&self, n: &str, _: usize) -> Result<KRat> {
        if n == "i" {
            if *self.r.k.d() != (-1).into() {
                return self.not_in_field("i");
            }
            return Ok(KRat {
                a: self.r.q.zero(),
                b: self.r.q.one(),
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
            None => Ok(self.r.constant(a)),
            Some(f) if f.d() == self.r.k.d() => Ok(KRat {
                a: self.r.q.zero(),
                b: self.r.q.from_rational(&b),
            }),
            Some(_) => self.not_in_field(&format!("sqrt({q})")),
        }
    }
    fn neg(&self, a: KRat, _: usize) -> Result<KRat> {
        Ok(a.neg(&self.r.q))
    }
    fn add(&self, a: KRat, b: KRat, subtract: bool, _: usize) -> Result<KRat> {
        let q = &self.r.q;
        let b = if subtract { b.neg(q) } else { b };
        Ok(KRat {
            a: size_ok(q.add(&a.a, &b.a))?,
            b: size_ok(q.add(&a.b, &b.b))?,
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
        let mut acc = KRat::real(&self.r.q, self.r.q.one());
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
        let q = crate::study::qv::field("v").unwrap();
        let r = KReader {
            k: QuadraticField::new(d).unwrap(),
            q: q.clone(),
        };
        r.eval(s, &|n| Ok((n == "v").then(|| KRat::real(&q, q.var(0)))))
    }

    fn qv(s: &str) -> RatFunc {
        crate::study::qv::field("v").unwrap().parse(s).unwrap()
    }

    #[test]
    fn reads_quadratic_rational_functions() {
        // (sqrt 2 v)^2 = 2 v^2; 1/(1 + sqrt 2) = sqrt 2 - 1
        let x = ev(2, "(sqrt(2)*v)^2").unwrap();
        assert_eq!(x.a, qv("2*v^2"));
        assert!(x.b.num().is_zero());
        let y = ev(2, "1/(1 + sqrt(8)/2)").unwrap();
        assert_eq!((y.a, y.b), (qv("-1"), qv("1")));
        let z = ev(-1, "(v + i)^-1").unwrap();
        // (v - i)/(v^2 + 1)
        assert_eq!(z.a, qv("(v)/(v^2 + 1)"));
        assert_eq!(z.b, qv("(-1)/(v^2 + 1)"));
        assert!(ev(2, "i").is_err());
        assert!(ev(2, "sqrt(3)").is_err());
        assert!(ev(-1, "sqrt(v)").is_err());
        assert!(ev(2, "v/(v - v)").is_err());
        assert!(ev(2, "w").is_err());
    }
}
