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
use compat::{Loaded, Typed, from_loaded};
use exactlti::field::{Field, Q, Rational};
use exactlti::matrix::Matrix;
use exactlti::poly::Poly;
use exactlti::realization::{self, MinrealMethod};
use exactlti::report::{MatrixOut, Report};
use num_bigint::BigInt;
use num_traits::ToPrimitive;
use pyo3::create_exception;
use pyo3::exceptions::{PyRuntimeError, PyTimeoutError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyTuple};
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

// ---------------------------------------------------------------- plain output data

/// A value to be turned into Python objects on the caller's thread (the worker has no GIL).
enum Out {
    None,
    Bool(bool),
    Int(i64),
    Big(BigInt),
    Float(f64),
    Str(String),
    List(Vec<Out>),
    Tuple(Vec<Out>),
    Dict(Vec<(&'static str, Out)>),
    Sys(Arc<Sys>),
}

impl Out {
    fn to_py(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
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
            Out::Sys(s) => Py::new(py, System { inner: s.clone() })?.into_any(),
        })
    }
}

fn int(n: &BigInt) -> Out {
    match n.to_i64() {
        Some(v) => Out::Int(v),
        None => Out::Big(n.clone()),
    }
}

fn usize_out(n: usize) -> Out {
    Out::Int(n as i64)
}

/// A rational as `(numerator, denominator)`.
fn q(r: &Rational) -> Out {
    Out::Tuple(vec![int(r.numer()), int(r.denom())])
}

fn strs(rows: &[Vec<String>]) -> Out {
    Out::List(
        rows.iter()
            .map(|r| Out::List(r.iter().map(|s| Out::Str(s.clone())).collect()))
            .collect(),
    )
}

fn approx_rows(rows: &[Vec<(f64, f64)>]) -> Out {
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

/// A matrix: `q` = rows of integer pairs when every entry is rational, else `exact`,
/// `latex` (strings) and `approx` (pairs re, im).
fn mat<K: Field>(m: &Matrix<K>) -> Out {
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
            let mo = MatrixOut::from_matrix(m);
            kv.push(("exact", strs(&mo.exact)));
            kv.push(("latex", strs(&mo.latex)));
            kv.push(("approx", approx_rows(&mo.approx)));
        }
    }
    Out::Dict(kv)
}

/// A matrix whose entries lie in several fields (exact strings with per-root symbols).
fn matout(mo: &MatrixOut) -> Out {
    Out::Dict(vec![
        ("nrows", usize_out(mo.nrows)),
        ("ncols", usize_out(mo.ncols)),
        ("exact", strs(&mo.exact)),
        ("latex", strs(&mo.latex)),
        ("approx", approx_rows(&mo.approx)),
    ])
}

/// Polynomial: `q` coefficients low degree first when rational, and its text in `s`.
fn poly<K: Field>(p: &Poly<K>) -> Out {
    let k = p.field();
    let rat: Option<Vec<Out>> = p
        .coeffs()
        .iter()
        .map(|c| k.to_rational(c).map(|r| q(&r)))
        .collect();
    Out::Dict(vec![
        ("q", rat.map(Out::List).unwrap_or(Out::None)),
        ("text", Out::Str(p.to_string_var("s"))),
    ])
}

/// The polynomial over Q when every coefficient is rational.
fn poly_q<K: Field>(p: &Poly<K>) -> Option<Poly<Q>> {
    let k = p.field();
    let c: Option<Vec<Rational>> = p.coeffs().iter().map(|c| k.to_rational(c)).collect();
    c.map(|c| Poly::new(Q, c))
}

fn report(r: &Report) -> Out {
    Out::Str(r.to_json().to_string())
}

fn alg(n: &exactlti::algebraic::AlgebraicNumber, mult: usize) -> Out {
    let (re, im) = n.approx();
    Out::Dict(vec![
        ("minpoly", poly(n.minpoly())),
        ("value", Out::Str(n.value_string())),
        ("approx", Out::Tuple(vec![Out::Float(re), Out::Float(im)])),
        ("multiplicity", usize_out(mult)),
    ])
}

// ---------------------------------------------------------------- systems

/// A system over its ground field, as the library's reader typed it.
#[allow(clippy::large_enum_variant)]
pub enum Sys {
    Q(String, Typed<Q>),
    Quadratic(String, Typed<exactlti::field::QuadraticField>),
}

