//! Commands on files with symbolic parameters (over $\mathbb{Q}(p_1, \dots, p_k)$) and with
//! `--symbolic` / `--at` on the command line.
//!
//! What works over $\mathbb{Q}(p)$ (every result with `field` and `conditions`, the
//! irreducible polynomials it assumes nonzero, and `verified` = its identity holds as
//! rational functions): `linalg rank|det|charpoly|minpoly|rref|inverse|nullspace` on `A`,
//! `jordan` and `mnf` ([`super::symbolic_jordan`]), `scb`, `minreal` (Kalman, Rosenbrock,
//! Ho-Kalman), `tf`, `zeros` (with the zero polynomial's factors over $\mathbb{Q}(p)$), `ctrb`,
//! `obsv`, `standard`, `analyze`
//! ([`system`]); `bifurcations` in [`super::bifurcations`]. Every other command refuses with
//! one line and exit status 2 (`modes`: give values with `--at`).
//!
//! This module imports only leaf command modules (`common`, `symbolic_jordan`): a file whose
//! symbols all got values is handed back ([`Handled::Valued`]) to the ordinary dispatch.

mod modes;
pub(super) mod system;

use super::common::{exact_only, linalg_report, with_path};
use super::{Command, Failure, Outcome};
use crate::io::symbolic::{SymbolicOptions, load_symbolic_path, refusal};
use crate::io::{LoadedSystem, TypedAny};
use crate::report::str_list;
use std::path::{Path, PathBuf};

/// What [`execute`] did with a command.
pub(super) enum Handled {
    /// Computed over $\mathbb{Q}(p)$ (or refused).
    Done(Outcome),
    /// `--at` gave every symbol a value: the ordinary command on this system.
    Valued(Box<LoadedSystem>, PathBuf),
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
    }
}

fn file_of(cmd: &Command) -> Option<&Path> {
    match cmd {
        Command::Jordan { file, .. }
        | Command::Minreal { file, .. }
        | Command::Standard { file }
        | Command::Scb { file }
        | Command::Mnf { file }
        | Command::Zeros { file }
        | Command::Pencil { file }
        | Command::Ctrb { file }
        | Command::Obsv { file }
        | Command::Tf { file }
        | Command::Modes { file }
        | Command::Freqresp { file, .. }
        | Command::Pzmap { file, .. }
        | Command::Step { file, .. }
        | Command::Impulse { file, .. }
        | Command::Check { file }
        | Command::Sweep { file, .. }
        | Command::Critical { file, .. }
        | Command::Linalg { file, .. } => Some(file),
        Command::Analyze { file, .. } => file.as_deref(),
        Command::Poly { .. }
        | Command::Bifurcations { .. }
        | Command::Interconnect(_)
        | Command::Dcgain { .. } => None,
    }
}

/// Handles `cmd` when its file has symbols or the command line gives `--symbolic`/`--at`;
/// `Ok(None)`: an ordinary file, left to the ordinary dispatch.
pub(super) fn execute(cmd: &Command, opts: &SymbolicOptions) -> Result<Option<Handled>, Failure> {
    let Some(path) = file_of(cmd) else {
        return Ok(None);
    };
    // cheap test: a file without symbols and no command-line say is left alone
    if opts.is_empty() {
        let text = crate::io::read_text(path).unwrap_or_default();
        if !text.contains("symbols") && !text.contains("null") {
            return Ok(None);
        }
    }
    let loaded = match load_symbolic_path(path, opts) {
        Ok(l) => l,
        // the ordinary reader reports its own errors
        Err(_) if opts.is_empty() => return Ok(None),
        Err(e) => {
            return Err(Failure {
                code: 2,
                message: e.to_string(),
            });
        }
    };
    let refuse = |what: String| Failure {
        code: 2,
        message: format!("{}: {what}", path.display()),
    };
    let direct = matches!(
        cmd,
        Command::Jordan { .. }
            | Command::Minreal { .. }
            | Command::Standard { .. }
            | Command::Scb { .. }
            | Command::Mnf { .. }
            | Command::Zeros { .. }
            | Command::Modes { .. }
            | Command::Freqresp { .. }
            | Command::Pzmap { .. }
            | Command::Step { .. }
            | Command::Impulse { .. }
            | Command::Check { .. }
            | Command::Linalg { .. }
    );
    match &loaded.system {
        TypedAny::RatFunc(t) => {
            let k = t.a_raw.field();
            match cmd {
                Command::Sweep { param, .. } | Command::Critical { param, .. } => {
                    // the swept parameter may be `null` (the study gives it its values);
                    // every other symbol needs a number: a plot and a crossing are numbers
                    let other: Vec<&String> = k.vars().iter().filter(|v| *v != param).collect();
                    if !opts.is_empty() {
                        return Err(refuse(format!(
                            "`{}` does not take --symbolic or --at yet; write the values into the file",
                            name(cmd)
                        )));
                    }
                    if other.is_empty() {
                        return Ok(None);
                    }
                    let list: Vec<&str> = other.iter().map(|s| s.as_str()).collect();
                    Err(refuse(format!(
                        "`{}` along {param} needs a number for every other parameter ({} without one); write their values into the file",
                        name(cmd),
                        list.join(", ")
                    )))
                }
                Command::Linalg { op, .. } => {
                    let k = k.fresh();
                    let a = t.a_raw.map(&k, |x| x.clone());
                    let r = linalg_report(*op, &a, path)?;
                    let conds = k.conditions_strings().map_err(|e| with_path(path, e))?;
                    Ok(Some(Handled::Done(Outcome::plain(
                        exact_only(r)
                            .str("field", k.to_string())
                            .with("conditions", str_list(conds)),
                    ))))
                }
                Command::Jordan { real: false, .. } => {
                    crate::cli::symbolic_jordan::jordan_outcome(&t.a_raw)
                        .map(|o| Some(Handled::Done(o)))
                        .map_err(|e| with_path(path, e))
                }
                Command::Mnf { .. } => {
                    crate::cli::symbolic_jordan::mnf_outcome(&t.ss.a, &t.ss.b, &t.ss.c, &t.ss.d)
                        .map(|o| Some(Handled::Done(o)))
                        .map_err(|e| with_path(path, e))
                }
                _ => match system::run(cmd, &loaded.file, t, path)? {
                    Some(out) => Ok(Some(Handled::Done(out))),
                    None => Err(refuse(refusal(&format!("`{}`", name(cmd)), k))),
                },
            }
        }
        _ if opts.is_empty() => Ok(None),
        _ if direct => Ok(Some(Handled::Valued(Box::new(loaded), path.to_path_buf()))),
        _ => Err(refuse(format!(
            "`{}` does not take --symbolic or --at yet; write the values into the file",
            name(cmd)
        ))),
    }
}
