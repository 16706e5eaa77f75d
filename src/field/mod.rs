//! Exact fields as runtime *domain values* (STYLE.md 7.3).
//!
//! A field is a cheap-to-clone value `K: Field` (zero-sized for [`Q`], a shared context for
//! a number field) whose methods do the arithmetic on `K::Elem`. Elements are canonical, so
//! `==` on elements is mathematical equality. [`crate::poly::Poly`] and
//! [`crate::matrix::Matrix`] store one `K`.
//!
//! | field | type | elements |
//! |---|---|---|
//! | $\mathbb{Q}$ | [`Q`] | [`Rational`] |
//! | $\mathbb{Q}(\sqrt d)$ | [`QuadraticField`] | [`Quadratic`] $= a + b\sqrt d$ |
//! | $\mathbb{Q}\[t\]/(m)$ | `crate::algebraic::NumberField` (above `poly`: it needs $\mathbb{Q}\[x\]$ and irreducibility) | `NfElem`: polynomials of degree $< \deg m$ |
//! | $F(i)$ over a real $F$ | [`ComplexField`] | pairs $a + b i$ |
//!
//! Why hand-written: no maintained pure-Rust crate offers exact number fields with runtime
//! moduli, embeddings and the ordering that control-theory algorithms need.

use std::fmt;

pub(crate) mod complex;
pub(crate) mod kernels;
pub use kernels::{KernelTable, Kernels};
pub mod lehmer;
pub(crate) mod quadratic;
pub use complex::{ComplexField, ComplexPair};
pub mod expr;
pub(crate) mod rational;
mod rational_mulmod;
pub mod value;
pub use value::{ElemValue, Generator};

/// $x^e$ by repeated squaring from `one` ($x^0 = $ `one`), `mul` the product: at most
/// $2 \log_2 e$ products. Serves scalars, polynomials and matrices alike.
pub fn pow_by_squaring<T: Clone>(x: &T, mut e: u32, one: T, mul: impl Fn(&T, &T) -> T) -> T {
    let mut base = x.clone();
    let mut acc = one;
    while e > 0 {
        if e & 1 == 1 {
            acc = mul(&acc, &base);
        }
        e >>= 1;
        if e > 0 {
            base = mul(&base, &base);
        }
    }
    acc
}
pub use quadratic::{Quadratic, QuadraticElems, QuadraticField, radical_text};
pub use rational::{Q, Rational, parse_rational, rational_to_f64};

/// How the elements of a field are written (text and LaTeX). Every [`Field`] has one; the
/// implementations live in `report::display` with every other string of the math types
/// (values in math, strings in report/), so generic code writes `k.fmt_elem(a)` as before.
pub trait ElemDisplay<E> {
    /// Exact display of an element (e.g. `-3/7`, `1 - sqrt(2)/2`, `2 + i`).
    fn fmt_elem(&self, a: &E) -> String;
    /// LaTeX display of an element.
    fn latex_elem(&self, a: &E) -> String {
        self.fmt_elem(a)
    }
}

