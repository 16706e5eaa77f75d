//! The exact DC gain $G(0) = D - C A^{-1} B$ (python-control's `dcgain`), entry by entry.
//!
//! When $A$ is invertible, $G(0) = D - C X$ with $A X = B$; each entry is also read from the
//! exact transfer matrix in lowest terms, $g_{ij}(0) = n_{ij}(0) / d_{ij}(0)$, and the two
//! must agree (`verified`). When $A$ is singular, an entry whose reduced denominator vanishes
//! at $s = 0$ has a pole there and its DC gain is infinite (`None`); the other entries are
//! finite (a pole at 0 that cancels in that channel does not make it infinite, where
//! python-control's state-space evaluation gives `inf` or `nan`).

use super::StateSpace;
use crate::error::Result;
use crate::field::Field;
use crate::matrix::Matrix;

/// The DC gain of every channel: `Some(g)` finite, `None` a pole at $s = 0$.
#[derive(Clone, Debug, PartialEq)]
pub struct DcGain<K: Field> {
    pub entries: Vec<Vec<Option<K::Elem>>>,
    /// $D - C A^{-1} B$ when $A$ is invertible.
    pub matrix: Option<Matrix<K>>,
    /// The transfer-matrix entries at 0 equal `matrix` (when there is one), and every
    /// infinite entry has a reduced denominator vanishing at 0.
    pub verified: bool,
}

/// The exact DC gain of `s`.
///
/// # Errors
/// Only internal failures.
pub fn dc_gain<K: Field>(s: &StateSpace<K>) -> Result<DcGain<K>> {
    let k = s.field().clone();
    let g = s.transfer_matrix()?;
    let entries: Vec<Vec<Option<K::Elem>>> = g
        .entries
        .iter()
        .map(|row| {
            row.iter()
                .map(|f| k.div(&f.num.coeff(0), &f.den.coeff(0)))
                .collect()
        })
        .collect();
    let matrix = match s.a.inverse() {
        Ok(ai) => Some(&s.d - &(&(&s.c * &ai) * &s.b)),
        Err(crate::error::Error::Singular) => None,
        Err(e) => return Err(e),
    };
    let verified = match &matrix {
        Some(m) => entries.iter().enumerate().all(|(i, row)| {
            row.iter()
                .enumerate()
                .all(|(j, x)| x.as_ref() == Some(m.get(i, j)))
        }),
        // a singular A: the finite entries come from reduced fractions, nothing to compare
        None => true,
    };
    Ok(DcGain {
        entries,
        matrix,
        verified,
    })
}