macro_rules! over {
    ($s:expr, |$t:ident| $body:expr) => {
        match &*$s {
            Sys::Q(_, $t) => $body,
            Sys::Quadratic(_, $t) => $body,
        }
    };
}

impl Sys {
    fn from_loaded(l: Loaded) -> Self {
        match l {
            Loaded::Q(g, t) => Sys::Q(g, t),
            Loaded::Quadratic(g, t) => Sys::Quadratic(g, t),
        }
    }
    fn rational(&self, what: &str) -> FResult<&Typed<Q>> {
        match self {
            Sys::Q(_, t) => Ok(t),
            Sys::Quadratic(g, _) => Err(Fail::Unsupported(format!(
                "{what} needs rational matrices; this system's entries lie in {g}"
            ))),
        }
    }
}

/// An exact state-space system (standard form; a descriptor system is converted on input).
#[pyclass(frozen, module = "exactlti._core")]
pub struct System {
    inner: Arc<Sys>,
}

fn typed_system<K: Field>(t: &Typed<K>) -> Out {
    let s = &t.ss;
    Out::Dict(vec![
        ("A", mat(&s.a)),
        ("B", mat(&s.b)),
        ("C", mat(&s.c)),
        ("D", mat(&s.d)),
        (
            "E",
            t.descriptor
                .as_ref()
                .map(|d| mat(&d.e))
                .unwrap_or(Out::None),
        ),
        (
            "descriptor_A",
            t.descriptor
                .as_ref()
                .map(|d| mat(&d.a))
                .unwrap_or(Out::None),
        ),
    ])
}

fn minreal_typed<K: Field>(t: &Typed<K>, m: MinrealMethod) -> FResult<Out>
where
    Sys: From<(String, Typed<K>)>,
{
    let r = realization::minimal(&t.ss, m)?;
    let sys = Sys::from((
        String::new(),
        Typed {
            descriptor: None,
            a_raw: r.system.a.clone(),
            ss: r.system.clone(),
        },
    ));
    Ok(Out::Dict(vec![
        ("system", Out::Sys(Arc::new(sys))),
        ("order", usize_out(r.order)),
        ("original_order", usize_out(r.original_order)),
        ("method", Out::Str(r.method.name().to_string())),
        ("T", r.t.as_ref().map(mat).unwrap_or(Out::None)),
        ("verified", Out::Bool(r.verified)),
        ("report", report(&r.report())),
    ]))
}

impl From<(String, Typed<Q>)> for Sys {
    fn from((_, t): (String, Typed<Q>)) -> Self {
        Sys::Q("QQ".into(), t)
    }
}

impl From<(String, Typed<exactlti::field::QuadraticField>)> for Sys {
    fn from((_, t): (String, Typed<exactlti::field::QuadraticField>)) -> Self {
        let g = t.ss.a.field().to_string();
        Sys::Quadratic(g, t)
    }
}

fn scb_typed<K: Field>(t: &Typed<K>) -> FResult<Out> {
    let s = &t.ss;
    let r = exactlti::structure::scb::scb(&s.a, &s.b, &s.c, &s.d)?;
    let mp = r.minimum_phase();
    Ok(Out::Dict(vec![
        ("A", mat(&r.a)),
        ("B", mat(&r.b)),
        ("C", mat(&r.c)),
        ("D", mat(&r.d)),
        ("Gamma1", mat(&r.gamma1)),
        ("Gamma2", mat(&r.gamma2)),
        ("Gamma3", mat(&r.gamma3)),
        ("U", mat(&r.u_pre)),
        ("Y", mat(&r.y_pre)),
        (
            "dims",
            Out::List(r.dims.iter().map(|&d| usize_out(d)).collect()),
        ),
        (
            "chains",
            Out::List(r.chains.iter().map(|&d| usize_out(d)).collect()),
        ),
        ("m0", usize_out(r.m0)),
        ("left_invertible", Out::Bool(r.left_invertible)),
        ("right_invertible", Out::Bool(r.right_invertible)),
        ("zero_polynomial", poly(&r.invariant_zero_polynomial())),
        ("minimum_phase", mp.map(Out::Bool).unwrap_or(Out::None)),
        ("verified", Out::Bool(r.verified)),
        ("report", report(&r.report())),
    ]))
}

