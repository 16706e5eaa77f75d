//! Finite eigenvalues of a regular pencil $sE - A$ in floating point, when their number
//! $r = \deg \det(sE - A)$ is known exactly (from the exact path), without QZ: shift and
//! invert.
//!
//! For a shift $\sigma$ with $\sigma E - A$ invertible,
//! $(\lambda E - A)x = 0 \iff (\sigma E - A)^{-1} E\,x = \mu x$ with
//! $\mu = 1/(\sigma - \lambda)$, and the infinite eigenvalues are $\mu = 0$. So the finite
//! eigenvalues are $\lambda = \sigma - 1/\mu$ for the $r$ eigenvalues $\mu$ of largest
//! modulus of $M = (\sigma E - A)^{-1}E$ ([`eigenvalues`]: balanced real Schur). Because
//! $r$ is exact, no tolerance decides which $\mu$ are zero.
//!
//! The shift is chosen among six irrational multiples of the scale
//! $\lVert A\rVert_F / \lVert E\rVert_F$ (three of each sign): the one with the least
//! $|\sigma|\,\lVert M\rVert_F$, i.e. the farthest from the spectrum relative to its size.
//! Accuracy: a simple eigenvalue moves by about
//! $\varepsilon \lVert M\rVert\,|\sigma - \lambda|^2$ times its condition number; an
//! infinite eigenvalue in a block of size $k$ spreads to $|\mu| \approx
//! (\varepsilon\lVert M\rVert)^{1/k}$, which only a finite $\lambda$ with
//! $|\sigma - \lambda| \gtrsim (\varepsilon\lVert M\rVert)^{-1/k}$ could be confused with.

use nalgebra::DMatrix;
use num_complex::Complex;

use super::{check_square, eigenvalues};
use crate::error::{Error, Result};

/// Multipliers of the scale tried as shifts.
const SHIFTS: [f64; 6] = [
    0.618_033_988_749_895,
    -0.754_877_666_246_693,
    1.324_717_957_244_746,
    -1.465_571_231_876_768,
    0.381_966_011_250_105,
    -2.205_569_430_400_59,
];

/// The `r` finite eigenvalues of the regular pencil $sE - A$, sorted by (real, imaginary)
/// part (see the module docs).
///
/// # Errors
/// `NotSquare`/`Shape` for matrices that are not square of one size, `Invalid` for
/// $r > n$ or a non-finite entry, `Singular` when every shift leaves $\sigma E - A$
/// singular (a singular pencil, or $E = 0$ with $r > 0$).
pub fn pencil_finite_eigenvalues(
    e: &DMatrix<f64>,
    a: &DMatrix<f64>,
    r: usize,
) -> Result<Vec<Complex<f64>>> {
    check_square("pencil eigenvalues", a)?;
    let n = a.nrows();
    if e.shape() != a.shape() {
        return Err(Error::Shape {
            op: "pencil eigenvalues",
            expected: a.shape(),
            found: e.shape(),
        });
    }
    if r > n {
        return Err(Error::Invalid(format!(
            "{r} finite eigenvalues asked of a pencil of order {n}"
        )));
    }
    if !a.iter().chain(e.iter()).all(|x| x.is_finite()) {
        return Err(Error::Invalid("a non-finite entry in the pencil".into()));
    }
    if r == 0 {
        return Ok(vec![]);
    }
    let (ne, na) = (e.norm(), a.norm());
    if ne == 0.0 {
        return Err(Error::Singular);
    }
    let scale = if na > 0.0 { na / ne } else { 1.0 };
    let mut best: Option<(f64, f64, DMatrix<f64>)> = None;
    for c in SHIFTS {
        let sigma = c * scale;
        let Some(m) = (e * sigma - a).lu().solve(e) else {
            continue;
        };
        if !m.iter().all(|x| x.is_finite()) {
            continue;
        }
        let score = sigma.abs() * m.norm();
        if best.as_ref().is_none_or(|b| score < b.0) {
            best = Some((score, sigma, m));
        }
    }
    let (_, sigma, m) = best.ok_or(Error::Singular)?;
    let mut mu = eigenvalues(&m)?;
    mu.sort_by(|x, y| y.norm().total_cmp(&x.norm()));
    if mu[r - 1].norm() == 0.0 {
        return Err(Error::Singular);
    }
    let mut out: Vec<Complex<f64>> = mu[..r]
        .iter()
        .map(|u| Complex::new(sigma, 0.0) - u.inv())
        .collect();
    out.sort_by(|x, y| x.re.total_cmp(&y.re).then(x.im.total_cmp(&y.im)));
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn index_one_and_index_two_pencils() {
        // E = diag(1, 1, 0), A = [[0, 1, 0], [-2, -3, 0], [0, 0, 1]]: finite -1, -2
        let e = DMatrix::from_row_slice(3, 3, &[1., 0., 0., 0., 1., 0., 0., 0., 0.]);
        let a = DMatrix::from_row_slice(3, 3, &[0., 1., 0., -2., -3., 0., 0., 0., 1.]);
        let ev = pencil_finite_eigenvalues(&e, &a, 2).unwrap();
        assert!((ev[0].re + 2.0).abs() < 1e-12 && (ev[1].re + 1.0).abs() < 1e-12);
        // a nilpotent block of size 2 beside the finite eigenvalue 5
        let e = DMatrix::from_row_slice(3, 3, &[1., 0., 0., 0., 0., 1., 0., 0., 0.]);
        let a = DMatrix::from_row_slice(3, 3, &[5., 0., 0., 0., 1., 0., 0., 0., 1.]);
        let ev = pencil_finite_eigenvalues(&e, &a, 1).unwrap();
        assert!((ev[0].re - 5.0).abs() < 1e-12 && ev[0].im == 0.0, "{ev:?}");
        assert!(pencil_finite_eigenvalues(&e, &a, 4).is_err());
        // singular pencil: E = A = diag(1, 0)
        let z = DMatrix::from_row_slice(2, 2, &[1., 0., 0., 0.]);
        assert!(matches!(
            pencil_finite_eigenvalues(&z, &z, 1),
            Err(Error::Singular)
        ));
    }
}
