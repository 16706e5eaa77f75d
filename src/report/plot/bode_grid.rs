//! The Bode plot of a MIMO system as an output x input grid (MATLAB's `bode` layout): one
//! cell per channel `u_j -> y_i` (rows: outputs, columns: inputs), each a magnitude [dB]
//! panel over a phase [deg] panel on a shared log frequency axis [Hz]; the magnitude and
//! phase scales are shared along each output row so that the channels of one output
//! compare at a glance.

use super::Response;
use super::bode::{db_ticks, phase_ticks, unwrapped_phase_deg};
use super::svg::{COLORS, Panel, Svg, finite_range, nice_range};

/// Magnitudes [dB] and unwrapped phases [deg] of channel `(i, j)`.
fn channel(resp: &Response, i: usize, j: usize) -> (Vec<f64>, Vec<f64>) {
    let ch: Vec<(f64, f64)> = resp.iter().map(|g| g[i][j]).collect();
    let mag = ch
        .iter()
        .map(|(re, im)| (20.0 * re.hypot(*im).max(1e-300).log10()).max(-400.0))
        .collect();
    (mag, unwrapped_phase_deg(&ch))
}

/// A phase range on multiples of 45 degrees (at least 90 wide).
fn phase_span(lo: f64, hi: f64) -> (f64, f64) {
    if !lo.is_finite() || !hi.is_finite() {
        return (-180.0, 180.0);
    }
    let (a, b) = ((lo / 45.0).floor() * 45.0, (hi / 45.0).ceil() * 45.0);
    if b - a < 90.0 {
        let mid = ((a + b) / 2.0 / 45.0).round() * 45.0;
        (mid - 45.0, mid + 45.0)
    } else {
        (a, b)
    }
}

/// The grid Bode plot of `resp` at `freqs` [Hz], `inputs` and `outputs` naming the columns
/// and rows; `marks`: labelled vertical lines [Hz] (the Nyquist frequency of a sampled
/// system).
pub fn bode_grid_svg(
    freqs: &[f64],
    resp: &Response,
    title: &str,
    (inputs, outputs): (&[String], &[String]),
    marks: &[(f64, &str)],
) -> String {
    let (p, m) = (outputs.len(), inputs.len());
    let (left, right, top) = (84.0, 24.0, 40.0);
    let (gap_x, gap_mp, gap_y) = (78.0, 16.0, 74.0);
    let cw: f64 = if m <= 2 { 380.0 } else { 300.0 };
    let (mh, ph) = (150.0, 110.0);
    let w = left + right + cw * m as f64 + gap_x * (m.max(1) - 1) as f64;
    let h = top + (18.0 + mh + gap_mp + ph + gap_y) * p as f64;
    let mut svg = Svg::new(w, h, title);
    let lf = finite_range(freqs.iter().map(|f| f.max(1e-300).log10()));
    for (i, out) in outputs.iter().enumerate() {
        let cells: Vec<(Vec<f64>, Vec<f64>)> = (0..m).map(|j| channel(resp, i, j)).collect();
        let (ml, mhi) = finite_range(cells.iter().flat_map(|c| c.0.iter().copied()));
        let (pl, phi) = finite_range(cells.iter().flat_map(|c| c.1.iter().copied()));
        let y0 = top + 18.0 + (18.0 + mh + gap_mp + ph + gap_y) * i as f64;
        for (j, (mag, phase)) in cells.iter().enumerate() {
            let x0 = left + (cw + gap_x) * j as f64;
            let mp = Panel {
                x0,
                y0,
                w: cw,
                h: mh,
                xr: lf,
                yr: nice_range(ml, mhi),
                logx: true,
                mirror: false,
            };
            let pp = Panel {
                y0: y0 + mh + gap_mp,
                h: ph,
                yr: phase_span(pl, phi),
                ..mp.clone()
            };
            svg.axes_with(&mp, "", "magnitude [dB]", false, Some(&db_ticks(mp.yr)));
            svg.axes_with(
                &pp,
                "frequency [Hz]",
                "phase [deg]",
                true,
                Some(&phase_ticks(pp.yr)),
            );
            svg.text(
                x0 + cw / 2.0,
                y0 - 6.0,
                "middle",
                12.0,
                &format!("{} \u{2192} {out}", inputs[j]),
            );
            for &(f, label) in marks {
                if f > 0.0 {
                    svg.vline(&mp, f, "#555", Some(label));
                    svg.vline(&pp, f, "#555", None);
                }
            }
            let col = COLORS[(i * m + j) % COLORS.len()];
            let pts = |ys: &[f64]| -> Vec<(f64, f64)> {
                freqs.iter().copied().zip(ys.iter().copied()).collect()
            };
            svg.polyline(&mp, &pts(mag), col, 1.8, false);
            svg.polyline(&pp, &pts(phase), col, 1.8, false);
        }
    }
    svg.finish()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_cell_per_channel_named_input_to_output() {
        let freqs = [0.1, 1.0, 10.0];
        // 2 outputs x 3 inputs, G_ij = (i + 1) / (j + 1) (real, constant)
        let resp: Response = freqs
            .iter()
            .map(|_| {
                (0..2)
                    .map(|i| {
                        (0..3)
                            .map(|j| ((i + 1) as f64 / (j + 1) as f64, 0.0))
                            .collect()
                    })
                    .collect()
            })
            .collect();
        let ins: Vec<String> = ["a", "b", "c"].map(String::from).to_vec();
        let outs: Vec<String> = ["y", "z"].map(String::from).to_vec();
        let svg = bode_grid_svg(&freqs, &resp, "t", (&ins, &outs), &[(5.0, "Nyquist")]);
        for i in &outs {
            for j in &ins {
                assert!(svg.contains(&format!("{j} \u{2192} {i}")), "{j} -> {i}");
            }
        }
        // 6 cells of 2 panels, each with its frame
        assert_eq!(svg.matches(r##"fill="none" stroke="#333""##).count(), 12);
        assert_eq!(svg.matches(">Nyquist<").count(), 6);
        assert_eq!(phase_span(-10.0, 10.0), (-45.0, 45.0));
        assert_eq!(phase_span(-100.0, -20.0), (-135.0, 0.0));
    }
}
