//! `analyze`: every section that applies, as one report.
//!
//! Each section is computed under its own budget (`--section-seconds`, default 10 s, never
//! more than what is left of `--max-seconds`; see [`crate::api::budget`]) and, in text mode,
//! printed as soon as it is done. A section that runs out of time is reported in place
//! (`skipped`, with the reason and the command that insists) and the report goes on; a section
//! that cannot be computed says why (`error`, or `not_applicable` for a condition of the
//! method). When the exact Jordan form hits a limit of the implementation
//! ([`Error::is_unable`]), the float backend's guess is added as `float_fallback` (marked
//! `exact: false`). When `--max-seconds` ran out before any section was done, the command
//! stops with exit status 2 and no report; when it ran out later, the report is complete with
//! the sections cut marked, and the exit status is 2.

mod eigen;
mod runner;

use super::budget::{Budget, Events};
use super::{Failure, Outcome};
use crate::error::Error;
use crate::field::Field;
use crate::io::{GroundField, SystemFile, TypedSystem};
use crate::realization;
use crate::report::{Report, Value, str_list};
use eigen::eigen_sections;
pub(crate) use eigen::structure_section;
use runner::{Insist, Section, Sections};
use std::sync::Arc;

/// How `analyze` runs: the budget of its sections and where finished sections stream.
#[derive(Debug, Default)]
pub struct AnalyzeOptions {
    pub budget: Budget,
    pub events: Events,
    /// `--full`: compute the free response however large.
    pub full: bool,
}

/// A section that does not apply to this system: the title and why (never silently absent).
fn not_applicable(title: &str, why: impl Into<String>) -> Value {
    Value::Obj(Report::titled(title).str("not_applicable", why))
}

fn system_section<K: Field>(f: &SystemFile, t: &TypedSystem<K>) -> Report {
    let mut r = Report::titled("system")
        .str("file", f.path.clone())
        .str("name", f.name.clone().unwrap_or_default())
        .str("field", f.ground.to_string())
        .int("states", t.ss.nstates())
        .int("inputs", t.ss.ninputs())
        .int("outputs", t.ss.noutputs());
    if let Some(d) = &t.descriptor {
        r = r
            .str("form", "descriptor")
            .int("descriptor_states", d.nstates());
    } else if f.is_second_order() {
        r = r.str("form", "second order");
    } else {
        r = r.str("form", "state space");
    }
    // the signals' names from the file (`inputs`, `outputs`, `states`)
    for (key, names) in [
        ("input_names", &f.signals.inputs),
        ("output_names", &f.signals.outputs),
        ("state_names", &f.signals.states),
    ] {
        if let Some(v) = names {
            r = r.with(key, str_list(v.clone()));
        }
    }
    match t.ss.a.charpoly() {
        Ok(p) => r.str("charpoly", p.to_string_var("s")),
        Err(e) => r.str("charpoly", "").str("charpoly_error", e.to_string()),
    }
}

/// Whether the minimal realization was verified, and the realization section.
fn realization_section<K: Field>(t: &TypedSystem<K>) -> Result<(bool, Report), Error> {
    let s = &t.ss;
    let rc = realization::controllability_matrix(&s.a, &s.b).rank();
    let ro = realization::observability_matrix(&s.a, &s.c).rank();
    let min = realization::minimal_kalman(s)?;
    let tf = s.transfer_matrix()?;
    let r = Report::titled("realization")
        .int("controllability_rank", rc)
        .int("observability_rank", ro)
        .bool("controllable", rc == s.nstates())
        .bool("observable", ro == s.nstates())
        .int("mcmillan_degree", min.order)
        .with(
            "transfer_matrix",
            Value::List(tf.to_strings().into_iter().map(str_list).collect()),
        )
        .obj("minimal_realization", min.report());
    Ok((min.verified, r))
}

/// The whole analysis with the default budgets and nothing streamed.
pub fn analyze<K: GroundField>(f: &SystemFile, t: &TypedSystem<K>) -> Result<Outcome, Failure> {
    analyze_with(f, t, &AnalyzeOptions::default())
}

