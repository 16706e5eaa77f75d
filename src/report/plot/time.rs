//! Step and impulse response plots: one panel per input -> output channel (rows: outputs,
//! columns: inputs), named from the system file, with the exact final value of a step
//! response drawn as a dashed line.

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
    let t_end = tp.times.last().copied().unwrap_or(1.0);
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
            svg.axes(&panel, "time [s]", &tp.outputs[i], show_x);
            svg.text(
                panel.x0 + panel.w / 2.0,
                panel.y0 - 6.0,
                "middle",
                12.0,
                &format!("{} \u{2192} {}", tp.inputs[j], tp.outputs[i]),
            );
            let pts: Vec<(f64, f64)> = tp.times.iter().copied().zip(ys).collect();
            svg.polyline(&panel, &pts, COLORS[0], 1.8, false);
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
