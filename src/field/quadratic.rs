//! Quadratic fields $\mathbb{Q}(\sqrt d)$: elements $a + b\sqrt d$ ("algebraic-number pairs").
//!
//! `d` is a square-free integer different from 0 and 1; `d = -1` gives $\mathbb{Q}(i)$.
//! For `d > 0` the field is real (embedding $\sqrt d > 0$) and elements have an exact sign
//! and ordering: $a + b\sqrt d > 0$ is decided by comparing $a^2$ with $d b^2$.
//!
//! | entry point | computes |
//! |---|---|
//! | [`QuadraticField::new`] | the field for a square-free `d` |
//! | [`QuadraticField::sqrt_of_rational`] | $\sqrt{r}$ as (field, element) for any rational `r` |
//! | [`Field::sign`] | exact sign (real fields only) |

use super::{Field, Kernels, Rational, lehmer, rational_to_f64};
use crate::error::{Error, Result};
use num_bigint::BigInt;
use num_traits::{One, Signed, ToPrimitive, Zero};
use std::cmp::Ordering;

/// The field $\mathbb{Q}(\sqrt d)$, `d` square-free, `d != 0, 1`.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct QuadraticField {
    d: BigInt,
}

/// An element $a + b\sqrt d$.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Quadratic {
    pub a: Rational,
    pub b: Rational,
}

impl Quadratic {
    pub fn new(a: Rational, b: Rational) -> Self {
        Quadratic { a, b }
    }
}

/// A type-equality witness `E = Quadratic`, returned in [`crate::field::Kernels::Quadratic`]: views a
/// slice of elements as [`Quadratic`]s and turns them back into elements, without copying.
pub type QuadraticElems<E> = super::Elems<Quadratic, E>;

/// Trial division in [`squarefree_split`] goes up to this bound.
const TRIAL_LIMIT: u64 = 1_000_000;

/// The primes up to [`TRIAL_LIMIT`] (sieved once).
fn small_primes() -> &'static [u32] {
    static PRIMES: std::sync::OnceLock<Vec<u32>> = std::sync::OnceLock::new();
    PRIMES.get_or_init(|| {
        let n = TRIAL_LIMIT as usize;
        let mut composite = vec![false; n + 1];
        let mut out = vec![];
        for i in 2..=n {
            if !composite[i] {
                out.push(i as u32);
                let mut j = i * i;
                while j <= n {
                    composite[j] = true;
                    j += i;
                }
            }
        }
        out
    })
}

/// Square-free part and square root of the square part: `n = s^2 * f`, returns `(s, f)`.
/// Trial division up to `10^6`; a remaining cofactor is assumed square-free only if it is
/// not a perfect square (larger square factors are then rejected by the caller).
pub fn squarefree_split(n: &BigInt) -> (BigInt, BigInt) {
    let sign = if n.is_negative() {
        -BigInt::one()
    } else {
        BigInt::one()
    };
    let mut m = n.abs();
    let mut s = BigInt::one();
    let mut f = BigInt::one();
    // the last trial divisor: min(sqrt(m), TRIAL_LIMIT), updated when m shrinks
    let bound = |m: &BigInt| {
        m.sqrt()
            .to_u64()
            .map_or(TRIAL_LIMIT, |r| r.min(TRIAL_LIMIT))
    };
    let mut last = bound(&m);
    for &p in small_primes() {
        let p = u64::from(p);
        if p > last {
            break;
        }
        let mut e = 0u32;
        while (&m % p).is_zero() {
            m /= p;
            e += 1;
        }
        if e > 0 {
            s *= num_traits::pow(BigInt::from(p), (e / 2) as usize);
            if e % 2 == 1 {
                f *= p;
            }
            last = bound(&m);
        }
    }
    let r = m.sqrt();
    if &r * &r == m {
        s *= r;
    } else {
        f *= m;
    }
    (s, sign * f)
}

