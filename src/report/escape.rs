//! Escaping of strings for output: control characters shown as escapes in text, the LaTeX
//! specials escaped in LaTeX text. User strings (a system's `name`, signal names, file names)
//! reach every output format; none of them may forge a line or break out of a LaTeX comment.

use super::{Alt, AltText, Report, Value};

/// `s` with every control character written as an escape: `\n`, `\r`, `\t`, `\\` stays
/// as is, others as `\u{1b}`. A one-line string stays one line.
///
/// # Examples
/// ```
/// use exactlti::report::escape::escape_control;
/// assert_eq!(escape_control("a\nb\u{1b}"), "a\\nb\\u{1b}");
/// assert_eq!(escape_control("x^2 - 1/2"), "x^2 - 1/2");
/// ```
pub fn escape_control(s: &str) -> String {
    if !s.chars().any(is_control) {
        return s.to_string();
    }
    let mut out = String::with_capacity(s.len() + 8);
    for c in s.chars() {
        match c {
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            c if is_control(c) => out.push_str(&format!("\\u{{{:x}}}", c as u32)),
            c => out.push(c),
        }
    }
    out
}

/// Control characters, and the Unicode line and paragraph separators.
fn is_control(c: char) -> bool {
    c.is_control() || c == '\u{2028}' || c == '\u{2029}'
}

/// [`escape_control_report`], without a copy when no string needs escaping (the common
/// case: a report with 10^4 matrix entries is printed as it is, issue 29).
pub fn escaped_report(r: &Report) -> std::borrow::Cow<'_, Report> {
    if report_has_control(r) {
        std::borrow::Cow::Owned(escape_control_report(r))
    } else {
        std::borrow::Cow::Borrowed(r)
    }
}

/// Some title, key or string of `r` that [`escape_control_report`] changes.
fn report_has_control(r: &Report) -> bool {
    let has = |s: &str| s.chars().any(is_control);
    r.title.as_deref().is_some_and(has)
        || r.items.iter().any(|(k, v)| has(k) || value_has_control(v))
}

fn value_has_control(v: &Value) -> bool {
    let has = |s: &str| s.chars().any(is_control);
    match v {
        Value::Str(s) => has(s),
        Value::Math(m) => has(&m.text) || has(&m.latex),
        Value::List(xs) => xs.iter().any(value_has_control),
        Value::Obj(r) => report_has_control(r),
        Value::Matrix(m) => m.exact.iter().flatten().any(|x| has(x)),
        Value::Alt(a) => {
            value_has_control(&a.data)
                || match &a.text {
                    AltText::Hidden => false,
                    AltText::Summary(lines) => lines.iter().any(|x| has(x)),
                    AltText::Table { header, rows } => {
                        header.iter().chain(rows.iter().flatten()).any(|x| has(x))
                    }
                }
        }
        _ => false,
    }
}

/// The report with [`escape_control`] applied to every title, key and string.
pub fn escape_control_report(r: &Report) -> Report {
    Report {
        title: r.title.as_deref().map(escape_control),
        items: r
            .items
            .iter()
            .map(|(k, v)| (escape_control(k), escape_control_value(v)))
            .collect(),
    }
}

fn escape_control_value(v: &Value) -> Value {
    match v {
        Value::Str(s) => Value::Str(escape_control(s)),
        Value::Math(m) => Value::math(escape_control(&m.text), escape_control(&m.latex)),
        Value::List(xs) => Value::List(xs.iter().map(escape_control_value).collect()),
        Value::Obj(r) => Value::Obj(escape_control_report(r)),
        Value::Matrix(m) => {
            let mut m = m.clone();
            for row in &mut m.exact {
                for x in row.iter_mut() {
                    *x = escape_control(x);
                }
            }
            Value::Matrix(m)
        }
        Value::Alt(a) => {
            let text = match &a.text {
                AltText::Hidden => AltText::Hidden,
                AltText::Summary(lines) => {
                    AltText::Summary(lines.iter().map(|x| escape_control(x)).collect())
                }
                AltText::Table { header, rows } => AltText::Table {
                    header: header.iter().map(|x| escape_control(x)).collect(),
                    rows: rows
                        .iter()
                        .map(|r| r.iter().map(|x| escape_control(x)).collect())
                        .collect(),
                },
            };
            Value::Alt(Box::new(Alt {
                data: escape_control_value(&a.data),
                text,
            }))
        }
        other => other.clone(),
    }
}

