//! Floats and values as short text, and plain tables: the cells that both the report
//! renderer ([`super::text`]) and the float series ([`super::series`]) write.

use super::Value;

/// `x` to 4 significant digits (`0`, `-1.25`, `0.003142`, `1.235e-5`).
pub fn short(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return if x.is_nan() {
            "nan".into()
        } else {
            format!("{x}")
        };
    }
    let a = x.abs();
    if !(1e-3..1e5).contains(&a) {
        return format!("{x:.3e}");
    }
    let e = a.log10().floor() as i32;
    let dec = (3 - e).max(0) as usize;
    let t = format!("{x:.dec$}");
    let t = if t.contains('.') {
        t.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        t
    };
    if t == "-0" { "0".into() } else { t }
}

/// `x` to 6 significant digits, in scientific notation below 1e-4 or from 1e6 on
/// (`6.6e-16`, `1.00087`, `0.0625`, `-12345.7`, `2.5e+06` is written `2.5e6`): never
/// `0.0000000000` for a nonzero number.
pub fn sig(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return short(x);
    }
    let e_form = format!("{x:.5e}");
    let (mant, exp) = e_form.split_once('e').unwrap_or((&e_form, "0"));
    let exp: i32 = exp.parse().unwrap_or(0);
    if (-4..6).contains(&exp) {
        let dec = (5 - exp).max(0) as usize;
        trim_zeros(&format!("{x:.dec$}"))
    } else {
        format!("{}e{exp}", trim_zeros(mant))
    }
}

fn trim_zeros(t: &str) -> String {
    if t.contains('.') {
        t.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        t.to_string()
    }
}

/// `re + im i` to 6 significant digits (`1.5-0.25i`, `2i`).
pub fn sig_complex(z: (f64, f64)) -> String {
    complex_with(z, sig)
}

/// `re + im i` to 4 significant digits (`1.5-0.25i`, `2i`).
pub fn short_complex(z: (f64, f64)) -> String {
    complex_with(z, short)
}

/// `re + im i` with each part written by `part` (`1.5-0.25i`, `2i`, a real number alone).
fn complex_with((re, im): (f64, f64), part: fn(f64) -> String) -> String {
    if im == 0.0 {
        part(re)
    } else if re == 0.0 {
        format!("{}i", part(im))
    } else if im < 0.0 {
        format!("{}-{}i", part(re), part(-im))
    } else {
        format!("{}+{}i", part(re), part(im))
    }
}

/// A table: the first row is the header, columns left-aligned.
pub fn text_table(rows: &[Vec<String>], indent: usize) -> String {
    let pad = " ".repeat(indent);
    let ncols = rows.iter().map(Vec::len).max().unwrap_or(0);
    let w: Vec<usize> = (0..ncols)
        .map(|j| {
            rows.iter()
                .filter_map(|r| r.get(j))
                .map(|c| c.chars().count())
                .max()
                .unwrap_or(0)
        })
        .collect();
    let mut s = String::new();
    for r in rows {
        let cells: Vec<String> = r
            .iter()
            .enumerate()
            // padded by hand: a format width above u16::MAX panics ("Formatting argument out
            // of range"), and a symbolic cell can be longer than that
            .map(|(j, c)| {
                let fill = w[j].saturating_sub(c.chars().count());
                format!("{c}{}", " ".repeat(fill))
            })
            .collect();
        s.push_str(&format!("{pad}{}\n", cells.join("  ").trim_end()));
    }
    s
}

pub(super) fn inline_text(v: &Value) -> String {
    match v {
        Value::Null => "-".into(),
        Value::Bool(b) => b.to_string(),
        Value::Int(n) => n.to_string(),
        Value::Float(x) => sig(*x),
        Value::Str(s) => s.clone(),
        Value::Math(m) => m.text.clone(),
        Value::Matrix(mo) => format!("{:?}", mo.exact),
        Value::List(xs) => format!(
            "[{}]",
            xs.iter().map(inline_text).collect::<Vec<_>>().join(", ")
        ),
        Value::Obj(r) => r
            .items
            .iter()
            .map(|(k, v)| format!("{k}={}", inline_text(v)))
            .collect::<Vec<_>>()
            .join(", "),
        Value::Alt(a) => inline_text(&a.data),
    }
}
