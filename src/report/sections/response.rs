//! Reports of the free response $x(t) = e^{At} x_0$ in closed form
//! ([`crate::jordan::StateResponse`] over $\mathbb{Q}$, the number fields and, every
//! eigenvalue in the field, $\mathbb{Q}(p)$) and of the mode
//! contributions ([`crate::realization::contribution`]).

use super::eigenvalue_text;
use crate::algebraic::Ext;
use crate::field::{ElemDisplay, Field};
use crate::jordan::{EigenField, JordanForm, StateResponse};
use crate::matrix::Matrix;
use crate::ratfunc::{RatFunc, RatFuncField};
use crate::realization::contribution::{Contributions, Truncation, Weight};
use crate::report::{Report, Value, str_list};

/// The identities every closed form here is checked by.
pub fn response_identities() -> Value {
    str_list([
        "x'(t) = A x(t): A g_k = s g_k + (k+1) g_(k+1) for every eigenvalue s and power k \
         (the derivative of t^k e^(s t) is s t^k e^(s t) + k t^(k-1) e^(s t))"
            .to_string(),
        "x(0) = x0: the g_0 of all eigenvalues add up to x0".to_string(),
    ])
}

/// `x(t)` at the requested times (float evaluation of the exact closed form).
/// $x(t)$ at one time: `(t, real parts, imaginary parts)`, the imaginary parts `None` for a
/// real system (real $A$ and $x_0$).
pub type TimeValue = (f64, Vec<f64>, Option<Vec<f64>>);

fn values(times: &[TimeValue]) -> Value {
    let floats = |x: &[f64]| Value::List(x.iter().map(|v| Value::Float(*v)).collect());
    Value::List(
        times
            .iter()
            .map(|(t, x, im)| {
                let r = Report::new().float("t", *t).with("x", floats(x));
                Value::Obj(match im {
                    Some(im) => r.with("x_imag", floats(im)),
                    None => r,
                })
            })
            .collect(),
    )
}

/// The free response over an exact field with a Jordan form: one term per eigenvalue and
/// power (`g` exact in the eigenvalue's field), the identities, `verified`, and the float
/// values at `times`.
pub fn state_response_report<F: EigenField>(
    jf: &JordanForm<F>,
    sr: &StateResponse<Ext<F>>,
    x0: &Matrix<F>,
    times: &[TimeValue],
    verified: bool,
) -> Report {
    let items = super::jordan::response_terms(jf, "g", |ev| sr.terms_of(jf, ev));
    let mut r = Report::titled("Free response x(t) = e^(At) x0 = sum_k t^k e^(s t) g")
        .matrix("x0", x0)
        .list("terms", items)
        .with("identities", response_identities());
    if !times.is_empty() {
        r = r.with("values", values(times));
    }
    r.str(
        "exact",
        "the g are exact (in the eigenvalue's field; conjugate eigenvalues have conjugate g); \
         the values at given times are floats",
    )
    .bool("verified", verified)
}

/// The free response over $\mathbb{Q}(p)$ (every eigenvalue in $\mathbb{Q}(p)$: the terms of
/// `fr`, from [`JordanForm::free_response`], lie in the base field), with the form's
/// conditions; `verified` as the caller checked it.
pub fn param_response_report(
    jf: &JordanForm<RatFuncField>,
    fr: &StateResponse<Ext<RatFuncField>>,
    x0: &[RatFunc],
    verified: bool,
) -> Report {
    let k = jf.base();
    let values = jf.values();
    let mut items = vec![];
    for (ci, power, g) in &fr.terms {
        let e = g.field();
        let theta = values[*ci]
            .as_ref()
            .map_or_else(String::new, |v| k.fmt_elem(v));
        let g = g.as_slice().iter().map(|x| match e.to_base(x) {
            Some(v) => k.fmt_elem(&v),
            None => e.fmt_elem(x),
        });
        items.push(Value::Obj(
            Report::new()
                .str("eigenvalue", theta)
                .int("power", *power)
                .with("g", str_list(g)),
        ));
    }
    Report::titled("Free response x(t) = e^(At) x0 = sum_k t^k e^(s t) g")
        .str("field", k.to_string())
        .with("x0", str_list(x0.iter().map(|x| k.fmt_elem(x))))
        .list("terms", items)
        .with("identities", response_identities())
        .with("conditions", str_list(super::conditions_qp(jf)))
        .bool("verified", verified)
}

fn weight_values<F: Field>(k: &F, w: &Weight<F::Elem>) -> (String, Option<f64>) {
    match w {
        Weight::Zero => ("0".into(), Some(0.0)),
        Weight::Infinite => ("inf".into(), None),
        Weight::H2Squared(r) => (k.fmt_elem(r), k.approx(r).map(|z| z.0)),
        Weight::H2SquaredWhereStable(r) => (k.fmt_elem(r), None),
    }
}

const WEIGHT_WORDS: &str = "h2_squared = ||C_p (sI - A_p)^-1 B_p||_2^2 of the mode's part (exact, Lyapunov over the field; conjugate transposes over Q(i)); \
     0: every Markov parameter of the part vanishes (eq. 33: b c = 0); inf: the part \
     contributes and is not asymptotically stable. A mode is one irreducible factor of \
     the characteristic polynomial (a real eigenvalue, a complex pair, or all conjugates), \
     so every truncation stays over the field. H = C G_k B are the residues (eq. 33's products b c): \
     G(s) = D + sum k! H / (s - eigenvalue)^(k+1)";

