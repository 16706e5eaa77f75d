//! The orthogonal controllability staircase and the ranks it reveals.
//!
//! An orthogonal $Q$ ($x = Q z$, $A' = Q^T A Q$, $B' = Q^T B$, $C' = C Q$) brings $(A, B)$ to
//!
//! $$[B' \mid A'] = \left[\begin{array}{c|cccc} B_1 & A_{11} & A_{12} & \cdots & * \\
//!   0 & A_{21} & A_{22} & \cdots & * \\ 0 & 0 & A_{32} & \cdots & * \\ \vdots & & & \ddots \\
//!   0 & 0 & \cdots & 0 & A_{\bar c} \end{array}\right]$$
//!
//! with $B_1$, $A_{21}$, $A_{32}, \dots$ of full row rank $r_1 \ge r_2 \ge \dots$; the
//! controllable part has order $n_c = \sum r_i$. Each step compresses one block by Householder
//! QR with column pivoting followed by a Jacobi SVD of the small triangular factor (it gives
//! the singular values on which the rank is decided, see [`super::RankGap`]); singular values
//! below the threshold are set to zero, which is a backward error of at most their size.
//! The same kernel on $(A^T, C^T)$ gives the observable part.
//!
//! | entry point                | returns                                     | cost          |
//! |----------------------------|---------------------------------------------|---------------|
//! | [`controllability_rank`]   | [`FloatRank`] of $[B, AB, \dots, A^{n-1}B]$ | $O(n^3)$      |
//! | [`observability_rank`]     | [`FloatRank`] of the observability matrix   | $O(n^3)$      |
//! | [`is_controllable`], [`is_observable`] | [`Truth`]                       | $O(n^3)$      |

use nalgebra::DMatrix;

use super::svd::left_basis;
use super::{RankGap, Tol, Truth, all_clear, check_finite, check_square, decide_rank, pow2_ratio};
use crate::error::{Error, Result};

/// A numerical rank with its diagnostics.
#[derive(Clone, Debug, PartialEq)]
pub struct FloatRank {
    /// The decided rank.
    pub rank: usize,
    /// `True` when every step's singular value gap was clear.
    pub truth: Truth,
    /// One decision per staircase step.
    pub gaps: Vec<RankGap>,
}

/// Result of the staircase kernel.
pub(crate) struct Staircase {
    /// Order of the controllable part (leading states).
    pub order: usize,
    /// The rank decision of each step.
    pub gaps: Vec<RankGap>,
}

/// Numerical rank of the controllability matrix of `(a, b)`.
///
/// # Examples
/// ```
/// use exactlti::float::{controllability_rank, Tol, Truth};
/// use nalgebra::DMatrix;
/// let a = DMatrix::from_row_slice(2, 2, &[0.0, 1.0, 0.0, 0.0]);
/// let b = DMatrix::from_row_slice(2, 1, &[1.0, 0.0]);
/// let r = controllability_rank(&a, &b, &Tol::default()).unwrap();
/// assert_eq!((r.rank, r.truth), (1, Truth::True));
/// ```
///
/// # Errors
/// [`Error::NotSquare`] / [`Error::Shape`] for bad shapes, [`Error::Invalid`] for non-finite
/// entries.
pub fn controllability_rank(a: &DMatrix<f64>, b: &DMatrix<f64>, tol: &Tol) -> Result<FloatRank> {
    check_square("controllability_rank", a)?;
    check_finite("controllability_rank", b)?;
    if b.nrows() != a.nrows() {
        return Err(Error::Shape {
            op: "controllability_rank",
            expected: (a.nrows(), b.ncols()),
            found: b.shape(),
        });
    }
    let mut a = a.clone();
    // rank [B, AB, ...] = rank [αB, A αB, ...]: bring B to the size of A (exact power of 2)
    let mut b = b * pow2_ratio(a.norm(), b.norm());
    let mut c = DMatrix::<f64>::zeros(0, a.nrows());
    let scale = a.norm().max(b.norm());
    let s = controllable_staircase(&mut a, &mut b, &mut c, scale, tol, "controllability");
    Ok(FloatRank {
        rank: s.order,
        truth: all_clear(&s.gaps),
        gaps: s.gaps,
    })
}

/// Numerical rank of the observability matrix of `(a, c)` (the dual staircase).
///
/// # Errors
/// As [`controllability_rank`].
pub fn observability_rank(a: &DMatrix<f64>, c: &DMatrix<f64>, tol: &Tol) -> Result<FloatRank> {
    check_square("observability_rank", a)?;
    if c.ncols() != a.nrows() {
        return Err(Error::Shape {
            op: "observability_rank",
            expected: (c.nrows(), a.nrows()),
            found: c.shape(),
        });
    }
    let mut r = controllability_rank(&a.transpose(), &c.transpose(), tol)?;
    for g in &mut r.gaps {
        g.what = g.what.replace("controllability", "observability");
    }
    Ok(r)
}

