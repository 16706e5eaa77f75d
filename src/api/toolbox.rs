//! `margin`, `stepinfo`, `damp`, `gram`: thin wrappers over
//! [`crate::system::margins`] (exact margins over $\mathbb{Q}$, $\mathbb{Q}(\sqrt d)$,
//! $\mathbb{Q}(i)$),
//! [`crate::float::stepinfo`] (step characteristics on the float step response, final
//! value the exact DC gain), [`crate::realization::damp`] and
//! [`crate::realization::gramian`] (exact Lyapunov solve, verified), with their reports in
//! [`crate::report::sections`].

use super::common::with_path;
use super::ground::numeric;
use super::{Failure, Outcome};
use crate::field::Field;
use crate::float::stepinfo::step_info;
use crate::float::{self, to_dmatrix};
use crate::io::{GroundField, SystemFile, TypedSystem};
use crate::realization::{self, GramType};
use crate::report::sections;
use crate::system::time_response::{default_horizon, default_points, time_grid};
use clap::Subcommand;
use std::path::{Path, PathBuf};

/// Default number of samples of `stepinfo` (at least; more for fast poles).
const STEPINFO_POINTS: usize = 10_000;

/// `gram --type`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum GramArg {
    /// Controllability: A W + W A^T + B B^T = 0.
    C,
    /// Observability: A^T W + W A + C^T C = 0.
    O,
}

/// The toolbox subcommands (python-control's `margin`, `step_info`, `damp`, `gram`).
#[derive(Subcommand, Debug, Clone)]
pub enum ToolboxCmd {
    /// Gain and phase margins of a SISO loop (exact over Q, Q(sqrt d), Q(i): crossover frequencies and the
    /// gain margin as algebraic numbers, cos of the phase margin exact), python-control's
    /// choice of the reported margins; `inf` when there is no crossover.
    Margin {
        /// System file (JSON or TOML; see "FILE" in `exactlti --help`).
        file: PathBuf,
    },
    /// Step characteristics per channel (python-control's `step_info`: rise 10-90 %,
    /// settling 2 %, overshoot, undershoot, peak) on the float step response; the final value
    /// is the exact DC gain, and a channel with an unstable pole has none.
    Stepinfo {
        /// System file (JSON or TOML; see "FILE" in `exactlti --help`).
        file: PathBuf,
        /// Horizon in seconds (default: from the poles, as `step`).
        #[arg(long, value_name = "S")]
        to: Option<f64>,
        /// Number of samples on [0, --to] (2 to 100000; default at least 10000).
        #[arg(long, value_name = "N")]
        points: Option<usize>,
    },
    /// Damping table: per pole natural frequency (rad/s and Hz), damping ratio, time constant;
    /// exact wn^2 and 2 zeta wn where the pole's minimal polynomial has degree <= 2.
    Damp {
        /// System file (JSON or TOML; see "FILE" in `exactlti --help`).
        file: PathBuf,
    },
    /// Controllability (c) or observability (o) Gramian of a stable system, by an exact
    /// Lyapunov solve over the system's field (Q, Q(sqrt d), Q(i): conjugate transposes A^H),
    /// substituted back into its equation (verified).
    Gram {
        /// System file (JSON or TOML; see "FILE" in `exactlti --help`).
        file: PathBuf,
        /// c: A W + W A^T + B B^T = 0; o: A^T W + W A + C^T C = 0.
        #[arg(long = "type", value_enum, default_value_t = GramArg::C)]
        kind: GramArg,
    },
}

impl ToolboxCmd {
    /// The command's name as typed.
    pub fn name(&self) -> &'static str {
        match self {
            ToolboxCmd::Margin { .. } => "margin",
            ToolboxCmd::Stepinfo { .. } => "stepinfo",
            ToolboxCmd::Damp { .. } => "damp",
            ToolboxCmd::Gram { .. } => "gram",
        }
    }
    /// The system file it reads.
    pub fn file(&self) -> &Path {
        match self {
            ToolboxCmd::Margin { file }
            | ToolboxCmd::Stepinfo { file, .. }
            | ToolboxCmd::Damp { file }
            | ToolboxCmd::Gram { file, .. } => file,
        }
    }
}

fn bad(path: &Path, what: String) -> Failure {
    Failure::input(format!("{}: {what}", path.display()))
}

