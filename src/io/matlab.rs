//! MATLAB-style matrix text: `"[0 1; -2 -3]"`, `"[1, 2/3; 0.5 -1e-2]"`, `"[]"`.
//!
//! Rows end at `;` or a line break, entries are separated by `,` or by blanks. As in
//! MATLAB, a blank separates entries unless it sits next to a binary operator:
//! `[1 -2]` has two entries, `[1 - 2]` and `[1-2]` have one (`-1`), `[a *b]` has one.
//! Entries are exact expressions (see [`super::expr`]); empty rows are skipped, so `[]`,
//! `[;]` and `""` are the $0 \times 0$ matrix. The outer brackets are optional.
//!
//! | entry point | gives |
//! |---|---|
//! | [`split_matlab_matrix`] | the entries as text, row by row (checked rectangular) |
//! | [`parse_matlab_matrix`] | the exact [`MatrixEntries`] and their [`Ground`] |

use super::expr;
use super::{ExactScalar, Ground, InputError, MatrixEntries};
use crate::error::{Error, Result};

/// A bad matrix text: [`Error::MatrixText`] (`row`/`col` 1-based when the error is about one
/// row or entry).
fn text_error(row: Option<usize>, col: Option<usize>, msg: impl Into<String>) -> Error {
    Error::MatrixText {
        row,
        col,
        msg: msg.into(),
    }
}

fn whole(msg: impl Into<String>) -> Error {
    text_error(None, None, msg)
}

/// The error of a matrix text as an [`InputError`] of key `key` of `file`: the row and
/// column of the text become the error's, the message stays.
pub(crate) fn key_error(file: &str, key: &str, e: Error) -> InputError {
    match e {
        Error::MatrixText { row, col, msg } => InputError {
            row,
            col,
            ..InputError::key(file, key, msg)
        },
        e => InputError::key(file, key, e.to_string()),
    }
}

/// The message of a matrix-text error without its place.
pub(crate) fn message(e: &Error) -> String {
    match e {
        Error::MatrixText { msg, .. } => msg.clone(),
        e => e.to_string(),
    }
}

/// Splits MATLAB-style matrix text into rows of entry texts.
///
/// # Examples
/// ```
/// use exactlti::io::split_matlab_matrix;
/// let rows = split_matlab_matrix("[0 1; -2 -3]").unwrap();
/// assert_eq!(rows, [["0", "1"], ["-2", "-3"]]);
/// assert_eq!(split_matlab_matrix("[a - b, c*(d -e)]").unwrap(), [["a - b", "c*(d -e)"]]);
/// assert!(split_matlab_matrix("[]").unwrap().is_empty());
/// ```
///
/// # Errors
/// Unbalanced brackets or parentheses, nested brackets, empty entries (`[1,,2]`), and
/// rows of different lengths (naming the row).
pub fn split_matlab_matrix(text: &str) -> Result<Vec<Vec<String>>> {
    let t = text.trim();
    let inner = match (t.strip_prefix('['), t.ends_with(']')) {
        (Some(rest), true) => &rest[..rest.len() - 1],
        (Some(_), false) => return Err(whole("missing ']' at the end of the matrix")),
        (None, _) => t,
    };
    if inner.contains(['[', ']']) {
        return Err(whole(
            "unexpected '[' or ']' inside the matrix (nesting is not supported)",
        ));
    }
    let mut rows: Vec<Vec<String>> = Vec::new();
    let mut row: Vec<String> = Vec::new();
    let mut cur = String::new();
    let mut depth = 0usize;
    let cs: Vec<char> = inner.chars().collect();
    let mut i = 0;
    while i < cs.len() {
        let c = cs[i];
        match c {
            '(' => depth += 1,
            ')' if depth == 0 => return Err(whole("unbalanced ')' in the matrix")),
            ')' => depth -= 1,
            _ => {}
        }
        let at_top = depth == 0;
        if at_top && (c == ';' || c == '\n' || c == '\r') {
            end_entry(&mut cur, &mut row, rows.len(), false)?;
            if !row.is_empty() {
                rows.push(std::mem::take(&mut row));
            }
            i += 1;
        } else if at_top && c == ',' {
            end_entry(&mut cur, &mut row, rows.len(), true)?;
            i += 1;
        } else if c.is_whitespace() && c != '\n' && c != '\r' {
            let mut j = i;
            while j < cs.len() && cs[j].is_whitespace() && cs[j] != '\n' && cs[j] != '\r' {
                j += 1;
            }
            if at_top && blank_separates(&cur, &cs[j..]) {
                end_entry(&mut cur, &mut row, rows.len(), false)?;
            } else if !cur.is_empty() {
                cur.push(' ');
            }
            i = j;
        } else {
            if c == ';' {
                return Err(whole("';' inside parentheses"));
            }
            cur.push(c);
            i += 1;
        }
    }
    if depth > 0 {
        return Err(whole("missing ')' in the matrix"));
    }
    end_entry(&mut cur, &mut row, rows.len(), false)?;
    if !row.is_empty() {
        rows.push(row);
    }
    if let Some(first) = rows.first() {
        let n = first.len();
        if let Some((r, bad)) = rows.iter().enumerate().find(|(_, r)| r.len() != n) {
            return Err(text_error(Some(r + 1), None, ragged_msg(bad.len(), n)));
        }
    }
    Ok(rows)
}

