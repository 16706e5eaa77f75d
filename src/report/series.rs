//! Text of float series (the reports of `step`, `impulse`, `sweep`, `freqresp`): a summary
//! and a table of a sample of rows, in place of every sample on one line.
//!
//! A report holding an abscissa and one value per abscissa point is a *series*:
//! `times_s` + `response` (time responses, `response[k][i][j]` = output i for input j at
//! `times_s[k]`), `values` + `eigenvalues_approx` (a parameter sweep), `frequencies_hz` +
//! `response` (a frequency response, `[re, im]` per channel). Text shows what was computed
//! (range and number of points), per channel the extremes (and the last value), and
//! [`SAMPLE_ROWS`] evenly spaced rows plus the rows of the extremes; the sampled rows are
//! exactly the data's rows (not interpolated). JSON and LaTeX keep every sample.

use super::text_cells::{sig, text_table};
use super::{AltText, Report, Value};

/// Evenly spaced rows of a series table (the rows of the extremes come on top).
pub const SAMPLE_ROWS: usize = 21;

/// The widest table of a series (columns past it are left to `--csv` / JSON).
const TABLE_WIDTH: usize = 190;

fn floats(v: Option<&Value>) -> Option<Vec<f64>> {
    let Value::List(xs) = data(v?) else {
        return None;
    };
    xs.iter()
        .map(|x| match x {
            Value::Float(f) => Some(*f),
            Value::Int(n) => Some(*n as f64),
            _ => None,
        })
        .collect()
}

fn data(v: &Value) -> &Value {
    match v {
        Value::Alt(a) => &a.data,
        other => other,
    }
}

/// `v` as a list of lists of lists of floats (`[k][i][j]`), or `None`.
fn cube(v: Option<&Value>) -> Option<Vec<Vec<Vec<f64>>>> {
    let Value::List(ks) = data(v?) else {
        return None;
    };
    ks.iter()
        .map(|k| match k {
            Value::List(rows) => rows.iter().map(|r| floats(Some(r))).collect(),
            _ => None,
        })
        .collect()
}

/// The row indices shown: `SAMPLE_ROWS` evenly spaced (first and last included) and `extra`.
pub fn sample_rows(n: usize, extra: &[usize]) -> Vec<usize> {
    if n <= SAMPLE_ROWS + 4 {
        return (0..n).collect();
    }
    let mut idx: Vec<usize> = (0..SAMPLE_ROWS)
        .map(|k| k * (n - 1) / (SAMPLE_ROWS - 1))
        .collect();
    idx.extend(extra.iter().copied().filter(|&i| i < n));
    idx.sort_unstable();
    idx.dedup();
    idx
}

/// Index of the largest and of the smallest of `ys` (the first on ties; NaN ignored).
fn arg_extremes(ys: &[f64]) -> Option<(usize, usize)> {
    let mut it = ys.iter().enumerate().filter(|(_, y)| !y.is_nan());
    let (i0, _) = it.next()?;
    let (mut hi, mut lo) = (i0, i0);
    for (i, y) in it {
        if *y > ys[hi] {
            hi = i;
        }
        if *y < ys[lo] {
            lo = i;
        }
    }
    Some((hi, lo))
}

/// Keeps the first columns of a table that fit [`TABLE_WIDTH`]; the note names the others.
fn fit_columns(rows: &mut [Vec<String>]) -> Option<String> {
    let ncols = rows.first().map_or(0, Vec::len);
    let mut used = 0;
    let mut keep = 0;
    while keep < ncols {
        let w = rows
            .iter()
            .map(|r| r[keep].chars().count())
            .max()
            .unwrap_or(0)
            + 2;
        if keep > 1 && used + w > TABLE_WIDTH {
            break;
        }
        used += w;
        keep += 1;
    }
    if keep == ncols {
        return None;
    }
    rows.iter_mut().for_each(|r| r.truncate(keep));
    Some(format!(
        "columns {}..{ncols} of the table left out here: too wide",
        keep + 1
    ))
}

