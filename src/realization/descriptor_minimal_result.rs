//! The result of [`super::descriptor_minimal`] and its check at infinity: below both
//! [`super::descriptor_minimal`] and [`super::descriptor_minimal_steps`] (which records the
//! result), so that the two files do not use each other.

use crate::field::Field;
use crate::system::Descriptor;

/// A minimal descriptor realization with its exact checks.
#[derive(Clone, Debug)]
pub struct DescriptorMinimal<K: Field> {
    pub system: Descriptor<K>,
    /// Order of the minimal realization ($n_f + n_\infty$).
    pub order: usize,
    /// Finite (McMillan degree of the strictly proper part) and infinite parts of `order`.
    pub finite_order: usize,
    pub infinite_order: usize,
    /// Order of an irreducible realization of the original (non-dynamic modes kept).
    pub irreducible_order: usize,
    pub original_order: usize,
    /// Degree $q$ of the polynomial part (0: proper).
    pub polynomial_degree: usize,
    /// Same transfer matrix, finite and infinite controllability and observability, no
    /// non-dynamic modes: checked exactly.
    pub verified: bool,
}

/// $\mathrm{rank}[E, B] = n$, $\mathrm{rank}[E; C] = n$, $A\ker E \subseteq \mathrm{im}\,E$.
pub fn is_minimal_at_infinity<K: Field>(sys: &Descriptor<K>) -> bool {
    let n = sys.nstates();
    let re = sys.e.rank();
    let akere = &sys.a * &sys.e.nullspace();
    sys.e.hstack(&sys.b).is_ok_and(|x| x.rank() == n)
        && sys.e.vstack(&sys.c).is_ok_and(|x| x.rank() == n)
        && sys.e.hstack(&akere).is_ok_and(|x| x.rank() == re)
}
