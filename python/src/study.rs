//! Parameter studies of a system file, read by the api's one loader as the command line
//! reads it: `sweep` (float eigenvalues along one parameter at given values, finite
//! eigenvalues of the pencil where E(v) is singular; [`exactlti::api::sweep_file`]) and
//! `execute` (any command on its file, e.g. `critical`, through
//! [`exactlti::api::execute`]). A parameter the file does not name is refused
//! (`ValueError` naming the parameters it has).

use crate::out::{Out, usize_out};
use crate::{FResult, Fail, run};
use exactlti::api::sweep_file;
use exactlti::study::{PointStatus, SweepResult};
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
        let opts = exactlti::api::Options::default();
        Ok(sweep_out(&sweep_file(
            Path::new(&path),
            &param,
            &opts,
            &values,
        )?))
    })?
    .to_py(py)
}

/// Any command of the command line on its file, dispatched as the command line does (the
/// file read once by the api's one loader; `critical` and `sweep` of a file the reader
/// refuses at its nominal values are studied as there): the report as JSON text, whether
/// its exact checks passed, and whether the float path agrees.
#[pyfunction]
#[pyo3(signature = (args, max_seconds=None))]
pub(crate) fn execute(
    py: Python<'_>,
    args: Vec<String>,
    max_seconds: Option<f64>,
) -> PyResult<(String, bool, bool)> {
    run(py, max_seconds, move || {
        let cmd = exactlti::api::Command::parse_args(&args).map_err(Fail::Input)?;
        let out = exactlti::api::execute(&cmd)?;
        let text =
            serde_json::to_string(&out.report.to_json()).map_err(|e| Fail::Input(e.to_string()))?;
        Ok((text, out.verified, !out.float_disagrees))
    })
}