/// Whether `(a, b)` is controllable: `False` only when a rank deficiency is clear.
///
/// # Errors
/// As [`controllability_rank`].
pub fn is_controllable(a: &DMatrix<f64>, b: &DMatrix<f64>, tol: &Tol) -> Result<Truth> {
    let r = controllability_rank(a, b, tol)?;
    Ok(Truth::from_bool(r.rank == a.nrows()).if_certain(r.truth))
}

/// Whether `(a, c)` is observable: `False` only when a rank deficiency is clear.
///
/// # Errors
/// As [`observability_rank`].
pub fn is_observable(a: &DMatrix<f64>, c: &DMatrix<f64>, tol: &Tol) -> Result<Truth> {
    let r = observability_rank(a, c, tol)?;
    Ok(Truth::from_bool(r.rank == a.nrows()).if_certain(r.truth))
}

/// Brings `(a, b, c)` to controllability staircase form in place (orthogonal similarity) and
/// returns the order of the controllable part. No shape checks. Rank decisions use the
/// threshold `tol.threshold(scale)`.
pub(crate) fn controllable_staircase(
    a: &mut DMatrix<f64>,
    b: &mut DMatrix<f64>,
    c: &mut DMatrix<f64>,
    scale: f64,
    tol: &Tol,
    what: &str,
) -> Staircase {
    let n = a.nrows();
    let m = b.ncols();
    let mut gaps = Vec::new();
    let (mut off, mut prev, mut width) = (0usize, 0usize, m);
    let mut first = true;
    let mut work: Vec<f64> = Vec::new();
    let mut tmp: Vec<f64> = Vec::new();
    let mut step = 1;
    while off < n && width > 0 {
        let len = n - off;
        // Copy the block to compress (len x width, column-major).
        work.clear();
        {
            let (src, ld, c0) = if first {
                (b.as_slice(), n, 0)
            } else {
                (a.as_slice(), n, prev)
            };
            for j in 0..width {
                let col = &src[(c0 + j) * ld..(c0 + j + 1) * ld];
                work.extend_from_slice(&col[off..n]);
            }
        }
        let k = len.min(width);
        let taus = qr_col_piv(&mut work, len, width, k);
        let r_fac = DMatrix::from_fn(
            k,
            width,
            |i, j| if j >= i { work[i + j * len] } else { 0.0 },
        );
        let (sv, u) = left_basis(&r_fac);
        let g = decide_rank(&format!("{what} step {step}"), &sv, scale, tol);
        let r = g.rank;
        gaps.push(g);
        // Apply the reflectors, then U, on both sides.
        let ccols = if first { 0 } else { prev };
        for (j, &tau) in taus.iter().enumerate() {
            let v = &work[j * len + j..(j + 1) * len];
            let r0 = off + j;
            apply_left(a, r0, v, tau, ccols);
            if first {
                apply_left(b, r0, v, tau, 0);
            }
            apply_right(a, r0, v, tau, &mut tmp);
            apply_right(c, r0, v, tau, &mut tmp);
        }
        small_left(a, off, &u, ccols, &mut tmp);
        if first {
            small_left(b, off, &u, 0, &mut tmp);
        }
        small_right(a, off, &u, &mut tmp);
        small_right(c, off, &u, &mut tmp);
        // Zero the compressed block below its rank.
        let blk: &mut DMatrix<f64> = if first { b } else { a };
        let c0 = if first { 0 } else { prev };
        for j in c0..c0 + width {
            for i in off + r..n {
                blk[(i, j)] = 0.0;
            }
        }
        if r == 0 {
            break;
        }
        prev = off;
        off += r;
        width = r;
        first = false;
        step += 1;
    }
    Staircase { order: off, gaps }
}

/// Householder QR with column pivoting of the `len x width` column-major `w`, `k` reflectors;
/// returns their `tau`s. On return the upper trapezoid of `w` holds R (of the pivoted matrix)
/// and column `j` strictly below the diagonal holds `v_j[1..]`; `v_j[0] = 1` is implicit (the
/// diagonal slot holds R's entry, and `apply_left`/`apply_right` never read `v[0]`).
fn qr_col_piv(w: &mut [f64], len: usize, width: usize, k: usize) -> Vec<f64> {
    let mut taus = Vec::with_capacity(k);
    let mut norms: Vec<f64> = (0..width)
        .map(|j| w[j * len..(j + 1) * len].iter().map(|x| x * x).sum::<f64>())
        .collect();
    let mut rdiag = Vec::with_capacity(k);
    for j in 0..k {
        // Pivot: the remaining column of largest norm.
        let p = (j..width)
            .max_by(|&x, &y| norms[x].total_cmp(&norms[y]).then(y.cmp(&x)))
            .unwrap_or(j);
        if p != j {
            for i in 0..len {
                w.swap(j * len + i, p * len + i);
            }
            norms.swap(j, p);
        }
        let (tau, beta) = householder(&mut w[j * len + j..(j + 1) * len]);
        rdiag.push(beta);
        // v = [1, w[j+1..]]: temporarily put 1 in the diagonal slot.
        w[j * len + j] = 1.0;
        for l in j + 1..width {
            let (vcol, rest) = w.split_at_mut(l * len);
            let v = &vcol[j * len + j..(j + 1) * len];
            let x = &mut rest[j..len];
            let dot: f64 = v.iter().zip(x.iter()).map(|(p, q)| p * q).sum();
            let s = tau * dot;
            for (xi, vi) in x.iter_mut().zip(v) {
                *xi -= s * vi;
            }
            norms[l] = x[1..].iter().map(|y| y * y).sum();
        }
        taus.push(tau);
    }
    // Restore R's diagonal over the temporary leading 1s.
    for (j, &beta) in rdiag.iter().enumerate() {
        w[j * len + j] = beta;
    }
    taus
}

