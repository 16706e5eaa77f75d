//! Step and impulse response plots: one panel per input -> output channel (rows: outputs,
//! columns: inputs), named from the system file, with the exact final value of a step
//! response drawn as a dashed line. A discrete-time response (samples $y_k$ at $t = kT$)
//! is drawn as stairs: $y_k$ held on $[kT, (k+1)T)$, a dot at each sample.

use super::svg::{COLORS, Panel, Svg, finite_range, nice_range};

/// What a time-response plot shows.
pub struct TimePlot<'a> {
    pub title: &'a str,
    /// `"step response"` or `"impulse response"`: the y label's prefix.
    pub what: &'a str,
    pub times: &'a [f64],
    /// `values[k][i][j]`: output `i` for input `j` at `times[k]`.
    pub values: &'a [Vec<Vec<f64>>],
    pub inputs: &'a [String],
    pub outputs: &'a [String],
    /// Dashed reference lines per channel (the exact final value), `final_values[i][j]`.
    pub final_values: Option<&'a [Vec<f64>]>,
    /// The label of the dashed lines.
    pub final_label: &'a str,
    /// Sampled values (discrete time): drawn as stairs held over each sample period.
    pub stairs: bool,
}

/// The stairs through samples `(t_k, y_k)`: $y_k$ held until $t_{k+1}$ (the last sample
/// held for one more period).
fn stairs(pts: &[(f64, f64)]) -> Vec<(f64, f64)> {
    let mut out = Vec::with_capacity(2 * pts.len());
    for (k, &(t, y)) in pts.iter().enumerate() {
        let next = match (pts.get(k + 1), k) {
            (Some(&(tn, _)), _) => tn,
            (None, 0) => t + 1.0,
            (None, _) => t + (t - pts[k - 1].0),
        };
        out.push((t, y));
        out.push((next, y));
    }
    out
}

/// The SVG of a time-response plot.
pub fn time_response_svg(tp: &TimePlot<'_>) -> String {
    let p = tp.outputs.len();
    let m = tp.inputs.len();
    let (left, right, top, gap_x, gap_y) = (90.0, 30.0, 44.0, 70.0, 62.0);
    let total_w: f64 = if m > 2 { 360.0 * m as f64 } else { 840.0 };
    let pw =
        ((total_w - left - right - gap_x * (m.max(1) - 1) as f64) / m.max(1) as f64).max(160.0);
    let ph: f64 = if p <= 2 { 230.0 } else { 170.0 };
    let w = left + right + pw * m.max(1) as f64 + gap_x * (m.max(1) - 1) as f64;
    let h = top + (ph + gap_y) * p.max(1) as f64 + 10.0;
    let mut svg = Svg::new(w, h, tp.title);
    let mut t_end = tp.times.last().copied().unwrap_or(1.0);
    if tp.stairs && tp.times.len() > 1 {
        // the last sample is held for one period
        t_end += t_end - tp.times[tp.times.len() - 2];
    }
    let xr = if t_end > 0.0 {
        (0.0, t_end)
    } else {
        (0.0, 1.0)
    };
    for i in 0..p {
        for j in 0..m {
            let ys: Vec<f64> = tp.values.iter().map(|v| v[i][j]).collect();
            let fin = tp.final_values.map(|f| f[i][j]);
            let (lo, hi) = finite_range(ys.iter().copied().chain(fin).chain([0.0]));
            let panel = Panel {
                x0: left + (pw + gap_x) * j as f64,
                y0: top + 18.0 + (ph + gap_y) * i as f64,
                w: pw,
                h: ph,
                xr,
                yr: nice_range(lo, hi),
                logx: false,
                mirror: false,
            };
            let show_x = true;
            let xlabel = if tp.stairs {
                "time [s] (samples t = k dt)"
            } else {
                "time [s]"
            };
            svg.axes(&panel, xlabel, &tp.outputs[i], show_x);
            svg.text(
                panel.x0 + panel.w / 2.0,
                panel.y0 - 6.0,
                "middle",
                12.0,
                &format!("{} \u{2192} {}", tp.inputs[j], tp.outputs[i]),
            );
            let pts: Vec<(f64, f64)> = tp.times.iter().copied().zip(ys).collect();
            if tp.stairs {
                svg.polyline(&panel, &stairs(&pts), COLORS[0], 1.8, false);
                if pts.len() <= 200 {
                    svg.dots(&panel, &pts, COLORS[0], 2.5);
                }
            } else {
                svg.polyline(&panel, &pts, COLORS[0], 1.8, false);
            }
            if let Some(f) = fin {
                svg.polyline(&panel, &[(xr.0, f), (xr.1, f)], COLORS[1], 1.2, true);
                if i == 0 && j == m - 1 {
                    svg.legend(
                        &panel,
                        &[
                            (tp.what.to_string(), COLORS[0].to_string(), false),
                            (tp.final_label.to_string(), COLORS[1].to_string(), true),
                        ],
                    );
                }
            }
        }
    }
    svg.finish()
}

#[cfg(test)]
mod tests {
    use super::stairs;

    #[test]
    fn stairs_hold_each_sample_for_one_period() {
        let s = stairs(&[(0.0, 1.0), (0.5, 2.0), (1.0, -1.0)]);
        assert_eq!(
            s,
            vec![
                (0.0, 1.0),
                (0.5, 1.0),
                (0.5, 2.0),
                (1.0, 2.0),
                (1.0, -1.0),
                (1.5, -1.0)
            ]
        );
        assert_eq!(stairs(&[(0.0, 3.0)]), vec![(0.0, 3.0), (1.0, 3.0)]);
        assert!(stairs(&[]).is_empty());
    }
}
