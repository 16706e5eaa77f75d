//! The matrix kernels a field registers: its entry in the method table that
//! [`crate::matrix::Matrix`] consults for every caller (as FLINT's `gr` registers
//! `MAT_CHARPOLY` on a ring and SymPy's `DomainMatrix` picks its method from the domain).
//!
//! [`Field::kernels`] returns one [`Kernels`] value:
//!
//! | variant | field | kernels (dispatched by `matrix::kernels`) |
//! |---|---|---|
//! | [`Kernels::Rational`] | $\mathbb{Q}$ | fraction-free and multi-modular $\mathbb{Q}$ kernels (`matrix::over_q`) |
//! | [`Kernels::Quadratic`] | $\mathbb{Q}(\sqrt d)$ | multi-modular charpoly and det (both embeddings $\sqrt d \mapsto \pm r$ modulo primes), integer products, regular representation (`matrix::over_k`) |
//! | [`Kernels::Table`] | a field with its own table ($\mathbb{Q}(p)$: evaluation/interpolation) | the [`KernelTable`] methods (also the gcd in $K\lbrack s\rbrack$, dispatched by `Poly::gcd`) |
//! | [`Kernels::Generic`] | any other | the generic algorithms of `Matrix<K>` only |
//!
//! The $\mathbb{Q}$ and $\mathbb{Q}(\sqrt d)$ entries are type-equality witnesses (the
//! kernels sit above this floor, in `matrix`); a [`KernelTable`] table is code the field
//! brings along. Every kernel computes the same canonical result as the generic algorithm
//! (RREF, rank, canonical null-space basis, $\det A$, $\det(xI - A)$ low degree first,
//! $A^{-1}$, $AB$); a method returning `None` lets the generic algorithm run.

use super::{Field, QuadraticElems, RationalElems};
use crate::error::Result;
use num_bigint::BigInt;

/// A field's entry in the kernel table (see the module docs).
pub enum Kernels<'a, K: Field> {
    /// Only the generic algorithms.
    Generic,
    /// The elements are [`super::Rational`]s: the $\mathbb{Q}$ kernels.
    Rational(RationalElems<K::Elem>),
    /// The elements are [`super::Quadratic`]s of $\mathbb{Q}(\sqrt d)$ (with $d$).
    Quadratic(QuadraticElems<K::Elem>, &'a BigInt),
    /// The field's own kernels.
    Table(&'a dyn KernelTable<K>),
}

/// Optional fast kernels of a field (matrices, and the gcd of polynomials); every default is `None` (take the generic
/// algorithm). Matrices are row-major slices of the given shape.
pub trait KernelTable<K: Field>: Sync {
    /// $\det(xI - A)$, low degree first, monic, length `n + 1`.
    fn charpoly(&self, k: &K, n: usize, a: &[K::Elem]) -> Option<Result<Vec<K::Elem>>> {
        let _ = (k, n, a);
        None
    }
    /// $\det A$.
    fn det(&self, k: &K, n: usize, a: &[K::Elem]) -> Option<Result<K::Elem>> {
        let _ = (k, n, a);
        None
    }
    /// Canonical RREF (`m x n`) and pivot columns.
    fn rref(&self, k: &K, m: usize, n: usize, a: &[K::Elem]) -> Option<(Vec<K::Elem>, Vec<usize>)> {
        let _ = (k, m, n, a);
        None
    }
    /// The pivot columns of the RREF when they are cheap to certify (without the RREF).
    fn pivots(&self, k: &K, m: usize, n: usize, a: &[K::Elem]) -> Option<Vec<usize>> {
        let _ = (k, m, n, a);
        None
    }
    /// $\operatorname{rank} A$.
    fn rank(&self, k: &K, m: usize, n: usize, a: &[K::Elem]) -> Option<usize> {
        let _ = (k, m, n, a);
        None
    }
    /// A proved lower bound of $\operatorname{rank} A$ that records nothing (no conditions):
    /// the rank of an image (at a point, modulo a prime) in which every nonzero minor is the
    /// image of a nonzero minor of $A$. `None`: no cheap bound.
    fn rank_lower_bound(&self, k: &K, m: usize, n: usize, a: &[K::Elem]) -> Option<usize> {
        let _ = (k, m, n, a);
        None
    }
    /// The canonical null-space basis, one vector per non-pivot column of the RREF.
    fn nullspace(&self, k: &K, m: usize, n: usize, a: &[K::Elem]) -> Option<Vec<Vec<K::Elem>>> {
        let _ = (k, m, n, a);
        None
    }
    /// `Some(None)` when $A$ is singular.
    fn inverse(&self, k: &K, n: usize, a: &[K::Elem]) -> Option<Option<Vec<K::Elem>>> {
        let _ = (k, n, a);
        None
    }
    /// The monic gcd of two nonzero polynomials (coefficients low degree first, no trailing
    /// zeros) in $K\lbrack s\rbrack$; dispatched by `Poly::gcd`.
    fn poly_gcd(&self, k: &K, f: &[K::Elem], g: &[K::Elem]) -> Option<Vec<K::Elem>> {
        let _ = (k, f, g);
        None
    }
    /// The product of an `m x l` and an `l x n` matrix.
    fn mul(
        &self,
        k: &K,
        dims: (usize, usize, usize),
        a: &[K::Elem],
        b: &[K::Elem],
    ) -> Option<Vec<K::Elem>> {
        let _ = (k, dims, a, b);
        None
    }
}
