//! The Kalman decomposition.
//!
//! With $\mathcal R$ = controllable subspace (column space of $\mathcal C$) and
//! $\mathcal N$ = unobservable subspace (null space of $\mathcal O$), the basis
//! $T = [X_{c\bar o}, X_{co}, X_{\bar c\bar o}, X_{\bar c o}]$ with
//! $X_{c\bar o}$ a basis of $\mathcal R \cap \mathcal N$, $X_{co}$ completing it to $\mathcal R$,
//! $X_{\bar c\bar o}$ completing it to $\mathcal N$, and $X_{\bar c o}$ completing all to
//! $K^n$, gives in coordinates $x = T z$
//! $$T^{-1}AT = \begin{bmatrix} A_{11} & A_{12} & A_{13} & A_{14} \\ 0 & A_{22} & 0 & A_{24}
//! \\ 0 & 0 & A_{33} & A_{34} \\ 0 & 0 & 0 & A_{44}\end{bmatrix},\ T^{-1}B = \begin{bmatrix}
//! B_1 \\ B_2 \\ 0 \\ 0\end{bmatrix},\ CT = [0, C_2, 0, C_4],$$
//! and $(A_{22}, B_2, C_2, D)$ is a minimal realization.

use super::controllability::{controllability_matrix, observability_matrix};
use crate::error::Result;
use crate::field::Field;
use crate::matrix::Matrix;
use crate::system::StateSpace;

/// The four-part Kalman decomposition.
#[derive(Clone, Debug)]
pub struct KalmanDecomposition<K: Field> {
    /// `x = T z`.
    pub t: Matrix<K>,
    /// The transformed system $(T^{-1}AT, T^{-1}B, CT, D)$.
    pub system: StateSpace<K>,
    /// Dimensions of the parts (controllable-unobservable, controllable-observable,
    /// uncontrollable-unobservable, uncontrollable-observable), in the order of `t`.
    pub dims: [usize; 4],
}

impl<K: Field> KalmanDecomposition<K> {
    /// The minimal (controllable and observable) part $(A_{22}, B_2, C_2, D)$.
    pub fn minimal_part(&self) -> StateSpace<K> {
        let s = self.dims[0];
        let idx: Vec<usize> = (s..s + self.dims[1]).collect();
        self.system.select_states(&idx)
    }
}

/// Columns of `cand` that extend the columns of `base` (independent) to a basis of the span
/// of both, chosen greedily in order.
fn extend_with<K: Field>(base: &Matrix<K>, cand: &Matrix<K>) -> Matrix<K> {
    let both = base.hstack(cand).expect("same rows");
    let (_, piv) = both.rref();
    let picked: Vec<usize> = piv
        .into_iter()
        .filter(|&c| c >= base.ncols())
        .map(|c| c - base.ncols())
        .collect();
    cand.select_cols(&picked)
}

/// Computes the Kalman decomposition.
///
/// # Errors
/// Never for a valid system (the basis is invertible by construction; a failure is reported
/// as `Verification`).
pub fn kalman_decomposition<K: Field>(sys: &StateSpace<K>) -> Result<KalmanDecomposition<K>> {
    let n = sys.nstates();
    let r = controllability_matrix(&sys.a, &sys.b).column_space();
    let o = observability_matrix(&sys.a, &sys.c);
    let nn = o.nullspace();
    // R ∩ N = R * null(O R)
    let x1 = if r.ncols() == 0 {
        r.clone()
    } else {
        &r * &(&o * &r).nullspace()
    };
    let x1 = x1.column_space();
    let x2 = extend_with(&x1, &r);
    let x3 = extend_with(&x1, &nn);
    let sofar = x1.hstack(&x2)?.hstack(&x3)?;
    let x4 = sofar.complete_basis();
    let t = sofar.hstack(&x4)?;
    debug_assert_eq!(t.ncols(), n);
    let system = sys.transform(&t)?;
    Ok(KalmanDecomposition {
        t,
        system,
        dims: [x1.ncols(), x2.ncols(), x3.ncols(), x4.ncols()],
    })
}
