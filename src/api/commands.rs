//! One function per command: load, compute, report.
//!
//! Commands on a system file are written once, generic over the file's field `K`, inside
//! [`FileCommand::visit`] (over $\mathbb{Q}(p)$: [`super::symbolic::execute`]); the file's
//! field is decided at one point, [`System::run`].

use super::a_only::a_command;
use super::common::with_path;
use super::system::{System, SystemVisitor};
use super::{Command, Failure, MethodArg, Outcome};
use crate::field::Field;
use crate::io::symbolic::SymbolicOptions;
use crate::io::{SystemFile, TypedSystem};
use crate::realization::{self, SystemField};
use crate::report::{Report, Value, sections};
use std::path::Path;

/// Dispatches a command (no `--symbolic`, no `--at`).
pub fn execute(cmd: &Command) -> Result<Outcome, Failure> {
    execute_with(cmd, None, None)
}

/// How the command line runs a command: when it started, its bound, where events go.
#[derive(Debug)]
pub struct RunContext {
    pub start: std::time::Instant,
    /// `--max-seconds`.
    pub max_seconds: f64,
    /// Where streamed sections go (text mode of `analyze`).
    pub events: super::budget::Events,
    /// `--full`.
    pub full: bool,
    /// The format of stdout when a command may write its report there as it computes it
    /// (long sweeps); `None` in process.
    pub stdout: Option<super::Format>,
}

/// Dispatches a command with `--symbolic` / `--at` (see [`crate::io::symbolic`]).
pub fn execute_with(
    cmd: &Command,
    symbolic: Option<&str>,
    at: Option<&str>,
) -> Result<Outcome, Failure> {
    let ctx = RunContext {
        start: std::time::Instant::now(),
        max_seconds: 1e7,
        events: None,
        full: false,
        stdout: None,
    };
    execute_ctx(cmd, symbolic, at, &ctx)
}

/// Dispatches a command run by the command line (budgets of `analyze` from `ctx`).
///
/// The file is read once ([`System::open`], with `--symbolic` / `--at`) and the command
/// runs on the system over its field ([`System::run`]); over $\mathbb{Q}(p)$ the command's
/// symbolic form ([`super::symbolic`]).
pub fn execute_ctx(
    cmd: &Command,
    symbolic: Option<&str>,
    at: Option<&str>,
    ctx: &RunContext,
) -> Result<Outcome, Failure> {
    let opts = SymbolicOptions::from_args(symbolic, at).map_err(Failure::input)?;
    if let Command::Poly { op } = cmd {
        return poly(op).map(Outcome::plain);
    }
    // `linalg` on a file holding only a plain rational matrix: read in one pass
    if let Some(out) = super::linalg::fast(cmd, &opts, ctx) {
        return out;
    }
    // commands on several files, each read by the one reader
    if let Command::Interconnect(c) = cmd {
        return super::interconnect::run(c, &opts);
    }
    // a file with only D is a static gain
    if let Command::Dcgain { file } = cmd {
        return super::dcgain::run(&System::open_or_gain(file, &opts)?);
    }
    let sys = match file_of(cmd) {
        None => System::builtin(&opts)?,
        Some(path) => match System::open(path, &opts) {
            Ok(s) => s,
            // files that are not systems in standard form: a pencil, `G`, an improper
            // descriptor (the descriptor reader), a matrix A alone (`jordan`, `linalg`)
            Err(err) if opts.is_empty() => {
                if super::pencil_cmds::handles(cmd, None) {
                    return super::pencil_cmds::execute(cmd, path);
                }
                if matches!(cmd, Command::Jordan { .. } | Command::Linalg { .. }) {
                    return super::a_only::fallback(cmd, path, err);
                }
                // a parameter study of a file without that parameter: that is the answer; a
                // file the study reads (an improper pencil) is studied
                if let Command::Sweep { param, .. } | Command::Critical { param, .. } = cmd {
                    crate::study::ParamFamily::from_file(path, param)?;
                    if super::common::check_study_file(path).is_ok() {
                        return study(cmd, path, &opts.at, ctx);
                    }
                }
                return Err(err.into());
            }
            Err(err) => return Err(err.into()),
        },
    };
    sys.run(FileCommand {
        cmd,
        path: sys.path(),
        opts: &opts,
        from_file: sys.from_file(),
        ctx,
        sys: &sys,
    })
}

