//! Float invariant zeros of the Rosenbrock system matrix.
//!
//! The invariant zeros are the $s$ where $P(s) = \begin{bmatrix} A - sI & B \\ C & D
//! \end{bmatrix}$ loses rank below its normal rank. Following Emami-Naeini and Van Dooren
//! (1982), orthogonal compressions reduce the system without changing the finite zeros:
//!
//! 1. compress the rows of $D$: $U^T[C\ D] = \begin{bmatrix} C_\sigma & 0 \\ C_\rho & D_\rho
//!    \end{bmatrix}$ with $D_\rho$ of full row rank;
//! 2. compress the columns of $C_\sigma$: $C_\sigma W = [0\ \ C_\mu]$, $C_\mu$ of full column
//!    rank $\mu$. Those rows force $x_2 = 0$ (the last $\mu$ states of $x = W [x_1; x_2]$), so
//!    unimodular row operations remove $x_2$, the rows that fixed it, and the zero rows, leaving
//!    $$\left(A_{11},\ B_1,\ \begin{bmatrix} A_{21} \\ C_{\rho 1}\end{bmatrix},\
//!    \begin{bmatrix} B_2 \\ D_\rho \end{bmatrix}\right)$$
//!    with $n - \mu$ states;
//! 3. repeat until $D$ has full row rank, then do the same on the dual
//!    $(A^T, C^T, B^T, D^T)$, alternating until $D$ is square and invertible.
//!
//! The zeros are then the eigenvalues of $A - B D^{-1} C$ of the reduced system.
//!
//! | entry point                 | returns                               |
//! |-----------------------------|---------------------------------------|
//! | [`invariant_zeros`]         | the zeros, sorted as eigenvalues      |
//! | [`invariant_zeros_report`]  | [`FloatZeros`] with the rank decisions |

use nalgebra::DMatrix;
use nalgebra::linalg::LU;
use num_complex::Complex;

use super::svd::{left_basis, right_basis};
use super::{RankGap, Tol, Truth, all_clear, check_system, decide_rank, eigenvalues, pow2_ratio};
use crate::error::{Error, Result};

/// Invariant zeros with diagnostics.
#[derive(Clone, Debug, PartialEq)]
pub struct FloatZeros {
    /// The finite invariant zeros, sorted by real part then imaginary part.
    pub zeros: Vec<Complex<f64>>,
    /// Number of states of the reduced system (= number of finite zeros).
    pub reduced_order: usize,
    /// `True` when every rank decision had a clear gap.
    pub truth: Truth,
    /// The rank decisions of the reduction.
    pub gaps: Vec<RankGap>,
}

/// The finite invariant zeros of `(a, b, c, d)`; see [`invariant_zeros_report`].
///
/// # Examples
/// ```
/// use exactlti::float::{invariant_zeros, Tol};
/// use nalgebra::DMatrix;
/// // G(s) = (s + 1) / (s^2 + 3 s + 2): a zero at -1.
/// let a = DMatrix::from_row_slice(2, 2, &[0.0, 1.0, -2.0, -3.0]);
/// let b = DMatrix::from_row_slice(2, 1, &[0.0, 1.0]);
/// let c = DMatrix::from_row_slice(1, 2, &[1.0, 1.0]);
/// let z = invariant_zeros(&a, &b, &c, &DMatrix::zeros(1, 1), &Tol::default()).unwrap();
/// assert_eq!(z.len(), 1);
/// assert!((z[0].re + 1.0).abs() < 1e-12 && z[0].im == 0.0);
/// ```
///
/// # Errors
/// As [`invariant_zeros_report`].
pub fn invariant_zeros(
    a: &DMatrix<f64>,
    b: &DMatrix<f64>,
    c: &DMatrix<f64>,
    d: &DMatrix<f64>,
    tol: &Tol,
) -> Result<Vec<Complex<f64>>> {
    Ok(invariant_zeros_report(a, b, c, d, tol)?.zeros)
}

