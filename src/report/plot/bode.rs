//! Bode plot: magnitude [dB] and unwrapped phase [deg] panels over a log frequency axis,
//! one curve per input-output channel (named from the system's `inputs`/`outputs`).

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

/// The Bode plot of `resp` at `freqs` [Hz]; `labels[i][j]` names channel (i, j).
pub fn bode_svg(freqs: &[f64], resp: &Response, title: &str, labels: &[Vec<String>]) -> String {
    let p = resp.first().map_or(0, Vec::len);
    let m = resp.first().and_then(|r| r.first()).map_or(0, Vec::len);
    let channels = p * m;
    let cols = if channels > 1 { 2 } else { 1 };
    let rows = channels.div_ceil(cols);
    let (w, h) = (840.0, 650.0 + 18.0 * rows as f64);
    let mut svg = Svg::new(w, h, title);
    let lf = finite_range(freqs.iter().map(|f| f.max(1e-300).log10()));
    let mut mags = vec![];
    let mut phases = vec![];
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
        }
    }
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
    let mut legend = vec![];
    for (c, (mg, ph)) in mags.iter().zip(&phases).enumerate() {
        let col = COLORS[c % COLORS.len()];
        let mp: Vec<(f64, f64)> = freqs.iter().copied().zip(mg.iter().copied()).collect();
        let pp: Vec<(f64, f64)> = freqs.iter().copied().zip(ph.iter().copied()).collect();
        svg.polyline(&top, &mp, col, 1.8, false);
        svg.polyline(&bot, &pp, col, 1.8, false);
        let (i, j) = (c / m.max(1), c % m.max(1));
        let name = labels
            .get(i)
            .and_then(|r| r.get(j))
            .cloned()
            .unwrap_or_else(|| format!("G{}{}", i + 1, j + 1));
        legend.push((name, col.to_string(), false));
    }
    svg.legend_at(bot.x0, bot.y0 + bot.h + 56.0, cols, 360.0, &legend);
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