/// Runs `cmd` on a system already read (the command's file argument is not read again;
/// `--symbolic` / `--at` were applied when `sys` was read). The Python package's entry.
///
/// An interconnection's first system is `sys`; its other files are read by
/// [`System::open_or_gain`] (with systems already read: [`execute_on_many`]).
pub fn execute_on(cmd: &Command, sys: &System, ctx: &RunContext) -> Result<Outcome, Failure> {
    if let Command::Interconnect(c) = cmd {
        let rest = c.files().into_iter().skip(1);
        let rest = rest
            .map(|p| System::open_or_gain(p, &SymbolicOptions::default()))
            .collect::<Result<Vec<_>, _>>()?;
        let all: Vec<&System> = std::iter::once(sys).chain(&rest).collect();
        return execute_on_many(cmd, &all, ctx);
    }
    execute_on_many(cmd, &[sys], ctx)
}

/// Runs `cmd` on systems already read: an interconnection on all of them (in the order of
/// its files), every other command on the first.
pub fn execute_on_many(
    cmd: &Command,
    systems: &[&System],
    ctx: &RunContext,
) -> Result<Outcome, Failure> {
    if let Command::Poly { op } = cmd {
        return poly(op).map(Outcome::plain);
    }
    if let Command::Interconnect(c) = cmd {
        return super::interconnect::run_on(c, systems);
    }
    let Some(sys) = systems.first() else {
        return Err(Failure::input("no system given".into()));
    };
    if let Command::Dcgain { .. } = cmd {
        return super::dcgain::run(sys);
    }
    sys.run(FileCommand {
        cmd,
        path: sys.path(),
        opts: &SymbolicOptions::default(),
        from_file: sys.from_file(),
        ctx,
        sys,
    })
}

/// `sweep` / `critical` of the file at `path` (`at`: values of other parameters).
fn study(
    cmd: &Command,
    path: &Path,
    at: &[(String, String)],
    ctx: &RunContext,
) -> Result<Outcome, Failure> {
    match cmd {
        Command::Sweep { .. } => match super::sweep::SweepArgs::of(cmd, path, at) {
            Some(args) => super::sweep::run(&args, ctx.stdout),
            None => Err(not_a_sweep()),
        },
        Command::Critical { .. } => match super::critical::CriticalArgs::of(cmd, path, at) {
            Some(args) => super::critical::run(&args),
            None => Err(not_a_sweep()),
        },
        _ => Err(Failure::verification(
            "internal: not a parameter study".into(),
        )),
    }
}

impl Default for RunContext {
    /// Now, no bound (10^7 s), nothing streams, compact text.
    fn default() -> Self {
        RunContext {
            start: std::time::Instant::now(),
            max_seconds: 1e7,
            events: None,
            full: false,
            stdout: None,
        }
    }
}

/// The system file a command reads (`None`: `analyze` on the built-in example).
/// [`super::sweep::SweepArgs::of`] answers every `Command::Sweep`; this is never reached.
fn not_a_sweep() -> Failure {
    Failure::verification("internal: parameter-study arguments of another command".into())
}

pub(super) fn file_of(cmd: &Command) -> Option<&Path> {
    match cmd {
        Command::Jordan { file, .. }
        | Command::Minreal { file, .. }
        | Command::Standard { file }
        | Command::Scb { file }
        | Command::Mnf { file }
        | Command::Zeros { file }
        | Command::Pencil { file }
        | Command::Ctrb { file }
        | Command::Obsv { file }
        | Command::Tf { file }
        | Command::Modes { file }
        | Command::Freqresp { file, .. }
        | Command::Pzmap { file, .. }
        | Command::Step { file, .. }
        | Command::Impulse { file, .. }
        | Command::Check { file }
        | Command::Sweep { file, .. }
        | Command::Critical { file, .. }
        | Command::Bifurcations { file, .. }
        | Command::Linalg { file, .. } => Some(file),
        Command::Dcgain { file } => Some(file),
        Command::Toolbox(c) => Some(c.file()),
        Command::Discrete(c) => Some(c.file()),
        Command::Response(c) => Some(c.file()),
        Command::Analyze { file, .. } => file.as_deref(),
        Command::Poly { .. } | Command::Interconnect(_) => None,
    }
}

