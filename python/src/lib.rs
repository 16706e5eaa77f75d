//! `exactlti._core`: the PyO3 layer under the `exactlti` Python package.
//!
//! Thin by design: systems are read by the library's own system-file reader (so a bad entry
//! gives the command line's one-line message), every computation runs on a worker thread
//! with the GIL released while this thread polls for Ctrl-C (`check_signals`) and for the
//! `max_seconds` deadline, and results come back as plain dicts of exact data that the
//! pure-Python layer (`python/exactlti/`) wraps in classes: every exact number as a VALUE
//! (rationals as integer pairs, $a + b\sqrt d$, polynomials in a marked root, rational
//! functions of the parameters as term lists, algebraic numbers by minimal polynomial and
//! isolating box: the encoding is in [`values`]), its display text and LaTeX beside it only
//! to be shown; Python builds SymPy from the values and parses no text.
//!
//! The choices of a command are the api's, not repeated here: which matrix `jordan`
//! decomposes and over which field ([`exactlti::api::jordan_values`]), loading
//! ([`exactlti::api::System`]), every command of the command line ([`exactlti::api::execute_on`]).
#![allow(non_snake_case)]

use exactlti::Error;
use exactlti::error::ErrorClass;
mod study;
use exactlti::api::runner::{Poll, Worker};
use exactlti::io::TypedSystem as Typed;
use exactlti::ratfunc::RatFuncField;
use exactlti::realization;
use exactlti::system::discrete::stability::Domain;
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

impl Fail {
    /// The failure of class `class` with message `m`.
    fn of_class(class: ErrorClass, m: String) -> Self {
        match class {
            ErrorClass::Unsupported => Fail::Unsupported(m),
            ErrorClass::Limit => Fail::Limit(m),
            ErrorClass::Verification => Fail::Verification(m),
            ErrorClass::Input => Fail::Input(m),
        }
    }
}

impl From<Error> for Fail {
    /// By the library's class of the error ([`Error::class`]), as the command line does.
    fn from(e: Error) -> Self {
        Fail::of_class(e.class(), e.to_string())
    }
}

