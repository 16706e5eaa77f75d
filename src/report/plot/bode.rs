//! Bode plot: magnitude [dB] and unwrapped phase [deg] panels over a log frequency axis,
//! one curve per input-output channel (named from the system's `inputs`/`outputs`); for a
//! system with complex coefficients ([`bode_svg_two_sided`]) over negative and positive
//! frequencies side by side.

use super::Response;
use super::svg::{COLORS, Panel, Svg, finite_range, nice_range};

/// Phase in degrees, unwrapped along the frequency axis (jumps > 180 deg removed).
pub fn unwrapped_phase_deg(values: &[(f64, f64)]) -> Vec<f64> {
    let mut out = Vec::with_capacity(values.len());
    let mut offset = 0.0;
    let mut prev: Option<f64> = None;
    let mag = |k: usize| values[k].0.hypot(values[k].1);
    for (k, &(re, im)) in values.iter().enumerate() {
        let raw = im.atan2(re).to_degrees();
        if let Some(p) = prev {
            let mut d = raw + offset - p;
            while d > 180.0 {
                offset -= 360.0;
                d -= 360.0;
            }
            while d < -180.0 {
                offset += 360.0;
                d += 360.0;
            }
            // a jump of exactly 180 degrees (an undamped pole or zero between two grid
            // points, the response real on both sides): down across a resonance peak (a
            // pole, the magnitude rising into it), up across a notch (a zero)
            if (d.abs() - 180.0).abs() < 1e-6 {
                let rising = k < 2 || mag(k - 1) >= mag(k - 2);
                if rising && d > 0.0 {
                    offset -= 360.0;
                } else if !rising && d < 0.0 {
                    offset += 360.0;
                }
            }
        }
        let v = raw + offset;
        out.push(v);
        prev = Some(v);
    }
    out
}

/// Magnitudes [dB] and unwrapped phases [deg] of each channel, row by row, and the
/// channel names (`labels[i][j]`, else `G<i><j>`).
type Curves = (Vec<Vec<f64>>, Vec<Vec<f64>>, Vec<String>);

fn curves(resp: &Response, labels: &[Vec<String>]) -> Curves {
    let p = resp.first().map_or(0, Vec::len);
    let m = resp.first().and_then(|r| r.first()).map_or(0, Vec::len);
    let (mut mags, mut phases, mut names) = (vec![], vec![], vec![]);
    for i in 0..p {
        for j in 0..m {
            let ch: Vec<(f64, f64)> = resp.iter().map(|g| g[i][j]).collect();
            mags.push(
                ch.iter()
                    .map(|(re, im)| 20.0 * re.hypot(*im).max(1e-300).log10())
                    .map(|x| x.max(-400.0))
                    .collect::<Vec<f64>>(),
            );
            phases.push(unwrapped_phase_deg(&ch));
            names.push(
                labels
                    .get(i)
                    .and_then(|r| r.get(j))
                    .cloned()
                    .unwrap_or_else(|| format!("G{}{}", i + 1, j + 1)),
            );
        }
    }
    (mags, phases, names)
}

/// The Bode plot of `resp` at `freqs` [Hz]; `labels[i][j]` names channel (i, j).
pub fn bode_svg(freqs: &[f64], resp: &Response, title: &str, labels: &[Vec<String>]) -> String {
    bode_svg_marked(freqs, resp, title, labels, &[])
}

/// The curves of `resp`, the columns of their legend (two for more than one channel) and
/// a canvas `w` wide and `h` high plus a legend line per row.
fn canvas(
    resp: &Response,
    labels: &[Vec<String>],
    title: &str,
    (w, h): (f64, f64),
) -> (Curves, usize, Svg) {
    let curves = curves(resp, labels);
    let channels = curves.2.len();
    let cols = if channels > 1 { 2 } else { 1 };
    let rows = channels.div_ceil(cols);
    let svg = Svg::new(w, h + 18.0 * rows as f64, title);
    (curves, cols, svg)
}

/// [`bode_svg`] with labelled vertical lines at the frequencies of `marks` [Hz] on both
/// panels (the Nyquist frequency $1/(2T)$ of a discrete-time system).
pub fn bode_svg_marked(
    freqs: &[f64],
    resp: &Response,
    title: &str,
    labels: &[Vec<String>],
    marks: &[(f64, &str)],
) -> String {
    let ((mags, phases, names), cols, mut svg) = canvas(resp, labels, title, (840.0, 650.0));
    let lf = finite_range(freqs.iter().map(|f| f.max(1e-300).log10()));
    let (ml, mh) = finite_range(mags.iter().flatten().copied());
    let (pl, ph) = finite_range(phases.iter().flatten().copied());
    let top = Panel {
        x0: 90.0,
        y0: 40.0,
        w: 700.0,
        h: 270.0,
        xr: lf,
        yr: nice_range(ml, mh),
        logx: true,
        mirror: false,
    };
    let bot = Panel {
        y0: 340.0,
        yr: phase_range(pl, ph),
        ..top.clone()
    };
    svg.axes_with(
        &top,
        "frequency [Hz]",
        "magnitude [dB]",
        false,
        Some(&db_ticks(top.yr)),
    );
    svg.axes_with(
        &bot,
        "frequency [Hz]",
        "phase [deg]",
        true,
        Some(&phase_ticks(bot.yr)),
    );
    for &(f, label) in marks {
        if f > 0.0 {
            svg.vline(&top, f, "#555", Some(label));
            svg.vline(&bot, f, "#555", None);
        }
    }
    let mut legend = vec![];
    for (c, ((mg, ph), name)) in mags.iter().zip(&phases).zip(names).enumerate() {
        let col = COLORS[c % COLORS.len()];
        let mp: Vec<(f64, f64)> = freqs.iter().copied().zip(mg.iter().copied()).collect();
        let pp: Vec<(f64, f64)> = freqs.iter().copied().zip(ph.iter().copied()).collect();
        svg.polyline(&top, &mp, col, 1.8, false);
        svg.polyline(&bot, &pp, col, 1.8, false);
        legend.push((name, col.to_string(), false));
    }
    svg.legend_at(bot.x0, bot.y0 + bot.h + 56.0, cols, 360.0, &legend);
    svg.finish()
}

