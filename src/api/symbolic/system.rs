//! The system commands over $\mathbb{Q}(p)$: `scb`, `minreal`, `tf`, `zeros`, `ctrb`,
//! `obsv`, `standard`, `analyze`.
//!
//! Each runs the generic algorithm over [`RatFuncField`] on a fresh condition log and adds
//! `field` and `conditions` to the report. Decisions that need numbers (signs, Hurwitz,
//! approximations) are made only where they hold for every parameter value (a zero at
//! $s = 0$ is not minimum phase); otherwise `minimum_phase` says "depends on parameters".

use super::conditions::{self, Item};
use crate::api::common::exact_only;
use crate::api::common::with_path;
use crate::api::{Command, Failure, Outcome};
use crate::field::ElemDisplay;
use crate::field::Field;
use crate::io::{SystemFile, TypedSystem};
use crate::poly::Poly;
use crate::ratfunc::RatFuncField;
use crate::ratfunc::{Part, Reason, Structure};
use crate::realization;
use crate::report::sections::conditions::with_conditions;
use crate::report::{Report, Value, sections, str_list};
use crate::structure::factor_qp::{factor_over_qp, hurwitz_over_qp};
use crate::system::StateSpace;
use crate::system::discrete::stability::Domain;
use std::path::Path;

type T = TypedSystem<RatFuncField>;

/// Runs `cmd` over $\mathbb{Q}(p)$; `Ok(None)`: the command does not work over
/// $\mathbb{Q}(p)$ (the caller refuses it).
pub(in crate::api) fn run(
    cmd: &Command,
    f: &SystemFile,
    t: &T,
    path: &Path,
) -> Result<Option<Outcome>, Failure> {
    let k = t.a_raw.field().fresh();
    let t = t.in_field(&k);
    let e = |err| with_path(path, err);
    let s = &t.ss;
    // the command's own condition set (`conditions` module docs); `None`: the log's
    let mut items: Option<Vec<Item>> = None;
    let (r, ok) = match cmd {
        Command::Scb { .. } => {
            let r = crate::structure::scb::scb(&s.a, &s.b, &s.c, &s.d).map_err(e)?;
            let ok = r.verified;
            let zp = r.invariant_zero_polynomial();
            items = honest(scb_items(&r, &zp)).map_err(e)?;
            let rep = minimum_phase(r.report(), &zp).map_err(e)?;
            (rep.with("zero_factors", factors(&zp).map_err(e)?), ok)
        }
        Command::Zeros { .. } => {
            let z = crate::structure::zeros::invariant_zeros(&s.a, &s.b, &s.c, &s.d).map_err(e)?;
            items = Some(conditions::zero_escapes(&z.polynomial));
            let rep = minimum_phase(z.report(), &z.polynomial).map_err(e)?;
            (
                rep.with("zero_factors", factors(&z.polynomial).map_err(e)?),
                true,
            )
        }
        Command::Minreal {
            method, descriptor, ..
        } => {
            if *descriptor {
                return Ok(None);
            }
            let Some(m) = method.exact() else {
                return Ok(None);
            };
            let r = realization::minimal(s, m).map_err(e)?;
            items = honest(conditions::mcmillan(&r.system, s))
                .map_err(e)?
                .map(|m| {
                    let mut v = conditions::result_poles(&r.system, r.t.as_ref());
                    v.extend(m);
                    v
                });
            (r.report(), r.verified)
        }
        Command::Ctrb { .. } | Command::Obsv { .. } => {
            if t.descriptor.is_some() {
                return Ok(None);
            }
            let dual = matches!(cmd, Command::Obsv { .. });
            let c = if dual {
                realization::observability_structure(&s.a, &s.c)
            } else {
                realization::controllability_structure(&s.a, &s.b)
            }
            .map_err(e)?;
            let part = if dual {
                c.uncontrollable.transpose()
            } else {
                c.uncontrollable.clone()
            };
            let key = if dual {
                "unobservable_charpoly_factors"
            } else {
                "uncontrollable_charpoly_factors"
            };
            let cp = part.charpoly().map_err(e)?;
            items = honest(if dual {
                conditions::krylov_drops(&s.a.transpose(), &s.c.transpose(), true)
            } else {
                conditions::krylov_drops(&s.a, &s.b, false)
            })
            .map_err(e)?;
            let rep = sections::ctrb_report(&c, dual).map_err(e)?;
            (rep.with(key, factors(&cp).map_err(e)?), c.verified)
        }
        Command::Tf { .. } => {
            // with E: G = C (sE - A)^-1 B + D of the pencil, and the standard form (the
            // system the other commands see) checked against it by its Markov parameters
            let (g, mut v) = match &t.descriptor {
                Some(d) => (
                    realization::descriptor_transfer_matrix(d).map_err(e)?,
                    conditions::pencil(d).map_err(e)?,
                ),
                None => (s.transfer_matrix().map_err(e)?, vec![]),
            };
            let (rep, ok, min) = tf(s, &g, Domain::of(f.signals.dt.as_ref())).map_err(e)?;
            items = honest(conditions::mcmillan(&min, s)).map_err(e)?.map(|m| {
                v.extend(m);
                v
            });
            (rep, ok)
        }
        Command::Standard { .. } => match &t.descriptor {
            Some(d) => {
                let r = realization::descriptor_to_standard(d).map_err(e)?;
                (r.report(), r.verified)
            }
            None => (sections::already_standard(s), true),
        },
        Command::Analyze { .. } => {
            let out = crate::api::analyze::analyze(f, &t)?;
            let mut rep = depends(out.report, "minimum_phase");
            let mut ok = out.verified;
            // the eigenvalue structure over Q(p) (its conditions join this computation's)
            let title = "eigenvalues and Jordan structure over Q(p)";
            let (sec, jf) = crate::api::analyze::structure_section(&s.a, title);
            if let Some(jf) = jf {
                ok &= jf.verified;
                for c in &jf.conditions {
                    k.record_condition(c.num());
                }
            }
            rep.push("jordan", Value::Obj(sec));
            // the modal table as formulas, as `modes` over Q(p) (one code path)
            let modes = match super::modes::modes_report(&s.a) {
                Ok(m) => Value::Obj(m),
                Err(err) => {
                    Value::Obj(Report::titled("modes over Q(p)").str("error", err.to_string()))
                }
            };
            (set_key(rep, "modes", modes), ok)
        }
        Command::Modes { .. } => (super::modes::modes_report(&s.a).map_err(e)?, true),
        _ => return Ok(None),
    };
    let items = items.map(|v| with_input(&t, v));
    finish(&k, r, ok, items).map(Some).map_err(e)
}

