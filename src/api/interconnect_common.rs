//! What the interconnection commands share ([`super::interconnect`] for `series`, `parallel`,
//! `feedback`, `append`; [`super::connect_file`] and [`super::connect_names`] for `connect`):
//! their options, the common sample time and the `--out` system file.

use super::Failure;
use crate::field::Field;
use crate::system::interconnect::Operation;
use std::path::{Path, PathBuf};

/// Options of every interconnection.
#[derive(clap::Args, Debug, Clone)]
pub struct InterconnectOpts {
    /// Also the exact minimal realization of the result (Kalman decomposition), verified.
    #[arg(long)]
    pub minreal: bool,
    /// Write the result (the minimal realization with --minreal) as a JSON system file.
    #[arg(long, value_name = "OUT.json")]
    pub out: Option<PathBuf>,
}

/// The sample time shared by every system (`None`: all continuous). A static gain (no
/// states) fits either.
///
/// # Errors
/// A continuous and a discrete system, or two different sample times, named by file.
pub(crate) fn common_dt(
    op: Operation,
    names: &[String],
    systems: &[&super::System],
) -> Result<Option<crate::field::Rational>, Failure> {
    let mut seen: Option<(usize, Option<crate::field::Rational>)> = None;
    for (i, s) in systems.iter().enumerate() {
        if s.nstates() == 0 && s.dt().is_none() {
            continue; // a static gain
        }
        let dt = s.file().signals.dt.clone();
        match &seen {
            None => seen = Some((i, dt)),
            Some((j, d0)) if *d0 != dt => {
                let show = |d: &Option<crate::field::Rational>| {
                    d.as_ref().map_or("continuous time".to_string(), |d| {
                        format!("dt = {}", crate::report::display::fmt_rational(d))
                    })
                };
                return Err(Failure::input(format!(
                    "{}: cannot connect {} ({}) with {} ({}): every system needs the same time domain and sample time (convert with c2d or d2c)",
                    op.name(),
                    names[*j],
                    show(d0),
                    names[i],
                    show(&dt)
                )));
            }
            Some(_) => {}
        }
    }
    Ok(seen.and_then(|(_, d)| d))
}

/// Writes `sys` as a JSON system file to `out` (`--out` of the interconnection commands);
/// a `.toml` name is an input error (only JSON is written).
pub(crate) fn write_system_file<K: Field>(
    out: &Path,
    name: &str,
    sys: &crate::system::StateSpace<K>,
    vars: &[String],
    signals: &crate::io::keys::SignalNames,
) -> Result<(), Failure> {
    if out
        .extension()
        .is_some_and(|x| x.eq_ignore_ascii_case("toml"))
    {
        return Err(Failure::input(format!(
            "{}: --out writes JSON; name the file .json",
            out.display()
        )));
    }
    let text = crate::io::write::system_file_text(Some(name), sys, vars, signals);
    std::fs::write(out, text)
        .map_err(|err| Failure::input(format!("{}: cannot write: {err}", out.display())))
}