/// LAPACK-style Householder vector: on return `x[0] = beta` and `x[1..]` holds `v[1..]`
/// with `(I - tau v v^T) x_in = beta e_1`, `v[0] = 1`.
fn householder(x: &mut [f64]) -> (f64, f64) {
    let alpha = x[0];
    let xnorm = x[1..].iter().map(|y| y * y).sum::<f64>().sqrt();
    if xnorm == 0.0 {
        return (0.0, alpha);
    }
    let beta = -alpha.signum() * alpha.hypot(xnorm);
    let tau = (beta - alpha) / beta;
    let s = 1.0 / (alpha - beta);
    for y in &mut x[1..] {
        *y *= s;
    }
    x[0] = beta;
    (tau, beta)
}

/// `M[r0.., c0..] = (I - tau v v^T) M[r0.., c0..]` (v[0] taken as 1).
fn apply_left(m: &mut DMatrix<f64>, r0: usize, v: &[f64], tau: f64, c0: usize) {
    if tau == 0.0 {
        return;
    }
    let nr = m.nrows();
    let nc = m.ncols();
    let data = m.as_mut_slice();
    for j in c0..nc {
        let col = &mut data[j * nr + r0..(j + 1) * nr];
        let mut dot = col[0];
        for (x, vi) in col[1..].iter().zip(&v[1..]) {
            dot += x * vi;
        }
        let s = tau * dot;
        col[0] -= s;
        for (x, vi) in col[1..].iter_mut().zip(&v[1..]) {
            *x -= s * vi;
        }
    }
}

/// `M[.., c0..] = M[.., c0..] (I - tau v v^T)` (v[0] taken as 1).
fn apply_right(m: &mut DMatrix<f64>, c0: usize, v: &[f64], tau: f64, w: &mut Vec<f64>) {
    if tau == 0.0 {
        return;
    }
    let nr = m.nrows();
    if nr == 0 {
        return;
    }
    let data = m.as_mut_slice();
    w.clear();
    w.extend_from_slice(&data[c0 * nr..(c0 + 1) * nr]);
    for (i, &vi) in v.iter().enumerate().skip(1) {
        let col = &data[(c0 + i) * nr..(c0 + i + 1) * nr];
        for (wr, x) in w.iter_mut().zip(col) {
            *wr += vi * x;
        }
    }
    for (i, &vi) in v.iter().enumerate() {
        let s = tau * if i == 0 { 1.0 } else { vi };
        let col = &mut data[(c0 + i) * nr..(c0 + i + 1) * nr];
        for (x, wr) in col.iter_mut().zip(w.iter()) {
            *x -= s * wr;
        }
    }
}

/// Rows `r0..r0+k`, columns `c0..`: `M <- U^T M`.
fn small_left(m: &mut DMatrix<f64>, r0: usize, u: &DMatrix<f64>, c0: usize, t: &mut Vec<f64>) {
    let k = u.nrows();
    let nr = m.nrows();
    let nc = m.ncols();
    let data = m.as_mut_slice();
    for j in c0..nc {
        let col = &mut data[j * nr + r0..j * nr + r0 + k];
        t.clear();
        t.extend_from_slice(col);
        for (i, x) in col.iter_mut().enumerate() {
            *x = (0..k).map(|q| u[(q, i)] * t[q]).sum();
        }
    }
}

/// Columns `c0..c0+k`: `M <- M U`.
fn small_right(m: &mut DMatrix<f64>, c0: usize, u: &DMatrix<f64>, t: &mut Vec<f64>) {
    let k = u.nrows();
    let nr = m.nrows();
    if nr == 0 {
        return;
    }
    let data = m.as_mut_slice();
    t.clear();
    t.extend_from_slice(&data[c0 * nr..(c0 + k) * nr]);
    for i in 0..k {
        let col = &mut data[(c0 + i) * nr..(c0 + i + 1) * nr];
        col.fill(0.0);
        for q in 0..k {
            let uq = u[(q, i)];
            let src = &t[q * nr..(q + 1) * nr];
            for (x, s) in col.iter_mut().zip(src) {
                *x += uq * s;
            }
        }
    }
}
