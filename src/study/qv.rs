//! The field $\mathbb{Q}(v)$ of a one-parameter study: the tower's
//! [`RatFuncField`] with one symbol, an element $f = n(v)/d(v)$ with $n, d \in
//! \mathbb{Z}[v]$ coprime. This module holds what the study needs on top of it: the
//! evaluator of system-file expressions with a name lookup ([`eval_qv`], the one grammar of
//! [`crate::field::expr`]), values at a point of any field ([`eval_in`]) or in `f64`, and
//! the numerator/denominator as polynomials over $\mathbb{Q}$ ([`num_q`], [`den_q`]).
//!
//! Work is bounded: exponents $|n| \le$ [`MAX_EXP`], degrees $\le$ [`MAX_DEGREE`]
//! (`Limit` beyond), nesting as in [`crate::field::expr`].

use crate::error::{Error, Result};
use crate::field::expr::{Algebra, Dialect, RESERVED, SyntaxError, evaluate, parse_number};
use crate::field::{Field, Q, Rational};
use crate::mpoly::MPoly;
use crate::poly::Poly;
use crate::ratfunc::{RatFunc, RatFuncField};

/// Largest |exponent| accepted in an expression.
pub const MAX_EXP: u32 = 64;
/// Largest degree of a numerator or denominator.
pub const MAX_DEGREE: usize = 256;

/// $\mathbb{Q}(v)$ with the symbol named `param`.
///
/// # Errors
/// `Invalid` for a name that cannot be a symbol.
pub fn field(param: &str) -> Result<RatFuncField> {
    RatFuncField::new(&[param])
}

/// A univariate integer polynomial as a polynomial over $\mathbb{Q}$.
pub fn upoly(f: &MPoly) -> Poly<Q> {
    Poly::new(
        Q,
        f.to_univariate(0)
            .iter()
            .map(|c| Rational::from_integer(c.to_constant().unwrap_or_default()))
            .collect(),
    )
}

/// The numerator of `f` in $\mathbb{Q}[v]$.
pub fn num_q(f: &RatFunc) -> Poly<Q> {
    upoly(f.num())
}

/// The denominator of `f` in $\mathbb{Q}[v]$, monic.
pub fn den_q(f: &RatFunc) -> Poly<Q> {
    upoly(f.den()).monic()
}

/// $f(v_0)$ in `k`.
///
/// # Errors
/// `DivisionByZero` when the denominator vanishes at `v0`.
pub fn eval_in<K: Field>(k: &K, f: &RatFunc, v0: &K::Elem) -> Result<K::Elem> {
    let h = |p: &MPoly| {
        p.to_univariate(0).iter().rev().fold(k.zero(), |acc, c| {
            let c = Rational::from_integer(c.to_constant().unwrap_or_default());
            k.add(&k.mul(&acc, v0), &k.from_rational(&c))
        })
    };
    let d = k.inv(&h(f.den())).ok_or(Error::DivisionByZero)?;
    Ok(k.mul(&h(f.num()), &d))
}

/// `f` as `(n, d)` over $\mathbb{Q}$ with `d` monic: $f = n/d$.
pub fn parts_q(f: &RatFunc) -> (Poly<Q>, Poly<Q>) {
    let d = upoly(f.den());
    let lc = d.lc();
    let inv = Q.inv(&lc).expect("nonzero denominator");
    (num_q(f).scale(&inv), d.scale(&inv))
}

/// The coefficients of a univariate integer polynomial in `f64`, low degree first.
pub fn coeffs_f64(f: &MPoly) -> Vec<f64> {
    f.to_univariate(0)
        .iter()
        .map(|c| {
            crate::field::rational_to_f64(&Rational::from_integer(
                c.to_constant().unwrap_or_default(),
            ))
        })
        .collect()
}

/// The rational constant `f` is, if it is one.
pub fn constant(f: &RatFunc) -> Option<Rational> {
    f.to_rational()
}

/// `Limit` above [`MAX_DEGREE`].
pub(crate) fn size_ok(f: RatFunc) -> Result<RatFunc> {
    if f.num().deg(0) as usize > MAX_DEGREE || f.den().deg(0) as usize > MAX_DEGREE {
        return Err(Error::Limit(format!(
            "rational function of degree above {MAX_DEGREE}"
        )));
    }
    Ok(f)
}

/// $\mathbb{Q}(v)$ with names resolved by `lookup`; errors name the text.
struct InQv<'a> {
    k: &'a RatFuncField,
    text: &'a str,
    lookup: &'a dyn Fn(&str) -> Result<Option<RatFunc>>,
}