/// Runs a toolbox command on a system over its exact field.
pub(super) fn run<K: GroundField>(
    cmd: &ToolboxCmd,
    f: &SystemFile,
    t: &TypedSystem<K>,
    path: &Path,
) -> Result<Outcome, Failure> {
    let e = |err| with_path(path, err);
    match cmd {
        ToolboxCmd::Margin { .. } => {
            let t = numeric(t, "margin", path)?;
            let m = crate::system::margins::margins(&t.ss).map_err(e)?;
            Ok(Outcome::new(sections::margins_report(&m), m.verified))
        }
        ToolboxCmd::Damp { .. } => {
            let t = numeric(t, "damp", path)?;
            let rows = realization::damp_over(&t.ss.a).map_err(e)?;
            Ok(Outcome::plain(sections::damp_report(&rows)))
        }
        ToolboxCmd::Gram { kind, .. } => {
            let kind = match kind {
                GramArg::C => GramType::Controllability,
                GramArg::O => GramType::Observability,
            };
            let g = realization::gramian(&t.ss, kind).map_err(e)?;
            Ok(Outcome::new(sections::gram_report(&g), g.verified))
        }
        ToolboxCmd::Stepinfo { to, points, .. } => stepinfo(f, t, path, *to, *points),
    }
}

/// `stepinfo`: the float step response on the grid of `step`, characteristics per channel.
fn stepinfo<K: Field + 'static>(
    f: &SystemFile,
    t: &TypedSystem<K>,
    path: &Path,
    to: Option<f64>,
    points: Option<usize>,
) -> Result<Outcome, Failure> {
    let e = |err| with_path(path, err);
    let s = &t.ss;
    let (p, m) = (s.noutputs(), s.ninputs());
    if points.is_some_and(|n| !(2..=100_000).contains(&n))
        || to.is_some_and(|x| !(x.is_finite() && x > 0.0))
    {
        return Err(bad(
            path,
            "stepinfo: need 2 <= --points <= 100000 and --to > 0 seconds".into(),
        ));
    }
    if p == 0 || m == 0 {
        return Err(bad(
            path,
            "stepinfo needs at least one input and one output (B and C)".into(),
        ));
    }
    let conv = |x| to_dmatrix(x).map_err(e);
    let (a, b, c, d) = (conv(&s.a)?, conv(&s.b)?, conv(&s.c)?, conv(&s.d)?);
    let poles: Vec<(f64, f64)> = if a.nrows() == 0 {
        vec![]
    } else {
        float::eigenvalues(&a)
            .map_err(e)?
            .into_iter()
            .map(|z| (z.re, z.im))
            .collect()
    };
    let a_stable = poles.iter().all(|z| z.0 < 0.0);
    let t_end = to.unwrap_or_else(|| default_horizon(&poles));
    // finer than `step`'s plot grid: the characteristics are read off the samples
    let n = points.unwrap_or_else(|| default_points(t_end, &poles).max(STEPINFO_POINTS));
    let times = time_grid(t_end, n);
    let resp = float::time_response(float::Input::Step, [&a, &b, &c, &d], &times).map_err(e)?;
    let dc = crate::system::dcgain::dc_gain(s).map_err(e)?;
    let g = s.transfer_matrix().map_err(e)?;
    let (_, ins, outs) = super::plots::names(f, path, m, p);
    let k = s.field();
    let mut channels = vec![];
    for i in 0..p {
        for j in 0..m {
            let y: Vec<f64> = resp.iter().map(|r| r[(i, j)]).collect();
            let stable = channel_stable(&g.entries[i][j].den).unwrap_or(a_stable);
            let fin = dc.entries[i][j]
                .as_ref()
                .and_then(|x| k.approx(x))
                .map(|z| z.0);
            let info = match (stable, fin) {
                (false, _) | (_, None) => {
                    Err("a pole of this channel is not in the open left half-plane: no final value")
                }
                (true, Some(y_inf)) => {
                    step_info(&times, &y, y_inf).map_err(sections::no_stepinfo_reason)
                }
            };
            channels.push(sections::stepinfo_channel(
                &outs[i],
                &ins[j],
                info.as_ref().map_err(|w| *w),
            ));
        }
    }
    let r = crate::report::Report::titled("step characteristics")
        .float("horizon_s", t_end)
        .int("points", n)
        .with("channels", sections::stepinfo_table(channels));
    Ok(Outcome::plain(r))
}

/// Every root of the reduced denominator in the open left half-plane, decided exactly by
/// Routh–Hurwitz over $\mathbb{Q}$; over a larger field (`None` here) the caller decides from
/// the float eigenvalues of $A$.
fn channel_stable<K: Field>(den: &crate::poly::Poly<K>) -> Option<bool> {
    den.to_rational_poly().map(|q| realization::is_hurwitz(&q))
}
