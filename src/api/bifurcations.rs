//! `bifurcations --of scb|jordan|minreal|zeros|ctrb [--depth N]` (contract, second wave):
//! the generic structure of a symbolic system and, for each condition that can vanish, the
//! structure on that branch ([`crate::structure::bifurcation`]).
//!
//! Report: `of`, `field`, `generic{...}` (the structural fields, `conditions`, `verified`)
//! and `branches[]`, each with `condition` (`"sigma1 = 0"`), `substitution` (the parameter
//! solved for), `outcome` (`explored`, `undefined`, `not_explored`), `changed` (the
//! structure differs from its parent's), the structural fields, `conditions`, `verified` and
//! its own `branches[]`.

use super::symbolic::system::factors;
use super::{Failure, Outcome};
use crate::error::Result;
use crate::field::ElemDisplay;
use crate::io::TypedSystem;
use crate::ratfunc::RatFuncField;
use crate::realization::{self, MinrealMethod};
use crate::report::{Report, Value, sections, str_list};
use crate::structure::bifurcation::{BranchOutcome, Limits, Node, bifurcations};
use crate::system::StateSpace;
use clap::ValueEnum;
use std::path::Path;

/// `--of`: the structure explored.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Of {
    Scb,
    Jordan,
    Minreal,
    Zeros,
    Ctrb,
}

/// The structure on one branch: `key` is compared between a branch and its parent, `info`
/// only shown.
#[derive(Clone, Debug)]
struct Summary {
    key: Vec<(String, Value)>,
    info: Vec<(String, Value)>,
    verified: bool,
}

impl PartialEq for Summary {
    fn eq(&self, other: &Self) -> bool {
        let j = |v: &[(String, Value)]| {
            let mut r = Report::new();
            r.items = v.to_vec();
            r.to_json()
        };
        j(&self.key) == j(&other.key)
    }
}

fn ints(v: &[usize]) -> Value {
    Value::List(v.iter().map(|&x| Value::Int(x as i64)).collect())
}

fn summary(of: Of, s: &StateSpace<RatFuncField>) -> Result<Summary> {
    let k = s.field().clone();
    let kv = |a: &str, v: Value| (a.to_string(), v);
    Ok(match of {
        Of::Scb => {
            let r = crate::structure::scb::scb(&s.a, &s.b, &s.c, &s.d)?;
            let zp = r.invariant_zero_polynomial();
            let [na, nb, nc, nd] = r.dims;
            let dims = Report::new()
                .int("a", na)
                .int("b", nb)
                .int("c", nc)
                .int("d", nd);
            Summary {
                key: vec![
                    kv("dims", Value::Obj(dims)),
                    kv("chains", ints(&r.chains)),
                    kv("left_invertible", Value::Bool(r.left_invertible)),
                    kv("right_invertible", Value::Bool(r.right_invertible)),
                ],
                info: vec![
                    kv("zero_polynomial", Value::Str(zp.to_string_var("s"))),
                    kv("zero_factors", factors(&zp)?),
                    kv("A", matrix_value(&r.a)),
                ],
                verified: r.verified,
            }
        }
        Of::Zeros => {
            let z = crate::structure::zeros::invariant_zeros(&s.a, &s.b, &s.c, &s.d)?;
            Summary {
                key: vec![
                    kv("normal_rank", Value::Int(z.normal_rank as i64)),
                    kv("zero_count", Value::Int(z.polynomial.deg() as i64)),
                ],
                info: vec![
                    kv(
                        "zero_polynomial",
                        Value::Str(z.polynomial.to_string_var("s")),
                    ),
                    kv("zero_factors", factors(&z.polynomial)?),
                ],
                verified: true,
            }
        }
        Of::Minreal => {
            let m = realization::minimal(s, MinrealMethod::Kalman)?;
            let c = realization::controllability_structure(&s.a, &s.b)?;
            let o = realization::observability_structure(&s.a, &s.c)?;
            Summary {
                key: vec![
                    kv("order", Value::Int(m.order as i64)),
                    kv("controllable_order", Value::Int(c.order as i64)),
                    kv("observable_order", Value::Int(o.order as i64)),
                ],
                info: vec![kv(
                    "pole_polynomial",
                    Value::Str(m.system.a.charpoly()?.to_string_var("s")),
                )],
                verified: m.verified && c.verified && o.verified,
            }
        }
        Of::Ctrb => {
            let c = realization::controllability_structure(&s.a, &s.b)?;
            let cp = c.uncontrollable.charpoly()?;
            Summary {
                key: vec![
                    kv("controllable_order", Value::Int(c.order as i64)),
                    kv("controllability_indices", ints(&c.indices)),
                ],
                info: vec![kv("uncontrollable_charpoly_factors", factors(&cp)?)],
                verified: c.verified,
            }
        }
        Of::Jordan => {
            let jf = crate::jordan::jordan_qp(&s.a)?;
            // its conditions go into this computation's log
            for c in &jf.conditions {
                k.record_condition(c.num());
            }
            let mut key = Vec::new();
            let mut vals = Vec::new();
            for (c, value) in jf.components.iter().zip(jf.values()) {
                key.push(Value::Obj(
                    Report::new()
                        .int("degree", c.degree())
                        .int("algebraic_multiplicity", c.multiplicity)
                        .with("blocks", ints(&c.blocks)),
                ));
                let mut v = Report::new().str("factor", c.factor.to_string_var("s"));
                if let Some(x) = &value {
                    v = v.str("value", k.fmt_elem(x));
                }
                vals.push(Value::Obj(v.with("blocks", ints(&c.blocks))));
            }
            Summary {
                key: vec![kv("eigenvalue_structure", Value::List(key))],
                info: vec![kv("eigenvalues", Value::List(vals))],
                verified: jf.verified,
            }
        }
    })
}

