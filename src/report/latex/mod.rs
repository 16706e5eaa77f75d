//! LaTeX rendering of a [`Report`] (`--format latex`): a fragment that `\input`s into any
//! document loading `amsmath`, or with `--standalone` a complete document.
//!
//! Every value is typeset: exact strings through [`to_math`] as math (`\frac`, `\sqrt`,
//! `\mathrm{i}`, subscripts for `r7`), prose as escaped text, matrices as `bmatrix` (up to
//! amsmath's 10 columns) or `array` (wider), lists of objects as nested `description`
//! lists (at most [`MAX_LIST_DEPTH`] deep: LaTeX allows six), long lists cut at
//! [`MAX_LIST_ITEMS`] with the count of what was left out. User strings (names, keys, file
//! names) are escaped ([`super::escape`]), so none can end a `%` comment or a math group.

mod expr;
pub mod lines;
mod math;
mod values;

pub use expr::{ident, to_math};
pub use math::math;
pub use values::{algebraic_latex, ext_latex, poly_latex, poly_over_ext_latex};

use super::escape::{latex_comment, latex_text};
use super::{MatrixOut, Report, Value};
use std::fmt::Write;

/// Nesting depth of `description` lists beyond which objects are written inline.
pub const MAX_LIST_DEPTH: usize = 4;
/// Entries of a list typeset before "... and N more (see --format json)".
pub const MAX_LIST_ITEMS: usize = 64;
/// Columns of a matrix typeset in one `array`; wider matrices are split into column blocks.
pub const MAX_MATRIX_COLS: usize = 24;

/// The report as a LaTeX fragment for an `amsmath` document.
///
/// # Examples
/// ```
/// use exactlti::report::Report;
/// use exactlti::report::latex::fragment;
/// let r = Report::titled("eigen\nvalues").str("value", "1/2 + sqrt(5)/2");
/// let t = fragment(&r);
/// assert!(t.contains("$\\frac{1}{2} + \\frac{\\sqrt{5}}{2}$"));
/// assert!(t.starts_with("% exactlti: eigen\\nvalues\n"));
/// ```
pub fn fragment(r: &Report) -> String {
    let mut s = String::new();
    if let Some(t) = &r.title {
        let _ = writeln!(s, "% exactlti: {}", latex_comment(t));
        let _ = writeln!(
            s,
            "\\par\\medskip\\noindent\\textbf{{{}}}\\par",
            latex_text(t)
        );
    }
    items(&mut s, r, 0);
    s
}

/// The report as a complete LaTeX document (`article`, `amsmath`; the page is widened for
/// wide matrices).
pub fn standalone(r: &Report) -> String {
    let body = fragment(r);
    let width_cm = (estimate_width_em(r) * 0.45).clamp(16.0, 200.0);
    let title = r.title.as_deref().map(latex_comment).unwrap_or_default();
    format!(
        "% exactlti: {title}\n\\documentclass[11pt]{{article}}\n\\usepackage{{amsmath}}\n\
         \\setlength{{\\textwidth}}{{{width_cm:.1}cm}}\n\\setlength{{\\paperwidth}}{{\\dimexpr\\textwidth+3cm\\relax}}\n\
         \\setlength{{\\oddsidemargin}}{{-1in}}\\addtolength{{\\oddsidemargin}}{{1.5cm}}\n\
         \\setlength{{\\evensidemargin}}{{\\oddsidemargin}}\n\
         \\setlength{{\\textheight}}{{24cm}}\\setlength{{\\topmargin}}{{-1in}}\\addtolength{{\\topmargin}}{{1cm}}\n\
         \\ifdefined\\pdfpagewidth\\setlength{{\\pdfpagewidth}}{{\\paperwidth}}\\fi\n\
         \\setlength{{\\parindent}}{{0pt}}\n\\begin{{document}}\n{body}\\end{{document}}\n"
    )
}

/// A rough width (in em) of the widest matrix block, for the standalone page.
fn estimate_width_em(r: &Report) -> f64 {
    let mut w: f64 = 0.0;
    for (_, v) in &r.items {
        w = w.max(value_width(v));
    }
    w
}

fn value_width(v: &Value) -> f64 {
    match v {
        Value::Matrix(m) => {
            let cols = m.ncols.min(MAX_MATRIX_COLS);
            let widest: Vec<usize> = (0..cols)
                .map(|j| m.exact.iter().map(|r| r[j].len()).max().unwrap_or(1))
                .collect();
            widest.iter().map(|&c| c as f64 * 0.55 + 1.2).sum::<f64>() + 4.0
        }
        Value::Obj(r) => estimate_width_em(r) + 2.0,
        Value::List(xs) => xs.iter().map(value_width).fold(0.0, f64::max) + 2.0,
        Value::Str(s) => (s.len() as f64 * 0.5).min(60.0),
        Value::Math(m) => (m.text.len() as f64 * 0.5).min(60.0),
        _ => 0.0,
    }
}

