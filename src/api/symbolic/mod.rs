//! Commands on files with symbolic parameters (over $\mathbb{Q}(p_1, \dots, p_k)$) and with
//! `--symbolic` / `--at` on the command line.
//!
//! What works over $\mathbb{Q}(p)$ (every result with `field` and `conditions`, the
//! irreducible polynomials it assumes nonzero, and `verified` = its identity holds as
//! rational functions): `linalg rank|det|charpoly|minpoly|rref|inverse|nullspace` on `A`,
//! `jordan` and `mnf` ([`super::symbolic_jordan`]), `scb`, `minreal` (Kalman, Rosenbrock,
//! Ho-Kalman), `tf` (with `E`: of the pencil), `zeros` (with the zero polynomial's factors
//! over $\mathbb{Q}(p)$), `ctrb`, `obsv`, `standard`, `analyze`, `modes` (formulas,
//! [`modes`]) ([`system`]); `pencil`, `minreal --descriptor` (generic); `bifurcations` in
//! [`super::bifurcations`]; `sweep` / `critical` along the one symbol. Every other command
//! refuses with one line and exit status 2 saying why (numbers asked of symbols: give them
//! values with `--at`).
//!
//! [`execute`] is the $\mathbb{Q}(p)$ arm of [`crate::api::System::run`]; a file whose
//! symbols all got values (`--at`) is typed over its numeric field and never comes here.

pub(super) mod conditions;
mod modes;
pub(super) mod system;

use super::common::{exact_only, linalg_report, with_path};
use super::{Command, Failure, MethodArg, Outcome};
use crate::io::symbolic::refusal;
use crate::io::{SystemFile, TypedSystem};
use crate::ratfunc::RatFuncField;
use crate::report::sections::conditions::with_conditions;
use std::path::Path;

/// A descriptor-level command ([`super::pencil_cmds`]) over $\mathbb{Q}(p)$, on a fresh
/// condition log, with `field` and `conditions`.
fn descriptor(
    cmd: &Command,
    f: &SystemFile,
    t: &TypedSystem<RatFuncField>,
    path: &Path,
) -> Result<Outcome, Failure> {
    let k = t.a_raw.field().fresh();
    let t = t.in_field(&k);
    let out = super::pencil_cmds::execute_typed(cmd, path, f, &t)?;
    let conds = k.explained().map_err(|e| with_path(path, e))?;
    let r = with_conditions(
        exact_only(out.report).str("field", k.to_string()),
        &k,
        &conds,
    );
    Ok(Outcome::new(r, out.verified))
}

/// The condition set of `linalg OP` on `a` (`conditions` module docs): the input's
/// denominators for `det` and `charpoly` (identities), with the gcd of the maximal minors for
/// `rank`; the log of the elimination for the others.
fn linalg_conditions(
    op: crate::api::args::LinalgOp,
    a: &crate::matrix::Matrix<RatFuncField>,
) -> crate::Result<Vec<crate::ratfunc::Condition>> {
    use crate::api::args::LinalgOp;
    use crate::ratfunc::{Part, Reason, Structure};
    let k = a.field();
    let mut items = conditions::denominators(Part::A, a, false);
    match op {
        LinalgOp::Det | LinalgOp::Charpoly => {}
        LinalgOp::Rank => {
            let r = a.rank();
            let why = Reason::StructureChange(Structure::Rank { rank: r });
            items.extend(a.rank_drop(r)?.all().into_iter().map(|f| (f, why)));
        }
        _ => items.extend(k.recorded_with_reasons()),
    }
    k.explain(items)
}

/// The command's name as typed.
fn name(cmd: &Command) -> &'static str {
    match cmd {
        Command::Jordan { .. } => "jordan",
        Command::Minreal { .. } => "minreal",
        Command::Standard { .. } => "standard",
        Command::Scb { .. } => "scb",
        Command::Mnf { .. } => "mnf",
        Command::Zeros { .. } => "zeros",
        Command::Pencil { .. } => "pencil",
        Command::Ctrb { .. } => "ctrb",
        Command::Obsv { .. } => "obsv",
        Command::Tf { .. } => "tf",
        Command::Modes { .. } => "modes",
        Command::Freqresp { .. } => "freqresp",
        Command::Pzmap { .. } => "pzmap",
        Command::Step { .. } => "step",
        Command::Impulse { .. } => "impulse",
        Command::Check { .. } => "check",
        Command::Poly { .. } => "poly",
        Command::Linalg { .. } => "linalg",
        Command::Analyze { .. } => "analyze",
        Command::Sweep { .. } => "sweep",
        Command::Critical { .. } => "critical",
        Command::Bifurcations { .. } => "bifurcations",
        Command::Interconnect(c) => c.name(),
        Command::Dcgain { .. } => "dcgain",
        Command::Toolbox(c) => c.name(),
        Command::Discrete(c) => c.name(),
        Command::Response(c) => c.name(),
    }
}

