//! Reports: one result model rendered as text, JSON or LaTeX (the CLI's `--format`).
//!
//! A [`Report`] is an ordered list of named [`Value`]s. Exact matrices are stored with their
//! exact entry strings, LaTeX strings and floating approximations; in JSON a matrix `T`
//! becomes `"T": [["1", "-1/2"], ...]` plus `"T_approx": [[1.0, -0.5], ...]` as the CLI
//! contract requires.

pub mod display;
pub mod escape;
pub mod html;
pub mod latex;
pub mod numbers;
pub mod plot;
pub mod sections;
pub(crate) mod series;
pub(crate) mod steps;
pub(crate) mod steps_base;
pub(crate) mod steps_forms;
pub mod steps_html;
pub mod steps_latex;
pub(crate) mod steps_modes;
pub(crate) mod steps_more;
pub(crate) mod steps_norm;
pub(crate) mod summary;
pub(crate) mod text;
pub(crate) mod text_cells;

pub use sections::critical_report;
pub use steps::derivation_report;
pub use text::{TextOptions, text_matrix};

use crate::field::Field;
use crate::matrix::Matrix;
use serde_json::{Map, Number, Value as Json};

/// An exact matrix prepared for output.
#[derive(Clone, Debug, PartialEq)]
pub struct MatrixOut {
    pub exact: Vec<Vec<String>>,
    pub latex: Vec<Vec<String>>,
    pub approx: Vec<Vec<(f64, f64)>>,
    /// The entries as values ([`crate::field::ElemValue`], for bindings: the Python package
    /// builds SymPy from them), made with the LaTeX strings ([`Target::Every`]); empty when
    /// not made, `None` for an entry shown by text only.
    pub values: Vec<Vec<Option<crate::field::ElemValue>>>,
    pub nrows: usize,
    pub ncols: usize,
}

impl MatrixOut {
    pub fn from_matrix<K: Field>(m: &Matrix<K>) -> Self {
        let k = m.field();
        MatrixOut {
            exact: m.to_rows_strings(),
            latex: (0..m.nrows())
                .map(|i| m.row(i).iter().map(|x| k.latex_elem(x)).collect())
                .collect(),
            approx: m.to_approx_complex(),
            values: (0..m.nrows())
                .map(|i| m.row(i).iter().map(|x| k.elem_value(x)).collect())
                .collect(),
            nrows: m.nrows(),
            ncols: m.ncols(),
        }
    }
    /// The matrix prepared for one output only ([`Target`]): the exact strings (every format
    /// shows them), the approximations only where that output shows them (JSON's
    /// `_approx`; compact text when an entry is longer than [`text::MAX_EXACT_ENTRY`]); the
    /// LaTeX strings only for [`Target::Every`] (no renderer of [`Report`] reads them: the
    /// LaTeX output writes the exact strings in math mode; the Python package reads them).
    /// A rendering not built is left empty. Issue 29: the command line's `linalg rref` of a
    /// 100x100 matrix built 2 x 10^4 strings it never printed.
    pub fn for_target<K: Field>(m: &Matrix<K>, target: Target) -> Self {
        if target == Target::Every {
            return Self::from_matrix(m);
        }
        let exact = m.to_rows_strings();
        let approx = match target {
            Target::Every | Target::Json => true,
            Target::Text { full } => {
                !full
                    && exact
                        .iter()
                        .flatten()
                        .any(|e| e.chars().count() > text::MAX_EXACT_ENTRY)
            }
            Target::Latex => false,
        };
        let latex = if target == Target::Latex {
            latex_of_elements(m, &exact)
        } else {
            vec![]
        };
        MatrixOut {
            exact,
            latex,
            approx: if approx {
                m.to_approx_complex()
            } else {
                vec![]
            },
            values: vec![],
            nrows: m.nrows(),
            ncols: m.ncols(),
        }
    }
    /// From exact entry strings (typeset from the text) and their approximations, for matrices
    /// whose entries live in different fields.
    pub fn from_parts(exact: Vec<Vec<String>>, approx: Vec<Vec<(f64, f64)>>) -> Self {
        let nrows = exact.len();
        let ncols = exact.first().map_or(0, |r| r.len());
        MatrixOut {
            latex: exact.clone(),
            exact,
            approx,
            values: vec![],
            nrows,
            ncols,
        }
    }
    /// The LaTeX of entry `(i, j)` made from its element, when the field made one of its
    /// own (`None`: none, or the same as the exact string: typeset from that string).
    pub fn latex_at(&self, i: usize, j: usize) -> Option<&str> {
        let l = self.latex.get(i)?.get(j)?;
        (!l.is_empty() && self.exact.get(i)?.get(j)? != l).then_some(l.as_str())
    }
    fn is_complex(&self) -> bool {
        self.approx.iter().flatten().any(|(_, im)| *im != 0.0)
    }
}