/// The Bode plot of a system with complex coefficients, whose response is two-sided
/// ($G(-j\omega) \ne \overline{G(j\omega)}$), as MATLAB draws it: magnitude [dB] and phase
/// [deg] over negative frequencies on the left (a mirrored log axis, $-f_{max}$ to
/// $-f_{min}$) and positive ones on the right ($f_{min}$ to $f_{max}$), the two sides on
/// the same vertical scales. `freqs` [Hz] holds the negative frequencies (increasing) then
/// the positive ones; the phase is unwrapped along them in that order.
pub fn bode_svg_two_sided(
    freqs: &[f64],
    resp: &Response,
    title: &str,
    labels: &[Vec<String>],
) -> String {
    let ((mags, phases, names), cols, mut svg) = canvas(resp, labels, title, (1000.0, 690.0));
    let lf = finite_range(freqs.iter().map(|f| f.abs().max(1e-300).log10()));
    let (ml, mh) = finite_range(mags.iter().flatten().copied());
    let (pl, ph) = finite_range(phases.iter().flatten().copied());
    let neg_mag = Panel {
        x0: 90.0,
        y0: 64.0,
        w: 400.0,
        h: 250.0,
        xr: lf,
        yr: nice_range(ml, mh),
        logx: true,
        mirror: true,
    };
    let neg_phase = Panel {
        y0: 364.0,
        yr: phase_range(pl, ph),
        ..neg_mag.clone()
    };
    let right = |p: &Panel| Panel {
        x0: 560.0,
        mirror: false,
        ..p.clone()
    };
    let (pos_mag, pos_phase) = (right(&neg_mag), right(&neg_phase));
    for (p, head) in [
        (&neg_mag, "negative frequencies (f < 0)"),
        (&pos_mag, "positive frequencies (f > 0)"),
    ] {
        svg.text(p.x0 + p.w / 2.0, p.y0 - 10.0, "middle", 13.0, head);
    }
    let db = db_ticks(neg_mag.yr);
    let deg = phase_ticks(neg_phase.yr);
    let xneg = "frequency [Hz], f < 0 (log |f|, mirrored)";
    svg.axes_with(&neg_mag, xneg, "magnitude [dB]", false, Some(&db));
    svg.axes_with(&neg_phase, xneg, "phase [deg]", true, Some(&deg));
    let xpos = "frequency [Hz], f > 0";
    svg.axes_with(&pos_mag, xpos, "magnitude [dB]", false, Some(&db));
    svg.axes_with(&pos_phase, xpos, "phase [deg]", true, Some(&deg));
    let mut legend = vec![];
    for (c, ((mg, ph), name)) in mags.iter().zip(&phases).zip(names).enumerate() {
        let col = COLORS[c % COLORS.len()];
        for (neg, (top, bot)) in [
            (true, (&neg_mag, &neg_phase)),
            (false, (&pos_mag, &pos_phase)),
        ] {
            let side = |ys: &[f64]| -> Vec<(f64, f64)> {
                freqs
                    .iter()
                    .zip(ys)
                    .filter(|(f, _)| if neg { **f < 0.0 } else { **f > 0.0 })
                    .map(|(f, y)| (*f, *y))
                    .collect()
            };
            svg.polyline(top, &side(mg), col, 1.8, false);
            svg.polyline(bot, &side(ph), col, 1.8, false);
        }
        legend.push((name, col.to_string(), false));
    }
    svg.legend_at(
        neg_phase.x0,
        neg_phase.y0 + neg_phase.h + 56.0,
        cols,
        430.0,
        &legend,
    );
    svg.finish()
}

/// Ticks every `step` in `[lo, hi]`, `step` the first of `steps` giving at most `max` ticks.
fn ticks_from(r: (f64, f64), steps: &[f64], max: usize) -> Vec<f64> {
    let span = (r.1 - r.0).abs();
    let step = steps
        .iter()
        .copied()
        .find(|s| span / s <= max as f64)
        .unwrap_or_else(|| (span / max as f64 / 360.0).ceil() * 360.0);
    let first = (r.0 / step).ceil() as i64;
    let last = (r.1 / step).floor() as i64;
    (first..=last).map(|k| k as f64 * step).collect()
}

