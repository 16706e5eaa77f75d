//! Plots of a parameter sweep: real and imaginary parts of the eigenvalues against the
//! parameter (two panels sharing the parameter axis, as Fig. 3 of Meijaard et al. 2007),
//! and a root locus in the complex plane.

use super::svg::{COLORS, Panel, Svg, finite_range, nice_range};
use crate::study::SweepResult;
use num_complex::Complex;

/// At most this many parameter values are drawn (the sweep is subsampled evenly).
const MAX_DRAWN: usize = 1500;

fn subsample(sw: &SweepResult) -> (Vec<f64>, Vec<Vec<Complex<f64>>>) {
    let tr = sw.tracks();
    let step = sw.values.len().div_ceil(MAX_DRAWN).max(1);
    let idx: Vec<usize> = (0..sw.values.len()).step_by(step).collect();
    (
        idx.iter().map(|&i| sw.values[i]).collect(),
        idx.iter().map(|&i| tr[i].clone()).collect(),
    )
}

/// A range holding most of the values: the full range unless a few values are far out,
/// then $\pm 2.5\times$ the 90% quantile of $|x|$.
fn robust_range(xs: &[f64]) -> (f64, f64) {
    let (lo, hi) = finite_range(xs.iter().copied());
    let mut a: Vec<f64> = xs
        .iter()
        .filter(|x| x.is_finite())
        .map(|x| x.abs())
        .collect();
    if a.is_empty() {
        return (-1.0, 1.0);
    }
    a.sort_by(f64::total_cmp);
    let q = a[(a.len() * 9) / 10].max(1e-12);
    nice_range(lo.max(-2.5 * q), hi.min(2.5 * q))
}

/// Real parts (upper panel) and imaginary parts $\ge 0$ (lower panel) of the eigenvalues
/// against the parameter; parameter ranges where every real part is negative are shaded;
/// `marks` are drawn as labelled vertical lines (e.g. exact critical values).
pub fn sweep_svg(sw: &SweepResult, title: &str, xlabel: &str, marks: &[(f64, String)]) -> String {
    let (vals, tr) = subsample(sw);
    let n = tr.iter().map(Vec::len).max().unwrap_or(0);
    let (w, h) = (820.0, 640.0);
    let mut svg = Svg::new(w, h, title);
    let xr = finite_range(vals.iter().copied());
    let xr = if xr.1 > xr.0 {
        xr
    } else {
        (xr.0 - 1.0, xr.0 + 1.0)
    };
    let res: Vec<f64> = tr.iter().flatten().map(|z| z.re).collect();
    let ims: Vec<f64> = tr.iter().flatten().map(|z| z.im.max(0.0)).collect();
    let top = Panel {
        x0: 80.0,
        y0: 40.0,
        w: 700.0,
        h: 250.0,
        xr,
        yr: robust_range(&res),
        logx: false,
        mirror: false,
    };
    let imr = robust_range(&ims);
    let bot = Panel {
        y0: 320.0,
        yr: (0.0, imr.1.max(1e-9)),
        ..top.clone()
    };
    // stable bands
    for p in [&top, &bot] {
        let mut start: Option<f64> = None;
        for (k, (v, ev)) in vals.iter().zip(&tr).enumerate() {
            let st = !ev.is_empty() && ev.iter().all(|z| z.re < 0.0);
            match (st, start) {
                (true, None) => start = Some(*v),
                (false, Some(s)) => {
                    svg.band(p, s, vals[k.saturating_sub(1)].max(s), "#e3f4e1");
                    start = None;
                }
                _ => {}
            }
        }
        if let (Some(s), Some(e)) = (start, vals.last()) {
            svg.band(p, s, *e, "#e3f4e1");
        }
    }
    svg.axes(&top, xlabel, "real part of eigenvalue [1/s]", false);
    svg.axes(&bot, xlabel, "imaginary part [rad/s]", true);
    for k in 0..n {
        let c = COLORS[k % COLORS.len()];
        let clip = |y: f64, r: (f64, f64)| if y < r.0 || y > r.1 { f64::NAN } else { y };
        let re: Vec<(f64, f64)> = vals
            .iter()
            .zip(&tr)
            .map(|(v, ev)| (*v, ev.get(k).map_or(f64::NAN, |z| clip(z.re, top.yr))))
            .collect();
        let im: Vec<(f64, f64)> = vals
            .iter()
            .zip(&tr)
            .map(|(v, ev)| {
                let y = ev
                    .get(k)
                    .map_or(f64::NAN, |z| if z.im >= 0.0 { z.im } else { f64::NAN });
                (*v, clip(y, bot.yr))
            })
            .collect();
        svg.polyline(&top, &re, c, 1.8, false);
        svg.polyline(&bot, &im, c, 1.8, false);
    }
    for (x, label) in marks {
        if *x >= xr.0 && *x <= xr.1 {
            svg.vline(&top, *x, "#555", Some(label));
            svg.vline(&bot, *x, "#555", None);
        }
    }
    svg.legend(
        &top,
        &[(
            "all real parts < 0 (stable)".to_string(),
            "#9fd39a".to_string(),
            false,
        )],
    );
    svg.finish()
}

