//! `exactlti._core`: the PyO3 layer under the `exactlti` Python package.
//!
//! Thin by design: systems are read by the library's own system-file reader (so a bad entry
//! gives the command line's one-line message), every computation runs on a worker thread
//! with the GIL released while this thread polls for Ctrl-C (`check_signals`) and for the
//! `max_seconds` deadline, and results come back as plain dicts of exact data (rationals as
//! integer pairs, other field elements as exact strings with their LaTeX and approximations)
//! that the pure-Python layer (`python/exactlti/`) wraps in classes.
#![allow(non_snake_case)]

use exactlti::Error;
mod compat;
mod study;
use compat::{Loaded, Typed, from_loaded};
use exactlti::field::{Q, QuadraticField};
use exactlti::ratfunc::RatFuncField;
use exactlti::realization;
use pyo3::create_exception;
use pyo3::exceptions::{PyRuntimeError, PyTimeoutError, PyValueError};
use pyo3::prelude::*;
use std::path::Path;
use std::sync::Arc;
use std::sync::mpsc;
use std::time::{Duration, Instant};

create_exception!(
    _core,
    UnsupportedError,
    pyo3::exceptions::PyNotImplementedError,
    "A case exactlti does not handle (yet)."
);
create_exception!(
    _core,
    VerificationError,
    PyRuntimeError,
    "An exact identity failed: an internal error of exactlti."
);

// ---------------------------------------------------------------- errors

/// A failure of the worker: the command line's message and its class.
enum Fail {
    /// Bad input or an undefined result (CLI exit 2): `ValueError`.
    Input(String),
    /// `Error::Unsupported`: `NotImplementedError` (subclass `UnsupportedError`).
    Unsupported(String),
    /// `Error::Limit` (a size or time bound of the library): `TimeoutError`.
    Limit(String),
    /// `Error::Verification`: `VerificationError`.
    Verification(String),
}

impl From<Error> for Fail {
    fn from(e: Error) -> Self {
        let m = e.to_string();
        match e {
            Error::Unsupported(_) => Fail::Unsupported(m),
            Error::Limit(_) => Fail::Limit(m),
            Error::Verification(_) => Fail::Verification(m),
            _ => Fail::Input(m),
        }
    }
}

impl From<exactlti::io::InputError> for Fail {
    fn from(e: exactlti::io::InputError) -> Self {
        Fail::Input(e.to_string())
    }
}

impl From<Fail> for PyErr {
    fn from(f: Fail) -> PyErr {
        match f {
            Fail::Input(m) => PyValueError::new_err(m),
            Fail::Unsupported(m) => UnsupportedError::new_err(m),
            Fail::Limit(m) => PyTimeoutError::new_err(m),
            Fail::Verification(m) => VerificationError::new_err(m),
        }
    }
}

type FResult<T> = Result<T, Fail>;

// ---------------------------------------------------------------- the worker

/// Runs `f` on a worker thread (the command line's 256 MiB stack) with the GIL released.
/// Every 20 ms the caller's thread takes the GIL back to run Python's signal handlers
/// (Ctrl-C raises `KeyboardInterrupt` here) and to check the deadline (`TimeoutError`).
/// A panic in the library becomes `RuntimeError`, never a crash of the interpreter. On an
/// interrupt or a timeout the worker is left to finish in the background and its result is
/// dropped, as the command line does with `--max-seconds`.
fn run<T: Send + 'static>(
    py: Python<'_>,
    max_seconds: Option<f64>,
    f: impl FnOnce() -> FResult<T> + Send + 'static,
) -> PyResult<T> {
    let (tx, rx) = mpsc::channel();
    let rx = std::sync::Mutex::new(rx);
    let spawned = std::thread::Builder::new()
        .name("exactlti-worker".into())
        .stack_size(256 << 20)
        .spawn(move || {
            let r = std::panic::catch_unwind(std::panic::AssertUnwindSafe(f));
            let _ = tx.send(r);
        });
    if spawned.is_err() {
        return Err(PyRuntimeError::new_err("could not start the worker thread"));
    }
    let start = Instant::now();
    let limit = max_seconds
        .filter(|s| s.is_finite() && *s > 0.0)
        .map(|s| Duration::from_secs_f64(s.min(1e7)));
    loop {
        let got = py.detach(|| {
            rx.lock()
                .map_err(|_| mpsc::RecvTimeoutError::Disconnected)
                .and_then(|r| r.recv_timeout(Duration::from_millis(20)))
        });
        match got {
            Ok(Ok(r)) => return r.map_err(PyErr::from),
            Ok(Err(panic)) => {
                let msg = panic
                    .downcast_ref::<&str>()
                    .map(|s| s.to_string())
                    .or_else(|| panic.downcast_ref::<String>().cloned())
                    .unwrap_or_default();
                return Err(PyRuntimeError::new_err(format!(
                    "internal failure (the computation panicked): {msg}"
                )));
            }
            Err(mpsc::RecvTimeoutError::Disconnected) => {
                return Err(PyRuntimeError::new_err(
                    "internal failure (the worker thread stopped)",
                ));
            }
            Err(mpsc::RecvTimeoutError::Timeout) => {
                // Ctrl-C (KeyboardInterrupt) or any other signal handler's exception
                py.check_signals()?;
                if let Some(l) = limit
                    && start.elapsed() >= l
                {
                    return Err(PyTimeoutError::new_err(format!(
                        "stopped after max_seconds={}: the exact computation did not finish in time",
                        l.as_secs_f64()
                    )));
                }
            }
        }
    }
}

