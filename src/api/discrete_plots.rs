//! Plots of a discrete-time system (file key `dt`): the Bode plot of
//! $G(e^{j 2\pi f T})$ up to the Nyquist frequency $1/(2T)$ [Hz], marked by a vertical
//! line, and step/impulse responses as stairs (sample $y_k$ held on $[kT, (k+1)T)$).
//! Float values for drawing only; the exact sequences are in the reports.

use super::Failure;
use super::float_cmds::{FloatAbcd, float_abcd, float_response_dt};
use crate::field::{Field, Rational, rational_to_f64};
use crate::io::{GroundField, SystemFile, TypedSystem};
use crate::report::plot::bode::bode_svg_marked;
use crate::report::plot::time::{TimePlot, time_response_svg};
use crate::report::plot::{logspace, response_table};
use crate::system::dcgain::gain_at;
use crate::system::discrete::stability::{Domain, Verdict};
use std::path::Path;

fn write(out: &Path, text: &str) -> Result<(), Failure> {
    std::fs::write(out, text)
        .map_err(|err| Failure::input(format!("{}: cannot write: {err}", out.display())))
}

/// Writes the Bode SVG of a sampled system over `[from, to]` Hz (`to` at most the Nyquist
/// frequency $1/(2T)$, where the response of a sampled system is periodic).
pub fn bode_file_dt<K: Field>(
    f: &SystemFile,
    t: &TypedSystem<K>,
    path: &Path,
    dt: &Rational,
    (from, to, points): (f64, f64, usize),
    out: &Path,
) -> Result<(), Failure> {
    let (title, ins, outs) = super::plots::names(f, path, t.ss.ninputs(), t.ss.noutputs());
    let sys = float_abcd(t, path)?;
    if matches!(sys, FloatAbcd::Complex(_)) {
        return Err(Failure::unsupported(format!(
            "{}: --svg: the Bode plot of a discrete-time system with complex coefficients is not drawn (use --csv)",
            path.display()
        )));
    }
    let labels: Vec<Vec<String>> = outs
        .iter()
        .map(|o| ins.iter().map(|i| format!("{i} \u{2192} {o}")).collect())
        .collect();
    let t_s = rational_to_f64(dt);
    let nyquist = 0.5 / t_s;
    let freqs = logspace(from, to, points);
    let resp = float_response_dt(t, &sys, path, &freqs, Some(t_s))?;
    let title = format!(
        "{title}: Bode plot of G(e^(j 2 pi f T)), T = {} s",
        crate::report::display::fmt_rational(dt)
    );
    let label = format!(
        "Nyquist 1/(2T) = {} Hz",
        crate::report::text::short(nyquist)
    );
    let marks: Vec<(f64, &str)> = if to >= nyquist * (1.0 - 1e-9) {
        vec![(nyquist, label.as_str())]
    } else {
        vec![]
    };
    let table = response_table(&resp);
    let svg = if ins.len() * outs.len() > 1 {
        // MIMO: an output x input grid of magnitude and phase panels
        let g = crate::report::plot::bode_grid::bode_grid_svg;
        g(&freqs, &table, &title, (&ins, &outs), &marks)
    } else {
        bode_svg_marked(&freqs, &table, &title, &labels, &marks)
    };
    write(out, &svg)
}

/// What a sampled time response shows.
pub struct Stairs<'a> {
    pub title: &'a str,
    pub impulse: bool,
    pub times: &'a [f64],
    pub values: &'a [Vec<Vec<f64>>],
    pub inputs: &'a [String],
    pub outputs: &'a [String],
}

/// The exact final value $G(1)$ of a step response when the system is asymptotically stable
/// (decided exactly over its field, $|z| < 1$), as floats for the dashed line (real parts
/// under the marked embedding); `None` over a field without numbers.
fn final_values<K: GroundField>(t: &TypedSystem<K>) -> Option<Vec<Vec<f64>>> {
    let st = super::ground::stability_over(&t.ss.a, Domain::Discrete).ok()?;
    if st.verdict != Verdict::AsymptoticallyStable {
        return None;
    }
    let k = t.ss.field();
    let g = gain_at(&t.ss, &k.one()).ok()?;
    let m = g.matrix?;
    (0..m.nrows())
        .map(|i| m.row(i).iter().map(|x| k.approx(x).map(|z| z.0)).collect())
        .collect()
}

/// Writes the stairs SVG of a sampled step or impulse response (step: with the exact
/// final value $G(1)$ dashed when the system is stable).
pub fn stairs_file<K: GroundField>(
    t: &TypedSystem<K>,
    plot: &Stairs<'_>,
    out: &Path,
) -> Result<(), Failure> {
    let fin = if plot.impulse { None } else { final_values(t) };
    let what = if plot.impulse {
        "impulse response"
    } else {
        "step response"
    };
    let tp = TimePlot {
        title: &format!("{}: {what} (discrete time)", plot.title),
        what,
        times: plot.times,
        values: plot.values,
        inputs: plot.inputs,
        outputs: plot.outputs,
        final_values: fin.as_deref(),
        final_label: "final value G(1) (exact)",
        stairs: true,
    };
    write(out, &time_response_svg(&tp))
}
