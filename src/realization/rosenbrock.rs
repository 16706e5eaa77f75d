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
//! The reached states after each step are the nested Krylov spaces, so the staircase
//! coordinates are formed from them directly (see [`controllable_staircase`]): one
//! similarity $T^{-1} A T$ instead of one per step, whose entries grew with every step.
//!
//! The minimal realization needs no $T^{-1}$ at all ([`controllable_part`]): in the basis of
//! the reached Krylov columns, $A$ maps column $A^j b_i$ to $A^{j+1} b_i$, whose coordinates
//! are a column of the RREF of the Krylov matrix (extended by one block), and $B$'s columns
//! are the block $j = 0$; so $(A_{22}, B_2, C_2)$ of eq. 17 are read off the RREF, and for
//! one input at full rank off the characteristic polynomial ($A^n b = -\sum_k c_k A^k b$,
//! Cayley–Hamilton). The dual staircase is the same on the dual of that part, and the
//! minimal system is the dual of the dual's controllable part. Over $\mathbb{Q}(p)$ this
//! avoids inverting a Vandermonde-like Krylov matrix (`diag(p0..p9)`: rows with
//! denominators $\prod_{j \ne i} (p_i - p_j)$) and its squared Hankel counterpart.

use super::minimal::MinimalRealization;
use crate::error::Result;
use crate::field::Field;
use crate::matrix::Matrix;
use crate::system::StateSpace;

/// Controllable part by the staircase: returns `(T, k)` with `x = T z` such that the last `k`
/// coordinates of `z` are the controllable ones and $T^{-1}AT$ has the eq. 17 zero pattern.
///
/// The staircase's reached subspaces are the nested Krylov spaces $\mathcal R_j =
/// \mathrm{im}[B, AB, \dots, A^{j-1}B]$: after step $j$ the bottom coordinates span
/// $\mathcal R_j$. So `T` is built from them directly, without accumulating $2k$
/// similarity products (whose entries grow at every step): its last columns are the pivot
/// columns of $[B, AB, \dots]$ (greedy left to right, so those of the first $j$ blocks
/// span $\mathcal R_j$), block $0$ last, and its first columns unit vectors completing
/// them. $A$ maps $\mathcal R_j$ into $\mathcal R_{j+1}$ and $\mathcal R$ into itself,
/// which is the zero pattern of eq. 17 with full-row-rank coupling blocks.
pub fn controllable_staircase<K: Field>(
    a: &Matrix<K>,
    b: &Matrix<K>,
) -> Result<(Matrix<K>, usize)> {
    let fld = a.field().clone();
    let n = a.nrows();
    let m = b.ncols();
    // Krylov blocks until the rank stops growing (then R_j is A-invariant)
    let mut kry = b.clone();
    let mut last = b.clone();
    let mut rank = if m == 0 { 0 } else { kry.rank() };
    while rank > 0 && rank < n {
        last = a * &last;
        let next = kry.hstack(&last)?;
        let r = next.rank();
        if r == rank {
            break;
        }
        kry = next;
        rank = r;
    }
    if rank == 0 {
        return Ok((Matrix::identity(fld, n), 0));
    }
    let (_, piv) = kry.rref();
    // block 0 last: order the pivot columns by descending block index
    let mut cols = piv.clone();
    cols.sort_by_key(|&c| (std::cmp::Reverse(c / m), c));
    let reached = kry.select_cols(&cols);
    // unit vectors e_j for the non-pivot coordinates of reached^T complete the basis
    let (_, rows) = reached.transpose().rref();
    let comp: Vec<usize> = (0..n).filter(|j| !rows.contains(j)).collect();
    let mut t = Matrix::zeros(fld.clone(), n, n);
    for (c, &j) in comp.iter().enumerate() {
        t.set(j, c, fld.one());
    }
    t.set_block(0, comp.len(), &reached);
    Ok((t, rank))
}

/// The reached Krylov columns and the coordinates of every Krylov column in them.
struct Krylov<K: Field> {
    /// $[B, AB, \dots, A^J B]$: the blocks that raised the rank, then one more.
    ext: Matrix<K>,
    /// Pivot columns of `ext` (greedy left to right), ascending; all in the first $J$ blocks.
    piv: Vec<usize>,
    /// `rank x ext.ncols()`: column $j$ of `ext` is $\sum_k$ `coords[k, j]` `ext[:, piv[k]]`.
    coords: Matrix<K>,
}

