//! `--steps`: the derivation of `jordan` (also `--real`), `scb`, `zeros`, `tf`, `standard`,
//! `mnf` and of `minreal --method kalman|jordan|rosenbrock|ho-kalman`, step by step,
//! over $\mathbb{Q}$ and over $\mathbb{Q}(p)$ (files with symbols, `--symbolic`, `--at`).
//! A descriptor file (with `E`) is derived through its standard form: the steps of
//! `standard` first, then the command's on the standard system (what the command computes).
//! For `zeros` this is exact, not an approximation: the standard form comes from constant
//! invertible maps of the pencil and the elimination of its infinite part $I - sN$, which
//! is unimodular, so the Smith form of the system pencil and with it the finite invariant
//! zeros are unchanged; `jordan --real` is the real Jordan form of the finite dynamics, as
//! `jordan` is.
//!
//! The steps are computed by [`crate::jordan::steps`] and [`crate::realization::steps`] and
//! rendered by [`crate::report::steps`] (text, JSON) and [`crate::report::steps_latex`]
//! (LaTeX, written here directly: a derivation typesets as a worked example, not as a list).
//! Exit 1 when an identity of a step fails.

use super::{Command, Failure, Format, MethodArg, Outcome};
use crate::algebraic::NumberField;
use crate::field::Field;
use crate::field::Q;
use crate::io::TypedSystem;
use crate::io::symbolic::SymbolicOptions;
use crate::io::{GroundField, TypedAny};
use crate::jordan::derivation::{AssumptionLog, Derivation, Method, Recorder, ratfunc_log};
use crate::jordan::normalize::Normalization;
use crate::jordan::real_steps::lift_derivation;
use crate::report::steps::derivation_report;
use crate::report::steps_latex::derivation_latex;
use crate::system::{Descriptor, StateSpace};
use std::path::Path;

/// What `--steps` derives.
#[derive(Clone, Copy, PartialEq)]
enum What {
    Jordan,
    RealJordan(bool),
    Kalman,
    JordanMethod,
    Scb,
    Zeros,
    Tf,
    Rosenbrock,
    HoKalman,
    Standard,
    Mnf,
    /// `minreal --descriptor`.
    DescriptorMinimal,
    /// `contributions [--keep K]`.
    Contributions(Option<usize>),
    /// `response --x0 ...` (the free response).
    Response,
}

/// `--steps` for a case it does not cover (exit 2; Python's `UnsupportedError`).
fn refuse(message: String) -> Failure {
    Failure::unsupported(message)
}

const AVAILABLE: &str = "--steps: available for `jordan` (also --real), `scb`, `zeros`, `tf`, `standard`, `mnf`, `minreal --method kalman|jordan|rosenbrock|ho-kalman`, `minreal --descriptor`, `contributions` and `response` (not for `minreal --method era`)";

/// The file and the derivation `cmd` asks for.
fn what(cmd: &Command) -> Option<(&Path, What)> {
    Some(match cmd {
        Command::Jordan {
            file, real: false, ..
        } => (file, What::Jordan),
        Command::Jordan { file, expand, .. } => (file, What::RealJordan(*expand)),
        Command::Minreal {
            file,
            descriptor: true,
            ..
        } => (file, What::DescriptorMinimal),
        Command::Minreal { file, method, .. } => (
            file,
            match method {
                MethodArg::Kalman => What::Kalman,
                MethodArg::Jordan => What::JordanMethod,
                MethodArg::Rosenbrock => What::Rosenbrock,
                MethodArg::HoKalman => What::HoKalman,
                MethodArg::Era => return None,
            },
        ),
        Command::Scb { file } => (file, What::Scb),
        Command::Zeros { file } => (file, What::Zeros),
        Command::Tf { file } => (file, What::Tf),
        Command::Standard { file } => (file, What::Standard),
        Command::Mnf { file } => (file, What::Mnf),
        Command::Response(super::ResponseCmd::Contributions { file, keep }) => {
            (file, What::Contributions(*keep))
        }
        Command::Response(super::ResponseCmd::Response { file, .. }) => (file, What::Response),
        _ => return None,
    })
}

/// A recorder for `method`, with the assumption log over $\mathbb{Q}(p)$.
fn recorder<'a, K: Field>(
    method: Method,
    k: &K,
    log: Option<AssumptionLog<'a, K>>,
) -> Recorder<'a, K> {
    match log {
        Some(l) => Recorder::with_log(method, k.clone(), l),
        None => Recorder::new(method, k.clone()),
    }
}