/// `s` as LaTeX text (outside math): the specials `\ { } $ & # ^ _ % ~` escaped, control
/// characters shown as `\n`-style escapes, and characters a default pdflatex set-up cannot
/// typeset (beyond Latin-1 and Latin Extended-A) written as `[U+XXXX]`.
///
/// # Examples
/// ```
/// use exactlti::report::escape::latex_text;
/// assert_eq!(latex_text("50% of a_1\n"), "50\\% of a\\_1\\textbackslash{}n");
/// ```
pub fn latex_text(s: &str) -> String {
    let mut out = String::with_capacity(s.len() + 8);
    for c in escape_control(s).chars() {
        match c {
            '\\' => out.push_str("\\textbackslash{}"),
            '{' => out.push_str("\\{"),
            '}' => out.push_str("\\}"),
            '$' => out.push_str("\\$"),
            '&' => out.push_str("\\&"),
            '#' => out.push_str("\\#"),
            '%' => out.push_str("\\%"),
            '_' => out.push_str("\\_"),
            '^' => out.push_str("\\^{}"),
            '~' => out.push_str("\\~{}"),
            '<' => out.push_str("\\textless{}"),
            '>' => out.push_str("\\textgreater{}"),
            '|' => out.push_str("\\textbar{}"),
            c if c.is_ascii() => out.push(c),
            c if ('\u{a1}'..='\u{17f}').contains(&c) && c != '\u{ad}' => out.push(c),
            c => out.push_str(&format!("[U+{:04X}]", c as u32)),
        }
    }
    out
}

/// `s` for a LaTeX `%` comment: one line (control characters escaped), ASCII only.
pub fn latex_comment(s: &str) -> String {
    escape_control(s)
        .chars()
        .map(|c| if c.is_ascii() { c } else { '?' })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::Report;

    /// [`escaped_report`] is [`escape_control_report`], borrowing exactly when nothing
    /// changes: a control character in any one place (title, key, string, matrix entry,
    /// table cell, summary line) makes it a copy with that place escaped.
    #[test]
    fn escaped_report_is_the_escape_and_copies_only_when_needed() {
        let build = |bad: Option<usize>| {
            let s = |i: usize| if bad == Some(i) { "a\nb" } else { "ab" }.to_string();
            let m = matrix_value(s(3));
            let alt = Value::table(Value::Null, vec![s(4)], vec![vec![s(5)]]);
            let summary = Value::Alt(Box::new(Alt {
                data: Value::Str(s(6)),
                text: AltText::Summary(vec![s(7)]),
            }));
            let mut r = Report::titled(s(0));
            r.push(s(1), Value::Str("x".into()));
            r.push("k", Value::List(vec![Value::Str(s(2)), Value::Int(1)]));
            r.push("m", m);
            r.push("t", alt);
            r.push("s", summary);
            r
        };
        let clean = build(None);
        assert!(matches!(
            escaped_report(&clean),
            std::borrow::Cow::Borrowed(_)
        ));
        assert_eq!(
            escaped_report(&clean).as_ref(),
            &escape_control_report(&clean)
        );
        for bad in 0..8 {
            let r = build(Some(bad));
            let e = escaped_report(&r);
            assert!(matches!(e, std::borrow::Cow::Owned(_)), "place {bad}");
            assert_eq!(e.as_ref(), &escape_control_report(&r));
            assert_ne!(e.as_ref(), &r, "place {bad}");
        }
    }

    fn matrix_value(entry: String) -> Value {
        Value::Matrix(Box::new(crate::report::MatrixOut::from_parts(
            vec![vec![entry]],
            vec![vec![(1.0, 0.0)]],
        )))
    }
}