/// A key as a list label: matrix names (`A`, `G1`, `T_R`) as math, other keys as text.
fn label(k: &str, v: &Value) -> String {
    if matches!(v, Value::Matrix(_))
        && k.len() <= 4
        && k.starts_with(|c: char| c.is_ascii_uppercase())
        && k.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
    {
        return format!("${}$", expr::ident(k));
    }
    latex_text(&k.replace('_', " "))
}

/// A scalar string: math when it is in the display grammar, text otherwise.
fn scalar_str(s: &str) -> String {
    match to_math(s) {
        Some(m) => format!("${m}$"),
        None => latex_text(s),
    }
}

/// The same as math content (inside `$...$`).
fn scalar_in_math(s: &str) -> String {
    match to_math(s) {
        Some(m) => m,
        None => format!("\\text{{{}}}", latex_text(s)),
    }
}

/// A float as LaTeX math: up to 10 significant digits, `\times 10^{e}` outside 1e-3..1e6.
pub fn float_math(x: f64) -> String {
    if x.is_nan() {
        return "\\text{NaN}".into();
    }
    if x.is_infinite() {
        return if x > 0.0 { "\\infty" } else { "-\\infty" }.into();
    }
    if x == 0.0 {
        return "0".into();
    }
    let e = x.abs().log10().floor() as i32;
    if (-3..6).contains(&e) {
        let decimals = (9 - e).clamp(0, 12) as usize;
        let s = format!("{x:.decimals$}");
        let s = if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        };
        return s;
    }
    let s = format!("{x:.9e}");
    let (m, ex) = s.split_once('e').unwrap_or((&s, "0"));
    let m = if m.contains('.') {
        m.trim_end_matches('0').trim_end_matches('.')
    } else {
        m
    };
    format!("{m} \\times 10^{{{ex}}}")
}

fn is_scalar(v: &Value) -> bool {
    matches!(
        v,
        Value::Null
            | Value::Bool(_)
            | Value::Int(_)
            | Value::Float(_)
            | Value::Str(_)
            | Value::Math(_)
    )
}

/// A scalar inside math.
fn math_scalar(v: &Value) -> String {
    match v {
        Value::Null => "\\text{--}".into(),
        Value::Bool(b) => format!("\\text{{{b}}}"),
        Value::Int(n) => n.to_string(),
        Value::Float(x) => float_math(*x),
        Value::Str(s) => scalar_in_math(s),
        Value::Math(m) => m.latex.clone(),
        _ => String::new(),
    }
}

/// A list of scalars or of lists of scalars, inline in math: `a, b, c` or `(1, 2), (3, 4)`.
fn inline_list(xs: &[Value], budget: &mut usize) -> Option<String> {
    let mut parts = Vec::new();
    for x in xs {
        if *budget == 0 {
            break;
        }
        match x {
            x if is_scalar(x) => {
                *budget -= 1;
                parts.push(math_scalar(x));
            }
            Value::List(ys) => parts.push(format!("\\left({}\\right)", inline_list(ys, budget)?)),
            _ => return None,
        }
    }
    let mut s = parts.join(",\\ ");
    if parts.len() < xs.len() {
        let _ = write!(
            s,
            ",\\ \\dots\\ \\text{{(and {} more; all in --format json)}}",
            xs.len() - parts.len()
        );
    }
    Some(s)
}

/// A value after its label.
fn value(s: &mut String, v: &Value, depth: usize) {
    match v {
        Value::Null => s.push_str("--"),
        Value::Bool(b) => s.push_str(if *b { "true" } else { "false" }),
        Value::Int(n) => {
            let _ = write!(s, "${n}$");
        }
        Value::Float(x) => {
            let _ = write!(s, "${}$", float_math(*x));
        }
        Value::Str(x) => s.push_str(&scalar_str(x)),
        Value::Math(m) => {
            let _ = write!(s, "${}$", m.latex);
        }
        Value::Alt(a) => value(s, &a.data, depth),
        Value::Matrix(m) => matrix(s, m),
        Value::List(xs) if xs.is_empty() => s.push_str("(none)"),
        Value::List(xs) => {
            let mut budget = MAX_LIST_ITEMS;
            if let Some(inline) = inline_list(xs, &mut budget) {
                let _ = write!(s, "${inline}$");
            } else {
                list(s, xs, depth);
            }
        }
        Value::Obj(r) => {
            if let Some(t) = &r.title {
                let _ = write!(s, "\\textit{{{}}}", latex_text(t));
            }
            if depth >= MAX_LIST_DEPTH {
                inline_obj(s, r);
            } else {
                s.push('\n');
                items(s, r, depth + 1);
            }
        }
    }
}