/// The derivation of a system command over any field (with the assumption log over
/// $\mathbb{Q}(p)$).
fn system_steps<'a, K: Field>(
    ss: &StateSpace<K>,
    what: What,
    log: Option<AssumptionLog<'a, K>>,
) -> crate::error::Result<Derivation<K>> {
    let method = match what {
        What::Kalman => return crate::realization::steps::kalman_steps(ss, log),
        What::Scb => Method::Scb,
        What::Zeros => Method::Zeros,
        What::Tf => Method::Transfer,
        What::Rosenbrock => Method::Rosenbrock,
        What::HoKalman => Method::HoKalman,
        What::Mnf => Method::Mnf,
        _ => {
            return Err(crate::error::Error::Invalid(
                "internal: not a system derivation".into(),
            ));
        }
    };
    let mut rec = recorder(method, ss.field(), log);
    let r = Some(&mut rec);
    let (a, b, c, d) = (&ss.a, &ss.b, &ss.c, &ss.d);
    match what {
        What::Scb => drop(crate::structure::scb::scb_recorded(a, b, c, d, r)?),
        What::Zeros => drop(crate::structure::zeros::invariant_zeros_recorded(
            a, b, c, d, r,
        )?),
        What::Tf => drop(ss.transfer_matrix_recorded(r)?),
        What::Rosenbrock => drop(crate::realization::minimal_rosenbrock_recorded(ss, r)?),
        What::Mnf => drop(
            crate::structure::mechanical::mechanical_normal_form_recorded(
                None,
                [a, b, c, d],
                crate::structure::mechanical::DEFAULT_MAX_CANDIDATES,
                r,
            )?,
        ),
        _ => drop(crate::realization::minimal_ho_kalman_recorded(ss, r)?),
    }
    Ok(rec.finish())
}

/// The standard form of a descriptor system, step by step, and the standard system.
fn standard_steps<'a, K: Field>(
    d: &Descriptor<K>,
    log: Option<AssumptionLog<'a, K>>,
) -> crate::error::Result<(Derivation<K>, StateSpace<K>)> {
    let mut rec = recorder(Method::Standard, d.a.field(), log);
    let f = crate::realization::descriptor_to_standard_recorded(d, Some(&mut rec))?;
    Ok((rec.finish(), f.system))
}

/// The derivation of `what` for a system over any field, a descriptor system through its
/// standard form first (its steps, then the command's on the standard system).
fn any_steps<K: Field>(
    ss: &StateSpace<K>,
    descriptor: Option<&Descriptor<K>>,
    what: What,
    log: &dyn Fn() -> Option<AssumptionLog<'static, K>>,
) -> crate::error::Result<Derivation<K>> {
    let Some(d) = descriptor else {
        return system_steps(ss, what, log());
    };
    let (mut first, ss) = standard_steps(d, log())?;
    if what == What::Standard {
        return Ok(first);
    }
    let then = system_steps(&ss, what, log())?;
    first.method = then.method;
    first.steps.extend(then.steps);
    Ok(first)
}

/// Runs `cmd` with `--steps`; LaTeX is written to stdout here (the outcome is `streamed`).
pub fn execute(
    cmd: &Command,
    symbolic: Option<&str>,
    at: Option<&str>,
    format: Format,
    standalone: bool,
) -> Result<Outcome, Failure> {
    let Some((file, _)) = what(cmd) else {
        return Err(refuse(refusal(cmd)));
    };
    let opts = SymbolicOptions::from_args(symbolic, at).map_err(Failure::input)?;
    let render = Render { format, standalone };
    let sys = match super::System::open(file, &opts) {
        Ok(sys) => sys,
        Err(err) => {
            // an improper descriptor system: read as a descriptor system only
            return match what(cmd) {
                Some((_, What::DescriptorMinimal)) => {
                    descriptor_file(file, &render).unwrap_or_else(|| Err(Failure::from(err)))
                }
                _ => Err(Failure::from(err)),
            };
        }
    };
    derive(cmd, &sys, &render)
}

/// A derivation with every rendering built (the library's callers, the Python package):
/// the report (JSON data: `steps: [{step, sentence, <objects>, identity, holds, assumes}]`),
/// whether every identity held, the LaTeX fragment (a worked example) and HTML (math for
/// MathJax, as notebooks show it).
pub struct Steps {
    pub report: crate::report::Report,
    pub verified: bool,
    pub latex: String,
    pub html: String,
}

