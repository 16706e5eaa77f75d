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
//!
//! When one input makes the system controllable and observable, $T$ is the Krylov basis
//! $[b, Ab, \dots, A^{n-1}b]$ and $(T^{-1}AT, T^{-1}b)$ is read off without $T^{-1}$: the
//! companion matrix of $\det(sI - A) = s^n + \sum_i c_i s^i$ (ones below the diagonal, last
//! column $-c$; $A\,A^{n-1}b = -\sum_i c_i A^i b$ by Cayley–Hamilton) and $e_1$.

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
    let piv = both.pivots();
    let picked: Vec<usize> = piv
        .into_iter()
        .filter(|&c| c >= base.ncols())
        .map(|c| c - base.ncols())
        .collect();
    cand.select_cols(&picked)
}

/// $(T^{-1}AT, T^{-1}b, CT, D)$ for the Krylov basis $T = [b, Ab, \dots, A^{n-1}b]$ (module
/// docs).
fn krylov_companion<K: Field>(sys: &StateSpace<K>, t: &Matrix<K>) -> Result<StateSpace<K>> {
    let k = sys.field().clone();
    let n = sys.nstates();
    let cp = sys.a.charpoly()?;
    let a = Matrix::from_fn(k.clone(), n, n, |i, j| {
        if j + 1 == n {
            k.neg(&cp.coeff(i))
        } else if i == j + 1 {
            k.one()
        } else {
            k.zero()
        }
    });
    let b = Matrix::from_fn(
        k.clone(),
        n,
        1,
        |i, _| if i == 0 { k.one() } else { k.zero() },
    );
    StateSpace::new(a, b, sys.c.try_mul(t)?, sys.d.clone())
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
    let system = if sys.ninputs() == 1 && x2.ncols() == n {
        krylov_companion(sys, &t)?
    } else {
        sys.transform(&t)?
    };
    Ok(KalmanDecomposition {
        t,
        system,
        dims: [x1.ncols(), x2.ncols(), x3.ncols(), x4.ncols()],
    })
}
