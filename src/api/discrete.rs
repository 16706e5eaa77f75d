//! Discrete time at the front door: `stability` (exact, for a continuous or a sampled
//! system), `c2d`, `d2c`, and the commands on a system with a sample time (the file key
//! `dt`): `step`/`impulse` as exact difference-equation sequences, `freqresp` on the unit
//! circle, and a refusal naming the reason for the commands whose meaning is continuous
//! time (margins, damping, Gramians, modes, sweeps). Thin wrapper over
//! [`crate::system::discrete`] and [`crate::report::sections`].

use super::common::with_path;
use super::{Failure, Outcome};
use crate::field::{Field, Q, Rational, rational_to_f64};
use crate::io::{GroundField, SystemFile, TypedSystem};
use crate::report::Value;
use crate::report::display::fmt_rational;
use crate::report::sections::{conversion_report, sequence_report, stability_report};
use crate::system::StateSpace;
use crate::system::discrete::stability::Domain;
use crate::system::discrete::{impulse_sequence, step_sequence, tustin, tustin_inverse, zoh_exact};
use clap::Subcommand;
use std::path::{Path, PathBuf};

/// How `c2d` discretizes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, clap::ValueEnum)]
pub enum C2dMethod {
    /// Bilinear s = (2/T)(z - 1)/(z + 1): exact over every field.
    #[default]
    Tustin,
    /// Zero-order hold: A_d = e^(A T) in floating point (the result's entries are the
    /// binary floats, written as the decimals they are).
    Zoh,
}

/// The discrete-time subcommands.
#[derive(Subcommand, Debug, Clone)]
pub enum DiscreteCmd {
    /// Exact stability over Q, Q(sqrt d), Q(i) without floats: every eigenvalue in Re s < 0,
    /// or |z| < 1 for a file with `dt` (Schur-Cohn / Jury per irreducible factor of
    /// det(sI - A) over the field, a Sturm count on the circle, the minimal polynomial for
    /// marginal stability).
    Stability {
        /// System file (JSON or TOML; see "FILE" in `exactlti --help`).
        file: PathBuf,
    },
    /// Continuous to discrete time with sample time --dt (python-control's `c2d`).
    C2d {
        /// System file of a continuous-time system.
        file: PathBuf,
        /// Sample time in seconds: an exact number (0.1 is 1/10).
        #[arg(long)]
        dt: String,
        /// tustin (exact) or zoh (float matrix exponential).
        #[arg(long, value_enum, default_value_t = C2dMethod::Tustin)]
        method: C2dMethod,
        /// Write the result as a JSON system file (with its `dt`).
        #[arg(long, value_name = "OUT.json")]
        out: Option<PathBuf>,
    },
    /// Discrete to continuous time, the exact inverse of Tustin (python-control's `d2c`).
    D2c {
        /// System file with `dt`.
        file: PathBuf,
        /// Write the result as a JSON system file.
        #[arg(long, value_name = "OUT.json")]
        out: Option<PathBuf>,
    },
}

impl DiscreteCmd {
    /// The command's name as typed.
    pub fn name(&self) -> &'static str {
        match self {
            DiscreteCmd::Stability { .. } => "stability",
            DiscreteCmd::C2d { .. } => "c2d",
            DiscreteCmd::D2c { .. } => "d2c",
        }
    }
    /// The system file.
    pub fn file(&self) -> &Path {
        match self {
            DiscreteCmd::Stability { file }
            | DiscreteCmd::C2d { file, .. }
            | DiscreteCmd::D2c { file, .. } => file,
        }
    }
}

fn fail(path: &Path, message: impl Into<String>) -> Failure {
    Failure::input(format!("{}: {}", path.display(), message.into()))
}