/// A command on one system file.
struct FileCommand<'a> {
    cmd: &'a Command,
    path: &'a Path,
    opts: &'a SymbolicOptions,
    /// The system was read from `path` (the descriptor reader may read it again).
    from_file: bool,
    ctx: &'a RunContext,
    /// The system as read (a sweep over an extension field reads it again with values).
    sys: &'a System,
}

impl SystemVisitor for FileCommand<'_> {
    type Output = Result<Outcome, Failure>;
    fn visit<K: crate::io::GroundField>(self, f: &SystemFile, t: &TypedSystem<K>) -> Self::Output {
        let path = self.path;
        let e = |err| with_path(path, err);
        let s = &t.ss;
        if let Some(r) = super::discrete::on_sampled(self.cmd, f, t, path) {
            return r;
        }
        if super::pencil_cmds::handles(self.cmd, Some(f)) {
            return if self.opts.is_empty() && self.from_file {
                super::pencil_cmds::execute(self.cmd, path)
            } else {
                super::pencil_cmds::execute_typed(self.cmd, path, f, t)
            };
        }
        match self.cmd {
            Command::Bifurcations { .. } => Err(super::bifurcations::needs_symbols(path)),
            Command::Analyze {
                section_seconds, ..
            } => super::analyze::analyze_with(f, t, &analyze_options(*section_seconds, self.ctx)),
            // entries in Q(sqrt d) or Q(i): the system read again at each value
            Command::Sweep { .. } if matches!(f.ground, crate::io::Ground::Quadratic(_)) => {
                match super::sweep::SweepArgs::of(self.cmd, path, &self.opts.at) {
                    Some(args) => super::sweep::run_field(&args, self.sys, self.ctx.stdout),
                    None => Err(not_a_sweep()),
                }
            }
            Command::Critical { .. } if self.from_file => {
                match (
                    &f.ground,
                    super::critical::CriticalArgs::of(self.cmd, path, &self.opts.at),
                ) {
                    (crate::io::Ground::Quadratic(k), Some(args)) => {
                        super::critical::run_field(&args, k)
                    }
                    _ => study(self.cmd, path, &self.opts.at, self.ctx),
                }
            }
            Command::Sweep { .. } | Command::Critical { .. } if !self.from_file => {
                Err(Failure::input(format!(
                    "{}: a parameter study reads its system file (give the file's path)",
                    path.display()
                )))
            }
            Command::Sweep { .. } | Command::Critical { .. } => {
                study(self.cmd, path, &self.opts.at, self.ctx)
            }
            Command::Jordan { .. } if t.descriptor.is_some() => {
                let d = t.descriptor.as_ref().expect("checked");
                super::a_only::descriptor_jordan(self.cmd, d, path)
            }
            Command::Jordan { .. } | Command::Linalg { .. } => {
                a_command(self.cmd, &t.a_raw, path).expect("an A-only command")
            }
            Command::Modes { .. } => Ok(Outcome::plain(K::modal_table(&s.a).map_err(e)?.report())),
            Command::Mnf { .. } => mnf(s, path),
            Command::Scb { .. } => {
                let r = crate::structure::scb::scb(&s.a, &s.b, &s.c, &s.d).map_err(e)?;
                let ok = r.verified && r.verify();
                Ok(Outcome::new(r.report(), ok))
            }
            Command::Zeros { .. } => {
                let z =
                    crate::structure::zeros::invariant_zeros(&s.a, &s.b, &s.c, &s.d).map_err(e)?;
                let domain = crate::system::discrete::stability::Domain::of(f.signals.dt.as_ref());
                Ok(Outcome::plain(z.report_in(domain)))
            }
            Command::Freqresp { .. } => super::freqresp_cmd::freqresp_command(self.cmd, f, t, path),
            Command::Pzmap { svg, .. } => {
                super::plots::pzmap(f, t, path, svg.as_deref()).map(Outcome::plain)
            }
            Command::Step { opts, .. } | Command::Impulse { opts, .. } => {
                let args = super::plots::TimeArgs {
                    impulse: matches!(self.cmd, Command::Impulse { .. }),
                    to: opts.to,
                    points: opts.points,
                    svg: opts.svg.as_deref(),
                    csv: opts.csv.as_deref(),
                    float_only: opts.float,
                };
                let (r, ok) = super::plots::time_response(f, t, path, &args)?;
                Ok(Outcome::new(r, ok))
            }
            Command::Check { .. } => {
                let r = super::float_cmds::check(t, path)?;
                let agree = !matches!(r.get("agree"), Some(Value::Bool(false)));
                Ok(Outcome::float_vs_exact(r, agree))
            }
            Command::Minreal { method, hankel, .. } => minreal(t, *method, *hankel, path),
            Command::Toolbox(c) => super::toolbox::run(c, f, t, path),
            Command::Discrete(c) => super::discrete::run(c, f, t, path),
            Command::Response(c) => super::response::run(c, f, t, path),
            Command::Standard { .. } => Ok(standard(t, path)?),
            Command::Poly { .. }
            | Command::Pencil { .. }
            | Command::Ctrb { .. }
            | Command::Obsv { .. }
            | Command::Tf { .. }
            | Command::Interconnect(_)
            | Command::Dcgain { .. } => Err(Failure::verification(
                "internal: command dispatched elsewhere".into(),
            )),
        }
    }
    fn visit_symbolic(
        self,
        f: &SystemFile,
        t: &TypedSystem<crate::ratfunc::RatFuncField>,
    ) -> Self::Output {
        if let Some(r) = super::discrete::on_sampled(self.cmd, f, t, self.path) {
            return r;
        }
        match self.cmd {
            Command::Discrete(c) => super::discrete::run(c, f, t, self.path),
            Command::Response(c) => super::response::run_symbolic(c, t, self.path),
            Command::Bifurcations { of, depth, .. } => {
                super::bifurcations::run(self.path, t, *of, *depth)
            }
            // the swept parameter may be a symbol (the study gives it its values); every
            // other symbol needs a number: a plot and a crossing are numbers
            Command::Sweep { param, .. } | Command::Critical { param, .. } => {
                let k = t.a_raw.field();
                let other: Vec<&str> = k
                    .vars()
                    .iter()
                    .filter(|v| *v != param)
                    .map(String::as_str)
                    .collect();
                if other.is_empty() {
                    return self.visit(f, t);
                }
                let name = if matches!(self.cmd, Command::Sweep { .. }) {
                    "sweep"
                } else {
                    "critical"
                };
                Err(Failure::input(format!(
                    "{}: `{name}` along {param} needs numbers for every other parameter ({} without one); give them values with --at or in the file",
                    self.path.display(),
                    other.join(", ")
                )))
            }
            _ => super::symbolic::execute(self.cmd, f, t, self.path),
        }
    }
}

