//! The fields of system matrices as base fields of the Jordan decomposition
//! ([`JordanField`]): $\mathbb{Q}$, $\mathbb{Q}(\sqrt d)$, $\mathbb{Q}(i)$ (certified
//! eigenvalues, [`super::jordan_over`]) and $\mathbb{Q}(p_1, \dots, p_k)$ (the generic
//! structure with its conditions, [`super::jordan_qp`]).
//!
//! Operations that need the eigenstructure of a matrix (the PBH test, the finite part of a
//! pencil, the Jordan-form realization) are written once over a [`JordanField`]; the field
//! supplies the decomposition, no caller asks which field it has.
//!
//! The result's eigenvalue list ([`JordanForm::eigenvalues`], [`super::eigenvalue`]) is one
//! type for all of them: certified numbers over the number fields, elements of
//! $\mathbb{Q}(p)$ or the irreducible factor whose roots they are over $\mathbb{Q}(p)$.

use super::over_qp::charpoly_factors as charpoly_factors_qp;
use super::{EigenField, JordanForm, jordan_over, jordan_qp};
use crate::error::Result;
use crate::field::{Field, Q, QuadraticField};
use crate::matrix::Matrix;
use crate::poly::Poly;
use crate::ratfunc::RatFuncField;

/// Code run on a matrix over the field its eigenvalues are computed in
/// ([`JordanField::on_eigen_field`]): certified algebraic numbers over a number field, or
/// over $\mathbb{Q}(p)$ elements of the field and roots of irreducible factors
/// ([`super::EigenValue::InField`], [`super::EigenValue::RootOf`]).
pub trait EigenVisitor {
    type Output;
    /// Over a field with certified eigenvalues ($\mathbb{Q}$, $\mathbb{Q}(\sqrt d)$,
    /// $\mathbb{Q}(i)$).
    fn visit<F: EigenField>(self, a: &Matrix<F>) -> Self::Output;
    /// Over $\mathbb{Q}(p_1, \dots, p_k)$.
    fn visit_qp(self, a: &Matrix<RatFuncField>) -> Self::Output;
}

/// A base field of the exact Jordan decomposition of a system's matrices.
pub trait JordanField: Field + 'static {
    /// The exact Jordan form of the square matrix `a` (each component verified).
    ///
    /// # Errors
    /// `NotSquare`; those of the factorization and of the chains.
    fn jordan_form(a: &Matrix<Self>) -> Result<JordanForm<Self>>;
    /// The monic irreducible factors of $\chi_A$ over the field with their multiplicities
    /// (over $\mathbb{Q}(p)$ the conditions under which they stay irreducible, coprime and
    /// of their degree are recorded in `a`'s field).
    ///
    /// # Errors
    /// `NotSquare`; those of the factorization.
    fn charpoly_factors(a: &Matrix<Self>) -> Result<Vec<(Poly<Self>, usize)>>;
    /// Runs `v` on `a` over the field its eigenvalues are computed in: $\mathbb{Q}$;
    /// $\mathbb{Q}(\sqrt d)$ ($\mathbb{Q}(i)$) unless every entry is rational (then over
    /// $\mathbb{Q}$); $\mathbb{Q}(p)$ ([`EigenVisitor::visit_qp`]).
    fn on_eigen_field<V: EigenVisitor>(a: &Matrix<Self>, v: V) -> V::Output;
}

/// The factors of $\chi_A$ over a field with certified eigenvalues.
fn eigen_charpoly_factors<F: EigenField>(a: &Matrix<F>) -> Result<Vec<(Poly<F>, usize)>> {
    let (_, factors) = super::eigenvalues_over(a)?;
    Ok(factors.into_iter().map(|(g, e, _, _)| (g, e)).collect())
}

impl JordanField for Q {
    fn jordan_form(a: &Matrix<Q>) -> Result<JordanForm<Q>> {
        jordan_over(a)
    }
    fn charpoly_factors(a: &Matrix<Q>) -> Result<Vec<(Poly<Q>, usize)>> {
        eigen_charpoly_factors(a)
    }
    fn on_eigen_field<V: EigenVisitor>(a: &Matrix<Q>, v: V) -> V::Output {
        v.visit(a)
    }
}

impl JordanField for QuadraticField {
    fn jordan_form(a: &Matrix<QuadraticField>) -> Result<JordanForm<QuadraticField>> {
        jordan_over(a)
    }
    fn charpoly_factors(a: &Matrix<QuadraticField>) -> Result<Vec<(Poly<QuadraticField>, usize)>> {
        eigen_charpoly_factors(a)
    }
    fn on_eigen_field<V: EigenVisitor>(a: &Matrix<QuadraticField>, v: V) -> V::Output {
        match crate::matrix::to_rational_matrix(a) {
            Some(q) => v.visit(&q),
            None => v.visit(a),
        }
    }
}

impl JordanField for RatFuncField {
    fn jordan_form(a: &Matrix<RatFuncField>) -> Result<JordanForm<RatFuncField>> {
        jordan_qp(a)
    }
    fn charpoly_factors(a: &Matrix<RatFuncField>) -> Result<Vec<(Poly<RatFuncField>, usize)>> {
        let cp = charpoly_factors_qp(a)?;
        Ok(cp
            .factors
            .into_iter()
            .map(|f| (f.monic, f.multiplicity))
            .collect())
    }
    fn on_eigen_field<V: EigenVisitor>(a: &Matrix<RatFuncField>, v: V) -> V::Output {
        v.visit_qp(a)
    }
}