/// Runs a discrete-time subcommand on a system over its field.
pub fn run<K: GroundField>(
    cmd: &DiscreteCmd,
    f: &SystemFile,
    t: &TypedSystem<K>,
    path: &Path,
) -> Result<Outcome, Failure> {
    let dt = f.signals.dt.as_ref();
    if t.descriptor.is_some() {
        return Err(fail(
            path,
            "a descriptor system (key E): convert it with `exactlti standard` first",
        ));
    }
    let e = |err| with_path(path, err);
    match cmd {
        DiscreteCmd::Stability { .. } => {
            let domain = if dt.is_some() {
                Domain::Discrete
            } else {
                Domain::Continuous
            };
            let s = super::ground::stability_over(&t.ss.a, domain).map_err(e)?;
            Ok(Outcome::plain(stability_report(&s, dt)))
        }
        DiscreteCmd::C2d {
            dt: text,
            method,
            out,
            ..
        } => {
            if let Some(d) = dt {
                return Err(fail(
                    path,
                    format!("already a discrete-time system (dt = {})", fmt_rational(d)),
                ));
            }
            let step = crate::field::parse_rational(text)
                .map_err(|m| fail(path, format!("--dt '{text}': {m}")))?;
            if step <= Rational::from_integer(0.into()) {
                return Err(fail(path, format!("--dt must be positive, found {text}")));
            }
            let (sys_text, rep) = match method {
                C2dMethod::Tustin => {
                    let d = tustin(&t.ss, &step).map_err(e)?;
                    let back = tustin_inverse(&d, &step).map_err(e)?;
                    let ok = back == t.ss;
                    let rep = conversion_report(
                        "c2d (Tustin, exact)",
                        "tustin: s = (2/T)(z - 1)/(z + 1); A_d = (I - A T/2)^-1 (I + A T/2), B_d = T (I - A T/2)^-1 B, C_d = C (I - A T/2)^-1, D_d = D + C B_d / 2",
                        &step,
                        &d,
                        Some(("d2c(c2d(G)) = G exactly (A, B, C, D)", ok)),
                    );
                    (written(f, &d, &step), (rep, ok))
                }
                C2dMethod::Zoh => {
                    if let Some(z) = zoh_exact(&t.ss, &step).map_err(e)? {
                        let rep = conversion_report(
                            "c2d (zero-order hold, exact)",
                            "zoh with A nilpotent: A_d = e^(A T) = sum_{k<n} A^k T^k / k!, B_d = sum_{k<n} A^k T^(k+1) / (k+1)! B (the series stop)",
                            &step,
                            &z.system,
                            Some((
                                "log(A_d) = A T and A_d - I = A Gamma, B_d = Gamma B, exactly",
                                z.verified,
                            )),
                        );
                        (written(f, &z.system, &step), (rep, z.verified))
                    } else {
                        let d = zoh_of(t, path, &step)?;
                        let rep = conversion_report(
                            "c2d (zero-order hold, float)",
                            "zoh: A_d = e^(A T), B_d = int_0^T e^(A tau) dtau B from the float matrix exponential of [[A, B], [0, 0]] T; the entries are binary floats written exactly",
                            &step,
                            &d,
                            None,
                        )
                        .str(
                            "why_float",
                            "A has an eigenvalue lambda != 0: e^(A T) holds e^(lambda T), transcendental (Lindemann-Weierstrass), so no exact result over a number field; exact only for nilpotent A (integrator chains)",
                        );
                        (written(f, &d, &step), (rep, true))
                    }
                }
            };
            finish(rep, out.as_deref(), &sys_text)
        }
        DiscreteCmd::D2c { out, .. } => {
            let Some(step) = dt else {
                return Err(fail(
                    path,
                    "d2c needs a discrete-time system: the file has no `dt`",
                ));
            };
            let c = tustin_inverse(&t.ss, step).map_err(e)?;
            let ok = tustin(&c, step).map_err(e)? == t.ss;
            let rep = conversion_report(
                "d2c (Tustin inverse, exact)",
                "tustin inverse: N = (A_d + I)^-1, A = (2/T)(A_d - I) N, B = (2/T) N B_d, C = 2 C_d N, D = D_d - C_d N B_d",
                step,
                &c,
                Some(("c2d(d2c(G)) = G exactly (A, B, C, D)", ok)),
            );
            let mut file = f.clone();
            file.signals.dt = None;
            let text = written_plain(&file, &c);
            finish((rep, ok), out.as_deref(), &text)
        }
    }
}

