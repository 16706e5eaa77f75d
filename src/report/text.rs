//! Plain-text rendering of a [`Report`], for people.
//!
//! With [`TextOptions::cli`] (the command line without `--full`), a matrix whose exact entries
//! are long (more than [`MAX_EXACT_ENTRY`] characters) is shown approximately, 4 significant
//! digits per entry, under a line giving its shape and the length of its longest exact entry;
//! a matrix wider than the terminal width is printed in column blocks. `--full` prints every
//! exact entry; JSON and LaTeX are always complete. [`Value::Alt`] values show their own text
//! (a table, or nothing, or summary lines) in place of their data. Compact mode also shows
//! a table of more than 25 rows by 21 evenly spaced rows and a list of more than
//! [`LONG_LIST`] numbers by its first and last items; float series (`step`, `sweep`, ...)
//! are shown by [`super::series`]. Floats are written to 6 significant digits ([`sig`]), and
//! every line longer than [`MAX_LINE`] characters is wrapped ([`wrap_lines`]).

use super::{Alt, AltText, MatrixOut, Report, Value};

pub(super) use super::text_cells::inline_text;
pub use super::text_cells::{short, short_complex, sig, text_table};

/// Longest exact entry printed as it is in compact mode.
pub const MAX_EXACT_ENTRY: usize = 24;

/// How text is rendered.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TextOptions {
    /// Every matrix in full (exact entries, column blocks of at most [`MAX_LINE`] characters).
    pub full: bool,
    /// Width of a line in characters (column blocks in compact mode).
    pub width: usize,
}

impl Default for TextOptions {
    /// Full text (the library's `to_text`).
    fn default() -> Self {
        TextOptions {
            full: true,
            width: 100,
        }
    }
}

impl TextOptions {
    /// The command line's text: compact unless `--full`.
    pub fn cli(full: bool) -> Self {
        TextOptions { full, width: 100 }
    }
}

impl Report {
    /// Plain-text rendering (every matrix in full).
    pub fn to_text(&self) -> String {
        self.to_text_with(&TextOptions::default())
    }
    /// Plain-text rendering with options.
    pub fn to_text_with(&self, o: &TextOptions) -> String {
        let mut s = String::new();
        self.text_into(&mut s, 0, o);
        wrap_lines(&s, MAX_LINE)
    }
    fn text_into(&self, s: &mut String, indent: usize, o: &TextOptions) {
        let pad = " ".repeat(indent);
        if let Some(t) = &self.title {
            s.push_str(&format!("{pad}== {t} ==\n"));
        }
        let series = super::series::series_text(self, indent);
        for (k, v) in &self.items {
            match &series {
                Some((text, keys)) if keys.contains(&k.as_str()) => {
                    if k == keys[0] {
                        s.push_str(text);
                    }
                }
                _ => item_text(s, k, v, indent, o),
            }
        }
    }
}

fn item_text(s: &mut String, k: &str, v: &Value, indent: usize, o: &TextOptions) {
    let pad = " ".repeat(indent);
    match v {
        Value::Matrix(mo) => matrix_text(s, &format!("{pad}{k} "), mo, indent, o),
        Value::Obj(r) if r.title.is_some() => r.text_into(s, indent, o),
        Value::Obj(r) => {
            s.push_str(&format!("{pad}{k}:\n"));
            r.text_into(s, indent + 2, o);
        }
        Value::Alt(a) => alt_text(s, k, a, indent, o),
        Value::List(xs) if !o.full && xs.len() > LONG_LIST && xs.iter().all(is_scalar) => {
            s.push_str(&format!("{pad}{k}: {}\n", long_list(xs)));
        }
        Value::List(xs)
            if xs
                .iter()
                .any(|x| matches!(x, Value::Obj(_) | Value::Matrix(_) | Value::Alt(_))) =>
        {
            s.push_str(&format!("{pad}{k}:\n"));
            for (i, x) in xs.iter().enumerate() {
                match x {
                    Value::Obj(r) => {
                        s.push_str(&format!("{pad}  [{}]\n", i + 1));
                        r.text_into(s, indent + 4, o);
                    }
                    Value::Matrix(mo) => matrix_text(s, &format!("{pad}  - "), mo, indent + 4, o),
                    Value::Alt(a) => alt_text(s, "-", a, indent + 2, o),
                    other => s.push_str(&format!("{pad}  - {}\n", inline_text(other))),
                }
            }
        }
        other => s.push_str(&format!("{pad}{k}: {}\n", inline_text(other))),
    }
}

