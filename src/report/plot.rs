//! Frequency-response output: CSV and a self-contained SVG Bode magnitude plot.
//!
//! Hand-written SVG (a few dozen lines) instead of a plotting crate: the CLI needs one plot
//! type, and this keeps the dependency tree and CI build small.

pub mod bode;
pub mod pzmap;
pub mod svg;
pub mod sweep;
pub mod time;

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

/// An SVG Bode magnitude plot (log frequency axis, dB), one curve per input-output pair.
pub fn response_svg(freqs: &[f64], resp: &Response, title: &str) -> String {
    let (w, h, ml, mr, mt, mb) = (800.0, 480.0, 70.0, 20.0, 40.0, 50.0);
    let (p, m) = dims(resp);
    let lf: Vec<f64> = freqs.iter().map(|f| f.max(1e-300).log10()).collect();
    let (fmin, fmax) = (
        lf.iter().cloned().fold(f64::INFINITY, f64::min),
        lf.iter().cloned().fold(f64::NEG_INFINITY, f64::max),
    );
    let mut all = vec![];
    for k in 0..freqs.len() {
        for i in 0..p {
            for j in 0..m {
                let (re, im) = resp[k][i][j];
                all.push(mag_db(re, im).clamp(-400.0, 400.0));
            }
        }
    }
    let (mut ymin, mut ymax) = (
        all.iter().cloned().fold(f64::INFINITY, f64::min),
        all.iter().cloned().fold(f64::NEG_INFINITY, f64::max),
    );
    if !ymin.is_finite() || !ymax.is_finite() {
        ymin = -1.0;
        ymax = 1.0;
    }
    if ymax - ymin < 1e-9 {
        ymin -= 1.0;
        ymax += 1.0;
    }
    let fx = |x: f64| ml + (x - fmin) / (fmax - fmin).max(1e-12) * (w - ml - mr);
    let fy = |y: f64| mt + (ymax - y) / (ymax - ymin) * (h - mt - mb);
    let mut s = String::new();
    let _ = writeln!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" font-family="sans-serif" font-size="12">"#
    );
    let _ = writeln!(s, r#"<rect width="100%" height="100%" fill="white"/>"#);
    let _ = writeln!(
        s,
        r#"<text x="{}" y="20" text-anchor="middle" font-size="14">{}</text>"#,
        w / 2.0,
        xml_escape(title)
    );
    let _ = writeln!(
        s,
        r#"<rect x="{ml}" y="{mt}" width="{}" height="{}" fill="none" stroke="black"/>"#,
        w - ml - mr,
        h - mt - mb
    );
    for d in (fmin.floor() as i64)..=(fmax.ceil() as i64) {
        let x = fx(d as f64);
        if x >= ml - 0.5 && x <= w - mr + 0.5 {
            let _ = writeln!(
                s,
                r##"<line x1="{x:.1}" y1="{mt}" x2="{x:.1}" y2="{}" stroke="#ddd"/><text x="{x:.1}" y="{}" text-anchor="middle">1e{d}</text>"##,
                h - mb,
                h - mb + 16.0
            );
        }
    }
    for t in 0..=5 {
        let y = ymin + (ymax - ymin) * t as f64 / 5.0;
        let _ = writeln!(
            s,
            r##"<line x1="{ml}" y1="{:.1}" x2="{}" y2="{:.1}" stroke="#ddd"/><text x="{}" y="{:.1}" text-anchor="end">{y:.1}</text>"##,
            fy(y),
            w - mr,
            fy(y),
            ml - 4.0,
            fy(y) + 4.0
        );
    }
    let _ = writeln!(
        s,
        r#"<text x="{}" y="{}" text-anchor="middle">frequency [Hz]</text>"#,
        w / 2.0,
        h - 10.0
    );
    let _ = writeln!(
        s,
        r#"<text x="16" y="{}" transform="rotate(-90 16 {})" text-anchor="middle">magnitude [dB]</text>"#,
        h / 2.0,
        h / 2.0
    );
    let colors = [
        "#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b",
    ];
    let mut c = 0;
    for i in 0..p {
        for j in 0..m {
            let pts: Vec<String> = (0..freqs.len())
                .map(|k| {
                    let (re, im) = resp[k][i][j];
                    format!(
                        "{:.2},{:.2}",
                        fx(lf[k]),
                        fy(mag_db(re, im).clamp(ymin, ymax))
                    )
                })
                .collect();
            let _ = writeln!(
                s,
                r#"<polyline fill="none" stroke="{}" stroke-width="1.5" points="{}"/>"#,
                colors[c % colors.len()],
                pts.join(" ")
            );
            let _ = writeln!(
                s,
                r#"<text x="{}" y="{}" fill="{}">G{}{}</text>"#,
                w - mr - 40.0,
                mt + 16.0 + 14.0 * c as f64,
                colors[c % colors.len()],
                i + 1,
                j + 1
            );
            c += 1;
        }
    }
    s.push_str("</svg>\n");
    s
}

fn xml_escape(t: &str) -> String {
    t.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
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
    fn csv_and_svg() {
        let f = logspace(0.1, 10.0, 3);
        assert!((f[1] - 1.0).abs() < 1e-12);
        let r: Response = f.iter().map(|x| vec![vec![(1.0 / x, 0.0)]]).collect();
        let csv = response_csv(&f, &r);
        assert!(csv.starts_with("frequency_hz,G11_mag_db,G11_phase_deg\n"));
        assert_eq!(csv.lines().count(), 4);
        let svg = response_svg(&f, &r, "test");
        assert!(svg.contains("<polyline"));
    }
}
