//! The short text of `analyze`: each section in a line or a few (system, field, order,
//! stability, minimal order, McMillan degree, zeros, Jordan structure), the whole section
//! with `--full`; JSON and LaTeX always show the whole section.
//!
//! [`analyze_section`] wraps a finished section in a [`Value::Alt`] whose text is
//! [`AltText::Summary`]; the lines are read off the section's own values (no computation
//! besides counting and the sign of real parts). The characteristic polynomial is printed
//! once, named `chi(s)` in the system section, and the zero polynomial once, `z(s)` in the
//! zeros section; the other sections refer to them by name.

use super::text::{inline_text, short_complex};
use super::{Alt, AltText, Report, Value};

/// Longest list of exact values printed in one summary line (else approximations).
const EXACT_LINE: usize = 120;

fn s(r: &Report, k: &str) -> String {
    r.get(k).map_or_else(|| "-".into(), inline_text)
}

fn items<'a>(r: &'a Report, k: &str) -> &'a [Value] {
    match r.get(k) {
        Some(Value::List(xs)) => xs,
        Some(Value::Alt(a)) => match &a.data {
            Value::List(xs) => xs,
            _ => &[],
        },
        _ => &[],
    }
}

fn obj(v: &Value) -> Option<&Report> {
    match v {
        Value::Obj(r) => Some(r),
        _ => None,
    }
}

fn int(r: &Report, k: &str) -> Option<i64> {
    match r.get(k) {
        Some(Value::Int(n)) => Some(*n),
        _ => None,
    }
}

fn approx(r: &Report) -> Option<(f64, f64)> {
    match r.get("approx") {
        Some(Value::List(xs)) => match xs.as_slice() {
            [Value::Float(a), Value::Float(b)] => Some((*a, *b)),
            [Value::Float(a)] => Some((*a, 0.0)),
            _ => None,
        },
        _ => None,
    }
}

/// Multiplicity of an eigenvalue or zero object (`algebraic_multiplicity` or `multiplicity`).
fn mult(r: &Report) -> i64 {
    int(r, "algebraic_multiplicity")
        .or_else(|| int(r, "multiplicity"))
        .unwrap_or(1)
}

/// The values of eigenvalue / zero objects in one line: exact when short, else approximate.
fn values_line(xs: &[Value]) -> String {
    let objs: Vec<&Report> = xs.iter().filter_map(obj).collect();
    let with_mult = |v: String, r: &Report| match mult(r) {
        1 => v,
        m => format!("{v} (x{m})"),
    };
    let exact: Vec<String> = objs.iter().map(|r| with_mult(s(r, "value"), r)).collect();
    let line = exact.join(", ");
    if line.chars().count() <= EXACT_LINE && objs.iter().all(|r| r.get("value").is_some()) {
        return line;
    }
    let approx: Vec<String> = objs
        .iter()
        .filter_map(|r| approx(r).map(|z| with_mult(short_complex(z), r)))
        .collect();
    format!("~ {}", approx.join(", "))
}

fn system(r: &Report) -> Vec<String> {
    let name = s(r, "name");
    let mut out = vec![if name.is_empty() { s(r, "file") } else { name }];
    out.push(format!(
        "field {}, order {}, inputs {}, outputs {}, {}",
        s(r, "field"),
        s(r, "states"),
        s(r, "inputs"),
        s(r, "outputs"),
        s(r, "form")
    ));
    out.push(format!(
        "characteristic polynomial chi(s) = {}",
        s(r, "charpoly")
    ));
    out.push(MORE.into());
    out
}

fn realization(r: &Report) -> Vec<String> {
    let mut out = vec![format!(
        "minimal order = McMillan degree {}; controllability rank {}, observability rank {}",
        s(r, "mcmillan_degree"),
        s(r, "controllability_rank"),
        s(r, "observability_rank")
    )];
    let g = s(r, "transfer_matrix");
    if g.chars().count() <= EXACT_LINE {
        out.push(format!("G(s) = {g}"));
    }
    out
}

fn scb(r: &Report) -> Vec<String> {
    let zeros: i64 = items(r, "invariant_zeros")
        .iter()
        .filter_map(obj)
        .map(mult)
        .sum();
    vec![format!(
        "dims {}, chains {}, {zeros} invariant zeros (roots of z(s)), left/right invertible {}/{}",
        s(r, "dims"),
        s(r, "chains"),
        s(r, "left_invertible"),
        s(r, "right_invertible")
    )]
}

fn zeros(r: &Report) -> Vec<String> {
    let zs = items(r, "invariant_zeros");
    let n: i64 = zs.iter().filter_map(obj).map(mult).sum();
    let mut out = vec![format!(
        "{n}, minimum phase {}, normal rank {}",
        s(r, "minimum_phase"),
        s(r, "normal_rank")
    )];
    if n > 0 {
        out.push(format!(
            "  zero polynomial z(s) = {}",
            s(r, "zero_polynomial")
        ));
        out.push(format!("  zeros: {}", values_line(zs)));
    }
    out
}

