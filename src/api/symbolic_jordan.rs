//! `jordan FILE` over $\mathbb{Q}(p_1, \dots, p_k)$: the report of
//! [`crate::jordan::params::jordan_params`] on the file's `A`.
//!
//! Keys: `field`, `n`, `charpoly` (monic over $\mathbb{Q}(p)$), `charpoly_factors` (in
//! $\mathbb{Z}\lbrack p, s\rbrack$ with multiplicities), `eigenvalues[]` (`value` for an
//! eigenvalue in $\mathbb{Q}(p)$, else `roots_of` the irreducible factor, `degree`,
//! `algebraic_multiplicity`, `geometric_multiplicity`, `blocks`, `kernel_dims`), `J`, `T`
//! (exact rational functions), `presentation`, `conditions`, `verified` ($A T = T J$ as
//! rational functions, $\det T \ne 0$).

use super::Outcome;
use super::common::exact_only;
use crate::error::Result;
use crate::field::Field;
use crate::jordan::params::{ParamJordanForm, jordan_params};
use crate::matrix::Matrix;
use crate::ratfunc::RatFuncField;
use crate::report::{Report, Value, str_list};

/// A matrix as rows of exact strings (no `approx` over $\mathbb{Q}(p)$).
fn rows(k: &RatFuncField, m: &Matrix<RatFuncField>) -> Value {
    Value::List(
        (0..m.nrows())
            .map(|i| str_list(m.row(i).iter().map(|x| k.fmt_elem(x))))
            .collect(),
    )
}

/// The contract's report of a Jordan form over $\mathbb{Q}(p)$.
pub fn report(jf: &ParamJordanForm) -> Report {
    let k = &jf.field;
    let s = jf.var_name();
    let evs: Vec<Value> = jf
        .eigenvalues
        .iter()
        .map(|e| {
            let mut r = Report::new();
            r = match &e.value {
                Some(v) => r.str("value", k.fmt_elem(v)),
                None => r.str("roots_of", format!("{} = 0", jf.fmt_factor(&e.factor))),
            };
            let ints =
                |xs: &[usize]| Value::List(xs.iter().map(|&b| Value::Int(b as i64)).collect());
            Value::Obj(
                r.str("factor", jf.fmt_factor(&e.factor))
                    .int("degree", e.degree)
                    .int("algebraic_multiplicity", e.algebraic_multiplicity)
                    .int("geometric_multiplicity", e.geometric_multiplicity)
                    .with("blocks", ints(&e.blocks))
                    .with("kernel_dims", ints(&e.kernel_dims)),
            )
        })
        .collect();
    let factors: Vec<String> = jf
        .eigenvalues
        .iter()
        .map(|e| {
            let f = jf.fmt_factor(&e.factor);
            let f = if e.factor.len() > 1 {
                format!("({f})")
            } else {
                f
            };
            if e.algebraic_multiplicity > 1 {
                format!("{f}^{}", e.algebraic_multiplicity)
            } else {
                f
            }
        })
        .collect();
    let charpoly = {
        let cs = jf.charpoly.coeffs();
        let mut parts = vec![];
        for (i, c) in cs.iter().enumerate().rev() {
            if k.is_zero(c) {
                continue;
            }
            let mono = match i {
                0 => String::new(),
                1 => s.clone(),
                _ => format!("{s}^{i}"),
            };
            let cf = k.fmt_elem(c);
            parts.push(match (mono.is_empty(), k.is_one(c)) {
                (true, _) => format!("({cf})"),
                (false, true) => mono,
                (false, false) => format!("({cf})*{mono}"),
            });
        }
        if parts.is_empty() {
            "0".to_string()
        } else {
            parts.join(" + ")
        }
    };
    let presentation = if jf.complete {
        "every eigenvalue in the field: J is the Jordan matrix, T its chains".to_string()
    } else {
        "eigenvalues of irreducible factors of degree >= 2 are roots of that factor: their \
         diagonal block of J is the restriction of A to ker f(A)^e (T: a basis of it); \
         their Jordan blocks are listed under eigenvalues[].blocks"
            .to_string()
    };
    Report::titled("Jordan form over QQ(p)")
        .str("field", k.to_string())
        .int("n", jf.n())
        .str("charpoly", charpoly)
        .str("charpoly_factored", factors.join("*"))
        .list("eigenvalues", evs)
        .with("J", rows(k, &jf.j))
        .with("T", rows(k, &jf.t))
        .str("presentation", presentation)
        .with("conditions", str_list(jf.conditions_strings()))
        .bool("verified", jf.verified)
}

/// `jordan FILE` on a symbolic `A`.
///
/// # Errors
/// Those of [`jordan_params`].
pub fn jordan_outcome(a: &Matrix<RatFuncField>) -> Result<Outcome> {
    let jf = jordan_params(a)?;
    Ok(Outcome::new(report(&jf), jf.verified))
}

/// `jordan --real FILE` on a symbolic `A` ([`crate::jordan::over_qp::real_form_qp`]); the
/// conditions recorded in its fresh field join the report.
///
/// # Errors
/// Those of the real form over $\mathbb{Q}(p)$.
pub fn real_outcome(a: &Matrix<RatFuncField>) -> Result<Outcome> {
    let r = crate::jordan::over_qp::real_form_qp(a)?;
    let conds = r.a.field().conditions_strings()?;
    let rep = exact_only(r.report()).with("conditions", str_list(conds));
    Ok(Outcome::new(rep, r.verified))
}

/// `mnf FILE` over $\mathbb{Q}(p)$: [`crate::structure::mechanical::mechanical_normal_form_in`]
/// on $(A, B, C, D)$ in a fresh field. The report is the rational one with the theorem's
/// checks under `existence_checks` and `conditions` the polynomials in the parameters the
/// result assumes nonzero (pivots and divisions, the denominators of $T$ and $T^{-1}$); `verified`: the exact check of
/// the form (similarity, Markov parameters) as rational functions.
///
/// # Errors
/// Those of the normal form.
pub fn mnf_outcome(
    a: &Matrix<RatFuncField>,
    b: &Matrix<RatFuncField>,
    c: &Matrix<RatFuncField>,
    d: &Matrix<RatFuncField>,
) -> Result<Outcome> {
    let k = a.field().fresh();
    let re = |m: &Matrix<RatFuncField>| {
        Matrix::from_vec(k.clone(), m.nrows(), m.ncols(), m.as_slice().to_vec())
    };
    let (a, b, c, d) = (re(a), re(b), re(c), re(d));
    let m = crate::structure::mechanical::mechanical_normal_form_in(
        None,
        &a,
        &b,
        &c,
        &d,
        crate::structure::mechanical::DEFAULT_MAX_CANDIDATES,
    )?;
    // t is invertible where t and t^-1 (checked: t^-1 t = I) are both defined
    if let Some(f) = &m.form {
        for x in f.t.as_slice().iter().chain(f.t_inv.as_slice()) {
            k.record_condition(x.den());
        }
    }
    let conds = k.conditions_strings()?;
    let mut r = exact_only(m.report());
    for item in r.items.iter_mut() {
        if item.0 == "conditions" {
            item.0 = "existence_checks".to_string();
        }
    }
    let r = r
        .str("field", k.to_string())
        .with("conditions", str_list(conds));
    Ok(Outcome::new(r, !m.exists || m.verified))
}
