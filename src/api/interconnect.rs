//! `series`, `parallel`, `feedback`, `append`: thin wrapper over
//! [`crate::system::interconnect`] (the operations and their exact check),
//! [`crate::io::combine`] (the files over one field), [`crate::realization::minimal`]
//! (`--minreal`), [`crate::report::sections::interconnection_report`] and
//! [`crate::io::write`] (`--out`: the result as a system file that reads back).

use super::common::with_path;
use super::{Failure, Outcome};
use crate::io::combine::{SystemsVisitor, common_field};
use crate::io::symbolic::SymbolicOptions;
use crate::io::{InputError, TypedSystem};
use crate::realization::{MinrealMethod, minimal};
use crate::report::sections::{PartInfo, interconnection_report};
use crate::system::interconnect::{Interconnection, Operation, Sign, verify};
use clap::Subcommand;
use std::path::{Path, PathBuf};

pub use super::interconnect_common::InterconnectOpts;
use super::interconnect_common::{common_dt, write_system_file};

/// The interconnection subcommands (python-control's conventions).
#[derive(Subcommand, Debug, Clone)]
pub enum InterconnectCmd {
    /// Series connection G then H (python-control `series(G, H)` = H * G): transfer
    /// matrix H G, states [x_G; x_H].
    Series {
        /// The first system (its outputs feed H).
        g: PathBuf,
        /// The second system.
        h: PathBuf,
        #[command(flatten)]
        opts: InterconnectOpts,
    },
    /// Parallel connection: transfer matrix G + H.
    Parallel {
        g: PathBuf,
        h: PathBuf,
        #[command(flatten)]
        opts: InterconnectOpts,
    },
    /// Feedback u = r - K y around G: transfer matrix (I + G K)^-1 G (with --positive
    /// u = r + K y, (I - G K)^-1 G). K is a system file or a static gain (a file with only D).
    Feedback {
        /// The system in the forward path.
        g: PathBuf,
        /// The feedback path: a system, or a file with only `D` (a gain).
        k: PathBuf,
        /// Positive feedback (sign +1).
        #[arg(long)]
        positive: bool,
        #[command(flatten)]
        opts: InterconnectOpts,
    },
    /// The systems side by side: transfer matrix diag(G1, G2, ...).
    Append {
        /// The systems, in order.
        #[arg(required = true, num_args = 1..)]
        files: Vec<PathBuf>,
        #[command(flatten)]
        opts: InterconnectOpts,
    },
    /// Connect systems by signal names (python-control's `interconnect`), from a connection
    /// file: {"systems": ["plant.json", "ctrl.json"], "connections": [["u", "v"], ["e",
    /// "-y"]], "inputs": ["e"], "outputs": ["y"]} (paths relative to the file; each
    /// connection: an input, then the outputs summed into it, `-y` subtracts; an external
    /// input drives the subsystem inputs of its name: here e = r - y with r external).
    Connect {
        /// The connection file (JSON, or TOML by its extension).
        file: PathBuf,
        #[command(flatten)]
        opts: InterconnectOpts,
    },
}

impl InterconnectCmd {
    /// The command's name as typed.
    pub fn name(&self) -> &'static str {
        match self.parts() {
            Some((op, ..)) => op.name(),
            None => "connect",
        }
    }
    /// The files, in order (`connect`: its connection file).
    pub fn files(&self) -> Vec<&Path> {
        match (self, self.parts()) {
            (InterconnectCmd::Connect { file, .. }, _) => vec![file.as_path()],
            (_, Some((_, files, _))) => files,
            (_, None) => vec![],
        }
    }
    /// The operation, its files and options; `None` for `connect` (a connection file).
    fn parts(&self) -> Option<(Operation, Vec<&Path>, &InterconnectOpts)> {
        Some(match self {
            InterconnectCmd::Series { g, h, opts } => (Operation::Series, vec![g, h], opts),
            InterconnectCmd::Parallel { g, h, opts } => (Operation::Parallel, vec![g, h], opts),
            InterconnectCmd::Feedback {
                g,
                k,
                positive,
                opts,
            } => {
                let s = if *positive {
                    Sign::Positive
                } else {
                    Sign::Negative
                };
                (Operation::Feedback(s), vec![g, k], opts)
            }
            InterconnectCmd::Append { files, opts } => (
                Operation::Append,
                files.iter().map(PathBuf::as_path).collect(),
                opts,
            ),
            InterconnectCmd::Connect { .. } => return None,
        })
    }
    /// [`Self::parts`], or the error that `connect` reads its connection file.
    fn parts_or_fail(&self) -> Result<(Operation, Vec<&Path>, &InterconnectOpts), Failure> {
        self.parts().ok_or_else(|| {
            Failure::input(
                "connect: reads its connection file (exactlti connect FILE; in Python \
                 exactlti.interconnect)"
                    .into(),
            )
        })
    }
}