/// The derivation `cmd` asks for (`jordan`, `scb`, `minreal --method kalman`, ...: what
/// `--steps` accepts) of a system already read, every rendering built ([`Steps`]).
pub fn steps_on(cmd: &Command, sys: &super::System) -> Result<Steps, Failure> {
    derive(cmd, sys, &Strings)
}

/// What a derivation becomes: the command line's output, or [`Steps`].
trait Sink {
    type Out;
    fn show<K: Field>(&self, d: &Derivation<K>) -> Result<Self::Out, Failure>;
}

/// A sink that shows a derivation in the system's variable (`z` in discrete time).
struct InVariable<'a, S> {
    inner: &'a S,
    var: &'static str,
}

impl<S: Sink> Sink for InVariable<'_, S> {
    type Out = S::Out;
    fn show<K: Field>(&self, d: &Derivation<K>) -> Result<S::Out, Failure> {
        if d.variable == self.var {
            return self.inner.show(d);
        }
        let mut d = d.clone();
        d.variable = self.var;
        self.inner.show(&d)
    }
}

/// Every rendering as strings.
struct Strings;

impl Sink for Strings {
    type Out = Steps;
    fn show<K: Field>(&self, d: &Derivation<K>) -> Result<Steps, Failure> {
        Ok(Steps {
            report: derivation_report(d),
            verified: d.verified(),
            latex: derivation_latex(d, false),
            html: crate::report::steps_html::derivation_html(d),
        })
    }
}

/// Why `--steps` refuses `cmd` (`None`: the general list of what it derives).
fn refusal(cmd: &Command) -> String {
    match cmd {
        Command::Minreal {
            method: MethodArg::Era,
            ..
        } => "--steps: `minreal --method era` is the float path (an SVD of the Hankel matrix, identities only up to round-off), so it has no exact derivation; `minreal --method ho-kalman --steps` derives the exact rank factorization of the same Hankel matrix".into(),
        _ => AVAILABLE.into(),
    }
}