impl QuadraticField {
    /// The field $\mathbb{Q}(\sqrt d)$.
    ///
    /// # Errors
    /// `Invalid` when `d` is 0, 1, or not square-free.
    pub fn new(d: impl Into<BigInt>) -> Result<Self> {
        let d = d.into();
        let (s, f) = squarefree_split(&d);
        if d.is_zero() || d.is_one() || !s.is_one() || f != d {
            return Err(Error::Invalid(format!(
                "sqrt({d}) does not define a quadratic field (d must be square-free, not 0 or 1)"
            )));
        }
        Ok(QuadraticField { d })
    }
    /// The Gaussian rationals $\mathbb{Q}(i)$.
    pub fn gaussian() -> Self {
        QuadraticField {
            d: BigInt::from(-1),
        }
    }
    /// The radicand `d`.
    pub fn d(&self) -> &BigInt {
        &self.d
    }
    /// Is the field real (`d > 0`)?
    pub fn is_real(&self) -> bool {
        self.d.is_positive()
    }
    /// The generator $\sqrt d$.
    pub fn gen_elem(&self) -> Quadratic {
        Quadratic {
            a: Rational::zero(),
            b: Rational::one(),
        }
    }
    /// $\sqrt r$ for a rational `r`: `Ok(None)` field when `r` is a rational square
    /// (the element is then returned as a rational), else the field $\mathbb{Q}(\sqrt{f})$
    /// and the element $s\sqrt f$ with $r = s^2 f$.
    pub fn sqrt_of_rational(r: &Rational) -> (Option<QuadraticField>, Rational, Rational) {
        // r = n/m = n*m/m^2
        let nm = r.numer() * r.denom();
        let (s, f) = squarefree_split(&nm);
        let coef = Rational::new(s, r.denom().clone());
        if f.is_one() || nm.is_zero() {
            (
                None,
                if nm.is_zero() { Rational::zero() } else { coef },
                Rational::zero(),
            )
        } else {
            (Some(QuadraticField { d: f }), Rational::zero(), coef)
        }
    }
    /// Norm $a^2 - d b^2$.
    pub fn norm(&self, x: &Quadratic) -> Rational {
        lehmer::sub(
            &lehmer::mul(&x.a, &x.a),
            &self.times_d(&lehmer::mul(&x.b, &x.b)),
        )
    }
    /// `d * x` (canonical), for the products of the $\sqrt d$ parts.
    fn times_d(&self, x: &Rational) -> Rational {
        if self.d.is_negative() && self.d.magnitude().is_one() {
            -x
        } else {
            lehmer::mul(x, &Rational::from_integer(self.d.clone()))
        }
    }
    /// The Galois conjugate $a - b\sqrt d$.
    pub fn galois(&self, x: &Quadratic) -> Quadratic {
        Quadratic {
            a: x.a.clone(),
            b: -&x.b,
        }
    }
}

/// The text of $\sqrt d$ in every display: `i` for `d = -1`, `sqrt(3)*i` for `d = -3`,
/// `sqrt(2)` for `d = 2`.
pub fn radical_text(d: &BigInt) -> String {
    if *d == BigInt::from(-1) {
        "i".into()
    } else if d.is_negative() {
        format!("sqrt({})*i", -d)
    } else {
        format!("sqrt({d})")
    }
}

impl QuadraticField {
    /// Floating-point approximation `(re, im)` under the marked embedding
    /// ($\sqrt d > 0$, or $\sqrt d = i\sqrt{-d}$); always defined (the field trait's
    /// [`Field::approx`] wraps it in `Some`).
    pub fn approx(&self, x: &Quadratic) -> (f64, f64) {
        let a = rational_to_f64(&x.a);
        let b = rational_to_f64(&x.b);
        let r = rational_to_f64(&Rational::from_integer(self.d.abs())).sqrt();
        if self.d.is_positive() {
            (a + b * r, 0.0)
        } else {
            (a, b * r)
        }
    }
}

