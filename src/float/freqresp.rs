//! Float frequency response.
//!
//! $G(j\omega) = C (j\omega I - A)^{-1} B + D$ at $\omega = 2\pi f$ for each frequency $f$
//! in hertz, one complex LU factorisation of $j\omega I - A$ per frequency ($O(n^3)$ each).
//!
//! | entry point  | returns                               |
//! |--------------|---------------------------------------|
//! | [`freqresp`] | one `p x m` complex matrix per frequency |

use nalgebra::DMatrix;
use nalgebra::linalg::LU;
use num_complex::Complex;

use super::check_system;
use crate::error::{Error, Result};

/// The frequency response at the frequencies `freqs_hz` (hertz).
///
/// # Examples
/// ```
/// use exactlti::float::freqresp;
/// use nalgebra::DMatrix;
/// // G(s) = 1 / (s + 1): |G(0)| = 1.
/// let one = DMatrix::from_element(1, 1, 1.0);
/// let g = freqresp(&(-&one), &one, &one, &DMatrix::zeros(1, 1), &[0.0]).unwrap();
/// assert!((g[0][(0, 0)].re - 1.0).abs() < 1e-15);
/// ```
///
/// # Errors
/// Shape errors and non-finite entries as [`super::minreal`]; [`Error::Invalid`] for a
/// non-finite frequency; [`Error::Singular`] when $j\omega$ is an eigenvalue of $A$.
pub fn freqresp(
    a: &DMatrix<f64>,
    b: &DMatrix<f64>,
    c: &DMatrix<f64>,
    d: &DMatrix<f64>,
    freqs_hz: &[f64],
) -> Result<Vec<DMatrix<Complex<f64>>>> {
    check_system("freqresp", a, b, c, d)?;
    let z = |m: &DMatrix<f64>| m.map(|x| Complex::new(x, 0.0));
    freqresp_complex(&z(a), &z(b), &z(c), &z(d), freqs_hz)
}

/// The frequency response of a system with complex matrices (e.g. over $\mathbb{Q}(i)$),
/// at the frequencies `freqs_hz` (hertz; negative ones allowed). Its response is not
/// conjugate-symmetric: $G(-j\omega) \ne \overline{G(j\omega)}$ in general.
///
/// # Examples
/// ```
/// use exactlti::float::freqresp_complex;
/// use nalgebra::DMatrix;
/// use num_complex::Complex;
/// // G(s) = 1 / (s - i): at f = -1/(2 pi) Hz, s = -i and G = 1/(-2i) = i/2.
/// let i = DMatrix::from_element(1, 1, Complex::new(0.0, 1.0));
/// let one = DMatrix::from_element(1, 1, Complex::new(1.0, 0.0));
/// let f = -1.0 / (2.0 * std::f64::consts::PI);
/// let g = freqresp_complex(&i, &one, &one, &DMatrix::zeros(1, 1), &[f]).unwrap();
/// assert!((g[0][(0, 0)] - Complex::new(0.0, 0.5)).norm() < 1e-15);
/// ```
///
/// # Errors
/// As [`freqresp`].
pub fn freqresp_complex(
    a: &DMatrix<Complex<f64>>,
    b: &DMatrix<Complex<f64>>,
    c: &DMatrix<Complex<f64>>,
    d: &DMatrix<Complex<f64>>,
    freqs_hz: &[f64],
) -> Result<Vec<DMatrix<Complex<f64>>>> {
    let (n, _, _) = check_system("freqresp", a, b, c, d)?;
    if freqs_hz.iter().any(|f| !f.is_finite()) {
        return Err(Error::Invalid("freqresp: non-finite frequency".into()));
    }
    let mut out = Vec::with_capacity(freqs_hz.len());
    if n == 0 {
        // no finite dynamics: G = D (nalgebra's LU solve panics on 0 x 0)
        out.resize(freqs_hz.len(), d.clone());
        return Ok(out);
    }
    for &f in freqs_hz {
        let jw = Complex::new(0.0, 2.0 * std::f64::consts::PI * f);
        let mut m = -a;
        for i in 0..n {
            m[(i, i)] += jw;
        }
        let x = LU::new(m).solve(b).ok_or(Error::Singular)?;
        if x.iter().any(|z| !z.re.is_finite() || !z.im.is_finite()) {
            return Err(Error::Singular);
        }
        out.push(c * x + d);
    }
    Ok(out)
}