fn zeros_typed<K: Field>(t: &Typed<K>) -> FResult<Out> {
    let s = &t.ss;
    let z = exactlti::structure::zeros::invariant_zeros(&s.a, &s.b, &s.c, &s.d)?;
    let rat = poly_q(&z.polynomial);
    let roots = match rat {
        Some(p) if !p.is_zero() && p.deg() > 0 => Out::List(
            exactlti::algebraic::roots(&p)?
                .iter()
                .map(|(n, m)| alg(n, *m))
                .collect(),
        ),
        Some(_) => Out::List(vec![]),
        None => Out::None,
    };
    Ok(Out::Dict(vec![
        ("polynomial", poly(&z.polynomial)),
        ("normal_rank", usize_out(z.normal_rank)),
        ("count", usize_out(z.count())),
        ("roots", roots),
        ("report", report(&z.report())),
    ]))
}

fn tf_typed<K: Field>(t: &Typed<K>) -> FResult<Out> {
    let g = t.ss.transfer_matrix()?;
    Ok(Out::List(
        g.entries
            .iter()
            .map(|row| {
                Out::List(
                    row.iter()
                        .map(|h| Out::Tuple(vec![poly(&h.num), poly(&h.den)]))
                        .collect(),
                )
            })
            .collect(),
    ))
}

fn to_dmatrix<K: Field>(m: &Matrix<K>) -> FResult<nalgebra::DMatrix<f64>> {
    let a = m.to_approx_complex();
    if a.iter().flatten().any(|(_, im)| *im != 0.0) {
        return Err(Fail::Unsupported(
            "unsupported: the frequency response needs real matrices".into(),
        ));
    }
    Ok(nalgebra::DMatrix::from_fn(m.nrows(), m.ncols(), |i, j| {
        a[i][j].0
    }))
}

fn freqresp_typed<K: Field>(t: &Typed<K>, omega: &[f64]) -> FResult<Out> {
    let s = &t.ss;
    let [a, b, c, d] = [&s.a, &s.b, &s.c, &s.d].map(to_dmatrix);
    let hz: Vec<f64> = omega
        .iter()
        .map(|w| w / (2.0 * std::f64::consts::PI))
        .collect();
    let g = exactlti::float::freqresp(&a?, &b?, &c?, &d?, &hz)?;
    Ok(Out::List(
        g.iter()
            .map(|m| {
                Out::List(
                    (0..m.nrows())
                        .map(|i| {
                            Out::List(
                                (0..m.ncols())
                                    .map(|j| {
                                        Out::Tuple(vec![
                                            Out::Float(m[(i, j)].re),
                                            Out::Float(m[(i, j)].im),
                                        ])
                                    })
                                    .collect(),
                            )
                        })
                        .collect(),
                )
            })
            .collect(),
    ))
}

fn jordan_out(jf: &exactlti::jordan::JordanForm, real: bool) -> FResult<Out> {
    let evs = Out::List(
        jf.eigenvalues
            .iter()
            .map(|e| {
                Out::Dict(vec![
                    ("minpoly", poly(&e.minpoly)),
                    ("value", Out::Str(e.value.clone())),
                    (
                        "approx",
                        Out::Tuple(vec![Out::Float(e.approx.0), Out::Float(e.approx.1)]),
                    ),
                    ("symbol", Out::Str(e.symbol.clone())),
                    (
                        "algebraic_multiplicity",
                        usize_out(e.algebraic_multiplicity),
                    ),
                    (
                        "geometric_multiplicity",
                        usize_out(e.geometric_multiplicity),
                    ),
                    (
                        "blocks",
                        Out::List(e.blocks.iter().map(|&b| usize_out(b)).collect()),
                    ),
                ])
            })
            .collect(),
    );
    let mut kv = vec![
        ("eigenvalues", evs),
        ("charpoly", poly(&jf.charpoly)),
        ("A", mat(&jf.a)),
    ];
    if real {
        let rf = jf.real_form()?;
        let (j, t) = rf.j_t_out();
        kv.push(("J", matout(&j)));
        kv.push(("T", matout(&t)));
        kv.push(("exact", Out::Bool(rf.exact)));
        kv.push(("verified", Out::Bool(rf.verified)));
        kv.push((
            "notes",
            Out::List(rf.notes.iter().map(|s| Out::Str(s.clone())).collect()),
        ));
        kv.push(("report", report(&rf.report())));
    } else {
        let (j, t) = match jf.single_field() {
            Some((j, t)) if j.field().degree() == 1 => (mat(&j), mat(&t)),
            _ => {
                let (j, t) = jf.j_t_out();
                (matout(&j), matout(&t))
            }
        };
        kv.push(("J", j));
        kv.push(("T", t));
        kv.push(("exact", Out::Bool(true)));
        kv.push(("verified", Out::Bool(jf.verified)));
        kv.push(("notes", Out::List(vec![])));
        kv.push(("report", report(&jf.report())));
    }
    Ok(Out::Dict(kv))
}