mod ops;
mod out;
mod symbolic;
use ops::*;
use out::*;

// ---------------------------------------------------------------- systems

/// A system over its ground field, as the library's reader typed it.
#[allow(clippy::large_enum_variant)]
pub enum Sys {
    Q(String, Typed<Q>),
    Quadratic(String, Typed<QuadraticField>),
    /// Symbolic parameters: entries in $\mathbb{Q}(p_1, \dots, p_k)$.
    Sym(String, Typed<RatFuncField>),
}

/// `$body` over the system's concrete field (generic code that makes sense over every field).
macro_rules! over {
    ($s:expr, |$t:ident| $body:expr) => {
        match &*$s {
            Sys::Q(_, $t) => $body,
            Sys::Quadratic(_, $t) => $body,
            Sys::Sym(_, $t) => $body,
        }
    };
}

/// `$body` over a numeric field; a symbolic system is refused (`what` needs numbers).
macro_rules! over_numeric {
    ($s:expr, $what:expr, |$t:ident| $body:expr) => {
        match &*$s {
            Sys::Q(_, $t) => $body,
            Sys::Quadratic(_, $t) => $body,
            Sys::Sym(g, _) => Err(symbolic::needs_numbers($what, g)),
        }
    };
}

impl Sys {
    fn from_loaded(l: Loaded) -> Self {
        match l {
            Loaded::Q(g, t) => Sys::Q(g, t),
            Loaded::Quadratic(g, t) => Sys::Quadratic(g, t),
            Loaded::Sym(g, t) => Sys::Sym(g, t),
        }
    }
    fn rational(&self, what: &str) -> FResult<&Typed<Q>> {
        match self {
            Sys::Q(_, t) => Ok(t),
            Sys::Quadratic(g, _) => Err(Fail::Unsupported(format!(
                "{what} needs rational matrices; this system's entries lie in {g}"
            ))),
            Sys::Sym(g, _) => Err(symbolic::needs_numbers(what, g)),
        }
    }
}

/// An exact state-space system (standard form; a descriptor system is converted on input).
#[pyclass(frozen, module = "exactlti._core")]
pub struct System {
    pub(crate) inner: Arc<Sys>,
}

impl From<(String, Typed<Q>)> for Sys {
    fn from((_, t): (String, Typed<Q>)) -> Self {
        Sys::Q("QQ".into(), t)
    }
}

impl From<(String, Typed<QuadraticField>)> for Sys {
    fn from((_, t): (String, Typed<QuadraticField>)) -> Self {
        let g = t.ss.a.field().to_string();
        Sys::Quadratic(g, t)
    }
}

impl From<(String, Typed<RatFuncField>)> for Sys {
    fn from((_, t): (String, Typed<RatFuncField>)) -> Self {
        let g = t.ss.a.field().to_string();
        Sys::Sym(g, t)
    }
}

#[pymethods]
impl System {
    /// The exact matrices as a dict of plain data (see the Python layer).
    fn matrices(&self) -> PyResult<Py<PyAny>> {
        Python::attach(|py| over!(self.inner, |t| typed_system(t)).to_py(py))
    }