/// Stability: the exact verdict of the section's `stability` (decided over $\mathbb{Q}$
/// without floats) when there is one, else read off the eigenvalues' approximate real parts
/// and their Jordan blocks, and said to be so.
fn stability(eigs: &[&Report], exact: Option<&Report>) -> String {
    if let Some(Value::Str(v)) = exact.and_then(|r| r.get("verdict")) {
        return format!("stability (exact): {v}");
    }
    format!("{} (from the approximations)", stability_approx(eigs))
}

/// Stability from the eigenvalues' approximate real parts and their Jordan blocks.
fn stability_approx(eigs: &[&Report]) -> String {
    fn re(r: &Report) -> f64 {
        approx(r).map_or(f64::NAN, |z| z.0)
    }
    fn big(r: &Report) -> bool {
        match r.get("blocks") {
            Some(Value::List(b)) => b.iter().any(|x| matches!(x, Value::Int(n) if *n > 1)),
            _ => false,
        }
    }
    if eigs.iter().any(|r| re(r).is_nan()) {
        return "stability: - (no approximations)".into();
    }
    if eigs.iter().all(|r| re(r) < 0.0) {
        "stability: asymptotically stable (every eigenvalue in Re s < 0)".into()
    } else if eigs.iter().any(|r| re(r) > 0.0) {
        let n: i64 = eigs.iter().filter(|r| re(r) > 0.0).map(|r| mult(r)).sum();
        format!("stability: unstable ({n} eigenvalues in Re s > 0)")
    } else if eigs.iter().any(|r| re(r) == 0.0 && big(r)) {
        "stability: unstable (a Jordan block larger than 1 on the imaginary axis)".into()
    } else {
        "stability: marginally stable (eigenvalues on the imaginary axis, all semisimple)".into()
    }
}

fn jordan(r: &Report) -> Vec<String> {
    let eigs: Vec<&Report> = items(r, "eigenvalues").iter().filter_map(obj).collect();
    let n: i64 = eigs.iter().map(|e| mult(e)).sum();
    let mut out = vec![
        format!(
            "{n} eigenvalues (roots of chi(s)), {} distinct: {}",
            eigs.len(),
            values_line(items(r, "eigenvalues"))
        ),
        stability(&eigs, r.get("stability").and_then(obj)),
    ];
    let nontrivial: Vec<String> = eigs
        .iter()
        .filter(|e| int(e, "geometric_multiplicity") != Some(mult(e)))
        .map(|e| format!("{} blocks {}", s(e, "value"), s(e, "blocks")))
        .collect();
    out.push(if nontrivial.is_empty() {
        "Jordan structure: diagonalizable (every Jordan block 1x1)".into()
    } else {
        format!("Jordan structure: {}", nontrivial.join("; "))
    });
    if let Some(v) = r.get("verified") {
        out.push(format!("verified (A T = T J): {}", inline_text(v)));
    }
    out
}

fn modes(r: &Report) -> Vec<String> {
    let ms: Vec<&Report> = items(r, "modes").iter().filter_map(obj).collect();
    let f: Vec<String> = ms
        .iter()
        .map(|m| match m.get("frequency_hz") {
            Some(Value::Float(x)) => super::text::sig(*x),
            _ => "-".into(),
        })
        .collect();
    vec![format!(
        "{} modes (frequencies in Hz: {})",
        ms.len(),
        f.join(", ")
    )]
}

/// The scalar items of a section in one line (`key value`), lists and matrices counted.
fn generic(r: &Report) -> Vec<String> {
    let parts: Vec<String> = r
        .items
        .iter()
        .filter_map(|(k, v)| match v {
            Value::Bool(_) | Value::Int(_) | Value::Float(_) => {
                Some(format!("{k} {}", inline_text(v)))
            }
            Value::Str(t) if t.chars().count() <= 100 => Some(format!("{k}: {t}")),
            _ => None,
        })
        .collect();
    vec![parts.join(", ")]
}

/// A section of `analyze` with its short text (the section's title, then its lines).
pub fn analyze_section(key: &str, v: Value) -> Value {
    let Value::Obj(r) = &v else {
        return v;
    };
    // a section that failed, was skipped or does not apply says so in full
    if ["error", "skipped", "not_applicable"]
        .iter()
        .any(|k| r.get(k).is_some())
    {
        return v;
    }
    let mut lines = match key {
        "system" => system(r),
        "realization" => realization(r),
        "structure" => scb(r),
        "zeros" => zeros(r),
        "jordan" => jordan(r),
        "modes" => modes(r),
        _ => generic(r),
    };
    if let Some(t) = &r.title {
        let first = lines.remove(0);
        lines.insert(0, format!("{t}: {first}"));
    }
    Value::Alt(Box::new(Alt {
        data: v,
        text: AltText::Summary(lines),
    }))
}

/// The line under the short text of `analyze`: where the rest is.
pub const MORE: &str = "(a summary: every section in full with --full, or --format json)";
