//! Reports of the control engineer's toolbox: `margin` (exact crossovers and margins),
//! `damp` (damping table, rad/s and Hz), `gram` (exact Gramian and its check) and
//! `stepinfo` (float step characteristics per channel).

use crate::algebraic::AlgebraicNumber;
use crate::field::Field;
use crate::float::stepinfo::{NoStepInfo, StepInfo};
use crate::realization::{DampRow, GramType, Gramian};
use crate::report::display::fmt_rational;
use crate::report::text::short;
use crate::report::{Report, Value};
use crate::system::margins::{Margins, to_db};

/// Significant digits of the certified decimals of exact numbers.
const DIGITS: usize = 15;

/// `value` (exact display), `minpoly`, `decimal` (certified digits) and `approx`.
fn algebraic(r: Report, key: &str, x: &AlgebraicNumber) -> Report {
    r.str(key, x.value_string())
        .str(&format!("{key}_minpoly"), x.minpoly().to_string())
        .str(&format!("{key}_decimal"), x.digits(DIGITS).0)
        .float(&format!("{key}_approx"), x.approx().0)
}

fn inf() -> Value {
    Value::Str("inf".into())
}

/// The `margin` report: python-control's four numbers (`gain_margin`, `phase_margin_deg`,
/// `phase_crossover_frequency`, `gain_crossover_frequency`; `inf` / `null` when there is no
/// crossover), exact where exact, and every crossing.
pub fn margins_report<K: crate::field::Field>(m: &Margins<K>) -> Report {
    let mut r = Report::titled("gain and phase margins")
        .str(
            "transfer_function",
            format!(
                "({})/({})",
                m.num.to_string_var("s"),
                m.den.to_string_var("s")
            ),
        )
        .str("phase_crossing_polynomial", m.imag_poly.to_string_var("w"))
        .str(
            "gain_crossing_polynomial",
            m.magnitude_poly.to_string_var("w"),
        );
    match m.gain_margin() {
        Some(c) => {
            r = algebraic(r, "gain_margin", &c.gain_margin)
                .float("gain_margin_db", to_db(c.gain_margin.approx().0));
            r = algebraic(r, "phase_crossover_frequency", &c.w);
        }
        None => {
            r = r
                .with("gain_margin", inf())
                .with("gain_margin_db", inf())
                .with("phase_crossover_frequency", Value::Null);
        }
    }
    match m.phase_margin() {
        Some(c) => {
            r = r.float("phase_margin_deg", c.phase_margin_deg);
            r = algebraic(r, "phase_margin_cos", &c.cos_phase_margin);
            r = algebraic(r, "gain_crossover_frequency", &c.w);
        }
        None => {
            r = r
                .with("phase_margin_deg", inf())
                .with("gain_crossover_frequency", Value::Null);
        }
    }
    let pcs = m
        .phase_crossings
        .iter()
        .map(|c| {
            let o = algebraic(Report::new(), "w", &c.w);
            Value::Obj(
                algebraic(o, "gain_margin", &c.gain_margin)
                    .float("gain_margin_db", to_db(c.gain_margin.approx().0)),
            )
        })
        .collect();
    let pc_rows = m
        .phase_crossings
        .iter()
        .map(|c| {
            vec![
                c.w.digits(10).0,
                c.gain_margin.digits(10).0,
                short(to_db(c.gain_margin.approx().0)),
                clip(&c.gain_margin.value_string()),
            ]
        })
        .collect();
    let gcs = m
        .gain_crossings
        .iter()
        .map(|c| {
            let o =
                algebraic(Report::new(), "w", &c.w).float("phase_margin_deg", c.phase_margin_deg);
            Value::Obj(algebraic(o, "cos_phase_margin", &c.cos_phase_margin))
        })
        .collect();
    let gc_rows = m
        .gain_crossings
        .iter()
        .map(|c| {
            vec![
                c.w.digits(10).0,
                short(c.phase_margin_deg),
                clip(&c.cos_phase_margin.value_string()),
            ]
        })
        .collect();
    let h = |xs: &[&str]| xs.iter().map(|s| s.to_string()).collect::<Vec<_>>();
    r.with(
        "phase_crossings",
        Value::table(
            Value::List(pcs),
            h(&["w (rad/s)", "gain margin", "dB", "exact"]),
            pc_rows,
        ),
    )
    .with(
        "gain_crossings",
        Value::table(
            Value::List(gcs),
            h(&["w (rad/s)", "phase margin (deg)", "cos(phase margin)"]),
            gc_rows,
        ),
    )
    .bool("real_everywhere", m.real_everywhere)
    .bool("unit_gain_everywhere", m.unit_gain_everywhere)
    .bool("verified", m.verified)
}

/// A display cut to 80 characters for a table cell (JSON keeps it whole).
fn clip(s: &str) -> String {
    if s.chars().count() <= 80 {
        s.to_string()
    } else {
        format!("{}...", s.chars().take(77).collect::<String>())
    }
}

