//! The report of `critical`: the critical values of one parameter, the intervals between
//! them, and at each value the eigenvalues of $A(v_0)$; the factor of a repeated eigenvalue
//! and its exact value are rendered here from the polynomial over $\mathbb{Q}(v_0)$ (or
//! $K(v_0)$) and the algebraic number the study holds, text and LaTeX from the same value.

use crate::algebraic::AlgebraicNumber;
use crate::field::Rational;
use crate::report::display::fmt_rational;
use crate::report::latex::{algebraic_latex, poly_over_ext_latex};
use crate::report::{Report, Value};
use crate::study::CriticalValues;
use crate::study::critical::{EigenvalueAt, FactorAt};

/// Longest factor or eigenvalue shown (a factor over a field of high degree is a wall of digits; its
/// eigenvalue and blocks are still reported).
const MAX_FACTOR_LEN: usize = 400;

/// The text and LaTeX of the factor, in `x` with coefficients in $t = v_0$.
pub fn factor_displays(f: &FactorAt) -> (String, String) {
    match f {
        FactorAt::Q(p) => (p.to_string(), poly_over_ext_latex(p, "x")),
        FactorAt::K(p) => (p.to_string(), poly_over_ext_latex(p, "x")),
    }
}

/// `factor` (the irreducible factor over $\mathbb{Q}(v_0)$) and `eigenvalue` (its root,
/// exactly, when the factor is linear) of a repeated eigenvalue.
fn eigenvalue_at(mut o: Report, e: &EigenvalueAt) -> Report {
    if let Some(f) = &e.factor {
        let (text, latex) = factor_displays(f);
        if text.len() <= MAX_FACTOR_LEN {
            o = o.math("factor", text, latex);
        }
    }
    if let Some(v) = &e.value {
        let text = v.value_string();
        if text.len() <= MAX_FACTOR_LEN {
            o = o.math("eigenvalue", text, algebraic_latex(v));
        }
    }
    o
}

fn number(a: &AlgebraicNumber, digits: usize) -> Report {
    // isolating interval refined to about the displayed precision
    let w = Rational::new(
        1.into(),
        num_bigint::BigInt::from(10).pow(digits.min(60) as u32),
    );
    let a = &a.refined(&w).unwrap_or_else(|_| a.clone());
    let (lo, hi) = a.interval().unwrap_or_default();
    Report::new()
        .str("value", a.value_string())
        .float("approx", a.approx().0)
        .str("digits", a.digits(digits).0)
        .str("minpoly", a.minpoly().to_string())
        .list(
            "interval",
            vec![Value::Str(fmt_rational(&lo)), Value::Str(fmt_rational(&hi))],
        )
}

/// The report of a [`CriticalValues`] (contract keys `critical_values[]`, `intervals[]`).
pub fn critical_report(cv: &CriticalValues, digits: usize) -> Report {
    let doubled = cv.over_field.as_ref().is_some_and(|f| f.doubled);
    let crit: Vec<Value> = cv
        .critical
        .iter()
        .map(|c| {
            let mut r = number(&c.value, digits).str("kind", c.kind.name());
            if let Some(h) = &c.minpoly_over_field {
                r = r.str("minpoly_over_field", h.to_string());
            }
            if let Some(w) = c.omega {
                r = r.float("omega", w);
            }
            let eig: Vec<Value> = c
                .eigenvalues_at
                .iter()
                .map(|e| {
                    let o = Report::new()
                        .list(
                            "approx",
                            vec![Value::Float(e.approx.0), Value::Float(e.approx.1)],
                        )
                        .int("algebraic_multiplicity", e.multiplicity)
                        .list(
                            "blocks",
                            e.blocks.iter().map(|b| Value::Int(*b as i64)).collect(),
                        );
                    Value::Obj(eigenvalue_at(o, e))
                })
                .collect();
            Value::Obj(r.bool("certified", c.certified).list("eigenvalues_at", eig))
        })
        .collect();
    let ivs: Vec<Value> = cv
        .intervals
        .iter()
        .map(|iv| {
            let c = &iv.counts;
            Value::Obj(
                Report::new()
                    .str("from", iv.from.value_string())
                    .str("to", iv.to.value_string())
                    .float("from_approx", iv.from.approx().0)
                    .float("to_approx", iv.to.approx().0)
                    .rational("sample", &iv.sample)
                    .bool("stable", iv.stable)
                    .int(
                        "unstable_eigenvalues",
                        if doubled {
                            c.unstable() / 2
                        } else {
                            c.unstable()
                        },
                    )
                    .int("real_negative", c.real_negative)
                    .int("zero", c.zero)
                    .int("real_positive", c.real_positive)
                    .int("complex_pairs_stable", c.complex_pairs_stable)
                    .int("imaginary_pairs", c.imaginary_pairs)
                    .int("complex_pairs_unstable", c.complex_pairs_unstable),
            )
        })
        .collect();
    let rejected: Vec<Value> = cv
        .rejected
        .iter()
        .map(|(a, why)| Value::Obj(number(a, digits).str("reason", why.clone())))
        .collect();
    let charpoly: Vec<Value> = match &cv.over_field {
        Some(f) => f
            .charpoly
            .iter()
            .map(|c| Value::Str(c.to_string_var(&cv.param)))
            .collect(),
        None => cv
            .charpoly
            .coeffs
            .iter()
            .map(|c| Value::Str(c.to_string_var(&cv.param)))
            .collect(),
    };
    let out = Report::titled(format!(
        "critical values of {} on [{}, {}]",
        cv.param,
        fmt_rational(&cv.from),
        fmt_rational(&cv.to)
    ))
    .str("param", cv.param.clone());
    let out = match &cv.over_field {
        Some(f) if f.doubled => out
            .str("field", f.field.to_string())
            .str(
                "counts_of",
                "A(v) and its complex conjugate (same real parts; unstable_eigenvalues is that of A(v))",
            ),
        Some(f) => out.str("field", f.field.to_string()),
        None => out,
    };
    out.list("critical_values", crit)
        .list("intervals", ivs)
        .list("rejected", rejected)
        .list(
            "singular_values",
            cv.singular
                .iter()
                .zip(&cv.singular_reasons)
                .map(|(a, why)| Value::Obj(number(a, digits).str("reason", why.name())))
                .collect(),
        )
        .list(
            "persistent",
            cv.persistent
                .iter()
                .map(|k| Value::Str(k.name().into()))
                .collect(),
        )
        .list("charpoly_coeffs", charpoly)
        .bool("verified", cv.verified)
}
