//! Float eigenvalues and eigenvectors.
//!
//! Eigenvalues are those of $D^{-1} A D$ (Parlett-Reinsch balancing, a diagonal similarity that
//! leaves them unchanged), reduced to Hessenberg form $H = Q^T (D^{-1}AD) Q$ and read off by the
//! double-shift QR iteration with exceptional shifts ([`super::hqr`], LAPACK's `dlahqr`).
//! Eigenvectors come from inverse iteration: $(A - \lambda I) x_{k+1} = x_k$, normalised.
//!
//! | entry point      | returns                                         | cost          |
//! |------------------|-------------------------------------------------|---------------|
//! | [`eigenvalues`]  | eigenvalues sorted by (real part, imaginary part) | $O(n^3)$    |
//! | [`eigenvectors`] | eigenvalues and unit eigenvectors as columns    | $O(n^4)$      |

use nalgebra::DMatrix;
use nalgebra::linalg::{Hessenberg, LU, balancing};
use num_complex::Complex;

use super::check_square;
use crate::error::{Error, Result};

/// The eigenvalues of `a`, sorted by real part and then imaginary part (ascending).
///
/// Conjugate pairs are exact conjugates. Multiple eigenvalues come out scattered (a Jordan
/// block of size $k$ by about $(\varepsilon\lVert A\rVert)^{1/k}$); see
/// [`super::jordan_guess`] for the structure.
///
/// # Errors
/// [`Error::NotSquare`] for a non-square `a`, [`Error::Invalid`] for a non-finite entry,
/// [`Error::Limit`] when the QR iteration does not converge (a block needing more than
/// $30\max(10, n)$ steps; not seen with the exceptional shifts).
pub fn eigenvalues(a: &DMatrix<f64>) -> Result<Vec<Complex<f64>>> {
    check_square("eigenvalues", a)?;
    let n = a.nrows();
    if n == 0 {
        return Ok(Vec::new());
    }
    // Scale by a power of two (exact; eigenvalues scale with it) so that the largest entry is
    // about 1: squares of entries near 1e300 overflow and stall the balancing loop.
    let amax = a.amax();
    let s = super::pow2_ratio(1.0, amax);
    let mut m = a * s;
    balancing::balance_parlett_reinsch(&mut m);
    let h = Hessenberg::new(m).h();
    let mut ev: Vec<Complex<f64>> = super::hqr::hessenberg_eigenvalues(&h)
        .ok_or_else(|| Error::Limit("eigenvalues: QR iteration did not converge".into()))?
        .iter()
        .map(|z| z / s)
        .collect();
    sort_eigenvalues(&mut ev);
    Ok(ev)
}

/// Sorts by real part, then imaginary part, with a total order (deterministic).
pub(crate) fn sort_eigenvalues(ev: &mut [Complex<f64>]) {
    ev.sort_by(|x, y| x.re.total_cmp(&y.re).then(x.im.total_cmp(&y.im)));
}

/// Eigenvalues and eigenvectors (as columns), as returned by [`eigenvectors`].
pub type EigenPairs = (Vec<Complex<f64>>, DMatrix<Complex<f64>>);

/// Eigenvalues (as [`eigenvalues`]) and unit eigenvectors: column `i` of the matrix satisfies
/// $A v_i \approx \lambda_i v_i$.
///
/// Meant for the diagonalizable case: for a defective eigenvalue the columns of one cluster
/// are nearly parallel (use [`super::jordan_guess`] first).
///
/// # Algorithm
/// Two steps of inverse iteration per eigenvalue with a complex LU of $A - \lambda I$ (the
/// shift is nudged by $\varepsilon\lVert A\rVert$ when the LU is exactly singular).
///
/// # Errors
/// As [`eigenvalues`].
pub fn eigenvectors(a: &DMatrix<f64>) -> Result<EigenPairs> {
    let ev = eigenvalues(a)?;
    let n = a.nrows();
    let ac: DMatrix<Complex<f64>> = a.map(|x| Complex::new(x, 0.0));
    let norm = a.norm().max(f64::MIN_POSITIVE);
    let mut v = DMatrix::<Complex<f64>>::zeros(n, n);
    for (j, &lam) in ev.iter().enumerate() {
        let x = inverse_iteration(&ac, lam, norm, j)?;
        v.set_column(j, &x);
    }
    Ok((ev, v))
}

/// Unit vector `x` with `(A - lam I) x ≈ 0`, by inverse iteration from a fixed start.
fn inverse_iteration(
    ac: &DMatrix<Complex<f64>>,
    lam: Complex<f64>,
    norm: f64,
    salt: usize,
) -> Result<nalgebra::DVector<Complex<f64>>> {
    let n = ac.nrows();
    // A deterministic start vector with no special structure.
    let mut x = nalgebra::DVector::<Complex<f64>>::from_fn(n, |i, _| {
        let t = ((i * 7919 + salt * 104_729) % 1009) as f64 / 1009.0;
        Complex::new(1.0 + t, 0.5 - t)
    });
    let mut shift = lam;
    for attempt in 0..8 {
        let mut m = ac.clone();
        for i in 0..n {
            m[(i, i)] -= shift;
        }
        let lu = LU::new(m);
        let mut ok = true;
        for _ in 0..2 {
            match lu.solve(&x) {
                Some(y) if y.iter().all(|z| z.re.is_finite() && z.im.is_finite()) => {
                    let nrm = y.norm();
                    if nrm == 0.0 {
                        ok = false;
                        break;
                    }
                    x = y / Complex::new(nrm, 0.0);
                }
                _ => {
                    ok = false;
                    break;
                }
            }
        }
        if ok {
            // Fix the phase: largest entry real positive.
            let (imax, _) = x.iter().enumerate().fold((0, -1.0), |acc, (i, z)| {
                if z.norm() > acc.1 { (i, z.norm()) } else { acc }
            });
            let ph = x[imax] / Complex::new(x[imax].norm(), 0.0);
            return Ok(x.map(|z| z / ph));
        }
        let nudge = f64::EPSILON * norm * 4f64.powi(attempt + 1);
        shift = lam + Complex::new(nudge, nudge);
    }
    Err(Error::Limit(
        "eigenvectors: inverse iteration failed".to_string(),
    ))
}