fn truth(t: exactlti::float::Truth) -> Out {
    Out::Str(format!("{t:?}"))
}

fn check_typed<K: Field>(t: &Typed<K>) -> FResult<Out> {
    use exactlti::float::{self, Tol};
    let s = &t.ss;
    let [a, b, c, d] = [&s.a, &s.b, &s.c, &s.d].map(to_dmatrix);
    let (a, b, c, d) = (a?, b?, c?, d?);
    let tol = Tol::default();
    let item = |name: &str, exact: Out, fl: Out, tr: Out, agree: bool| {
        Out::Dict(vec![
            ("what", Out::Str(name.to_string())),
            ("exact", exact),
            ("float", fl),
            ("float_truth", tr),
            ("agree", Out::Bool(agree)),
        ])
    };
    let mut items = vec![];
    let exact_min = realization::minimal(s, MinrealMethod::Kalman)?;
    let fm = float::minreal(&a, &b, &c, &d, &tol)?;
    items.push(item(
        "mcmillan_degree",
        usize_out(exact_min.order),
        usize_out(fm.order),
        truth(fm.truth),
        exact_min.order == fm.order,
    ));
    let rc = realization::controllability_matrix(&s.a, &s.b).rank();
    let frc = float::controllability_rank(&a, &b, &tol)?;
    items.push(item(
        "controllability_rank",
        usize_out(rc),
        usize_out(frc.rank),
        truth(frc.truth),
        rc == frc.rank,
    ));
    let ro = realization::observability_matrix(&s.a, &s.c).rank();
    let fro = float::observability_rank(&a, &c, &tol)?;
    items.push(item(
        "observability_rank",
        usize_out(ro),
        usize_out(fro.rank),
        truth(fro.truth),
        ro == fro.rank,
    ));
    // eigenvalues: the float ones matched to the exact ones (greedy nearest)
    let fe = float::eigenvalues(&a)?;
    let exact_ev: Option<Vec<(f64, f64)>> = exactlti::matrix::to_rational_matrix(&s.a)
        .map(|aq| -> FResult<Vec<(f64, f64)>> {
            let p = aq.charpoly()?;
            let mut v = vec![];
            if p.deg() > 0 {
                for (n, m) in exactlti::algebraic::roots(&p)? {
                    for _ in 0..m {
                        v.push(n.approx());
                    }
                }
            }
            Ok(v)
        })
        .transpose()?;
    if let Some(ev) = exact_ev {
        let mut used = vec![false; fe.len()];
        let mut worst = 0.0f64;
        for (re, im) in &ev {
            let mut best = (f64::INFINITY, usize::MAX);
            for (j, z) in fe.iter().enumerate() {
                let dist = ((z.re - re).powi(2) + (z.im - im).powi(2)).sqrt();
                if !used[j] && dist < best.0 {
                    best = (dist, j);
                }
            }
            if best.1 != usize::MAX {
                used[best.1] = true;
                worst = worst.max(best.0);
            }
        }
        items.push(Out::Dict(vec![
            ("what", Out::Str("max_eigenvalue_error".into())),
            ("exact", Out::Float(0.0)),
            ("float", Out::Float(worst)),
            ("float_truth", Out::None),
            ("agree", Out::Bool(worst <= 1e-6)),
        ]));
    }
    Ok(Out::List(items))
}

