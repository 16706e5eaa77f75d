//! Checks of a Kronecker structure through block Toeplitz ranks, independent of the
//! staircase that produced it (a cross-check of the index bookkeeping; the proof is the
//! staircase's step certificate, [`super::staircase`]).
//!
//! * Right indices: the polynomial solutions $x(s) = \sum_{j \le k} x_j s^j$ of
//!   $(A - sE)x = 0$ form $\ker M_k$, $M_k$ block bidiagonal ($(k+2)m \times (k+1)n$, $A$ on
//!   the diagonal, $-E$ below), and $\dim\ker M_k = \sum_{\varepsilon_i \le k}
//!   (k - \varepsilon_i + 1)$.
//! * Local structure at $\lambda$ (finite, or $\infty$ via $tA - E$ at $t = 0$): with
//!   $T_k(\lambda)$ the $(k+1) \times (k+1)$ block lower-triangular Toeplitz matrix of
//!   $P(\lambda)$ and $P'(\lambda)$, $\dim\ker T_k(\lambda) = (k+1)(n - r) +
//!   \sum_i \min(\kappa_i, k+1)$ over the partial multiplicities $\kappa_i$ at $\lambda$
//!   (local Smith form).
//!
//! Over $\mathbb{Q}$ the ranks of all $T_k$, $k \le k_{\max}$, come from one pass over the
//! block columns modulo a prime ([`toeplitz_ranks_mod_p`]), without assembling $T_k$.
//! Each rank is compared with the one the structure predicts ([`toeplitz_ranks_match`]): over
//! $\mathbb{Q}$ modulo a word prime, which proves $\mathrm{rank} \ge$ the prediction
//! exactly (a rank modulo $p$ is a lower bound, [`crate::qkernels::modular::rank`]) and
//! refutes any structure that predicts a lower rank than the one found modulo $p$; the
//! certified rank decides when two primes fall short. The upper bound
//! $\mathrm{rank} \le$ the prediction is the staircase certificate's (exhibited null
//! spaces), so together the identities are exact.

use crate::field::Field;
use crate::matrix::Matrix;

/// $M_k$ of the right polynomial null space.
fn right_toeplitz<K: Field>(a: &Matrix<K>, e: &Matrix<K>, k: usize) -> Matrix<K> {
    let (m, n) = a.shape();
    let fld = a.field().clone();
    let ne = -e;
    let mut t = Matrix::zeros(fld, (k + 2) * m, (k + 1) * n);
    for j in 0..=k {
        t.set_block(j * m, j * n, a);
        t.set_block((j + 1) * m, j * n, &ne);
    }
    t
}

/// The block Toeplitz matrix $T_k$ with `p0` on the diagonal and `p1` below it.
fn local_toeplitz<K: Field>(p0: &Matrix<K>, p1: &Matrix<K>, k: usize) -> Matrix<K> {
    let (m, n) = p0.shape();
    let mut t = Matrix::zeros(p0.field().clone(), (k + 1) * m, (k + 1) * n);
    for j in 0..=k {
        t.set_block(j * m, j * n, p0);
        if j < k {
            t.set_block((j + 1) * m, j * n, p1);
        }
    }
    t
}

/// Ranks modulo `pr` of the block Toeplitz matrices $T_k$ (`p0` on the diagonal, `p1`
/// below; with `tail` one more block row holding `p1` under the last block column, the
/// $M_k$ of the right indices) for $k = 0..=$`kmax`, in one pass over the block columns.
/// Eliminating block column $c$ touches only the rows left over from block row $c$ (zero
/// before column $c$) and block row $c + 1$; what is left over afterwards lives in block
/// column $c + 1$ alone and is replaced by an echelon basis of its row space (a row
/// operation). $T_k$ shares its first $k$ block-column steps with $T_{k+1}$, so
/// $\mathrm{rank}\,T_k = (\text{pivots before column } k) + \mathrm{rank}$(the leftover,
/// with `p1` below it when `tail`); `r0`, `r1` are the images of `p0`, `p1` modulo `pr`
/// ([`Matrix::image_mod_p`]).
fn toeplitz_ranks_mod_p(
    pr: &crate::qkernels::prime::Prime,
    r0: &[u64],
    r1: &[u64],
    (m, n): (usize, usize),
    kmax: usize,
    tail: bool,
) -> Vec<usize> {
    use crate::qkernels::modular::rank::{eliminate_mod_p, rank_mod_p};
    if n == 0 {
        return vec![0; kmax + 1];
    }
    let mut ranks = Vec::with_capacity(kmax + 1);
    let mut before = 0usize;
    let mut left = r0.to_vec();
    for k in 0..=kmax {
        let mut last = left.clone();
        if tail {
            last.extend_from_slice(r1);
        }
        let rows = last.len() / n;
        ranks.push(before + rank_mod_p(pr, rows, n, &mut last));
        if k == kmax {
            break;
        }
        // [left, 0; p1, p0] over block columns c, c + 1
        let lrows = left.len() / n;
        let rows = lrows + m;
        let mut act = vec![0u64; rows * 2 * n];
        for i in 0..lrows {
            act[i * 2 * n..i * 2 * n + n].copy_from_slice(&left[i * n..(i + 1) * n]);
        }
        for i in 0..m {
            let row = &mut act[(lrows + i) * 2 * n..(lrows + i + 1) * 2 * n];
            row[..n].copy_from_slice(&r1[i * n..(i + 1) * n]);
            row[n..].copy_from_slice(&r0[i * n..(i + 1) * n]);
        }
        let piv = eliminate_mod_p(pr, rows, 2 * n, &mut act, n);
        before += piv;
        let mut rest: Vec<u64> = (piv..rows)
            .flat_map(|i| act[i * 2 * n + n..(i + 1) * 2 * n].iter().copied())
            .collect();
        let rr = rank_mod_p(pr, rows - piv, n, &mut rest);
        rest.truncate(rr * n);
        left = rest;
    }
    ranks
}

