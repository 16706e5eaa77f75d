//! Degree and coefficient bounds of polynomials computed from a matrix over
//! $\mathbb{Z}\lbrack p\rbrack$ (see [`super::interp`] for the certificate), and the size of the
//! interpolation grid they give: the lower set $\{e : e_v \le d_v, |e| \le D\}$.

use super::MPoly;
use crate::qkernels::prime::Prime;
use num_bigint::BigInt;
use num_traits::{One, Signed};

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
        // the degrees of every entry of the rows, once (the assignment bound reads each
        // many times): per entry the degree in each parameter, then the total degree
        let stride = nvars + 1;
        let mut degs = vec![0u32; rows.len() * ncols * stride];
        for (k, &i) in rows.iter().enumerate() {
            for (j, e) in b[i * ncols..(i + 1) * ncols].iter().enumerate() {
                let at = (k * ncols + j) * stride;
                degs[at..at + nvars].copy_from_slice(&e.degrees_array()[..nvars]);
                degs[at + nvars] = e.total_degree();
            }
        }
        let deg_at = |i: usize, j: usize, v: usize| degs[(i * ncols + j) * stride + v];
        let mut dv = vec![0u32; nvars];
        let mut dtot = 0u32;
        let mut coef = BigInt::one();
        for (k, &i) in rows.iter().enumerate() {
            for (v, d) in dv.iter_mut().enumerate() {
                *d += (0..ncols).map(|j| deg_at(k, j, v)).max().unwrap_or(0);
            }
            dtot += (0..ncols).map(|j| deg_at(k, j, nvars)).max().unwrap_or(0);
            let r: BigInt = b[i * ncols..(i + 1) * ncols].iter().map(norm1).sum();
            coef *= r + 1u32;
        }
        // the assignment bound: every term takes entries at distinct rows and columns. It
        // is at most the sum of the row maxima, so when the map i -> i attains that sum
        // (a dense matrix: every entry of the same degree) it is that sum, no Hungarian run
        if !rows.is_empty() && ncols > 0 {
            let assign = |d: u32, v: usize| -> u32 {
                let diag = (rows.len() <= ncols)
                    .then(|| (0..rows.len()).map(|i| deg_at(i, i, v)).sum::<u32>());
                if diag == Some(d) {
                    return d;
                }
                d.min(max_assignment(rows.len(), ncols, |i, j| {
                    i64::from(deg_at(i, j, v))
                }))
            };
            for (v, d) in dv.iter_mut().enumerate() {
                *d = assign(*d, v);
            }
            dtot = assign(dtot, nvars);
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

/// The largest $\sum_i w(i, \sigma(i))$ over injective maps $\sigma$ from the `r` rows to
/// the `c` columns (or from the columns to the rows when $r > c$), for weights $w \ge 0$, as
/// `u32` (saturating): the Hungarian algorithm on the costs $-w$, $O(r^2 c)$.
///
/// With $w(i, j) = \deg B_{ij}$ (0 for a zero entry) it bounds the degree of every minor of
/// $B$ and of every coefficient of $\det(xI - B)$ (a term of either takes entries at distinct
/// rows and columns; a smaller minor extends to a full map by entries of weight $\ge 0$): the
/// degree of the transposed Hankel or Krylov matrix $\deg B_{ij} = i + j$ is $\sum_i 2i$, where
/// the row maxima add up to $\sum_i (i + c - 1)$.
pub(super) fn max_assignment(r: usize, c: usize, w: impl Fn(usize, usize) -> i64) -> u32 {
    let (n, m, tr) = if r <= c { (r, c, false) } else { (c, r, true) };
    let cost = |i: usize, j: usize| -> i64 { if tr { -w(j, i) } else { -w(i, j) } };
    const INF: i64 = i64::MAX / 4;
    // potentials u (rows), v (columns); p[j] = row matched to column j (1-based, 0 = none)
    let mut u = vec![0i64; n + 1];
    let mut v = vec![0i64; m + 1];
    let mut p = vec![0usize; m + 1];
    let mut way = vec![0usize; m + 1];
    for i in 1..=n {
        p[0] = i;
        let mut j0 = 0usize;
        let mut minv = vec![INF; m + 1];
        let mut used = vec![false; m + 1];
        loop {
            used[j0] = true;
            let i0 = p[j0];
            let (mut delta, mut j1) = (INF, 0usize);
            for j in 1..=m {
                if !used[j] {
                    let cur = cost(i0 - 1, j - 1) - u[i0] - v[j];
                    if cur < minv[j] {
                        minv[j] = cur;
                        way[j] = j0;
                    }
                    if minv[j] < delta {
                        delta = minv[j];
                        j1 = j;
                    }
                }
            }
            for j in 0..=m {
                if used[j] {
                    u[p[j]] += delta;
                    v[j] -= delta;
                } else {
                    minv[j] -= delta;
                }
            }
            j0 = j1;
            if p[j0] == 0 {
                break;
            }
        }
        loop {
            let j1 = way[j0];
            p[j0] = p[j1];
            j0 = j1;
            if j0 == 0 {
                break;
            }
        }
    }
    let total: i64 = (1..=m)
        .filter(|&j| p[j] != 0)
        .map(|j| -cost(p[j] - 1, j - 1))
        .sum();
    u32::try_from(total).unwrap_or(u32::MAX)
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

#[cfg(test)]
mod tests {
    use super::max_assignment;
    use crate::rng::SplitMix64;

    /// The largest sum over injective maps, by trying every map (rows into columns).
    fn brute(r: usize, c: usize, w: &[i64], used: &mut Vec<bool>, i: usize) -> i64 {
        if i == r {
            return 0;
        }
        let mut best = i64::MIN;
        for j in 0..c {
            if !used[j] {
                used[j] = true;
                best = best.max(w[i * c + j] + brute(r, c, w, used, i + 1));
                used[j] = false;
            }
        }
        best
    }

    #[test]
    fn assignment_is_the_best_injective_map() {
        let mut rng = SplitMix64(0xa551);
        for case in 0..60 {
            let (r, c) = (1 + case % 5, 1 + (case / 5) % 6);
            let w: Vec<i64> = (0..r * c).map(|_| rng.int(0, 9)).collect();
            let want = if r <= c {
                brute(r, c, &w, &mut vec![false; c], 0)
            } else {
                let wt: Vec<i64> = (0..r * c).map(|k| w[(k % r) * c + k / r]).collect();
                brute(c, r, &wt, &mut vec![false; r], 0)
            };
            let got = max_assignment(r, c, |i, j| w[i * c + j]);
            assert_eq!(i64::from(got), want, "case {case}: {r} x {c}");
        }
        // a Hankel pattern deg = i + j: sum 2i, not the row maxima's sum
        assert_eq!(max_assignment(8, 8, |i, j| (i + j) as i64), 56);
    }
}