fn push_table(s: &mut String, pad: &str, what: &str, n: usize, mut rows: Vec<Vec<String>>) {
    let shown = rows.len() - 1;
    let cut = fit_columns(&mut rows);
    if shown < n {
        s.push_str(&format!(
            "{pad}{what} ({shown} of {n} rows: evenly spaced and the extremes; all rows: --format json or --csv FILE):\n"
        ));
    } else {
        s.push_str(&format!("{pad}{what} ({n} rows):\n"));
    }
    s.push_str(&text_table(&rows, pad.len() + 2));
    if let Some(c) = cut {
        s.push_str(&format!(
            "{pad}  ({c}; every column: --format json or --csv FILE)\n"
        ));
    }
}

fn names(r: &Report, key: &str, n: usize, base: &str) -> Vec<String> {
    match r.get(key) {
        Some(Value::List(xs)) if xs.len() == n => xs
            .iter()
            .map(|x| match x {
                Value::Str(s) => s.clone(),
                other => super::text_cells::inline_text(other),
            })
            .collect(),
        _ => (1..=n).map(|k| format!("{base}{k}")).collect(),
    }
}

/// A time response (`times_s`, `response`): its text, or `None` when `r` is not one.
fn time_series(r: &Report, pad: &str) -> Option<String> {
    let t = floats(r.get("times_s"))?;
    let y = cube(r.get("response"))?;
    if t.len() != y.len() || t.is_empty() {
        return None;
    }
    let (p, m) = (y[0].len(), y[0].first().map_or(0, Vec::len));
    if y.iter()
        .any(|g| g.len() != p || g.iter().any(|row| row.len() != m))
    {
        return None;
    }
    let ins = names(r, "inputs", m, "u");
    let outs = names(r, "outputs", p, "y");
    let n = t.len();
    let mut s = format!(
        "{pad}horizon: t = {} .. {} s, {n} points (step {})\n",
        sig(t[0]),
        sig(t[n - 1]),
        sig(if n > 1 { t[1] - t[0] } else { 0.0 })
    );
    let mut header = vec!["t (s)".to_string()];
    let mut extra = vec![];
    s.push_str(&format!("{pad}per channel (input -> output):\n"));
    for (i, o) in outs.iter().enumerate() {
        for (j, u) in ins.iter().enumerate() {
            let ys: Vec<f64> = y.iter().map(|g| g[i][j]).collect();
            header.push(format!("{u} -> {o}"));
            if let Some((hi, lo)) = arg_extremes(&ys) {
                extra.extend([hi, lo]);
                s.push_str(&format!(
                    "{pad}  {u} -> {o}: max {} at t = {}, min {} at t = {}, at t = {}: {}\n",
                    sig(ys[hi]),
                    sig(t[hi]),
                    sig(ys[lo]),
                    sig(t[lo]),
                    sig(t[n - 1]),
                    sig(ys[n - 1])
                ));
            }
        }
    }
    let mut rows = vec![header];
    for k in sample_rows(n, &extra) {
        let mut row = vec![sig(t[k])];
        row.extend(y[k].iter().flatten().map(|v| sig(*v)));
        rows.push(row);
    }
    push_table(&mut s, pad, "samples", n, rows);
    Some(s)
}