/// Runs `cmd` on a system over $\mathbb{Q}(p)$ (the arm of [`crate::api::System::run`] for
/// that field): its symbolic form, or one line saying why it needs numbers.
pub(super) fn execute(
    cmd: &Command,
    f: &SystemFile,
    t: &TypedSystem<RatFuncField>,
    path: &Path,
) -> Result<Outcome, Failure> {
    let refuse = |what: String| Failure::unsupported(format!("{}: {what}", path.display()));
    let k = t.a_raw.field();
    match cmd {
        Command::Linalg { op, .. } => {
            let k = k.fresh();
            let a = t.a_raw.map(&k, |x| x.clone());
            let r = linalg_report(*op, &a, path)?;
            let conds = linalg_conditions(*op, &a).map_err(|e| with_path(path, e))?;
            Ok(Outcome::plain(with_conditions(
                exact_only(r).str("field", k.to_string()),
                &k,
                &conds,
            )))
        }
        Command::Jordan {
            normalize: Some(n),
            real,
            ..
        } => {
            let how = crate::api::a_only::normalization(Some(n), *real)?;
            let run = |af: &crate::matrix::Matrix<RatFuncField>| {
                crate::api::symbolic_jordan::normalized_outcome(af, &how)
                    .map_err(|e| with_path(path, e))
            };
            match t.descriptor.as_ref() {
                Some(d) => crate::api::a_only::descriptor_jordan_with(d, path, run),
                None => run(&t.a_raw),
            }
        }
        // a descriptor file: the Jordan form of the pencil's finite part (not of A alone)
        Command::Jordan { real, .. } if t.descriptor.is_some() => {
            let d = t.descriptor.as_ref().expect("descriptor");
            let real = *real;
            crate::api::a_only::descriptor_jordan_with(d, path, |af| {
                let r = if real {
                    crate::api::symbolic_jordan::real_outcome(af)
                } else {
                    crate::api::symbolic_jordan::jordan_outcome(af)
                };
                r.map_err(|e| with_path(path, e))
            })
        }
        Command::Jordan { real: false, .. } => {
            crate::api::symbolic_jordan::jordan_outcome(&t.a_raw).map_err(|e| with_path(path, e))
        }
        Command::Mnf { .. } => {
            crate::api::symbolic_jordan::mnf_outcome(&t.ss.a, &t.ss.b, &t.ss.c, &t.ss.d)
                .map_err(|e| with_path(path, e))
        }
        // numbers asked of symbols: not a question over Q(p)
        Command::Freqresp { .. }
        | Command::Pzmap { .. }
        | Command::Step { .. }
        | Command::Impulse { .. }
        | Command::Check { .. }
        | Command::Sweep { .. }
        | Command::Critical { .. }
        | Command::Toolbox(_)
        | Command::Minreal {
            method: MethodArg::Era,
            descriptor: false,
            ..
        } => Err(super::ground::needs_numbers(k, name(cmd), path)),
        Command::Jordan { real: true, .. } => {
            crate::api::symbolic_jordan::real_outcome(&t.a_raw).map_err(|e| with_path(path, e))
        }
        // the descriptor-level commands, generic over the field
        Command::Pencil { .. }
        | Command::Minreal {
            descriptor: true, ..
        } => descriptor(cmd, f, t, path),
        Command::Ctrb { .. } | Command::Obsv { .. } if t.descriptor.is_some() => {
            descriptor(cmd, f, t, path)
        }
        _ => match system::run(cmd, f, t, path)? {
            Some(out) => Ok(out),
            None => Err(refuse(refusal(&format!("`{}`", name(cmd)), k))),
        },
    }
}
