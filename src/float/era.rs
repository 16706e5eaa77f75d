//! Markov parameters and the eigensystem realization algorithm (ERA).
//!
//! Markov parameters: $M_0 = D$, $M_k = C A^{k-1} B$ ($k \ge 1$). ERA (Juang and Pappa; the
//! minimal-realizations paper, eq. 10-15) takes the block Hankel matrices
//! $H_0 = [M_{i+j+1}]_{i<r,\,j<s}$ and $H_1 = [M_{i+j+2}]_{i<r,\,j<s}$, the SVD
//! $H_0 = U \Sigma V^T$ (one-sided Jacobi) truncated to the numerical rank (or a requested order) $n$, and
//!
//! $$A = \Sigma_n^{-1/2} U_n^T H_1 V_n \Sigma_n^{-1/2},\quad
//!   B = \Sigma_n^{1/2} V_n^T \begin{bmatrix} I_m \\ 0 \end{bmatrix},\quad
//!   C = \begin{bmatrix} I_p & 0 \end{bmatrix} U_n \Sigma_n^{1/2},\quad D = M_0.$$
//!
//! When $H_0$ has exact rank equal to the McMillan degree, this realization is minimal and
//! reproduces every Markov parameter.
//!
//! | entry point             | returns                              |
//! |-------------------------|--------------------------------------|
//! | [`markov_parameters`]   | $M_0, \dots, M_{k-1}$                |
//! | [`era`]                 | [`FloatRealization`]                 |

use super::svd::jacobi_svd;
use nalgebra::DMatrix;

use super::{RankGap, Tol, Truth, check_finite, check_system, decide_rank};
use crate::error::{Error, Result};

/// A realization computed from Markov parameters, with its diagnostics.
#[derive(Clone, Debug, PartialEq)]
pub struct FloatRealization {
    /// State matrix (`order x order`).
    pub a: DMatrix<f64>,
    /// Input matrix (`order x m`).
    pub b: DMatrix<f64>,
    /// Output matrix (`p x order`).
    pub c: DMatrix<f64>,
    /// Feedthrough `M_0`.
    pub d: DMatrix<f64>,
    /// The order used.
    pub order: usize,
    /// Block rows and block columns of the Hankel matrices.
    pub hankel_blocks: (usize, usize),
    /// Singular values of $H_0$, descending.
    pub singular_values: Vec<f64>,
    /// The rank decision on $H_0$.
    pub rank_gap: RankGap,
    /// `True` when the rank gap is clear, the order equals the numerical rank, the Hankel
    /// matrix is larger than its rank (so the McMillan degree was reached), and the dropped
    /// singular values are at the rounding floor (`sqrt(gap) * ε σ_1 k`).
    pub truth: Truth,
}

/// The first `k` Markov parameters `D, CB, CAB, ..., C A^{k-2} B`.
///
/// # Errors
/// Shape errors and non-finite entries, as [`super::minreal`].
pub fn markov_parameters(
    a: &DMatrix<f64>,
    b: &DMatrix<f64>,
    c: &DMatrix<f64>,
    d: &DMatrix<f64>,
    k: usize,
) -> Result<Vec<DMatrix<f64>>> {
    check_system("markov_parameters", a, b, c, d)?;
    let mut out = Vec::with_capacity(k);
    if k == 0 {
        return Ok(out);
    }
    out.push(d.clone());
    let mut x = b.clone();
    for i in 1..k {
        out.push(c * &x);
        if i + 1 < k {
            x = a * &x;
        }
    }
    Ok(out)
}