/// The mechanical normal form over an exact field; exit 1 when a form it found fails its check
/// (nothing to verify when the form does not exist: that verdict is the exact decision).
fn mnf<K: Field>(s: &crate::system::StateSpace<K>, path: &Path) -> Result<Outcome, Failure> {
    use crate::structure::mechanical::{DEFAULT_MAX_CANDIDATES, mechanical_normal_form_in};
    let m = mechanical_normal_form_in(None, &s.a, &s.b, &s.c, &s.d, DEFAULT_MAX_CANDIDATES)
        .map_err(|err| with_path(path, err))?;
    Ok(Outcome::new(m.report(), !m.exists || m.verified))
}

fn minreal<K: SystemField>(
    t: &TypedSystem<K>,
    method: MethodArg,
    hankel: Option<usize>,
    path: &Path,
) -> Result<Outcome, Failure> {
    let Some(m) = method.exact() else {
        let r = super::float_cmds::era(t, path, hankel)?;
        let agree = !matches!(r.get("agree_with_exact"), Some(Value::Bool(false)));
        return Ok(Outcome::float_vs_exact(r, agree));
    };
    let r = realization::minimal(&t.ss, m).map_err(|e| with_path(path, e))?;
    Ok(Outcome::new(r.report(), r.verified))
}