fn matrix_value(m: &crate::matrix::Matrix<RatFuncField>) -> Value {
    let k = m.field();
    Value::List(
        (0..m.nrows())
            .map(|i| {
                Value::List(
                    (0..m.ncols())
                        .map(|j| Value::Str(k.fmt_elem(m.get(i, j))))
                        .collect(),
                )
            })
            .collect(),
    )
}

/// The report of one node (without `condition`), and whether every result below verified.
fn node_report(k: &RatFuncField, n: &Node<Summary>) -> (Report, bool) {
    let mut r = Report::new();
    r.items.extend(n.result.key.iter().cloned());
    r.items.extend(n.result.info.iter().cloned());
    let conds: Vec<String> = n.conditions.iter().map(|c| k.fmt_poly(c)).collect();
    r = r
        .with("conditions", str_list(conds))
        .bool("verified", n.result.verified);
    let mut ok = n.result.verified;
    if n.expanded {
        let mut bs = Vec::new();
        for b in &n.branches {
            let mut br =
                Report::new().str("condition", format!("{} = 0", k.fmt_poly(&b.condition)));
            let eq = sections::branch_equation(k, b);
            let why = sections::branch_reason(k, b).unwrap_or_default();
            match &b.outcome {
                BranchOutcome::Explored(child) => {
                    let (cr, cok) = node_report(k, child);
                    ok &= cok;
                    br = br
                        .str("substitution", eq)
                        .str("outcome", "explored")
                        .bool("changed", n.changed(b).unwrap_or(false));
                    br.items.extend(cr.items);
                }
                BranchOutcome::Undefined => {
                    br = br
                        .str("substitution", eq)
                        .str("outcome", "undefined")
                        .str("reason", why);
                }
                BranchOutcome::NotExplored(_) => {
                    br = br.str("outcome", "not_explored").str("reason", why);
                }
            }
            bs.push(Value::Obj(br));
        }
        r = r.list("branches", bs);
    }
    (r, ok)
}

/// `bifurcations` on a numeric system: refused, saying what it needs.
pub(super) fn needs_symbols(file: &Path) -> Failure {
    Failure::input(format!(
        "{}: bifurcations needs symbolic parameters (null values, a `symbols` list, or --symbolic)",
        file.display()
    ))
}

/// Runs `bifurcations` on a system over $\mathbb{Q}(p)$.
pub(super) fn run(
    file: &Path,
    t: &TypedSystem<RatFuncField>,
    of: Of,
    depth: usize,
) -> std::result::Result<Outcome, Failure> {
    let k = t.a_raw.field().clone();
    let f = move |s: &StateSpace<RatFuncField>| summary(of, s);
    let limits = Limits {
        depth,
        ..Limits::default()
    };
    let tree = bifurcations(&t.ss, &f, limits).map_err(|e| super::common::with_path(file, e))?;
    let (mut generic, ok) = node_report(&k, &tree);
    let branches = generic
        .items
        .iter()
        .position(|(key, _)| key == "branches")
        .map(|i| generic.items.remove(i).1)
        .unwrap_or(Value::List(vec![]));
    generic.title = None;
    let r = Report::titled("structural bifurcations")
        .str("of", format!("{of:?}").to_lowercase())
        .str("field", k.to_string())
        .int("depth", depth)
        .obj("generic", generic)
        .with("branches", branches)
        .bool("verified", ok);
    Ok(Outcome::new(r, ok))
}
