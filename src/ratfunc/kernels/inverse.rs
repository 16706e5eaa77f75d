//! The inverse kernel of $\mathbb{Q}(p)$: $A^{-1}$ by evaluation/interpolation of the
//! adjugate, one division per entry at the end.
//!
//! With row $i$ of $A$ cleared ($B = DA$, $D = \operatorname{diag}(d_i)$, $B$ over
//! $\mathbb{Z}\lbrack p\rbrack$),
//! $$A^{-1} = B^{-1} D, \qquad (A^{-1})_{ij} = \frac{\operatorname{adj}(B)_{ij}\, d_j}{\det B}.$$
//! $\det B$ and the $n^2$ entries of $\operatorname{adj} B$ (the $(n-1)$-minors, so the degree
//! and coefficient bounds of $\det B$ by rows and by columns hold for them too,
//! [`Bounds::of_square`]) are interpolated together ([`interpolate_zp`], shifted nodes: at a
//! point where $B$ is singular modulo the prime the map is undefined and the grid is moved);
//! $\operatorname{adj} B = \det B \cdot B^{-1}$ at each point. $\det B = 0$: $A$ is singular.
//! The result is checked exactly, $B \operatorname{adj} B = \det B \cdot I$, before the
//! entries are brought to lowest terms (the only gcds). Recorded: the numerator of
//! $\det A$ (the inverse holds where it is nonzero). A matrix that splits into blocks is
//! inverted block by block; a grid over [`MAX_VALUES`] residues (many parameters) is
//! replaced by fraction-free Gauss–Jordan on $[B \mid I]$ ([`super::fraction_free`]), checked
//! by the same identity.

use super::blocks::{Block, split, sub};
use super::clear_rows;
use super::fraction_free::gauss_jordan_zp;
use super::interp::{Bounds, grid_points, interpolate_zp};
use super::modp::{det_mod_p, eval_mod_p, profile_mod_p};
use crate::field::Field;
use crate::mpoly::MPoly;
use crate::qkernels::modular::inverse::inverse_mod_p;
use crate::ratfunc::{RatFunc, RatFuncField};

/// Largest number of residues (grid points times outputs) one prime may hold (64 MB).
const MAX_VALUES: usize = 1 << 23;

/// $A^{-1}$ of the `n x n` row-major `a`: `Some(Some(inv))`, `Some(None)` when singular,
/// `None` when the generic algorithm should run (see the module docs).
pub fn inverse_qp(k: &RatFuncField, n: usize, a: &[RatFunc]) -> Option<Option<Vec<RatFunc>>> {
    if let Some(blocks) = split(k, n, n, a) {
        return by_blocks(k, n, a, &blocks);
    }
    let nv = k.nvars();
    let (b, ds) = clear_rows(nv, n, n, a);
    let map = |pr: &crate::qkernels::prime::Prime, x: &mut [u64]| {
        let det = det_mod_p(pr, n, &mut x.to_vec());
        if det == 0 || !inverse_mod_p(pr, n, x) {
            return None;
        }
        let mut v = Vec::with_capacity(n * n + 1);
        v.push(det);
        v.extend(x.iter().map(|&y| pr.mul(y, det)));
        Some(v)
    };
    let bounds = Bounds::of_square(nv, n, &b).probe(&b, &map);
    let out = if grid_points(&bounds).saturating_mul(n * n + 1 + b.len()) > MAX_VALUES {
        // the grid is too large: fraction-free Gauss-Jordan on [B | I]
        fraction_free(nv, n, &b)?
    } else {
        match interpolate_zp(nv, &b, &bounds, n * n + 1, true, map) {
            Ok(Some(o)) => o,
            // singular at every shifted grid point tried: decide singularity exactly
            Ok(None) => return super::det_zp(nv, n, &b).ok()?.is_zero().then_some(None),
            Err(_) => fraction_free(nv, n, &b)?,
        }
    };
    let det = &out[0];
    if det.is_zero() {
        return Some(None);
    }
    let adj = &out[1..];
    if !check(n, &b, adj, det) {
        return None;
    }
    // valid where det A = det B / prod d_i is nonzero (the generic elimination records it too)
    let dprod = ds.iter().fold(MPoly::one(nv), |acc, d| acc.mul(d));
    if let Some(q) = k.frac(det.clone(), dprod) {
        k.record_condition(q.num());
    }
    let inv = (0..n * n)
        .map(|t| {
            if adj[t].is_zero() {
                k.zero()
            } else {
                k.frac(adj[t].mul(&ds[t % n]), det.clone())
                    .expect("nonzero")
            }
        })
        .collect();
    Some(Some(inv))
}