/// The derivation of `cmd` on `sys`, given to `out`.
fn derive<S: Sink>(cmd: &Command, sys: &super::System, out: &S) -> Result<S::Out, Failure> {
    let var = if sys.dt().is_some() { "z" } else { "s" };
    let out = &InVariable { inner: out, var };
    let Some((_, what)) = what(cmd) else {
        return Err(refuse(refusal(cmd)));
    };
    let file = sys.path();
    let norm = normalization(cmd)?;
    let loaded = sys.loaded();
    let e = |err: crate::error::Error| super::common::with_path(file, err);
    let descriptor = match &loaded.system {
        TypedAny::Rational(t) => t.descriptor.is_some(),
        TypedAny::Quadratic(t) => t.descriptor.is_some(),
        TypedAny::RatFunc(t) => t.descriptor.is_some(),
    };
    if !descriptor && what == What::Standard {
        return Err(refuse(format!(
            "{}: --steps for `standard` needs a descriptor system (a file with E); this one is already in standard form",
            path_text(file)
        )));
    }
    if what == What::DescriptorMinimal {
        return match &loaded.system {
            TypedAny::Rational(t) => {
                out.show(&desc_min(&t.ss, t.descriptor.as_ref(), None).map_err(e)?)
            }
            TypedAny::Quadratic(t) => {
                out.show(&desc_min(&t.ss, t.descriptor.as_ref(), None).map_err(e)?)
            }
            TypedAny::RatFunc(t) => {
                let k = t.ss.field().fresh();
                let t = t.in_field(&k);
                let log = Some(ratfunc_log(&k));
                out.show(&desc_min(&t.ss, t.descriptor.as_ref(), log).map_err(e)?)
            }
        };
    }
    match (&loaded.system, what) {
        (TypedAny::Rational(t), What::Contributions(keep)) if !descriptor => {
            let d = crate::realization::contribution_steps::contributions_steps(&t.ss, keep);
            out.show(&d.map_err(e)?)
        }
        (TypedAny::Rational(t), What::Response) if !descriptor => {
            let x0 = x0_column(cmd, t.ss.field(), t.ss.nstates())?;
            let d = crate::realization::contribution_steps::response_steps(&t.ss.a, &x0);
            out.show(&d.map_err(e)?)
        }
        (TypedAny::Quadratic(t), What::Contributions(keep)) if !descriptor => {
            let jf = crate::jordan::jordan_over(&t.ss.a).map_err(e)?;
            let d = crate::realization::contribution_steps::contributions_steps_in(&t.ss, jf, keep);
            out.show(&d.map_err(e)?)
        }
        (TypedAny::Quadratic(t), What::Response) if !descriptor => {
            let x0 = x0_column(cmd, t.ss.field(), t.ss.nstates())?;
            let jf = crate::jordan::jordan_over(&t.ss.a).map_err(e)?;
            out.show(&crate::realization::contribution_steps::response_steps_in(
                &jf, &x0,
            ))
        }
        (TypedAny::RatFunc(t), What::Contributions(keep)) if !descriptor => {
            let d = crate::realization::contribution_steps::contributions_steps_qp(&t.ss, keep);
            out.show(&d.map_err(e)?)
        }
        (TypedAny::RatFunc(t), What::Response) if !descriptor => {
            let x0 = x0_column(cmd, t.ss.field(), t.ss.nstates())?;
            let d = crate::realization::contribution_steps::response_steps_qp(&t.ss.a, &x0);
            out.show(&d.map_err(e)?)
        }
        (_, What::Contributions(_) | What::Response) => Err(refuse(format!(
            "{}: --steps for `contributions` and `response` derives a system without E (its standard form's A is what `response` integrates: derive `standard --steps` first); this file's entries lie in {}{}",
            path_text(file),
            loaded.file.ground,
            if descriptor { " and it has E" } else { "" }
        ))),
        (TypedAny::Rational(t), What::Jordan) => out.show(&jordan_q(t, &norm).map_err(e)?),
        (TypedAny::Rational(t), What::RealJordan(expand)) => {
            out.show(&real_jordan_q(t, expand).map_err(e)?)
        }
        (TypedAny::RatFunc(t), What::Jordan) => {
            let Some(d) = &t.descriptor else {
                let d = crate::jordan::steps::jordan_steps_params_with(&t.a_raw, &norm);
                return out.show(&d.map_err(e)?);
            };
            let (mut first, ss) = standard_steps(d, None).map_err(e)?;
            let then = crate::jordan::steps::jordan_steps_params_with(&ss.a, &norm).map_err(e)?;
            first.method = then.method;
            first.steps.extend(then.steps);
            out.show(&first)
        }
        (TypedAny::Rational(t), What::JordanMethod) => {
            let run = |ss: &StateSpace<Q>| crate::realization::steps::jordan_method_steps(ss);
            out.show(&through_standard(&t.ss, t.descriptor.as_ref(), None, run).map_err(e)?)
        }
        (TypedAny::RatFunc(t), What::JordanMethod) => {
            let k = t.ss.field().fresh();
            let t = t.in_field(&k);
            let run = crate::realization::steps::jordan_method_steps_qp;
            let log = || Some(ratfunc_log(&k));
            out.show(&through_standard(&t.ss, t.descriptor.as_ref(), log(), run).map_err(e)?)
        }
        (TypedAny::RatFunc(t), What::RealJordan(_)) => {
            let k = t.ss.field().fresh();
            let t = t.in_field(&k);
            let run = |ss: &StateSpace<_>| crate::jordan::real_steps::real_jordan_steps_qp(&ss.a);
            let log = || Some(ratfunc_log(&k));
            let d = match &t.descriptor {
                None => crate::jordan::real_steps::real_jordan_steps_qp(&t.a_raw),
                Some(d) => through_standard(&t.ss, Some(d), log(), run),
            };
            out.show(&d.map_err(e)?)
        }
        (_, What::Jordan | What::JordanMethod | What::RealJordan(_)) => Err(refuse(format!(
            "{}: --steps for this command needs rational entries or entries in QQ(p) (this file's lie in {})",
            path_text(file),
            loaded.file.ground,
        ))),
        (TypedAny::Rational(t), w) => {
            out.show(&any_steps(&t.ss, t.descriptor.as_ref(), w, &|| None).map_err(e)?)
        }
        (TypedAny::Quadratic(t), w) => {
            out.show(&any_steps(&t.ss, t.descriptor.as_ref(), w, &|| None).map_err(e)?)
        }
        (TypedAny::RatFunc(t), w) => {
            // a fresh field: its conditions are the ones this derivation assumes
            let k = t.ss.field().fresh();
            let t = t.in_field(&k);
            let log = || Some(ratfunc_log(&k));
            out.show(&any_steps(&t.ss, t.descriptor.as_ref(), w, &log).map_err(e)?)
        }
    }
}

