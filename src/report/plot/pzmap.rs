//! Pole-zero map: poles as crosses, zeros as open circles in the complex plane, equal scales
//! on both axes (one unit is as many pixels on the real axis as on the imaginary axis, as
//! `axis equal` draws it), the imaginary axis (the stability boundary) drawn, multiplicities
//! written beside their marker.

use super::svg::{Panel, Svg, finite_range, nice_range};
use std::fmt::Write;

/// A point of the map: `(re, im, multiplicity)`.
pub type Point = (f64, f64, usize);

/// Data ranges around all points (and the origin), padded, with equal units per pixel.
fn square_ranges(pts: &[Point], w: f64, h: f64) -> ((f64, f64), (f64, f64)) {
    let (xl, xh) = finite_range(pts.iter().map(|p| p.0).chain([0.0]));
    let (yl, yh) = finite_range(pts.iter().map(|p| p.1).chain([0.0]));
    let pad = |lo: f64, hi: f64| {
        let d = (hi - lo).max(1e-9 * (1.0 + lo.abs().max(hi.abs())));
        (lo - 0.12 * d, hi + 0.12 * d)
    };
    let (xl, xh) = pad(xl, xh);
    let (yl, yh) = pad(yl, yh);
    // equal scale: widen the range that is short for its side
    let (ux, uy) = ((xh - xl) / w, (yh - yl) / h);
    let unit = ux.max(uy);
    let (cx, cy) = ((xl + xh) / 2.0, (yl + yh) / 2.0);
    let xr = nice_range(cx - unit * w / 2.0, cx + unit * w / 2.0);
    let yr = nice_range(cy - unit * h / 2.0, cy + unit * h / 2.0);
    // the nice rounding may widen one more than the other: re-equalise
    let unit = ((xr.1 - xr.0) / w).max((yr.1 - yr.0) / h);
    let grow = |r: (f64, f64), side: f64| {
        let c = (r.0 + r.1) / 2.0;
        (c - unit * side / 2.0, c + unit * side / 2.0)
    };
    (grow(xr, w), grow(yr, h))
}

/// The pole-zero map. `poles` and `zeros` carry their multiplicities; the SVG marks each
/// distinct pole with `class="pole"` and each distinct zero with `class="zero"`.
pub fn pzmap_svg(poles: &[Point], zeros: &[Point], title: &str) -> String {
    let (w, h) = (760.0, 620.0);
    let mut svg = Svg::new(w, h, title);
    let all: Vec<Point> = poles.iter().chain(zeros).copied().collect();
    let (pw, ph) = (560.0, 500.0);
    let (xr, yr) = square_ranges(&all, pw, ph);
    let p = Panel {
        x0: 90.0,
        y0: 40.0,
        w: pw,
        h: ph,
        xr,
        yr,
        logx: false,
        mirror: false,
    };
    svg.axes(&p, "real part [1/s]", "imaginary part [rad/s]", true);
    // the imaginary axis: the stability boundary
    if xr.0 < 0.0 && xr.1 > 0.0 {
        let x = p.px(0.0);
        let _ = writeln!(
            svg.s,
            r##"<line x1="{x:.1}" y1="{}" x2="{x:.1}" y2="{}" stroke="#999"/>"##,
            p.y0,
            p.y0 + p.h
        );
    }
    let count = |xs: &[Point]| xs.iter().map(|q| q.2).sum::<usize>();
    for (kind, xs, color) in [("pole", poles, "#d62728"), ("zero", zeros, "#1f77b4")] {
        for &(re, im, mult) in xs {
            if !(re.is_finite() && im.is_finite()) {
                continue;
            }
            let (cx, cy) = (p.px(re), p.py(im));
            let _ = if kind == "pole" {
                writeln!(
                    svg.s,
                    r#"<path class="pole" data-multiplicity="{mult}" d="M{:.2} {:.2} L{:.2} {:.2} M{:.2} {:.2} L{:.2} {:.2}" stroke="{color}" stroke-width="2.2"/>"#,
                    cx - 6.0,
                    cy - 6.0,
                    cx + 6.0,
                    cy + 6.0,
                    cx - 6.0,
                    cy + 6.0,
                    cx + 6.0,
                    cy - 6.0
                )
            } else {
                writeln!(
                    svg.s,
                    r#"<circle class="zero" data-multiplicity="{mult}" cx="{cx:.2}" cy="{cy:.2}" r="6" fill="none" stroke="{color}" stroke-width="2.2"/>"#
                )
            };
            if mult > 1 {
                svg.text(cx + 8.0, cy - 7.0, "start", 11.0, &format!("{mult}"));
            }
        }
    }
    // legend to the right of the panel
    let lx = p.x0 + p.w + 20.0;
    let _ = writeln!(
        svg.s,
        r##"<path d="M{} {} L{} {} M{} {} L{} {}" stroke="#d62728" stroke-width="2.2"/>"##,
        lx,
        p.y0 + 10.0,
        lx + 12.0,
        p.y0 + 22.0,
        lx,
        p.y0 + 22.0,
        lx + 12.0,
        p.y0 + 10.0
    );
    svg.text(
        lx + 20.0,
        p.y0 + 20.0,
        "start",
        12.0,
        &format!("poles ({})", count(poles)),
    );
    let _ = writeln!(
        svg.s,
        r##"<circle cx="{}" cy="{}" r="6" fill="none" stroke="#1f77b4" stroke-width="2.2"/>"##,
        lx + 6.0,
        p.y0 + 42.0
    );
    svg.text(
        lx + 20.0,
        p.y0 + 46.0,
        "start",
        12.0,
        &format!("zeros ({})", count(zeros)),
    );
    if poles.iter().chain(zeros).any(|q| q.2 > 1) {
        svg.text(lx, p.y0 + 72.0, "start", 11.0, "n: multiplicity");
    }
    svg.finish()
}