/// Runs an interconnection command on its files, each read once by the one reader
/// ([`super::System::open_or_gain`]: a file with only `D` is a static gain).
pub fn run(cmd: &InterconnectCmd, sym: &SymbolicOptions) -> Result<Outcome, Failure> {
    if let InterconnectCmd::Connect { file, opts } = cmd {
        return super::connect_file::run(file, opts, sym);
    }
    let (_, paths, _) = cmd.parts_or_fail()?;
    let systems = paths
        .iter()
        .map(|p| super::System::open_or_gain(p, sym))
        .collect::<Result<Vec<_>, InputError>>()?;
    run_on(cmd, &systems.iter().collect::<Vec<_>>())
}

/// Runs an interconnection command on systems already read, in the order of the command's
/// files (named by them in the report).
///
/// # Errors
/// Systems over two different fields; a count other than the command's; the errors of
/// the interconnection.
pub fn run_on(cmd: &InterconnectCmd, systems: &[&super::System]) -> Result<Outcome, Failure> {
    let (op, _, opts) = cmd.parts_or_fail()?;
    let (names, signals) = checked_parts(cmd, systems)?;
    let loaded: Vec<_> = systems.iter().map(|s| s.loaded()).collect();
    let systems = common_field(&loaded)?;
    systems.run(Connect {
        op,
        names,
        opts,
        signals,
    })
}

/// The checks both entry points share: one system per file of the command, one time domain.
/// Returns the files' names and the result's signal names (with the common sample time).
fn checked_parts(
    cmd: &InterconnectCmd,
    systems: &[&super::System],
) -> Result<(Vec<String>, crate::io::SignalNames), Failure> {
    let (op, paths, _) = cmd.parts_or_fail()?;
    if systems.len() != paths.len() {
        return Err(Failure::input(format!(
            "{}: needs {} systems (got {})",
            op.name(),
            paths.len(),
            systems.len()
        )));
    }
    let names: Vec<String> = paths.iter().map(|p| p.display().to_string()).collect();
    let dt = common_dt(op, &names, systems)?;
    Ok((names, result_signals(op, systems, dt)))
}

/// The signal names and sample time of the result: python-control's rules for names (the
/// inputs of the first system and the outputs of the last in a series, of the first in a
/// parallel connection or a feedback loop), states left unnamed.
fn result_signals(
    op: Operation,
    systems: &[&super::System],
    dt: Option<crate::field::Rational>,
) -> crate::io::SignalNames {
    let sig = |i: usize| {
        systems
            .get(i)
            .map(|s| s.file().signals.clone())
            .unwrap_or_default()
    };
    let (inputs, outputs) = match op {
        Operation::Series => (sig(0).inputs, sig(systems.len().saturating_sub(1)).outputs),
        Operation::Parallel | Operation::Feedback(_) => (sig(0).inputs, sig(0).outputs),
        Operation::Append => {
            let cat = |f: fn(&crate::io::SignalNames) -> Option<Vec<String>>| {
                systems
                    .iter()
                    .map(|s| f(&s.file().signals))
                    .collect::<Option<Vec<_>>>()
                    .map(|v| v.concat())
            };
            (cat(|s| s.inputs.clone()), cat(|s| s.outputs.clone()))
        }
    };
    crate::io::SignalNames {
        inputs,
        outputs,
        states: None,
        dt,
    }
}