/// A parameter sweep (`values`, `eigenvalues_approx`): its text, or `None`.
fn sweep_series(r: &Report, pad: &str) -> Option<String> {
    let v = floats(r.get("values"))?;
    let ev = cube(r.get("eigenvalues_approx"))?;
    if v.len() != ev.len() || v.is_empty() {
        return None;
    }
    let param = match r.get("param") {
        Some(Value::Str(p)) => p.clone(),
        _ => "value".into(),
    };
    let n = v.len();
    // the spectral abscissa (largest real part) per value; NaN where there are none
    let abscissa: Vec<f64> = ev
        .iter()
        .map(|e| {
            e.iter()
                .filter_map(|z| z.first().copied())
                .fold(f64::NAN, f64::max)
        })
        .collect();
    let mut s = format!(
        "{pad}range: {param} = {} .. {}, {n} values\n",
        sig(v[0]),
        sig(v[n - 1])
    );
    let mut extra = vec![];
    if let Some((hi, lo)) = arg_extremes(&abscissa) {
        extra.extend([hi, lo]);
        s.push_str(&format!(
            "{pad}largest real part of the eigenvalues: max {} at {param} = {}, min {} at {param} = {}\n",
            sig(abscissa[hi]),
            sig(v[hi]),
            sig(abscissa[lo]),
            sig(v[lo])
        ));
    }
    let mut rows = vec![vec![
        param.clone(),
        "max Re".to_string(),
        "eigenvalues".to_string(),
    ]];
    for k in sample_rows(n, &extra) {
        let list: Vec<String> = ev[k]
            .iter()
            .map(|z| match z.as_slice() {
                [re, im] => super::text_cells::sig_complex((*re, *im)),
                other => other.iter().map(|x| sig(*x)).collect::<Vec<_>>().join(" "),
            })
            .collect();
        let mut text = list.join(", ");
        if text.chars().count() > 120 {
            text = format!(
                "{} ... ({} eigenvalues)",
                text.chars().take(110).collect::<String>(),
                list.len()
            );
        }
        rows.push(vec![sig(v[k]), sig(abscissa[k]), text]);
    }
    push_table(&mut s, pad, "samples", n, rows);
    Some(s)
}

/// A frequency response (`frequencies_hz`, `response` with `[re, im]` per channel whose
/// text is a table): the peak magnitude per channel and the table's rows sampled.
fn freq_series(r: &Report, pad: &str) -> Option<String> {
    let f = floats(r.get("frequencies_hz"))?;
    let Some(Value::Alt(alt)) = r.get("response") else {
        return None;
    };
    let AltText::Table { header, rows } = &alt.text else {
        return None;
    };
    let Value::List(ks) = &alt.data else {
        return None;
    };
    if ks.len() != f.len() || rows.len() != f.len() || f.is_empty() {
        return None;
    }
    let n = f.len();
    // magnitude per channel per frequency
    let mags: Vec<Vec<f64>> = ks
        .iter()
        .map(|k| match k {
            Value::List(rs) => rs
                .iter()
                .flat_map(|row| match row {
                    Value::List(cs) => cs.clone(),
                    _ => vec![],
                })
                .map(|c| match floats(Some(&c)).as_deref() {
                    Some([re, im]) => re.hypot(*im),
                    _ => f64::NAN,
                })
                .collect(),
            _ => vec![],
        })
        .collect();
    let nch = mags.first().map_or(0, Vec::len);
    let mut s = format!(
        "{pad}range: f = {} .. {} Hz, {n} frequencies\n",
        sig(f[0]),
        sig(f[n - 1])
    );
    let mut extra = vec![];
    for c in 0..nch {
        let col: Vec<f64> = mags
            .iter()
            .map(|m| m.get(c).copied().unwrap_or(f64::NAN))
            .collect();
        if let Some((hi, _)) = arg_extremes(&col) {
            extra.push(hi);
            let name = header
                .get(1 + 2 * c)
                .map_or("G", |h| h.trim_end_matches(" (dB)"));
            let name = if name == "magnitude" { "G" } else { name };
            s.push_str(&format!(
                "{pad}  {name}: peak |G| = {} ({} dB) at f = {} Hz; at f = {} Hz: {} dB\n",
                sig(col[hi]),
                sig(20.0 * col[hi].log10()),
                sig(f[hi]),
                sig(f[0]),
                sig(20.0 * col[0].log10())
            ));
        }
    }
    let mut table = vec![header.clone()];
    table.extend(sample_rows(n, &extra).into_iter().map(|k| rows[k].clone()));
    push_table(&mut s, pad, "response", n, table);
    Some(s)
}

/// The text of `r`'s series and the keys it stands for, or `None` when `r` holds none.
pub fn series_text(r: &Report, indent: usize) -> Option<(String, &'static [&'static str])> {
    let pad = " ".repeat(indent);
    if let Some(t) = time_series(r, &pad) {
        return Some((t, &["times_s", "response"][..]));
    }
    if let Some(t) = sweep_series(r, &pad) {
        return Some((t, &["values", "eigenvalues_approx"][..]));
    }
    freq_series(r, &pad).map(|t| (t, &["frequencies_hz", "response"][..]))
}