/// The Krylov matrix $[B, AB, \dots, A^{n-1}B]$, its pivot columns (one pivot computation:
/// the ranks of the growing blocks would each be certified by a minor of their own, which
/// for the dual of a companion form does not factor), the blocks that raised the rank and
/// one more, and the coordinates of all their columns in the pivot columns (`None` when $B$
/// reaches nothing).
fn krylov<K: Field>(a: &Matrix<K>, b: &Matrix<K>) -> Result<Option<Krylov<K>>> {
    let n = a.nrows();
    let m = b.ncols();
    if n == 0 || m == 0 {
        return Ok(None);
    }
    let mut blocks = vec![b.clone()];
    for _ in 0..n {
        let next = a * blocks.last().expect("one block");
        blocks.push(next);
    }
    let hstack = |bs: &[Matrix<K>]| -> Result<Matrix<K>> {
        let mut out = bs[0].clone();
        for x in &bs[1..] {
            out = out.hstack(x)?;
        }
        Ok(out)
    };
    let piv = hstack(&blocks[..n])?.pivots();
    let Some(&lastpiv) = piv.last() else {
        return Ok(None);
    };
    // blocks 0..=J: the J blocks that raised the rank and the one that did not (or A^n B)
    let ext = hstack(&blocks[..lastpiv / m + 2])?;
    let rank = piv.len();
    if m == 1 && rank == n {
        // pivots b, Ab, ..., A^{n-1} b; A^n b = -sum_k c_k A^k b (Cayley-Hamilton)
        return Ok(Some(Krylov {
            ext,
            piv: (0..n).collect(),
            coords: super::ho_kalman::cayley_hamilton_coords(a)?,
        }));
    }
    let (r, piv) = ext.rref();
    let coords = r.submatrix(0, piv.len(), 0, ext.ncols());
    Ok(Some(Krylov { ext, piv, coords }))
}

/// The controllable part $(A_{22}, B_2, C_2, D)$ of eq. 17 and its order: equal to the last
/// `k` states of `sys.transform(T)` for `(T, k)` from [`controllable_staircase`], computed
/// without $T^{-1}$ (see the module docs).
///
/// # Errors
/// Only internal failures.
pub fn controllable_part<K: Field>(sys: &StateSpace<K>) -> Result<(StateSpace<K>, usize)> {
    let Some(kr) = krylov(&sys.a, &sys.b)? else {
        return Ok((sys.select_states(&[]), 0));
    };
    let fld = sys.field().clone();
    let m = sys.ninputs();
    let r = kr.piv.len();
    // the staircase order of the reached columns: block 0 last
    let mut order: Vec<usize> = (0..r).collect();
    order.sort_by_key(|&k| (std::cmp::Reverse(kr.piv[k] / m), kr.piv[k]));
    // coordinates of ext's column j, in the staircase order
    let coord = |row: usize, j: usize| kr.coords.get(order[row], j).clone();
    let a = Matrix::from_fn(fld.clone(), r, r, |i, q| coord(i, kr.piv[order[q]] + m));
    let b = Matrix::from_fn(fld.clone(), r, m, coord);
    let cols: Vec<usize> = order.iter().map(|&k| kr.piv[k]).collect();
    let c = sys.c.try_mul(&kr.ext.select_cols(&cols))?;
    Ok((StateSpace::new(a, b, c, sys.d.clone())?, r))
}

/// Minimal realization by Rosenbrock's method (the dispatcher [`super::minimal`] passes no
/// recorder); with `rec`, both staircases and the minimal part are recorded
/// (`minreal --method rosenbrock --steps`, see [`super::steps`]).
///
/// # Errors
/// Only internal failures (`Singular` from a transform that is invertible by construction).
pub fn minimal_rosenbrock_recorded<K: Field>(
    sys: &StateSpace<K>,
    rec: Option<&mut crate::jordan::derivation::Recorder<'_, K>>,
) -> Result<MinimalRealization<K>> {
    let Some(rec) = rec else {
        // the staircase's controllable part, then that of its dual (eq. 19), dualized back
        let (ctrl, _) = controllable_part(sys)?;
        let (obs, _) = controllable_part(&ctrl.dual())?;
        let min = obs.dual();
        return Ok(MinimalRealization::new(
            sys,
            min,
            super::MinrealMethod::Rosenbrock,
            None,
        ));
    };
    let n = sys.nstates();
    let (t1, kc) = controllable_staircase(&sys.a, &sys.b)?;
    let s1 = sys.transform(&t1)?;
    super::steps_record::staircase(rec, sys, &t1, &s1, kc, false);
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
    super::steps_record::staircase(rec, &dual, &t2, &dual.transform(&t2)?, ko, true);
    super::steps_record::minimal_part(rec, sys, &min);
    Ok(MinimalRealization::new(
        sys,
        min,
        super::MinrealMethod::Rosenbrock,
        None,
    ))
}