/// Compares the predicted ranks `want[k]` of $T_k$ (as [`toeplitz_ranks_mod_p`]) with
/// the ranks modulo up to two primes: equal closes $k$ (a proof of $\mathrm{rank} \ge$
/// the prediction), larger refutes, smaller (a prime dividing the minors) waits for the
/// next prime; the exact rank of the assembled matrix is the last resort.
fn toeplitz_ranks_match<K: Field>(
    p0: &Matrix<K>,
    p1: &Matrix<K>,
    want: &[usize],
    tail: bool,
    assemble: impl Fn(usize) -> Matrix<K>,
) -> bool {
    let kmax = want.len().saturating_sub(1);
    let mut open: Vec<usize> = (0..want.len()).collect();
    for pr in crate::qkernels::prime::primes(11).take(2) {
        let Some((r0, r1)) = p0.image_mod_p(&pr).zip(p1.image_mod_p(&pr)) else {
            continue;
        };
        let got = toeplitz_ranks_mod_p(&pr, &r0, &r1, p0.shape(), kmax, tail);
        if open.iter().any(|&k| got[k] > want[k]) {
            return false;
        }
        open.retain(|&k| got[k] < want[k]);
        if open.is_empty() {
            return true;
        }
    }
    open.into_iter().all(|k| assemble(k).rank() == want[k])
}

/// Checks the right indices `eps` against $\dim\ker M_k$, $k = 0..=\max\varepsilon$.
pub(crate) fn check_right<K: Field>(a: &Matrix<K>, e: &Matrix<K>, eps: &[usize]) -> bool {
    let kmax = eps.iter().copied().max().unwrap_or(0);
    let n = a.ncols();
    let mut want = Vec::new();
    for k in 0..=kmax {
        let dim: usize = eps.iter().filter(|&&x| x <= k).map(|&x| k - x + 1).sum();
        if dim > (k + 1) * n {
            return false;
        }
        want.push((k + 1) * n - dim);
    }
    toeplitz_ranks_match(a, &-e, &want, true, |k| right_toeplitz(a, e, k))
}

/// Checks partial multiplicities `blocks` at a point against $\dim\ker T_k$,
/// $k = 0..=\max\kappa$ (`defect` $= n - r$).
pub(crate) fn check_local<K: Field>(
    p0: &Matrix<K>,
    p1: &Matrix<K>,
    defect: usize,
    blocks: &[usize],
) -> bool {
    let kmax = blocks.iter().copied().max().unwrap_or(0);
    let n = p0.ncols();
    let mut want = Vec::new();
    for k in 0..=kmax {
        let dim = (k + 1) * defect + blocks.iter().map(|&b| b.min(k + 1)).sum::<usize>();
        if dim > (k + 1) * n {
            return false;
        }
        want.push((k + 1) * n - dim);
    }
    toeplitz_ranks_match(p0, p1, &want, false, |k| local_toeplitz(p0, p1, k))
}

/// $\mathrm{rank}(A - s_0 E) \ge r$ at some point $s_0$ (tried modulo a prime at
/// $s_0 = 0, 1, -1, 2, \dots$, at most `tries` points, then exactly): then the normal rank
/// is at least $r$.
pub(crate) fn rank_attained<K: Field>(
    a: &Matrix<K>,
    e: &Matrix<K>,
    r: usize,
    tries: usize,
) -> bool {
    let fld = a.field();
    let at = |t: i64| {
        let s0 = if t % 2 == 1 { (t + 1) / 2 } else { -(t / 2) };
        a - &e.scale(&fld.from_i64(s0))
    };
    (0..tries as i64).any(|t| at(t).rank_at_least_mod_p(r))
        || (0..tries as i64).any(|t| at(t).rank() >= r)
}