/// The zoh discretization over Q (float exponential, exact rationals of the floats).
fn zoh_of<K: Field>(
    t: &TypedSystem<K>,
    path: &Path,
    dt: &Rational,
) -> Result<StateSpace<Q>, Failure> {
    let e = |err| with_path(path, err);
    let conv = |m| crate::float::to_dmatrix(m).map_err(e);
    let (a, b) = (conv(&t.ss.a)?, conv(&t.ss.b)?);
    let (ad, bd) = crate::float::time_response::zoh(&a, &b, rational_to_f64(dt)).map_err(e)?;
    let exact = |m: &nalgebra::DMatrix<f64>| -> Result<crate::matrix::Matrix<Q>, Failure> {
        let rows: Option<Vec<Vec<Rational>>> = (0..m.nrows())
            .map(|i| {
                (0..m.ncols())
                    .map(|j| Rational::from_float(m[(i, j)]))
                    .collect()
            })
            .collect();
        let rows = rows.ok_or_else(|| fail(path, "zoh: a non-finite entry"))?;
        if m.nrows() == 0 || m.ncols() == 0 {
            return Ok(crate::matrix::Matrix::zeros(Q, m.nrows(), m.ncols()));
        }
        crate::matrix::Matrix::from_rows(Q, rows).map_err(e)
    };
    let (c, d) = (conv(&t.ss.c)?, conv(&t.ss.d)?);
    StateSpace::new(exact(&ad)?, exact(&bd)?, exact(&c)?, exact(&d)?).map_err(e)
}

fn written<K: GroundField>(f: &SystemFile, s: &StateSpace<K>, dt: &Rational) -> String {
    let mut file = f.clone();
    file.signals.dt = Some(dt.clone());
    written_plain(&file, s)
}

fn written_plain<K: GroundField>(f: &SystemFile, s: &StateSpace<K>) -> String {
    let mut signals = f.signals.clone();
    signals.states = None;
    crate::io::write::system_file_text(f.name.as_deref(), s, &symbols_of(s), &signals)
}

fn symbols_of<K: GroundField>(s: &StateSpace<K>) -> Vec<String> {
    s.field()
        .symbolic()
        .map(|k| k.vars().to_vec())
        .unwrap_or_default()
}

fn finish(
    (rep, ok): (crate::report::Report, bool),
    out: Option<&Path>,
    text: &str,
) -> Result<Outcome, Failure> {
    let mut rep = rep;
    if let Some(out) = out {
        std::fs::write(out, text)
            .map_err(|err| Failure::input(format!("{}: cannot write: {err}", out.display())))?;
        rep = rep.str("written", out.display().to_string());
    }
    Ok(Outcome::new(rep, ok))
}

/// What a command does on a system with a sample time: `Some` when it is answered here
/// (step, impulse, freqresp) or refused (continuous-time meaning), `None` when the command
/// means the same in discrete time (structure, realizations, poles and zeros).
pub fn on_sampled<K: GroundField>(
    cmd: &super::Command,
    f: &SystemFile,
    t: &TypedSystem<K>,
    path: &Path,
) -> Option<Result<Outcome, Failure>> {
    use super::Command as C;
    let dt = f.signals.dt.as_ref()?;
    let refuse = |what: &str| {
        Some(Err(fail(
            path,
            format!(
                "`{what}` is for continuous-time systems; this system has dt = {} (discrete time). \
                 For a sampled system: step, impulse, dcgain, freqresp, stability, tf, pzmap, \
                 zeros, jordan, minreal, ctrb, obsv, d2c",
                fmt_rational(dt)
            ),
        )))
    };
    match cmd {
        C::Step { opts, .. } | C::Impulse { opts, .. } => {
            let impulse = matches!(cmd, C::Impulse { .. });
            Some(sequence(f, t, path, dt, impulse, opts))
        }
        C::Freqresp { .. } => Some(super::freqresp_cmd::freqresp_command(cmd, f, t, path)),
        C::Analyze { .. } => refuse("analyze"),
        C::Modes { .. } => refuse("modes"),
        C::Mnf { .. } => refuse("mnf"),
        C::Sweep { .. } => refuse("sweep"),
        C::Critical { .. } => refuse("critical"),
        C::Toolbox(c) => refuse(c.name()),
        _ => None,
    }
}