impl From<exactlti::io::InputError> for Fail {
    fn from(e: exactlti::io::InputError) -> Self {
        Error::from(e).into()
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
    /// A command's failure, by its class ([`exactlti::api::Failure::class`]): an
    /// unsupported case or a size bound of an api command raises the same exception type as
    /// the library's error would.
    fn from(f: exactlti::api::Failure) -> Self {
        Fail::of_class(f.class, f.message)
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
mod values;
use ops::*;
use out::*;

// ---------------------------------------------------------------- systems

/// Runs generic code on a system over its concrete ground field through the library's one
/// dispatch ([`exactlti::api::System::run`]): `$num` for every field, `$sym` (when given)
/// over $\mathbb{Q}(p_1, \dots, p_k)$. The names in `[...]` are moved into the visitor.
/// The time domain of a system file (discrete when it has a sample time `dt`).
fn domain_of(f: &exactlti::io::SystemFile) -> Domain {
    Domain::of(f.signals.dt.as_ref())
}

macro_rules! visit {
    ($s:expr => $out:ty, [$($v:ident : $ty:ty),*], |$f:ident, $t:ident| $num:expr) => {{
        struct V { $($v: $ty),* }
        impl exactlti::api::SystemVisitor for V {
            type Output = $out;
            #[allow(unused_variables)]
            fn visit<K: exactlti::realization::SystemField>(
                self,
                $f: &exactlti::io::SystemFile,
                $t: &Typed<K>,
            ) -> $out {
                let V { $($v),* } = self;
                $num
            }
        }
        $s.run(V { $($v),* })
    }};
    ($s:expr => $out:ty, [$($v:ident : $ty:ty),*], |$f:ident, $t:ident| $num:expr,
     sym |$f2:ident, $t2:ident| $sym:expr) => {{
        struct V { $($v: $ty),* }
        impl exactlti::api::SystemVisitor for V {
            type Output = $out;
            #[allow(unused_variables)]
            fn visit<K: exactlti::realization::SystemField>(
                self,
                $f: &exactlti::io::SystemFile,
                $t: &Typed<K>,
            ) -> $out {
                let V { $($v),* } = self;
                $num
            }
            #[allow(unused_variables)]
            fn visit_symbolic(
                self,
                $f2: &exactlti::io::SystemFile,
                $t2: &Typed<RatFuncField>,
            ) -> $out {
                let V { $($v),* } = self;
                $sym
            }
        }
        $s.run(V { $($v),* })
    }};
}

/// An exact state-space system (standard form; a descriptor system is converted on input).
#[pyclass(frozen, module = "exactlti._core")]
pub struct System {
    /// The system as the library's front door read it (every operation runs on it).
    pub(crate) api: Arc<exactlti::api::System>,
}

impl System {
    fn new(s: exactlti::api::System) -> Self {
        System { api: Arc::new(s) }
    }
}

#[pymethods]
impl System {
    /// The exact matrices as a dict of plain data (see the Python layer).
    fn matrices(&self) -> PyResult<Py<PyAny>> {
        let out = visit!(self.api => Out, [], |f, t| typed_system(t));
        Python::attach(|py| out.to_py(py))
    }

    /// The system as a report of the library (`A`, `B`, `C`, `D`; `E` and the descriptor's
    /// `A` for a descriptor system), rendered by its report layer: `{latex, html}`.
    fn render(&self) -> PyResult<Py<PyAny>> {
        let ground = self.api.ground().to_string();
        let r = visit!(self.api => exactlti::report::Report, [ground: String], |f, t| {
            let s = &t.ss;
            let title = match &t.descriptor {
                None => format!("state space over {ground}"),
                Some(_) => format!("descriptor system over {ground}, with its standard form (A, B, C, D)"),
            };
            let mut r = exactlti::report::Report::titled(title)
                .matrices(&[("A", &s.a), ("B", &s.b), ("C", &s.c), ("D", &s.d)]);
            if let Some(d) = &t.descriptor {
                r = r.matrices(&[("E", &d.e), ("A_E", &d.a)]);
            }
            r
        });
        let out = Out::Dict(vec![
            ("latex", Out::Str(r.to_latex_math())),
            ("html", Out::Str(r.to_html())),
        ]);
        Python::attach(|py| out.to_py(py))
    }

    /// Name of the ground field (`QQ`, `QQ(sqrt(2))`, ...).
    #[getter]
    fn ground(&self) -> String {
        self.api.ground().to_string()
    }

    /// The symbolic parameters (empty for a numeric system).
    #[getter]
    fn params(&self) -> Vec<String> {
        visit!(self.api => Vec<String>, [], |f, t| vec![],
               sym |f, t| t.a_raw.field().vars().to_vec())
    }

    #[getter]
    fn shape(&self) -> (usize, usize, usize) {
        visit!(self.api => (usize, usize, usize), [], |f, t| (
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
        let s = self.api.clone();
        let out = run(py, max_seconds, move || {
            visit!(s => FResult<Out>, [method: String], |f, t| minreal_typed(t, method_of(&method)?),
                   sym |f, t| symbolic::minreal(t, method_of(&method)?))
        })?;
        out.to_py(py)
    }

    #[pyo3(signature = (max_seconds=None))]
    fn scb(&self, py: Python<'_>, max_seconds: Option<f64>) -> PyResult<Py<PyAny>> {
        let s = self.api.clone();
        run(
            py,
            max_seconds,
            move || visit!(s => FResult<Out>, [], |f, t| scb_typed(t), sym |f, t| symbolic::scb(t)),
        )?
        .to_py(py)
    }

    #[pyo3(signature = (max_seconds=None))]
    fn zeros(&self, py: Python<'_>, max_seconds: Option<f64>) -> PyResult<Py<PyAny>> {
        let s = self.api.clone();
        run(py, max_seconds, move || {
            visit!(s => FResult<Out>, [], |f, t| zeros_typed(t, domain_of(f)), sym |f, t| symbolic::zeros(t, domain_of(f)))
        })?
        .to_py(py)
    }

    /// Roots of the characteristic polynomial of `A` with multiplicities, over the field the
    /// api decomposes `A` in ([`exactlti::api::poles::eigenvalues`], as `pzmap`); over
    /// $\mathbb{Q}(p)$ the factors of $\det(sI - A)$.
    #[pyo3(signature = (max_seconds=None))]
    fn poles(&self, py: Python<'_>, max_seconds: Option<f64>) -> PyResult<Py<PyAny>> {
        let s = self.api.clone();
        run(py, max_seconds, move || {
            visit!(s => FResult<Out>, [], |f, t| {
                let roots = exactlti::api::poles::eigenvalues(&t.ss.a).ok_or_else(|| {
                    Fail::Unsupported(format!(
                        "exact poles are not supported over {}",
                        t.ss.a.field()
                    ))
                })??;
                Ok(Out::List(roots.iter().map(|(n, _, m)| alg(n, *m)).collect()))
            }, sym |f, t| symbolic::poles(t))
        })?
        .to_py(py)
    }

    #[pyo3(signature = (real=false, max_seconds=None))]
    fn jordan(&self, py: Python<'_>, real: bool, max_seconds: Option<f64>) -> PyResult<Py<PyAny>> {
        let s = self.api.clone();
        let path = self.api.path().to_path_buf();
        run(py, max_seconds, move || {
            visit!(s => FResult<Out>, [real: bool, path: std::path::PathBuf], |f, t| ops::jordan_typed(t, real, &path),
                   sym |f, t| {
                if real {
                    return Err(Fail::Unsupported(format!(
                        "symbolic parameters: the real Jordan form is not yet supported over {}; \
                         give values (subs)",
                        f.ground
                    )));
                }
                match &t.descriptor {
                    Some(d) => symbolic::jordan_descriptor(d, &path),
                    None => symbolic::jordan(&t.a_raw),
                }
            })
        })?
        .to_py(py)
    }

    #[pyo3(signature = (max_seconds=None))]
    fn mnf(&self, py: Python<'_>, max_seconds: Option<f64>) -> PyResult<Py<PyAny>> {
        let s = self.api.clone();
        run(py, max_seconds, move || {
            visit!(s => FResult<Out>, [], |f, t| {
                // over every numeric field, as the command line's `mnf`
                let ss = &t.ss;
                let r = exactlti::structure::mechanical::mechanical_normal_form(
                    &ss.a, &ss.b, &ss.c, &ss.d,
                )?;
                Ok(Out::Dict(mnf_out(&r)))
            }, sym |f, t| symbolic::mnf(t))
        })?
        .to_py(py)
    }

    #[pyo3(signature = (max_seconds=None))]
    fn modes(&self, py: Python<'_>, max_seconds: Option<f64>) -> PyResult<Py<PyAny>> {
        let s = self.api.clone();
        run(py, max_seconds, move || {
            visit!(s => FResult<Out>, [], |f, t| modes_out(&t.ss.a), sym |f, t| Err(symbolic::needs_numbers("the modal table", &f.ground.to_string())))
        })?
        .to_py(py)
    }

    #[pyo3(signature = (max_seconds=None))]
    fn tf(&self, py: Python<'_>, max_seconds: Option<f64>) -> PyResult<Py<PyAny>> {
        let s = self.api.clone();
        run(
            py,
            max_seconds,
            move || visit!(s => FResult<Out>, [], |f, t| tf_typed(t, domain_of(f)), sym |f, t| symbolic::tf(t, domain_of(f))),
        )?
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
        let s = self.api.clone();
        run(py, max_seconds, move || {
            visit!(s => FResult<Out>, [count: usize], |f, t| Ok(Out::List(
                t.ss.markov(count).iter().map(mat).collect()
            )))
        })?
        .to_py(py)
    }

    #[pyo3(signature = (max_seconds=None))]
    fn ctrb(&self, py: Python<'_>, max_seconds: Option<f64>) -> PyResult<Py<PyAny>> {
        let s = self.api.clone();
        run(py, max_seconds, move || {
            visit!(s => FResult<Out>, [], |f, t| Ok(mat(
                &realization::controllability_matrix(&t.ss.a, &t.ss.b)
            )))
        })?
        .to_py(py)
    }

    #[pyo3(signature = (max_seconds=None))]
    fn obsv(&self, py: Python<'_>, max_seconds: Option<f64>) -> PyResult<Py<PyAny>> {
        let s = self.api.clone();
        run(py, max_seconds, move || {
            visit!(s => FResult<Out>, [], |f, t| Ok(mat(
                &realization::observability_matrix(&t.ss.a, &t.ss.c)
            )))
        })?
        .to_py(py)
    }

    /// The float path beside the exact path: the command line's `check` run by the api
    /// ([`exactlti::api::execute_on`]) on this system, as [`System::command`] returns it
    /// (over $\mathbb{Q}(p)$ `ValueError`: it needs numbers).
    #[pyo3(signature = (max_seconds=None))]
    fn check(&self, py: Python<'_>, max_seconds: Option<f64>) -> PyResult<CommandOut> {
        let s = self.api.clone();
        let r = run(py, max_seconds, move || {
            visit!(s => FResult<()>, [], |f, t| Ok(()),
                   sym |f, t| Err(symbolic::needs_numbers("the float cross-check", &f.ground.to_string())))?;
            let file = s.path().display().to_string();
            let cmd = exactlti::api::Command::parse_args(&["check", &file]).map_err(Fail::Input)?;
            let out = exactlti::api::execute_on(&cmd, &s, &exactlti::api::RunContext::default())?;
            command_out(&out)
        })?;
        r.into_py(py)
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
    ) -> PyResult<CommandOut> {
        let s = self.api.clone();
        let r = run(py, max_seconds, move || {
            let cmd = exactlti::api::Command::parse_args(&args).map_err(Fail::Input)?;
            let ctx = exactlti::api::RunContext::default();
            let out = exactlti::api::execute_on(&cmd, &s, &ctx)?;
            command_out(&out)
        })?;
        r.into_py(py)
    }

    /// The derivation of one command step by step (`args` as the command line spells them
    /// after the program name, without `--steps`; what `--steps` accepts): the steps as
    /// JSON text (`steps: [{step, sentence, <objects>, identity, holds, assumes}]`), whether
    /// every identity held, and the derivation as LaTeX and as HTML, both made by the
    /// library's report layer.
    #[pyo3(signature = (args, max_seconds=None))]
    fn steps(
        &self,
        py: Python<'_>,
        args: Vec<String>,
        max_seconds: Option<f64>,
    ) -> PyResult<(String, bool, String, String)> {
        let s = self.api.clone();
        run(py, max_seconds, move || {
            let cmd = exactlti::api::Command::parse_args(&args).map_err(Fail::Input)?;
            let out = exactlti::api::steps::steps_on(&cmd, &s)?;
            let text = serde_json::to_string(&out.report.to_json())
                .map_err(|e| Fail::Input(e.to_string()))?;
            Ok((text, out.verified, out.latex, out.html))
        })
    }

    /// The path (or name) the system was read from, and whether it is a file.
    #[getter]
    fn source(&self) -> (String, bool) {
        (self.api.path().display().to_string(), self.api.from_file())
    }

    /// Frequency response `C (j w I - A)^{-1} B + D` in floating point, `omega` in rad/s.
    fn freqresp(&self, py: Python<'_>, omega: Vec<f64>) -> PyResult<Py<PyAny>> {
        let s = self.api.clone();
        run(py, None, move || {
            visit!(s => FResult<Out>, [omega: Vec<f64>], |f, t| freqresp_typed(t, &omega, f.signals.dt.as_ref().map(exactlti::field::rational_to_f64)),
                   sym |f, t| Err(symbolic::needs_numbers("the frequency response", &f.ground.to_string())))
        })?
        .to_py(py)
    }

    /// Balanced truncation of order `order` on the float path (square-root method):
    /// `A`, `B`, `C`, `D` (float rows), `hankel_singular_values`, `error_bound`.
    fn balred(&self, py: Python<'_>, order: usize) -> PyResult<Py<PyAny>> {
        let s = self.api.clone();
        run(py, None, move || {
            visit!(s => FResult<Out>, [order: usize], |f, t| balred_typed(t, order),
                   sym |f, t| Err(symbolic::needs_numbers("balanced truncation", &f.ground.to_string())))
        })?
        .to_py(py)
    }

    /// The sample time of a discrete-time system as exact text (`None`: continuous).
    #[getter]
    fn dt(&self) -> Option<String> {
        self.api.dt().map(exactlti::report::display::fmt_rational)
    }

    /// The input and output names the system carries (`None` where it has none).
    #[getter]
    fn signal_names(&self) -> (Option<Vec<String>>, Option<Vec<String>>) {
        let s = &self.api.file().signals;
        (s.inputs.clone(), s.outputs.clone())
    }

    /// The same system with input/output names and a sample time (`dt`: exact text, `None`
    /// or `"0"`: continuous); names whose count does not fit are an error.
    #[pyo3(signature = (inputs=None, outputs=None, dt=None))]
    fn with_signals(
        &self,
        inputs: Option<Vec<String>>,
        outputs: Option<Vec<String>>,
        dt: Option<String>,
    ) -> PyResult<System> {
        let dt = match dt {
            None => None,
            Some(t) => {
                let q = exactlti::field::parse_rational(&t)
                    .map_err(|e| PyValueError::new_err(format!("dt '{t}': {e}")))?;
                if q < exactlti::field::Rational::from_integer(0.into()) {
                    return Err(PyValueError::new_err(format!("dt must be >= 0, found {t}")));
                }
                (q != exactlti::field::Rational::from_integer(0.into())).then_some(q)
            }
        };
        let (n, m, p) = self.shape();
        let signals = exactlti::io::SignalNames {
            inputs,
            outputs,
            states: None,
            dt,
        };
        signals
            .check(&self.api.path().display().to_string(), n, m, p)
            .map_err(|e| PyValueError::new_err(e.to_string()))?;
        Ok(System::new(self.api.as_ref().clone().with_signals(signals)))
    }

    /// An interconnection (`args` as the command line spells it) of this system and
    /// `others` as a new system (names and sample time by python-control's rules).
    #[pyo3(signature = (args, others, max_seconds=None))]
    fn connect_system(
        &self,
        py: Python<'_>,
        args: Vec<String>,
        others: Vec<PyRef<'_, System>>,
        max_seconds: Option<f64>,
    ) -> PyResult<System> {
        let mut all = vec![self.api.clone()];
        all.extend(others.iter().map(|o| o.api.clone()));
        let s = run(py, max_seconds, move || {
            let cmd = exactlti::api::Command::parse_args(&args).map_err(Fail::Input)?;
            let exactlti::api::Command::Interconnect(c) = cmd else {
                return Err(Fail::Input(format!(
                    "{}: not an interconnection",
                    args.join(" ")
                )));
            };
            let refs: Vec<&exactlti::api::System> = all.iter().map(|s| s.as_ref()).collect();
            Ok(exactlti::api::interconnect_system(&c, &refs)?)
        })?;
        Ok(System::new(s))
    }

    /// Runs an interconnection of the command line (`series`, `parallel`, `feedback`,
    /// `append`: `args` as the command line spells them, one file name per system) on this
    /// system and `others`, in that order, through the library's front door.
    #[pyo3(signature = (args, others, max_seconds=None))]
    fn connect(
        &self,
        py: Python<'_>,
        args: Vec<String>,
        others: Vec<PyRef<'_, System>>,
        max_seconds: Option<f64>,
    ) -> PyResult<CommandOut> {
        let mut all = vec![self.api.clone()];
        all.extend(others.iter().map(|o| o.api.clone()));
        let r = run(py, max_seconds, move || {
            let cmd = exactlti::api::Command::parse_args(&args).map_err(Fail::Input)?;
            let ctx = exactlti::api::RunContext::default();
            let refs: Vec<&exactlti::api::System> = all.iter().map(|s| s.as_ref()).collect();
            let out = exactlti::api::execute_on_many(&cmd, &refs, &ctx)?;
            command_out(&out)
        })?;
        r.into_py(py)
    }
}

/// A command's outcome for Python: the report as JSON text, whether its exact checks
/// passed, whether the float path agrees, the report as LaTeX (one math formula) and HTML
/// (the library's report layer renders both from the report's values), and the values of
/// its matrices by key (`Report.to_sympy`; [`values`]).
type CommandOut = (String, bool, bool, String, String, Py<PyAny>);

/// [`CommandOut`] made on the worker (the values still plain data).
struct Outcome((String, bool, bool, String, String), Out);

impl Outcome {
    fn into_py(self, py: Python<'_>) -> PyResult<CommandOut> {
        let ((a, b, c, d, e), v) = (self.0, self.1);
        Ok((a, b, c, d, e, v.to_py(py)?))
    }
}

fn command_out(out: &exactlti::api::Outcome) -> FResult<Outcome> {
    let text =
        serde_json::to_string(&out.report.to_json()).map_err(|e| Fail::Input(e.to_string()))?;
    Ok(Outcome(
        (
            text,
            out.verified,
            !out.float_disagrees,
            out.report.to_latex_math(),
            out.report.to_html(),
        ),
        values::report_values(&out.report),
    ))
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

/// Reads a system file (JSON or TOML, chosen by extension) as the command line does (a
/// file with only `D` is the static gain `y = D u`):
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
        Ok(exactlti::api::System::open_or_gain(
            Path::new(&path),
            &opts,
        )?)
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

/// Connection by signal names (python-control's `interconnect`): `connections` as
/// `[input, output, -output, ...]`, external `inputs` and `outputs` by name.
#[pyfunction]
#[pyo3(signature = (systems, connections, inputs, outputs, max_seconds=None))]
fn connect_names(
    py: Python<'_>,
    systems: Vec<PyRef<'_, System>>,
    connections: Vec<Vec<String>>,
    inputs: Vec<String>,
    outputs: Vec<String>,
    max_seconds: Option<f64>,
) -> PyResult<System> {
    let all: Vec<_> = systems.iter().map(|s| s.api.clone()).collect();
    let c = exactlti::api::NamedConnection {
        connections,
        inputs,
        outputs,
    };
    let s = run(py, max_seconds, move || {
        let refs: Vec<&exactlti::api::System> = all.iter().map(|s| s.as_ref()).collect();
        Ok(exactlti::api::connect_named(&refs, &c)?)
    })?;
    Ok(System::new(s))
}

#[pymodule]
fn _core(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<System>()?;
    m.add_function(wrap_pyfunction!(connect_names, m)?)?;
    m.add_function(wrap_pyfunction!(load_json, m)?)?;
    m.add_function(wrap_pyfunction!(load_file, m)?)?;
    m.add_function(wrap_pyfunction!(study::sweep, m)?)?;
    m.add_function(wrap_pyfunction!(study::execute, m)?)?;
    m.add_function(wrap_pyfunction!(_panic_for_test, m)?)?;
    m.add_function(wrap_pyfunction!(_sleep_for_test, m)?)?;
    m.add("UnsupportedError", m.py().get_type::<UnsupportedError>())?;
    m.add("VerificationError", m.py().get_type::<VerificationError>())?;
    Ok(())
}
