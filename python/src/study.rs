//! Parameter studies of a system file: `sweep` (float eigenvalues along one parameter,
//! finite eigenvalues of the pencil where E(v) is singular) and `critical` (exact critical
//! values), as the command line's `sweep` and `critical`. A parameter the file does not
//! name is refused (`ValueError` naming the parameters it has).

use crate::out::{Out, usize_out};
use crate::{FResult, Fail, run};
use exactlti::study::{
    CriticalValues, ParamFamily, PointStatus, SweepResult, critical_values, sweep as sweep_at,
};
use pyo3::prelude::*;
use std::path::Path;

fn status_name(s: &PointStatus) -> &'static str {
    match s {
        PointStatus::Regular => "regular",
        PointStatus::Descriptor { .. } => "descriptor",
        PointStatus::Pole => "pole",
        PointStatus::SingularPencil => "singular_pencil",
        PointStatus::Failed => "failed",
    }
}

fn sweep_out(sw: &SweepResult) -> Out {
    let ev = sw
        .eigenvalues
        .iter()
        .map(|e| {
            Out::List(
                e.iter()
                    .map(|z| Out::Tuple(vec![Out::Float(z.re), Out::Float(z.im)]))
                    .collect(),
            )
        })
        .collect();
    let infinite = sw
        .status
        .iter()
        .map(|s| match s {
            PointStatus::Descriptor { infinite } => usize_out(*infinite),
            _ => usize_out(0),
        })
        .collect();
    Out::Dict(vec![
        ("param", Out::Str(sw.param.clone())),
        (
            "values",
            Out::List(sw.values.iter().map(|v| Out::Float(*v)).collect()),
        ),
        ("eigenvalues", Out::List(ev)),
        (
            "status",
            Out::List(
                sw.status
                    .iter()
                    .map(|s| Out::Str(status_name(s).into()))
                    .collect(),
            ),
        ),
        ("infinite_eigenvalues", Out::List(infinite)),
    ])
}

fn critical_out(cv: &CriticalValues) -> Out {
    let num = |a: &exactlti::algebraic::AlgebraicNumber| {
        vec![
            ("value", Out::Str(a.value_string())),
            ("approx", Out::Float(a.approx().0)),
        ]
    };
    let crit = cv
        .critical
        .iter()
        .map(|c| {
            let mut d = num(&c.value);
            d.push(("kind", Out::Str(c.kind.name().into())));
            d.push(("certified", Out::Bool(c.certified)));
            d.push(("omega", c.omega.map_or(Out::None, Out::Float)));
            Out::Dict(d)
        })
        .collect();
    let sing = cv
        .singular
        .iter()
        .zip(&cv.singular_reasons)
        .map(|(a, why)| {
            let mut d = num(a);
            d.push(("reason", Out::Str(why.name().into())));
            Out::Dict(d)
        })
        .collect();
    let ivs = cv
        .intervals
        .iter()
        .map(|iv| {
            Out::Dict(vec![
                ("from", Out::Str(iv.from.value_string())),
                ("to", Out::Str(iv.to.value_string())),
                ("stable", Out::Bool(iv.stable)),
                ("unstable_eigenvalues", usize_out(iv.counts.unstable())),
            ])
        })
        .collect();
    Out::Dict(vec![
        ("param", Out::Str(cv.param.clone())),
        ("critical_values", Out::List(crit)),
        ("singular_values", Out::List(sing)),
        ("intervals", Out::List(ivs)),
        ("verified", Out::Bool(cv.verified)),
    ])
}

/// Eigenvalues of the system file's family at each of `values` of the parameter `param`.
#[pyfunction]
#[pyo3(signature = (path, param, values))]
pub(crate) fn sweep(
    py: Python<'_>,
    path: String,
    param: String,
    values: Vec<f64>,
) -> PyResult<Py<PyAny>> {
    run(py, None, move || -> FResult<Out> {
        let fam = ParamFamily::from_file(Path::new(&path), &param)?;
        Ok(sweep_out(&sweep_at(&fam, &values, None)?))
    })?
    .to_py(py)
}

/// Exact critical values of the parameter `param` on `[lo, hi]` (exact numbers as text).
#[pyfunction]
#[pyo3(signature = (path, param, lo, hi, max_seconds=None))]
pub(crate) fn critical(
    py: Python<'_>,
    path: String,
    param: String,
    lo: String,
    hi: String,
    max_seconds: Option<f64>,
) -> PyResult<Py<PyAny>> {
    run(py, max_seconds, move || -> FResult<Out> {
        let fam = ParamFamily::from_file(Path::new(&path), &param)?;
        let bound = |s: &str| {
            exactlti::field::parse_rational(s.trim())
                .map_err(|e| Fail::Input(format!("critical: bound '{s}': {e}")))
        };
        let cv = critical_values(&fam, &bound(&lo)?, &bound(&hi)?)?;
        Ok(critical_out(&cv))
    })?
    .to_py(py)
}