/// Exact step/impulse sequences of a sampled system with float values for plots.
fn sequence<K: GroundField>(
    f: &SystemFile,
    t: &TypedSystem<K>,
    path: &Path,
    dt: &Rational,
    impulse: bool,
    opts: &super::TimeOpts,
) -> Result<Outcome, Failure> {
    let samples = match (opts.points, opts.to) {
        (Some(n), _) => n,
        (None, Some(to)) => (to / rational_to_f64(dt)).floor() as usize + 1,
        (None, None) => 51,
    };
    if !(2..=10_000).contains(&samples) {
        return Err(fail(
            path,
            format!("need 2 to 10000 samples (--points, or --to / dt + 1); got {samples}"),
        ));
    }
    let what = if impulse {
        "impulse response"
    } else {
        "step response"
    };
    let seq = if impulse {
        impulse_sequence(&t.ss, samples, dt)
    } else {
        step_sequence(&t.ss, samples)
    };
    let k = t.ss.field();
    let approx: Option<Vec<Vec<Vec<f64>>>> = seq
        .iter()
        .map(|m| {
            (0..m.nrows())
                .map(|i| m.row(i).iter().map(|x| k.approx(x).map(|z| z.0)).collect())
                .collect()
        })
        .collect();
    let times: Vec<f64> = (0..samples)
        .map(|i| i as f64 * rational_to_f64(dt))
        .collect();
    let (_, ins, outs) = super::plots::names(f, path, t.ss.ninputs(), t.ss.noutputs());
    let mut rep = sequence_report(what, dt, &seq, (&ins, &outs)).str(
        "method",
        if impulse {
            "difference equation x[k+1] = A x[k] + B u[k] from x[0] = 0 with a unit-area pulse u[0] = 1/dt (python-control, MATLAB): y[0] = D/dt, y[k] = C A^(k-1) B / dt"
        } else {
            "difference equation x[k+1] = A x[k] + B u[k] from x[0] = 0 with u[k] = 1: y[k] = D + sum_{i<k} C A^i B"
        },
    );
    if let Some(vals) = &approx {
        rep = rep
            .list("times_s", times.iter().map(|x| Value::Float(*x)).collect())
            .list(
                "response",
                vals.iter()
                    .map(|g| {
                        Value::List(
                            g.iter()
                                .map(|r| Value::List(r.iter().map(|x| Value::Float(*x)).collect()))
                                .collect(),
                        )
                    })
                    .collect(),
            );
        if let Some(out) = &opts.csv {
            let mut text = String::from("sample,time_s");
            for o in &outs {
                for i in &ins {
                    text.push_str(&format!(",{i} -> {o}"));
                }
            }
            text.push('\n');
            for (n, g) in vals.iter().enumerate() {
                text.push_str(&format!("{n},{}", times[n]));
                for v in g.iter().flatten() {
                    text.push_str(&format!(",{v}"));
                }
                text.push('\n');
            }
            std::fs::write(out, text).map_err(|err| fail(out, format!("cannot write: {err}")))?;
        }
        if let Some(out) = &opts.svg {
            let (title, ..) = super::plots::names(f, path, t.ss.ninputs(), t.ss.noutputs());
            let plot = super::discrete_plots::Stairs {
                title: &title,
                impulse,
                times: &times,
                values: vals,
                inputs: &ins,
                outputs: &outs,
            };
            super::discrete_plots::stairs_file(t, &plot, out)?;
            rep = rep.str("svg", out.display().to_string());
        }
    } else if opts.svg.is_some() {
        return Err(fail(
            path,
            "--svg: the samples have no float values over this field (use --format json)",
        ));
    }
    Ok(Outcome::new(rep.bool("verified", true), true))
}