/// Phase ticks on multiples of 45, 90, 180 or 360 degrees (at most 8).
pub fn phase_ticks(r: (f64, f64)) -> Vec<f64> {
    ticks_from(r, &[15.0, 45.0, 90.0, 180.0, 360.0, 720.0], 8)
}

/// Magnitude ticks on 10, 20, 40, 50, 100 ... dB (at most 7).
pub fn db_ticks(r: (f64, f64)) -> Vec<f64> {
    ticks_from(r, &[1.0, 2.0, 5.0, 10.0, 20.0, 40.0, 50.0, 100.0, 200.0], 7)
}

/// A phase range on multiples of 45 degrees.
fn phase_range(lo: f64, hi: f64) -> (f64, f64) {
    if !lo.is_finite() || !hi.is_finite() {
        return (-180.0, 180.0);
    }
    let a = (lo / 45.0).floor() * 45.0;
    let b = (hi / 45.0).ceil() * 45.0;
    if b - a < 45.0 {
        (a - 45.0, b + 45.0)
    } else {
        (a, b)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn undamped_pole_and_zero_turn_the_phase_the_right_way() {
        // (s^2 + 4)/(s^2 + 1) on the imaginary axis: real, a pole at w = 1, a zero at w = 2
        let vals: Vec<(f64, f64)> = (1..400)
            .map(|k| {
                let w = 0.01 * k as f64 + 0.003;
                ((4.0 - w * w) / (1.0 - w * w), 0.0)
            })
            .collect();
        let ph = unwrapped_phase_deg(&vals);
        assert!(ph[0].abs() < 1e-9);
        assert!((ph[150] + 180.0).abs() < 1e-9, "{}", ph[150]);
        assert!(ph[398].abs() < 1e-9, "{}", ph[398]);
    }

    #[test]
    fn phase_unwraps_through_180() {
        // 1/(s + 1)^3 at growing frequency: phase goes 0 -> -270 without a jump
        let vals: Vec<(f64, f64)> = (0..200)
            .map(|k| {
                let w = 10f64.powf(-2.0 + 4.0 * k as f64 / 199.0);
                let z = num_complex::Complex::new(1.0, w).powi(3).inv();
                (z.re, z.im)
            })
            .collect();
        let ph = unwrapped_phase_deg(&vals);
        assert_eq!(
            phase_ticks((-270.0, 0.0)),
            vec![-270.0, -225.0, -180.0, -135.0, -90.0, -45.0, 0.0]
        );
        assert_eq!(db_ticks((-120.0, 20.0)).len(), 8);
        assert_eq!(db_ticks((-35.0, 5.0)), vec![-30.0, -20.0, -10.0, 0.0]);
        assert!(ph.windows(2).all(|w| (w[1] - w[0]).abs() < 30.0));
        assert!((ph[199] + 270.0).abs() < 5.0 && ph[0].abs() < 5.0);
    }
}

/// The frequency range (Hz) a Bode plot shows for these poles and zeros (`[re, im]` in
/// rad/s): from a decade below the slowest nonzero one to a decade above the fastest, both
/// rounded out to whole decades; 0.01 .. 10 Hz when there is none.
pub fn default_range(points: &[(f64, f64)]) -> (f64, f64) {
    let hz: Vec<f64> = points
        .iter()
        .map(|z| z.0.hypot(z.1) / (2.0 * std::f64::consts::PI))
        .filter(|f| f.is_finite() && *f > 1e-12)
        .collect();
    if hz.is_empty() {
        return (0.01, 10.0);
    }
    let lo = hz.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = hz.iter().copied().fold(0.0, f64::max);
    let lo = 10f64.powf(lo.log10().floor() - 1.0).max(1e-12);
    let hi = 10f64.powf(hi.log10().ceil() + 1.0).min(1e12);
    (lo, hi.max(lo * 100.0))
}

#[cfg(test)]
mod range_tests {
    use super::default_range;

    #[test]
    fn range_covers_every_pole_and_zero_with_a_decade_each_side() {
        assert_eq!(default_range(&[]), (0.01, 10.0));
        assert_eq!(default_range(&[(0.0, 0.0)]), (0.01, 10.0));
        // property: every corner frequency lies at least a decade inside the range
        let mut g = crate::rng::SplitMix64(5);
        for _ in 0..500 {
            let pts: Vec<(f64, f64)> = (0..g.int(1, 6))
                .map(|_| {
                    let r = 10f64.powf(g.int(-400, 400) as f64 / 100.0);
                    let a = g.int(0, 314) as f64 / 100.0;
                    (-r * a.cos(), r * a.sin())
                })
                .collect();
            let (lo, hi) = default_range(&pts);
            assert!(lo < hi);
            for (re, im) in &pts {
                let f = re.hypot(*im) / (2.0 * std::f64::consts::PI);
                assert!(lo <= f / 10.0 * (1.0 + 1e-9) && f * 10.0 <= hi * (1.0 + 1e-9));
            }
        }
    }
}
