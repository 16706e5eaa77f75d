//! The descriptor-level commands: `pencil`, `ctrb`, `obsv`, `tf`, `minreal --descriptor`,
//! and `zeros` of a file with `E` (contract, second wave). Load with
//! [`crate::io::load_descriptor::load_descriptor_path`], compute, report.

use super::common::with_path;
use super::{Command, Failure, Outcome};
use crate::field::Field;
use crate::io::load_descriptor::{
    DescriptorVisitor, GivenTransfer, LoadedDescriptor, load_descriptor_path,
};
use crate::io::{GroundField, SystemFile, TypedSystem};
use crate::matrix::Matrix;
use crate::pencil::pencil_structure;
use crate::realization::{
    controllability_structure, descriptor_controllability, descriptor_transfer_matrix,
    minimal_descriptor, observability_structure, realize_state_space, realize_transfer,
};
use crate::report::sections;
use crate::structure::descriptor_zeros::descriptor_zeros;
use crate::system::discrete::stability::Domain;
use crate::system::{Descriptor, StateSpace};
use std::path::Path;

/// Whether a command goes through this module (`zeros` only for systems with `E` or `G`,
/// `minreal` only with `--descriptor`); `file`: the system as read, `None` when the
/// ordinary reader refused the file (then the top-level keys are looked at).
pub fn handles(cmd: &Command, file: Option<&SystemFile>) -> bool {
    match cmd {
        Command::Pencil { .. }
        | Command::Ctrb { .. }
        | Command::Obsv { .. }
        | Command::Tf { .. } => true,
        Command::Minreal { descriptor, .. } => *descriptor,
        Command::Zeros { file: path } => match file {
            Some(f) => f.e.is_some() || f.extra.contains_key("G"),
            None => file_has_key(path, "E") || file_has_key(path, "G"),
        },
        _ => false,
    }
}

/// Runs a command of [`handles`] on a system already read (with `--at` values): the
/// descriptor `E x' = A x + B u` as given, or `E = I`.
pub fn execute_typed<K: GroundField>(
    cmd: &Command,
    path: &Path,
    f: &SystemFile,
    t: &TypedSystem<K>,
) -> Result<Outcome, Failure> {
    let (desc, has_e) = match &t.descriptor {
        Some(d) => (d.clone(), true),
        None => {
            let s = &t.ss;
            let i = Matrix::identity(s.a.field().clone(), s.nstates());
            let d = Descriptor::new(i, s.a.clone(), s.b.clone(), s.c.clone(), s.d.clone())
                .map_err(|err| with_path(path, err))?;
            (d, false)
        }
    };
    run_on(cmd, path, (has_e, &f.signals), None, &desc)
}

/// The rows and columns of a transfer matrix by name (`outputs`, `inputs`) when the file
/// names them (a model file: its sensors and actuators).
fn channel_names(rep: &mut crate::report::Report, s: &crate::io::SignalNames, p: usize, m: usize) {
    let strs = |v: &[String]| {
        crate::report::Value::List(v.iter().cloned().map(crate::report::Value::Str).collect())
    };
    if let Some(o) = s.outputs.as_ref().filter(|o| o.len() == p) {
        rep.push("outputs", strs(o));
    }
    if let Some(i) = s.inputs.as_ref().filter(|i| i.len() == m) {
        rep.push("inputs", strs(i));
    }
}

/// The report with the file's sample time `dt` after its `variable` (discrete time only).
fn with_dt(rep: crate::report::Report, s: &crate::io::SignalNames) -> crate::report::Report {
    match &s.dt {
        Some(dt) => {
            let mut items = Vec::with_capacity(rep.items.len() + 1);
            for (k, v) in rep.items {
                let after = k == "variable";
                items.push((k, v));
                if after {
                    items.push((
                        "dt".to_string(),
                        crate::report::Value::Str(crate::report::display::fmt_rational(dt)),
                    ));
                }
            }
            crate::report::Report {
                title: rep.title,
                items,
            }
        }
        None => rep,
    }
}

/// A cheap look at the top-level keys (the full reader validates later).
fn file_has_key(path: &Path, key: &str) -> bool {
    let Ok(text) = crate::io::read_text(path) else {
        return false;
    };
    if path.extension().is_some_and(|x| x == "toml") {
        toml::from_str::<toml::Value>(&text).is_ok_and(|v| v.get(key).is_some())
    } else {
        serde_json::from_str::<serde_json::Value>(&text).is_ok_and(|v| v.get(key).is_some())
    }
}

/// Runs one of the commands of [`handles`].
pub fn execute(cmd: &Command, path: &Path) -> Result<Outcome, Failure> {
    let l = load_descriptor_path(path)?;
    if let Some((a, e)) = &l.pencil {
        if !matches!(cmd, Command::Pencil { .. }) {
            return Err(Failure::input(format!(
                "{}: key A: must be square (a rectangular A is a pencil: use `exactlti pencil`)",
                path.display()
            )));
        }
        let ps = pencil_structure(a, e).map_err(|err| with_path(path, err))?;
        return Ok(Outcome::new(sections::pencil_report(&ps), ps.verified));
    }
    l.run(Run { cmd, path })
}

