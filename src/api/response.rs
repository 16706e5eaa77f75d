//! `response FILE --x0 ...` (the free response $x(t) = e^{At} x_0$ in closed form, exact over
//! every numeric field ($\mathbb{Q}$, $\mathbb{Q}(\sqrt d)$, $\mathbb{Q}(i)$: `--x0` in the
//! system's field, `--times` the exact terms embedded by the field's `approx`, with the
//! imaginary parts when $A$ or $x_0$ is not real) and in symbols over $\mathbb{Q}(p)$) and `contributions FILE [--keep K]` (the
//! modes ranked by contribution, minimal-realizations paper eq. 33, and the truncation with
//! its exact error): thin wrappers over [`crate::jordan::StateResponse`],
//! [`crate::jordan::JordanForm::free_response`] over [`crate::jordan::jordan_qp`] and
//! [`crate::realization::contribution`].
//!
//! An initial state with symbols (`--x0 "y0, psi0, v0, r0"`) moves the computation to
//! $\mathbb{Q}(p)$ with those symbols added to the file's: the Jordan paper's eq. 36-37 in
//! symbols. (Its eq. 36 prints the $t^2$ term of $y$ as $+r_0 u t^2/2$; the closed form, and
//! its own eq. 37a, give $-r_0 u t^2/2$: a sign slip in eq. 36.)

use super::common::with_path;
use super::ground::numeric;
use super::{Failure, Outcome};
use crate::field::ElemDisplay;
use crate::io::{GroundField, NumericField, SystemFile, TypedSystem};
use crate::jordan::jordan_over;
use crate::jordan::jordan_qp;
use crate::matrix::Matrix;
use crate::ratfunc::RatFuncField;
use crate::realization::contribution::{contributions_in, contributions_qp};
use crate::report::sections::response as rep;
use clap::Subcommand;
use std::path::{Path, PathBuf};

/// The response commands.
#[derive(Subcommand, Debug, Clone)]
pub enum ResponseCmd {
    /// Free response x(t) = e^(At) x0 in closed form: sum over eigenvalues s and powers k of
    /// t^k e^(s t) g, each g exact; checked exactly (x' = A x term by term, x(0) = x0). Over
    /// Q(p) (symbols in the file or in --x0) when every eigenvalue lies in Q(p).
    Response {
        /// System file (JSON or TOML; see "FILE" in `exactlti --help`).
        file: PathBuf,
        /// Initial state: n comma-separated exact numbers of the system's field (`1, 0, -1/2`;
        /// `1 + sqrt(2)`, `i` over Q(sqrt 2), Q(i)), or expressions in the
        /// file's parameters and new symbols (`y0, psi0, v0, r0`: the response in symbols).
        #[arg(long, value_name = "X0", allow_hyphen_values = true)]
        x0: String,
        /// Also evaluate x(t) (float) at these times in seconds (`0,0.5,1`; x0 in numbers).
        #[arg(long, value_name = "T1,T2,...")]
        times: Option<String>,
    },
    /// Modes ranked by contribution (minimal-realizations paper eq. 33): exact H2 norm^2 of each
    /// mode's part and its residues C G_k B; with --keep K the truncated realization over Q and
    /// its exact error (H2^2, DC gain, C B of the dropped part).
    Contributions {
        /// System file (JSON or TOML; see "FILE" in `exactlti --help`).
        file: PathBuf,
        /// Keep the K heaviest modes (a mode: one irreducible factor of the characteristic
        /// polynomial, so the truncation stays over Q).
        #[arg(long, value_name = "K")]
        keep: Option<usize>,
    },
}

impl ResponseCmd {
    /// The command's name as typed.
    pub fn name(&self) -> &'static str {
        match self {
            ResponseCmd::Response { .. } => "response",
            ResponseCmd::Contributions { .. } => "contributions",
        }
    }
    /// The system file.
    pub fn file(&self) -> &Path {
        match self {
            ResponseCmd::Response { file, .. } | ResponseCmd::Contributions { file, .. } => file,
        }
    }
}