    /// Name of the ground field (`QQ`, `QQ(sqrt(2))`, ...).
    #[getter]
    fn ground(&self) -> String {
        match &*self.inner {
            Sys::Q(g, _) | Sys::Quadratic(g, _) | Sys::Sym(g, _) => g.clone(),
        }
    }

    /// The symbolic parameters (empty for a numeric system).
    #[getter]
    fn params(&self) -> Vec<String> {
        match &*self.inner {
            Sys::Sym(_, t) => t.a_raw.field().vars().to_vec(),
            _ => vec![],
        }
    }

    #[getter]
    fn shape(&self) -> (usize, usize, usize) {
        over!(self.inner, |t| (
            t.ss.nstates(),
            t.ss.ninputs(),
            t.ss.noutputs()
        ))
    }

    #[pyo3(signature = (method, max_seconds=None))]
    fn minreal(
        &self,
        py: Python<'_>,
        method: String,
        max_seconds: Option<f64>,
    ) -> PyResult<Py<PyAny>> {
        let s = self.inner.clone();
        let out = run(py, max_seconds, move || {
            if method == "jordan" {
                let t = s.rational("the Jordan-form method")?;
                let r = realization::minimal_jordan(&t.ss)?;
                return Ok(Out::Dict(vec![
                    ("system", Out::None),
                    ("order", usize_out(r.mcmillan_degree)),
                    ("original_order", usize_out(r.stages[0])),
                    (
                        "stages",
                        Out::List(r.stages.iter().map(|&x| usize_out(x)).collect()),
                    ),
                    ("method", Out::Str("jordan".into())),
                    ("T", Out::None),
                    ("verified", Out::Bool(r.verified)),
                    ("report", report(&r.report())),
                ]));
            }
            let m = method_of(&method)?;
            match &*s {
                Sys::Sym(_, t) => symbolic::minreal(t, m),
                _ => over!(s, |t| minreal_typed(t, m)),
            }
        })?;
        out.to_py(py)
    }

    #[pyo3(signature = (max_seconds=None))]
    fn scb(&self, py: Python<'_>, max_seconds: Option<f64>) -> PyResult<Py<PyAny>> {
        let s = self.inner.clone();
        run(py, max_seconds, move || match &*s {
            Sys::Sym(_, t) => symbolic::scb(t),
            _ => over!(s, |t| scb_typed(t)),
        })?
        .to_py(py)
    }

    #[pyo3(signature = (max_seconds=None))]
    fn zeros(&self, py: Python<'_>, max_seconds: Option<f64>) -> PyResult<Py<PyAny>> {
        let s = self.inner.clone();
        run(py, max_seconds, move || match &*s {
            Sys::Sym(_, t) => symbolic::zeros(t),
            _ => over!(s, |t| zeros_typed(t)),
        })?
        .to_py(py)
    }

    /// Roots of the characteristic polynomial of `A` with multiplicities.
    #[pyo3(signature = (max_seconds=None))]
    fn poles(&self, py: Python<'_>, max_seconds: Option<f64>) -> PyResult<Py<PyAny>> {
        let s = self.inner.clone();
        run(py, max_seconds, move || {
            if let Sys::Sym(_, t) = &*s {
                return symbolic::poles(t);
            }
            let t = s.rational("exact poles")?;
            let p = t.ss.a.charpoly()?;
            if p.deg() == 0 {
                return Ok(Out::List(vec![]));
            }
            Ok(Out::List(
                exactlti::algebraic::roots(&p)?
                    .iter()
                    .map(|(n, m)| alg(n, *m))
                    .collect(),
            ))
        })?
        .to_py(py)
    }

    #[pyo3(signature = (real=false, max_seconds=None))]
    fn jordan(&self, py: Python<'_>, real: bool, max_seconds: Option<f64>) -> PyResult<Py<PyAny>> {
        let s = self.inner.clone();
        run(py, max_seconds, move || {
            let jf = match &*s {
                Sys::Q(_, t) if t.descriptor.is_some() => {
                    return ops::descriptor_jordan(t, real, exactlti::jordan::jordan);
                }
                Sys::Quadratic(_, t) if t.descriptor.is_some() => {
                    return ops::descriptor_jordan(t, real, exactlti::jordan::jordan_quadratic);
                }
                Sys::Q(_, t) => exactlti::jordan::jordan(&t.a_raw)?,
                Sys::Quadratic(_, t) => exactlti::jordan::jordan_quadratic(&t.a_raw)?,
                Sys::Sym(g, t) => {
                    if real {
                        return Err(Fail::Unsupported(format!(
                            "symbolic parameters: the real Jordan form is not yet supported over {g}; \
                             give values (subs)"
                        )));
                    }
                    return symbolic::jordan(&t.a_raw);
                }
            };
            jordan_out(&jf, real)
        })?
        .to_py(py)
    }

