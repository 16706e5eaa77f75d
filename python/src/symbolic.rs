//! Systems with symbolic parameters: entries in $\mathbb{Q}(p_1, \dots, p_k)$.
//!
//! Each operation runs the library's generic algorithm on the system copied into a fresh
//! field (an empty condition log, as the command line's `src/cli/symbolic` does) and adds
//! `params` (the symbol names), `field` and `conditions`: the irreducible polynomials in
//! the parameters the result assumes nonzero (pivots, divisions, $\det T$). `verified` is
//! the result's identity checked as rational functions. Questions that need numbers
//! (signs, the modal table, the float cross-check) are refused with one line.

use crate::ops::{mnf_out, scb_typed, tf_parts, zeros_typed};
use crate::out::*;
use crate::values::{elem, terms};
use crate::{FResult, Fail};
use exactlti::field::{ElemDisplay, Field};
use exactlti::io::TypedSystem as Typed;
use exactlti::matrix::Matrix;
use exactlti::poly::Poly;
use exactlti::ratfunc::RatFuncField;
use exactlti::realization::{self, MinrealMethod};
use exactlti::structure::factor_qp::factor_over_qp;
use exactlti::system::discrete::stability::Domain;

type T = Typed<RatFuncField>;

/// The refusal of an operation that needs numbers (`ValueError`, as the command line's
/// exit status 2).
pub(crate) fn needs_numbers(what: &str, field: &str) -> Fail {
    Fail::Input(format!(
        "symbolic parameters: {what} needs numbers, this system's entries lie in {field}; \
         give every symbol a value first (StateSpace.subs)"
    ))
}

fn refield(t: &T) -> (RatFuncField, T) {
    let k = t.a_raw.field().fresh();
    let t = t.in_field(&k);
    (k, t)
}

/// `params`, `field` and `conditions` (after the computation filled the log).
fn context(k: &RatFuncField) -> FResult<Vec<(&'static str, Out)>> {
    let conds = k.conditions_strings()?;
    // the same polynomials as values: terms of the normalized display
    let values = k
        .conditions()?
        .iter()
        .map(|p| terms(&p.display_normalized()))
        .collect();
    Ok(vec![
        ("condition_values", Out::List(values)),
        (
            "params",
            Out::List(k.vars().iter().map(|v| Out::Str(v.clone())).collect()),
        ),
        ("field", Out::Str(k.to_string())),
        (
            "conditions",
            Out::List(conds.into_iter().map(Out::Str).collect()),
        ),
    ])
}

fn with_context(out: Out, k: &RatFuncField) -> FResult<Out> {
    let Out::Dict(mut kv) = out else {
        return Ok(out);
    };
    kv.retain(|(key, _)| *key != "minimum_phase" && *key != "report");
    kv.extend(context(k)?);
    Ok(Out::Dict(kv))
}

/// The monic irreducible factors over $\mathbb{Q}(p)$: `{factor, multiplicity, root?}`
/// with the factor's coefficients (low degree first) as exact strings.
fn factors(p: &Poly<RatFuncField>) -> FResult<Out> {
    if p.is_zero() || p.deg() == 0 {
        return Ok(Out::List(vec![]));
    }
    let k = p.field().clone();
    let fs = factor_over_qp(p)?;
    Ok(Out::List(
        fs.iter()
            .map(|(g, e)| {
                let mut kv = vec![
                    ("factor", poly(g)),
                    ("multiplicity", usize_out(*e)),
                    ("root", Out::None),
                ];
                if g.deg() == 1 {
                    let r = k.div(&k.neg(&g.coeff(0)), &g.coeff(1));
                    if let Some(r) = r {
                        kv[2].1 = Out::Str(k.fmt_elem(&r));
                        kv.push(("root_value", elem(&k, &r)));
                    }
                }
                Out::Dict(kv)
            })
            .collect(),
    ))
}

pub(crate) fn scb(t: &T) -> FResult<Out> {
    let (k, t) = refield(t);
    let s = &t.ss;
    let r = exactlti::structure::scb::scb(&s.a, &s.b, &s.c, &s.d)?;
    let zf = factors(&r.invariant_zero_polynomial())?;
    let Out::Dict(mut kv) = scb_typed(&t)? else {
        unreachable!("scb output is a dict")
    };
    kv.push(("zero_factors", zf));
    with_context(Out::Dict(kv), &k)
}

pub(crate) fn zeros(t: &T, domain: Domain) -> FResult<Out> {
    let (k, t) = refield(t);
    let s = &t.ss;
    let z = exactlti::structure::zeros::invariant_zeros(&s.a, &s.b, &s.c, &s.d)?;
    let zf = factors(&z.polynomial)?;
    let Out::Dict(mut kv) = zeros_typed(&t, domain)? else {
        unreachable!("zeros output is a dict")
    };
    kv.push(("factors", zf));
    with_context(Out::Dict(kv), &k)
}

/// The characteristic polynomial of `A` and its factors over $\mathbb{Q}(p)$.
pub(crate) fn poles(t: &T) -> FResult<Out> {
    let (k, t) = refield(t);
    let p = t.ss.a.charpoly()?;
    let kv = vec![("polynomial", poly(&p)), ("factors", factors(&p)?)];
    with_context(Out::Dict(kv), &k)
}

