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
mod study;
use exactlti::api::runner::{Poll, Worker};
use exactlti::field::{Q, QuadraticField};
use exactlti::io::{TypedAny, TypedSystem as Typed};
use exactlti::ratfunc::RatFuncField;
use exactlti::realization;
use pyo3::create_exception;
use pyo3::exceptions::{PyRuntimeError, PyTimeoutError, PyValueError};
use pyo3::prelude::*;
use std::path::Path;
use std::sync::Arc;
use std::time::Duration;

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
            Fail::Input(m) => PyValueError::new_err(scrub(&m)),
            Fail::Unsupported(m) => UnsupportedError::new_err(scrub(&m)),
            Fail::Limit(m) => PyTimeoutError::new_err(scrub(&m)),
            Fail::Verification(m) => VerificationError::new_err(scrub(&m)),
        }
    }
}

impl From<exactlti::api::Failure> for Fail {
    /// A command's failure: exit status 1 is a failed exact check, 2 bad input or a request
    /// that cannot be met (the message says why).
    fn from(f: exactlti::api::Failure) -> Self {
        if f.code == 1 {
            Fail::Verification(f.message)
        } else {
            Fail::Input(f.message)
        }
    }
}

type FResult<T> = Result<T, Fail>;

// ---------------------------------------------------------------- the worker

/// Runs `f` on the library's worker ([`exactlti::api::runner::Worker`]: the command line's
/// 256 MiB stack, a panic caught) with the GIL released. Every 20 ms the caller's thread
/// takes the GIL back to run Python's signal handlers (Ctrl-C raises `KeyboardInterrupt`
/// here); past `max_seconds` it raises `TimeoutError`. A panic in the library becomes
/// `RuntimeError`, never a crash of the interpreter. On an interrupt or a timeout the worker
/// is left to finish in the background and its result is dropped, as the command line does
/// with `--max-seconds`.
fn run<T: Send + 'static>(
    py: Python<'_>,
    max_seconds: Option<f64>,
    f: impl FnOnce() -> FResult<T> + Send + 'static,
) -> PyResult<T> {
    let deadline = Worker::<FResult<T>>::deadline_in(max_seconds);
    let w = Worker::spawn("exactlti-worker", deadline, f).map_err(PyRuntimeError::new_err)?;
    loop {
        match py.detach(|| w.poll(Duration::from_millis(20))) {
            Poll::Done(r) => return r.map_err(PyErr::from),
            Poll::Panicked(msg) => {
                return Err(PyRuntimeError::new_err(format!(
                    "internal failure (the computation panicked): {}",
                    scrub(&msg)
                )));
            }
            Poll::TimedOut => {
                return Err(PyTimeoutError::new_err(format!(
                    "stopped after max_seconds={}: the exact computation did not finish in time",
                    max_seconds.unwrap_or_default()
                )));
            }
            // Ctrl-C (KeyboardInterrupt) or any other signal handler's exception
            Poll::Pending => py.check_signals()?,
        }
    }
}

