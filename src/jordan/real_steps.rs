//! The real Jordan form step by step (`jordan --real --steps`, issue 27): the complex
//! derivation of [`super::steps::jordan_steps`] (kernel sequences, Weyr/Segre, chains), then
//! per complex pair $\theta = a + bi$, $\bar\theta$ the real columns and blocks that
//! [`super::JordanForm::real_form_with`] built from those chains, each checked
//! $A T_c = T_c J_c$ in the pair's real field $F$, and finally $A T = T J$ over one real field
//! when every block lies in it.
//!
//! The pair steps are the real form's own blocks (recorded from its result, not derived a
//! second time). A pair whose real field is large stays compact (a step without matrices).

use super::derivation::{Derivation, Method, Object, StepKind};
use super::real::RealEntries;
use crate::algebraic::NumberField;
use crate::error::Result;
use crate::field::{Field, Q};
use crate::matrix::Matrix;

/// The real Jordan form of a rational matrix, step by step (module docs); `expand` as
/// `jordan --real --expand`.
///
/// # Errors
/// As [`super::jordan`] and [`super::JordanForm::real_form_with`].
pub fn real_jordan_steps(a: &Matrix<Q>, expand: bool) -> Result<Derivation<NumberField>> {
    let mut d = super::steps::jordan_steps(a)?;
    d.method = Method::RealJordan;
    let jf = super::jordan(a)?;
    let rf = jf.real_form_with(expand)?;
    // the part of a factor: its index in the derivation's factorization step
    let factors: Vec<_> = d
        .of_kind(StepKind::Factorization)
        .find_map(|s| match s.get("factors") {
            Some(Object::Factors(f)) => Some(f.iter().map(|(p, _)| p.to_string()).collect()),
            _ => None,
        })
        .unwrap_or_else(Vec::new);
    for b in rf.blocks.iter().filter(|b| b.pair) {
        let comp = jf.eigenvalues[b.eigenvalue].component;
        let shown = rf.factors[comp].to_string();
        let part = factors.iter().position(|f| *f == shown);
        let (objects, holds) = match &b.entries {
            RealEntries::Expanded { pair, t, j } => {
                let ok = &pair.matrix(a) * t == t * j;
                let objects = vec![
                    ("Tc", Object::Matrix(t.clone())),
                    ("Jc", Object::Matrix(j.clone())),
                ];
                (objects, Some(ok))
            }
            _ => (vec![("compact", Object::Count(1))], None),
        };
        d.steps.push(super::derivation::Step {
            kind: StepKind::RealPair,
            part,
            objects,
            holds,
            assumes: vec![],
        });
    }
    if let Some((j, t)) = rf.single_field() {
        let f = t.field().clone();
        let af = a.map(&f, |x| f.from_rational(x));
        let ok = &af * &t == &t * &j && t.det().is_ok_and(|x| !f.is_zero(&x));
        d.steps.push(super::derivation::Step {
            kind: StepKind::RealForm,
            part: None,
            objects: vec![("T", Object::Matrix(t)), ("J", Object::Matrix(j))],
            holds: Some(ok),
            assumes: vec![],
        });
    }
    Ok(d)
}