/// The `damp` report: `poles[]` with `pole`, `approx`, `multiplicity`,
/// `natural_frequency_rad_s`, `natural_frequency_hz`, `damping_ratio`, `time_constant_s`
/// and the exact `wn_squared`, `two_zeta_wn`, `time_constant_exact` where rational.
pub fn damp_report(rows: &[DampRow]) -> Report {
    let opt = |x: Option<f64>| x.map_or(Value::Null, Value::Float);
    let ex = |x: &Option<crate::field::Rational>| {
        x.as_ref()
            .map_or(Value::Null, |q| Value::Str(fmt_rational(q)))
    };
    let data = rows
        .iter()
        .map(|d| {
            Value::Obj(
                Report::new()
                    .math(
                        "pole",
                        d.pole.value_string(),
                        crate::report::latex::algebraic_latex(&d.pole),
                    )
                    .str("minpoly", d.pole.minpoly().to_string())
                    .with(
                        "approx",
                        Value::List(vec![Value::Float(d.approx.0), Value::Float(d.approx.1)]),
                    )
                    .int("multiplicity", d.multiplicity)
                    .float("natural_frequency_rad_s", d.wn_rad_s)
                    .float("natural_frequency_hz", d.wn_hz)
                    .with("damping_ratio", opt(d.zeta))
                    .with("time_constant_s", opt(d.time_constant_s))
                    .with("wn_squared", ex(&d.wn_squared))
                    .with("two_zeta_wn", ex(&d.two_zeta_wn))
                    .with("time_constant_exact", ex(&d.time_constant_exact)),
            )
        })
        .collect();
    let header = [
        "pole",
        "mult.",
        "wn (rad/s)",
        "wn (Hz)",
        "zeta",
        "tau (s)",
        "wn^2",
        "2 zeta wn",
    ]
    .map(String::from)
    .to_vec();
    let dash = |x: &Option<crate::field::Rational>| {
        x.as_ref().map_or("-".into(), |q| clip(&fmt_rational(q)))
    };
    let text = rows
        .iter()
        .map(|d| {
            let shown = d.pole.value_string();
            let pole = if shown.chars().count() <= 40 {
                shown
            } else {
                crate::report::text::short_complex(d.approx)
            };
            vec![
                pole,
                d.multiplicity.to_string(),
                short(d.wn_rad_s),
                short(d.wn_hz),
                d.zeta.map_or("-".into(), short),
                d.time_constant_s.map_or("-".into(), short),
                dash(&d.wn_squared),
                dash(&d.two_zeta_wn),
            ]
        })
        .collect();
    Report::titled("damping table").with("poles", Value::table(Value::List(data), header, text))
}

/// The `gram` report: `type`, `W` (exact, with `W_approx`), the equation, `verified`.
pub fn gram_report<F: Field>(g: &Gramian<F>) -> Report {
    let (t, eq) = match (g.kind, g.hermitian) {
        (GramType::Controllability, false) => ("c", "A W + W A^T + B B^T = 0"),
        (GramType::Observability, false) => ("o", "A^T W + W A + C^T C = 0"),
        (GramType::Controllability, true) => ("c", "A W + W A^H + B B^H = 0"),
        (GramType::Observability, true) => ("o", "A^H W + W A + C^H C = 0"),
    };
    Report::titled("Gramian")
        .str("type", t)
        .str("equation", eq)
        .matrix::<F>("W", &g.w)
        .bool("verified", g.verified)
}

/// One channel of `stepinfo` (python-control's keys), or `null` values with the `reason`.
pub fn stepinfo_channel(output: &str, input: &str, info: Result<&StepInfo, &str>) -> Report {
    let r = Report::new().str("output", output).str("input", input);
    match info {
        Ok(s) => r
            .float("RiseTime", s.rise_time)
            .with(
                "SettlingTime",
                s.settling_time.map_or(Value::Null, Value::Float),
            )
            .floats(&[
                ("SettlingMin", s.settling_min),
                ("SettlingMax", s.settling_max),
                ("Overshoot", s.overshoot),
                ("Undershoot", s.undershoot),
                ("Peak", s.peak),
                ("PeakTime", s.peak_time),
                ("SteadyStateValue", s.steady_state_value),
            ]),
        Err(why) => r.str("reason", why),
    }
}

/// The reason a channel has no step characteristics, in words.
pub fn no_stepinfo_reason(e: NoStepInfo) -> &'static str {
    match e {
        NoStepInfo::ZeroFinalValue => "the final value is 0 (rise and settling are relative to it)",
        NoStepInfo::NotReached => {
            "the response does not reach 90 % of its final value on this horizon (raise --to)"
        }
        NoStepInfo::BadSamples => "the response is not finite on this horizon",
    }
}

/// The text table of `stepinfo` channels.
pub fn stepinfo_table(channels: Vec<Report>) -> Value {
    let header = [
        "channel",
        "rise (s)",
        "settling (s)",
        "overshoot (%)",
        "peak",
        "peak time (s)",
        "final value",
    ]
    .map(String::from)
    .to_vec();
    let cell = |r: &Report, k: &str| match r.get(k) {
        Some(Value::Float(x)) => short(*x),
        _ => "-".into(),
    };
    let rows = channels
        .iter()
        .map(|r| {
            let name = |k| match r.get(k) {
                Some(Value::Str(s)) => s.clone(),
                _ => String::new(),
            };
            let mut row = vec![format!("{} <- {}", name("output"), name("input"))];
            for k in [
                "RiseTime",
                "SettlingTime",
                "Overshoot",
                "Peak",
                "PeakTime",
                "SteadyStateValue",
            ] {
                row.push(cell(r, k));
            }
            if let Some(Value::Str(why)) = r.get("reason") {
                row[1] = why.clone();
            }
            row
        })
        .collect();
    Value::table(
        Value::List(channels.into_iter().map(Value::Obj).collect()),
        header,
        rows,
    )
}
