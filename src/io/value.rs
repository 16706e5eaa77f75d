//! The value of an exact expression: $a + b\sqrt d$ with $a, b \in \mathbb{Q}$ and at most
//! one square-free radicand `d`, with every operation size-checked against
//! [`MAX_BITS`] and [`MAX_EXPONENT`] (re-exported by [`super::expr`]); its errors are the
//! crate's [`Error::Invalid`] with the message.

use crate::error::{Error, Result};
use crate::field::{ElemDisplay, Q, QuadraticField, Rational};
use num_bigint::BigInt;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// Largest accepted |exponent| in `x^n` (and in literals such as `1e-3`).
pub use crate::field::expr::MAX_EXPONENT;
/// Largest accepted size (bits of a numerator or denominator) of any intermediate value.
/// num-bigint's gcd (binary, quadratic) makes one operation on numbers of this size cost
/// tens of milliseconds at most; beyond it an input could stall for seconds.
pub const MAX_BITS: u64 = 1 << 14;

/// An invalid expression: [`Error::Invalid`] with what is wrong (a 1-based character
/// position where useful); its `Display` is the message itself.
pub(crate) fn err<T>(msg: impl Into<String>) -> Result<T> {
    Err(Error::Invalid(msg.into()))
}

/// A value $a + b\sqrt d$; `k` is `Some` exactly when `b != 0` (canonical).
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Value {
    pub a: Rational,
    pub b: Rational,
    pub k: Option<QuadraticField>,
}

/// `x + y`, skipping num-rational's gcd reduction when both are integers (its binary gcd
/// is quadratic even for `gcd(x, 1)`).
fn q_add(x: &Rational, y: &Rational) -> Rational {
    if x.is_integer() && y.is_integer() {
        Rational::from_integer(x.numer() + y.numer())
    } else {
        x + y
    }
}

/// `x * y`, with the same integer shortcut as [`q_add`].
fn q_mul(x: &Rational, y: &Rational) -> Rational {
    if x.is_zero() || y.is_zero() {
        Rational::zero()
    } else if x.is_integer() && y.is_integer() {
        Rational::from_integer(x.numer() * y.numer())
    } else {
        x * y
    }
}

/// `x^n` for a rational `x`: numerator and denominator powered separately (already in
/// lowest terms, no gcd needed). `x` must be non-zero when `n < 0`.
fn q_pow(x: &Rational, n: u32, negative: bool) -> Rational {
    let p = num_traits::pow(x.numer().clone(), n as usize);
    let q = num_traits::pow(x.denom().clone(), n as usize);
    if !negative {
        Rational::new_raw(p, q)
    } else if p.is_negative() {
        Rational::new_raw(-q, -p)
    } else {
        Rational::new_raw(q, p)
    }
}

fn bits(q: &Rational) -> u64 {
    q.numer().bits().max(q.denom().bits())
}

/// `(b sqrt(d)) * (c sqrt(e))` for square-free `d != e`: `b c g sqrt(f)` with `g = gcd(d, e)`
/// and `f = (d/g)(e/g)` square-free (`sqrt(3)*i` is `sqrt(-3)`, `sqrt(2)*sqrt(3)` is
/// `sqrt(6)`), so every display of a quadratic number (`sqrt(3)*i/2`) reads back.
fn radical_product(
    b: &Rational,
    x: &QuadraticField,
    c: &Rational,
    y: &QuadraticField,
) -> Result<Value> {
    use num_integer::Integer;
    let g = x.d().gcd(y.d());
    let f = (x.d() / &g) * (y.d() / &g);
    // both negative: sqrt(d) sqrt(e) = i^2 sqrt(|d| |e|) = -sqrt(|d e|)
    let g = if x.d().is_negative() && y.d().is_negative() {
        -g
    } else {
        g
    };
    let coef = q_mul(&q_mul(b, c), &Rational::from_integer(g));
    if f.is_one() {
        return Value::rational(coef).checked();
    }
    if f.abs() >= BigInt::from(10u64.pow(18)) {
        return err("product of square roots too large (the radicand must stay below 10^18)");
    }
    let k = QuadraticField::new(f).map_err(|e| Error::Invalid(e.to_string()))?;
    Value::new(Rational::zero(), coef, Some(k)).checked()
}