/// The LaTeX of each entry made from the element by its field (`latex_elem`: fractions,
/// radicals, rational functions with `\\mathit` names), empty where the field has no LaTeX
/// of its own for it (it equals the text: the renderer typesets the text).
fn latex_of_elements<K: Field>(m: &Matrix<K>, exact: &[Vec<String>]) -> Vec<Vec<String>> {
    let k = m.field();
    (0..m.nrows())
        .map(|i| {
            m.row(i)
                .iter()
                .zip(&exact[i])
                .map(|(x, e)| {
                    let l = k.latex_elem(x);
                    if l == *e { String::new() } else { l }
                })
                .collect()
        })
        .collect()
}

/// The output a report is built for ([`MatrixOut::for_target`]): the command line knows its
/// `--format` (and `--full`) before it computes, and builds only what it prints.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Target {
    /// Every rendering (the library, the Python package).
    #[default]
    Every,
    Json,
    /// Text; `full`: every exact entry (`--full`), else long entries approximately.
    Text {
        full: bool,
    },
    Latex,
}

/// A value in a report.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    Null,
    Bool(bool),
    Int(i64),
    Float(f64),
    /// An exact number or expression shown as a string.
    Str(String),
    Matrix(Box<MatrixOut>),
    List(Vec<Value>),
    Obj(Report),
    /// Data with its own text display (a table, or nothing): JSON and LaTeX show the data.
    Alt(Box<Alt>),
    /// An exact value with its LaTeX made from the elements: text and JSON show `text`,
    /// LaTeX and HTML show `latex` (never re-parsed from `text`).
    Math(Box<MathOut>),
}

/// The two displays of an exact value: [`Value::Math`].
#[derive(Clone, Debug, PartialEq)]
pub struct MathOut {
    /// The plain display (`x + 101*sqrt(610)/1830`).
    pub text: String,
    /// LaTeX math without delimiters, made from the same value.
    pub latex: String,
}

impl Value {
    /// An exact value shown as `text`, typeset as `latex` (made from the value).
    pub fn math(text: impl Into<String>, latex: impl Into<String>) -> Value {
        Value::Math(Box::new(MathOut {
            text: text.into(),
            latex: latex.into(),
        }))
    }
}

/// A value shown differently in text: [`Value::Alt`].
#[derive(Clone, Debug, PartialEq)]
pub struct Alt {
    /// What JSON and LaTeX show.
    pub data: Value,
    /// What text shows instead.
    pub text: AltText,
}

/// The text display of a [`Value::Alt`].
#[derive(Clone, Debug, PartialEq)]
pub enum AltText {
    /// Nothing (the data is shown by a table elsewhere in the report).
    Hidden,
    /// A table with a header row.
    Table {
        header: Vec<String>,
        rows: Vec<Vec<String>>,
    },
    /// Short lines in the command line's compact text; the data itself with `--full`.
    Summary(Vec<String>),
}

impl Value {
    /// `data` shown in text as a table.
    pub fn table(data: Value, header: Vec<String>, rows: Vec<Vec<String>>) -> Value {
        Value::Alt(Box::new(Alt {
            data,
            text: AltText::Table { header, rows },
        }))
    }
    /// `data` not shown in text.
    pub fn hidden_in_text(data: Value) -> Value {
        Value::Alt(Box::new(Alt {
            data,
            text: AltText::Hidden,
        }))
    }
}

/// An ordered list of named values (a JSON object, a text section).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Report {
    pub title: Option<String>,
    pub items: Vec<(String, Value)>,
}