/// The comma-separated entries of `--x0` (`n` of them).
fn entries(text: &str, n: usize, path: &Path) -> Result<Vec<String>, Failure> {
    let xs: Vec<String> = text.split(',').map(|s| s.trim().to_string()).collect();
    if xs.len() != n || xs.iter().any(String::is_empty) {
        return Err(Failure::input(format!(
            "{}: --x0 needs {n} comma-separated entries (the state has {n}), got {}",
            path.display(),
            xs.iter().filter(|x| !x.is_empty()).count()
        )));
    }
    Ok(xs)
}

/// Symbols in the entries (identifiers), in order of appearance.
fn symbols(xs: &[String]) -> Result<Vec<String>, Failure> {
    let mut out: Vec<String> = vec![];
    for x in xs {
        let ids = crate::mpoly::parse::identifiers(x)
            .map_err(|e| Failure::input(format!("--x0 entry \"{x}\": {e}")))?;
        for id in ids {
            if !out.contains(&id) {
                out.push(id);
            }
        }
    }
    Ok(out)
}

/// `--times`: finite numbers.
fn times(text: Option<&str>) -> Result<Vec<f64>, Failure> {
    let Some(text) = text else { return Ok(vec![]) };
    text.split(',')
        .map(|s| {
            let s = s.trim();
            s.parse::<f64>()
                .ok()
                .filter(|t| t.is_finite())
                .ok_or_else(|| Failure::input(format!("--times: '{s}' is not a finite number")))
        })
        .collect()
}

/// Runs a response command on a system over an exact field without symbols: the one
/// computation over the system's numeric field ($\mathbb{Q}$, $\mathbb{Q}(\sqrt d)$,
/// $\mathbb{Q}(i)$); `--x0` in that field, or with symbols of its own (over $\mathbb{Q}$:
/// the response in symbols).
pub(super) fn run<K: GroundField>(
    cmd: &ResponseCmd,
    _f: &SystemFile,
    t: &TypedSystem<K>,
    path: &Path,
) -> Result<Outcome, Failure> {
    let t = numeric(t, cmd.name(), path)?;
    run_over(cmd, &t.ss, path)
}

fn run_over<F: NumericField>(
    cmd: &ResponseCmd,
    ss: &crate::system::StateSpace<F>,
    path: &Path,
) -> Result<Outcome, Failure> {
    let e = |err| with_path(path, err);
    let k = ss.field();
    match cmd {
        ResponseCmd::Contributions { keep, .. } => {
            let c = contributions_in(ss, jordan_over(&ss.a).map_err(e)?).map_err(e)?;
            let tr = match keep {
                Some(k) => Some(c.truncate(*k).map_err(e)?),
                None => None,
            };
            let r = rep::contributions_report(&c, tr.as_ref());
            let ok = c.verified && tr.as_ref().is_none_or(|t| t.verified);
            Ok(Outcome::new(r, ok))
        }
        ResponseCmd::Response { x0, times: ts, .. } => {
            let n = ss.nstates();
            let xs = entries(x0, n, path)?;
            // symbols of its own (not `i`, `sqrt`): the response in symbols
            let reserved = crate::field::expr::lex::reserved_meaning;
            let own = symbols(&xs).is_ok_and(|s| s.iter().any(|s| reserved(s).is_none()));
            if own {
                let a: Vec<String> = ss.a.as_slice().iter().map(|x| k.fmt_elem(x)).collect();
                return symbolic_response(&[], (n, a), &xs, path);
            }
            let x0m = x0_column(k, &xs)?;
            let jf = jordan_over(&ss.a).map_err(e)?;
            let sr = jf.free_response().from_state(&x0m);
            let ok = jf.verified && sr.verify(&jf, &x0m);
            // real when A and x0 equal their conjugates (exactly): then x(t) is real
            let real =
                ss.a.as_slice()
                    .iter()
                    .chain(x0m.as_slice())
                    .all(|x| k.conj(x).as_ref() == Some(x));
            let values: Vec<rep::TimeValue> = times(ts.as_deref())?
                .into_iter()
                .map(|t| {
                    let z = sr.evaluate_complex(&jf, t);
                    let re = z.iter().map(|z| z.re).collect();
                    let im = (!real).then(|| z.iter().map(|z| z.im).collect());
                    (t, re, im)
                })
                .collect();
            Ok(Outcome::new(
                rep::state_response_report(&jf, &sr, &x0m, &values, ok),
                ok,
            ))
        }
    }
}