fn alt_text(s: &mut String, k: &str, a: &Alt, indent: usize, o: &TextOptions) {
    let pad = " ".repeat(indent);
    match &a.text {
        AltText::Hidden => {}
        AltText::Table { header, rows } => {
            let idx = if o.full {
                (0..rows.len()).collect()
            } else {
                super::series::sample_rows(rows.len(), &[])
            };
            if idx.len() < rows.len() {
                s.push_str(&format!(
                    "{pad}{k} ({} of {} rows, evenly spaced; all rows: --format json):\n",
                    idx.len(),
                    rows.len()
                ));
            } else {
                s.push_str(&format!("{pad}{k}:\n"));
            }
            let mut all = vec![header.clone()];
            all.extend(idx.into_iter().map(|i| rows[i].clone()));
            s.push_str(&text_table(&all, indent + 2));
        }
        AltText::Summary(lines) if !o.full => {
            for l in lines {
                s.push_str(&format!("{pad}{l}\n"));
            }
        }
        AltText::Summary(_) => item_text(s, k, &a.data, indent, o),
    }
}

/// Lists longer than this (of numbers or strings) show their first and last items in text.
const LONG_LIST: usize = 24;

fn is_scalar(v: &Value) -> bool {
    matches!(
        v,
        Value::Null | Value::Bool(_) | Value::Int(_) | Value::Float(_) | Value::Str(_)
    )
}

/// `[x1, ..., x8, ..., xn]` with the count: a long list in one line.
fn long_list(xs: &[Value]) -> String {
    let head: Vec<String> = xs[..8].iter().map(inline_text).collect();
    let tail: Vec<String> = xs[xs.len() - 2..].iter().map(inline_text).collect();
    format!(
        "[{}, ..., {}] ({} items; all: --format json)",
        head.join(", "),
        tail.join(", "),
        xs.len()
    )
}

/// The longest line of any text output.
pub const MAX_LINE: usize = 200;

/// `text` with every line longer than `max` characters broken after a separator (`, `,
/// ` + `, ` - `, a space) before the limit, continuation lines indented 4 more than the
/// line's own indentation (a run without a separator is cut at the limit).
pub fn wrap_lines(text: &str, max: usize) -> String {
    if text.lines().all(|l| l.chars().count() <= max) {
        return text.to_string();
    }
    let mut out = String::with_capacity(text.len() + text.len() / 50);
    for line in text.split_inclusive('\n') {
        let (body, nl) = match line.strip_suffix('\n') {
            Some(b) => (b, "\n"),
            None => (line, ""),
        };
        if body.chars().count() <= max {
            out.push_str(line);
            continue;
        }
        let indent = body.chars().take_while(|c| *c == ' ').count();
        let cont = " ".repeat((indent + 4).min(max / 2));
        let mut rest: Vec<char> = body.chars().collect();
        let mut first = true;
        loop {
            let room = if first { max } else { max - cont.len() };
            if !first {
                out.push_str(&cont);
            }
            if rest.len() <= room {
                out.extend(rest.iter());
                break;
            }
            // the last separator in the room (keep it on this line)
            let cut = (room / 2..room)
                .rev()
                .find(|&i| rest[i] == ' ')
                .map_or(room, |i| i + 1);
            let head: String = rest[..cut].iter().collect();
            out.push_str(head.trim_end());
            out.push('\n');
            rest.drain(..cut);
            while rest.first() == Some(&' ') {
                rest.remove(0);
            }
            first = false;
        }
        out.push_str(nl);
    }
    out
}

