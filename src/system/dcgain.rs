//! The exact DC gain $G(0) = D - C A^{-1} B$ (python-control's `dcgain`), entry by entry.
//!
//! When $A$ is invertible, $G(0) = D - C X$ with $A X = B$; each entry is also read from the
//! exact transfer matrix in lowest terms, $g_{ij}(0) = n_{ij}(0) / d_{ij}(0)$, and the two
//! must agree (`verified`). When $A$ is singular, an entry whose reduced denominator vanishes
//! at $s = 0$ has a pole there and its DC gain is infinite (`None`); the other entries are
//! finite (a pole at 0 that cancels in that channel does not make it infinite, where
//! python-control's state-space evaluation gives `inf` or `nan`).
//!
//! [`gain_at`] is the same at any point $z_0$: $G(z_0) = D + C (z_0 I - A)^{-1} B$; the DC
//! gain of a discrete-time system is $G(1)$.

use super::StateSpace;
use crate::error::Result;
use crate::field::Field;
use crate::matrix::Matrix;

/// The DC gain of every channel: `Some(g)` finite, `None` a pole at $s = 0$.
#[derive(Clone, Debug, PartialEq)]
pub struct DcGain<K: Field> {
    /// The point $z_0$ (0 in continuous time, 1 in discrete time).
    pub point: K::Elem,
    pub entries: Vec<Vec<Option<K::Elem>>>,
    /// $D + C (z_0 I - A)^{-1} B$ ($D - C A^{-1} B$ at 0) when $z_0$ is not an eigenvalue.
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
    gain_at(s, &s.field().zero())
}

/// The exact gain $G(z_0)$ of every channel (`None`: a pole at $z_0$ in that channel).
///
/// # Errors
/// Only internal failures.
pub fn gain_at<K: Field>(s: &StateSpace<K>, z0: &K::Elem) -> Result<DcGain<K>> {
    let k = s.field().clone();
    let g = s.transfer_matrix()?;
    let entries: Vec<Vec<Option<K::Elem>>> = g
        .entries
        .iter()
        .map(|row| {
            row.iter()
                .map(|f| k.div(&f.num.eval(z0), &f.den.eval(z0)))
                .collect()
        })
        .collect();
    let n = s.nstates();
    let shifted = &Matrix::identity(k.clone(), n).scale(z0) - &s.a;
    let matrix = match shifted.inverse() {
        Ok(mi) => Some(&s.d + &(&(&s.c * &mi) * &s.b)),
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
        point: z0.clone(),
        entries,
        matrix,
        verified,
    })
}
