//! `tf`'s check of a transfer matrix against a state-space system, one function for the
//! command over $\mathbb{Q}(p)$ and for Python's `tf()` ([`minimal_of_transfer`]).

use crate::error::Result;
use crate::field::Field;
use crate::realization::{MinimalRealization, minimal_kalman};
use crate::system::StateSpace;
use crate::system::transfer::TransferMatrix;

/// The Kalman minimal realization of `s` (its order is the McMillan degree of `g` when `g`
/// is the transfer matrix of `s`) and whether it is: every entry's expansion at
/// $s = \infty$ equals $D, CB, CAB, \dots$ of `s` ($2n + 1$ terms) and the minimal
/// realization's own checks held.
///
/// # Errors
/// Those of the Kalman decomposition.
pub fn minimal_of_transfer<K: Field>(
    s: &StateSpace<K>,
    g: &TransferMatrix<K>,
) -> Result<(MinimalRealization<K>, bool)> {
    let min = minimal_kalman(s)?;
    let ok = min.verified && g.matches_markov(s);
    Ok((min, ok))
}