/// The whole analysis; `verified` is the conjunction of every exact check made.
pub fn analyze_with<K: GroundField>(
    f: &SystemFile,
    t: &TypedSystem<K>,
    opts: &AnalyzeOptions,
) -> Result<Outcome, Failure> {
    let title = format!(
        "exactlti analysis: {}",
        f.name.clone().unwrap_or_else(|| f.path.clone())
    );
    let file = (!f.path.starts_with("built-in:")).then(|| f.path.clone());
    let mut secs = Sections::new(Report::titled(title), &opts.budget, &opts.events, file);
    let (fa, ta) = (Arc::new(f.clone()), Arc::new(t.clone()));
    let sys = {
        let (fa, ta) = (fa.clone(), ta.clone());
        secs.run("system", Insist::Command("linalg charpoly"), move || {
            system_section(&fa, &ta)
        })
    };
    secs.push("system", sys.map_or_else(|v| v, Value::Obj));
    let s = &t.ss;
    if s.ninputs() > 0 && s.noutputs() > 0 {
        io_sections(&mut secs, &ta);
    } else {
        let why = format!(
            "the system has {} inputs and {} outputs",
            s.ninputs(),
            s.noutputs()
        );
        secs.push("realization", not_applicable("realization", why.clone()));
        secs.push(
            "structure",
            not_applicable("special coordinate basis", why.clone()),
        );
        secs.push("zeros", not_applicable("invariant zeros", why));
    }
    let how = (opts.full, f.path.as_str());
    if let Some(n) = K::numeric(t) {
        let routh = K::rational(t).map(|q| q.ss.a.clone());
        eigen_sections(Arc::new(n.clone()), &mut secs, how, routh);
    } else {
        // no certified eigenvalues: the Jordan structure over the field is the caller's
        // (`api::symbolic`, with its conditions); the PBH tests by ranks hold over every field
        // with a Jordan decomposition (their conditions recorded in the field)
        let why = format!(
            "needs rational matrices; this file's entries lie in {}",
            f.ground
        );
        secs.push(
            "jordan",
            not_applicable("eigenvalues and Jordan form", why.clone()),
        );
        let pbh = eigen::pbh_by_rank(Arc::new(t.ss.clone()));
        eigen::pbh_section(&mut secs, s.ninputs(), Some(pbh));
        secs.push("modes", not_applicable("modal table", why));
    }
    mechanical_section(&fa, &ta, &mut secs);
    if secs.done == 0 && !secs.cut.is_empty() {
        return Err(Failure::input(format!(
            "stopped after --max-seconds {}: the exact computation did not finish in time",
            opts.budget.max_seconds.unwrap_or(0.0)
        )));
    }
    let mut out = Outcome::new(secs.report, secs.verified);
    if !secs.cut.is_empty() {
        out.stopped = Some(format!(
            "--max-seconds {} ran out: {} section(s) skipped ({}); the report marks them",
            opts.budget.max_seconds.unwrap_or(0.0),
            secs.cut.len(),
            secs.cut.join(", ")
        ));
    }
    Ok(out)
}

/// The sections that need inputs and outputs: realization, structure (SCB), zeros.
fn io_sections<K: Field + 'static>(secs: &mut Sections, t: &Arc<TypedSystem<K>>) {
    let (t1, t2, t3) = (t.clone(), t.clone(), t.clone());
    // the SCB assumes [B; D] and [C, D] of full rank; report why when it does not apply
    let scb = "special coordinate basis";
    let table = [
        (
            "realization",
            Section::new("realization", Insist::Command("minreal"), move || {
                realization_section(&t1)
            }),
        ),
        (
            "structure",
            Section::new(scb, Insist::Command("scb"), move || {
                let s = &t2.ss;
                let r = crate::structure::scb::scb(&s.a, &s.b, &s.c, &s.d);
                Ok(match r {
                    Ok(scb) => (scb.verified && scb.verify(), scb.report()),
                    Err(e) => (
                        true,
                        Report::titled(scb).str("not_applicable", e.to_string()),
                    ),
                })
            }),
        ),
        (
            "zeros",
            Section::new("invariant zeros", Insist::Command("zeros"), move || {
                let s = &t3.ss;
                crate::structure::zeros::invariant_zeros(&s.a, &s.b, &s.c, &s.d)
                    .map(|z| (true, z.report()))
            }),
        ),
    ];
    for (key, sec) in table {
        secs.section(key, sec);
    }
}

/// Free responses larger than this (estimated bytes of exact text) are announced with their
/// size instead of computed (`--full` computes them).
const MAX_FREE_RESPONSE_BYTES: usize = 400_000;

/// The mechanical normal form (over any exact field), under its budget.
fn mechanical_section<K: Field + 'static>(
    f: &Arc<SystemFile>,
    t: &Arc<TypedSystem<K>>,
    secs: &mut Sections,
) {
    use crate::structure::mechanical::{DEFAULT_MAX_CANDIDATES, mechanical_normal_form_in};
    let s = &t.ss;
    let title = "mechanical normal form";
    // applies to first-order systems with inputs and an even number of states (files
    // already in second-order form are mechanical by input)
    if !f.is_second_order() && s.ninputs() > 0 && s.nstates().is_multiple_of(2) {
        let tt = t.clone();
        let work = move || {
            let s = &tt.ss;
            mechanical_normal_form_in(None, &s.a, &s.b, &s.c, &s.d, DEFAULT_MAX_CANDIDATES)
                .map(|m| (!m.exists || m.verified, m.report()))
        };
        secs.section(
            "mechanical",
            Section::new(title, Insist::Command("mnf"), work),
        );
    } else {
        let why = if f.is_second_order() {
            "the file is already in second-order form"
        } else if s.ninputs() == 0 {
            "the system has no inputs"
        } else {
            "an odd number of states has no second-order form"
        };
        secs.push("mechanical", not_applicable(title, why));
    }
}