struct Connect<'a> {
    op: Operation,
    names: Vec<String>,
    opts: &'a InterconnectOpts,
    signals: crate::io::SignalNames,
}

impl SystemsVisitor for Connect<'_> {
    type Output = Result<Outcome, Failure>;
    fn visit<K: crate::io::GroundField>(self, systems: &[TypedSystem<K>]) -> Self::Output {
        let what = format!("{} {}", self.op.name(), self.names.join(" "));
        let e = |err| with_path(Path::new(&what), err);
        let parts: Vec<_> = systems.iter().map(|t| t.ss.clone()).collect();
        let conn = Interconnection::of(self.op, &parts).map_err(e)?;
        let sys = conn.compute().map_err(e)?;
        let min = if self.opts.minreal {
            Some(minimal(&sys, MinrealMethod::Kalman).map_err(e)?)
        } else {
            None
        };
        // over Q(p): the conditions of the result, before the check evaluates at points
        let symbols = sys
            .field()
            .symbolic()
            .map(|k| (k.vars().to_vec(), k.conditions_strings()));
        let verified = verify(&conn, &sys);
        let info: Vec<PartInfo> = self
            .names
            .iter()
            .zip(&parts)
            .map(|(n, s)| PartInfo {
                name: n.clone(),
                states: s.nstates(),
                inputs: s.ninputs(),
                outputs: s.noutputs(),
            })
            .collect();
        let mut report = interconnection_report(self.op, &info, &sys, verified, min.as_ref());
        if let Some((_, conds)) = &symbols {
            let conds = conds.clone().map_err(e)?;
            report = report.with("conditions", crate::report::str_list(conds));
        }
        if let Some(out) = &self.opts.out {
            let written = min.as_ref().map_or(&sys, |m| &m.system);
            let vars = symbols.map(|s| s.0).unwrap_or_default();
            let name = format!("{} of {}", self.op.name(), self.names.join(", "));
            write_system_file(out, &name, written, &vars, &self.signals)?;
            report = report.str("written", out.display().to_string());
        }
        let ok = verified && min.as_ref().is_none_or(|m| m.verified);
        Ok(Outcome::new(report, ok))
    }
}

/// The interconnection of `systems` (in the order of the command's files) as a system of
/// its own (the Python operators `G * H`, `G + H`, `-G`, `G.feedback(K)`): the exact result,
/// its signal names and sample time by python-control's rules ([`result_signals`]).
///
/// # Errors
/// As [`run_on`]: a wrong count, two fields, two time domains, the interconnection's own.
pub fn system_of(
    cmd: &InterconnectCmd,
    systems: &[&super::System],
) -> Result<super::System, Failure> {
    let (op, _, _) = cmd.parts_or_fail()?;
    let (names, signals) = checked_parts(cmd, systems)?;
    let loaded: Vec<_> = systems.iter().map(|s| s.loaded()).collect();
    let name = format!("{} of {}", op.name(), names.join(", "));
    let sys = common_field(&loaded)?.run(Build { op, name: &name })?;
    Ok(sys.with_signals(signals))
}

struct Build<'a> {
    op: Operation,
    name: &'a str,
}

impl SystemsVisitor for Build<'_> {
    type Output = Result<super::System, Failure>;
    fn visit<K: crate::io::GroundField>(self, systems: &[TypedSystem<K>]) -> Self::Output {
        let e = |err| with_path(Path::new(self.name), err);
        let parts: Vec<_> = systems.iter().map(|t| t.ss.clone()).collect();
        let conn = Interconnection::of(self.op, &parts).map_err(e)?;
        let ss = conn.compute().map_err(e)?;
        if !verify(&conn, &ss) {
            return Err(Failure::verification(format!(
                "{}: the exact check of the interconnection failed",
                self.name
            )));
        }
        let typed = TypedSystem {
            descriptor: None,
            a_raw: ss.a.clone(),
            ss,
        };
        Ok(super::System::from_ground(self.name, typed))
    }
}
