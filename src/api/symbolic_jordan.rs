//! `jordan FILE` over $\mathbb{Q}(p_1, \dots, p_k)$: the report of [`crate::jordan::jordan_qp`]
//! (the generic [`JordanForm`] over $\mathbb{Q}(p)$) on the file's `A`
//! (its `report`, written in `report/sections/jordan.rs`).
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
#[cfg(doc)]
use crate::jordan::JordanForm;
use crate::jordan::jordan_qp;
use crate::matrix::Matrix;
use crate::ratfunc::RatFuncField;
use crate::report::sections::conditions::with_conditions;

/// `jordan FILE` on a symbolic `A`.
///
/// # Errors
/// Those of [`jordan_qp`].
pub fn jordan_outcome(a: &Matrix<RatFuncField>) -> Result<Outcome> {
    let jf = jordan_qp(a)?;
    let k = jf.base().clone();
    let conds = explained_with_input(&k, a)?;
    Ok(Outcome::new(
        with_conditions(jf.report(), &k, &conds),
        jf.verified,
    ))
}

/// The log of `k` (with reasons) and the denominators of the input `a`.
fn explained_with_input(
    k: &RatFuncField,
    a: &Matrix<RatFuncField>,
) -> Result<Vec<crate::ratfunc::Condition>> {
    let mut items = k.recorded_with_reasons();
    for i in 0..a.nrows() {
        for j in 0..a.ncols() {
            let d = a.get(i, j).den();
            if !d.is_constant() {
                let part = crate::ratfunc::Part::A;
                let why = crate::ratfunc::Reason::InputDenominator {
                    part,
                    row: i,
                    col: j,
                };
                items.push((d.clone(), why));
            }
        }
    }
    k.explain(items)
}

/// `jordan --normalize X FILE` on a symbolic `A`: the chains of every eigenvalue in
/// $\mathbb{Q}(p)$ normalised ([`crate::jordan::normalize::normalize_form_qp`]: $A T = T J$
/// and $\det T \ne 0$ checked again, the divisions it made among the conditions).
///
/// # Errors
/// Those of [`jordan_qp`] and of the normalisation.
pub fn normalized_outcome(
    a: &Matrix<RatFuncField>,
    how: &crate::jordan::normalize::Normalization,
) -> Result<Outcome> {
    let mut jf = jordan_qp(a)?;
    let closed = crate::jordan::normalize::normalize_form_qp(&mut jf, how)?;
    let r = crate::report::steps_norm::normalized_form_report_qp(&jf, how, &closed);
    Ok(Outcome::new(r, jf.verified))
}

/// `jordan --real FILE` on a symbolic `A` ([`crate::jordan::over_qp::real_form_qp`]); the
/// conditions recorded in its fresh field join the report.
///
/// # Errors
/// Those of the real form over $\mathbb{Q}(p)$.
pub fn real_outcome(a: &Matrix<RatFuncField>) -> Result<Outcome> {
    let r = crate::jordan::over_qp::real_form_qp(a)?;
    let k = r.a.field().clone();
    let conds = explained_with_input(&k, a)?;
    let rep = with_conditions(exact_only(r.report()), &k, &conds);
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
        use crate::ratfunc::{Part, Reason};
        for (part, m) in [(Part::T, &f.t), (Part::TInv, &f.t_inv)] {
            for i in 0..m.nrows() {
                for j in 0..m.ncols() {
                    let why = Reason::PoleOfEntry {
                        part,
                        row: i,
                        col: j,
                    };
                    k.record_because(m.get(i, j).den(), why);
                }
            }
        }
    }
    let conds = explained_with_input(&k, &a)?;
    let mut r = exact_only(m.report());
    for item in r.items.iter_mut() {
        if item.0 == "conditions" {
            item.0 = "existence_checks".to_string();
        }
    }
    let r = with_conditions(r.str("field", k.to_string()), &k, &conds);
    Ok(Outcome::new(r, !m.exists || m.verified))
}