/// ERA realization from Markov parameters `markov[0] = D, markov[k] = C A^{k-1} B`.
///
/// With `order = None` the order is the numerical rank of $H_0$; `Some(n)` truncates to `n`.
///
/// # Examples
/// ```
/// use exactlti::float::{era, markov_parameters, Tol, Truth};
/// use nalgebra::DMatrix;
/// let a = DMatrix::from_row_slice(2, 2, &[0.0, 1.0, -2.0, -3.0]);
/// let b = DMatrix::from_row_slice(2, 1, &[0.0, 1.0]);
/// let c = DMatrix::from_row_slice(1, 2, &[1.0, 0.0]);
/// let d = DMatrix::zeros(1, 1);
/// let h = markov_parameters(&a, &b, &c, &d, 8).unwrap();
/// let r = era(&h, None, &Tol::default()).unwrap();
/// assert_eq!((r.order, r.truth), (2, Truth::True));
/// ```
///
/// # Errors
/// [`Error::Invalid`] for fewer than three parameters, parameters of different shapes,
/// non-finite entries, or a requested order larger than the Hankel matrix or beyond a zero
/// singular value.
pub fn era(markov: &[DMatrix<f64>], order: Option<usize>, tol: &Tol) -> Result<FloatRealization> {
    if markov.len() < 3 {
        return Err(Error::Invalid(format!(
            "era: need at least 3 Markov parameters (D, CB, CAB), got {}",
            markov.len()
        )));
    }
    let (p, m) = markov[0].shape();
    if p == 0 || m == 0 {
        return Err(Error::Invalid(format!(
            "era: Markov parameters are {p}x{m}; need at least one input and one output"
        )));
    }
    for h in markov {
        if h.shape() != (p, m) {
            return Err(Error::Shape {
                op: "era",
                expected: (p, m),
                found: h.shape(),
            });
        }
        check_finite("era", h)?;
    }
    let moments = markov.len() - 1;
    let r = moments / 2;
    let s = moments - r;
    let hankel = |shift: usize| {
        let mut h = DMatrix::<f64>::zeros(r * p, s * m);
        for i in 0..r {
            for j in 0..s {
                h.view_mut((i * p, j * m), (p, m))
                    .copy_from(&markov[i + j + 1 + shift]);
            }
        }
        h
    };
    let h0 = hankel(0);
    let h1 = hankel(1);
    let svd = jacobi_svd(h0);
    let sv: Vec<f64> = svd.sv[..(r * p).min(s * m)].to_vec();
    let gap = decide_rank("rank H0", &sv, 0.0, tol);
    let maxrank = sv.len();
    let n = order.unwrap_or(gap.rank);
    if n > maxrank {
        return Err(Error::Invalid(format!(
            "era: order {n} exceeds the Hankel matrix size {maxrank}; supply more Markov parameters"
        )));
    }
    if n > 0 && sv[n - 1] <= 0.0 {
        return Err(Error::Invalid(format!(
            "era: order {n} reaches a zero singular value of the Hankel matrix"
        )));
    }
    // U_n = W_n Σ_n^{-1} (W = H0 V), V_n^T.
    let sq: Vec<f64> = sv[..n].iter().map(|x| x.sqrt()).collect();
    let un = DMatrix::from_fn(r * p, n, |i, j| svd.w[(i, j)] / sv[j]);
    let vtn = svd.v.columns(0, n).transpose();
    let mut a = un.transpose() * &h1 * vtn.transpose();
    for i in 0..n {
        for j in 0..n {
            a[(i, j)] /= sq[i] * sq[j];
        }
    }
    let b = DMatrix::from_fn(n, m, |i, j| sq[i] * vtn[(i, j)]);
    let c = DMatrix::from_fn(p, n, |i, j| un[(i, j)] * sq[j]);
    let saturated = gap.rank >= maxrank;
    // Markov parameters of a finite system give a Hankel matrix whose discarded singular
    // values are rounding noise; dropped values far above that floor mean the fast modes
    // swamped the slow ones (the paper's sec. 4 ERA failure), so the order is not trusted.
    let floor = f64::EPSILON * sv.first().copied().unwrap_or(0.0) * sv.len() as f64;
    let noise_only = gap.dropped <= tol.gap.max(1.0).sqrt() * floor;
    let truth = if gap.truth == Truth::True && n == gap.rank && !saturated && noise_only {
        Truth::True
    } else {
        Truth::Unknown
    };
    Ok(FloatRealization {
        a,
        b,
        c,
        d: markov[0].clone(),
        order: n,
        hankel_blocks: (r, s),
        singular_values: sv,
        rank_gap: gap,
        truth,
    })
}
