//! A system written as a system file (JSON) that the reader reads back to the same matrices:
//! entries as exact strings in the display of their field (`-1/2`, `1 + sqrt(2)/2`,
//! `-a - k`, each parsed back by [`super::expr`] or the symbolic reader), symbols as `null`
//! parameters, a matrix with a zero dimension as `[]` (read as $n \times 0$ or
//! $0 \times n$ by the shape rules).

use super::SignalNames;
use crate::field::Field;
use crate::matrix::Matrix;
use crate::system::StateSpace;
use serde_json::{Map, Value};

fn matrix_json<K: Field>(m: &Matrix<K>) -> Value {
    if m.nrows() == 0 || m.ncols() == 0 {
        return Value::Array(vec![]);
    }
    let k = m.field();
    Value::Array(
        (0..m.nrows())
            .map(|i| {
                Value::Array(
                    m.row(i)
                        .iter()
                        .map(|x| Value::String(k.fmt_elem(x)))
                        .collect(),
                )
            })
            .collect(),
    )
}

/// The system file of `ss`: keys `name` (when given), `parameters` (each of `symbols` as
/// `null`, when there are symbols), `A`, `B`, `C`, `D`, and from `signals` the names
/// `inputs`, `outputs`, `states` whose counts fit and the sample time `dt`.
pub fn system_file_json<K: Field>(
    name: Option<&str>,
    ss: &StateSpace<K>,
    symbols: &[String],
    signals: &SignalNames,
) -> Value {
    let mut o = Map::new();
    if let Some(n) = name {
        o.insert("name".into(), Value::String(n.to_string()));
    }
    if let Some(dt) = &signals.dt {
        o.insert(
            "dt".into(),
            Value::String(crate::field::ElemDisplay::fmt_elem(&crate::field::Q, dt)),
        );
    }
    let lists = [
        ("inputs", &signals.inputs, ss.ninputs()),
        ("outputs", &signals.outputs, ss.noutputs()),
        ("states", &signals.states, ss.nstates()),
    ];
    for (key, names, count) in lists {
        if let Some(xs) = names.as_ref().filter(|xs| xs.len() == count) {
            let xs = xs.iter().map(|x| Value::String(x.clone())).collect();
            o.insert(key.into(), Value::Array(xs));
        }
    }
    if !symbols.is_empty() {
        let p: Map<String, Value> = symbols.iter().map(|s| (s.clone(), Value::Null)).collect();
        o.insert("parameters".into(), Value::Object(p));
    }
    for (key, m) in [("A", &ss.a), ("B", &ss.b), ("C", &ss.c), ("D", &ss.d)] {
        o.insert(key.into(), matrix_json(m));
    }
    Value::Object(o)
}

/// [`system_file_json`] as text: one key per line, one matrix row per line.
pub fn system_file_text<K: Field>(
    name: Option<&str>,
    ss: &StateSpace<K>,
    symbols: &[String],
    signals: &SignalNames,
) -> String {
    let Value::Object(o) = system_file_json(name, ss, symbols, signals) else {
        unreachable!("an object")
    };
    let mut lines = Vec::new();
    for (k, v) in &o {
        let key = Value::String(k.clone()).to_string();
        let val = match v {
            Value::Array(rows) if rows.first().is_some_and(Value::is_array) => {
                let rows: Vec<String> = rows.iter().map(row_text).collect();
                format!("[\n    {}\n  ]", rows.join(",\n    "))
            }
            v => v.to_string(),
        };
        lines.push(format!("  {key}: {val}"));
    }
    format!("{{\n{}\n}}\n", lines.join(",\n"))
}

/// `["1", "-1/2"]`: a row with a space after each comma.
fn row_text(row: &Value) -> String {
    match row {
        Value::Array(xs) => {
            let xs: Vec<String> = xs.iter().map(Value::to_string).collect();
            format!("[{}]", xs.join(", "))
        }
        v => v.to_string(),
    }
}
