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

mod runner;

use super::budget::{Budget, Events};
use super::{Failure, Outcome};
use crate::error::Error;
use crate::field::{Field, Q, QuadraticField};
use crate::io::{SystemFile, TypedSystem, as_rational};
use crate::realization::{self, MinrealMethod};
use crate::report::{Report, Value, sections, str_list};
use runner::{Insist, Sections, failed_msg};
use std::sync::Arc;

/// How `analyze` runs: the budget of its sections and where finished sections stream.
#[derive(Debug, Default)]
pub struct AnalyzeOptions {
    pub budget: Budget,
    pub events: Events,
    /// `--full`: compute the free response however large.
    pub full: bool,
}

/// A section that failed: the title and the reason.
fn failed(title: &str, e: &Error) -> Value {
    failed_msg(title, &e.to_string())
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

/// The realization section and whether its minimal realization was verified.
fn realization_section<K: Field>(t: &TypedSystem<K>) -> Result<(Report, bool), Error> {
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

/// The whole analysis with the default budgets and nothing streamed.
pub fn analyze<K: Field + 'static>(f: &SystemFile, t: &TypedSystem<K>) -> Result<Outcome, Failure> {
    analyze_with(f, t, &AnalyzeOptions::default())
}

/// The whole analysis; `verified` is the conjunction of every exact check made.
pub fn analyze_with<K: Field + 'static>(
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
    let quad = (t as &dyn std::any::Any).downcast_ref::<TypedSystem<QuadraticField>>();
    if let Some(q) = as_rational(t) {
        rational_sections(&fa, Arc::new(q.clone()), &mut secs, opts.full);
    } else if let Some(q) = quad {
        quadratic_sections(Arc::new(q.clone()), &mut secs, (opts.full, &f.path));
    } else {
        let why = format!(
            "needs rational matrices; this file's entries lie in {}",
            f.ground
        );
        secs.push(
            "jordan",
            not_applicable("eigenvalues and Jordan form", why.clone()),
        );
        secs.push("pbh", not_applicable("PBH tests", why.clone()));
        secs.push("modes", not_applicable("modal table", why));
    }
    mechanical_section(&fa, &ta, &mut secs);
    if secs.done == 0 && !secs.cut.is_empty() {
        return Err(Failure {
            code: 2,
            message: format!(
                "stopped after --max-seconds {}: the exact computation did not finish in time",
                opts.budget.max_seconds.unwrap_or(0.0)
            ),
        });
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
    let title = "realization";
    let tt = t.clone();
    let sec = match secs.run(title, Insist::Command("minreal"), move || {
        realization_section(&tt)
    }) {
        Ok(Ok((rep, ok))) => {
            secs.verified &= ok;
            Value::Obj(rep)
        }
        Ok(Err(e)) => failed(title, &e),
        Err(v) => v,
    };
    secs.push("realization", sec);
    // the SCB assumes [B; D] and [C, D] of full rank; report why when it does not apply
    let title = "special coordinate basis";
    let tt = t.clone();
    let sec = match secs.run(title, Insist::Command("scb"), move || {
        let s = &tt.ss;
        crate::structure::scb::scb(&s.a, &s.b, &s.c, &s.d)
            .map(|scb| (scb.verified && scb.verify(), scb.report()))
    }) {
        Ok(Ok((ok, rep))) => {
            secs.verified &= ok;
            Value::Obj(rep)
        }
        Ok(Err(e)) => Value::Obj(Report::titled(title).str("not_applicable", e.to_string())),
        Err(v) => v,
    };
    secs.push("structure", sec);
    let title = "invariant zeros";
    let tt = t.clone();
    let sec = match secs.run(title, Insist::Command("zeros"), move || {
        let s = &tt.ss;
        crate::structure::zeros::invariant_zeros(&s.a, &s.b, &s.c, &s.d).map(|z| z.report())
    }) {
        Ok(Ok(rep)) => Value::Obj(rep),
        Ok(Err(e)) => failed(title, &e),
        Err(v) => v,
    };
    secs.push("zeros", sec);
}

/// Free responses larger than this (estimated bytes of exact text) are announced with their
/// size instead of computed (`--full` computes them).
const MAX_FREE_RESPONSE_BYTES: usize = 400_000;

/// The estimated size of the free response's exact text: $G = v w$ per simple eigenvalue
/// (entries about as long as an entry of `v` plus one of `w`), from the length of `T`.
fn free_response_estimate(sec: &Report, n: usize) -> usize {
    match sec.get("T") {
        Some(Value::Matrix(t)) => 2 * n * t.exact.iter().flatten().map(String::len).sum::<usize>(),
        _ => 0,
    }
}

/// The command that computes everything in full.
fn insist_full(path: &str) -> String {
    if path.starts_with("built-in:") {
        "exactlti analyze --full".into()
    } else {
        format!("exactlti analyze {path} --full")
    }
}

/// The Jordan section: the form, its real form and the free response, each under its budget.
fn jordan_section(
    t: &Arc<TypedSystem<Q>>,
    secs: &mut Sections,
    (full, path): (bool, &str),
) -> (Value, Option<Arc<crate::jordan::JordanForm>>) {
    let title = "eigenvalues and Jordan form";
    let tt = t.clone();
    let jf = match secs.run(title, Insist::Command("jordan"), move || {
        let r = crate::jordan::jordan(&tt.ss.a);
        r.map(|jf| {
            let rep = jf.report();
            (Arc::new(jf), rep)
        })
    }) {
        Err(v) => return (v, None),
        Ok(r) => r,
    };
    let (jf, mut sec) = match jf {
        Ok(x) => x,
        Err(e) => {
            let mut sec = Report::titled(title).str("error", e.to_string());
            if e.is_unable() {
                let tt = t.clone();
                let fb = secs.run("float guess", Insist::Analyze, move || {
                    sections::float_jordan_fallback(&tt.ss.a)
                });
                if let Ok(Ok(fb)) = fb {
                    sec.push("float_fallback", Value::Obj(fb));
                }
            }
            return (Value::Obj(sec), None);
        }
    };
    secs.verified &= jf.verified;
    sec.title = Some(title.into());
    let j = jf.clone();
    let title = "Real Jordan form";
    let real = match secs.run(title, Insist::Command("jordan --real"), move || {
        j.real_form()
            .map(|rf| (!rf.exact || rf.verified, rf.report()))
    }) {
        Ok(Ok((ok, rep))) => {
            secs.verified &= ok;
            Value::Obj(rep)
        }
        Ok(Err(e)) => failed(title, &e),
        Err(v) => v,
    };
    sec.push("real_form", real);
    let j = jf.clone();
    let title = "Free response x(t) = sum_k t^k e^(s t) G x0";
    let est = free_response_estimate(&sec, jf.n());
    let fr = if !full && est > MAX_FREE_RESPONSE_BYTES {
        Value::Obj(Report::titled(title).str(
            "not_computed",
            format!(
                "about {} KB of exact entries (an n x n matrix G per eigenvalue and power, in the \
                 eigenvalue's field); for a simple eigenvalue G = v w with v the column of T and \
                 w the row of T^-1; run `{}` to compute it",
                est / 1000,
                insist_full(path)
            ),
        ))
    } else {
        match secs.run(title, Insist::Analyze, move || {
            let rep = j.free_response().report(&j);
            (matches!(rep.get("verified"), Some(Value::Bool(true))), rep)
        }) {
            Ok((ok, rep)) => {
                secs.verified &= ok;
                Value::Obj(rep)
            }
            Err(v) => v,
        }
    };
    sec.push("free_response", fr);
    (Value::Obj(sec), Some(jf))
}

/// PBH tests per irreducible factor of the characteristic polynomial: for a simple factor
/// (one eigenvalue theta of multiplicity 1) the left-eigenvector form, `w B != 0` and
/// `C v != 0` in QQ(theta) with `v`, `w` from the Jordan form; otherwise the rank of
/// `[A - theta I, B]` (and of `[A - theta I; C]`) over QQ(theta).
fn pbh(
    jf: Option<&crate::jordan::JordanForm>,
    s: &crate::system::StateSpace<Q>,
) -> crate::Result<(bool, bool)> {
    let Some(jf) = jf.filter(|jf| jf.components.iter().all(|c| c.multiplicity == 1)) else {
        return realization::pbh_controllable(&s.a, &s.b)
            .and_then(|pc| realization::pbh_observable(&s.a, &s.c).map(|po| (pc, po)));
    };
    let (mut pc, mut po) = (true, true);
    for c in &jf.components {
        let k = &c.field;
        pc &= !(&c.left_chains * &s.b.convert_to(k)).is_zero();
        po &= !(&s.c.convert_to(k) * &c.chains).is_zero();
    }
    Ok((pc, po))
}

/// The sections that need rational matrices.
fn rational_sections(f: &Arc<SystemFile>, t: Arc<TypedSystem<Q>>, secs: &mut Sections, full: bool) {
    let (sec, jf) = jordan_section(&t, secs, (full, &f.path));
    secs.push("jordan", sec);
    let tt = t.clone();
    let pbh = move || pbh(jf.as_deref(), &tt.ss).map(Some);
    let tt = t.clone();
    let modes = move || realization::modal_table(&tt.ss.a).map(|m| m.report());
    pbh_and_modes(secs, t.ss.ninputs() > 0, pbh, modes);
}

/// The PBH section (when the system has inputs; `pbh` gives `None` when the Jordan form
/// it uses was not computed) and the modal table, each under its own budget.
fn pbh_and_modes(
    secs: &mut Sections,
    has_inputs: bool,
    pbh: impl FnOnce() -> crate::Result<Option<(bool, bool)>> + Send + 'static,
    modes: impl FnOnce() -> crate::Result<Report> + Send + 'static,
) {
    let title = "PBH tests (exact, one test per irreducible factor)";
    let sec = if !has_inputs {
        not_applicable("PBH tests", "the system has no inputs")
    } else {
        match secs.run(title, Insist::Analyze, pbh) {
            Ok(Ok(Some((pc, po)))) => Value::Obj(
                Report::titled(title)
                    .bool("controllable", pc)
                    .bool("observable", po),
            ),
            Ok(Ok(None)) => not_applicable(title, "the Jordan form was not computed"),
            Ok(Err(e)) => failed(title, &e),
            Err(v) => v,
        }
    };
    secs.push("pbh", sec);
    let title = "modal table";
    let sec = match secs.run(title, Insist::Command("modes"), modes) {
        Ok(Ok(rep)) => Value::Obj(rep),
        Ok(Err(e)) => failed(title, &e),
        Err(v) => v,
    };
    secs.push("modes", sec);
}

/// The Jordan form (with the real form over a real field), PBH tests and the modal table
/// over a quadratic field $K$ ([`crate::jordan::jordan_over`]).
fn quadratic_sections(
    t: Arc<TypedSystem<QuadraticField>>,
    secs: &mut Sections,
    (full, path): (bool, &str),
) {
    let title = "eigenvalues and Jordan form";
    let tt = t.clone();
    let jf = match secs.run(title, Insist::Command("jordan"), move || {
        crate::jordan::jordan_over(&tt.ss.a).map(|jf| {
            let rep = jf.report();
            (Arc::new(jf), rep)
        })
    }) {
        Ok(Ok((jf, mut sec))) => {
            secs.verified &= jf.verified;
            sec.title = Some(title.into());
            if jf.base().is_real() {
                let title = "Real Jordan form";
                let j = jf.clone();
                let real = match secs.run(title, Insist::Command("jordan --real"), move || {
                    j.real_form().map(|rf| (rf.verified, rf.report()))
                }) {
                    Ok(Ok((ok, rep))) => {
                        secs.verified &= ok;
                        Value::Obj(rep)
                    }
                    Ok(Err(e)) => failed(title, &e),
                    Err(v) => v,
                };
                sec.push("real_form", real);
            } else {
                sec.push(
                    "real_form",
                    not_applicable("Real Jordan form", "A is not real (entries in QQ(i))"),
                );
            }
            let fr = free_response_k(
                &jf,
                secs,
                free_response_estimate(&sec, jf.n()),
                (full, path),
            );
            sec.push("free_response", fr);
            secs.push("jordan", Value::Obj(sec));
            Some(jf)
        }
        Ok(Err(e)) => {
            secs.push("jordan", failed(title, &e));
            None
        }
        Err(v) => {
            secs.push("jordan", v);
            None
        }
    };
    let tt = t.clone();
    let pbh = move || Ok(pbh_over_k(jf.as_deref(), &tt));
    let tt = t.clone();
    let modes = move || realization::modal_table_over(&tt.ss.a).map(|m| m.report());
    pbh_and_modes(secs, t.ss.ninputs() > 0, pbh, modes);
}

/// The free response over $K$ under its budget, or its size when too large (as over Q).
fn free_response_k(
    jf: &Arc<crate::jordan::JordanForm<QuadraticField>>,
    secs: &mut Sections,
    est: usize,
    (full, path): (bool, &str),
) -> Value {
    let title = "Free response x(t) = sum_k t^k e^(s t) G x0";
    if !full && est > MAX_FREE_RESPONSE_BYTES {
        return Value::Obj(Report::titled(title).str(
            "not_computed",
            format!(
                "about {} KB of exact entries (an n x n matrix G per eigenvalue and power, in the \
                 eigenvalue's field); run `{}` to compute it",
                est / 1000,
                insist_full(path)
            ),
        ));
    }
    let j = jf.clone();
    match secs.run(title, Insist::Analyze, move || {
        let rep = j.free_response().report(&j);
        (matches!(rep.get("verified"), Some(Value::Bool(true))), rep)
    }) {
        Ok((ok, rep)) => {
            secs.verified &= ok;
            Value::Obj(rep)
        }
        Err(v) => v,
    }
}

/// PBH over $K$ from the Jordan form, per factor $g$ in $E = K\[t\]/(g)$: the left
/// eigenvectors of $t$ are the rows of $W$ ending a Jordan block (they span the left
/// eigenspace) and the right ones the columns of $V$ starting one, so $(A, B)$ is
/// controllable at $t$ iff $W_{\text{ends}} B$ has full row rank (the number of blocks), and
/// observable iff $C V_{\text{starts}}$ has full column rank (`None` without a Jordan form).
fn pbh_over_k(
    jf: Option<&crate::jordan::JordanForm<QuadraticField>>,
    t: &TypedSystem<QuadraticField>,
) -> Option<(bool, bool)> {
    let s = &t.ss;
    let (mut pc, mut po) = (true, true);
    for c in &jf?.components {
        let e = &c.field;
        let lift = |m: &crate::matrix::Matrix<QuadraticField>| m.map(e, |x| e.from_base(x));
        let (mut starts, mut ends, mut off) = (vec![], vec![], 0);
        for &b in &c.blocks {
            starts.push(off);
            ends.push(off + b - 1);
            off += b;
        }
        let nb = c.blocks.len();
        pc &= (&c.left_chains.select_rows(&ends) * &lift(&s.b)).rank() == nb;
        po &= (&lift(&s.c) * &c.chains.select_cols(&starts)).rank() == nb;
    }
    Some((pc, po))
}

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
        let sec = match secs.run(title, Insist::Command("mnf"), move || {
            let s = &tt.ss;
            mechanical_normal_form_in(None, &s.a, &s.b, &s.c, &s.d, DEFAULT_MAX_CANDIDATES)
                .map(|m| (!m.exists || m.verified, m.report()))
        }) {
            Ok(Ok((ok, rep))) => {
                secs.verified &= ok;
                Value::Obj(rep)
            }
            Ok(Err(e)) => failed(title, &e),
            Err(v) => v,
        };
        secs.push("mechanical", sec);
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