/// The ranked modes (heaviest first) and, with `--keep`, the truncation with its exact error
/// (over $\mathbb{Q}$, $\mathbb{Q}(\sqrt d)$, $\mathbb{Q}(i)$: each eigenvalue named, its
/// residues in its own field).
pub fn contributions_report<F: EigenField>(
    c: &Contributions<F>,
    trunc: Option<&Truncation<F>>,
) -> Report {
    let jf = &c.jordan;
    let k = jf.base();
    let modes: Vec<Value> = c
        .modes
        .iter()
        .enumerate()
        .map(|(rank, m)| {
            let (w, approx) = weight_values(k, &m.weight);
            let mut residues = vec![];
            for &ev in &m.eigenvalues {
                let (field, f) = jf.root_map(ev);
                for (power, h) in m.residues.iter().enumerate() {
                    residues.push(Value::Obj(
                        Report::new()
                            .str("eigenvalue", eigenvalue_text(&jf.eigenvalues[ev]))
                            .int("power", power)
                            .matrix("H", &h.map(&field, &f)),
                    ));
                }
            }
            let mut r = Report::new()
                .int("rank", rank + 1)
                .with(
                    "eigenvalues",
                    str_list(
                        m.eigenvalues
                            .iter()
                            .map(|&i| eigenvalue_text(&jf.eigenvalues[i])),
                    ),
                )
                .int("order", m.part.a.nrows())
                .str("h2_squared", w);
            if let Some(x) = approx {
                r = r.float("h2_squared_approx", x);
            }
            Value::Obj(r.list("residues", residues))
        })
        .collect();
    let r =
        Report::titled("Mode contributions (minimal-realizations paper eq. 33), heaviest first")
            .str("weight", WEIGHT_WORDS)
            .list("modes", modes);
    with_truncation(r, c, trunc)
}

/// [`contributions_report`] over $\mathbb{Q}(p)$: each mode named by its factor, the residues
/// at its generic root $t$ (in $\mathbb{Q}(p)$ for a linear factor), the weights rational
/// functions that are the squared $H_2$ norms where the parts are stable, the modes in the
/// factors' order (not ranked: [`crate::realization::contribution`]), and the conditions.
pub fn contributions_report_qp(c: &Contributions<RatFuncField>) -> Report {
    let jf = &c.jordan;
    let k = jf.base();
    let modes: Vec<Value> = c
        .modes
        .iter()
        .map(|m| {
            let comp = &jf.components[m.component];
            let (w, _) = weight_values(k, &m.weight);
            let residues: Vec<Value> = m
                .residues
                .iter()
                .enumerate()
                .map(|(power, h)| {
                    Value::Obj(Report::new().int("power", power).matrix("H", h))
                })
                .collect();
            let mut r = Report::new()
                .str("factor", comp.factor.to_string_var("s"))
                .int("order", m.part.a.nrows())
                .str("h2_squared", w);
            if matches!(m.weight, Weight::H2SquaredWhereStable(_)) {
                r = r.str(
                    "h2_squared_valid",
                    "where A_p is Hurwitz (a sign condition on the parameters, not decided in symbols); elsewhere the H2 norm is infinite",
                );
            }
            Value::Obj(r.list("residues", residues))
        })
        .collect();
    let title = if c.ranked {
        "Mode contributions (minimal-realizations paper eq. 33), heaviest first"
    } else {
        "Mode contributions (minimal-realizations paper eq. 33), in the order of the factors (weights in symbols are not ranked)"
    };
    Report::titled(title)
        .str("field", k.to_string())
        .str("weight", WEIGHT_WORDS)
        .list("modes", modes)
        .with("conditions", str_list(super::conditions_qp(jf)))
        .bool("verified", c.verified)
}

/// The truncation (when asked) and `verified`.
fn with_truncation<F: Field>(
    mut r: Report,
    c: &Contributions<F>,
    trunc: Option<&Truncation<F>>,
) -> Report {
    let k = c.d.field();
    if let Some(t) = trunc {
        let mut tr = Report::new()
            .with(
                "kept_ranks",
                Value::List(t.kept.iter().map(|&i| Value::Int(i as i64 + 1)).collect()),
            )
            .int("order", t.system.a.nrows())
            .matrices(&[
                ("A", &t.system.a),
                ("B", &t.system.b),
                ("C", &t.system.c),
                ("D", &t.system.d),
            ]);
        tr = match &t.error_h2_squared {
            Some(h) => tr.str("error_h2_squared", k.fmt_elem(h)).float(
                "error_h2_approx",
                k.approx(h).map_or(f64::NAN, |z| z.0.sqrt()),
            ),
            None => tr.str(
                "error_h2_squared",
                "inf (a dropped mode is not asymptotically stable)",
            ),
        };
        tr = match &t.error_dc {
            Some(m) => tr.matrix("error_dc_gain", m),
            None => tr.str("error_dc_gain", "inf (a dropped mode has the eigenvalue 0)"),
        };
        tr = tr
            .matrix("error_markov0", &t.error_markov0)
            .str(
                "exact",
                "A, B, C, D and the errors are exact; only *_approx are floats",
            )
            .bool("verified", t.verified);
        r = r.obj("truncation", tr);
    }
    r.bool("verified", c.verified && trunc.is_none_or(|t| t.verified))
}