/// Objects inside lists beyond the depth limit: `key: value; ...` on one paragraph.
fn inline_obj(s: &mut String, r: &Report) {
    for (i, (k, v)) in r.items.iter().enumerate() {
        if i > 0 {
            s.push_str("; ");
        }
        let _ = write!(s, "{}: ", latex_text(k));
        match v {
            Value::Obj(r) => {
                s.push('[');
                inline_obj(s, r);
                s.push(']');
            }
            Value::List(xs) if !xs.iter().all(is_scalar) => {
                let mut budget = MAX_LIST_ITEMS;
                match inline_list(xs, &mut budget) {
                    Some(t) => {
                        let _ = write!(s, "${t}$");
                    }
                    None => {
                        let _ = write!(s, "({} entries; see --format json)", xs.len());
                    }
                }
            }
            Value::Matrix(m) => {
                let _ = write!(
                    s,
                    "({}$\\times${} matrix; see --format json)",
                    m.nrows, m.ncols
                );
            }
            other => value(s, other, MAX_LIST_DEPTH),
        }
    }
}

/// A list with objects or matrices: a `description` list labelled by position.
fn list(s: &mut String, xs: &[Value], depth: usize) {
    if depth >= MAX_LIST_DEPTH {
        let _ = write!(s, "({} entries; see --format json)", xs.len());
        return;
    }
    s.push_str("\n\\begin{description}\n");
    for (i, x) in xs.iter().take(MAX_LIST_ITEMS).enumerate() {
        let _ = write!(s, "\\item[{}.] ", i + 1);
        value(s, x, depth + 1);
        s.push('\n');
    }
    if xs.len() > MAX_LIST_ITEMS {
        let _ = writeln!(
            s,
            "\\item[\\dots] and {} more (all in --format json)",
            xs.len() - MAX_LIST_ITEMS
        );
    }
    s.push_str("\\end{description}\n");
}

/// The items of a report as a `description` list.
fn items(s: &mut String, r: &Report, depth: usize) {
    if r.items.is_empty() {
        return;
    }
    s.push_str("\\begin{description}\n");
    for (k, v) in &r.items {
        let _ = write!(s, "\\item[{}] ", label(k, v));
        value(s, v, depth);
        s.push('\n');
    }
    s.push_str("\\end{description}\n");
}

/// A matrix as display math: `bmatrix` up to 10 columns, `array` beyond (amsmath's matrix
/// environments take at most `MaxMatrixCols` = 10), column blocks of [`MAX_MATRIX_COLS`].
fn matrix(s: &mut String, m: &MatrixOut) {
    let _ = write!(s, "$({}\\times {})$", m.nrows, m.ncols);
    if m.nrows == 0 || m.ncols == 0 {
        s.push_str(" (empty)");
        return;
    }
    let blocks: Vec<(usize, usize)> = (0..m.ncols)
        .step_by(MAX_MATRIX_COLS)
        .map(|c0| (c0, (c0 + MAX_MATRIX_COLS).min(m.ncols)))
        .collect();
    for &(c0, c1) in &blocks {
        if blocks.len() > 1 {
            let _ = write!(s, "\n\ncolumns {}--{}:", c0 + 1, c1);
        }
        let cols = c1 - c0;
        let (open, close) = if cols <= 10 {
            ("\\begin{bmatrix}".to_string(), "\\end{bmatrix}")
        } else {
            (
                format!("\\left[\\begin{{array}}{{*{{{cols}}}{{c}}}}"),
                "\\end{array}\\right]",
            )
        };
        let _ = writeln!(s, "\n\\[\n{open}");
        for (i, row) in m.exact.iter().enumerate() {
            let cells: Vec<String> = (c0..c1)
                .map(|j| {
                    m.latex_at(i, j)
                        .map_or_else(|| scalar_in_math(&row[j]), String::from)
                })
                .collect();
            let _ = writeln!(s, "  {} \\\\", cells.join(" & "));
        }
        let _ = write!(s, "{close}\n\\]");
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::qmat;

    #[test]
    fn matrices_lists_and_escapes() {
        let wide = crate::matrix::Matrix::<crate::field::Q>::identity(crate::field::Q, 12);
        let r = Report::titled("t\n\\end{document}")
            .matrix("A", &qmat![[1, "1/2"], [3, 4]])
            .matrix("T_R", &wide)
            .str("name", "50% \\input{x}\nnext")
            .list("xs", (0..100).map(Value::Int).collect());
        let t = fragment(&r);
        assert!(
            t.contains("\\begin{bmatrix}\n  1 & \\frac{1}{2} \\\\"),
            "{t}"
        );
        assert!(t.contains("\\begin{array}{*{12}{c}}"), "{t}");
        assert!(t.contains("\\item[$T_{R}$]"), "{t}");
        assert!(
            t.contains("50\\% \\textbackslash{}input\\{x\\}\\textbackslash{}nnext"),
            "{t}"
        );
        assert!(t.contains("and 36 more"), "{t}");
        // no user text reaches the start of a line after a comment
        for line in t.lines() {
            assert!(!line.starts_with("\\end{document}"), "{line}");
        }
        assert_eq!(float_math(1.5e-7), "1.5 \\times 10^{-7}");
        assert_eq!(float_math(-0.25), "-0.25");
        assert_eq!(float_math(123456.0), "123456");
    }
}