impl Report {
    pub fn new() -> Self {
        Self::default()
    }
    pub fn titled(title: impl Into<String>) -> Self {
        Report {
            title: Some(title.into()),
            items: vec![],
        }
    }
    pub fn push(&mut self, key: impl Into<String>, v: Value) -> &mut Self {
        self.items.push((key.into(), v));
        self
    }
    pub fn with(mut self, key: impl Into<String>, v: Value) -> Self {
        self.items.push((key.into(), v));
        self
    }
    pub fn str(self, key: &str, s: impl Into<String>) -> Self {
        self.with(key, Value::Str(s.into()))
    }
    /// An exact value shown as `text` and typeset as `latex` ([`Value::Math`]).
    pub fn math(self, key: &str, text: impl Into<String>, latex: impl Into<String>) -> Self {
        self.with(key, Value::math(text, latex))
    }
    /// A rational number, its text and LaTeX made from the value (`-3/7`, `-\\frac{3}{7}`).
    pub fn rational(self, key: &str, q: &crate::field::Rational) -> Self {
        use crate::field::{ElemDisplay, Q};
        self.math(key, Q.fmt_elem(q), Q.latex_elem(q))
    }
    pub fn int(self, key: &str, n: usize) -> Self {
        self.with(key, Value::Int(n as i64))
    }
    pub fn bool(self, key: &str, b: bool) -> Self {
        self.with(key, Value::Bool(b))
    }
    /// The item `key` set to `v` in place (appended when absent).
    pub fn set(mut self, key: &str, v: Value) -> Self {
        match self.items.iter_mut().find(|(k, _)| k == key) {
            Some(item) => item.1 = v,
            None => self.items.push((key.to_string(), v)),
        }
        self
    }
    pub fn float(self, key: &str, x: f64) -> Self {
        self.with(key, Value::Float(x))
    }
    pub fn matrix<K: Field>(self, key: &str, m: &Matrix<K>) -> Self {
        self.with(key, Value::Matrix(Box::new(MatrixOut::from_matrix(m))))
    }
    /// One [`Report::int`] per `(key, n)`, in order.
    pub fn ints(self, items: &[(&str, usize)]) -> Self {
        items.iter().fold(self, |r, &(k, n)| r.int(k, n))
    }
    /// One [`Report::float`] per `(key, x)`, in order.
    pub fn floats(self, items: &[(&str, f64)]) -> Self {
        items.iter().fold(self, |r, &(k, x)| r.float(k, x))
    }
    /// One [`Report::matrix`] per `(key, m)`, in order.
    pub fn matrices<K: Field>(self, items: &[(&str, &Matrix<K>)]) -> Self {
        items.iter().fold(self, |r, &(k, m)| r.matrix(k, m))
    }
    /// [`Report::matrix`] built for one output only ([`MatrixOut::for_target`]).
    pub fn matrix_for<K: Field>(self, key: &str, m: &Matrix<K>, target: Target) -> Self {
        self.with(
            key,
            Value::Matrix(Box::new(MatrixOut::for_target(m, target))),
        )
    }
    pub fn obj(self, key: &str, r: Report) -> Self {
        self.with(key, Value::Obj(r))
    }
    pub fn list(self, key: &str, v: Vec<Value>) -> Self {
        self.with(key, Value::List(v))
    }
    pub fn get(&self, key: &str) -> Option<&Value> {
        self.items.iter().find(|(k, _)| k == key).map(|(_, v)| v)
    }

    /// JSON rendering (matrices as exact strings plus `<name>_approx`).
    pub fn to_json(&self) -> Json {
        let mut m = Map::new();
        for (k, v) in &self.items {
            if let Value::Matrix(mo) = v {
                m.insert(
                    k.clone(),
                    Json::Array(
                        mo.exact
                            .iter()
                            .map(|r| {
                                Json::Array(r.iter().map(|s| Json::String(s.clone())).collect())
                            })
                            .collect(),
                    ),
                );
                m.insert(format!("{k}_approx"), approx_json(mo));
            } else {
                m.insert(k.clone(), value_json(v));
            }
        }
        Json::Object(m)
    }

    /// LaTeX rendering: a fragment for an `amsmath` document (see [`latex`]).
    pub fn to_latex(&self) -> String {
        latex::fragment(self)
    }

    /// LaTeX as one math-mode formula, for notebooks (see [`latex::math`]).
    pub fn to_latex_math(&self) -> String {
        latex::math(self)
    }

    /// HTML rendering for notebooks, math for MathJax (see [`html`]).
    pub fn to_html(&self) -> String {
        html::fragment(self)
    }
}

fn float_json(x: f64) -> Json {
    Number::from_f64(x).map(Json::Number).unwrap_or(Json::Null)
}

fn approx_json(mo: &MatrixOut) -> Json {
    let cplx = mo.is_complex();
    Json::Array(
        mo.approx
            .iter()
            .map(|r| {
                Json::Array(
                    r.iter()
                        .map(|(re, im)| {
                            if cplx {
                                Json::Array(vec![float_json(*re), float_json(*im)])
                            } else {
                                float_json(*re)
                            }
                        })
                        .collect(),
                )
            })
            .collect(),
    )
}

fn value_json(v: &Value) -> Json {
    match v {
        Value::Null => Json::Null,
        Value::Bool(b) => Json::Bool(*b),
        Value::Int(n) => Json::Number((*n).into()),
        Value::Float(x) => float_json(*x),
        Value::Str(s) => Json::String(s.clone()),
        Value::Matrix(mo) => Json::Array(
            mo.exact
                .iter()
                .map(|r| Json::Array(r.iter().map(|s| Json::String(s.clone())).collect()))
                .collect(),
        ),
        Value::List(xs) => Json::Array(xs.iter().map(value_json).collect()),
        Value::Obj(r) => r.to_json(),
        Value::Alt(a) => value_json(&a.data),
        Value::Math(m) => Json::String(m.text.clone()),
    }
}

/// Helper: a list of exact strings.
pub fn str_list<I: IntoIterator<Item = String>>(xs: I) -> Value {
    Value::List(xs.into_iter().map(Value::Str).collect())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::qmat;
    #[test]
    fn renders() {
        let r = Report::titled("t")
            .matrix("T", &qmat![[1, 2], [3, 4]])
            .bool("verified", true)
            .int("order", 2);
        let j = r.to_json();
        assert_eq!(j["T"][1][0], "3");
        assert_eq!(j["T_approx"][0][1], 2.0);
        assert_eq!(j["verified"], true);
        assert!(r.to_text().contains("[ 1  2 ]"));
        assert!(r.to_latex().contains("\\begin{bmatrix}"));
    }
}
