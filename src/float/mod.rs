//! Float backend on nalgebra: tolerance-based analogues of the exact algorithms.
//!
//! Everything here works on `DMatrix<f64>` (and `DMatrix<Complex<f64>>` where complex
//! arithmetic is needed) and never claims certainty: every rank decision is a comparison of
//! singular values $\sigma_1 \ge \sigma_2 \ge \dots$ against a threshold
//! $t = \max(\text{abs}, \text{rel}\cdot S)$, where $S$ is a norm of the data, and is reported
//! as a [`RankGap`]. A decision is [`Truth::True`] ("numerically clear") only when the
//! threshold sits inside a wide gap: $\sigma_r \ge \sqrt{\text{gap}}\,t$ and
//! $\max(\sigma_{r+1}, \varepsilon S k) \le t/\sqrt{\text{gap}}$, with $k$ the number of
//! singular values. Otherwise it is [`Truth::Unknown`]. The exact path
//! (`realization`, `jordan`) is the one that proves; this module cross-checks and scales.
//!
//! | entry point                          | computes                                                | algorithm                               |
//! |--------------------------------------|---------------------------------------------------------|-----------------------------------------|
//! | [`eigenvalues`], [`eigenvectors`]    | $\lambda_i(A)$, $A v_i = \lambda_i v_i$                 | balancing + Hessenberg QR (`dlahqr`); inverse iteration |
//! | [`jordan_guess`]                     | clusters, multiplicities, Jordan block sizes            | clustering + ranks of $(A-cI)^k$ by SVD |
//! | [`minreal`]                          | controllable and observable part of $(A,B,C,D)$         | orthogonal staircase (as SLICOT TB01PD) |
//! | [`controllability_rank`], [`observability_rank`] | $\operatorname{rank}[B, AB, \dots]$, dual     | orthogonal staircase                    |
//! | [`markov_parameters`], [`era`]       | $D, CB, CAB, \dots$; realization from them              | ERA (Juang and Pappa), paper eq. 10-15  |
//! | [`invariant_zeros`]                  | $s$ where $\operatorname{rank}[A-sI, B; C, D]$ drops    | Emami-Naeini and Van Dooren reduction   |
//! | [`pencil_finite_eigenvalues`]        | the $r$ finite $\lambda$ with $\det(\lambda E - A) = 0$, $r$ given exactly | shift and invert, no QZ |
//! | [`freqresp`]                         | $G(j\omega) = C(j\omega I - A)^{-1}B + D$               | complex LU solves                       |
//! | [`modal::ModalSystem`]               | the same and $e^{Jh}$ stepping through the Jordan blocks | closed-form block inverse (eq. 56)      |

use nalgebra::DMatrix;

use crate::error::{Error, Result};

mod balred;
pub(crate) mod convert;
mod eigen;
mod era;
mod freqresp;
mod hqr;
mod jordan_guess;
mod minreal;
pub mod modal;
mod pencil_eig;
pub mod random;
mod staircase;
pub mod stepinfo;
mod svd;
pub mod time_response;
mod zeros;

pub use balred::{Balred, MAX_BALRED_ORDER, balred};
pub use convert::{to_cmatrix, to_dmatrix};
pub use eigen::{EigenPairs, eigenvalues, eigenvectors};
pub use era::{
    FloatRealization, HANKEL_ENTRY_LIMIT, HANKEL_WORK_LIMIT, SystemEra, era, era_system,
    markov_parameters,
};
pub use freqresp::{freqresp, freqresp_descriptor};
pub use jordan_guess::{Cluster, FloatJordan, jordan_guess};
pub use minreal::{FloatMinreal, minreal};
pub use pencil_eig::pencil_finite_eigenvalues;
pub use staircase::{
    FloatRank, controllability_rank, is_controllable, is_observable, observability_rank,
};
pub use time_response::{Input, time_response};
pub use zeros::{FloatZeros, invariant_zeros, invariant_zeros_report};

/// A float answer to a yes/no question: `Unknown` when the numbers do not decide it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Truth {
    /// Numerically clear (a wide singular value gap), not a proof.
    True,
    /// Numerically clear that it does not hold.
    False,
    /// The singular value gap is too narrow to decide.
    Unknown,
}

impl Truth {
    /// Conjunction: `False` wins, then `Unknown`.
    pub fn and(self, other: Truth) -> Truth {
        match (self, other) {
            (Truth::False, _) | (_, Truth::False) => Truth::False,
            (Truth::True, Truth::True) => Truth::True,
            _ => Truth::Unknown,
        }
    }

    /// `True` for `true`, `False` for `false`.
    pub fn from_bool(b: bool) -> Truth {
        if b { Truth::True } else { Truth::False }
    }

    /// `self` if `certain`, otherwise `Unknown`.
    pub fn if_certain(self, certain: Truth) -> Truth {
        if certain == Truth::True {
            self
        } else {
            Truth::Unknown
        }
    }
}

