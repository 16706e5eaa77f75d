//! The per-point maps of the $\mathbb{Q}(p)$ kernels, over $\mathbb{Z}/p$: determinant,
//! generic row/column profile, and the normalised solve $X = C_P^{-1} C$ with the leading
//! minors of $C_P$.

use crate::qkernels::prime::Prime;

/// Evaluation of $\mathbb{Z}\lbrack p\rbrack$ polynomials modulo a prime (in [`crate::mpoly::modp`]).
pub use crate::mpoly::modp::{ReducedPoly, eval_mod_p, powers};

/// $\det A$ of the `n x n` row-major `a` (destroyed): the kernel of the multi-modular
/// determinant over $\mathbb{Q}$.
pub use crate::qkernels::modular::det::det_mod_p;

/// Gauss–Jordan with the generic rule of `Matrix::rref` (the first row at or below the
/// current one with a nonzero entry in the column, swapped up): the pivot columns and the
/// original indices of the pivot rows, in pivot order.
pub fn profile_mod_p(pr: &Prime, m: usize, n: usize, a: &mut [u64]) -> (Vec<usize>, Vec<usize>) {
    let mut rows: Vec<usize> = (0..m).collect();
    let mut piv = Vec::new();
    let mut r = 0;
    for c in 0..n {
        if r == m {
            break;
        }
        let Some(p) = (r..m).find(|&i| a[i * n + c] != 0) else {
            continue;
        };
        if p != r {
            for j in 0..n {
                a.swap(p * n + j, r * n + j);
            }
            rows.swap(p, r);
        }
        let inv = pr.inv(a[r * n + c]).expect("nonzero pivot");
        for i in r + 1..m {
            let f = a[i * n + c];
            if f == 0 {
                continue;
            }
            let f = pr.mul(f, inv);
            for j in c..n {
                let t = pr.mul(f, a[r * n + j]);
                a[i * n + j] = pr.sub(a[i * n + j], t);
            }
        }
        piv.push(c);
        r += 1;
    }
    rows.truncate(r);
    (piv, rows)
}

/// For the `r x n` row-major `c` (destroyed) and pivot columns `piv` (`r` of them): the
/// leading minors $M_1, \dots, M_r$ of $C_P$ (no row exchanges) followed by the entries of
/// $\Delta X_{:,F}$, $X = C_P^{-1} C$, $\Delta = M_r$, row by row over the non-pivot columns
/// `free`. `None` when a leading minor vanishes at this point.
pub fn minors_and_solve_mod_p(
    pr: &Prime,
    n: usize,
    c: &mut [u64],
    piv: &[usize],
    free: &[usize],
) -> Option<Vec<u64>> {
    let r = piv.len();
    let mut out = Vec::with_capacity(r + r * free.len());
    let mut m = 1u64;
    for (k, &pc) in piv.iter().enumerate() {
        let pv = c[k * n + pc];
        if pv == 0 {
            return None;
        }
        m = pr.mul(m, pv);
        out.push(m);
        let inv = pr.inv(pv).expect("nonzero");
        for j in 0..n {
            c[k * n + j] = pr.mul(c[k * n + j], inv);
        }
        for i in 0..r {
            if i == k {
                continue;
            }
            let f = c[i * n + pc];
            if f == 0 {
                continue;
            }
            for j in 0..n {
                let t = pr.mul(f, c[k * n + j]);
                c[i * n + j] = pr.sub(c[i * n + j], t);
            }
        }
    }
    for k in 0..r {
        for &f in free {
            out.push(pr.mul(m, c[k * n + f]));
        }
    }
    Some(out)
}
