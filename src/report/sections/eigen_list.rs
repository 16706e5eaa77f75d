//! The eigenvalue list of a Jordan form over any base field as report objects, from
//! [`crate::jordan::JordanForm::eigenvalues`] (values, not re-parsed text): per entry its
//! `value` (a number, or an element of $\mathbb{Q}(p)$), else the irreducible `factor` whose
//! roots it stands for, the multiplicities, the Jordan `blocks`, and the typed answers about
//! the real embedding (`real`, `real_part_sign`: exact, or `not decided in symbols`).

use crate::field::Field;
use crate::jordan::{Decided, EigenValue, Eigenvalue, JordanForm};
use crate::report::{Report, Value};
use std::cmp::Ordering;

/// The text of a typed answer that the parameters' values decide.
pub const NOT_DECIDED: &str = "not decided in symbols";

/// `true` / `false`, or [`NOT_DECIDED`].
fn decided_bool(d: Decided<bool>) -> Value {
    match d {
        Decided::Exactly(b) => Value::Bool(b),
        Decided::NotInSymbols => Value::Str(NOT_DECIDED.into()),
    }
}

/// `negative` / `zero` / `positive`, or [`NOT_DECIDED`] (or why it was not computed).
fn sign_text<F: Field>(k: &F, e: &Eigenvalue<F>) -> String {
    match e.re_sign(k) {
        Ok(Decided::Exactly(Ordering::Less)) => "negative".into(),
        Ok(Decided::Exactly(Ordering::Equal)) => "zero".into(),
        Ok(Decided::Exactly(Ordering::Greater)) => "positive".into(),
        Ok(Decided::NotInSymbols) => NOT_DECIDED.into(),
        Err(err) => format!("not computed: {err}"),
    }
}

/// The eigenvalue objects of `jf` with the factor written in `var` (`factor`,
/// `algebraic_multiplicity`, `blocks`, `value` for a number or an element of the field,
/// `real`, `real_part_sign`), in the order of [`JordanForm::eigenvalues`].
pub fn eigenvalue_structure<F: Field>(jf: &JordanForm<F>, var: &str) -> Vec<Value> {
    let k = jf.base();
    jf.eigenvalues
        .iter()
        .map(|e| {
            let c = &jf.components[e.component];
            let ints = e.blocks.iter().map(|&b| Value::Int(b as i64)).collect();
            let mut r = Report::new()
                .str("factor", c.factor.to_string_var(var))
                .int("algebraic_multiplicity", e.algebraic_multiplicity)
                .with("blocks", Value::List(ints));
            if !matches!(e.value(), EigenValue::RootOf(_)) {
                r = r.str("value", super::jordan::eigenvalue_value_text(k, e));
            }
            Value::Obj(
                r.with("real", decided_bool(e.is_real()))
                    .str("real_part_sign", sign_text(k, e)),
            )
        })
        .collect()
}

/// Asymptotic stability ($\operatorname{Re}\theta < 0$ for every eigenvalue) read off the
/// typed signs of the eigenvalue list: `unstable` when a real part is positive or an
/// eigenvalue of zero real part has a Jordan block larger than 1 ($t^k$ growth), `not
/// asymptotically stable` when one is zero (all exact, whatever the other entries),
/// `asymptotically stable` when every sign is negative, else [`NOT_DECIDED`].
pub fn stability_text<F: Field>(jf: &JordanForm<F>) -> String {
    let k = jf.base();
    let mut signs = vec![];
    for e in &jf.eigenvalues {
        match e.re_sign(k) {
            Ok(s) => signs.push(s),
            Err(err) => return format!("not computed: {err}"),
        }
    }
    let has = |o: Ordering| signs.contains(&Decided::Exactly(o));
    let on_axis_block =
        jf.eigenvalues.iter().zip(&signs).any(|(e, s)| {
            *s == Decided::Exactly(Ordering::Equal) && e.blocks.iter().any(|&b| b > 1)
        });
    if has(Ordering::Greater) {
        "unstable: an eigenvalue has a positive real part".into()
    } else if on_axis_block {
        "unstable: a Jordan block larger than 1 on the imaginary axis".into()
    } else if has(Ordering::Equal) {
        "not asymptotically stable: an eigenvalue has zero real part".into()
    } else if signs.iter().all(|s| *s == Decided::Exactly(Ordering::Less)) {
        "asymptotically stable: every eigenvalue has a negative real part".into()
    } else {
        NOT_DECIDED.into()
    }
}
