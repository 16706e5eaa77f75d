//! Float frequency response.
//!
//! $G(j\omega) = C (j\omega I - A)^{-1} B + D$ at $\omega = 2\pi f$ for each frequency $f$
//! in hertz, one complex LU factorisation of $j\omega I - A$ per frequency ($O(n^3)$ each).
//!
//! | entry point  | returns                               |
//! |--------------|---------------------------------------|
//! | [`freqresp`] | one `p x m` complex matrix per frequency (real or complex $A, B, C, D$; continuous or sampled) |
//! | [`freqresp_descriptor`] | the same for $E\dot x = Ax + Bu$: $C(j\omega E - A)^{-1}B + D$ on the pencil |

use nalgebra::DMatrix;
use nalgebra::linalg::LU;
use num_complex::Complex;

use super::{FloatScalar, check_system};
use crate::error::{Error, Result};

/// The frequency response at the frequencies `freqs_hz` (hertz): $G(j\omega)$ in continuous
/// time (`dt` is `None`), $G(e^{j\omega T})$ on the unit circle for a discrete-time system with
/// sample time `dt = Some(T)` (seconds; up to the Nyquist frequency $1/(2T)$ for the distinct
/// values). Written once for real and complex matrices ([`super::FloatScalar`]): a complex
/// system (e.g. over $\mathbb{Q}(i)$) has a response that is not conjugate-symmetric,
/// $G(-j\omega) \ne \overline{G(j\omega)}$ in general, so negative frequencies are allowed.
///
/// # Examples
/// ```
/// use exactlti::float::freqresp;
/// use nalgebra::DMatrix;
/// use num_complex::Complex;
/// // G(s) = 1 / (s + 1): |G(0)| = 1.
/// let one = DMatrix::from_element(1, 1, 1.0);
/// let g = freqresp([&(-&one), &one, &one, &DMatrix::zeros(1, 1)], &[0.0], None).unwrap();
/// assert!((g[0][(0, 0)].re - 1.0).abs() < 1e-15);
/// // G(s) = 1 / (s - i): at f = -1/(2 pi) Hz, s = -i and G = 1/(-2i) = i/2.
/// let i = DMatrix::from_element(1, 1, Complex::new(0.0, 1.0));
/// let one = DMatrix::from_element(1, 1, Complex::new(1.0, 0.0));
/// let f = -1.0 / (2.0 * std::f64::consts::PI);
/// let g = freqresp([&i, &one, &one, &DMatrix::zeros(1, 1)], &[f], None).unwrap();
/// assert!((g[0][(0, 0)] - Complex::new(0.0, 0.5)).norm() < 1e-15);
/// // G(z) = 1 / (z - 1/2), T = 0.1: G(1) = 2 at f = 0, G(-1) = -2/3 at the Nyquist frequency.
/// let m = |x: f64| DMatrix::from_element(1, 1, x);
/// let g = freqresp([&m(0.5), &m(1.0), &m(1.0), &m(0.0)], &[0.0, 5.0], Some(0.1)).unwrap();
/// assert!((g[0][(0, 0)] - Complex::new(2.0, 0.0)).norm() < 1e-15);
/// assert!((g[1][(0, 0)] - Complex::new(-2.0 / 3.0, 0.0)).norm() < 1e-12);
/// ```
///
/// # Errors
/// Shape errors and non-finite entries as [`super::minreal`]; [`Error::Invalid`] for a
/// non-finite frequency or a sample time that is not finite and positive;
/// [`Error::Singular`] when $j\omega$ (or $e^{j\omega T}$) is an eigenvalue of $A$.
pub fn freqresp<T: FloatScalar>(
    [a, b, c, d]: [&DMatrix<T>; 4],
    freqs_hz: &[f64],
    dt: Option<f64>,
) -> Result<Vec<DMatrix<Complex<f64>>>> {
    if dt.is_some_and(|t| !(t.is_finite() && t > 0.0)) {
        return Err(Error::Invalid(
            "freqresp: the sample time must be > 0".into(),
        ));
    }
    check_system("freqresp", a, b, c, d)?;
    let z = |m: &DMatrix<T>| m.map(|x| Complex::new(x.real(), x.imaginary()));
    freqresp_pencil(None, [&z(a), &z(b), &z(c), &z(d)], freqs_hz, dt)
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
/// let g = freqresp_descriptor(&z(2.0), [&z(-1.0), &z(1.0), &z(1.0), &z(0.0)], &[0.0]).unwrap();
/// assert!((g[0][(0, 0)] - Complex::new(1.0, 0.0)).norm() < 1e-15);
/// ```
///
/// # Errors
/// As [`freqresp`]; [`Error::Shape`] when `E` is not `n x n`; [`Error::Singular`] at a
/// finite eigenvalue of the pencil (or for a singular pencil).
pub fn freqresp_descriptor(
    e: &DMatrix<Complex<f64>>,
    abcd: [&DMatrix<Complex<f64>>; 4],
    freqs_hz: &[f64],
) -> Result<Vec<DMatrix<Complex<f64>>>> {
    let a = abcd[0];
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
    freqresp_pencil(Some(e), abcd, freqs_hz, None)
}

/// $C(j\omega E - A)^{-1}B + D$ with $E = I$ when `e` is `None`; with a sample time `dt`
/// the point is $e^{j\omega T}$ instead of $j\omega$.
fn freqresp_pencil(
    e: Option<&DMatrix<Complex<f64>>>,
    [a, b, c, d]: [&DMatrix<Complex<f64>>; 4],
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
