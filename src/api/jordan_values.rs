//! The `jordan` command's choices as values, for bindings (the Python package) and for the
//! command line itself (one code path): which matrix is decomposed ($A$, or for a
//! descriptor system the finite part of its pencil $sE - A$, the pencil checked regular:
//! [`finite_part`]) and over which field ([`on_eigen_field`]: a matrix over
//! $\mathbb{Q}(\sqrt d)$ whose entries are all rational is decomposed over $\mathbb{Q}$; over
//! $\mathbb{Q}(p)$ the visitor's [`EigenVisitor::visit_qp`]).
//!
//! Identity: the finite part's $A_f$ has order $\deg\det(sE - A)$ (the pencil's finite
//! order), and its eigenvalues are the finite eigenvalues of the pencil; `verified` says the
//! Kronecker structure was verified and the orders agree.

use super::Failure;
use super::common::with_path;
use crate::field::Field;
use crate::jordan::JordanField;
use crate::matrix::Matrix;
use crate::system::Descriptor;
use std::path::Path;

/// The finite part of a regular pencil: the matrix `jordan` decomposes for a descriptor
/// system, with the sizes of the Jordan blocks at infinity.
#[derive(Clone, Debug)]
pub struct FinitePart<K: Field> {
    /// $A_f$ of the finite dynamics ([`crate::realization::finite_dynamics`]).
    pub a: Matrix<K>,
    /// Sizes of the Jordan blocks at $s = \infty$ (size 1: a non-dynamic mode).
    pub infinite_blocks: Vec<usize>,
    /// The Kronecker structure was verified and $A_f$ has the pencil's finite order.
    pub verified: bool,
    /// The sentence the report shows about it.
    pub note: String,
}

/// The finite part of the pencil of `d` (`path` names the system in messages).
///
/// # Errors
/// A singular pencil has no Jordan structure (an input failure naming its normal rank);
/// those of the Kronecker structure and of the finite dynamics.
pub fn finite_part<K: Field + 'static>(
    d: &Descriptor<K>,
    path: &Path,
) -> Result<FinitePart<K>, Failure> {
    let e = |err| with_path(path, err);
    let ks = crate::pencil::kronecker_structure(&d.a, &d.e).map_err(e)?;
    if !ks.is_regular() {
        return Err(Failure::input(format!(
            "{}: the pencil sE - A is singular (det(sE - A) = 0 for every s, normal rank {} < {}): it has no Jordan structure; `exactlti pencil` gives its Kronecker structure",
            path.display(),
            ks.normal_rank,
            ks.shape.0
        )));
    }
    let (af, method) = crate::realization::finite_dynamics(d).map_err(e)?;
    let note = format!(
        "descriptor system: J is the Jordan form of the finite part of the pencil sE - A ({} finite eigenvalues), computed on the finite part's A ({}); A T = T J holds for that A. infinite_blocks: sizes of the Jordan blocks at s = infinity ({} states; size 1 = non-dynamic mode)",
        af.nrows(),
        method.name(),
        ks.infinite_order()
    );
    Ok(FinitePart {
        verified: ks.verified && af.nrows() == ks.finite_order(),
        infinite_blocks: ks.infinite_divisors.clone(),
        a: af,
        note,
    })
}

pub use crate::jordan::EigenVisitor;

/// Runs `v` on `a` over the field its eigenvalues are computed in
/// ([`JordanField::on_eigen_field`]): $\mathbb{Q}$, or $\mathbb{Q}(\sqrt d)$ ($\mathbb{Q}(i)$)
/// unless every entry is rational (then over $\mathbb{Q}$), or $\mathbb{Q}(p)$
/// ([`EigenVisitor::visit_qp`]: eigenvalues in the field or roots of irreducible factors).
pub fn on_eigen_field<K: JordanField, V: EigenVisitor>(a: &Matrix<K>, v: V) -> V::Output {
    K::on_eigen_field(a, v)
}