pub(crate) fn minreal(t: &T, m: MinrealMethod) -> FResult<Out> {
    let (k, t) = refield(t);
    let r = realization::minimal(&t.ss, m)?;
    let sys = system_out(Typed {
        descriptor: None,
        a_raw: r.system.a.clone(),
        ss: r.system.clone(),
    });
    let kv = vec![
        ("system", sys),
        ("order", usize_out(r.order)),
        ("original_order", usize_out(r.original_order)),
        ("method", Out::Str(r.method.name().to_string())),
        ("T", r.t.as_ref().map(mat).unwrap_or(Out::None)),
        ("verified", Out::Bool(r.verified)),
    ];
    with_context(Out::Dict(kv), &k)
}

pub(crate) fn tf(t: &T, domain: Domain) -> FResult<Out> {
    if t.descriptor.is_some() {
        return Err(Fail::Unsupported(format!(
            "symbolic parameters: the transfer matrix of a descriptor system is not yet \
             supported over {}",
            t.a_raw.field()
        )));
    }
    let (k, t) = refield(t);
    let (mut kv, a_min) = tf_parts(&t.ss, domain)?;
    let poles = a_min.charpoly()?;
    kv.push(("pole_polynomial", poly_var(&poles, domain.var())));
    kv.push(("pole_factors", factors(&poles)?));
    with_context(Out::Dict(kv), &k)
}

pub(crate) fn mnf(t: &T) -> FResult<Out> {
    let (k, t) = refield(t);
    let s = &t.ss;
    let m = exactlti::structure::mechanical::mechanical_normal_form_in(
        None,
        &s.a,
        &s.b,
        &s.c,
        &s.d,
        exactlti::structure::mechanical::DEFAULT_MAX_CANDIDATES,
    )?;
    if let Some(f) = &m.form {
        k.record_condition(f.t.det()?.num());
    }
    let mut kv = mnf_out(&m);
    kv.retain(|(key, _)| *key != "verified");
    kv.push(("verified", Out::Bool(!m.exists || m.verified)));
    with_context(Out::Dict(kv), &k)
}

/// The Jordan structure of a descriptor system over $\mathbb{Q}(p)$: [`jordan`] of the
/// pencil's finite part as the api chooses it ([`exactlti::api::jordan_values::finite_part`],
/// the command line's code path), with `infinite_blocks` and the note.
pub(crate) fn jordan_descriptor(
    d: &exactlti::system::Descriptor<RatFuncField>,
    path: &std::path::Path,
) -> FResult<Out> {
    let fp = exactlti::api::jordan_values::finite_part(d, path)?;
    let Out::Dict(mut kv) = jordan(&fp.a)? else {
        unreachable!("jordan returns a dict")
    };
    kv.push(("notes", Out::List(vec![])));
    crate::ops::with_finite_part(&mut kv, &fp.infinite_blocks, fp.verified, &fp.note);
    Ok(Out::Dict(kv))
}

/// The Jordan structure over $\mathbb{Q}(p)$ ([`exactlti::jordan::jordan_qp`]).
pub(crate) fn jordan(a: &Matrix<RatFuncField>) -> FResult<Out> {
    let jf = exactlti::jordan::jordan_qp(a)?;
    let (t, j) = jf.primary_form()?;
    let k = jf.base();
    let mut var = k.vars().to_vec();
    var.push(exactlti::report::sections::qp_var_name(k.vars()));
    let evs = jf
        .components
        .iter()
        .zip(jf.values())
        .map(|(c, value)| {
            Out::Dict(vec![
                (
                    "value",
                    value
                        .as_ref()
                        .map(|v| Out::Str(k.fmt_elem(v)))
                        .unwrap_or(Out::None),
                ),
                (
                    "value_v",
                    value.as_ref().map(|v| elem(k, v)).unwrap_or(Out::None),
                ),
                (
                    "factor_terms",
                    terms(&exactlti::jordan::qp_form::integral(&c.factor)),
                ),
                (
                    "factor",
                    Out::Str(exactlti::jordan::qp_form::integral(&c.factor).to_string_vars(&var)),
                ),
                ("degree", usize_out(c.degree())),
                ("algebraic_multiplicity", usize_out(c.multiplicity)),
                (
                    "geometric_multiplicity",
                    usize_out(c.geometric_multiplicity()),
                ),
                (
                    "blocks",
                    Out::List(c.blocks.iter().map(|&b| usize_out(b)).collect()),
                ),
            ])
        })
        .collect();
    let ctx = context(k)?;
    let mut kv = vec![
        ("eigenvalues", Out::List(evs)),
        ("var", Out::Str(var.last().cloned().unwrap_or_default())),
        ("charpoly", poly(&jf.charpoly)),
        ("A", mat(&jf.a)),
        ("J", mat(&j)),
        ("T", mat(&t)),
        ("complete", Out::Bool(jf.complete())),
        ("verified", Out::Bool(jf.verified)),
    ];
    // the form's own conditions (discriminants, resultants, pivots), not the field's log
    kv.extend(
        ctx.into_iter()
            .filter(|(key, _)| *key != "conditions" && *key != "condition_values"),
    );
    kv.push((
        "condition_values",
        Out::List(
            jf.conditions
                .iter()
                .map(|c| terms(&c.num().display_normalized()))
                .collect(),
        ),
    ));
    kv.push((
        "conditions",
        Out::List(
            exactlti::report::sections::conditions_qp(&jf)
                .into_iter()
                .map(Out::Str)
                .collect(),
        ),
    ));
    Ok(Out::Dict(kv))
}