/// `items` and the input's denominators.
fn with_input(t: &T, mut items: Vec<Item>) -> Vec<Item> {
    items.extend(conditions::input(&t.ss, t.descriptor.as_ref()));
    items
}

/// The condition set of `scb`: where a zero escapes, the poles of the SCB matrices and of
/// the transformations, and where a transformation is singular.
fn scb_items(
    r: &crate::structure::scb::Scb<RatFuncField>,
    zp: &Poly<RatFuncField>,
) -> crate::Result<Vec<Item>> {
    let res = StateSpace {
        a: r.a.clone(),
        b: r.b.clone(),
        c: r.c.clone(),
        d: r.d.clone(),
    };
    let mut v = conditions::zero_escapes(zp);
    v.extend(conditions::result_poles(&res, None));
    for (p, m) in [
        (Part::Gamma1, &r.gamma1),
        (Part::Gamma2, &r.gamma2),
        (Part::Gamma3, &r.gamma3),
        (Part::U, &r.u_pre),
        (Part::Y, &r.y_pre),
    ] {
        v.extend(conditions::denominators(p, m, true));
        if m.is_square() && m.nrows() > 0 {
            let d = m.det()?;
            v.push((
                d.num().clone(),
                Reason::StructureChange(Structure::SingularBasis),
            ));
        }
    }
    Ok(v)
}

/// The outcome of a report over $\mathbb{Q}(p)$: exact only, the field and the conditions
/// (`items` with reasons, else those recorded in `k` during the computation), `verified` set
/// to `ok`.
fn finish(
    k: &RatFuncField,
    r: Report,
    ok: bool,
    items: Option<Vec<Item>>,
) -> crate::Result<Outcome> {
    let conds = match items {
        Some(v) => k.explain(v)?,
        None => k.explained()?,
    };
    let r = set_key(exact_only(r), "field", Value::Str(k.to_string()));
    let r = with_conditions(r, k, &conds);
    Ok(Outcome::new(set_key(r, "verified", Value::Bool(ok)), ok))
}

/// `r` with `key` set to `v` (replaced in place when present, else appended).
pub(in crate::api) fn set_key(mut r: Report, key: &str, v: Value) -> Report {
    match r.items.iter_mut().find(|(k, _)| k == key) {
        Some(slot) => slot.1 = v,
        None => r.items.push((key.to_string(), v)),
    }
    r
}

