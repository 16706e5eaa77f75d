//! The conditions of a result over $\mathbb{Q}(p)$ with their reasons
//! ([`crate::ratfunc::Condition`]): `conditions` (the polynomials, as before) and
//! `condition_reasons` (`{condition, kind, reason}` per polynomial: JSON has the `reason`
//! sentence, text shows a table, LaTeX typesets the polynomial). The sentences are made here,
//! from the [`Reason`] values.

use crate::ratfunc::{Condition, Part, RatFuncField, Reason, Structure};
use crate::report::{Report, Value, str_list};

/// A matrix's name in a sentence.
fn part(p: Part) -> &'static str {
    match p {
        Part::A => "A",
        Part::B => "B",
        Part::C => "C",
        Part::D => "D",
        Part::E => "E",
        Part::T => "T",
        Part::TInv => "T^-1",
        Part::Gamma1 => "G1",
        Part::Gamma2 => "G2",
        Part::Gamma3 => "G3",
        Part::U => "U",
        Part::Y => "Y",
        Part::Result => "the result",
    }
}

/// The short kind of a reason (a JSON key value).
pub fn reason_kind(r: &Reason) -> &'static str {
    match r {
        Reason::InputDenominator { .. } => "input_denominator",
        Reason::StructureChange(_) => "structure_change",
        Reason::PoleOfEntry { .. } => "pole_of_entry",
        Reason::ProofMinor { .. } => "proof_minor",
        Reason::Pivot => "pivot",
    }
}

/// What changes, as a sentence.
fn structure(s: &Structure) -> String {
    match *s {
        Structure::Rank { rank } => format!("the rank drops below {rank}"),
        Structure::Controllable { dim } => {
            format!("the controllable subspace drops below dimension {dim}")
        }
        Structure::Observable { dim } => {
            format!("the observable subspace drops below dimension {dim}")
        }
        Structure::Krylov { blocks, rank, dual } => {
            let (m, what) = if dual {
                ("[C; CA; ...]", "observability")
            } else {
                ("[B, AB, ...]", "controllability")
            };
            format!(
                "the rank of {m} with {blocks} block(s) drops below {rank}: the {what} indices change"
            )
        }
        Structure::McMillanDegree { degree } => {
            format!("the McMillan degree drops below {degree} (a pole cancels or is lost)")
        }
        Structure::FiniteEigenvalues { degree } => format!(
            "deg det(sE - A) drops below {degree}: a finite eigenvalue goes to infinity"
        ),
        Structure::SingularPencil => "det(sE - A) = 0 for every s: the pencil is singular".into(),
        Structure::ZeroEscapes { degree } => format!(
            "a coefficient of the zero polynomial has a pole: an invariant zero goes to infinity (fewer than {degree} finite zeros)"
        ),
        Structure::FactorDegree => {
            "the leading coefficient of a factor of the characteristic polynomial vanishes".into()
        }
        Structure::RepeatedEigenvalue => {
            "two eigenvalues of one factor meet (its discriminant vanishes): the Jordan blocks may change".into()
        }
        Structure::EigenvaluesMeet => {
            "eigenvalues of two factors meet (their resultant vanishes): the Jordan blocks may change".into()
        }
        Structure::SingularBasis => "det T = 0: the basis of the result is singular".into(),
    }
}

/// The reason as a sentence: what breaks where the condition vanishes.
pub fn reason_sentence(r: &Reason) -> String {
    match r {
        Reason::InputDenominator { part: p, row, col } => format!(
            "denominator of {}[{},{}] of the input: the model is undefined",
            part(*p),
            row + 1,
            col + 1
        ),
        Reason::StructureChange(s) => structure(s),
        Reason::PoleOfEntry { part: p, row, col } => format!(
            "pole of {}[{},{}] of the result: the result as written is undefined",
            part(*p),
            row + 1,
            col + 1
        ),
        Reason::ProofMinor { size } => format!(
            "a {size} x {size} minor that proved a rank at a point (the rank may stay where it vanishes)"
        ),
        Reason::Pivot => "a pivot of the elimination (divided by)".into(),
    }
}

/// The items `conditions` (the polynomials as strings, unchanged for readers of the plain
/// list) and `condition_reasons` of `cs`.
pub fn condition_items(k: &RatFuncField, cs: &[Condition]) -> [(String, Value); 2] {
    let vars = k.vars();
    let texts: Vec<String> = cs
        .iter()
        .map(|c| c.poly.display_normalized().to_string_vars(vars))
        .collect();
    let data = cs
        .iter()
        .zip(&texts)
        .map(|(c, t)| {
            let latex = c.poly.display_normalized().to_latex(vars);
            Value::Obj(
                Report::new()
                    .with("condition", Value::math(t.clone(), latex))
                    .str("kind", reason_kind(&c.reason))
                    .str("reason", reason_sentence(&c.reason)),
            )
        })
        .collect();
    let rows = cs
        .iter()
        .zip(&texts)
        .map(|(c, t)| vec![format!("{t} != 0"), reason_sentence(&c.reason)])
        .collect();
    [
        ("conditions".to_string(), str_list(texts)),
        (
            "condition_reasons".to_string(),
            Value::table(
                Value::List(data),
                vec!["condition".into(), "reason".into()],
                rows,
            ),
        ),
    ]
}

/// `r` with `conditions` and `condition_reasons` of `cs` (replacing a `conditions` item in
/// place, appended otherwise).
pub fn with_conditions(mut r: Report, k: &RatFuncField, cs: &[Condition]) -> Report {
    let [(ck, cv), (rk, rv)] = condition_items(k, cs);
    match r.items.iter().position(|(key, _)| key == &ck) {
        Some(i) => {
            r.items[i].1 = cv;
            r.items.retain(|(key, _)| key != &rk);
            let i = r
                .items
                .iter()
                .position(|(key, _)| key == &ck)
                .expect("kept");
            r.items.insert(i + 1, (rk, rv));
        }
        None => {
            r.items.push((ck, cv));
            r.items.push((rk, rv));
        }
    }
    r
}
