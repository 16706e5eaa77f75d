//! Ho–Kalman realization: the exact analogue of ERA (paper eq. 10-15), with a rank
//! factorization over the field in place of the SVD.
//!
//! With $H_0$ the block Hankel matrix of $C A^{i+j} B$ and $H_1$ the shifted one
//! ($C A^{i+j+1} B$), both with $n$ block rows and columns, a rank factorization
//! $H_0 = L R$ ($L$ = pivot columns of $H_0$, $R$ = non-zero rows of its RREF) gives
//! $A = L^{+} H_1 R^{+}$, $B$ = first $m$ columns of $R$, $C$ = first $p$ rows of $L$, where
//! $L^{+}$, $R^{+}$ are exact one-sided inverses ($L^+ L = I$, $R R^+ = I$) built from
//! invertible square submatrices. Since $H_0 = \mathcal O \mathcal C$ with full-rank
//! factors, $L = \mathcal O M$, $R = M^{-1}\mathcal C$ and $A = M^{-1} A_{min} M$.

use super::controllability::hankel_matrix;
use super::minimal::{MinimalRealization, MinrealMethod};
use crate::error::Result;
use crate::field::Field;
use crate::matrix::Matrix;
use crate::system::StateSpace;

/// A left inverse of a full-column-rank `l`: rows of `l` at the pivots of `l^T` form an
/// invertible square block; its inverse placed at those columns.
fn left_inverse<K: Field>(l: &Matrix<K>) -> Result<Matrix<K>> {
    let (_, rows) = l.transpose().rref();
    let sq = l.select_rows(&rows).inverse()?;
    let mut out = Matrix::zeros(l.field().clone(), l.ncols(), l.nrows());
    for (j, &r) in rows.iter().enumerate() {
        for i in 0..l.ncols() {
            out.set(i, r, sq.get(i, j).clone());
        }
    }
    Ok(out)
}

/// $[I_n \mid -c]$, $c$ the coefficients $c_0..c_{n-1}$ of $\det(tI - A)$: the coordinates of
/// $v, Av, \dots, A^n v$ in the basis $v, \dots, A^{n-1} v$ of a cyclic vector $v$ (by
/// Cayley–Hamilton $A^n v = -\sum_k c_k A^k v$). Shared by Ho–Kalman's single-channel
/// factorization and Rosenbrock's Krylov staircase.
pub(super) fn cayley_hamilton_coords<K: Field>(a: &Matrix<K>) -> Result<Matrix<K>> {
    let (fld, n) = (a.field().clone(), a.nrows());
    let cp = a.charpoly()?;
    Ok(Matrix::from_fn(fld.clone(), n, n + 1, |i, j| {
        if j == n {
            fld.neg(&cp.coeff(i))
        } else if i == j {
            fld.one()
        } else {
            fld.zero()
        }
    }))
}

/// The Ho–Kalman realization without one-sided inverses: the extended Hankel matrix
/// $H_e = [H_0, h]$ ($n$ block rows, $n + 1$ block columns, so $H_1 = H_e$ without its first
/// block column) has the rank and pivots of $H_0$, and $H_e = L R_e$ with $R_e$ the nonzero
/// rows of its RREF. Then $L^+ H_1 R^+ = R_e[:, m + P]$ ($P$ the pivots, $R^+$ the unit
/// columns at $P$): $A$ is read off the RREF, $B = R_e[:, 0..m]$, $C = H_0[0..p, P]$ — the
/// matrices of the factorization in the module docs, exactly. With one input and one output
/// at full rank $n$ (controllable and observable) the last column is $-c$ ($c$ the coefficients of $\det(sI - A)$: the
/// Markov parameters obey that recurrence) and no RREF is needed. Over $\mathbb{Q}(p)$ this
/// avoids the inverse of $H_0 = \mathcal O \mathcal C$, whose entries have the squared
/// Vandermonde determinant as denominators for `diag(p0..p9)`.
fn factor_extended<K: Field>(sys: &StateSpace<K>) -> Result<StateSpace<K>> {
    let (n, p, m) = (sys.nstates(), sys.noutputs(), sys.ninputs());
    let fld = sys.field().clone();
    let he = hankel_matrix(sys, n, n + 1, 0);
    // one input, one output: H_0 = O C is square, of rank n iff both factors are (their
    // determinants' factors are those of det H_0, and recorded as its conditions)
    let full = p == 1
        && m == 1
        && super::controllability::is_controllable(&sys.a, &sys.b)
        && super::controllability::is_observable(&sys.a, &sys.c);
    let (coords, piv) = if full {
        (cayley_hamilton_coords(&sys.a)?, (0..n).collect::<Vec<_>>())
    } else {
        let (r, piv) = he.rref();
        (r.submatrix(0, piv.len(), 0, he.ncols()), piv)
    };
    let r = piv.len();
    let a = Matrix::from_fn(fld.clone(), r, r, |i, j| coords.get(i, piv[j] + m).clone());
    let b = coords.submatrix(0, r, 0, m);
    let c = he.select_cols(&piv).submatrix(0, p, 0, r);
    StateSpace::new(a, b, c, sys.d.clone())
}

/// Minimal realization from the Markov parameters by Ho–Kalman (the dispatcher
/// [`super::minimal`] passes no recorder). With `rec`, the Hankel matrix, its factorization and
/// the minimal part are recorded (`minreal --method ho-kalman --steps`, see [`super::steps`]).
///
/// # Errors
/// Only internal failures.
pub fn minimal_ho_kalman_recorded<K: Field>(
    sys: &StateSpace<K>,
    rec: Option<&mut crate::jordan::derivation::Recorder<'_, K>>,
) -> Result<MinimalRealization<K>> {
    let n = sys.nstates();
    let (p, m) = (sys.noutputs(), sys.ninputs());
    let fld = sys.field().clone();
    if n == 0 || p == 0 || m == 0 {
        let min = StateSpace::new(
            Matrix::zeros(fld.clone(), 0, 0),
            Matrix::zeros(fld.clone(), 0, m),
            Matrix::zeros(fld, p, 0),
            sys.d.clone(),
        )?;
        if let Some(r) = rec {
            super::steps_record::minimal_part(r, sys, &min);
        }
        return Ok(MinimalRealization::new(
            sys,
            min,
            MinrealMethod::HoKalman,
            None,
        ));
    }
    let Some(rc) = rec else {
        let min = factor_extended(sys)?;
        return Ok(MinimalRealization::new(
            sys,
            min,
            MinrealMethod::HoKalman,
            None,
        ));
    };
    let h0 = hankel_matrix(sys, n, n, 0);
    let h1 = hankel_matrix(sys, n, n, 1);
    let (rref, piv) = h0.rref();
    let r = piv.len();
    super::steps_record::hankel(rc, &h0, r);
    let l = h0.select_cols(&piv);
    let rr = rref.submatrix(0, r, 0, h0.ncols());
    let linv = left_inverse(&l)?;
    let rinv = left_inverse(&rr.transpose())?.transpose();
    let a = &(&linv * &h1) * &rinv;
    let b = rr.submatrix(0, r, 0, m);
    let c = l.submatrix(0, p, 0, r);
    let min = StateSpace::new(a, b, c, sys.d.clone())?;
    super::steps_record::hankel_factor(rc, [&h0, &h1], [&l, &rr], [&linv, &rinv], &min);
    super::steps_record::minimal_part(rc, sys, &min);
    Ok(MinimalRealization::new(
        sys,
        min,
        MinrealMethod::HoKalman,
        None,
    ))
}