/// Root locus: each eigenvalue branch as a curve in the complex plane, a cross at the
/// first parameter value (the open-loop poles of a gain sweep from 0), a small square at the
/// last, and a black circle at each `zeros` entry: the finite limits of the branches as the
/// parameter grows without bound (for a gain sweep $A - kBC$ the open-loop zeros), as
/// root-locus plots mark them.
pub fn root_locus_svg(sw: &SweepResult, title: &str, zeros: &[Complex<f64>]) -> String {
    let (vals, tr) = subsample(sw);
    let n = tr.iter().map(Vec::len).max().unwrap_or(0);
    let (w, h) = (760.0, 620.0);
    let mut svg = Svg::new(w, h, title);
    let res: Vec<f64> = tr.iter().flatten().chain(zeros).map(|z| z.re).collect();
    let ims: Vec<f64> = tr.iter().flatten().chain(zeros).map(|z| z.im).collect();
    let p = Panel {
        x0: 80.0,
        y0: 40.0,
        w: 640.0,
        h: 510.0,
        xr: robust_range(&res),
        yr: robust_range(&ims),
        logx: false,
        mirror: false,
    };
    svg.axes(&p, "real part [1/s]", "imaginary part [rad/s]", true);
    svg.vline(&p, 0.0, "#999", None);
    for k in 0..n {
        let c = COLORS[k % COLORS.len()];
        let inside =
            |z: &Complex<f64>| z.re >= p.xr.0 && z.re <= p.xr.1 && z.im >= p.yr.0 && z.im <= p.yr.1;
        let pts: Vec<(f64, f64)> = tr
            .iter()
            .map(|ev| match ev.get(k) {
                Some(z) if inside(z) => (z.re, z.im),
                _ => (f64::NAN, f64::NAN),
            })
            .collect();
        svg.polyline(&p, &pts, c, 1.8, false);
        if let Some(z) = tr.first().and_then(|e| e.get(k)).filter(|z| inside(z)) {
            svg.marker(&p, z.re, z.im, 'x', c);
        }
        if let Some(z) = tr.last().and_then(|e| e.get(k)).filter(|z| inside(z)) {
            svg.marker(&p, z.re, z.im, 's', c);
        }
    }
    for z in zeros {
        if z.re >= p.xr.0 && z.re <= p.xr.1 && z.im >= p.yr.0 && z.im <= p.yr.1 {
            svg.marker(&p, z.re, z.im, 'o', "#000");
        }
    }
    if let (Some(a), Some(b)) = (vals.first(), vals.last()) {
        svg.text(
            p.x0 + p.w / 2.0,
            h - 12.0,
            "middle",
            11.0,
            &format!(
                "{} from {} (x) to {} (square); o: limits as {} grows without bound",
                sw.param,
                super::svg::fmt_tick(*a, (b - a).abs().max(f64::MIN_POSITIVE) / 1e4),
                super::svg::fmt_tick(*b, (b - a).abs().max(f64::MIN_POSITIVE) / 1e4),
                sw.param
            ),
        );
    }
    svg.finish()
}
