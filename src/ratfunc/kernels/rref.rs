//! The RREF and rank kernels of $\mathbb{Q}(p)$ (see the parent module docs for the method
//! and its exact check).

use super::blocks::{assemble, split, sub};
use super::fraction_free::gauss_jordan_zp;
use super::interp::{Bounds, grid_points, interpolate_zp};
use super::minor_cond::record_minor;
use super::modp::{eval_mod_p, minors_and_solve_mod_p, profile_mod_p};
use super::{clear_rows, profile_prime};
use crate::mpoly::MPoly;
use crate::qkernels::prime::Prime;
use crate::ratfunc::{RatFunc, RatFuncField};
use crate::rng::SplitMix64;

/// Largest number of residues (grid points times outputs and entries) one prime may hold;
/// beyond it the generic algorithm runs (a memory bound: 64 MB).
const MAX_VALUES: usize = 1 << 23;

/// A certified echelon form of the row-cleared matrix $B$ (`m x n`).
struct Echelon {
    /// Pivot columns $P$.
    piv: Vec<usize>,
    /// Original indices of the pivot rows $S$, in pivot order.
    rows: Vec<usize>,
    /// Leading minors $M_1..M_r$ of $B_{S,P}$ (empty when the rank was decided at a point).
    minors: Vec<MPoly>,
    /// $N = \Delta B_{S,P}^{-1} B_{S,F}$, row-major `r x |F|`.
    nmat: Vec<MPoly>,
    /// Non-pivot columns $F$.
    free: Vec<usize>,
    /// Row denominators $d_i$.
    ds: Vec<MPoly>,
}

/// A point of $(\mathbb{Z}/p)^k$ from a fixed stream.
fn point(pr: &Prime, k: usize, seed: u64) -> Vec<u64> {
    let mut rng = SplitMix64(seed);
    (0..k).map(|_| rng.next_u64() % pr.p).collect()
}

/// The exact check of the module docs: echelon shape and $\Delta B_{i,F} = B_{i,P} N$.
fn check(b: &[MPoly], n: usize, e: &Echelon) -> bool {
    let r = e.piv.len();
    let nf = e.free.len();
    let delta = &e.minors[r - 1];
    if delta.is_zero() {
        return false;
    }
    for k in 0..r {
        for (fi, &f) in e.free.iter().enumerate() {
            if f < e.piv[k] && !e.nmat[k * nf + fi].is_zero() {
                return false;
            }
        }
    }
    let m = b.len() / n;
    for i in 0..m {
        for (fi, &f) in e.free.iter().enumerate() {
            let lhs = delta.mul(&b[i * n + f]);
            let mut rhs = MPoly::zero(delta.nvars());
            for (k, &p) in e.piv.iter().enumerate() {
                let x = &b[i * n + p];
                let y = &e.nmat[k * nf + fi];
                if !x.is_zero() && !y.is_zero() {
                    rhs = rhs.add(&x.mul(y));
                }
            }
            if lhs != rhs {
                return false;
            }
        }
    }
    true
}

/// The certified echelon form; `None` when the kernel gives way to the generic algorithm
/// (three unlucky points, or a fraction-free elimination beyond its size bound). The
/// minors and $N$ are interpolated, or, when the grid is too large, computed by
/// fraction-free Gauss–Jordan on the same rows and pivots ([`gauss_jordan_zp`]); either way
/// [`check`] certifies them.
fn echelon(k: &RatFuncField, m: usize, n: usize, a: &[RatFunc]) -> Option<Echelon> {
    let nv = k.nvars();
    let (b, ds) = clear_rows(nv, m, n, a);
    if b.iter().all(MPoly::is_zero) {
        return Some(Echelon {
            piv: vec![],
            rows: vec![],
            minors: vec![],
            nmat: vec![],
            free: (0..n).collect(),
            ds,
        });
    }
    for attempt in 0..3 {
        let pr = profile_prime(attempt);
        let x = point(&pr, nv, 0xec4e_1011 + attempt as u64);
        let mut at: Vec<u64> = b.iter().map(|f| eval_mod_p(&pr, f, &x)).collect();
        let (piv, rows) = profile_mod_p(&pr, m, n, &mut at);
        let r = piv.len();
        let free: Vec<usize> = (0..n).filter(|c| !piv.contains(c)).collect();
        if r == 0 {
            continue;
        }
        if r == n {
            // full column rank, proved by a nonzero minor at this point: R = [I; 0] where
            // that minor is nonzero (its factors are the conditions)
            if !record_minor(k, &b, n, &rows, &piv, &ds) {
                return None;
            }
            return Some(Echelon {
                piv,
                rows,
                minors: vec![],
                nmat: vec![],
                free,
                ds,
            });
        }
        let c: Vec<MPoly> = rows
            .iter()
            .flat_map(|&i| b[i * n..(i + 1) * n].iter().cloned())
            .collect();
        let all: Vec<usize> = (0..r).collect();
        let map = |pr: &Prime, x: &mut [u64]| minors_and_solve_mod_p(pr, n, x, &piv, &free);
        let bounds = Bounds::of_rows(nv, n, &c, &all).probe(&c, &map);
        let nout = r + r * free.len();
        let too_large = grid_points(&bounds).saturating_mul(nout + c.len()) > MAX_VALUES;
        let interpolated = if too_large {
            None
        } else {
            match interpolate_zp(nv, &c, &bounds, nout, true, map) {
                Ok(Some(o)) => Some(o),
                Ok(None) => continue,
                Err(_) => None,
            }
        };
        let (minors, nmat) = match interpolated {
            Some(out) => {
                let mut out = out.into_iter();
                let minors: Vec<MPoly> = out.by_ref().take(r).collect();
                (minors, out.collect())
            }
            // the grid is too large: fraction-free elimination on the same rows and pivots
            None => {
                let mut c = c;
                let minors = gauss_jordan_zp(r, n, &mut c, &piv)?;
                let nmat = (0..r)
                    .flat_map(|i| free.iter().map(move |&f| (i, f)))
                    .map(|(i, f)| std::mem::replace(&mut c[i * n + f], MPoly::zero(nv)))
                    .collect();
                (minors, nmat)
            }
        };
        let e = Echelon {
            piv,
            rows,
            minors,
            nmat,
            free,
            ds: ds.clone(),
        };
        if check(&b, n, &e) {
            return Some(e);
        }
    }
    None
}

