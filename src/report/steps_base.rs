//! Small helpers shared by the step sentences (`report::steps` and its continuation files
//! `steps_more`, `steps_forms`, `steps_norm`, `steps_modes`): they sit below all of them so
//! that the chain of files has no cycle.

use crate::field::Field;
use crate::jordan::derivation::{Derivation, Object, Step, StepKind};

/// The variable of characteristic polynomials and transfer functions in displays: the
/// derivation's (`s`, or `z` in discrete time) unless a parameter is so named (then `x`).
pub(crate) fn poly_var<K: Field>(d: &Derivation<K>) -> &'static str {
    let shown = d.field.to_string();
    let v = d.variable;
    let named = [
        format!("({v},"),
        format!(", {v})"),
        format!(", {v},"),
        format!("({v})"),
    ];
    if named.iter().any(|n| shown.contains(n.as_str())) {
        "x"
    } else {
        v
    }
}

pub(crate) fn counts(xs: &[usize]) -> String {
    let v: Vec<String> = xs.iter().map(|x| x.to_string()).collect();
    v.join(", ")
}

pub(crate) fn one_based(xs: &[usize]) -> String {
    if xs.is_empty() {
        return "none".into();
    }
    let v: Vec<String> = xs.iter().map(|x| (x + 1).to_string()).collect();
    v.join(", ")
}

/// The field of a step's first matrix (a number field per part over $\mathbb{Q}$).
pub(crate) fn step_field<K: Field>(d: &Derivation<K>, s: &Step<K>) -> K {
    s.objects
        .iter()
        .find_map(|(_, o)| match o {
            Object::Matrix(m) => Some(m.field().clone()),
            _ => None,
        })
        .unwrap_or_else(|| d.field.clone())
}

/// The step that names the eigenvalue of `part` (kernel sequence or modal data).
pub(crate) fn theta_step<K: Field>(d: &Derivation<K>, part: Option<usize>) -> Option<&Step<K>> {
    d.steps.iter().find(|s| {
        s.part == part && matches!(s.kind, StepKind::KernelSequence | StepKind::ModalData)
    })
}
