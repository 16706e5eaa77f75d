//! `--steps`: the derivation of `jordan`, `scb`, `zeros`, `tf` and of `minreal --method
//! kalman|jordan|rosenbrock|ho-kalman`, step by step,
//! over $\mathbb{Q}$ and over $\mathbb{Q}(p)$ (files with symbols, `--symbolic`, `--at`).
//!
//! The steps are computed by [`crate::jordan::steps`] and [`crate::realization::steps`] and
//! rendered by [`crate::report::steps`] (text, JSON) and [`crate::report::steps_latex`]
//! (LaTeX, written here directly: a derivation typesets as a worked example, not as a list).
//! Exit 1 when an identity of a step fails.

use super::{Command, Failure, Format, MethodArg, Outcome};
use crate::field::Field;
use crate::io::TypedAny;
use crate::io::symbolic::SymbolicOptions;
use crate::jordan::derivation::{AssumptionLog, Derivation, Method, Recorder, ratfunc_log};
use crate::matrix::Matrix;
use crate::report::steps::derivation_report;
use crate::report::steps_latex::derivation_latex;
use crate::system::StateSpace;
use std::path::Path;

/// What `--steps` derives.
#[derive(Clone, Copy)]
enum What {
    Jordan,
    Kalman,
    JordanMethod,
    Scb,
    Zeros,
    Tf,
    Rosenbrock,
    HoKalman,
}

fn refuse(message: String) -> Failure {
    Failure { code: 2, message }
}

const AVAILABLE: &str = "--steps: available for `jordan` (without --real), `scb`, `zeros`, `tf` and `minreal --method kalman|jordan|rosenbrock|ho-kalman` (not yet for `standard`, `mnf`, `jordan --real`, descriptor systems)";

/// The file and the derivation `cmd` asks for.
fn what(cmd: &Command) -> Option<(&Path, What)> {
    Some(match cmd {
        Command::Jordan {
            file, real: false, ..
        } => (file, What::Jordan),
        Command::Minreal {
            file,
            method,
            descriptor: false,
            ..
        } => (
            file,
            match method {
                MethodArg::Kalman => What::Kalman,
                MethodArg::Jordan => What::JordanMethod,
                MethodArg::Rosenbrock => What::Rosenbrock,
                MethodArg::HoKalman => What::HoKalman,
                MethodArg::Era => return None,
            },
        ),
        Command::Scb { file } => (file, What::Scb),
        Command::Zeros { file } => (file, What::Zeros),
        Command::Tf { file } => (file, What::Tf),
        _ => return None,
    })
}

/// The derivation of a system command over any field (with the assumption log over
/// $\mathbb{Q}(p)$).
fn system_steps<'a, K: Field>(
    ss: &StateSpace<K>,
    what: What,
    log: Option<AssumptionLog<'a, K>>,
) -> crate::error::Result<Derivation<K>> {
    let method = match what {
        What::Kalman => return crate::realization::steps::kalman_steps(ss, log),
        What::Scb => Method::Scb,
        What::Zeros => Method::Zeros,
        What::Tf => Method::Transfer,
        What::Rosenbrock => Method::Rosenbrock,
        What::HoKalman => Method::HoKalman,
        What::Jordan | What::JordanMethod => {
            return Err(crate::error::Error::Invalid(
                "internal: not a system derivation".into(),
            ));
        }
    };
    let k = ss.field().clone();
    let mut rec = match log {
        Some(l) => Recorder::with_log(method, k, l),
        None => Recorder::new(method, k),
    };
    let r = Some(&mut rec);
    let (a, b, c, d) = (&ss.a, &ss.b, &ss.c, &ss.d);
    match what {
        What::Scb => drop(crate::structure::scb::scb_recorded(a, b, c, d, r)?),
        What::Zeros => drop(crate::structure::zeros::invariant_zeros_recorded(
            a, b, c, d, r,
        )?),
        What::Tf => drop(ss.transfer_matrix_recorded(r)?),
        What::Rosenbrock => drop(crate::realization::minimal_rosenbrock_recorded(ss, r)?),
        _ => drop(crate::realization::minimal_ho_kalman_recorded(ss, r)?),
    }
    Ok(rec.finish())
}

/// Runs `cmd` with `--steps`; LaTeX is written to stdout here (the outcome is `streamed`).
pub fn execute(
    cmd: &Command,
    symbolic: Option<&str>,
    at: Option<&str>,
    format: Format,
    standalone: bool,
) -> Result<Outcome, Failure> {
    let Some((file, what)) = what(cmd) else {
        return Err(refuse(AVAILABLE.into()));
    };
    let opts = SymbolicOptions::from_args(symbolic, at).map_err(refuse)?;
    let sys = super::System::open(file, &opts).map_err(|e| refuse(e.to_string()))?;
    let loaded = sys.loaded();
    let e = |err: crate::error::Error| super::common::with_path(file, err);
    let out = Render { format, standalone };
    let descriptor = match &loaded.system {
        TypedAny::Rational(t) => t.descriptor.is_some(),
        TypedAny::Quadratic(t) => t.descriptor.is_some(),
        TypedAny::RatFunc(t) => t.descriptor.is_some(),
    };
    if descriptor && !matches!(what, What::Jordan) {
        return Err(refuse(format!(
            "{}: --steps for a descriptor system (a file with E) is not available yet",
            path_text(file)
        )));
    }
    match (&loaded.system, what) {
        (TypedAny::Rational(t), What::Jordan) => {
            out.show(&crate::jordan::steps::jordan_steps(&t.a_raw).map_err(e)?)
        }
        (TypedAny::RatFunc(t), What::Jordan) => {
            out.show(&crate::jordan::steps::jordan_steps_params(&t.a_raw).map_err(e)?)
        }
        (TypedAny::Rational(t), What::JordanMethod) => {
            out.show(&crate::realization::steps::jordan_method_steps(&t.ss).map_err(e)?)
        }
        (_, What::Jordan | What::JordanMethod) => Err(refuse(format!(
            "{}: --steps for this command needs rational entries (this file's lie in {})",
            path_text(file),
            loaded.file.ground
        ))),
        (TypedAny::Rational(t), w) => out.show(&system_steps(&t.ss, w, None).map_err(e)?),
        (TypedAny::Quadratic(t), w) => out.show(&system_steps(&t.ss, w, None).map_err(e)?),
        (TypedAny::RatFunc(t), w) => {
            // a fresh field: its conditions are the ones this derivation assumes
            let k = t.ss.field().fresh();
            let mv = |m: &Matrix<_>| {
                Matrix::from_vec(k.clone(), m.nrows(), m.ncols(), m.as_slice().to_vec())
            };
            let s0 = &t.ss;
            let ss = StateSpace::new(mv(&s0.a), mv(&s0.b), mv(&s0.c), mv(&s0.d)).map_err(e)?;
            out.show(&system_steps(&ss, w, Some(ratfunc_log(&k))).map_err(e)?)
        }
    }
}

fn path_text(p: &Path) -> String {
    p.display().to_string()
}

/// The output format of a derivation.
struct Render {
    format: Format,
    standalone: bool,
}

impl Render {
    fn show<K: Field>(&self, d: &Derivation<K>) -> Result<Outcome, Failure> {
        let verified = d.verified();
        if self.format != Format::Latex {
            return Ok(Outcome::new(derivation_report(d), verified));
        }
        let text = derivation_latex(d, self.standalone);
        super::write_stdout(&text)
            .map_err(|err| refuse(format!("cannot write the output: {err}")))?;
        let mut o = Outcome::new(derivation_report(d), verified);
        o.streamed = true;
        Ok(o)
    }
}
