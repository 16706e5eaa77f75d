//! Independent exact checks of a Kronecker structure through block Toeplitz ranks.
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
//! Together with $\mathrm{rank}(A - s_0E) = r$ at one point and the dimension count these
//! determine every index without reference to the staircase that produced it.

use crate::field::Field;
use crate::matrix::Matrix;

/// $\dim\ker M_k$ for the right polynomial null space.
pub(crate) fn right_kernel_dim<K: Field>(a: &Matrix<K>, e: &Matrix<K>, k: usize) -> usize {
    let (m, n) = a.shape();
    let fld = a.field().clone();
    let ne = -e;
    let mut t = Matrix::zeros(fld, (k + 2) * m, (k + 1) * n);
    for j in 0..=k {
        t.set_block(j * m, j * n, a);
        t.set_block((j + 1) * m, j * n, &ne);
    }
    (k + 1) * n - t.rank()
}

/// $\dim\ker T_k$ for the block Toeplitz matrix with `p0` on the diagonal and `p1` below it.
pub(crate) fn local_kernel_dim<K: Field>(p0: &Matrix<K>, p1: &Matrix<K>, k: usize) -> usize {
    let (m, n) = p0.shape();
    let mut t = Matrix::zeros(p0.field().clone(), (k + 1) * m, (k + 1) * n);
    for j in 0..=k {
        t.set_block(j * m, j * n, p0);
        if j < k {
            t.set_block((j + 1) * m, j * n, p1);
        }
    }
    (k + 1) * n - t.rank()
}

/// Checks the right indices `eps` against $\dim\ker M_k$, $k = 0..=\max\varepsilon$.
pub(crate) fn check_right<K: Field>(a: &Matrix<K>, e: &Matrix<K>, eps: &[usize]) -> bool {
    let kmax = eps.iter().copied().max().unwrap_or(0);
    (0..=kmax).all(|k| {
        let want: usize = eps.iter().filter(|&&x| x <= k).map(|&x| k - x + 1).sum();
        right_kernel_dim(a, e, k) == want
    })
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
    (0..=kmax).all(|k| {
        let want = (k + 1) * defect + blocks.iter().map(|&b| b.min(k + 1)).sum::<usize>();
        local_kernel_dim(p0, p1, k) == want
    })
}

/// $\mathrm{rank}(A - s_0 E) = r$ for some $s_0$ among $0, 1, -1, 2, \dots$ (at most
/// `tries` points): then the normal rank is at least $r$.
pub(crate) fn rank_attained<K: Field>(
    a: &Matrix<K>,
    e: &Matrix<K>,
    r: usize,
    tries: usize,
) -> bool {
    let fld = a.field();
    (0..tries as i64).any(|t| {
        let s0 = if t % 2 == 1 { (t + 1) / 2 } else { -(t / 2) };
        (a - &e.scale(&fld.from_i64(s0))).rank() == r
    })
}
