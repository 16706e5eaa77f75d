//! The eigenvalue sections of `analyze`, once for every field with an exact Jordan form
//! ([`EigenField`]: $\mathbb{Q}$, $\mathbb{Q}(\sqrt d)$, $\mathbb{Q}(i)$): the Jordan form
//! ($A T = T J$), its real form when $A$ is real, its stability, the free response
//! $e^{At} = \sum_k t^k e^{\theta t} G_{\theta,k}$, the PBH tests and the modal table. The PBH
//! tests by ranks ([`pbh_section`]) serve every [`JordanField`] ($\mathbb{Q}(p)$ too).

use super::runner::{Insist, Section, Sections, failed_msg};
use super::{MAX_FREE_RESPONSE_BYTES, not_applicable};
use crate::field::Q;
use crate::io::TypedSystem;
use crate::jordan::{EigenField, JordanField, JordanForm, jordan_over};
use crate::matrix::Matrix;
use crate::realization;
use crate::report::{Report, Value, sections};
use crate::system::StateSpace;
use std::sync::Arc;

/// The PBH tests, computed when the section runs: `(controllable, observable)`.
pub(super) type Pbh = Box<dyn FnOnce() -> crate::Result<(bool, bool)> + Send>;

/// The PBH tests by ranks over every [`JordanField`], all over the base field
/// ([`realization::pbh_controllable`]: the Kalman rank decides every eigenvalue when it is
/// full; otherwise per irreducible factor $g$ the $g$-primary part's controllability, the left
/// kernel of $g(A)$; for $g = s - \theta$, $\theta \in F$, $\operatorname{rank}[A - \theta I,
/// B] < n$; over $\mathbb{Q}(p)$ a factor of degree $\ge 2$ is a `RootOf(g)` eigenvalue, tested
/// without splitting it). Over $\mathbb{Q}(p)$ the factorization and the ranks record their
/// conditions in the field.
pub(super) fn pbh_by_rank<F: JordanField>(s: Arc<StateSpace<F>>) -> Pbh {
    Box::new(move || {
        let pc = realization::pbh_controllable(&s.a, &s.b)?;
        Ok((pc, realization::pbh_observable(&s.a, &s.c)?))
    })
}

/// The PBH section: not applicable without inputs or without a way to test (`pbh` `None`).
pub(super) fn pbh_section(secs: &mut Sections, ninputs: usize, pbh: Option<Pbh>) {
    let title = "PBH tests (exact, one test per irreducible factor)";
    if ninputs == 0 {
        secs.push(
            "pbh",
            not_applicable("PBH tests", "the system has no inputs"),
        );
        return;
    }
    let Some(pbh) = pbh else {
        let why = "the Jordan form was not computed";
        secs.push("pbh", not_applicable(title, why));
        return;
    };
    let work = move || {
        let (pc, po) = pbh()?;
        let rep = Report::titled(title)
            .bool("controllable", pc)
            .bool("observable", po);
        Ok((true, rep))
    };
    secs.section("pbh", Section::new(title, Insist::Analyze, work));
}

/// The Jordan form (with the real form over a real field, the stability and the free
/// response), the PBH tests and the modal table over the system's field. `routh`: the
/// system's $A$ when the field is $\mathbb{Q}$ (stability by Routh-Hurwitz,
/// [`exact_stability`]); over the other fields the stability is read off the Jordan form's
/// typed signs ([`sections::stability_text`]).
pub(super) fn eigen_sections<F: EigenField + JordanField>(
    t: Arc<TypedSystem<F>>,
    secs: &mut Sections,
    (full, path): (bool, &str),
    routh: Option<Matrix<Q>>,
) {
    let (sec, jf) = jordan_section(&t, secs, (full, path), routh);
    secs.push("jordan", sec);
    let pbh: Pbh = match jf {
        Some(jf) => {
            let tt = t.clone();
            Box::new(move || Ok(pbh_from_jordan(&jf, &tt.ss)))
        }
        None => pbh_by_rank(Arc::new(t.ss.clone())),
    };
    pbh_section(secs, t.ss.ninputs(), Some(pbh));
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
    routh: Option<Matrix<Q>>,
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
    let stability = match routh {
        Some(a) => exact_stability(a, secs),
        None => jordan_stability(&jf),
    };
    sec.push("stability", stability);
    let est = free_response_estimate(&sec, jf.n());
    sec.push("free_response", free_response(&jf, secs, est, (full, path)));
    (Value::Obj(sec), Some(jf))
}

/// Stability decided exactly over $\mathbb{Q}$ (no floats: Routh-Hurwitz through the
/// Cayley map and Schur-Cohn per irreducible factor of $\det(sI - A)$, the minimal
/// polynomial for the blocks on the imaginary axis), under its budget.
fn exact_stability(a: Matrix<Q>, secs: &mut Sections) -> Value {
    use crate::system::discrete::stability::{Domain, stability_of};
    let title = "stability (exact)";
    match secs.run(title, Insist::Command("stability"), move || {
        stability_of(&a, Domain::Continuous)
    }) {
        Ok(Ok(s)) => Value::Obj(sections::stability_report(&s, None)),
        Ok(Err(e)) => failed_msg(title, &e.to_string()),
        Err(v) => v,
    }
}

/// Stability read off the Jordan form over any field ([`JordanField`]): the typed sign of
/// each eigenvalue's real part ([`crate::jordan::Eigenvalue::re_sign`], a
/// [`crate::jordan::Decided`]: exact over a number field; over $\mathbb{Q}(p)$ a sign that
/// depends on the parameters is "not decided in symbols", never guessed), with the Jordan
/// block sizes on the imaginary axis ([`sections::stability_text`]).
fn jordan_stability<F: crate::field::Field>(jf: &JordanForm<F>) -> Value {
    use crate::jordan::Decided;
    use std::cmp::Ordering;
    let k = jf.base();
    let signs: crate::Result<Vec<_>> = jf.eigenvalues.iter().map(|e| e.re_sign(k)).collect();
    let less = Decided::Exactly(Ordering::Less);
    let asymptotic = match signs {
        Ok(s) if s.iter().any(|d| d.exactly().is_some() && *d != less) => Value::Bool(false),
        Ok(s) if s.iter().all(|d| *d == less) => Value::Bool(true),
        Ok(_) => Value::Str(sections::NOT_DECIDED.into()),
        Err(e) => Value::Str(format!("not computed: {e}")),
    };
    Value::Obj(
        Report::titled("stability (exact)")
            .str("time", "continuous")
            .str("verdict", sections::stability_text(jf))
            .with("asymptotically_stable", asymptotic)
            .str(
                "method",
                "the signs of the eigenvalues' real parts, read off the Jordan form",
            ),
    )
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
