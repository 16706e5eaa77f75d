//! Degree and coefficient bounds of polynomials computed from a matrix over
//! $\mathbb{Z}\lbrack p\rbrack$ (see [`super::interp`] for the certificate), and the size of the
//! interpolation grid they give: the lower set $\{e : e_v \le d_v, |e| \le D\}$.

use super::MPoly;
use crate::qkernels::prime::Prime;
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

/// Degree and coefficient bounds of the outputs (see the module docs).
#[derive(Clone, Debug)]
pub struct Bounds {
    /// Degree bound per parameter.
    pub dv: Vec<u32>,
    /// Total-degree bound.
    pub dtot: u32,
    /// Bound on the absolute value of every integer coefficient.
    pub coef: BigInt,
    /// The certified bounds when these degrees were probed ([`Bounds::probe`]): a result
    /// interpolated with them is accepted only after [`super::probe::verify`]; else these run.
    pub certified: Option<Box<Bounds>>,
}

impl Bounds {
    /// Bounds for polynomials taking one entry from each row in `rows` of the row-major
    /// `B` with `ncols` columns (and possibly the 1 of $xI$).
    pub fn of_rows(nvars: usize, ncols: usize, b: &[MPoly], rows: &[usize]) -> Self {
        let mut dv = vec![0u32; nvars];
        let mut dtot = 0u32;
        let mut coef = BigInt::one();
        for &i in rows {
            let mut rowmax = vec![0u32; nvars];
            let mut rowtot = 0u32;
            let mut r = BigInt::zero();
            for e in &b[i * ncols..(i + 1) * ncols] {
                for (v, d) in e.degrees().into_iter().enumerate() {
                    rowmax[v] = rowmax[v].max(d);
                }
                rowtot = rowtot.max(e.total_degree());
                r += norm1(e);
            }
            for v in 0..nvars {
                dv[v] += rowmax[v];
            }
            dtot += rowtot;
            coef *= r + 1u32;
        }
        Bounds {
            dv,
            dtot,
            coef,
            certified: None,
        }
    }
    /// Bounds for $\det B$ and the coefficients of $\det(xI - B)$, `B` square `n x n`: every
    /// term takes one entry from each row AND each column, so the row bounds of
    /// [`Bounds::of_rows`] and the same bounds over the columns (those of $B^T$) both hold;
    /// the smaller of each is kept (diag-like matrices whose every row holds every parameter
    /// but each column few of them: a grid $2^9 \cdot 10$ instead of the simplex of degree 9).
    pub fn of_square(nvars: usize, n: usize, b: &[MPoly]) -> Self {
        let rows: Vec<usize> = (0..n).collect();
        let by_rows = Bounds::of_rows(nvars, n, b, &rows);
        let bt: Vec<MPoly> = (0..n * n).map(|k| b[(k % n) * n + k / n].clone()).collect();
        let by_cols = Bounds::of_rows(nvars, n, &bt, &rows);
        Bounds {
            dv: by_rows
                .dv
                .iter()
                .zip(&by_cols.dv)
                .map(|(x, y)| *x.min(y))
                .collect(),
            dtot: by_rows.dtot.min(by_cols.dtot),
            coef: by_rows.coef.min(by_cols.coef),
            certified: None,
        }
    }
}

/// 1-norm of a polynomial's coefficient vector.
fn norm1(f: &MPoly) -> BigInt {
    f.terms().iter().map(|t| t.1.abs()).sum()
}

/// Number of points of the grid of [`super::interp::interpolate_zp`] (`usize::MAX` on
/// overflow):
/// the box $\{e : e_v \le d_v\}$ when its total degree stays within $D$, else the lower set
/// $\{e : e_v \le d_v, |e| \le D\}$ (box and simplex at once; a lower set of exponents
/// determines the polynomials supported on it, see [`super::interp`]).
pub fn grid_points(bounds: &Bounds) -> usize {
    let nbox = bounds
        .dv
        .iter()
        .try_fold(1usize, |acc, &d| acc.checked_mul(d as usize + 1))
        .unwrap_or(usize::MAX);
    if box_inside(bounds) {
        return nbox;
    }
    lower_count(&bounds.dv, bounds.dtot).min(nbox)
}

/// Is the box inside the simplex ($\sum_v d_v \le D$)?
pub(super) fn box_inside(bounds: &Bounds) -> bool {
    bounds.dv.iter().map(|&d| u64::from(d)).sum::<u64>() <= u64::from(bounds.dtot)
}

/// $|\{e : e_v \le d_v, |e| \le D\}|$ by counting sums variable by variable (saturating).
fn lower_count(dv: &[u32], dtot: u32) -> usize {
    let big = dtot as usize;
    if big > 1 << 16 {
        return usize::MAX;
    }
    let mut ways = vec![0usize; big + 1];
    ways[0] = 1;
    for &d in dv {
        // next[s] = ways[s - d] + ... + ways[s], by prefix sums (saturating)
        let mut prefix = Vec::with_capacity(big + 2);
        prefix.push(0usize);
        for &w in &ways {
            prefix.push(prefix.last().copied().unwrap_or(0).saturating_add(w));
        }
        ways = (0..=big)
            .map(|s| {
                let lo = s.saturating_sub(d as usize);
                let (hi, low) = (prefix[s + 1], prefix[lo]);
                // a saturated prefix makes the difference meaningless: stay saturated
                if hi == usize::MAX {
                    usize::MAX
                } else {
                    hi - low
                }
            })
            .collect();
    }
    ways.iter().fold(0usize, |acc, &w| acc.saturating_add(w))
}

/// $1/j$ modulo the prime for $j = 1..m$ (index 0 holds 0).
pub(super) fn small_inverses(pr: &Prime, m: usize) -> Vec<u64> {
    (0..=m)
        .map(|j| {
            if j == 0 {
                0
            } else {
                pr.inv(j as u64).expect("small")
            }
        })
        .collect()
}