/// The initial state of `response --x0 --steps`: $n$ entries, each an element of the
/// system's field `k` ([`GroundField::parse_elem`]: rational numbers over $\mathbb{Q}$,
/// radicals and `i` over $\mathbb{Q}(\sqrt d)$, expressions in the file's parameters over
/// $\mathbb{Q}(p)$).
fn x0_column<K: GroundField>(
    cmd: &Command,
    k: &K,
    n: usize,
) -> Result<crate::matrix::Matrix<K>, Failure> {
    let Command::Response(super::ResponseCmd::Response { x0, .. }) = cmd else {
        return Err(Failure::input("internal: not `response`".to_string()));
    };
    let xs: Vec<&str> = x0.split(',').map(str::trim).collect();
    if xs.len() != n {
        return Err(Failure::input(format!(
            "--x0 needs {n} comma-separated entries (the state has {n}), got {}",
            xs.len()
        )));
    }
    let hint = match k.symbolic() {
        Some(_) => format!(
            "--steps reads --x0 in the file's parameters {k}; new symbols: `response` without --steps"
        ),
        None => "--steps derives from exact numbers; the response in symbols is `response` without --steps".to_string(),
    };
    let vals = xs
        .iter()
        .map(|x| {
            k.parse_elem(x)
                .map_err(|m| Failure::unsupported(format!("--x0 entry \"{x}\": {m} ({hint})")))
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(crate::matrix::Matrix::column(k.clone(), vals))
}

/// The chains' normalisation `jordan --normalize` asks for (none for the other commands).
fn normalization(cmd: &Command) -> Result<Normalization, Failure> {
    match cmd {
        Command::Jordan {
            normalize: Some(n),
            real,
            ..
        } => {
            if *real {
                return Err(Failure::input(
                    "--normalize: applies to the chains of `jordan`, not to the real form of `jordan --real`".to_string(),
                ));
            }
            n.parse().map_err(Failure::input)
        }
        _ => Ok(Normalization::default()),
    }
}

/// `minreal --descriptor --steps`: the minimal descriptor realization step by step
/// ([`crate::realization::minimal_descriptor_recorded`]); a file without `E` is the
/// descriptor system with $E = I$ (as `minreal --descriptor` reads it).
fn desc_min<'a, K: Field>(
    ss: &StateSpace<K>,
    d: Option<&Descriptor<K>>,
    log: Option<AssumptionLog<'a, K>>,
) -> crate::error::Result<Derivation<K>> {
    let with_e;
    let d = match d {
        Some(d) => d,
        None => {
            let e = crate::matrix::Matrix::identity(ss.field().clone(), ss.nstates());
            with_e = Descriptor::new(e, ss.a.clone(), ss.b.clone(), ss.c.clone(), ss.d.clone())?;
            &with_e
        }
    };
    let mut rec = recorder(Method::DescriptorMinimal, d.a.field(), log);
    crate::realization::minimal_descriptor_recorded(d, Some(&mut rec))?;
    Ok(rec.finish())
}

/// `minreal --descriptor --steps` of a file the ordinary loader refuses (an improper
/// descriptor system), read as a descriptor system; `None` when it is not one.
fn descriptor_file(file: &Path, out: &Render) -> Option<Result<Outcome, Failure>> {
    struct Visit<'a>(&'a Path, &'a Render);
    impl crate::io::load_descriptor::DescriptorVisitor for Visit<'_> {
        type Output = Result<Outcome, Failure>;
        fn visit<K: GroundField>(
            self,
            _: &crate::io::load_descriptor::LoadedDescriptor,
            s: &Descriptor<K>,
            _: Option<&crate::io::load_descriptor::GivenTransfer<K>>,
        ) -> Self::Output {
            let e = |err| super::common::with_path(self.0, err);
            // a fresh field (over Q(p): its conditions are the ones this derivation assumes)
            let k = s.a.field().fresh();
            let m = |x: &crate::matrix::Matrix<K>| {
                crate::matrix::Matrix::from_vec(
                    k.clone(),
                    x.nrows(),
                    x.ncols(),
                    x.as_slice().to_vec(),
                )
            };
            let d = Descriptor::new(m(&s.e), m(&s.a), m(&s.b), m(&s.c), m(&s.d)).map_err(e)?;
            self.1.show(&der(&d, k.assumption_log()).map_err(e)?)
        }
    }
    fn der<K: Field>(
        d: &Descriptor<K>,
        log: Option<AssumptionLog<'static, K>>,
    ) -> crate::error::Result<Derivation<K>> {
        let mut rec = recorder(Method::DescriptorMinimal, d.a.field(), log);
        crate::realization::minimal_descriptor_recorded(d, Some(&mut rec))?;
        Ok(rec.finish())
    }
    let l = crate::io::load_descriptor::load_descriptor_path(file).ok()?;
    (l.has_e && l.pencil.is_none() && l.transfer.is_none()).then(|| l.run(Visit(file, out)))
}

