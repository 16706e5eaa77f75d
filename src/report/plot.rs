//! Plots and tables of responses: the frequency response as CSV here, SVG plots in the
//! submodules (Bode magnitude and phase in [`bode`], pole-zero maps, parameter sweeps, time
//! responses).
//!
//! Hand-written SVG ([`svg`]) instead of a plotting crate: this keeps the dependency tree and
//! CI build small.

pub(crate) mod bode;
pub(crate) mod bode_grid;
pub(crate) mod pzmap;
pub mod svg;
pub mod sweep;
pub(crate) mod time;

use std::fmt::Write;

/// `response[k][i][j]` = $G_{ij}(j 2\pi f_k)$ as `(re, im)`.
pub type Response = Vec<Vec<Vec<(f64, f64)>>>;

/// The frequency response `G(j w_k)` (one complex matrix per frequency) as a [`Response`]
/// of `(re, im)` pairs.
pub fn response_table(resp: &[nalgebra::DMatrix<num_complex::Complex<f64>>]) -> Response {
    resp.iter()
        .map(|g| {
            (0..g.nrows())
                .map(|i| {
                    (0..g.ncols())
                        .map(|j| (g[(i, j)].re, g[(i, j)].im))
                        .collect()
                })
                .collect()
        })
        .collect()
}

/// CSV with one row per frequency: `frequency_hz, G11_mag_db, G11_phase_deg, ...`.
pub fn response_csv(freqs: &[f64], resp: &Response) -> String {
    let mut s = String::from("frequency_hz");
    let (p, m) = dims(resp);
    for i in 0..p {
        for j in 0..m {
            let _ = write!(
                s,
                ",G{}{}_mag_db,G{}{}_phase_deg",
                i + 1,
                j + 1,
                i + 1,
                j + 1
            );
        }
    }
    s.push('\n');
    for (k, f) in freqs.iter().enumerate() {
        let _ = write!(s, "{f}");
        for i in 0..p {
            for j in 0..m {
                let (re, im) = resp[k][i][j];
                let _ = write!(s, ",{},{}", mag_db(re, im), im.atan2(re).to_degrees());
            }
        }
        s.push('\n');
    }
    s
}

fn dims(resp: &Response) -> (usize, usize) {
    let p = resp.first().map_or(0, |r| r.len());
    let m = resp.first().and_then(|r| r.first()).map_or(0, |r| r.len());
    (p, m)
}

fn mag_db(re: f64, im: f64) -> f64 {
    20.0 * (re.hypot(im).max(1e-300)).log10()
}

/// Logarithmically spaced frequencies from `from` to `to` (inclusive), `n >= 2` points.
pub fn logspace(from: f64, to: f64, n: usize) -> Vec<f64> {
    if n <= 1 {
        return vec![from];
    }
    let (a, b) = (from.log10(), to.log10());
    (0..n)
        .map(|k| 10f64.powf(a + (b - a) * k as f64 / (n - 1) as f64))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn csv_and_logspace() {
        let f = logspace(0.1, 10.0, 3);
        assert!((f[1] - 1.0).abs() < 1e-12);
        let r: Response = f.iter().map(|x| vec![vec![(1.0 / x, 0.0)]]).collect();
        let csv = response_csv(&f, &r);
        assert!(csv.starts_with("frequency_hz,G11_mag_db,G11_phase_deg\n"));
        assert_eq!(csv.lines().count(), 4);
    }
}