fn method_of(name: &str) -> FResult<MinrealMethod> {
    Ok(match name {
        "kalman" => MinrealMethod::Kalman,
        "rosenbrock" => MinrealMethod::Rosenbrock,
        "ho-kalman" | "ho_kalman" | "hokalman" => MinrealMethod::HoKalman,
        other => {
            return Err(Fail::Input(format!(
                "unknown method '{other}' (kalman, rosenbrock, ho-kalman, jordan)"
            )));
        }
    })
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
            Sys::Q(g, _) | Sys::Quadratic(g, _) => g.clone(),
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
            over!(s, |t| minreal_typed(t, m))
        })?;
        out.to_py(py)
    }

    #[pyo3(signature = (max_seconds=None))]
    fn scb(&self, py: Python<'_>, max_seconds: Option<f64>) -> PyResult<Py<PyAny>> {
        let s = self.inner.clone();
        run(py, max_seconds, move || over!(s, |t| scb_typed(t)))?.to_py(py)
    }

    #[pyo3(signature = (max_seconds=None))]
    fn zeros(&self, py: Python<'_>, max_seconds: Option<f64>) -> PyResult<Py<PyAny>> {
        let s = self.inner.clone();
        run(py, max_seconds, move || over!(s, |t| zeros_typed(t)))?.to_py(py)
    }

    /// Roots of the characteristic polynomial of `A` with multiplicities.
    #[pyo3(signature = (max_seconds=None))]
    fn poles(&self, py: Python<'_>, max_seconds: Option<f64>) -> PyResult<Py<PyAny>> {
        let s = self.inner.clone();
        run(py, max_seconds, move || {
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
                Sys::Q(_, t) => exactlti::jordan::jordan(&t.a_raw)?,
                Sys::Quadratic(_, t) => exactlti::jordan::jordan_quadratic(&t.a_raw)?,
            };
            jordan_out(&jf, real)
        })?
        .to_py(py)
    }

    #[pyo3(signature = (max_seconds=None))]
    fn mnf(&self, py: Python<'_>, max_seconds: Option<f64>) -> PyResult<Py<PyAny>> {
        let s = self.inner.clone();
        run(py, max_seconds, move || {
            let t = s.rational("the mechanical normal form")?;
            let ss = &t.ss;
            let r = exactlti::structure::mechanical::mechanical_normal_form(
                &ss.a, &ss.b, &ss.c, &ss.d,
            )?;
            let mut kv = vec![
                ("exists", Out::Bool(r.exists)),
                (
                    "reason",
                    r.reason.clone().map(Out::Str).unwrap_or(Out::None),
                ),
                ("verified", Out::Bool(r.verified)),
                ("report", report(&r.report())),
            ];
            if let Some(f) = &r.form {
                kv.push(("M", mat(&f.mass)));
                kv.push(("L", mat(&f.damping)));
                kv.push(("K", mat(&f.stiffness)));
                kv.push(("F", mat(&f.input)));
                kv.push(("C", mat(&f.output)));
                kv.push(("D", mat(&f.feedthrough)));
                kv.push(("T", mat(&f.t)));
                kv.push(("A_tilde", mat(&f.a_tilde)));
                kv.push(("B_tilde", mat(&f.b_tilde)));
            }
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
        run(py, max_seconds, move || over!(s, |t| tf_typed(t)))?.to_py(py)
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
        run(py, max_seconds, move || over!(s, |t| check_typed(t)))?.to_py(py)
    }

    /// Frequency response `C (j w I - A)^{-1} B + D` in floating point, `omega` in rad/s.
    fn freqresp(&self, py: Python<'_>, omega: Vec<f64>) -> PyResult<Py<PyAny>> {
        let s = self.inner.clone();
        run(py, None, move || over!(s, |t| freqresp_typed(t, &omega)))?.to_py(py)
    }
}

/// Reads a system from JSON text (the system-file format; `name` is used in messages).
#[pyfunction]
fn load_json(py: Python<'_>, text: String, name: String) -> PyResult<System> {
    let l = run(py, None, move || {
        let l = exactlti::io::load_system_str(&text, exactlti::io::SystemFormat::Json, &name)?;
        from_loaded(l).map_err(Fail::Unsupported)
    })?;
    Ok(System {
        inner: Arc::new(Sys::from_loaded(l)),
    })
}

/// Reads a system file (JSON or TOML, chosen by extension).
#[pyfunction]
fn load_file(py: Python<'_>, path: String) -> PyResult<System> {
    let l = run(py, None, move || {
        let l = exactlti::io::load_system_path(Path::new(&path))?;
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
    m.add_function(wrap_pyfunction!(_panic_for_test, m)?)?;
    m.add_function(wrap_pyfunction!(_sleep_for_test, m)?)?;
    m.add("UnsupportedError", m.py().get_type::<UnsupportedError>())?;
    m.add("VerificationError", m.py().get_type::<VerificationError>())?;
    Ok(())
}
