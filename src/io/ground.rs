//! [`GroundField`]: what a ground field of a system file ($\mathbb{Q}$, $\mathbb{Q}(\sqrt d)$,
//! $\mathbb{Q}(i)$, $\mathbb{Q}(p_1, \dots, p_k)$) can do, said by the field's trait impl
//! instead of probing types in the commands.
//!
//! A command is written once over `K: GroundField`. What needs numbers (certified
//! eigenvalues, margins on the imaginary axis, float plots of exact results) asks
//! [`GroundField::numeric`] for the system over a [`NumericField`]: the same system (the identity witness
//! `K = K::Numeric`) over every field with an embedding into $\mathbb{C}$, and over
//! $\mathbb{Q}(p)$ `None`, which the api turns into its one refusal line ("needs numeric
//! entries: give values for m, u (--at)"). An algorithm written over $\mathbb{Q}$ only (the closed-form
//! step plot) asks [`GroundField::rational`].

use super::Ground;
use super::{TypedAny, TypedSystem};
use crate::field::{Field, Q, Quadratic, QuadraticField, Rational};
use crate::jordan::derivation::AssumptionLog;
use crate::jordan::{EigenField, JordanForm};
use crate::matrix::Matrix;
use crate::poly::Poly;
use crate::ratfunc::RatFunc;
use crate::ratfunc::RatFuncField;
use crate::realization::SystemField;
use crate::system::Descriptor;
use crate::system::margins::axis::AxisField;

/// A field whose elements are numbers: certified eigenvalues ([`EigenField`]), polynomials
/// split on the imaginary axis ([`AxisField`]), the Jordan method and the modal table
/// ([`SystemField`]), and a ground field of system files ([`GroundField`]).
pub trait NumericField: GroundField + EigenField + AxisField {}
impl<F: GroundField + EigenField + AxisField> NumericField for F {}

/// Monic irreducible factors with their multiplicities.
pub type Factors<F> = Vec<(Poly<F>, usize)>;

/// A ground field of a system file (see the module docs).
pub trait GroundField: SystemField {
    /// The field itself when it is numeric; over $\mathbb{Q}(p)$ a placeholder never reached.
    type Numeric: NumericField;
    /// The system over its numeric field (`None` over $\mathbb{Q}(p)$).
    fn numeric(t: &TypedSystem<Self>) -> Option<&TypedSystem<Self::Numeric>>;
    /// The descriptor system over its numeric field (`None` over $\mathbb{Q}(p)$).
    fn numeric_descriptor(d: &Descriptor<Self>) -> Option<&Descriptor<Self::Numeric>>;
    /// The matrix over its numeric field (`None` over $\mathbb{Q}(p)$).
    fn numeric_matrix(a: &Matrix<Self>) -> Option<&Matrix<Self::Numeric>>;
    /// The polynomial over its numeric field (`None` over $\mathbb{Q}(p)$).
    fn numeric_poly(p: &Poly<Self>) -> Option<&Poly<Self::Numeric>>;
    /// The Jordan form over its numeric field (`None` over $\mathbb{Q}(p)$).
    fn numeric_jordan(j: &JordanForm<Self>) -> Option<&JordanForm<Self::Numeric>>;
    /// The system over $\mathbb{Q}$ when the field is $\mathbb{Q}$.
    fn rational(t: &TypedSystem<Self>) -> Option<&TypedSystem<Q>>;
    /// The descriptor system over $\mathbb{Q}$ when the field is $\mathbb{Q}$.
    fn rational_descriptor(d: &Descriptor<Self>) -> Option<&Descriptor<Q>>;
    /// The monic irreducible factors of `p` over this field with their multiplicities
    /// ($\mathbb{Q}$: [`crate::algebraic::factor_q`]; $\mathbb{Q}(\sqrt d)$, $\mathbb{Q}(i)$:
    /// [`crate::algebraic::factor_over_quadratic`]; $\mathbb{Q}(p)$:
    /// [`crate::structure::factor_qp::factor_over_qp`]); `None` where the crate does not
    /// factor.
    fn factors(p: &Poly<Self>) -> Option<crate::error::Result<Factors<Self>>> {
        let _ = p;
        None
    }
    /// The field of rational functions when the field is $\mathbb{Q}(p_1, \dots, p_k)$
    /// (its symbols, its condition log).
    fn symbolic(&self) -> Option<&RatFuncField> {
        None
    }
    /// The system as one of the crate's typed systems.
    fn into_any(t: TypedSystem<Self>) -> TypedAny;
    /// An exact element of this field written as text (an entry of `--x0`): a rational
    /// number over $\mathbb{Q}$; an expression with `sqrt(d)` / `i` over $\mathbb{Q}(\sqrt d)$;
    /// a rational function of the symbols over $\mathbb{Q}(p)$.
    ///
    /// # Errors
    /// Why the text is not an element of the field (one line).
    fn parse_elem(&self, text: &str) -> Result<Self::Elem, String>;
    /// A nonzero element on the imaginary axis of the marked embedding ($\sqrt d$ of
    /// $\mathbb{Q}(\sqrt d)$, $d < 0$), from which exact points $s = r\sqrt d$ of the axis are
    /// made; `None` when the field meets the axis only at 0 (a real field) or has no embedding.
    fn imaginary_generator(&self) -> Option<Self::Elem> {
        None
    }
    /// The field with an empty record of what computations assume ($\mathbb{Q}(p)$: a fresh
    /// condition log; a numeric field assumes nothing: itself).
    fn fresh(&self) -> Self {
        self.clone()
    }
    /// What a derivation over this field assumes nonzero, read as it runs (`None`: nothing,
    /// over a numeric field).
    fn assumption_log(&self) -> Option<AssumptionLog<'static, Self>> {
        None
    }
}