/// A matrix under `head` (`"T "`): exact, or approximate when its entries are long.
fn matrix_text(s: &mut String, head: &str, mo: &MatrixOut, indent: usize, o: &TextOptions) {
    let shape = format!("({}x{})", mo.nrows, mo.ncols);
    let longest = mo
        .exact
        .iter()
        .flatten()
        .map(|e| e.chars().count())
        .max()
        .unwrap_or(0);
    // entries without a number (rational functions of parameters) have no approximation
    let numeric = mo
        .approx
        .iter()
        .flatten()
        .all(|z| z.0.is_finite() && z.1.is_finite());
    if o.full || !numeric {
        // every exact entry, in column blocks that keep lines within MAX_LINE (an entry is
        // never split unless it alone is wider than that)
        s.push_str(&format!("{head}{shape} =\n"));
        s.push_str(&blocks(&mo.exact, indent + 2, MAX_LINE));
    } else if longest <= MAX_EXACT_ENTRY {
        s.push_str(&format!("{head}{shape} =\n"));
        s.push_str(&blocks(&mo.exact, indent + 2, o.width));
    } else {
        let cells: Vec<Vec<String>> = mo
            .approx
            .iter()
            .map(|r| r.iter().map(|&z| short_complex(z)).collect())
            .collect();
        s.push_str(&format!(
            "{head}{shape} ~ (4 digits; exact entries up to {longest} characters: --full or --format json)\n"
        ));
        s.push_str(&blocks(&cells, indent + 2, o.width));
    }
}

/// Column-aligned text of a matrix of strings in blocks of columns that fit `width`.
fn blocks(rows: &[Vec<String>], indent: usize, width: usize) -> String {
    let ncols = rows.first().map_or(0, Vec::len);
    let w: Vec<usize> = (0..ncols)
        .map(|j| rows.iter().map(|r| r[j].chars().count()).max().unwrap_or(1))
        .collect();
    let total = indent + 4 + w.iter().map(|x| x + 2).sum::<usize>();
    if rows.is_empty() || ncols == 0 || total <= width {
        return text_matrix(rows, indent);
    }
    let mut out = String::new();
    let mut start = 0;
    while start < ncols {
        let mut end = start;
        let mut used = indent + 4;
        while end < ncols && (end == start || used + w[end] + 2 <= width) {
            used += w[end] + 2;
            end += 1;
        }
        out.push_str(&format!(
            "{}columns {}..{} of {ncols}:\n",
            " ".repeat(indent),
            start + 1,
            end
        ));
        out.push_str(&text_matrix_cols(rows, start..end, indent));
        start = end;
    }
    out
}

/// Column-aligned text of a matrix of strings.
pub fn text_matrix(rows: &[Vec<String>], indent: usize) -> String {
    let ncols = rows.first().map_or(0, Vec::len);
    text_matrix_cols(rows, 0..ncols, indent)
}