impl Value {
    pub(crate) fn new(a: Rational, b: Rational, k: Option<QuadraticField>) -> Self {
        let k = if b.is_zero() { None } else { k };
        Value { a, b, k }
    }
    pub(crate) fn rational(a: Rational) -> Self {
        Value::new(a, Rational::zero(), None)
    }
    pub(crate) fn is_zero(&self) -> bool {
        self.a.is_zero() && self.b.is_zero()
    }
    pub(crate) fn size(&self) -> u64 {
        bits(&self.a).max(bits(&self.b))
    }
    pub(crate) fn checked(self) -> Result<Value> {
        if self.size() > MAX_BITS {
            return err(format!("number too large (more than {MAX_BITS} bits)"));
        }
        Ok(self)
    }
    /// The common field of two values, or an error when they have different radicands.
    pub(crate) fn join(&self, o: &Value) -> Result<Option<QuadraticField>> {
        match (&self.k, &o.k) {
            (Some(x), Some(y)) if x != y => err(format!(
                "values of {x} and {y} cannot be mixed: all values must lie in one quadratic field"
            )),
            (Some(x), _) | (None, Some(x)) => Ok(Some(x.clone())),
            (None, None) => Ok(None),
        }
    }
    pub(crate) fn add(&self, o: &Value) -> Result<Value> {
        let k = self.join(o)?;
        Value::new(q_add(&self.a, &o.a), q_add(&self.b, &o.b), k).checked()
    }
    pub(crate) fn neg(&self) -> Value {
        Value::new(-&self.a, -&self.b, self.k.clone())
    }
    pub(crate) fn mul(&self, o: &Value) -> Result<Value> {
        if let (Some(x), Some(y)) = (&self.k, &o.k)
            && x != y
            && self.a.is_zero()
            && o.a.is_zero()
        {
            return radical_product(&self.b, x, &o.b, y);
        }
        let k = self.join(o)?;
        let bb = if self.b.is_zero() || o.b.is_zero() {
            Rational::zero()
        } else {
            let d = Rational::from_integer(k.as_ref().map_or_else(BigInt::zero, |k| k.d().clone()));
            q_mul(&d, &q_mul(&self.b, &o.b))
        };
        let a = q_add(&q_mul(&self.a, &o.a), &bb);
        let b = q_add(&q_mul(&self.a, &o.b), &q_mul(&self.b, &o.a));
        Value::new(a, b, k).checked()
    }
    pub(crate) fn inv(&self) -> Result<Value> {
        if self.is_zero() {
            return err("division by zero");
        }
        // (a + b r)^-1 = (a - b r) / (a^2 - d b^2); the norm is non-zero since d is no square
        let d =
            Rational::from_integer(self.k.as_ref().map_or_else(BigInt::zero, |k| k.d().clone()));
        let n = &self.a * &self.a - d * &self.b * &self.b;
        Value::new(&self.a / &n, -&self.b / &n, self.k.clone()).checked()
    }
    pub(crate) fn pow(&self, e: &Value) -> Result<Value> {
        if e.k.is_some() || !e.a.is_integer() {
            let shown = if e.k.is_some() {
                "a non-rational value".to_string()
            } else {
                Q.fmt_elem(&e.a)
            };
            return err(format!("exponent must be an integer, found {shown}"));
        }
        let n = match e.a.numer().abs().to_u32() {
            Some(n) if n <= MAX_EXPONENT => n,
            _ => {
                return err(format!(
                    "exponent {} is too large (at most {MAX_EXPONENT} in absolute value)",
                    e.a.numer()
                ));
            }
        };
        if self.is_zero() && e.a.is_negative() {
            return err("division by zero: 0 raised to a negative power");
        }
        if self.size().saturating_mul(u64::from(n)) > MAX_BITS {
            return err(format!("power too large (more than {MAX_BITS} bits)"));
        }
        if self.k.is_none() {
            return Value::rational(q_pow(&self.a, n, e.a.is_negative())).checked();
        }
        let mut result = Value::rational(Rational::one());
        let mut base = self.clone();
        let mut m = n;
        while m > 0 {
            if m & 1 == 1 {
                result = result.mul(&base)?;
            }
            m >>= 1;
            if m > 0 {
                base = base.mul(&base)?;
            }
        }
        if e.a.is_negative() {
            result.inv()
        } else {
            Ok(result)
        }
    }
    pub(crate) fn sqrt(&self) -> Result<Value> {
        if self.k.is_some() {
            return err("sqrt of a non-rational value is not supported; use sqrt of a rational");
        }
        // squarefree_split is exact below 10^18 (trial division to 10^6)
        let nm = self.a.numer() * self.a.denom();
        if nm.abs() >= BigInt::from(10u64.pow(18)) {
            return err("sqrt argument too large (numerator*denominator must stay below 10^18)");
        }
        let (k, a, b) = QuadraticField::sqrt_of_rational(&self.a);
        Ok(Value::new(a, b, k))
    }
}
