//! The size budget of the determinant kernel over $\mathbb{Q}(p)$: a bound on the number of
//! terms of the numerator of $\det M$, known before anything is expanded
//! ([`det_terms_bound`]); above [`MAX_DET_TERMS`] the kernel answers `Limit`
//! ([`det_budget`]) instead of expanding (a Vandermonde minor of diag(p0..p9) has 10!
//! terms), so every caller of `Matrix::det` over $\mathbb{Q}(p)$ is protected and falls back
//! (the conditions of a command: to its computation's log).

use super::RatFunc;
use crate::error::{Error, Result};

/// The most terms the numerator of a determinant may have (by [`det_terms_bound`]) for the
/// kernel to expand it.
pub const MAX_DET_TERMS: u128 = 2_000_000;

/// A bound on the number of terms of the numerator of $\det M$ ($M$ `m x n` row-major over
/// $\mathbb{Q}(p)$ with `nv` parameters) before it is computed: the smaller of
/// $\prod_v (d_v + 1)$ and $\binom{d + k}{k}$, with $d_v = \sum_i \max_j (\deg_v
/// \mathrm{num}_{ij} + \deg_v \mathrm{den}_{ij})$ and $d$ the same sum of total degrees ($k$
/// parameters): a degree bound of the cleared determinant, row by row. An upper bound of
/// the numerator's terms when each row has one denominator (a polynomial matrix); with
/// several denominators in a row their lcm is not counted (a heuristic there).
pub fn det_terms_bound(nv: usize, m: usize, n: usize, a: &[RatFunc]) -> u128 {
    let mut dv = vec![0u32; nv];
    let mut dtot = 0u32;
    for i in 0..m {
        let mut row = vec![0u32; nv];
        let mut rt = 0u32;
        for x in &a[i * n..(i + 1) * n] {
            let (p, q) = (x.num(), x.den());
            for (v, r) in row.iter_mut().enumerate() {
                *r = (*r).max(p.deg(v) + q.deg(v));
            }
            rt = rt.max(p.total_degree() + q.total_degree());
        }
        for (d, r) in dv.iter_mut().zip(row) {
            *d += r;
        }
        dtot += rt;
    }
    let dense = dv
        .iter()
        .fold(1u128, |acc, &d| acc.saturating_mul(u128::from(d) + 1));
    // C(dtot + nv, nv), exact step by step (C(dtot + i, i) = C(dtot + i - 1, i - 1) (dtot + i) / i)
    let mut simplex = 1u128;
    for i in 1..=nv as u128 {
        simplex = match simplex.checked_mul(u128::from(dtot) + i) {
            Some(x) => x / i,
            None => u128::MAX,
        };
        if simplex == u128::MAX {
            break;
        }
    }
    dense.min(simplex)
}

/// `Ok` when the determinant of the `m x n` matrix `a` is within [`MAX_DET_TERMS`] by
/// [`det_terms_bound`] (a $1 \times 1$ or smaller matrix always is: nothing is expanded).
///
/// # Errors
/// `Limit` beyond, naming the size and the bound.
pub fn det_budget(nv: usize, m: usize, n: usize, a: &[RatFunc]) -> Result<()> {
    if m.min(n) <= 1 || nv == 0 {
        return Ok(());
    }
    let bound = det_terms_bound(nv, m, n, a);
    if bound > MAX_DET_TERMS {
        return Err(Error::Limit(format!(
            "a {m} x {n} minor may have up to {bound} terms (more than {MAX_DET_TERMS})"
        )));
    }
    Ok(())
}