/// Records the numerators of the leading minors of $A$ on the pivot rows and columns.
fn record(k: &RatFuncField, e: &Echelon) {
    let nv = k.nvars();
    let mut sprod = MPoly::one(nv);
    for (idx, mk) in e.minors.iter().enumerate() {
        sprod = sprod.mul(&e.ds[e.rows[idx]]);
        if let Some(q) = k.frac(mk.clone(), sprod.clone()) {
            k.record_condition(q.num());
        }
    }
}

/// The canonical RREF of the `m x n` row-major `a` over $\mathbb{Q}(p)$ and its pivot
/// columns; `None`: the generic algorithm should run (see [`echelon`]).
pub fn rref_qp(
    k: &RatFuncField,
    m: usize,
    n: usize,
    a: &[RatFunc],
) -> Option<(Vec<RatFunc>, Vec<usize>)> {
    use crate::field::Field;
    if let Some(blocks) = split(k, m, n, a) {
        return assemble(k, m, n, a, &blocks, |x, bm, bn| rref_qp(k, bm, bn, x));
    }
    let e = echelon(k, m, n, a)?;
    record(k, &e);
    let r = e.piv.len();
    let nf = e.free.len();
    let mut out = vec![k.zero(); m * n];
    for (row, &p) in e.piv.iter().enumerate() {
        out[row * n + p] = k.one();
        if nf == 0 {
            continue;
        }
        let delta = &e.minors[r - 1];
        for (fi, &f) in e.free.iter().enumerate() {
            let x = &e.nmat[row * nf + fi];
            if !x.is_zero() {
                out[row * n + f] = k.frac(x.clone(), delta.clone()).expect("nonzero");
            }
        }
    }
    Some((out, e.piv))
}

/// The pivot columns of the RREF when a point proves them: its pivots are
/// $0, 1, \dots, r - 1$ with $r = \min(m, n)$ (every prefix of columns has the largest rank
/// it can have, so no generic pivot lies further left). `None` otherwise (the caller takes
/// the RREF). Recorded: the factors of that pivot minor ([`record_minor`]; `None` when they
/// cannot be found).
pub fn pivots_qp(k: &RatFuncField, m: usize, n: usize, a: &[RatFunc]) -> Option<Vec<usize>> {
    let (b, ds) = clear_rows(k.nvars(), m, n, a);
    let pr = profile_prime(0);
    let x = point(&pr, k.nvars(), 0xb17);
    let mut at: Vec<u64> = b.iter().map(|f| eval_mod_p(&pr, f, &x)).collect();
    let (piv, rows) = profile_mod_p(&pr, m, n, &mut at);
    let r = m.min(n);
    let ok = piv.len() == r && piv.iter().enumerate().all(|(i, &p)| i == p);
    (ok && record_minor(k, &b, n, &rows, &piv, &ds)).then_some(piv)
}

/// The rank of $A$ at a random point modulo a word prime, after clearing each row's
/// denominator: a lower bound of the generic rank over $\mathbb{Q}(p)$ (a minor that is
/// nonzero there is a nonzero polynomial), recording no condition.
pub fn rank_at_point(k: &RatFuncField, m: usize, n: usize, a: &[RatFunc]) -> usize {
    let (b, _) = clear_rows(k.nvars(), m, n, a);
    let pr = profile_prime(0);
    let x = point(&pr, k.nvars(), 0xa11);
    let mut at: Vec<u64> = b.iter().map(|f| eval_mod_p(&pr, f, &x)).collect();
    profile_mod_p(&pr, m, n, &mut at).0.len()
}

/// $\operatorname{rank} A$ over $\mathbb{Q}(p)$ (the conditions as for [`rref_qp`]).
pub fn rank_qp(k: &RatFuncField, m: usize, n: usize, a: &[RatFunc]) -> Option<usize> {
    if let Some(blocks) = split(k, m, n, a) {
        // rank A = sum of the blocks' ranks (see [`super::blocks`])
        return blocks.iter().try_fold(0, |acc, b| {
            rank_qp(k, b.rows.len(), b.cols.len(), &sub(a, n, b)).map(|r| acc + r)
        });
    }
    let (b, ds) = clear_rows(k.nvars(), m, n, a);
    // a rank equal to min(m, n) at a point is proved (a nonzero minor), where that minor is
    // nonzero (its factors are recorded)
    let pr = profile_prime(0);
    let x = point(&pr, k.nvars(), 0xa11);
    let mut at: Vec<u64> = b.iter().map(|f| eval_mod_p(&pr, f, &x)).collect();
    let (piv, rows) = profile_mod_p(&pr, m, n, &mut at);
    if piv.len() == m.min(n) {
        return record_minor(k, &b, n, &rows, &piv, &ds).then_some(piv.len());
    }
    let e = echelon(k, m, n, a)?;
    record(k, &e);
    Some(e.piv.len())
}
