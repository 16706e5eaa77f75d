//! The eigenvalue sections of `analyze`, once for every field with an exact Jordan form
//! ([`EigenField`]: $\mathbb{Q}$, $\mathbb{Q}(\sqrt d)$, $\mathbb{Q}(i)$): the Jordan form
//! ($A T = T J$), its real form when $A$ is real, the free response
//! $e^{At} = \sum_k t^k e^{\theta t} G_{\theta,k}$, the PBH tests and the modal table.

use super::runner::{Insist, Section, Sections, failed_msg};
use super::{MAX_FREE_RESPONSE_BYTES, not_applicable};
use crate::io::TypedSystem;
use crate::jordan::{EigenField, JordanField, JordanForm, jordan_over};
use crate::realization;
use crate::report::{Report, Value, sections};
use crate::system::StateSpace;
use std::sync::Arc;

/// The PBH tests by ranks, for when the Jordan form was not computed (`None`: no such test
/// over this field).
pub(super) type PbhByRank = Option<Box<dyn FnOnce() -> crate::Result<(bool, bool)> + Send>>;

/// The Jordan form (with the real form over a real field and the free response), the PBH
/// tests and the modal table over the system's field.
pub(super) fn eigen_sections<F: EigenField>(
    t: Arc<TypedSystem<F>>,
    secs: &mut Sections,
    (full, path): (bool, &str),
    by_rank: PbhByRank,
) {
    let (sec, jf) = jordan_section(&t, secs, (full, path));
    secs.push("jordan", sec);
    let title = "PBH tests (exact, one test per irreducible factor)";
    if t.ss.ninputs() == 0 {
        secs.push(
            "pbh",
            not_applicable("PBH tests", "the system has no inputs"),
        );
    } else if jf.is_none() && by_rank.is_none() {
        let why = "the Jordan form was not computed";
        secs.push("pbh", not_applicable(title, why));
    } else {
        let tt = t.clone();
        let work = move || {
            let (pc, po) = match (jf, by_rank) {
                (Some(jf), _) => pbh_from_jordan(&jf, &tt.ss),
                (None, Some(rank)) => rank()?,
                (None, None) => unreachable!("checked above"),
            };
            let rep = Report::titled(title)
                .bool("controllable", pc)
                .bool("observable", po);
            Ok((true, rep))
        };
        secs.section("pbh", Section::new(title, Insist::Analyze, work));
    }
    let modes = move || realization::modal_table_over(&t.ss.a).map(|m| (true, m.report()));
    let modal = Section::new("modal table", Insist::Command("modes"), modes);
    secs.section("modes", modal);
}

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
fn jordan_section<F: EigenField>(
    t: &Arc<TypedSystem<F>>,
    secs: &mut Sections,
    (full, path): (bool, &str),
) -> (Value, Option<Arc<JordanForm<F>>>) {
    let title = "eigenvalues and Jordan form";
    let tt = t.clone();
    let jf = match secs.run(title, Insist::Command("jordan"), move || {
        jordan_over(&tt.ss.a).map(|jf| {
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
    let title = "Real Jordan form";
    let real = if jf.base().is_real() {
        let j = jf.clone();
        secs.checked(title, Insist::Command("jordan --real"), move || {
            // a real form left in complex coordinates (exact = false) is not checked
            j.real_form()
                .map(|rf| (!rf.exact || rf.verified, rf.report()))
        })
        .unwrap_or_else(|e| failed_msg(title, &e.to_string()))
    } else {
        let why = format!("A is not real (entries in {})", jf.base());
        not_applicable(title, why)
    };
    sec.push("real_form", real);
    if let Some(q) =
        (t.as_ref() as &dyn std::any::Any).downcast_ref::<TypedSystem<crate::field::Q>>()
    {
        sec.push("stability", exact_stability(q, secs));
    }
    let est = free_response_estimate(&sec, jf.n());
    sec.push("free_response", free_response(&jf, secs, est, (full, path)));
    (Value::Obj(sec), Some(jf))
}

/// Stability decided exactly over $\mathbb{Q}$ (no floats: Routh-Hurwitz through the
/// Cayley map and Schur-Cohn per irreducible factor of $\det(sI - A)$, the minimal
/// polynomial for the blocks on the imaginary axis), under its budget.
fn exact_stability(t: &TypedSystem<crate::field::Q>, secs: &mut Sections) -> Value {
    use crate::system::discrete::stability::{Domain, stability_of};
    let a = t.ss.a.clone();
    let title = "stability (exact)";
    match secs.run(title, Insist::Command("stability"), move || {
        stability_of(&a, Domain::Continuous)
    }) {
        Ok(Ok(s)) => Value::Obj(sections::stability_report(&s, None)),
        Ok(Err(e)) => failed_msg(title, &e.to_string()),
        Err(v) => v,
    }
}

/// The free response under its budget, or its size when too large.
fn free_response<F: EigenField>(
    jf: &Arc<JordanForm<F>>,
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
                 eigenvalue's field); for a simple eigenvalue G = v w with v the column of T and \
                 w the row of T^-1; run `{}` to compute it",
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

/// PBH from the Jordan form, per factor $g$ in $E = F\[t\]/(g)$: the left eigenvectors of
/// $t$ are the rows of $W$ ending a Jordan block (they span the left eigenspace) and the
/// right ones the columns of $V$ starting one, so $(A, B)$ is controllable at $t$ iff
/// $W_{\text{ends}} B$ has full row rank (the number of blocks), and observable iff
/// $C V_{\text{starts}}$ has full column rank.
fn pbh_from_jordan<F: EigenField>(jf: &JordanForm<F>, s: &StateSpace<F>) -> (bool, bool) {
    let (mut pc, mut po) = (true, true);
    for c in &jf.components {
        let e = &c.field;
        let lift = |m: &crate::matrix::Matrix<F>| m.map(e, |x| e.from_base(x));
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
    (pc, po)
}

/// The eigenvalue structure of `a` over any field with a Jordan decomposition, read off the
/// generic eigenvalue list ([`sections::eigenvalue_structure`], the factor in `s`):
/// `eigenvalues`, `complete` (every eigenvalue lies in the field), `stability` (from the
/// typed signs: [`sections::stability_text`]), `verified`. The decomposition is returned
/// with it (its conditions join the caller's).
pub(crate) fn structure_section<F: JordanField>(
    a: &crate::matrix::Matrix<F>,
    title: &str,
) -> (Report, Option<JordanForm<F>>) {
    match F::jordan_form(a) {
        Ok(jf) => {
            let complete = jf.components.iter().all(|c| c.degree() == 1);
            let r = Report::titled(title)
                .list("eigenvalues", sections::eigenvalue_structure(&jf, "s"))
                .bool("complete", complete)
                .str("stability", sections::stability_text(&jf))
                .bool("verified", jf.verified);
            (r, Some(jf))
        }
        Err(err) => (Report::titled(title).str("error", err.to_string()), None),
    }
}