impl GroundField for Q {
    type Numeric = Q;
    fn numeric(t: &TypedSystem<Q>) -> Option<&TypedSystem<Q>> {
        Some(t)
    }
    fn numeric_descriptor(d: &Descriptor<Q>) -> Option<&Descriptor<Q>> {
        Some(d)
    }
    fn numeric_matrix(a: &Matrix<Q>) -> Option<&Matrix<Q>> {
        Some(a)
    }
    fn numeric_poly(p: &Poly<Q>) -> Option<&Poly<Q>> {
        Some(p)
    }
    fn numeric_jordan(j: &JordanForm<Q>) -> Option<&JordanForm<Q>> {
        Some(j)
    }
    fn rational(t: &TypedSystem<Q>) -> Option<&TypedSystem<Q>> {
        Some(t)
    }
    fn rational_descriptor(d: &Descriptor<Q>) -> Option<&Descriptor<Q>> {
        Some(d)
    }
    fn factors(p: &Poly<Q>) -> Option<crate::error::Result<Factors<Q>>> {
        Some(crate::algebraic::factor_q(p).map(|f| f.1))
    }
    fn into_any(t: TypedSystem<Q>) -> TypedAny {
        TypedAny::Rational(t)
    }
    fn parse_elem(&self, text: &str) -> Result<Rational, String> {
        crate::field::parse_rational(text)
    }
}

impl GroundField for QuadraticField {
    type Numeric = QuadraticField;
    fn numeric(t: &TypedSystem<Self>) -> Option<&TypedSystem<Self>> {
        Some(t)
    }
    fn numeric_descriptor(d: &Descriptor<Self>) -> Option<&Descriptor<Self>> {
        Some(d)
    }
    fn numeric_matrix(a: &Matrix<Self>) -> Option<&Matrix<Self>> {
        Some(a)
    }
    fn numeric_poly(p: &Poly<Self>) -> Option<&Poly<Self>> {
        Some(p)
    }
    fn numeric_jordan(j: &JordanForm<Self>) -> Option<&JordanForm<Self>> {
        Some(j)
    }
    fn rational(_: &TypedSystem<Self>) -> Option<&TypedSystem<Q>> {
        None
    }
    fn rational_descriptor(_: &Descriptor<Self>) -> Option<&Descriptor<Q>> {
        None
    }
    fn factors(p: &Poly<Self>) -> Option<crate::error::Result<Factors<Self>>> {
        Some(crate::algebraic::factor_over_quadratic(p))
    }
    fn into_any(t: TypedSystem<Self>) -> TypedAny {
        TypedAny::Quadratic(t)
    }
    fn imaginary_generator(&self) -> Option<Quadratic> {
        num_traits::Signed::is_negative(self.d()).then(|| {
            Quadratic::new(
                Rational::from_integer(0.into()),
                Rational::from_integer(1.into()),
            )
        })
    }
    fn parse_elem(&self, text: &str) -> Result<Quadratic, String> {
        let (x, g) = super::eval_expr(text, &[], &Ground::Quadratic(self.clone()))
            .map_err(|e| e.to_string())?;
        match g {
            Ground::Rational => Ok(self.from_rational(&x.a)),
            Ground::Quadratic(k) if k == *self => Ok(x.to_quadratic()),
            other => Err(format!("lies in {other}, not in {self}")),
        }
    }
}

impl GroundField for RatFuncField {
    type Numeric = Q;
    fn numeric(_: &TypedSystem<Self>) -> Option<&TypedSystem<Q>> {
        None
    }
    fn numeric_descriptor(_: &Descriptor<Self>) -> Option<&Descriptor<Q>> {
        None
    }
    fn numeric_matrix(_: &Matrix<Self>) -> Option<&Matrix<Q>> {
        None
    }
    fn numeric_poly(_: &Poly<Self>) -> Option<&Poly<Q>> {
        None
    }
    fn numeric_jordan(_: &JordanForm<Self>) -> Option<&JordanForm<Q>> {
        None
    }
    fn rational(_: &TypedSystem<Self>) -> Option<&TypedSystem<Q>> {
        None
    }
    fn rational_descriptor(_: &Descriptor<Self>) -> Option<&Descriptor<Q>> {
        None
    }
    fn factors(p: &Poly<Self>) -> Option<crate::error::Result<Factors<Self>>> {
        Some(crate::structure::factor_qp::factor_over_qp(p))
    }
    fn symbolic(&self) -> Option<&RatFuncField> {
        Some(self)
    }
    fn fresh(&self) -> Self {
        RatFuncField::fresh(self)
    }
    fn assumption_log(&self) -> Option<AssumptionLog<'static, Self>> {
        Some(crate::jordan::derivation::ratfunc_log(self))
    }
    fn into_any(t: TypedSystem<Self>) -> TypedAny {
        TypedAny::RatFunc(t)
    }
    fn parse_elem(&self, text: &str) -> Result<RatFunc, String> {
        self.parse(text).map_err(|e| e.to_string())
    }
}
