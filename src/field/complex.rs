//! Complex pairs $a + b i$ over a real field $F$ (for complex eigen-data).
//!
//! Requires $-1$ not to be a square in $F$, which holds for every real field (one whose
//! marked embedding is real). $(a + bi)^{-1} = (a - bi)/(a^2 + b^2)$.

use super::{Field, Rational};

/// The field $F(i)$ for a real field $F$.
#[derive(Clone, Debug, PartialEq)]
pub struct ComplexField<F: Field> {
    pub base: F,
}

/// An element $re + im \cdot i$.
#[derive(Clone, Debug, PartialEq)]
pub struct ComplexPair<E> {
    pub re: E,
    pub im: E,
}

impl<F: Field> ComplexField<F> {
    pub fn new(base: F) -> Self {
        ComplexField { base }
    }
    pub fn i(&self) -> ComplexPair<F::Elem> {
        ComplexPair {
            re: self.base.zero(),
            im: self.base.one(),
        }
    }
    pub fn from_base(&self, a: &F::Elem) -> ComplexPair<F::Elem> {
        ComplexPair {
            re: a.clone(),
            im: self.base.zero(),
        }
    }
}

impl<F: Field> Field for ComplexField<F> {
    type Elem = ComplexPair<F::Elem>;
    fn zero(&self) -> Self::Elem {
        ComplexPair {
            re: self.base.zero(),
            im: self.base.zero(),
        }
    }
    fn one(&self) -> Self::Elem {
        ComplexPair {
            re: self.base.one(),
            im: self.base.zero(),
        }
    }
    fn is_zero(&self, a: &Self::Elem) -> bool {
        self.base.is_zero(&a.re) && self.base.is_zero(&a.im)
    }
    fn add(&self, a: &Self::Elem, b: &Self::Elem) -> Self::Elem {
        ComplexPair {
            re: self.base.add(&a.re, &b.re),
            im: self.base.add(&a.im, &b.im),
        }
    }
    fn sub(&self, a: &Self::Elem, b: &Self::Elem) -> Self::Elem {
        ComplexPair {
            re: self.base.sub(&a.re, &b.re),
            im: self.base.sub(&a.im, &b.im),
        }
    }
    fn mul(&self, a: &Self::Elem, b: &Self::Elem) -> Self::Elem {
        let k = &self.base;
        if k.is_zero(&a.im) && k.is_zero(&b.im) {
            return ComplexPair {
                re: k.mul(&a.re, &b.re),
                im: k.zero(),
            };
        }
        ComplexPair {
            re: k.sub(&k.mul(&a.re, &b.re), &k.mul(&a.im, &b.im)),
            im: k.add(&k.mul(&a.re, &b.im), &k.mul(&a.im, &b.re)),
        }
    }
    fn neg(&self, a: &Self::Elem) -> Self::Elem {
        ComplexPair {
            re: self.base.neg(&a.re),
            im: self.base.neg(&a.im),
        }
    }
    fn inv(&self, a: &Self::Elem) -> Option<Self::Elem> {
        let k = &self.base;
        let n = k.add(&k.mul(&a.re, &a.re), &k.mul(&a.im, &a.im));
        let ni = k.inv(&n)?;
        Some(ComplexPair {
            re: k.mul(&a.re, &ni),
            im: k.neg(&k.mul(&a.im, &ni)),
        })
    }
    fn from_rational(&self, q: &Rational) -> Self::Elem {
        ComplexPair {
            re: self.base.from_rational(q),
            im: self.base.zero(),
        }
    }
    fn to_rational(&self, a: &Self::Elem) -> Option<Rational> {
        if self.base.is_zero(&a.im) {
            self.base.to_rational(&a.re)
        } else {
            None
        }
    }
    fn elem_value(&self, a: &Self::Elem) -> Option<super::ElemValue> {
        Some(super::ElemValue::Complex {
            re: Box::new(self.base.elem_value(&a.re)?),
            im: Box::new(self.base.elem_value(&a.im)?),
        })
    }
    fn approx(&self, a: &Self::Elem) -> Option<(f64, f64)> {
        let (r, _) = self.base.approx(&a.re)?;
        let (i, _) = self.base.approx(&a.im)?;
        Some((r, i))
    }
    fn conj(&self, a: &Self::Elem) -> Option<Self::Elem> {
        Some(ComplexPair {
            re: a.re.clone(),
            im: self.base.neg(&a.im),
        })
    }
}