impl InQv<'_> {
    fn bad<T>(&self, what: &str) -> Result<T> {
        Err(Error::Invalid(format!("{what} in '{}'", self.text)))
    }
    /// `a / b` for nonzero `b`, no condition recorded (reading is not a computation).
    fn div(&self, a: &RatFunc, b: &RatFunc) -> Result<RatFunc> {
        match self.k.div_unrecorded(a, b) {
            Some(x) => size_ok(x),
            None => self.bad("division by zero"),
        }
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
            .map(|q| self.k.from_rational(&q))
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
        Ok(self.k.neg(&a))
    }
    fn add(&self, a: RatFunc, b: RatFunc, subtract: bool, _: usize) -> Result<RatFunc> {
        size_ok(if subtract {
            self.k.sub(&a, &b)
        } else {
            self.k.add(&a, &b)
        })
    }
    fn mul(&self, a: RatFunc, b: RatFunc, divide: bool, _: usize) -> Result<RatFunc> {
        if divide {
            self.div(&a, &b)
        } else {
            size_ok(self.k.mul(&a, &b))
        }
    }
    fn pow(&self, base: RatFunc, e: RatFunc, _: usize) -> Result<RatFunc> {
        let Some(n) = constant(&e) else {
            return self.bad("exponent must be an integer constant");
        };
        if !n.is_integer() || n.numer().magnitude() > &MAX_EXP.into() {
            return self.bad(&format!(
                "exponent must be an integer with |n| <= {MAX_EXP}"
            ));
        }
        let k: i64 = n.to_integer().try_into().unwrap_or(0);
        let m = k.unsigned_abs() as u32;
        let (num, den) = (base.num().pow(m), base.den().pow(m));
        let p = size_ok(self.k.frac(num, den).ok_or(Error::DivisionByZero)?)?;
        if k < 0 {
            self.div(&self.k.one(), &p)
        } else {
            Ok(p)
        }
    }
}

/// Value of the expression `text` in $\mathbb{Q}(v)$ = `k`; names are resolved by `lookup`
/// (`Ok(None)`: unknown name).
///
/// # Errors
/// `Invalid` for syntax errors, unknown names, division by zero; `Unsupported` for
/// `sqrt`, `i`, `pi`; `Limit` beyond the size bounds.
///
/// # Examples
/// ```
/// use exactlti::field::{Field, parse_rational};
/// use exactlti::study::qv::{eval_qv, field};
/// let k = field("v").unwrap();
/// let two = k.from_i64(2);
/// let f = eval_qv(&k, "9.81*g + v^2/(2*v)", &|n| {
///     Ok(match n {
///         "v" => Some(k.var(0)),
///         "g" => Some(two.clone()),
///         _ => None,
///     })
/// })
/// .unwrap();
/// // v/2 + 19.62, exactly
/// assert!(f.den().is_constant());
/// assert_eq!(k.eval(&f, &[parse_rational("4").unwrap()]), Some(parse_rational("21.62").unwrap()));
/// ```
pub fn eval_qv(
    k: &RatFuncField,
    text: &str,
    lookup: &dyn Fn(&str) -> Result<Option<RatFunc>>,
) -> Result<RatFunc> {
    evaluate(&InQv { k, text, lookup }, text, Dialect::EXACT)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ev(s: &str) -> Result<RatFunc> {
        let k = field("v").unwrap();
        eval_qv(&k, s, &|n| {
            Ok(match n {
                "v" => Some(k.var(0)),
                "g" => Some(k.from_rational(&Rational::new(981.into(), 100.into()))),
                _ => None,
            })
        })
    }

    fn same(s: &str, want: &str) {
        let k = field("v").unwrap();
        assert_eq!(ev(s).unwrap(), k.parse(want).unwrap(), "{s}");
    }

    #[test]
    fn examples() {
        same("g*2 + v^2", "v^2 + 981/50");
        same("(v^2 - 1)/(v - 1)", "v + 1");
        same("1/(2*v)", "(1/2)/(v)");
        same("-v^-2", "(-1)/(v^2)");
        same("1.5e-3", "3/2000");
        let k = field("v").unwrap();
        assert_eq!(
            den_q(&ev("1/(2*v)").unwrap()),
            Poly::<Q>::from_i64s(&[0, 1])
        );
        let half = |a: i64, b: i64| Rational::new(a.into(), b.into());
        assert_eq!(
            num_q(&ev("g*2 + v^2").unwrap()).scale(&half(1, 50)),
            Poly::new(Q, vec![half(981, 50), half(0, 1), half(1, 1)])
        );
        let x = eval_in(
            &Q,
            &ev("1/(v - 1)").unwrap(),
            &Rational::from_integer(3.into()),
        );
        assert_eq!(x.unwrap(), Rational::new(1.into(), 2.into()));
        assert!(
            eval_in(
                &Q,
                &ev("1/(v - 1)").unwrap(),
                &Rational::from_integer(1.into())
            )
            .is_err()
        );
        assert_eq!(k.to_string(), "QQ(v)");
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
        assert!(matches!(ev("(v^60)^5"), Err(Error::Limit(_))));
    }
}