/// `minimum_phase` decided over $\mathbb{Q}(p)$ from the zero polynomial's factors
/// ([`hurwitz_over_qp`]: a zero at the origin for every parameter value is not minimum
/// phase), else "depends on parameters".
///
/// Undecided: `minimum_phase_requires` names the deciding rational functions, the entries
/// of the Routh array's first column of each undecided factor that are not constants (all
/// must be positive); files state no signs of their parameters, so none is assumed.
fn minimum_phase(r: Report, zeros: &Poly<RatFuncField>) -> crate::Result<Report> {
    Ok(match hurwitz_over_qp(zeros)? {
        Some(b) => set_key(r, "minimum_phase", Value::Bool(b)),
        None => {
            let k = zeros.field().clone();
            let mut req = vec![];
            // the Routh entries of a factor of degree > 4 or with long coefficients swell
            // (diag(p0..p9): degree 9 in 10 parameters): then no list is given at all (a
            // partial list would read as complete)
            let mut complete = true;
            for (g, _) in crate::structure::factor_qp::factor_over_qp(zeros)? {
                if crate::structure::scb::hurwitz(&g).is_none() {
                    if !routh_affordable(&g) {
                        complete = false;
                        break;
                    }
                    for x in conditions::routh_first_column(&g) {
                        if !k.is_constant(&x) {
                            req.push(format!("{} > 0", k.fmt_elem(&x)));
                        }
                    }
                }
            }
            req.dedup();
            let r = depends(r, "minimum_phase");
            if complete {
                r.with("minimum_phase_requires", str_list(req))
            } else {
                r
            }
        }
    })
}

/// A sign question over $\mathbb{Q}(p)$ is not decided: the key says so (nested reports
/// too, as in `analyze`).
fn depends(r: Report, key: &str) -> Report {
    fn value(v: Value, key: &str) -> Value {
        match v {
            Value::Obj(r) => Value::Obj(depends(r, key)),
            Value::List(xs) => Value::List(xs.into_iter().map(|x| value(x, key)).collect()),
            // an analyze section with its compact summary: the data, and the summary's
            // "minimum phase -" (an undecided value) said the same way
            Value::Alt(mut a) => {
                a.data = value(a.data, key);
                if let crate::report::AltText::Summary(lines) = &mut a.text {
                    let undecided = format!("{} -", key.replace('_', " "));
                    let said = format!("{} depends on parameters", key.replace('_', " "));
                    for l in lines.iter_mut() {
                        *l = l.replace(&undecided, &said);
                    }
                }
                Value::Alt(a)
            }
            v => v,
        }
    }
    let items = r
        .items
        .into_iter()
        .map(|(k, v)| {
            if k == key && matches!(v, Value::Null) {
                (k, Value::Str("depends on parameters".into()))
            } else {
                (k, value(v, key))
            }
        })
        .collect();
    Report {
        title: r.title,
        items,
    }
}

/// The monic irreducible factors over $\mathbb{Q}(p)$ as `{factor, multiplicity}` items
/// (with `root` for linear factors).
pub(in crate::api) fn factors(p: &Poly<RatFuncField>) -> crate::Result<Value> {
    let k = p.field().clone();
    let fs = factor_over_qp(p)?;
    Ok(Value::List(
        fs.iter()
            .map(|(g, e)| {
                let mut r = Report::new()
                    .str("factor", g.to_string_var("s"))
                    .int("multiplicity", *e);
                if g.deg() == 1 {
                    r = r.str("root", k.fmt_elem(&k.neg(&g.coeff(0))));
                }
                Value::Obj(r)
            })
            .collect(),
    ))
}

/// `tf` over $\mathbb{Q}(p)$: the one `tf` report ([`sections::tf_report`]) of the
/// minimal realization of `s` (Kalman; with `E`: `s` is the standard form whose transfer
/// matrix `g` is); verified: the realization's checks and the expansion of every entry at
/// $s = \infty$ equals $D, CB, CAB, \dots$ ($2n$ terms) of `s` and of the minimal system.
fn tf(
    s: &StateSpace<RatFuncField>,
    g: &crate::system::transfer::TransferMatrix<RatFuncField>,
    domain: Domain,
) -> crate::Result<(Report, bool, StateSpace<RatFuncField>)> {
    let r = realization::realize_state_space(s, g)?;
    let markov = g.matches_markov(s);
    let rep = sections::tf_report(g, &r, Some(markov), domain)?;
    let ok = matches!(rep.get("verified"), Some(Value::Bool(true)));
    let min = r.state_space.ok_or_else(|| {
        crate::Error::Verification("tf: the Kalman realization has no state-space form".into())
    })?;
    Ok((rep, ok, min))
}

/// The command's own condition set, or `None` (the computation's log, each condition labelled
/// by its step) when a minor it needs is too large to expand (`Limit`, e.g. the Vandermonde
/// minors of diag(p0..p9)).
fn honest(r: crate::Result<Vec<Item>>) -> crate::Result<Option<Vec<Item>>> {
    match r {
        Ok(v) => Ok(Some(v)),
        Err(crate::error::Error::Limit(_)) => Ok(None),
        Err(x) => Err(x),
    }
}

/// Whether the Routh first column of `g` is small enough to state: degree at most 4 and at
/// most 64 terms in its coefficients' numerators and denominators together.
fn routh_affordable(g: &Poly<RatFuncField>) -> bool {
    let terms: usize = (0..=g.deg())
        .map(|i| {
            let c = g.coeff(i);
            c.num().len() + c.den().len()
        })
        .sum();
    g.deg() <= 4 && terms <= 64
}