/// The finite invariant zeros of `(a, b, c, d)` with the rank decisions that produced them.
///
/// # Errors
/// Shape errors and non-finite entries as [`super::minreal`]; [`Error::Limit`] if the final
/// eigenvalue problem does not converge.
pub fn invariant_zeros_report(
    a: &DMatrix<f64>,
    b: &DMatrix<f64>,
    c: &DMatrix<f64>,
    d: &DMatrix<f64>,
    tol: &Tol,
) -> Result<FloatZeros> {
    check_system("invariant_zeros", a, b, c, d)?;
    // The zeros of (A, αB, βC, βDα) are those of (A, B, C, D): scale B and C to the size of
    // A by exact powers of two so that one threshold fits every block.
    let alpha = pow2_ratio(a.norm(), b.norm());
    let beta = pow2_ratio(a.norm(), c.norm());
    let mut sys = Sys {
        a: a.clone(),
        b: b * alpha,
        c: c * beta,
        d: d * (alpha * beta),
    };
    let scale =
        (sys.a.norm_squared() + sys.b.norm_squared() + sys.c.norm_squared() + sys.d.norm_squared())
            .sqrt();
    let mut gaps = Vec::new();
    loop {
        let changed = reduce(&mut sys, scale, tol, &mut gaps, "");
        let mut dual = sys.transposed();
        let changed_dual = reduce(&mut dual, scale, tol, &mut gaps, "dual ");
        sys = dual.transposed();
        if !changed && !changed_dual {
            break;
        }
    }
    let n = sys.a.nrows();
    let zeros = if n == 0 {
        Vec::new()
    } else if sys.d.nrows() == 0 {
        eigenvalues(&sys.a)?
    } else if !sys.d.is_square() {
        return Err(Error::Verification(format!(
            "invariant_zeros: the reduced D is {}x{}, not square",
            sys.d.nrows(),
            sys.d.ncols()
        )));
    } else {
        let lu = LU::new(sys.d.clone());
        let x = lu
            .solve(&sys.c)
            .ok_or_else(|| Error::Verification("invariant_zeros: reduced D is singular".into()))?;
        eigenvalues(&(&sys.a - &sys.b * x))?
    };
    Ok(FloatZeros {
        zeros,
        reduced_order: n,
        truth: all_clear(&gaps),
        gaps,
    })
}

#[derive(Clone, Debug)]
struct Sys {
    a: DMatrix<f64>,
    b: DMatrix<f64>,
    c: DMatrix<f64>,
    d: DMatrix<f64>,
}

impl Sys {
    fn transposed(&self) -> Sys {
        Sys {
            a: self.a.transpose(),
            b: self.c.transpose(),
            c: self.b.transpose(),
            d: self.d.transpose(),
        }
    }
}

/// One primal reduction to full row rank `D`; returns whether anything changed.
fn reduce(sys: &mut Sys, scale: f64, tol: &Tol, gaps: &mut Vec<RankGap>, tag: &str) -> bool {
    let mut changed = false;
    loop {
        let n = sys.a.nrows();
        let p = sys.d.nrows();
        if p == 0 {
            return changed;
        }
        let (sv, u) = left_basis(&sys.d);
        let g = decide_rank(&format!("{tag}rank D ({p} rows)"), &sv, scale, tol);
        let rho = g.rank;
        gaps.push(g);
        if rho == p {
            return changed;
        }
        changed = true;
        let sig = p - rho;
        // Rows: first the σ rows where D vanishes, then the ρ rows of D_ρ.
        let mut perm = DMatrix::<f64>::zeros(p, p);
        perm.columns_mut(0, sig).copy_from(&u.columns(rho, sig));
        perm.columns_mut(sig, rho).copy_from(&u.columns(0, rho));
        let cn = perm.transpose() * &sys.c;
        let dn = perm.transpose() * &sys.d;
        let c_sig = cn.rows(0, sig).into_owned();
        let c_rho = cn.rows(sig, rho).into_owned();
        let d_rho = dn.rows(sig, rho).into_owned();
        if n == 0 {
            sys.c = c_rho;
            sys.d = d_rho;
            continue;
        }
        // Column compression of C_σ: W = [null-space directions, range directions].
        let (svc, v) = right_basis(&c_sig);
        let gc = decide_rank(&format!("{tag}rank C_sigma ({sig} rows)"), &svc, scale, tol);
        let mu = gc.rank;
        gaps.push(gc);
        if mu == 0 {
            sys.c = c_rho;
            sys.d = d_rho;
            continue;
        }
        let mut w = DMatrix::<f64>::zeros(n, n);
        w.columns_mut(0, n - mu).copy_from(&v.columns(mu, n - mu));
        w.columns_mut(n - mu, mu).copy_from(&v.columns(0, mu));
        let at = w.transpose() * &sys.a * &w;
        let bt = w.transpose() * &sys.b;
        let ct = &c_rho * &w;
        let n1 = n - mu;
        let m = sys.b.ncols();
        let mut c_new = DMatrix::<f64>::zeros(mu + rho, n1);
        c_new.rows_mut(0, mu).copy_from(&at.view((n1, 0), (mu, n1)));
        c_new.rows_mut(mu, rho).copy_from(&ct.columns(0, n1));
        let mut d_new = DMatrix::<f64>::zeros(mu + rho, m);
        d_new.rows_mut(0, mu).copy_from(&bt.rows(n1, mu));
        d_new.rows_mut(mu, rho).copy_from(&d_rho);
        sys.a = at.view((0, 0), (n1, n1)).into_owned();
        sys.b = bt.rows(0, n1).into_owned();
        sys.c = c_new;
        sys.d = d_new;
    }
}
