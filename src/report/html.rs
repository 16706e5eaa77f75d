//! HTML rendering of a [`Report`] for notebooks (Jupyter's `_repr_html_`): a `<div>` with a
//! table of the report's items, nested tables for objects, numbered lists for lists of
//! objects, and every exact value as TeX math for MathJax (`\(..\)` inline, `\[..\]` for
//! matrices as `bmatrix`, the field's own LaTeX entries where the report kept them).
//!
//! User strings (names, keys, prose) are HTML-escaped, so none can open a tag; TeX inside
//! math delimiters is escaped too (MathJax reads the text content, where `&amp;` is `&`).
//! Long lists are cut at [`MAX_LIST_ITEMS`] and matrices beyond [`MAX_ENTRIES`] entries are
//! shown by their shape only, with the count of what was left out (JSON has everything).

use super::latex::{float_math, ident, to_math};
use super::{MatrixOut, Report, Value};
use std::fmt::Write;

/// Entries of a list shown before "... and N more".
pub const MAX_LIST_ITEMS: usize = 64;
/// Entries of a matrix typeset; larger matrices are shown by their shape.
pub const MAX_ENTRIES: usize = 2500;
/// Nesting depth of objects shown as tables; deeper ones are summarised.
pub const MAX_DEPTH: usize = 5;

/// `s` with the HTML specials escaped (`&`, `<`, `>`, `"`).
///
/// # Examples
/// ```
/// use exactlti::report::html::escape;
/// assert_eq!(escape("a<b & \"c\""), "a&lt;b &amp; &quot;c&quot;");
/// ```
pub fn escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            c => out.push(c),
        }
    }
    out
}

/// Inline math for MathJax.
pub fn inline_math(tex: &str) -> String {
    format!("\\({}\\)", escape(tex))
}

/// Display math for MathJax.
pub fn display_math(tex: &str) -> String {
    format!("\\[{}\\]", escape(tex))
}

/// The report as an HTML fragment (a `<div class="exactlti">`).
///
/// # Examples
/// ```
/// use exactlti::report::Report;
/// use exactlti::report::html::fragment;
/// let r = Report::titled("roots <b>").str("value", "1/2 + sqrt(5)/2").int("n", 2);
/// let h = fragment(&r);
/// assert!(h.contains("\\(\\frac{1}{2} + \\frac{\\sqrt{5}}{2}\\)"));
/// assert!(h.contains("roots &lt;b&gt;"));
/// ```
pub fn fragment(r: &Report) -> String {
    let mut s = String::from("<div class=\"exactlti\">");
    if let Some(t) = &r.title {
        let _ = write!(s, "<p><strong>{}</strong></p>", escape(t));
    }
    table(&mut s, r, 0);
    s.push_str("</div>");
    s
}

/// A key as a row label: matrix names (`A`, `T_R`) as math, other keys as text.
fn label(k: &str, v: &Value) -> String {
    if matches!(v, Value::Matrix(_))
        && k.len() <= 4
        && k.starts_with(|c: char| c.is_ascii_uppercase())
        && k.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
    {
        return inline_math(&ident(k));
    }
    escape(&k.replace('_', " "))
}

/// The items of a report as a two-column table.
fn table(s: &mut String, r: &Report, depth: usize) {
    if r.items.is_empty() {
        return;
    }
    s.push_str("<table style=\"text-align:left\">");
    for (k, v) in &r.items {
        let _ = write!(
            s,
            "<tr><th style=\"text-align:left;vertical-align:top\">{}</th><td style=\"text-align:left\">",
            label(k, v)
        );
        value(s, v, depth);
        s.push_str("</td></tr>");
    }
    s.push_str("</table>");
}

/// An exact string as math when it is in the display grammar, else as text.
fn scalar_str(x: &str) -> String {
    match to_math(x) {
        Some(m) => inline_math(&m),
        None => escape(x),
    }
}

/// A scalar as TeX (inside math), or `None` for a compound value.
fn scalar_tex(v: &Value) -> Option<String> {
    Some(match v {
        Value::Null => "\\text{--}".into(),
        Value::Bool(b) => format!("\\text{{{b}}}"),
        Value::Int(n) => n.to_string(),
        Value::Float(x) => float_math(*x),
        Value::Str(x) => to_math(x)?,
        Value::Math(m) => m.latex.clone(),
        _ => return None,
    })
}