/// A derivation over an extension of $F$ of the system (`run`), a descriptor system through
/// its standard form first (its steps over $F$ lifted, then `run`'s on the standard system).
fn through_standard<'a, F: Field>(
    ss: &StateSpace<F>,
    descriptor: Option<&Descriptor<F>>,
    log: Option<AssumptionLog<'a, F>>,
    run: impl Fn(&StateSpace<F>) -> crate::error::Result<Derivation<crate::algebraic::Ext<F>>>,
) -> crate::error::Result<Derivation<crate::algebraic::Ext<F>>> {
    let Some(d) = descriptor else {
        return run(ss);
    };
    let (first, ss) = standard_steps(d, log)?;
    Ok(after_lifted(&first, run(&ss)?))
}

/// `out` (over an extension of $F$) with the steps of `first` (over $F$, lifted) in front.
fn after_lifted<F: Field>(
    first: &Derivation<F>,
    mut out: Derivation<crate::algebraic::Ext<F>>,
) -> Derivation<crate::algebraic::Ext<F>> {
    let mut steps = lift_derivation(first, &out.field).steps;
    steps.append(&mut out.steps);
    out.steps = steps;
    out
}

/// `jordan --steps` over $\mathbb{Q}$; for a descriptor system the steps of its standard
/// form (lifted into the rationals as a number field of degree 1), then the Jordan steps of
/// the standard form's $A$ (the finite dynamics `jordan` reports).
fn jordan_q(
    t: &TypedSystem<Q>,
    norm: &Normalization,
) -> crate::error::Result<Derivation<NumberField>> {
    a_through_standard(t, |a| crate::jordan::steps::jordan_steps_with(a, norm))
}

/// `jordan --real --steps` over $\mathbb{Q}$; a descriptor system through its standard form
/// as in [`jordan_q`] (the real Jordan form of the finite dynamics).
fn real_jordan_q(
    t: &TypedSystem<Q>,
    expand: bool,
) -> crate::error::Result<Derivation<NumberField>> {
    a_through_standard(t, |a| {
        crate::jordan::real_steps::real_jordan_steps(a, expand)
    })
}

/// `run` on the file's $A$, or for a descriptor system on its standard form's $A$ after the
/// standard form's own steps (lifted, as in [`through_standard`]).
fn a_through_standard(
    t: &TypedSystem<Q>,
    run: impl Fn(&crate::matrix::Matrix<Q>) -> crate::error::Result<Derivation<NumberField>>,
) -> crate::error::Result<Derivation<NumberField>> {
    let Some(d) = &t.descriptor else {
        return run(&t.a_raw);
    };
    let (first, ss) = standard_steps(d, None)?;
    Ok(after_lifted(&first, run(&ss.a)?))
}

fn path_text(p: &Path) -> String {
    p.display().to_string()
}

/// The output format of a derivation.
struct Render {
    format: Format,
    standalone: bool,
}

impl Sink for Render {
    type Out = Outcome;
    fn show<K: Field>(&self, d: &Derivation<K>) -> Result<Outcome, Failure> {
        let verified = d.verified();
        if self.format != Format::Latex {
            return Ok(Outcome::new(derivation_report(d), verified));
        }
        let text = derivation_latex(d, self.standalone);
        super::write_stdout(&text)
            .map_err(|err| Failure::input(format!("cannot write the output: {err}")))?;
        let mut o = Outcome::new(derivation_report(d), verified);
        o.streamed = true;
        Ok(o)
    }
}
