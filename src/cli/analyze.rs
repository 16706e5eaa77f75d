//! `analyze`: every section that applies, as one report.
//!
//! A section that cannot be computed is not dropped: it appears with an `error` key saying
//! why (or `not_applicable` for a condition of the method). When the exact Jordan form hits
//! a limit of the implementation ([`Error::is_unable`]), the float backend's guess is added
//! as `float_fallback` (marked `exact: false`).

use super::{Failure, Outcome};
use crate::error::Error;
use crate::field::{Field, Q};
use crate::io::{SystemFile, TypedSystem, as_rational};
use crate::realization::{self, MinrealMethod};
use crate::report::{Report, Value, sections, str_list};

/// A section that failed: the title and the reason.
fn failed(title: &str, e: &Error) -> Value {
    Value::Obj(Report::titled(title).str("error", e.to_string()))
}

/// A section that does not apply to this system: the title and why (never silently absent).
fn skipped(title: &str, why: impl Into<String>) -> Value {
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

/// The realization section and whether its minimal realization was verified.
fn realization_section<K: Field>(t: &TypedSystem<K>) -> Result<(Report, bool), Failure> {
    let s = &t.ss;
    let rc = realization::controllability_matrix(&s.a, &s.b).rank();
    let ro = realization::observability_matrix(&s.a, &s.c).rank();
    let min = realization::minimal(s, MinrealMethod::Kalman)?;
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
    Ok((r, min.verified))
}

/// The whole analysis; `verified` is the conjunction of every exact check made.
pub fn analyze<K: Field + 'static>(f: &SystemFile, t: &TypedSystem<K>) -> Result<Outcome, Failure> {
    let mut verified = true;
    let mut r = Report::titled(format!(
        "exactlti analysis: {}",
        f.name.clone().unwrap_or_else(|| f.path.clone())
    ));
    r.push("system", Value::Obj(system_section(f, t)));
    let s = &t.ss;
    if s.ninputs() > 0 && s.noutputs() > 0 {
        let (rep, ok) = realization_section(t)?;
        verified &= ok;
        r.push("realization", Value::Obj(rep));
        // the SCB assumes [B; D] and [C, D] of full rank; report why when it does not apply
        match crate::structure::scb::scb(&s.a, &s.b, &s.c, &s.d) {
            Ok(scb) => {
                verified &= scb.verified && scb.verify();
                r.push("structure", Value::Obj(scb.report()))
            }
            Err(e) => r.push(
                "structure",
                Value::Obj(
                    Report::titled("special coordinate basis").str("not_applicable", e.to_string()),
                ),
            ),
        };
        match crate::structure::zeros::invariant_zeros(&s.a, &s.b, &s.c, &s.d) {
            Ok(z) => r.push("zeros", Value::Obj(z.report())),
            Err(e) => r.push("zeros", failed("invariant zeros", &e)),
        };
    } else {
        let why = format!(
            "the system has {} inputs and {} outputs",
            s.ninputs(),
            s.noutputs()
        );
        r.push("realization", skipped("realization", why.clone()));
        r.push(
            "structure",
            skipped("special coordinate basis", why.clone()),
        );
        r.push("zeros", skipped("invariant zeros", why));
    }
    if let Some(q) = as_rational(t) {
        verified &= rational_sections(q, &mut r);
    } else {
        let why = format!(
            "needs rational matrices; this file's entries lie in {}",
            f.ground
        );
        r.push(
            "jordan",
            skipped("eigenvalues and Jordan form", why.clone()),
        );
        r.push("pbh", skipped("PBH tests", why.clone()));
        r.push("modes", skipped("modal table", why));
    }
    verified &= mechanical_section(f, t, &mut r);
    Ok(Outcome::new(r, verified))
}

/// The sections that need rational matrices; returns the conjunction of their checks.
fn rational_sections(t: &TypedSystem<Q>, r: &mut Report) -> bool {
    let mut verified = true;
    let s = &t.ss;
    match crate::jordan::jordan(&s.a) {
        Ok(jf) => {
            verified &= jf.verified;
            let mut sec = jf.report();
            sec.title = Some("eigenvalues and Jordan form".into());
            match jf.real_form() {
                Ok(rf) => {
                    verified &= !rf.exact || rf.verified;
                    sec.push("real_form", Value::Obj(rf.report()))
                }
                Err(e) => sec.push("real_form", failed("Real Jordan form", &e)),
            };
            sec.push("free_response", Value::Obj(jf.free_response().report(&jf)));
            r.push("jordan", Value::Obj(sec));
        }
        Err(e) => {
            let mut sec = Report::titled("eigenvalues and Jordan form").str("error", e.to_string());
            if e.is_unable()
                && let Ok(fb) = sections::float_jordan_fallback(&s.a)
            {
                sec.push("float_fallback", Value::Obj(fb));
            }
            r.push("jordan", Value::Obj(sec));
        }
    }
    if s.ninputs() > 0 {
        let pbh = realization::pbh_controllable(&s.a, &s.b)
            .and_then(|pc| realization::pbh_observable(&s.a, &s.c).map(|po| (pc, po)));
        let title = "PBH tests (exact, one rank per irreducible factor)";
        match pbh {
            Ok((pc, po)) => r.push(
                "pbh",
                Value::Obj(
                    Report::titled(title)
                        .bool("controllable", pc)
                        .bool("observable", po),
                ),
            ),
            Err(e) => r.push("pbh", failed(title, &e)),
        };
    } else {
        r.push("pbh", skipped("PBH tests", "the system has no inputs"));
    }
    match realization::modal_table(&s.a) {
        Ok(m) => r.push("modes", Value::Obj(m.report())),
        Err(e) => r.push("modes", failed("modal table", &e)),
    };
    verified
}

/// The mechanical normal form (over any exact field); returns whether a form found verified.
fn mechanical_section<K: Field>(f: &SystemFile, t: &TypedSystem<K>, r: &mut Report) -> bool {
    use crate::structure::mechanical::{DEFAULT_MAX_CANDIDATES, mechanical_normal_form_in};
    let s = &t.ss;
    let mut verified = true;
    // mechanical normal form: applies to first-order systems with inputs and an even
    // number of states (files already in second-order form are mechanical by input)
    if !f.is_second_order() && s.ninputs() > 0 && s.nstates().is_multiple_of(2) {
        match mechanical_normal_form_in(None, &s.a, &s.b, &s.c, &s.d, DEFAULT_MAX_CANDIDATES) {
            Ok(m) => {
                verified &= !m.exists || m.verified;
                r.push("mechanical", Value::Obj(m.report()))
            }
            Err(e) => r.push("mechanical", failed("mechanical normal form", &e)),
        };
    } else {
        let why = if f.is_second_order() {
            "the file is already in second-order form"
        } else if s.ninputs() == 0 {
            "the system has no inputs"
        } else {
            "an odd number of states has no second-order form"
        };
        r.push("mechanical", skipped("mechanical normal form", why));
    }
    verified
}