/// The message for a row of `len` entries in a matrix whose first row has `n`.
pub(crate) fn ragged_msg(len: usize, n: usize) -> String {
    let entries = |k: usize| {
        if k == 1 {
            "1 entry".to_string()
        } else {
            format!("{k} entries")
        }
    };
    format!("this row has {} but row 1 has {}", entries(len), entries(n))
}

/// Does a run of blanks between `cur` and `rest` separate two entries (MATLAB's rule)?
fn blank_separates(cur: &str, rest: &[char]) -> bool {
    let Some(last) = cur.trim_end().chars().last() else {
        return false;
    };
    let Some(&next) = rest.first() else {
        return false;
    };
    if "+-*/^(".contains(last) || "*/^),;\n\r".contains(next) {
        return false;
    }
    // `1 - 2` is one entry (binary minus), `1 -2` two (unary minus)
    !("+-".contains(next) && rest.get(1).is_none_or(|c| c.is_whitespace()))
}

fn end_entry(cur: &mut String, row: &mut Vec<String>, nrows: usize, comma: bool) -> Result<()> {
    let e = cur.trim().to_string();
    cur.clear();
    if e.is_empty() {
        if comma {
            return Err(text_error(
                Some(nrows + 1),
                Some(row.len() + 1),
                "empty entry",
            ));
        }
        return Ok(());
    }
    row.push(e);
    Ok(())
}

/// Parses MATLAB-style matrix text with exact entries (no parameters).
///
/// # Examples
/// ```
/// use exactlti::io::{Ground, parse_matlab_matrix};
/// let (m, g) = parse_matlab_matrix("[1, 2/3; 0.5 -1e-2]").unwrap();
/// assert_eq!((m.nrows, m.ncols, g.clone()), (2, 2, Ground::Rational));
/// assert_eq!(m.display(&g), "[[1, 2/3], [1/2, -1/100]]");
/// let (m, g) = parse_matlab_matrix("[1 i; -i 2]").unwrap();
/// assert_eq!(m.display(&g), "[[1, i], [-i, 2]]");
/// ```
///
/// # Errors
/// Those of [`split_matlab_matrix`], an invalid entry (with its row and column), and
/// entries from two different quadratic fields.
pub fn parse_matlab_matrix(text: &str) -> Result<(MatrixEntries, Ground)> {
    let rows = split_matlab_matrix(text)?;
    let nrows = rows.len();
    let ncols = rows.first().map_or(0, Vec::len);
    let mut data = Vec::with_capacity(nrows * ncols);
    let mut scan = FieldScan::default();
    for (i, r) in rows.iter().enumerate() {
        for (j, s) in r.iter().enumerate() {
            let at = |msg: String| text_error(Some(i + 1), Some(j + 1), msg);
            let v = expr::eval_with(s, &|_| None).map_err(|e| at(e.to_string()))?;
            scan.admit(&v, &format!("row {}, column {}", i + 1, j + 1))
                .map_err(at)?;
            data.push(ExactScalar { a: v.a, b: v.b });
        }
    }
    let m = MatrixEntries { nrows, ncols, data };
    Ok((m, scan.ground()))
}

/// Tracks the one quadratic field the values seen so far live in.
#[derive(Default)]
pub(crate) struct FieldScan {
    first: Option<(crate::field::QuadraticField, String)>,
}

impl FieldScan {
    /// Accepts `v` if it is rational or lies in the field seen first; `place` names `v`.
    pub(crate) fn admit(
        &mut self,
        v: &expr::Value,
        place: &str,
    ) -> std::result::Result<(), String> {
        let Some(k) = &v.k else { return Ok(()) };
        match &self.first {
            None => {
                self.first = Some((k.clone(), place.to_string()));
                Ok(())
            }
            Some((k0, _)) if k0 == k => Ok(()),
            Some((k0, p0)) => Err(format!(
                "value lies in {k} but {p0} lies in {k0}; all values must lie in one quadratic field"
            )),
        }
    }
    /// The field of all admitted values.
    pub(crate) fn ground(&self) -> Ground {
        match &self.first {
            None => Ground::Rational,
            Some((k, _)) => Ground::Quadratic(k.clone()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn splitting() {
        let s = |t: &str| split_matlab_matrix(t).unwrap();
        assert_eq!(s("[1 -2]"), [["1", "-2"]]);
        assert_eq!(s("[1 - 2]"), [["1 - 2"]]);
        assert_eq!(s("[1 -2 + 3]"), [["1", "-2 + 3"]]);
        assert_eq!(s("[a *b, (c - d) e]"), [["a *b", "(c - d)", "e"]]);
        assert_eq!(s("[1 2\n 3 4\n]"), [["1", "2"], ["3", "4"]]);
        assert_eq!(s("[sqrt(2) (1 -2)]"), [["sqrt(2)", "(1 -2)"]]);
        assert_eq!(s("0 1; -2 -3"), [["0", "1"], ["-2", "-3"]]);
        assert!(s("[ ; ]").is_empty());
        assert_eq!(
            split_matlab_matrix("[1 2; 3]").unwrap_err().to_string(),
            "row 2, this row has 1 entry but row 1 has 2 entries"
        );
        assert!(split_matlab_matrix("[1,,2]").is_err());
        assert!(split_matlab_matrix("[1 2").is_err());
        assert!(split_matlab_matrix("[(1 2]").is_err());
        assert!(split_matlab_matrix("[1) 2]").is_err());
        assert!(split_matlab_matrix("[[1]]").is_err());
    }
}
