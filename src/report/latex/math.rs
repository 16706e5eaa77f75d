//! A report as ONE math-mode formula (`$\begin{array}{ll} ... \end{array}$`), for
//! notebooks (Jupyter's `_repr_latex_`: MathJax and KaTeX typeset math only, and
//! `nbconvert --to pdf` sets it inline): a two-column array of keys (`\text`) and values
//! (exact numbers through [`to_math`], matrices as `bmatrix`, objects as nested arrays,
//! lists inline or as numbered rows), cut like the fragment at [`MAX_LIST_ITEMS`] and
//! [`MAX_LIST_DEPTH`].

use super::{MAX_LIST_DEPTH, MAX_LIST_ITEMS, float_math, ident, to_math};
use crate::report::escape::latex_text;
use crate::report::{MatrixOut, Report, Value};

/// Entries of a matrix typeset; larger matrices are shown by their shape.
pub const MAX_ENTRIES: usize = 2500;

/// Text inside math: `\text{...}` with the LaTeX specials escaped.
fn text(s: &str) -> String {
    format!("\\text{{{}}}", latex_text(s))
}

/// The report as one math formula, `$...$`.
///
/// # Examples
/// ```
/// use exactlti::report::Report;
/// use exactlti::report::latex::math;
/// let r = Report::titled("roots").str("value", "1/2 + sqrt(5)/2").int("n", 2);
/// let t = math(&r);
/// assert!(t.starts_with('$') && t.ends_with('$'));
/// assert!(t.contains("\\text{value} & \\frac{1}{2} + \\frac{\\sqrt{5}}{2}"));
/// ```
pub fn math(r: &Report) -> String {
    let mut rows = vec![];
    if let Some(t) = &r.title {
        rows.push(format!("\\mathbf{{{}}} &", text(t)));
    }
    rows.extend(item_rows(r, 0));
    format!(
        "$\\begin{{array}}{{ll}}{}\\end{{array}}$",
        rows.join(" \\\\ ")
    )
}

fn item_rows(r: &Report, depth: usize) -> Vec<String> {
    r.items
        .iter()
        .map(|(k, v)| format!("{} & {}", label(k, v), value(v, depth)))
        .collect()
}

fn label(k: &str, v: &Value) -> String {
    if matches!(v, Value::Matrix(_))
        && k.len() <= 4
        && k.starts_with(|c: char| c.is_ascii_uppercase())
        && k.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
    {
        return ident(k);
    }
    text(&k.replace('_', " "))
}

fn scalar(v: &Value) -> Option<String> {
    Some(match v {
        Value::Null => "\\text{--}".into(),
        Value::Bool(b) => format!("\\text{{{b}}}"),
        Value::Int(n) => n.to_string(),
        Value::Float(x) => float_math(*x),
        Value::Str(s) => to_math(s).unwrap_or_else(|| text(s)),
        Value::Math(m) => m.latex.clone(),
        _ => return None,
    })
}

fn value(v: &Value, depth: usize) -> String {
    if let Some(s) = scalar(v) {
        return s;
    }
    match v {
        Value::Alt(a) => value(&a.data, depth),
        Value::Matrix(m) => matrix(m),
        Value::List(xs) if xs.is_empty() => text("(none)"),
        Value::List(xs) => list(xs, depth),
        Value::Obj(_) if depth >= MAX_LIST_DEPTH => text("(see the JSON report)"),
        Value::Obj(r) => {
            let mut rows = vec![];
            if let Some(t) = &r.title {
                rows.push(format!("\\textit{{{}}} &", latex_text(t)));
            }
            rows.extend(item_rows(r, depth + 1));
            format!(
                "\\begin{{array}}{{ll}}{}\\end{{array}}",
                rows.join(" \\\\ ")
            )
        }
        _ => String::new(),
    }
}

fn list(xs: &[Value], depth: usize) -> String {
    let shown = &xs[..xs.len().min(MAX_LIST_ITEMS)];
    let more = xs.len() - shown.len();
    let tail = if more > 0 {
        format!(",\\ \\dots\\ \\text{{(and {more} more)}}")
    } else {
        String::new()
    };
    let scalars: Option<Vec<String>> = shown.iter().map(scalar).collect();
    if let Some(parts) = scalars {
        return format!("{}{tail}", parts.join(",\\ "));
    }
    if depth >= MAX_LIST_DEPTH {
        return text(&format!("({} entries; see the JSON report)", xs.len()));
    }
    let rows: Vec<String> = shown
        .iter()
        .enumerate()
        .map(|(i, x)| format!("{}. & {}", i + 1, value(x, depth + 1)))
        .collect();
    format!(
        "\\begin{{array}}{{ll}}{}\\end{{array}}{tail}",
        rows.join(" \\\\ ")
    )
}

fn matrix(m: &MatrixOut) -> String {
    if m.nrows == 0 || m.ncols == 0 {
        return text(&format!("{} x {} (empty)", m.nrows, m.ncols));
    }
    if m.nrows * m.ncols > MAX_ENTRIES {
        return text(&format!(
            "{} x {} matrix (see the JSON report)",
            m.nrows, m.ncols
        ));
    }
    let rows: Vec<String> = (0..m.nrows)
        .map(|i| {
            (0..m.ncols)
                .map(|j| match m.latex_at(i, j) {
                    Some(l) => l.to_string(),
                    None => to_math(&m.exact[i][j]).unwrap_or_else(|| text(&m.exact[i][j])),
                })
                .collect::<Vec<_>>()
                .join(" & ")
        })
        .collect();
    // amsmath's bmatrix takes at most 10 columns; an array any number
    format!(
        "\\left[\\begin{{array}}{{*{{{}}}{{c}}}}{}\\end{{array}}\\right]",
        m.ncols,
        rows.join(" \\\\ ")
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::qmat;

    #[test]
    fn one_formula_with_nested_arrays() {
        let inner = Report::titled("part").int("k", 3);
        let r = Report::titled("t & }")
            .matrix("A", &qmat![[1, "1/2"], [3, 4]])
            .list("objs", vec![Value::Obj(inner)])
            .list("xs", (0..100).map(Value::Int).collect());
        let t = math(&r);
        assert!(t.starts_with("$\\begin{array}{ll}") && t.ends_with("\\end{array}$"));
        assert_eq!(t.matches('$').count(), 2, "{t}");
        assert!(t.contains("1 & \\frac{1}{2} \\\\ 3 & 4"), "{t}");
        assert!(t.contains("\\text{t \\& \\}}"), "{t}");
        assert!(t.contains("and 36 more"), "{t}");
        assert_eq!(
            t.matches("\\begin{array}").count(),
            t.matches("\\end{array}").count()
        );
    }
}