fn value(s: &mut String, v: &Value, depth: usize) {
    match v {
        Value::Null => s.push_str("&ndash;"),
        Value::Bool(b) => s.push_str(if *b { "true" } else { "false" }),
        Value::Int(n) => s.push_str(&n.to_string()),
        Value::Float(x) => s.push_str(&inline_math(&float_math(*x))),
        Value::Str(x) => s.push_str(&scalar_str(x)),
        Value::Math(m) => s.push_str(&inline_math(&m.latex)),
        Value::Alt(a) => value(s, &a.data, depth),
        Value::Matrix(m) => matrix(s, m),
        Value::List(xs) if xs.is_empty() => s.push_str("(none)"),
        Value::List(xs) => list(s, xs, depth),
        Value::Obj(r) if depth >= MAX_DEPTH => {
            let _ = write!(s, "({} items; all in JSON)", r.items.len());
        }
        Value::Obj(r) => {
            if let Some(t) = &r.title {
                let _ = write!(s, "<em>{}</em>", escape(t));
            }
            table(s, r, depth + 1);
        }
    }
}

/// A list: scalars inline in one math group, anything else as a numbered list.
fn list(s: &mut String, xs: &[Value], depth: usize) {
    let shown = &xs[..xs.len().min(MAX_LIST_ITEMS)];
    let more = xs.len() - shown.len();
    let scalars: Option<Vec<String>> = shown.iter().map(scalar_tex).collect();
    if let Some(parts) = scalars {
        s.push_str(&inline_math(&parts.join(",\\ ")));
    } else if depth >= MAX_DEPTH {
        let _ = write!(s, "({} entries; all in JSON)", xs.len());
        return;
    } else {
        s.push_str("<ol>");
        for x in shown {
            s.push_str("<li>");
            value(s, x, depth + 1);
            s.push_str("</li>");
        }
        s.push_str("</ol>");
    }
    if more > 0 {
        let _ = write!(s, " &hellip; and {more} more (all in JSON)");
    }
}

/// A matrix as `bmatrix` display math (its shape first); beyond [`MAX_ENTRIES`] the shape.
fn matrix(s: &mut String, m: &MatrixOut) {
    let _ = write!(s, "{}&times;{}", m.nrows, m.ncols);
    if m.nrows == 0 || m.ncols == 0 {
        s.push_str(" (empty)");
        return;
    }
    if m.nrows * m.ncols > MAX_ENTRIES {
        s.push_str(" (too large to show here; all entries in JSON)");
        return;
    }
    let use_latex = m.latex.len() == m.nrows && m.latex.iter().all(|r| r.len() == m.ncols);
    let cell = |i: usize, j: usize| -> String {
        if use_latex {
            m.latex[i][j].clone()
        } else {
            to_math(&m.exact[i][j])
                .unwrap_or_else(|| format!("\\text{{{}}}", m.exact[i][j].replace('\\', "")))
        }
    };
    // MathJax has no column limit (amsmath's 10 does not apply)
    let rows: Vec<String> = (0..m.nrows)
        .map(|i| {
            (0..m.ncols)
                .map(|j| cell(i, j))
                .collect::<Vec<_>>()
                .join(" & ")
        })
        .collect();
    let tex = format!("\\begin{{bmatrix}}{}\\end{{bmatrix}}", rows.join(" \\\\ "));
    let _ = write!(
        s,
        "<div style=\"overflow-x:auto\">{}</div>",
        display_math(&tex)
    );
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::qmat;

    #[test]
    fn tables_matrices_lists_and_escapes() {
        let big = crate::matrix::Matrix::<crate::field::Q>::identity(crate::field::Q, 60);
        let inner = Report::titled("part").int("k", 3);
        let r = Report::titled("t <script>")
            .matrix("A", &qmat![[1, "1/2"], [3, 4]])
            .matrix("T_R", &big)
            .str("name", "a < b & c")
            .list("xs", (0..100).map(Value::Int).collect())
            .list("objs", vec![Value::Obj(inner.clone()), Value::Obj(inner)]);
        let h = fragment(&r);
        assert!(
            h.contains("\\[\\begin{bmatrix}1 &amp; \\frac{1}{2} \\\\ 3 &amp; 4\\end{bmatrix}\\]"),
            "{h}"
        );
        assert!(h.contains("\\(T_{R}\\)"), "{h}");
        assert!(h.contains("60&times;60 (too large"), "{h}");
        assert!(h.contains("a &lt; b &amp; c"), "{h}");
        assert!(h.contains("and 36 more"), "{h}");
        assert!(h.contains("<ol><li><em>part</em>"), "{h}");
        assert!(!h.contains("<script>"), "{h}");
        // balanced tags
        for tag in ["table", "tr", "td", "ol", "li", "div"] {
            let open = h.matches(&format!("<{tag}")).count();
            let close = h.matches(&format!("</{tag}>")).count();
            assert_eq!(open, close, "{tag} in {h}");
        }
    }
}
