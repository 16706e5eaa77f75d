//! Rosenbrock's method (paper sec. 2.3, eq. 16-20), exactly.
//!
//! Elementary row operations on $P = [A\ B; C\ 0]$, applied as similarity transforms, bring
//! it to the staircase form of eq. 17, $\tilde P = [A_{11}\ 0\ 0; A_{21}\ A_{22}\ B_2;
//! C_1\ C_2\ 0]$ in which $(A_{22}, B_2, C_2)$ is the controllable part. The compressions are
//! exact (left null spaces from the canonical RREF) instead of orthogonal. The same staircase
//! on the dual $Q = [A_{22}^T\ C_2^T; B_2^T\ 0]$ (eq. 19) removes the unobservable states.
//!
//! # Algorithm
//! Staircase: compress $B$ to $[0; B_1]$ ($B_1$ of full row rank $\rho_1$); the states above
//! are driven only through the block $A_{12}$ coupling them to the $\rho_1$ reached ones;
//! compress that block in turn, and so on, until the coupling block is zero (the remaining
//! top states are uncontrollable) or no states remain. $O(n^4)$ field operations at worst.

use super::controllability::row_compression;
use super::minimal::MinimalRealization;
use crate::error::Result;
use crate::field::Field;
use crate::matrix::Matrix;
use crate::system::StateSpace;

/// Controllable part by the staircase: returns `(T, k)` with `x = T z` such that the last `k`
/// coordinates of `z` are the controllable ones and $T^{-1}AT$ has the eq. 17 zero pattern.
pub fn controllable_staircase<K: Field>(
    a: &Matrix<K>,
    b: &Matrix<K>,
) -> Result<(Matrix<K>, usize)> {
    let fld = a.field().clone();
    let n = a.nrows();
    let mut tinv = Matrix::identity(fld.clone(), n); // z = Tinv x
    let mut at = a.clone();
    // `top` = number of states not yet reached; the current "input" block acts on them.
    let mut top = n;
    let mut drive = b.clone(); // top x * block
    while top > 0 {
        let (s, r) = row_compression(&drive);
        if r == 0 {
            break;
        }
        // apply S on the first `top` coordinates
        let mut full = Matrix::identity(fld.clone(), n);
        full.set_block(0, 0, &s);
        let sinv = s.inverse()?;
        let mut full_inv = Matrix::identity(fld.clone(), n);
        full_inv.set_block(0, 0, &sinv);
        at = &(&full * &at) * &full_inv;
        tinv = &full * &tinv;
        let newtop = top - r;
        // the block coupling the new top states to the freshly reached ones
        drive = at.submatrix(0, newtop, newtop, top);
        top = newtop;
    }
    let t = tinv.inverse()?;
    Ok((t, n - top))
}

/// Minimal realization by Rosenbrock's method.
///
/// # Errors
/// Only internal failures (`Singular` from a transform that is invertible by construction).
pub fn minimal_rosenbrock<K: Field>(sys: &StateSpace<K>) -> Result<MinimalRealization<K>> {
    let n = sys.nstates();
    let (t1, kc) = controllable_staircase(&sys.a, &sys.b)?;
    let s1 = sys.transform(&t1)?;
    let cidx: Vec<usize> = (n - kc..n).collect();
    let ctrl = s1.select_states(&cidx);
    // observability staircase on the dual of the controllable part
    let dual = ctrl.dual();
    let (t2, ko) = controllable_staircase(&dual.a, &dual.b)?;
    // dual coordinates x_d = T2 w  <=>  for the primal, z = T2^{-T} w'
    let t2p = t2.inverse()?.transpose();
    let s2 = ctrl.transform(&t2p)?;
    let oidx: Vec<usize> = (kc - ko..kc).collect();
    let min = s2.select_states(&oidx);
    Ok(MinimalRealization::new(
        sys,
        min,
        super::MinrealMethod::Rosenbrock,
        None,
    ))
}
