//! `--steps`: the derivation of `jordan` and of `minreal --method kalman|jordan`, step by step,
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
use crate::jordan::derivation::{Derivation, ratfunc_log};
use crate::report::steps::derivation_report;
use crate::report::steps_latex::derivation_latex;
use std::path::Path;

/// What `--steps` derives.
#[derive(Clone, Copy)]
enum What {
    Jordan,
    Kalman,
    JordanMethod,
}

fn refuse(message: String) -> Failure {
    Failure { code: 2, message }
}

/// Runs `cmd` with `--steps`; LaTeX is written to stdout here (the outcome is `streamed`).
pub fn execute(
    cmd: &Command,
    symbolic: Option<&str>,
    at: Option<&str>,
    format: Format,
    standalone: bool,
) -> Result<Outcome, Failure> {
    let (file, what) = match cmd {
        Command::Jordan {
            file, real: false, ..
        } => (file, What::Jordan),
        Command::Minreal {
            file,
            method: MethodArg::Kalman,
            descriptor: false,
            ..
        } => (file, What::Kalman),
        Command::Minreal {
            file,
            method: MethodArg::Jordan,
            descriptor: false,
            ..
        } => (file, What::JordanMethod),
        _ => {
            return Err(refuse(
                "--steps: available for `jordan` (without --real) and `minreal --method kalman|jordan`"
                    .into(),
            ));
        }
    };
    let opts = SymbolicOptions::from_args(symbolic, at).map_err(refuse)?;
    let sys = super::System::open(file, &opts).map_err(|e| refuse(e.to_string()))?;
    let loaded = sys.loaded();
    let e = |err: crate::error::Error| super::common::with_path(file, err);
    let out = Render { format, standalone };
    match (&loaded.system, what) {
        (TypedAny::Rational(t), What::Jordan) => {
            out.show(&crate::jordan::steps::jordan_steps(&t.a_raw).map_err(e)?)
        }
        (TypedAny::RatFunc(t), What::Jordan) => {
            out.show(&crate::jordan::steps::jordan_steps_params(&t.a_raw).map_err(e)?)
        }
        (TypedAny::Rational(t), What::Kalman) => {
            out.show(&crate::realization::steps::kalman_steps(&t.ss, None).map_err(e)?)
        }
        (TypedAny::Quadratic(t), What::Kalman) => {
            out.show(&crate::realization::steps::kalman_steps(&t.ss, None).map_err(e)?)
        }
        (TypedAny::RatFunc(t), What::Kalman) => {
            let k = t.ss.field().fresh();
            let mv = |m: &crate::matrix::Matrix<_>| {
                crate::matrix::Matrix::from_vec(
                    k.clone(),
                    m.nrows(),
                    m.ncols(),
                    m.as_slice().to_vec(),
                )
            };
            let (s0, log) = (&t.ss, Some(ratfunc_log(&k)));
            let ss = crate::system::StateSpace::new(mv(&s0.a), mv(&s0.b), mv(&s0.c), mv(&s0.d))
                .map_err(e)?;
            out.show(&crate::realization::steps::kalman_steps(&ss, log).map_err(e)?)
        }
        (TypedAny::Rational(t), What::JordanMethod) => {
            out.show(&crate::realization::steps::jordan_method_steps(&t.ss).map_err(e)?)
        }
        _ => Err(refuse(format!(
            "{}: --steps for this command needs rational entries (this file's lie in {})",
            path_text(file),
            loaded.file.ground
        ))),
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