fn standard<K: Field>(t: &TypedSystem<K>, path: &Path) -> Result<Outcome, Failure> {
    match &t.descriptor {
        Some(d) => {
            let r = realization::descriptor_to_standard(d).map_err(|e| with_path(path, e))?;
            Ok(Outcome::new(r.report(), r.verified))
        }
        None => Ok(Outcome::plain(sections::already_standard(&t.ss))),
    }
}

fn poly(op: &super::PolyCmd) -> Result<Report, Failure> {
    let parse = |e: &str| {
        crate::poly::parse_poly_q(e)
            .map_err(|err| Failure::input(format!("polynomial \"{e}\": {err}")))
    };
    match op {
        super::PolyCmd::Factor { expr } => {
            let ids = crate::mpoly::parse::identifiers(expr)
                .map_err(|err| Failure::input(format!("polynomial \"{expr}\": {err}")))?;
            if ids.len() <= 1 && ids.iter().all(|v| v.len() == 1) {
                let p = parse(expr)?;
                return Ok(sections::factor_report(&p)?);
            }
            let (vars, p) = parse_multi(&[expr])?;
            Ok(sections::mfactor_report(&vars, &p[0])?)
        }
        super::PolyCmd::Gcd { f, g } => {
            let (vars, p) = parse_multi(&[f, g])?;
            Ok(sections::mgcd_report(&vars, &p[0], &p[1]))
        }
        super::PolyCmd::Roots { expr, digits } => {
            let p = parse(expr)?;
            if *digits == 0 || *digits > super::args::MAX_DIGITS {
                return Err(Failure::input(format!(
                    "--digits must be between 1 and {} (got {digits})",
                    super::args::MAX_DIGITS
                )));
            }
            Ok(sections::roots_report(&p, *digits)?)
        }
    }
}

/// Parses several polynomials in the union of their variables (sorted).
fn parse_multi(texts: &[&String]) -> Result<(Vec<String>, Vec<crate::mpoly::QPoly>), Failure> {
    let fail =
        |e: &str, err: crate::error::Error| Failure::input(format!("polynomial \"{e}\": {err}"));
    let mut vars: Vec<String> = Vec::new();
    for t in texts {
        vars.extend(crate::mpoly::parse::identifiers(t).map_err(|err| fail(t, err))?);
    }
    vars.sort();
    vars.dedup();
    if vars.len() > crate::mpoly::MAX_VARS {
        return Err(Failure::limit(format!(
            "at most {} variables",
            crate::mpoly::MAX_VARS
        )));
    }
    let refs: Vec<&str> = vars.iter().map(|s| s.as_str()).collect();
    let polys = texts
        .iter()
        .map(|t| crate::mpoly::parse_mpoly_in(t, &refs).map_err(|err| fail(t, err)))
        .collect::<Result<Vec<_>, _>>()?;
    Ok((vars, polys))
}

/// The built-in example of `analyze` without a file.
pub const BUILTIN_EXAMPLE: &str = include_str!("../../data/sliding-masses.json");

fn analyze_options(section_seconds: f64, ctx: &RunContext) -> super::analyze::AnalyzeOptions {
    super::analyze::AnalyzeOptions {
        budget: super::budget::Budget::new(section_seconds, ctx.start, ctx.max_seconds),
        events: ctx.events.clone(),
        full: ctx.full,
    }
}
