//! A small SVG canvas for the plots: panels with linear or log-10 axes, 1-2-5 ticks,
//! polylines, markers, labels, legends. Pure string output, no dependencies.

use std::fmt::Write;

/// Line colours (the usual categorical palette).
pub const COLORS: [&str; 10] = [
    "#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f",
    "#bcbd22", "#17becf",
];

/// Escapes text for SVG.
pub fn esc(t: &str) -> String {
    t.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// 1-2-5 ticks covering `[lo, hi]` (about `n` of them) and the step.
pub fn nice_ticks(lo: f64, hi: f64, n: usize) -> (Vec<f64>, f64) {
    let span = (hi - lo).abs().max(1e-300);
    let raw = span / n.max(1) as f64;
    let mag = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 2.5, 5.0, 10.0]
        .iter()
        .map(|m| m * mag)
        .find(|s| *s >= raw)
        .unwrap_or(10.0 * mag);
    let first = (lo / step).ceil() as i64;
    let last = (hi / step).floor() as i64;
    let ticks = (first..=last).map(|k| k as f64 * step).collect();
    (ticks, step)
}

/// Expands `[lo, hi]` to whole steps of its nice ticks (and a degenerate range to width 2).
pub fn nice_range(lo: f64, hi: f64) -> (f64, f64) {
    let (lo, hi) = if !lo.is_finite() || !hi.is_finite() {
        (-1.0, 1.0)
    } else if hi - lo < 1e-12 * (1.0 + lo.abs()) {
        (lo - 1.0, hi + 1.0)
    } else {
        (lo, hi)
    };
    let (_, step) = nice_ticks(lo, hi, 6);
    ((lo / step).floor() * step, (hi / step).ceil() * step)
}

/// Decimals that write every multiple of `step` exactly (0.25 -> 2, 2.5 -> 1, 5 -> 0).
fn step_decimals(step: f64) -> usize {
    let step = step.abs();
    (0..=12)
        .find(|&d| {
            let scaled = step * 10f64.powi(d);
            (scaled - scaled.round()).abs() <= 1e-6 * scaled.max(1.0)
        })
        .unwrap_or(12) as usize
}

/// A tick label: short, no trailing zeros, exponent form for very large/small numbers; as
/// many digits as the step needs, so that 0.25, 2.5 and 7.5 print as such.
pub fn fmt_tick(x: f64, step: f64) -> String {
    if x == 0.0 || x.abs() < 1e-9 * step.abs() {
        return "0".into();
    }
    let trim = |s: String| {
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        }
    };
    if x.abs() >= 1e5 || x.abs() < 1e-3 {
        // as many mantissa digits as the step needs: 8e-5, 1.2e-4, 2.5e5
        let e = x.abs().log10().floor() as i32;
        let digits = step_decimals(step / 10f64.powi(e)).min(6);
        let t = format!("{x:.digits$e}");
        let (m, ex) = t.split_once('e').unwrap_or((&t, "0"));
        return format!("{}e{ex}", trim(m.to_string()));
    }
    trim(format!("{x:.*}", step_decimals(step)))
}

/// A plot panel: data ranges mapped to a pixel rectangle.
#[derive(Clone, Debug)]
pub struct Panel {
    pub x0: f64,
    pub y0: f64,
    pub w: f64,
    pub h: f64,
    pub xr: (f64, f64),
    pub yr: (f64, f64),
    /// x axis in log10 (`xr` then holds log10 values).
    pub logx: bool,
    /// With `logx`: the axis of negative x (`xr` holds log10 of `|x|`), mirrored: `|x|`
    /// decreases from left to right, so that x increases (`-10^xr.1` on the left,
    /// `-10^xr.0` on the right) and the ticks read `-10^k`.
    pub mirror: bool,
}