/// Rank-decision tolerances; defaults scale with `f64::EPSILON`.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct Tol {
    /// Absolute threshold: singular values `<= abs` count as zero.
    pub abs: f64,
    /// Relative threshold: singular values `<= rel * S` count as zero (`S` a norm of the data).
    pub rel: f64,
    /// Accept rank r only if σ_r / σ_{r+1} ≥ `gap`; otherwise report `Truth::Unknown`.
    pub gap: f64,
}

impl Default for Tol {
    /// `abs = 0`, `rel = sqrt(ε) ≈ 1.5e-8` (MATLAB's `minreal` default), `gap = 1e3`.
    ///
    /// A staircase amplifies rounding errors step by step (see [`random`]), so thresholds
    /// near `ε` keep noise as rank; `sqrt(ε)` is the usual compromise.
    fn default() -> Self {
        Tol {
            abs: 0.0,
            rel: f64::EPSILON.sqrt(),
            gap: 1e3,
        }
    }
}

impl Tol {
    /// Tolerances from their three values.
    pub fn new(abs: f64, rel: f64, gap: f64) -> Self {
        Tol { abs, rel, gap }
    }

    /// The default tolerances with another relative threshold.
    pub fn with_rel(rel: f64) -> Self {
        Tol {
            rel,
            ..Tol::default()
        }
    }

    /// The threshold `max(abs, rel * scale)`.
    pub fn threshold(&self, scale: f64) -> f64 {
        self.abs.max(self.rel * scale)
    }
}

/// One rank decision and the singular values on both sides of the cut.
#[derive(Clone, Debug, PartialEq)]
pub struct RankGap {
    /// What was decided (e.g. `"controllability step 3"`).
    pub what: String,
    /// The decided rank `r`.
    pub rank: usize,
    /// Number of singular values considered.
    pub size: usize,
    /// The threshold `t`: singular values `> t` are kept.
    pub threshold: f64,
    /// The smallest kept singular value `σ_r` (`+inf` when `r = 0`).
    pub kept: f64,
    /// The largest dropped singular value `σ_{r+1}` (`0` when `r = size`).
    pub dropped: f64,
    /// `kept / max(dropped, noise floor)` (`threshold / ...` when `r = 0`).
    pub ratio: f64,
    /// `True` when `kept >= sqrt(gap) * threshold` and `max(dropped, noise floor) <=
    /// threshold / sqrt(gap)`, otherwise `Unknown`.
    pub truth: Truth,
}

/// Decides the numerical rank of a matrix from its singular values `sv` (any order).
///
/// `scale` is the norm the relative threshold refers to (at least `max sv` is used).
pub(crate) fn decide_rank(what: &str, sv: &[f64], scale: f64, tol: &Tol) -> RankGap {
    let mut s: Vec<f64> = sv.to_vec();
    s.sort_by(|a, b| b.total_cmp(a));
    let smax = s.first().copied().unwrap_or(0.0);
    let scale = scale.max(smax);
    let t = tol.threshold(scale);
    let rank = s.iter().take_while(|&&x| x > t).count();
    let floor = f64::EPSILON * scale * (s.len().max(1) as f64);
    let kept = if rank > 0 { s[rank - 1] } else { f64::INFINITY };
    let dropped = if rank < s.len() { s[rank] } else { 0.0 };
    let noise = dropped.max(floor);
    let ratio = if rank == 0 {
        if noise == 0.0 {
            f64::INFINITY
        } else {
            t / noise
        }
    } else {
        kept / noise.max(f64::MIN_POSITIVE)
    };
    // Clear when the threshold sits inside a wide gap: sqrt(gap) on both sides.
    let half = tol.gap.max(1.0).sqrt();
    let truth = if kept >= half * t && noise <= t / half {
        Truth::True
    } else {
        Truth::Unknown
    };
    RankGap {
        what: what.to_string(),
        rank,
        size: s.len(),
        threshold: t,
        kept,
        dropped,
        ratio,
        truth,
    }
}

/// The power of two nearest to `target / x` (1 when either is zero or not finite).
///
/// Controllability, observability, McMillan degree and invariant zeros do not change under
/// input and output scaling `B -> αB`, `C -> βC`, `D -> βDα`; scaling `B` and `C` to the size of
/// `A` by powers of two (exact in binary) lets one relative threshold serve every block, so
/// `A = diag(-1e20, -2e20)`, `B = [1; 1]` is not read as `B ≈ 0`.
pub(crate) fn pow2_ratio(target: f64, x: f64) -> f64 {
    if !(target > 0.0 && x > 0.0 && target.is_finite() && x.is_finite()) {
        return 1.0;
    }
    let k = (target / x).log2().round().clamp(-1000.0, 1000.0);
    2f64.powi(k as i32)
}

