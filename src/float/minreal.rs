//! Float minimal realization by two orthogonal staircases.
//!
//! $G(s) = C(sI - A)^{-1}B + D$ is unchanged by an orthogonal similarity and by dropping the
//! uncontrollable trailing block of the controllability staircase; applying the same to the
//! dual $(A^T, C^T, B^T)$ of the controllable part drops the unobservable states. The result
//! is controllable and observable up to the rank decisions (reported as [`RankGap`]s), so its
//! order is the numerical McMillan degree. The algorithm is that of SLICOT TB01PD (without
//! its optional balancing): $O(n^3)$ flops, no Krylov matrices.
//!
//! | entry point | returns          |
//! |-------------|------------------|
//! | [`minreal`] | [`FloatMinreal`] |

use nalgebra::DMatrix;

use super::staircase::controllable_staircase;
use super::{RankGap, Tol, Truth, all_clear, check_system, pow2_ratio};
use crate::error::Result;

/// A float minimal realization with its diagnostics.
#[derive(Clone, Debug, PartialEq)]
pub struct FloatMinreal {
    /// State matrix of the minimal part (`order x order`).
    pub a: DMatrix<f64>,
    /// Input matrix (`order x m`).
    pub b: DMatrix<f64>,
    /// Output matrix (`p x order`).
    pub c: DMatrix<f64>,
    /// Feedthrough (unchanged).
    pub d: DMatrix<f64>,
    /// The numerical McMillan degree.
    pub order: usize,
    /// Order of the controllable part found first.
    pub controllable_order: usize,
    /// `True` when every rank decision had a clear gap; never a proof.
    pub truth: Truth,
    /// All rank decisions (controllability steps, then observability steps).
    pub gaps: Vec<RankGap>,
}

/// Removes the uncontrollable and then the unobservable part of `(a, b, c, d)`.
///
/// The states of the result are `z` with `x = Q_1 Q_2 z` for orthogonal `Q_i` restricted to
/// the kept states (not returned).
///
/// # Examples
/// ```
/// use exactlti::float::{minreal, Tol, Truth};
/// use nalgebra::DMatrix;
/// // x2 is not reachable from u: order 1.
/// let a = DMatrix::from_row_slice(2, 2, &[-1.0, 0.0, 0.0, -2.0]);
/// let b = DMatrix::from_row_slice(2, 1, &[1.0, 0.0]);
/// let c = DMatrix::from_row_slice(1, 2, &[1.0, 1.0]);
/// let d = DMatrix::zeros(1, 1);
/// let r = minreal(&a, &b, &c, &d, &Tol::default()).unwrap();
/// assert_eq!((r.order, r.truth), (1, Truth::True));
/// assert!((r.a[(0, 0)] + 1.0).abs() < 1e-14);
/// ```
///
/// # Errors
/// [`crate::Error::NotSquare`] / [`crate::Error::Shape`] for inconsistent shapes,
/// [`crate::Error::Invalid`] for non-finite entries.
pub fn minreal(
    a: &DMatrix<f64>,
    b: &DMatrix<f64>,
    c: &DMatrix<f64>,
    d: &DMatrix<f64>,
    tol: &Tol,
) -> Result<FloatMinreal> {
    check_system("minreal", a, b, c, d)?;
    // Input and output scaling by powers of two (exact): the same transfer matrix up to
    // G -> β G α, undone on the result; one relative threshold then fits every block.
    let alpha = pow2_ratio(a.norm(), b.norm());
    let beta = pow2_ratio(a.norm(), c.norm());
    let mut a1 = a.clone();
    let mut b1 = b * alpha;
    let mut c1 = c * beta;
    let scale = a1.norm().max(b1.norm()).max(c1.norm());
    let st = controllable_staircase(&mut a1, &mut b1, &mut c1, scale, tol, "controllability");
    let nc = st.order;
    let mut gaps = st.gaps;
    // Dual of the controllable part.
    let mut at = a1.view((0, 0), (nc, nc)).transpose();
    let mut bt = c1.columns(0, nc).transpose();
    let mut ct = b1.rows(0, nc).transpose();
    let so = controllable_staircase(&mut at, &mut bt, &mut ct, scale, tol, "observability");
    let no = so.order;
    gaps.extend(so.gaps);
    Ok(FloatMinreal {
        a: at.view((0, 0), (no, no)).transpose(),
        b: ct.columns(0, no).transpose() / alpha,
        c: bt.rows(0, no).transpose() / beta,
        d: d.clone(),
        order: no,
        controllable_order: nc,
        truth: all_clear(&gaps),
        gaps,
    })
}