impl Panel {
    pub fn px(&self, x: f64) -> f64 {
        if self.logx && self.mirror {
            return self.lpx((-x).max(1e-300).log10());
        }
        let x = if self.logx { x.max(1e-300).log10() } else { x };
        self.x0 + (x - self.xr.0) / (self.xr.1 - self.xr.0) * self.w
    }
    /// The pixel of a log10 value on a log axis (of `|x|` when mirrored).
    fn lpx(&self, lx: f64) -> f64 {
        let t = (lx - self.xr.0) / (self.xr.1 - self.xr.0);
        let t = if self.mirror { 1.0 - t } else { t };
        self.x0 + t * self.w
    }
    pub fn py(&self, y: f64) -> f64 {
        let y = y.clamp(
            self.yr.0 - 0.05 * (self.yr.1 - self.yr.0),
            self.yr.1 + 0.05 * (self.yr.1 - self.yr.0),
        );
        self.y0 + (self.yr.1 - y) / (self.yr.1 - self.yr.0) * self.h
    }
}

/// An SVG document under construction.
pub struct Svg {
    pub s: String,
    pub w: f64,
    pub h: f64,
}

impl Svg {
    pub fn new(w: f64, h: f64, title: &str) -> Svg {
        let mut s = String::new();
        let _ = writeln!(
            s,
            r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" font-family="DejaVu Sans, Arial, sans-serif" font-size="12">"#
        );
        let _ = writeln!(s, "<title>{}</title>", esc(title));
        let _ = writeln!(s, r#"<rect width="100%" height="100%" fill="white"/>"#);
        let _ = writeln!(
            s,
            r#"<text x="{}" y="22" text-anchor="middle" font-size="15" font-weight="bold">{}</text>"#,
            w / 2.0,
            esc(&fit(title, w - 20.0, 9.0))
        );
        Svg { s, w, h }
    }

    /// Frame, grid, ticks and axis labels of a panel. `show_x_labels` false for upper
    /// panels that share the x axis with the one below.
    pub fn axes(&mut self, p: &Panel, xlabel: &str, ylabel: &str, show_x_labels: bool) {
        self.axes_with(p, xlabel, ylabel, show_x_labels, None);
    }

    /// As [`Svg::axes`], with the y ticks given (`None`: 1-2-5 ticks).
    pub fn axes_with(
        &mut self,
        p: &Panel,
        xlabel: &str,
        ylabel: &str,
        show_x_labels: bool,
        yticks: Option<&[f64]>,
    ) {
        let s = &mut self.s;
        let _ = writeln!(
            s,
            r##"<rect x="{}" y="{}" width="{}" height="{}" fill="none" stroke="#333"/>"##,
            p.x0, p.y0, p.w, p.h
        );
        let bottom = p.y0 + p.h;
        if p.logx {
            for d in (p.xr.0.floor() as i64)..=(p.xr.1.ceil() as i64) {
                for m in 1..10 {
                    let lx = d as f64 + (m as f64).log10();
                    if lx < p.xr.0 - 1e-9 || lx > p.xr.1 + 1e-9 {
                        continue;
                    }
                    let x = p.lpx(lx);
                    let col = if m == 1 { "#ccc" } else { "#eee" };
                    let _ = writeln!(
                        s,
                        r#"<line x1="{x:.1}" y1="{}" x2="{x:.1}" y2="{bottom}" stroke="{col}"/>"#,
                        p.y0
                    );
                    if m == 1 && show_x_labels {
                        let v = 10f64.powi(d as i32);
                        let _ = writeln!(
                            s,
                            r#"<text x="{x:.1}" y="{}" text-anchor="middle">{}</text>"#,
                            bottom + 16.0,
                            fmt_tick(if p.mirror { -v } else { v }, v)
                        );
                    }
                }
            }
        } else {
            let (ticks, step) = nice_ticks(p.xr.0, p.xr.1, 8);
            for t in ticks {
                let x = p.px(t);
                let _ = writeln!(
                    s,
                    r##"<line x1="{x:.1}" y1="{}" x2="{x:.1}" y2="{bottom}" stroke="#e4e4e4"/>"##,
                    p.y0
                );
                if show_x_labels {
                    let _ = writeln!(
                        s,
                        r#"<text x="{x:.1}" y="{}" text-anchor="middle">{}</text>"#,
                        bottom + 16.0,
                        fmt_tick(t, step)
                    );
                }
            }
        }
        let (ticks, step) = match yticks {
            Some(t) => {
                let step = t
                    .windows(2)
                    .map(|w| (w[1] - w[0]).abs())
                    .fold(f64::INFINITY, f64::min);
                (t.to_vec(), if step.is_finite() { step } else { 1.0 })
            }
            None => nice_ticks(p.yr.0, p.yr.1, 6),
        };
        for t in ticks {
            let y = p.py(t);
            let col = if t == 0.0 { "#999" } else { "#e4e4e4" };
            let _ = writeln!(
                s,
                r#"<line x1="{}" y1="{y:.1}" x2="{}" y2="{y:.1}" stroke="{col}"/><text x="{}" y="{:.1}" text-anchor="end">{}</text>"#,
                p.x0,
                p.x0 + p.w,
                p.x0 - 5.0,
                y + 4.0,
                fmt_tick(t, step)
            );
        }
        if show_x_labels {
            let _ = writeln!(
                s,
                r#"<text x="{}" y="{}" text-anchor="middle">{}</text>"#,
                p.x0 + p.w / 2.0,
                bottom + 34.0,
                esc(xlabel)
            );
        }
        let cy = p.y0 + p.h / 2.0;
        let lx = p.x0 - 52.0;
        let _ = writeln!(
            s,
            r#"<text x="{lx}" y="{cy}" transform="rotate(-90 {lx} {cy})" text-anchor="middle">{}</text>"#,
            esc(ylabel)
        );
    }

    /// A polyline through the points (NaN points break the line).
    pub fn polyline(&mut self, p: &Panel, pts: &[(f64, f64)], color: &str, width: f64, dash: bool) {
        let dash = if dash {
            r#" stroke-dasharray="6,3""#
        } else {
            ""
        };
        let mut seg: Vec<String> = vec![];
        let flush = |seg: &mut Vec<String>, s: &mut String| {
            if seg.len() >= 2 {
                let _ = writeln!(
                    s,
                    r#"<polyline fill="none" stroke="{color}" stroke-width="{width}"{dash} stroke-linejoin="round" points="{}"/>"#,
                    seg.join(" ")
                );
            }
            seg.clear();
        };
        for &(x, y) in pts {
            if x.is_finite() && y.is_finite() {
                seg.push(format!("{:.2},{:.2}", p.px(x), p.py(y)));
            } else {
                flush(&mut seg, &mut self.s);
            }
        }
        flush(&mut seg, &mut self.s);
    }

    /// Small filled circles.
    pub fn dots(&mut self, p: &Panel, pts: &[(f64, f64)], color: &str, r: f64) {
        for &(x, y) in pts {
            if x.is_finite() && y.is_finite() {
                let _ = writeln!(
                    self.s,
                    r#"<circle cx="{:.2}" cy="{:.2}" r="{r}" fill="{color}"/>"#,
                    p.px(x),
                    p.py(y)
                );
            }
        }
    }

    /// Crosses (poles) or open circles (zeros).
    /// A marker at data `(x, y)`: `'x'` a cross, `'s'` a filled square, anything else a circle.
    pub fn marker(&mut self, p: &Panel, x: f64, y: f64, kind: char, color: &str) {
        let (cx, cy) = (p.px(x), p.py(y));
        let _ = match kind {
            'x' => writeln!(
                self.s,
                r#"<path d="M{} {} L{} {} M{} {} L{} {}" stroke="{color}" stroke-width="2"/>"#,
                cx - 5.0,
                cy - 5.0,
                cx + 5.0,
                cy + 5.0,
                cx - 5.0,
                cy + 5.0,
                cx + 5.0,
                cy - 5.0
            ),
            's' => writeln!(
                self.s,
                r#"<rect x="{:.2}" y="{:.2}" width="8" height="8" fill="{color}" stroke="{color}"/>"#,
                cx - 4.0,
                cy - 4.0
            ),
            _ => writeln!(
                self.s,
                r#"<circle cx="{cx:.2}" cy="{cy:.2}" r="5" fill="none" stroke="{color}" stroke-width="2"/>"#
            ),
        };
    }

    /// A vertical line at data `x` with a rotated label.
    pub fn vline(&mut self, p: &Panel, x: f64, color: &str, label: Option<&str>) {
        let px = p.px(x);
        let _ = writeln!(
            self.s,
            r#"<line x1="{px:.1}" y1="{}" x2="{px:.1}" y2="{}" stroke="{color}" stroke-dasharray="4,3"/>"#,
            p.y0,
            p.y0 + p.h
        );
        if let Some(l) = label {
            let (tx, ty) = (px - 4.0, p.y0 + 6.0);
            let _ = writeln!(
                self.s,
                r#"<text x="{tx:.1}" y="{ty:.1}" transform="rotate(-90 {tx:.1} {ty:.1})" text-anchor="end" font-size="10" fill="{color}">{}</text>"#,
                esc(l)
            );
        }
    }

    /// A shaded band between data x values.
    pub fn band(&mut self, p: &Panel, xa: f64, xb: f64, color: &str) {
        let (a, b) = (p.px(xa), p.px(xb));
        let _ = writeln!(
            self.s,
            r#"<rect x="{a:.1}" y="{}" width="{:.1}" height="{}" fill="{color}"/>"#,
            p.y0,
            (b - a).max(0.0),
            p.h
        );
    }

    /// A legend box in the panel's top-right corner: (label, colour, dashed).
    pub fn legend(&mut self, p: &Panel, items: &[(String, String, bool)]) {
        if items.is_empty() {
            return;
        }
        let wmax = items.iter().map(|i| i.0.chars().count()).max().unwrap_or(0) as f64;
        let bw = 34.0 + 6.5 * wmax;
        let bh = 6.0 + 16.0 * items.len() as f64;
        let (x, y) = (p.x0 + p.w - bw - 6.0, p.y0 + 6.0);
        let _ = writeln!(
            self.s,
            r##"<rect x="{x:.1}" y="{y:.1}" width="{bw:.1}" height="{bh:.1}" fill="white" fill-opacity="0.85" stroke="#bbb"/>"##
        );
        for (k, (label, color, dash)) in items.iter().enumerate() {
            let yy = y + 14.0 + 16.0 * k as f64;
            let d = if *dash {
                r#" stroke-dasharray="6,3""#
            } else {
                ""
            };
            let _ = writeln!(
                self.s,
                r#"<line x1="{:.1}" y1="{:.1}" x2="{:.1}" y2="{:.1}" stroke="{color}" stroke-width="2"{d}/><text x="{:.1}" y="{:.1}">{}</text>"#,
                x + 6.0,
                yy - 4.0,
                x + 26.0,
                yy - 4.0,
                x + 30.0,
                yy,
                esc(label)
            );
        }
    }

    /// A legend laid out in `cols` columns of width `colw` from `(x, y)` (outside the
    /// panels, so it hides no curve): (label, colour, dashed).
    pub fn legend_at(
        &mut self,
        x: f64,
        y: f64,
        cols: usize,
        colw: f64,
        items: &[(String, String, bool)],
    ) {
        let cols = cols.max(1);
        for (k, (label, color, dash)) in items.iter().enumerate() {
            let (cx, cy) = (x + colw * (k % cols) as f64, y + 18.0 * (k / cols) as f64);
            let d = if *dash {
                r#" stroke-dasharray="6,3""#
            } else {
                ""
            };
            let _ = writeln!(
                self.s,
                r#"<line x1="{cx:.1}" y1="{:.1}" x2="{:.1}" y2="{:.1}" stroke="{color}" stroke-width="2.5"{d}/><text x="{:.1}" y="{cy:.1}">{}</text>"#,
                cy - 4.0,
                cx + 22.0,
                cy - 4.0,
                cx + 28.0,
                esc(label)
            );
        }
    }

    /// Free text.
    pub fn text(&mut self, x: f64, y: f64, anchor: &str, size: f64, t: &str) {
        let _ = writeln!(
            self.s,
            r#"<text x="{x:.1}" y="{y:.1}" text-anchor="{anchor}" font-size="{size}">{}</text>"#,
            esc(t)
        );
    }

    pub fn finish(mut self) -> String {
        self.s.push_str("</svg>\n");
        self.s
    }
}

/// `t` cut to about `width` pixels at `px` pixels per character, ending in "...", cut
/// after the middle of the text where possible (the end, e.g. ": Bode plot", is kept).
pub fn fit(t: &str, width: f64, px: f64) -> String {
    let max = (width / px).floor().max(8.0) as usize;
    let n = t.chars().count();
    if n <= max {
        return t.to_string();
    }
    // keep a suffix after the last ": " (what the plot is) when there is one
    let (head, tail) = match t.rfind(": ") {
        Some(k) if t[k..].chars().count() + 8 < max => (&t[..k], &t[k..]),
        _ => (t, ""),
    };
    let keep = max - tail.chars().count() - 3;
    let cut: String = head.chars().take(keep).collect();
    format!("{}...{tail}", cut.trim_end())
}

/// `(min, max)` of the finite values.
pub fn finite_range(xs: impl IntoIterator<Item = f64>) -> (f64, f64) {
    xs.into_iter()
        .filter(|x| x.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
            (a.min(x), b.max(x))
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tick_labels_are_exact_at_every_step() {
        for (step, xs, want) in [
            (0.25, [0.25, 0.5, 0.75], ["0.25", "0.5", "0.75"]),
            (2.5, [2.5, 5.0, 7.5], ["2.5", "5", "7.5"]),
            (0.025, [0.025, 0.05, 0.075], ["0.025", "0.05", "0.075"]),
            (
                250000.0,
                [250000.0, 500000.0, 750000.0],
                ["2.5e5", "5e5", "7.5e5"],
            ),
            (2.5e-5, [2.5e-5, 5e-5, 7.5e-5], ["2.5e-5", "5e-5", "7.5e-5"]),
        ] {
            for (x, w) in xs.iter().zip(want) {
                assert_eq!(fmt_tick(*x, step), w, "{x} step {step}");
            }
        }
        // property: on any nice tick set, labels are distinct and read back to the tick
        for (lo, hi) in [
            (0.0, 1.0),
            (-3.0, 17.0),
            (0.001, 0.0042),
            (1e5, 9e5),
            (-0.6, 0.6),
        ] {
            for n in 3..9 {
                let (ts, step) = nice_ticks(lo, hi, n);
                let labels: Vec<String> = ts.iter().map(|t| fmt_tick(*t, step)).collect();
                for (t, l) in ts.iter().zip(&labels) {
                    let back: f64 = l.parse().unwrap();
                    assert!((back - t).abs() <= 1e-9 * step, "{t} -> {l} (step {step})");
                }
                let mut u = labels.clone();
                u.dedup();
                assert_eq!(u.len(), labels.len(), "{labels:?}");
            }
        }
    }

    #[test]
    fn ticks_are_nice() {
        let (t, s) = nice_ticks(0.0, 10.0, 8);
        assert_eq!(s, 2.0);
        assert_eq!(t, vec![0.0, 2.0, 4.0, 6.0, 8.0, 10.0]);
        assert_eq!(fmt_tick(2.5, 0.5), "2.5");
        assert_eq!(fmt_tick(-10.0, 5.0), "-10");
        assert_eq!(nice_range(-0.3, 9.7), (-2.0, 10.0));
        assert_eq!(fit("short: x", 800.0, 9.0), "short: x");
        let long = format!("{}: Bode plot", "a".repeat(200));
        let f = fit(&long, 800.0, 9.0);
        assert!(f.ends_with("...: Bode plot") && f.chars().count() <= 88);
    }
}