/// `True` when every gap is clear, otherwise `Unknown`.
pub(crate) fn all_clear(gaps: &[RankGap]) -> Truth {
    if gaps.iter().all(|g| g.truth == Truth::True) {
        Truth::True
    } else {
        Truth::Unknown
    }
}

/// A float scalar of the backend: `f64`, or `Complex<f64>` for systems over a non-real
/// field such as $\mathbb{Q}(i)$. The generic routines ([`era`], [`freqresp`],
/// [`markov_parameters`]) are written once for both; the rank-revealing staircases stay real
/// and see a complex matrix through its real form [`FloatScalar::realify`], whose singular
/// values are those of the complex matrix, each twice.
pub trait FloatScalar: nalgebra::ComplexField<RealField = f64> + Copy {
    /// The real form of `m`: `m` itself for `f64`; for a complex `M = X + iY` the
    /// `2r x 2c` matrix $\begin{bmatrix} X & -Y \\ Y & X \end{bmatrix}$ (a ring
    /// homomorphism: ranks double, eigenvalues are those of $M$ and $\bar M$).
    fn realify(m: &DMatrix<Self>) -> DMatrix<f64>;
}

impl FloatScalar for f64 {
    fn realify(m: &DMatrix<f64>) -> DMatrix<f64> {
        m.clone()
    }
}

impl FloatScalar for num_complex::Complex<f64> {
    fn realify(m: &DMatrix<Self>) -> DMatrix<f64> {
        let (r, c) = m.shape();
        DMatrix::from_fn(2 * r, 2 * c, |i, j| {
            let z = m[(i % r.max(1), j % c.max(1))];
            match (i < r, j < c) {
                (true, true) | (false, false) => z.re,
                (true, false) => -z.im,
                (false, true) => z.im,
            }
        })
    }
}

/// Checks the shapes of `(A, B, C, D)` and that all entries are finite; returns `(n, m, p)`.
pub(crate) fn check_system<T: FloatScalar>(
    op: &'static str,
    a: &DMatrix<T>,
    b: &DMatrix<T>,
    c: &DMatrix<T>,
    d: &DMatrix<T>,
) -> Result<(usize, usize, usize)> {
    check_square(op, a)?;
    let n = a.nrows();
    let m = b.ncols();
    let p = c.nrows();
    if b.nrows() != n {
        return Err(Error::Shape {
            op,
            expected: (n, m),
            found: b.shape(),
        });
    }
    if c.ncols() != n {
        return Err(Error::Shape {
            op,
            expected: (p, n),
            found: c.shape(),
        });
    }
    if d.shape() != (p, m) {
        return Err(Error::Shape {
            op,
            expected: (p, m),
            found: d.shape(),
        });
    }
    for mat in [a, b, c, d] {
        check_finite(op, mat)?;
    }
    Ok((n, m, p))
}

/// Errors unless `a` is square with finite entries.
pub(crate) fn check_square<T: FloatScalar>(op: &'static str, a: &DMatrix<T>) -> Result<()> {
    if a.nrows() != a.ncols() {
        return Err(Error::NotSquare {
            op,
            nrows: a.nrows(),
            ncols: a.ncols(),
        });
    }
    check_finite(op, a)
}

/// Errors if some entry is NaN or infinite.
pub(crate) fn check_finite<T: FloatScalar>(op: &'static str, a: &DMatrix<T>) -> Result<()> {
    if a.iter().all(|x| x.is_finite()) {
        Ok(())
    } else {
        Err(Error::Invalid(format!(
            "{op}: matrix has a non-finite entry"
        )))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decide_rank_cases() {
        let tol = Tol::default();
        let g = decide_rank("x", &[1.0, 1e-16], 1.0, &tol);
        assert_eq!((g.rank, g.truth), (1, Truth::True));
        let g = decide_rank("x", &[1.0, 1e-7], 1.0, &tol);
        assert_eq!((g.rank, g.truth), (2, Truth::Unknown));
        let g = decide_rank("x", &[1.0, 1e-9], 1.0, &tol);
        assert_eq!((g.rank, g.truth), (1, Truth::Unknown));
        let g = decide_rank("x", &[1.0, 1e-12], 1.0, &tol);
        assert_eq!((g.rank, g.truth), (1, Truth::True));
        let g = decide_rank("x", &[0.0, 0.0], 0.0, &tol);
        assert_eq!((g.rank, g.truth), (0, Truth::True));
        let g = decide_rank("x", &[], 0.0, &tol);
        assert_eq!((g.rank, g.truth), (0, Truth::True));
        let g = decide_rank("x", &[3.0, 0.5], 3.0, &tol);
        assert_eq!((g.rank, g.truth), (2, Truth::True));
    }

    #[test]
    fn truth_and() {
        assert_eq!(Truth::True.and(Truth::Unknown), Truth::Unknown);
        assert_eq!(Truth::Unknown.and(Truth::False), Truth::False);
        assert_eq!(Truth::True.and(Truth::True), Truth::True);
    }
}
