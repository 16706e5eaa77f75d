//! Plain output data: values built on the worker thread (no GIL) and turned into Python
//! objects on the caller's thread.

use exactlti::field::{Field, Q, Rational};
use exactlti::matrix::Matrix;
use exactlti::poly::Poly;
use exactlti::report::{MatrixOut, Report};
use num_bigint::BigInt;
use num_traits::ToPrimitive;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyTuple};
use std::sync::Arc;

use crate::System;

/// The items of an output dict.
pub(crate) type Items = Vec<(&'static str, Out)>;

/// A value to be turned into Python objects on the caller's thread (the worker has no GIL).
#[derive(Clone)]
pub(crate) enum Out {
    None,
    Bool(bool),
    Int(i64),
    Big(BigInt),
    Float(f64),
    Str(String),
    List(Vec<Out>),
    Tuple(Vec<Out>),
    Dict(Vec<(&'static str, Out)>),
    /// A dict with keys made at run time (a report's keys).
    Map(Vec<(String, Out)>),
    /// A system computed here (a minimal realization, ...), given to the front door.
    Sys(Arc<exactlti::api::System>),
}

impl Out {
    pub(crate) fn to_py(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        Ok(match self {
            Out::None => py.None(),
            Out::Bool(b) => b.into_pyobject(py)?.to_owned().into_any().unbind(),
            Out::Int(n) => n.into_pyobject(py)?.into_any().unbind(),
            Out::Big(n) => n.into_pyobject(py)?.into_any().unbind(),
            Out::Float(x) => x.into_pyobject(py)?.into_any().unbind(),
            Out::Str(s) => s.into_pyobject(py)?.into_any().unbind(),
            Out::List(xs) => {
                let items = xs
                    .iter()
                    .map(|x| x.to_py(py))
                    .collect::<PyResult<Vec<_>>>()?;
                PyList::new(py, items)?.into_any().unbind()
            }
            Out::Tuple(xs) => {
                let items = xs
                    .iter()
                    .map(|x| x.to_py(py))
                    .collect::<PyResult<Vec<_>>>()?;
                PyTuple::new(py, items)?.into_any().unbind()
            }
            Out::Dict(kv) => {
                let d = PyDict::new(py);
                for (k, v) in kv {
                    d.set_item(*k, v.to_py(py)?)?;
                }
                d.into_any().unbind()
            }
            Out::Map(kv) => {
                let d = PyDict::new(py);
                for (k, v) in kv {
                    d.set_item(k, v.to_py(py)?)?;
                }
                d.into_any().unbind()
            }
            Out::Sys(s) => Py::new(py, System { api: s.clone() })?.into_any(),
        })
    }
}

/// A system over any field as output (a result of a computation).
pub(crate) fn system_out<K: Field + 'static>(t: exactlti::io::TypedSystem<K>) -> Out {
    match exactlti::api::System::from_field("system", t) {
        Some(s) => Out::Sys(Arc::new(s)),
        None => Out::None,
    }
}

pub(crate) fn int(n: &BigInt) -> Out {
    match n.to_i64() {
        Some(v) => Out::Int(v),
        None => Out::Big(n.clone()),
    }
}

pub(crate) fn usize_out(n: usize) -> Out {
    Out::Int(n as i64)
}

/// A rational as `(numerator, denominator)`.
pub(crate) fn q(r: &Rational) -> Out {
    Out::Tuple(vec![int(r.numer()), int(r.denom())])
}

pub(crate) fn strs(rows: &[Vec<String>]) -> Out {
    Out::List(
        rows.iter()
            .map(|r| Out::List(r.iter().map(|s| Out::Str(s.clone())).collect()))
            .collect(),
    )
}

pub(crate) fn approx_rows(rows: &[Vec<(f64, f64)>]) -> Out {
    Out::List(
        rows.iter()
            .map(|r| {
                Out::List(
                    r.iter()
                        .map(|(a, b)| Out::Tuple(vec![Out::Float(*a), Out::Float(*b)]))
                        .collect(),
                )
            })
            .collect(),
    )
}

/// A matrix: `q` = rows of integer pairs when every entry is rational, else `values` (rows
/// of element values, [`crate::values`]) with `exact`, `latex` (strings, for display) and
/// `approx` (pairs re, im).
pub(crate) fn mat<K: Field>(m: &Matrix<K>) -> Out {
    let k = m.field();
    let shape = |kv: &mut Vec<(&'static str, Out)>| {
        kv.push(("nrows", usize_out(m.nrows())));
        kv.push(("ncols", usize_out(m.ncols())));
    };
    let mut kv = vec![];
    shape(&mut kv);
    let rat: Option<Vec<Vec<Out>>> = (0..m.nrows())
        .map(|i| {
            m.row(i)
                .iter()
                .map(|x| k.to_rational(x).map(|r| q(&r)))
                .collect()
        })
        .collect();
    match rat {
        Some(rows) => kv.push(("q", Out::List(rows.into_iter().map(Out::List).collect()))),
        None => {
            kv.push(("values", crate::values::rows(m)));
            kv.push(("exact", strs(&m.to_rows_strings())));
            let latex: Vec<Vec<String>> = (0..m.nrows())
                .map(|i| m.row(i).iter().map(|x| k.latex_elem(x)).collect())
                .collect();
            kv.push(("latex", strs(&latex)));
            // no approximation over Q(p) (the parameters have no values)
            let approx = m.try_to_approx_complex();
            kv.push((
                "approx",
                approx.as_deref().map(approx_rows).unwrap_or(Out::None),
            ));
        }
    }
    Out::Dict(kv)
}

/// A matrix whose entries lie in several fields: their values (rows, [`crate::values`]),
/// and the report's exact strings (per-root symbols), LaTeX and approximations for display.
pub(crate) fn matout(mo: &MatrixOut, values: Out) -> Out {
    Out::Dict(vec![
        ("nrows", usize_out(mo.nrows)),
        ("ncols", usize_out(mo.ncols)),
        ("values", values),
        ("exact", strs(&mo.exact)),
        ("latex", strs(&mo.latex)),
        ("approx", approx_rows(&mo.approx)),
    ])
}

/// Polynomial: `q` coefficients low degree first when rational (else `values`, their
/// element values, and `coeffs`, their exact text for display), and its text in `s`.
pub(crate) fn poly<K: Field>(p: &Poly<K>) -> Out {
    poly_var(p, "s")
}

/// A polynomial as output with its text in the variable `var` (`z` for a discrete-time
/// system), which the dict names (`var`).
pub(crate) fn poly_var<K: Field>(p: &Poly<K>, var: &str) -> Out {
    let k = p.field();
    let rat: Option<Vec<Out>> = p
        .coeffs()
        .iter()
        .map(|c| k.to_rational(c).map(|r| q(&r)))
        .collect();
    let mut kv = vec![
        ("text", Out::Str(p.to_string_var(var))),
        ("var", Out::Str(var.to_string())),
    ];
    match rat {
        Some(c) => kv.push(("q", Out::List(c))),
        None => {
            kv.push(("q", Out::None));
            kv.push((
                "coeffs",
                Out::List(p.coeffs().iter().map(|c| Out::Str(k.fmt_elem(c))).collect()),
            ));
            kv.push(("values", crate::values::coeffs(p)));
        }
    }
    Out::Dict(kv)
}

/// The polynomial over Q when every coefficient is rational.
pub(crate) fn poly_q<K: Field>(p: &Poly<K>) -> Option<Poly<Q>> {
    let k = p.field();
    let c: Option<Vec<Rational>> = p.coeffs().iter().map(|c| k.to_rational(c)).collect();
    c.map(|c| Poly::new(Q, c))
}

/// A report: its JSON text, and its LaTeX and HTML (for `_repr_latex_`, `_repr_html_`),
/// all three made by the library's report layer from the report's values.
pub(crate) fn report(r: &Report) -> Out {
    Out::Dict(vec![
        ("json", Out::Str(r.to_json().to_string())),
        ("latex", Out::Str(r.to_latex_math())),
        ("html", Out::Str(r.to_html())),
    ])
}

pub(crate) fn alg(n: &exactlti::algebraic::AlgebraicNumber, mult: usize) -> Out {
    let (re, im) = n.approx();
    let ((rl, rh), (il, ih)) = n.bounding_box();
    let pair = |a, b| Out::Tuple(vec![q(a), q(b)]);
    Out::Dict(vec![
        ("minpoly", poly(n.minpoly())),
        ("box", Out::Tuple(vec![pair(&rl, &rh), pair(&il, &ih)])),
        ("value", Out::Str(n.value_string())),
        ("approx", Out::Tuple(vec![Out::Float(re), Out::Float(im)])),
        ("multiplicity", usize_out(mult)),
    ])
}