/// [`text_matrix`] of the columns `cols` of `rows`, written cell by cell (issue 29: 10^4
/// entries in one report).
fn text_matrix_cols(rows: &[Vec<String>], cols: std::ops::Range<usize>, indent: usize) -> String {
    let pad = " ".repeat(indent);
    if rows.is_empty() || cols.is_empty() {
        return format!("{pad}[]\n");
    }
    let w: Vec<usize> = cols
        .clone()
        .map(|j| rows.iter().map(|r| r[j].chars().count()).max().unwrap_or(1))
        .collect();
    let mut s = String::new();
    for r in rows {
        s.push_str(&pad);
        s.push_str("[ ");
        for (t, j) in cols.clone().enumerate() {
            if t > 0 {
                s.push_str("  ");
            }
            let c = &r[j];
            s.extend(std::iter::repeat_n(
                ' ',
                w[t].saturating_sub(c.chars().count()),
            ));
            s.push_str(c);
        }
        s.push_str(" ]\n");
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table_cells_longer_than_a_format_width() {
        // bounce-pitch `jordan --symbolic` has a 70,000-character cell: a `{:<w$}` width above
        // u16::MAX panicked; columns are padded by hand
        let long = "x".repeat(70_000);
        let rows = vec![
            vec!["a".to_string(), "b".to_string()],
            vec![long.clone(), "c".to_string()],
        ];
        let t = text_table(&rows, 2);
        let lines: Vec<&str> = t.lines().collect();
        assert_eq!(lines.len(), 2);
        assert_eq!(lines[0], format!("  a{}b", " ".repeat(70_000 + 1)));
        assert_eq!(lines[1], format!("  {long}  c"));
    }

    #[test]
    fn short_numbers() {
        assert_eq!(short(0.0), "0");
        assert_eq!(short(-1.25), "-1.25");
        assert_eq!(short(std::f64::consts::PI / 1000.0), "0.003142");
        assert_eq!(short(12345.678), "12346");
        assert_eq!(short(1.23456e-5), "1.235e-5");
        assert_eq!(short_complex((1.5, -0.25)), "1.5-0.25i");
        assert_eq!(short_complex((0.0, 2.0)), "2i");
    }

    #[test]
    fn significant_digits() {
        assert_eq!(sig(6.6e-16), "6.6e-16");
        assert_eq!(sig(1e-7), "1e-7");
        assert_eq!(sig(1.000870001), "1.00087");
        assert_eq!(sig(0.0625), "0.0625");
        assert_eq!(sig(-0.0048875855), "-0.00488759");
        assert_eq!(sig(2.5), "2.5");
        assert_eq!(sig(0.0), "0");
        assert_eq!(sig(999999.7), "1e6");
        assert_eq!(sig(-123456.7), "-123457");
        assert_eq!(sig(3.2e21), "3.2e21");
        // property: every nonzero finite number prints nonzero and reads back within 6 digits
        let mut g = crate::rng::SplitMix64(28);
        for _ in 0..2000 {
            let m = g.int(-999_999, 999_999) as f64 / 1000.0;
            let x = m * 10f64.powi(g.int(-20, 20) as i32);
            let t = sig(x);
            let back: f64 = t.parse().unwrap();
            assert!(x == 0.0 || back != 0.0, "{x} -> {t}");
            assert!((back - x).abs() <= 5e-6 * x.abs(), "{x} -> {t}");
        }
    }

    #[test]
    fn wrapped_lines_keep_every_character() {
        let long = format!(
            "  k: [{}]\nshort\n",
            (0..300)
                .map(|i| i.to_string())
                .collect::<Vec<_>>()
                .join(", ")
        );
        let w = wrap_lines(&long, 80);
        assert!(w.lines().all(|l| l.chars().count() <= 80), "{w}");
        let squash = |t: &str| t.split_whitespace().collect::<String>();
        assert_eq!(squash(&w), squash(&long));
        let run = "x".repeat(500);
        let w = wrap_lines(&run, 200);
        assert!(w.lines().all(|l| l.len() <= 200) && squash(&w) == run);
    }

    #[test]
    fn long_entries_compact_wide_matrices_in_blocks() {
        let long = "123456789/987654321 + 123456789/987654321*r1".to_string();
        let m = MatrixOut::from_parts(
            vec![vec![long.clone(), "0".into()], vec!["1".into(), "2".into()]],
            vec![vec![(0.125, 0.0), (0.0, 0.0)], vec![(1.0, 0.0), (2.0, 0.0)]],
        );
        let r = Report::new().with("T", Value::Matrix(Box::new(m)));
        let c = r.to_text_with(&TextOptions::cli(false));
        assert!(
            c.contains("T (2x2) ~") && c.contains("0.125") && !c.contains(&long),
            "{c}"
        );
        assert!(r.to_text_with(&TextOptions::cli(true)).contains(&long));
        assert!(r.to_text().contains(&long));
        let wide: Vec<Vec<String>> = vec![(0..40).map(|j| format!("{j}")).collect()];
        let t = blocks(&wide, 2, 100);
        assert!(
            t.contains("columns 1..") && t.lines().all(|l| l.len() <= 100),
            "{t}"
        );
        assert!(t.contains(" 39 ]"));
    }
}
