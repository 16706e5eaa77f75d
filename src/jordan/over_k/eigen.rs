//! Eigenvalues of a matrix over $K = \mathbb{Q}(\alpha)$: the factorization of $\chi_A$ over
//! $K$ ([`crate::algebraic::factor_over_quadratic`], Trager's norm method), the minimal
//! polynomial over $\mathbb{Q}$ of the roots of each factor, and the exact choice of the
//! roots that belong to $A$ (not to $\bar A$): [`crate::algebraic::roots_of_quadratic_factor`],
//! whose module docs give the argument.

use crate::algebraic::{AlgebraicNumber, rational_minpoly, roots_of_quadratic_factor};
use crate::error::Result;
use crate::field::{Q, QuadraticField};
use crate::poly::Poly;

pub use crate::algebraic::factor_over_quadratic as factor_over_k;

/// Certified roots with their approximations.
pub type CertifiedRoots = Vec<(AlgebraicNumber, (f64, f64))>;

/// The roots of the monic irreducible `g` over $K$ (under the embedding fixing $\alpha$),
/// as certified algebraic numbers with approximations, real part descending, with the
/// minimal polynomial over $\mathbb{Q}$ they share.
///
/// # Errors
/// `Limit` from root isolation or from the exact choice of the roots of `g`.
pub fn roots_of_factor(g: &Poly<QuadraticField>) -> Result<(Poly<Q>, CertifiedRoots)> {
    let m = rational_minpoly(g);
    let all = super::super::roots::certified_roots(&m)?;
    Ok((m, roots_of_quadratic_factor(g, all)?))
}
