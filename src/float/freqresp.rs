//! Float frequency response.
//!
//! $G(j\omega) = C (j\omega I - A)^{-1} B + D$ at $\omega = 2\pi f$ for each frequency $f$
//! in hertz, one complex LU factorisation of $j\omega I - A$ per frequency ($O(n^3)$ each).
//!
//! | entry point  | returns                               |
//! |--------------|---------------------------------------|
//! | [`freqresp`] | one `p x m` complex matrix per frequency |
//! | [`freqresp_descriptor`] | the same for $E\dot x = Ax + Bu$: $C(j\omega E - A)^{-1}B + D$ on the pencil |

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
    freqresp_pencil(None, a, b, c, d, freqs_hz, None)
}

/// The frequency response of a discrete-time system with sample time `dt` (seconds) on the
/// unit circle: $G(e^{j 2 \pi f T}) = C (e^{j\omega T} I - A)^{-1} B + D$ at each `f` (Hz,
/// up to the Nyquist frequency $1/(2T)$ for the distinct values).
///
/// # Examples
/// ```
/// use exactlti::float::freqresp_sampled;
/// use nalgebra::DMatrix;
/// use num_complex::Complex;
/// // G(z) = 1 / (z - 1/2): G(1) = 2 at f = 0, G(-1) = -2/3 at the Nyquist frequency.
/// let m = |x: f64| DMatrix::from_element(1, 1, Complex::new(x, 0.0));
/// let g = freqresp_sampled(&m(0.5), &m(1.0), &m(1.0), &m(0.0), &[0.0, 5.0], 0.1).unwrap();
/// assert!((g[0][(0, 0)] - Complex::new(2.0, 0.0)).norm() < 1e-15);
/// assert!((g[1][(0, 0)] - Complex::new(-2.0 / 3.0, 0.0)).norm() < 1e-12);
/// ```
///
/// # Errors
/// As [`freqresp`]; `Invalid` for a sample time that is not finite and positive.
pub fn freqresp_sampled(
    a: &DMatrix<Complex<f64>>,
    b: &DMatrix<Complex<f64>>,
    c: &DMatrix<Complex<f64>>,
    d: &DMatrix<Complex<f64>>,
    freqs_hz: &[f64],
    dt: f64,
) -> Result<Vec<DMatrix<Complex<f64>>>> {
    if !(dt.is_finite() && dt > 0.0) {
        return Err(Error::Invalid(
            "freqresp: the sample time must be > 0".into(),
        ));
    }
    freqresp_pencil(None, a, b, c, d, freqs_hz, Some(dt))
}

/// The frequency response of a descriptor system $E\dot x = Ax + Bu$, $y = Cx + Du$,
/// evaluated on the pencil: $G(j\omega) = C(j\omega E - A)^{-1}B + D$, one complex LU
/// factorisation of $j\omega E - A$ per frequency. No standard form is formed, so a badly
/// scaled conversion ($E^{-1}$ or a Weierstrass basis) cannot spoil the values.
///
/// # Examples
/// ```
/// use exactlti::float::freqresp_descriptor;
/// use nalgebra::DMatrix;
/// use num_complex::Complex;
/// // 2 x' = -x + u: G(s) = 1 / (2s + 1), G(0) = 1.
/// let z = |x: f64| DMatrix::from_element(1, 1, Complex::new(x, 0.0));
/// let g = freqresp_descriptor(&z(2.0), &z(-1.0), &z(1.0), &z(1.0), &z(0.0), &[0.0]).unwrap();
/// assert!((g[0][(0, 0)] - Complex::new(1.0, 0.0)).norm() < 1e-15);
/// ```
///
/// # Errors
/// As [`freqresp`]; [`Error::Shape`] when `E` is not `n x n`; [`Error::Singular`] at a
/// finite eigenvalue of the pencil (or for a singular pencil).
pub fn freqresp_descriptor(
    e: &DMatrix<Complex<f64>>,
    a: &DMatrix<Complex<f64>>,
    b: &DMatrix<Complex<f64>>,
    c: &DMatrix<Complex<f64>>,
    d: &DMatrix<Complex<f64>>,
    freqs_hz: &[f64],
) -> Result<Vec<DMatrix<Complex<f64>>>> {
    if e.shape() != a.shape() {
        return Err(Error::Shape {
            op: "freqresp E",
            expected: a.shape(),
            found: e.shape(),
        });
    }
    if e.iter().any(|z| !z.re.is_finite() || !z.im.is_finite()) {
        return Err(Error::Invalid("freqresp: non-finite entry in E".into()));
    }
    freqresp_pencil(Some(e), a, b, c, d, freqs_hz, None)
}

/// $C(j\omega E - A)^{-1}B + D$ with $E = I$ when `e` is `None`; with a sample time `dt`
/// the point is $e^{j\omega T}$ instead of $j\omega$.
fn freqresp_pencil(
    e: Option<&DMatrix<Complex<f64>>>,
    a: &DMatrix<Complex<f64>>,
    b: &DMatrix<Complex<f64>>,
    c: &DMatrix<Complex<f64>>,
    d: &DMatrix<Complex<f64>>,
    freqs_hz: &[f64],
    dt: Option<f64>,
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
        let w = 2.0 * std::f64::consts::PI * f;
        let jw = match dt {
            None => Complex::new(0.0, w),
            Some(t) => Complex::new(0.0, w * t).exp(),
        };
        let m = match e {
            Some(e) => e * jw - a,
            None => {
                let mut m = -a;
                for i in 0..n {
                    m[(i, i)] += jw;
                }
                m
            }
        };
        let x = LU::new(m).solve(b).ok_or(Error::Singular)?;
        if x.iter().any(|z| !z.re.is_finite() || !z.im.is_finite()) {
            return Err(Error::Singular);
        }
        out.push(c * x + d);
    }
    Ok(out)
}