impl Field for QuadraticField {
    type Elem = Quadratic;
    fn zero(&self) -> Quadratic {
        Quadratic {
            a: Rational::zero(),
            b: Rational::zero(),
        }
    }
    fn one(&self) -> Quadratic {
        Quadratic {
            a: Rational::one(),
            b: Rational::zero(),
        }
    }
    fn is_zero(&self, x: &Quadratic) -> bool {
        x.a.is_zero() && x.b.is_zero()
    }
    fn add(&self, x: &Quadratic, y: &Quadratic) -> Quadratic {
        Quadratic {
            a: lehmer::add(&x.a, &y.a),
            b: lehmer::add(&x.b, &y.b),
        }
    }
    fn sub(&self, x: &Quadratic, y: &Quadratic) -> Quadratic {
        Quadratic {
            a: lehmer::sub(&x.a, &y.a),
            b: lehmer::sub(&x.b, &y.b),
        }
    }
    fn mul(&self, x: &Quadratic, y: &Quadratic) -> Quadratic {
        if x.b.is_zero() && y.b.is_zero() {
            return Quadratic {
                a: lehmer::mul(&x.a, &y.a),
                b: Rational::zero(),
            };
        }
        Quadratic {
            a: lehmer::add(
                &lehmer::mul(&x.a, &y.a),
                &self.times_d(&lehmer::mul(&x.b, &y.b)),
            ),
            b: lehmer::add(&lehmer::mul(&x.a, &y.b), &lehmer::mul(&x.b, &y.a)),
        }
    }
    fn mul_add_assign(&self, acc: &mut Quadratic, x: &Quadratic, y: &Quadratic) {
        if !self.is_zero(x) && !self.is_zero(y) {
            *acc = self.add(acc, &self.mul(x, y));
        }
    }
    fn mul_sub_assign(&self, acc: &mut Quadratic, x: &Quadratic, y: &Quadratic) {
        if !self.is_zero(x) && !self.is_zero(y) {
            *acc = self.sub(acc, &self.mul(x, y));
        }
    }
    fn neg(&self, x: &Quadratic) -> Quadratic {
        Quadratic { a: -&x.a, b: -&x.b }
    }
    fn inv(&self, x: &Quadratic) -> Option<Quadratic> {
        if self.is_zero(x) {
            return None;
        }
        let ni = self.norm(x).recip();
        Some(Quadratic {
            a: lehmer::mul(&x.a, &ni),
            b: -lehmer::mul(&x.b, &ni),
        })
    }
    fn from_rational(&self, q: &Rational) -> Quadratic {
        Quadratic {
            a: q.clone(),
            b: Rational::zero(),
        }
    }
    fn to_rational(&self, x: &Quadratic) -> Option<Rational> {
        if x.b.is_zero() {
            Some(x.a.clone())
        } else {
            None
        }
    }
    fn elem_value(&self, x: &Quadratic) -> Option<super::ElemValue> {
        Some(super::ElemValue::Quadratic {
            a: x.a.clone(),
            b: x.b.clone(),
            d: self.d.clone(),
        })
    }
    fn approx(&self, x: &Quadratic) -> Option<(f64, f64)> {
        Some(QuadraticField::approx(self, x))
    }
    fn conj(&self, x: &Quadratic) -> Option<Quadratic> {
        if self.d.is_positive() {
            Some(x.clone())
        } else {
            Some(self.galois(x))
        }
    }
    fn kernels(&self) -> Kernels<'_, QuadraticField> {
        Kernels::Quadratic(QuadraticElems::IDENTITY, &self.d)
    }
    fn sign(&self, x: &Quadratic) -> Option<Ordering> {
        if !self.d.is_positive() {
            return if x.b.is_zero() {
                Some(x.a.cmp(&Rational::zero()))
            } else {
                None
            };
        }
        let sa = x.a.cmp(&Rational::zero());
        let sb = x.b.cmp(&Rational::zero());
        if sb == Ordering::Equal {
            return Some(sa);
        }
        if sa == Ordering::Equal || sa == sb {
            return Some(sb);
        }
        // opposite signs: compare a^2 with d b^2
        let a2 = &x.a * &x.a;
        let db2 = Rational::from_integer(self.d.clone()) * &x.b * &x.b;
        Some(match a2.cmp(&db2) {
            Ordering::Greater => sa,
            Ordering::Less => sb,
            Ordering::Equal => Ordering::Equal,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::ElemDisplay;
    fn r(n: i64, d: i64) -> Rational {
        Rational::new(n.into(), d.into())
    }
    #[test]
    fn display_and_arith() {
        let k = QuadraticField::new(2).unwrap();
        let x = Quadratic::new(r(1, 1), r(-1, 2));
        assert_eq!(k.fmt_elem(&x), "1 - sqrt(2)/2");
        let y = k.inv(&x).unwrap();
        assert!(k.is_one(&k.mul(&x, &y)));
        assert_eq!(k.sign(&x), Some(Ordering::Greater));
        assert_eq!(
            k.sign(&Quadratic::new(r(1, 1), r(-1, 1))),
            Some(Ordering::Less)
        );
        let g = QuadraticField::gaussian();
        assert_eq!(g.fmt_elem(&Quadratic::new(r(-1, 1), r(1, 1))), "-1 + i");
        assert_eq!(g.fmt_elem(&Quadratic::new(r(0, 1), r(1, 2))), "i/2");
        assert!(QuadraticField::new(8).is_err());
        // square factors of primes up to 10^6 are found, also beside a large cofactor
        let b = |x: i64| BigInt::from(x);
        assert_eq!(
            squarefree_split(&(b(999_983) * b(999_983) * 3)),
            (b(999_983), b(3))
        );
        let big = b(65_537) * b(65_537) * b(-5) * b(1_000_000_007);
        assert_eq!(squarefree_split(&big), (b(65_537), b(-5_000_000_035)));
        assert_eq!(squarefree_split(&b(-20)), (b(2), b(-5)));
        assert_eq!(squarefree_split(&b(49)), (b(7), b(1)));
        assert_eq!(squarefree_split(&b(1)), (b(1), b(1)));
        assert!(QuadraticField::new(1).is_err());
        let (f, a, b) = QuadraticField::sqrt_of_rational(&r(8, 3));
        assert_eq!(f.unwrap().d(), &BigInt::from(6));
        assert!(a.is_zero());
        assert_eq!(b, r(2, 3));
        let (f, a, _) = QuadraticField::sqrt_of_rational(&r(9, 4));
        assert!(f.is_none());
        assert_eq!(a, r(3, 2));
    }
}
