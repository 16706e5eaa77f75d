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