/// A message for Python users: a Rust path (`a::b::c`) is written as its last name.
fn scrub(m: &str) -> String {
    let mut out = String::with_capacity(m.len());
    for (i, part) in m.split("::").enumerate() {
        if i == 0 {
            out.push_str(part);
            continue;
        }
        // drop the identifier before `::` (the module) that was just written
        let keep = out
            .trim_end_matches(|c: char| c.is_ascii_alphanumeric() || c == '_')
            .len();
        out.truncate(keep);
        out.push_str(part);
    }
    out
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
    /// The typed system of a system read by the library's front door.
    fn of(s: &exactlti::api::System) -> Self {
        let g = s.ground().to_string();
        match &s.loaded().system {
            TypedAny::Rational(t) => Sys::Q(g, t.clone()),
            TypedAny::Quadratic(t) => Sys::Quadratic(g, t.clone()),
            TypedAny::RatFunc(t) => Sys::Sym(g, t.clone()),
            #[allow(unreachable_patterns)]
            _ => unreachable!("a ground field unknown to the Python layer"),
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
    /// The system as the library's front door read it (every command runs on it).
    pub(crate) api: Arc<exactlti::api::System>,
}

impl System {
    fn new(s: exactlti::api::System) -> Self {
        System {
            inner: Arc::new(Sys::of(&s)),
            api: Arc::new(s),
        }
    }
    /// A system computed here (a minimal realization, ...), given to the front door by its
    /// matrices.
    pub(crate) fn of_sys(s: Arc<Sys>) -> Self {
        let typed = match &*s {
            Sys::Q(_, t) => TypedAny::Rational(t.clone()),
            Sys::Quadratic(_, t) => TypedAny::Quadratic(t.clone()),
            Sys::Sym(_, t) => TypedAny::RatFunc(t.clone()),
        };
        let api = exactlti::api::System::from_typed("system", typed);
        System {
            inner: s,
            api: Arc::new(api),
        }
    }
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
                                    ("eigenvalue", Out::Str(md.eigenvalue.value_string())),
                                    ("minpoly", Out::Str(md.eigenvalue.minpoly().to_string())),
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

    /// Runs one operation of the command line on this system: `args` as the command line
    /// spells them after the program name, the file argument included (it names the system
    /// in messages; the system is not read again). Returns the report as JSON text (every
    /// exact value as a string, approximations as numbers) and whether its exact checks
    /// passed.
    #[pyo3(signature = (args, max_seconds=None))]
    fn command(
        &self,
        py: Python<'_>,
        args: Vec<String>,
        max_seconds: Option<f64>,
    ) -> PyResult<(String, bool, bool)> {
        let s = self.api.clone();
        run(py, max_seconds, move || {
            let cmd = exactlti::api::Command::parse_args(&args).map_err(Fail::Input)?;
            let ctx = exactlti::api::RunContext::default();
            let out = exactlti::api::execute_on(&cmd, &s, &ctx)?;
            let text = serde_json::to_string(&out.report.to_json())
                .map_err(|e| Fail::Input(e.to_string()))?;
            Ok((text, out.verified, !out.float_disagrees))
        })
    }

    /// The path (or name) the system was read from, and whether it is a file.
    #[getter]
    fn source(&self) -> (String, bool) {
        (self.api.path().display().to_string(), self.api.from_file())
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
/// Parameters with value `null` and those named in `symbols` stay symbols (the text
/// decides; `symbolic`, kept for callers, says the same).
#[pyfunction]
#[pyo3(signature = (text, name, symbolic=false))]
fn load_json(py: Python<'_>, text: String, name: String, symbolic: bool) -> PyResult<System> {
    let _ = symbolic;
    let s = run(py, None, move || {
        let fmt = exactlti::io::SystemFormat::Json;
        let opts = exactlti::api::Options::default();
        Ok(exactlti::api::System::from_text(&text, fmt, &name, &opts)?)
    })?;
    Ok(System::new(s))
}

/// Reads a system file (JSON or TOML, chosen by extension) as the command line does:
/// parameters with value `null` and those named in `symbols` stay symbols; `at` gives
/// values first (the command line's `--at`), `symbolic` names parameters kept as symbols
/// (the command line's `--symbolic`; an empty list: every parameter).
#[pyfunction]
#[pyo3(signature = (path, at=None, symbolic=None))]
fn load_file(
    py: Python<'_>,
    path: String,
    at: Option<Vec<(String, String)>>,
    symbolic: Option<Vec<String>>,
) -> PyResult<System> {
    let s = run(py, None, move || {
        let opts = exactlti::api::Options {
            symbolic,
            at: at.unwrap_or_default(),
        };
        Ok(exactlti::api::System::open(Path::new(&path), &opts)?)
    })?;
    Ok(System::new(s))
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