    #[pyo3(signature = (max_seconds=None))]
    fn mnf(&self, py: Python<'_>, max_seconds: Option<f64>) -> PyResult<Py<PyAny>> {
        let s = self.inner.clone();
        run(py, max_seconds, move || {
            if let Sys::Sym(_, t) = &*s {
                return symbolic::mnf(t);
            }
            let t = s.rational("the mechanical normal form")?;
            let ss = &t.ss;
            let r = exactlti::structure::mechanical::mechanical_normal_form(
                &ss.a, &ss.b, &ss.c, &ss.d,
            )?;
            let kv = mnf_out(&r);
            Ok(Out::Dict(kv))
        })?
        .to_py(py)
    }

    #[pyo3(signature = (max_seconds=None))]
    fn modes(&self, py: Python<'_>, max_seconds: Option<f64>) -> PyResult<Py<PyAny>> {
        let s = self.inner.clone();
        run(py, max_seconds, move || {
            let t = s.rational("the modal table")?;
            let m = realization::modal_table(&t.ss.a)?;
            let opt = |x: Option<f64>| x.map(Out::Float).unwrap_or(Out::None);
            Ok(Out::Dict(vec![
                (
                    "modes",
                    Out::List(
                        m.modes
                            .iter()
                            .map(|md| {
                                Out::Dict(vec![
                                    ("eigenvalue", Out::Str(md.eigenvalue.clone())),
                                    ("minpoly", Out::Str(md.minpoly.clone())),
                                    (
                                        "approx",
                                        Out::Tuple(vec![
                                            Out::Float(md.approx.0),
                                            Out::Float(md.approx.1),
                                        ]),
                                    ),
                                    ("multiplicity", usize_out(md.multiplicity)),
                                    ("frequency_hz", Out::Float(md.frequency_hz)),
                                    ("damping_ratio", opt(md.damping_ratio)),
                                    ("time_constant_s", opt(md.time_constant_s)),
                                    ("period_s", opt(md.period_s)),
                                ])
                            })
                            .collect(),
                    ),
                ),
                ("report", report(&m.report())),
            ]))
        })?
        .to_py(py)
    }

    #[pyo3(signature = (max_seconds=None))]
    fn tf(&self, py: Python<'_>, max_seconds: Option<f64>) -> PyResult<Py<PyAny>> {
        let s = self.inner.clone();
        run(py, max_seconds, move || match &*s {
            Sys::Sym(_, t) => symbolic::tf(t),
            _ => over!(s, |t| tf_typed(t)),
        })?
        .to_py(py)
    }

    /// Markov parameters `C A^k B` for `k < count` (`D` not included).
    #[pyo3(signature = (count, max_seconds=None))]
    fn markov(
        &self,
        py: Python<'_>,
        count: usize,
        max_seconds: Option<f64>,
    ) -> PyResult<Py<PyAny>> {
        let s = self.inner.clone();
        run(py, max_seconds, move || {
            Ok(over!(s, |t| Out::List(
                t.ss.markov(count).iter().map(mat).collect()
            )))
        })?
        .to_py(py)
    }

    #[pyo3(signature = (max_seconds=None))]
    fn ctrb(&self, py: Python<'_>, max_seconds: Option<f64>) -> PyResult<Py<PyAny>> {
        let s = self.inner.clone();
        run(py, max_seconds, move || {
            Ok(over!(s, |t| mat(&realization::controllability_matrix(
                &t.ss.a, &t.ss.b
            ))))
        })?
        .to_py(py)
    }

    #[pyo3(signature = (max_seconds=None))]
    fn obsv(&self, py: Python<'_>, max_seconds: Option<f64>) -> PyResult<Py<PyAny>> {
        let s = self.inner.clone();
        run(py, max_seconds, move || {
            Ok(over!(s, |t| mat(&realization::observability_matrix(
                &t.ss.a, &t.ss.c
            ))))
        })?
        .to_py(py)
    }