/// `[Δ, Δ B^{-1}]` (row-major after `Δ`) with $\Delta = \pm\det B$ by fraction-free
/// Gauss–Jordan on $[B_S \mid I_S]$, the rows $S$ in the pivot order of the rank profile at
/// a random point ([`gauss_jordan_zp`]; the RREF of $[B_S \mid I_S]$ is $[I \mid B^{-1}]$
/// whatever the row order). `None`: $B$ is singular at that point (undecided: the generic
/// algorithm runs) or the elimination gave up. Checked by the caller ([`check`]).
fn fraction_free(nv: usize, n: usize, b: &[MPoly]) -> Option<Vec<MPoly>> {
    let pr = super::profile_prime(0);
    let mut rng = crate::rng::SplitMix64(0x1a7e_b0a5);
    let x: Vec<u64> = (0..nv).map(|_| rng.next_u64() % pr.p).collect();
    let mut at: Vec<u64> = b.iter().map(|f| eval_mod_p(&pr, f, &x)).collect();
    let (piv, rows) = profile_mod_p(&pr, n, n, &mut at);
    if piv.len() < n {
        return None;
    }
    let w = 2 * n;
    let mut c = vec![MPoly::zero(nv); n * w];
    for (k, &i) in rows.iter().enumerate() {
        c[k * w..k * w + n].clone_from_slice(&b[i * n..(i + 1) * n]);
        c[k * w + n + i] = MPoly::one(nv);
    }
    let minors = gauss_jordan_zp(n, w, &mut c, &piv)?;
    let mut out = Vec::with_capacity(n * n + 1);
    out.push(minors.last()?.clone());
    for k in 0..n {
        out.extend(c[k * w + n..(k + 1) * w].iter().cloned());
    }
    Some(out)
}

/// $B \operatorname{adj} B = \det B \cdot I$, exactly.
fn check(n: usize, b: &[MPoly], adj: &[MPoly], det: &MPoly) -> bool {
    let nv = det.nvars();
    for i in 0..n {
        for j in 0..n {
            let mut s = MPoly::zero(nv);
            for t in 0..n {
                let (x, y) = (&b[i * n + t], &adj[t * n + j]);
                if !x.is_zero() && !y.is_zero() {
                    s = s.add(&x.mul(y));
                }
            }
            let want = if i == j { det.clone() } else { MPoly::zero(nv) };
            if s != want {
                return false;
            }
        }
    }
    true
}

/// Block by block: a square block diagonal matrix (up to permutation) is invertible exactly
/// when every block is square and invertible; $(A^{-1})_{c_j, r_i} = (A_c^{-1})_{ji}$.
fn by_blocks(
    k: &RatFuncField,
    n: usize,
    a: &[RatFunc],
    blocks: &[Block],
) -> Option<Option<Vec<RatFunc>>> {
    let covered: usize = blocks.iter().map(|b| b.rows.len()).sum();
    if covered < n || blocks.iter().any(|b| b.rows.len() != b.cols.len()) {
        return Some(None);
    }
    let mut out = vec![k.zero(); n * n];
    for blk in blocks {
        let s = blk.rows.len();
        let part = sub(a, n, blk);
        let inv = if s == 1 {
            Some(vec![k.inv(&part[0])?])
        } else {
            inverse_qp(k, s, &part)?
        };
        let Some(inv) = inv else {
            return Some(None);
        };
        for (ii, &c) in blk.cols.iter().enumerate() {
            for (jj, &r) in blk.rows.iter().enumerate() {
                out[c * n + r] = inv[ii * s + jj].clone();
            }
        }
    }
    Some(Some(out))
}
