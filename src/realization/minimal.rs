//! Minimal realizations: the result type and its exact verification (the algorithms are in
//! `kalman`/`method`, `rosenbrock`, `ho_kalman`, `jordan_method`). The result imports the
//! Jordan method's result types ([`super::jordan_result`]) only, never an algorithm's file, so
//! every method can build it without an import cycle.

use super::controllability::{is_controllable, is_observable};
use super::kalman::kalman_decomposition;
use crate::error::Result;
use crate::field::Field;
use crate::matrix::Matrix;
use crate::system::StateSpace;

/// Which algorithm computes the minimal realization.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub enum MinrealMethod {
    /// The controllable-observable block of the Kalman decomposition.
    #[default]
    Kalman,
    /// Rosenbrock's staircase of row operations, then its dual (paper sec. 2.3).
    Rosenbrock,
    /// Rank factorization of the block Hankel matrix (exact ERA).
    HoKalman,
    /// Jordan-form method of paper sec. 3.3.
    Jordan,
}

impl MinrealMethod {
    pub fn name(&self) -> &'static str {
        match self {
            MinrealMethod::Kalman => "kalman",
            MinrealMethod::Rosenbrock => "rosenbrock",
            MinrealMethod::HoKalman => "ho-kalman",
            MinrealMethod::Jordan => "jordan",
        }
    }
}

/// A minimal realization with its exact check.
#[derive(Clone, Debug)]
pub struct MinimalRealization<K: Field> {
    pub system: StateSpace<K>,
    /// Order of the minimal realization (= McMillan degree when verified).
    pub order: usize,
    /// Order of the original system.
    pub original_order: usize,
    pub method: MinrealMethod,
    /// A transform `x = T z` of the original system whose leading coordinates carry the
    /// minimal part, where the method provides one.
    pub t: Option<Matrix<K>>,
    /// Controllable, observable, and Markov parameters $C A^k B$ ($k < 2n$) and $D$ equal
    /// to the original's, all checked exactly.
    pub verified: bool,
    /// The Jordan-form method's full result (modal or primary blocks), for that method.
    pub jordan: Option<super::jordan_result::JordanMethod<K>>,
}

impl<K: Field> MinimalRealization<K> {
    /// Wraps a candidate and verifies it against the original.
    pub fn new(
        original: &StateSpace<K>,
        system: StateSpace<K>,
        method: MinrealMethod,
        t: Option<Matrix<K>>,
    ) -> Self {
        let verified = verify_minimal(original, &system);
        MinimalRealization {
            order: system.nstates(),
            original_order: original.nstates(),
            system,
            method,
            t,
            verified,
            jordan: None,
        }
    }
}

/// Exact check: `min` is controllable and observable and has the Markov parameters of `orig`
/// for indices $k < n + r$ ($n$, $r$ the two orders), and the same `D`. By Cayley–Hamilton on
/// the difference system (order $n + r$) this implies equality for every $k$, in particular
/// up to index $2n$ as the CLI contract states.
pub fn verify_minimal<K: Field>(orig: &StateSpace<K>, min: &StateSpace<K>) -> bool {
    let k = orig.nstates() + min.nstates();
    is_controllable(&min.a, &min.b) && is_observable(&min.a, &min.c) && orig.same_markov(min, k)
}

/// Minimal realization by the Kalman decomposition.
///
/// # Errors
/// Only internal failures.
pub fn minimal_kalman<K: Field>(sys: &StateSpace<K>) -> Result<MinimalRealization<K>> {
    let kd = kalman_decomposition(sys)?;
    let min = kd.minimal_part();
    // reorder T so the minimal part comes first
    let [d0, d1, d2, d3] = kd.dims;
    let mut order: Vec<usize> = (d0..d0 + d1).collect();
    order.extend(0..d0);
    order.extend(d0 + d1..d0 + d1 + d2 + d3);
    let t = kd.t.select_cols(&order);
    Ok(MinimalRealization::new(
        sys,
        min,
        MinrealMethod::Kalman,
        Some(t),
    ))
}