    /// The float path beside the exact path: McMillan degree, controllability and
    /// observability ranks, and eigenvalues, each exact and in floating point.
    #[pyo3(signature = (max_seconds=None))]
    fn check(&self, py: Python<'_>, max_seconds: Option<f64>) -> PyResult<Py<PyAny>> {
        let s = self.inner.clone();
        run(py, max_seconds, move || {
            over_numeric!(s, "the float cross-check", |t| check_typed(t))
        })?
        .to_py(py)
    }

    /// Frequency response `C (j w I - A)^{-1} B + D` in floating point, `omega` in rad/s.
    fn freqresp(&self, py: Python<'_>, omega: Vec<f64>) -> PyResult<Py<PyAny>> {
        let s = self.inner.clone();
        run(py, None, move || {
            over_numeric!(s, "the frequency response", |t| freqresp_typed(t, &omega))
        })?
        .to_py(py)
    }
}

/// Reads a system from JSON text (the system-file format; `name` is used in messages).
/// `symbolic`: parameters with value `null` and the `symbols` key stay symbols (the
/// library's `load_symbolic_str`); a file without symbols is read as by `load_json`.
#[pyfunction]
#[pyo3(signature = (text, name, symbolic=false))]
fn load_json(py: Python<'_>, text: String, name: String, symbolic: bool) -> PyResult<System> {
    let l = run(py, None, move || {
        let fmt = exactlti::io::SystemFormat::Json;
        let l = if symbolic {
            let opts = exactlti::io::symbolic::SymbolicOptions::default();
            exactlti::io::symbolic::load_symbolic_str(&text, fmt, &name, &opts)?
        } else {
            exactlti::io::load_system_str(&text, fmt, &name)?
        };
        from_loaded(l).map_err(Fail::Unsupported)
    })?;
    Ok(System {
        inner: Arc::new(Sys::from_loaded(l)),
    })
}

/// Reads a system file (JSON or TOML, chosen by extension) as the command line does:
/// parameters with value `null` and those named in `symbols` stay symbols; `at` gives
/// values first (the command line's `--at`).
#[pyfunction]
#[pyo3(signature = (path, at=None))]
fn load_file(py: Python<'_>, path: String, at: Option<Vec<(String, String)>>) -> PyResult<System> {
    let l = run(py, None, move || {
        let opts = exactlti::io::symbolic::SymbolicOptions {
            symbolic: None,
            at: at.unwrap_or_default(),
        };
        let l = match exactlti::io::symbolic::load_symbolic_path(Path::new(&path), &opts) {
            Ok(l) => l,
            // as the command line: without --at the ordinary reader reports its own errors
            Err(_) if opts.at.is_empty() => exactlti::io::load_system_path(Path::new(&path))?,
            Err(e) => return Err(e.into()),
        };
        from_loaded(l).map_err(Fail::Unsupported)
    })?;
    Ok(System {
        inner: Arc::new(Sys::from_loaded(l)),
    })
}

/// Test hook: a panic in the worker must become `RuntimeError`.
#[pyfunction]
fn _panic_for_test(py: Python<'_>) -> PyResult<()> {
    run(py, None, || -> FResult<()> { panic!("test panic") })
}

/// Test hook: `seconds` of busy work in the worker, to test Ctrl-C and `max_seconds`.
#[pyfunction]
#[pyo3(signature = (seconds, max_seconds=None))]
fn _sleep_for_test(py: Python<'_>, seconds: f64, max_seconds: Option<f64>) -> PyResult<()> {
    run(py, max_seconds, move || {
        std::thread::sleep(Duration::from_secs_f64(seconds));
        Ok(())
    })
}

#[pymodule]
fn _core(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<System>()?;
    m.add_function(wrap_pyfunction!(load_json, m)?)?;
    m.add_function(wrap_pyfunction!(load_file, m)?)?;
    m.add_function(wrap_pyfunction!(study::sweep, m)?)?;
    m.add_function(wrap_pyfunction!(study::critical, m)?)?;
    m.add_function(wrap_pyfunction!(_panic_for_test, m)?)?;
    m.add_function(wrap_pyfunction!(_sleep_for_test, m)?)?;
    m.add("UnsupportedError", m.py().get_type::<UnsupportedError>())?;
    m.add("VerificationError", m.py().get_type::<VerificationError>())?;
    Ok(())
}
