//! A derivation (`--steps`) as HTML for notebooks (Jupyter's `_repr_html_`): the worked
//! example of [`super::steps_latex`] with the same sentences, objects and identities, as an
//! ordered list of steps whose math MathJax typesets (`\(..\)` inline, `\[..\]` displays;
//! matrices in one block at full size, the cell scrolls sideways).

use super::html::{escape, inline_math};
use super::steps::{identity, kind_name, step_field, title};
use super::steps_latex::{assumes_latex, object_latex, sentence_latex, transfer_latex};
use crate::field::Field;
use crate::jordan::derivation::{Derivation, Step};
use std::fmt::Write;

/// LaTeX text escapes (`latex_text`) and what they stand for in HTML.
const TEXT_ESCAPES: [(&str, &str); 16] = [
    ("\\textbackslash{}", "\\"),
    ("\\textless{}", "&lt;"),
    ("\\textgreater{}", "&gt;"),
    ("\\textbar{}", "|"),
    ("\\^{}", "^"),
    ("\\~{}", "~"),
    ("\\{", "{"),
    ("\\}", "}"),
    ("\\$", "&#36;"),
    ("\\&", "&amp;"),
    ("\\#", "#"),
    ("\\%", "%"),
    ("\\_", "_"),
    ("---", "&mdash;"),
    ("--", "&ndash;"),
    ("~", " "),
];

/// A LaTeX sentence (text with `$..$` math) as HTML: text escaped, `\texttt{..}` as
/// `<code>`, the text escapes of `latex_text` undone, dashes as dashes, math as `\(..\)`.
///
/// # Examples
/// ```
/// use exactlti::report::steps_html::sentence_html;
/// assert_eq!(
///     sentence_html("In \\texttt{QQ(t)/(t\\^{}2)} (eq.~3) --- $a < b$."),
///     "In <code>QQ(t)/(t^2)</code> (eq. 3) &mdash; \\(a &lt; b\\)."
/// );
/// ```
pub fn sentence_html(t: &str) -> String {
    let mut out = String::new();
    let mut rest = t;
    let mut code_depth: Option<usize> = None;
    let mut depth = 0usize;
    'outer: while let Some(c) = rest.chars().next() {
        if c == '$' {
            let body = &rest[1..];
            let end = body.find('$').unwrap_or(body.len());
            out.push_str(&inline_math(&body[..end]));
            rest = body.get(end + 1..).unwrap_or("");
            continue;
        }
        for (from, to) in TEXT_ESCAPES {
            if let Some(r) = rest.strip_prefix(from) {
                out.push_str(to);
                rest = r;
                continue 'outer;
            }
        }
        if let Some(r) = rest.strip_prefix("\\texttt{") {
            out.push_str("<code>");
            code_depth = Some(depth);
            depth += 1;
            rest = r;
            continue;
        }
        match c {
            '{' => depth += 1,
            '}' => {
                depth = depth.saturating_sub(1);
                if code_depth == Some(depth) {
                    out.push_str("</code>");
                    code_depth = None;
                }
            }
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '&' => out.push_str("&amp;"),
            '"' => out.push_str("&quot;"),
            c => out.push(c),
        }
        rest = &rest[c.len_utf8()..];
    }
    out
}

fn step_html<K: Field>(s: &mut String, d: &Derivation<K>, i: usize, st: &Step<K>) {
    let _ = write!(
        s,
        "<li><p><strong>Step {}</strong> <code>{}</code>: {}</p>",
        i + 1,
        kind_name(st.kind),
        sentence_html(&sentence_latex(d, st))
    );
    let field = step_field(d, st);
    let var = super::steps::poly_var(d);
    let mut tex = String::new();
    for (k, o) in &st.objects {
        if transfer_latex(&mut tex, st, k, false, var) || super::steps_forms::flag(k) {
            continue;
        }
        object_latex(&mut tex, st.kind, k, o, &field, false, var);
    }
    if !tex.is_empty() {
        let _ = write!(s, "<div style=\"overflow-x:auto\">{}</div>", escape(&tex));
    }
    let (_, id) = identity(st.kind);
    if let Some(h) = st.holds {
        let verdict = if h {
            "holds exactly"
        } else {
            "<strong>FAILS</strong>"
        };
        let id = super::steps::in_variable(id, var);
        let _ = write!(
            s,
            "<p>Identity: {} &mdash; {verdict}.</p>",
            inline_math(&id)
        );
    }
    if let Some(conds) = assumes_latex(d, st) {
        let _ = write!(s, "<p>Assumes: {}.</p>", inline_math(&conds));
    }
    s.push_str("</li>");
}

/// The derivation as an HTML fragment (a `<div class="exactlti-steps">`).
pub fn derivation_html<K: Field>(d: &Derivation<K>) -> String {
    let mut s = String::from("<div class=\"exactlti-steps\">");
    let _ = write!(
        s,
        "<h4>{}</h4><p>Over <code>{}</code>.</p><ol style=\"list-style:none;padding-left:0\">",
        escape(title(d.method)),
        escape(&super::steps::field_name(&d.field))
    );
    for (i, st) in d.steps.iter().enumerate() {
        step_html(&mut s, d, i, st);
    }
    let _ = write!(
        s,
        "</ol><p>Every identity above was checked in exact arithmetic: {}.</p></div>",
        if d.verified() {
            "all hold"
        } else {
            "one <strong>FAILS</strong>"
        }
    );
    s
}