struct Run<'a> {
    cmd: &'a Command,
    path: &'a Path,
}

impl DescriptorVisitor for Run<'_> {
    type Output = Result<Outcome, Failure>;
    fn visit<K: GroundField>(
        self,
        l: &LoadedDescriptor,
        s: &Descriptor<K>,
        transfer: Option<&GivenTransfer<K>>,
    ) -> Self::Output {
        run_on(self.cmd, self.path, (l.has_e, &l.signals), transfer, s)
    }
}

/// One command on a descriptor system; `has_e`: the file gave `E`; `signals`: the file's
/// names of inputs and outputs; `transfer`: the file's `G` and its realization.
fn run_on<K: GroundField>(
    cmd: &Command,
    path: &Path,
    (has_e, signals): (bool, &crate::io::SignalNames),
    transfer: Option<&GivenTransfer<K>>,
    s: &Descriptor<K>,
) -> Result<Outcome, Failure> {
    {
        let e = |err| with_path(path, err);
        let domain = Domain::of(signals.dt.as_ref());
        match cmd {
            Command::Pencil { .. } => {
                let ps = pencil_structure(&s.a, &s.e).map_err(e)?;
                Ok(Outcome::new(sections::pencil_report(&ps), ps.verified))
            }
            Command::Ctrb { .. } | Command::Obsv { .. } => {
                let dual = matches!(cmd, Command::Obsv { .. });
                if has_e {
                    let d = descriptor_controllability(s, dual).map_err(e)?;
                    let r = sections::descriptor_ctrb_report(&d, dual).map_err(e)?;
                    Ok(Outcome::new(r, d.verified()))
                } else {
                    let c = if dual {
                        observability_structure(&s.a, &s.c)
                    } else {
                        controllability_structure(&s.a, &s.b)
                    }
                    .map_err(e)?;
                    Ok(Outcome::new(
                        sections::ctrb_report(&c, dual).map_err(e)?,
                        c.verified,
                    ))
                }
            }
            Command::Minreal { .. } => {
                let m = minimal_descriptor(s).map_err(e)?;
                Ok(Outcome::new(
                    sections::minreal_descriptor_report(&m),
                    m.verified,
                ))
            }
            Command::Zeros { .. } => {
                let z = descriptor_zeros(s).map_err(e)?;
                let v = z.pencil.verified;
                Ok(Outcome::new(
                    sections::descriptor_zeros_report(&z, domain).map_err(e)?,
                    v,
                ))
            }
            Command::Tf { .. } => {
                // a state-space input: its own (Kalman) minimal realization, and G checked
                // against its Markov parameters; a descriptor: G realized entry by entry
                let mut markov = None;
                let (g, r) = match transfer {
                    Some((g, r)) => (g.clone(), r.clone()),
                    None if !has_e => {
                        let ss =
                            StateSpace::new(s.a.clone(), s.b.clone(), s.c.clone(), s.d.clone())
                                .map_err(e)?;
                        let g = ss.transfer_matrix().map_err(e)?;
                        let r = realize_state_space(&ss, &g).map_err(e)?;
                        markov = Some(g.matches_markov(&ss));
                        (g, r)
                    }
                    None => {
                        let g = descriptor_transfer_matrix(s).map_err(e)?;
                        let r = realize_g(s, &g).map_err(e)?;
                        (g, r)
                    }
                };
                let mut rep = with_dt(
                    sections::tf_report(&g, &r, markov, domain).map_err(e)?,
                    signals,
                );
                channel_names(
                    &mut rep,
                    signals,
                    g.entries.len(),
                    g.entries.first().map_or(0, Vec::len),
                );
                let ok = matches!(rep.get("verified"), Some(crate::report::Value::Bool(true)));
                Ok(Outcome::new(rep, ok))
            }
            _ => Err(Failure::verification(
                "internal: command not handled by the descriptor commands".into(),
            )),
        }
    }
}

/// The minimal realization of `g`, the transfer matrix of the descriptor system `s`; without
/// inputs or without outputs `g` is the empty `p x m` matrix (no entry to realize), realized
/// by the order-0 system `D` (`p x m`).
fn realize_g<K: Field>(
    s: &Descriptor<K>,
    g: &crate::system::transfer::TransferMatrix<K>,
) -> crate::Result<crate::realization::TransferRealization<K>> {
    let (p, m) = (s.c.nrows(), s.b.ncols());
    if p > 0 && m > 0 {
        return realize_transfer(g);
    }
    let k = s.a.field().clone();
    let zero = |r, c| Matrix::zeros(k.clone(), r, c);
    let s0 = StateSpace::new(zero(0, 0), zero(0, m), zero(p, 0), s.d.clone())?;
    realize_state_space(&s0, g)
}