/// The entries of `--x0` as a column over `k`, each read in the field
/// ([`GroundField::parse_elem`]).
fn x0_column<K: GroundField>(k: &K, xs: &[String]) -> Result<Matrix<K>, Failure> {
    let vals = xs
        .iter()
        .map(|x| {
            k.parse_elem(x)
                .map_err(|m| Failure::input(format!("--x0 entry \"{x}\": {m}")))
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(Matrix::column(k.clone(), vals))
}

/// Runs a response command on a system over $\mathbb{Q}(p)$.
pub(super) fn run_symbolic(
    cmd: &ResponseCmd,
    t: &TypedSystem<RatFuncField>,
    path: &Path,
) -> Result<Outcome, Failure> {
    match cmd {
        ResponseCmd::Contributions { keep, .. } => {
            let e = |err| with_path(path, err);
            let c = contributions_qp(&t.ss).map_err(e)?;
            if let Some(k) = keep {
                // refused unless every weight was compared exactly
                let tr = c.truncate(*k).map_err(e)?;
                let ok = c.verified && tr.verified;
                let r = rep::contributions_report_qp(&c).obj(
                    "truncation",
                    crate::report::Report::new()
                        .int("order", tr.system.a.nrows())
                        .matrices(&[
                            ("A", &tr.system.a),
                            ("B", &tr.system.b),
                            ("C", &tr.system.c),
                        ])
                        .bool("verified", tr.verified),
                );
                return Ok(Outcome::new(r, ok));
            }
            Ok(Outcome::new(rep::contributions_report_qp(&c), c.verified))
        }
        ResponseCmd::Response { x0, times, .. } => {
            if times.is_some() {
                return Err(Failure::unsupported(format!(
                    "{}: --times evaluates numbers, this system's entries lie in {}; give every \
                     symbol a value with --at",
                    path.display(),
                    t.a_raw.field()
                )));
            }
            let (a, k0) = (&t.ss.a, t.ss.a.field());
            let xs = entries(x0, a.nrows(), path)?;
            let text = a.as_slice().iter().map(|x| k0.fmt_elem(x)).collect();
            symbolic_response(k0.vars(), (a.nrows(), text), &xs, path)
        }
    }
}

/// The closed form over $\mathbb{Q}(p)$, the field extended by the symbols of `xs`.
/// `a` is `n x n`, its entries as text in the symbols `vars0`.
fn symbolic_response(
    vars0: &[String],
    (n, a): (usize, Vec<String>),
    xs: &[String],
    path: &Path,
) -> Result<Outcome, Failure> {
    let e = |err| with_path(path, err);
    let mut vars: Vec<String> = vars0.to_vec();
    for s in symbols(xs)? {
        if !vars.contains(&s) {
            vars.push(s);
        }
    }
    let k = RatFuncField::new(&vars).map_err(e)?;
    let data: Vec<_> = a
        .iter()
        .map(|x| k.parse(x))
        .collect::<crate::error::Result<_>>()
        .map_err(e)?;
    let a = Matrix::from_vec(k.clone(), n, n, data);
    let x0: Vec<_> = xs
        .iter()
        .map(|x| {
            k.parse(x)
                .map_err(|err| Failure::input(format!("--x0 entry \"{x}\": {err}")))
        })
        .collect::<Result<_, _>>()?;
    let jf = jordan_qp(&a).map_err(e)?;
    if !jf.complete() {
        return Err(Failure::unsupported(format!(
            "{}: the closed form in symbols needs every eigenvalue in {}; here the characteristic \
             polynomial has an irreducible factor of degree > 1 over it (its roots are not \
             rational functions of the parameters); give every symbol a value with --at",
            path.display(),
            jf.base()
        )));
    }
    let x0m = Matrix::column(jf.base().clone(), x0.clone());
    let fr = jf.free_response().from_state(&x0m);
    let ok = jf.verified && fr.verify(&jf, &x0m);
    Ok(Outcome::new(
        rep::param_response_report(&jf, &fr, &x0, ok),
        ok,
    ))
}