/// An exact field, as a domain value.
pub trait Field:
    Clone + PartialEq + fmt::Debug + fmt::Display + Send + Sync + ElemDisplay<<Self as Field>::Elem>
{
    /// Canonical representation: `==` is mathematical equality.
    type Elem: Clone + PartialEq + fmt::Debug + Send + Sync;

    fn zero(&self) -> Self::Elem;
    fn one(&self) -> Self::Elem;
    fn is_zero(&self, a: &Self::Elem) -> bool;
    fn is_one(&self, a: &Self::Elem) -> bool {
        *a == self.one()
    }
    fn add(&self, a: &Self::Elem, b: &Self::Elem) -> Self::Elem;
    fn sub(&self, a: &Self::Elem, b: &Self::Elem) -> Self::Elem;
    fn mul(&self, a: &Self::Elem, b: &Self::Elem) -> Self::Elem;
    fn neg(&self, a: &Self::Elem) -> Self::Elem;
    /// Multiplicative inverse; `None` exactly when `a` is zero.
    fn inv(&self, a: &Self::Elem) -> Option<Self::Elem>;
    /// `a / b`; `None` exactly when `b` is zero.
    fn div(&self, a: &Self::Elem, b: &Self::Elem) -> Option<Self::Elem> {
        self.inv(b).map(|bi| self.mul(a, &bi))
    }
    /// The image of a rational number.
    fn from_rational(&self, q: &Rational) -> Self::Elem;
    fn from_i64(&self, n: i64) -> Self::Elem {
        self.from_rational(&Rational::from_integer(n.into()))
    }
    /// `Some(q)` when `a` lies in the prime field $\mathbb{Q}$.
    fn to_rational(&self, a: &Self::Elem) -> Option<Rational>;
    /// `acc += a * b`; override when the representation has a fused form.
    fn mul_add_assign(&self, acc: &mut Self::Elem, a: &Self::Elem, b: &Self::Elem) {
        *acc = self.add(acc, &self.mul(a, b));
    }
    /// `acc -= a * b`.
    fn mul_sub_assign(&self, acc: &mut Self::Elem, a: &Self::Elem, b: &Self::Elem) {
        *acc = self.sub(acc, &self.mul(a, b));
    }
    /// The element as a structured value ([`value`]: no display text); `None` only for a
    /// field that does not describe its elements (the default describes rational ones).
    fn elem_value(&self, a: &Self::Elem) -> Option<ElemValue> {
        value::rational_or_none(self, a)
    }
    /// Floating-point approximation `(re, im)` under the field's marked embedding; `None`
    /// for a field without one (e.g. a field of rational functions in symbols).
    fn approx(&self, a: &Self::Elem) -> Option<(f64, f64)> {
        let _ = a;
        None
    }
    /// Complex conjugate under the marked embedding, when the field is closed under it.
    fn conj(&self, a: &Self::Elem) -> Option<Self::Elem> {
        let _ = a;
        None
    }
    /// The field's entry in the matrix-kernel table ([`kernels`]): which fast kernels
    /// `Matrix<K>` uses for charpoly, det, RREF/rank, null space, inverse and products.
    /// The one place a field says what it is to the matrix layer.
    fn kernels(&self) -> Kernels<'_, Self>
    where
        Self: Sized,
    {
        Kernels::Generic
    }
    /// `Some` exactly when the elements are [`Rational`]s (read off [`Field::kernels`]):
    /// for the $\mathbb{Q}$-only modular shortcuts outside the matrix kernels.
    fn as_rationals(&self) -> Option<RationalElems<Self::Elem>>
    where
        Self: Sized,
    {
        match self.kernels() {
            Kernels::Rational(w) => Some(w),
            _ => None,
        }
    }
    /// `a * b` reduced modulo the monic `m` (coefficients low degree first, `a`, `b` of
    /// degree below `deg m`, the result without trailing zeros) when the field has a fast
    /// kernel for it ($\mathbb{Q}$ with an integral `m`: in integers, one division at the
    /// end); `None`: the caller's generic product.
    fn mul_mod_poly(
        &self,
        m: &[Self::Elem],
        a: &[Self::Elem],
        b: &[Self::Elem],
    ) -> Option<Vec<Self::Elem>> {
        let _ = (m, a, b);
        None
    }
    /// Is `a` zero-or-positive-real? Meaningful for real fields only (`None` otherwise).
    fn sign(&self, a: &Self::Elem) -> Option<std::cmp::Ordering> {
        let _ = a;
        None
    }
}

/// A type-equality witness `E = T`: views a slice of elements as `T`s and turns `T`s back
/// into elements, without copying. [`RationalElems`] (returned by [`Field::as_rationals`])
/// and [`QuadraticElems`] (in [`Kernels::Quadratic`]) are its two uses.
pub struct Elems<T, E> {
    view: for<'a> fn(&'a [E]) -> &'a [T],
    back: fn(Vec<T>) -> Vec<E>,
}

/// The witness `E = Rational` ([`Field::as_rationals`], [`Kernels::Rational`]).
pub type RationalElems<E> = Elems<Rational, E>;

impl<T, E> Clone for Elems<T, E> {
    fn clone(&self) -> Self {
        *self
    }
}
impl<T, E> Copy for Elems<T, E> {}

fn same_slice<T>(a: &[T]) -> &[T] {
    a
}
fn same_vec<T>(v: Vec<T>) -> Vec<T> {
    v
}

impl<T> Elems<T, T> {
    /// The witness for `T` itself.
    pub const IDENTITY: Self = Elems {
        view: same_slice::<T>,
        back: same_vec::<T>,
    };
}

impl<T, E> Elems<T, E> {
    /// The elements `a`, seen as `T`s.
    pub fn view<'a>(&self, a: &'a [E]) -> &'a [T] {
        (self.view)(a)
    }
    /// `T`s, as elements.
    pub fn back(&self, v: Vec<T>) -> Vec<E> {
        (self.back)(v)
    }
    /// One `T`, as an element.
    pub fn back_one(&self, x: T) -> E {
        self.back(vec![x]).pop().expect("one element in, one out")
    }
}
