//! The `exactlti` command line (contract: ../shared/CLI-CONTRACT.md).
//!
//! Thin: arguments → [`crate::io`] → library → [`crate::report::Report`] → text/JSON/LaTeX.
//! Exit status 0 on success; 2 for bad input or a request that cannot be met (one line on
//! stderr naming the file, key, row and column, or the violated condition); 1 for an
//! internal failure (an exact verification that failed). Long exact work is bounded by
//! `--max-seconds` (default 600).

mod analyze;
mod bifurcations;
mod commands;
mod common;
mod critical;
mod float_cmds;
mod pencil_cmds;
mod sweep;
mod symbolic;
mod symbolic_jordan;

/// One command run in-process (no output, no time bound): the report and its status.
pub use commands::execute;

use crate::error::Error;
use crate::report::Report;
use clap::{Parser, Subcommand, ValueEnum};
use std::path::PathBuf;
use std::sync::mpsc;
use std::time::Duration;

/// Output formats.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, ValueEnum)]
pub enum Format {
    #[default]
    Text,
    Json,
    Latex,
}

#[derive(Parser, Debug)]
#[command(
    name = "exactlti",
    version,
    about = "Exact structure of linear time-invariant systems: Jordan forms, minimal realizations, special coordinate basis, mechanical normal form"
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
    /// Output format.
    #[arg(long, global = true, value_enum, default_value_t = Format::Text)]
    pub format: Format,
    /// Upper bound on the wall time of the exact computation; exceeded: exit 2.
    #[arg(long, global = true, default_value_t = 600.0)]
    pub max_seconds: f64,
    /// Keep these parameters as symbols (comma separated; alone: every parameter).
    #[arg(long, global = true, num_args = 0..=1, default_missing_value = "", value_name = "NAMES")]
    pub symbolic: Option<String>,
    /// Values for parameters or symbols before the computation, e.g. "m=1500, u=20".
    #[arg(long, global = true, value_name = "VALUES")]
    pub at: Option<String>,
}

/// `--method` of `minreal`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum MethodArg {
    Kalman,
    Rosenbrock,
    HoKalman,
    Jordan,
    Era,
}

/// Operations of `linalg`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum LinalgOp {
    Rank,
    Det,
    Charpoly,
    Minpoly,
    Inverse,
    Nullspace,
    Rref,
}

/// Operations of `poly`.
#[derive(Subcommand, Debug)]
pub enum PolyCmd {
    /// Factorization over Q into irreducibles with multiplicities (uni- or multivariate).
    Factor {
        #[arg(allow_hyphen_values = true)]
        expr: String,
    },
    /// Greatest common divisor of two (multivariate) polynomials over Q, with cofactors.
    Gcd {
        #[arg(allow_hyphen_values = true)]
        f: String,
        #[arg(allow_hyphen_values = true)]
        g: String,
    },
    /// All complex roots, certified, as exact algebraic numbers.
    Roots {
        expr: String,
        /// Correct significant digits of the displayed approximations.
        #[arg(long, default_value_t = 10)]
        digits: usize,
    },
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// Exact Jordan decomposition of A.
    Jordan {
        file: PathBuf,
        /// Real Jordan form (2x2 blocks [[a, b], [-b, a]] for complex pairs).
        #[arg(long)]
        real: bool,
        /// With --real: write every complex pair in an explicit real field (degree up to
        /// d(d-1) for an eigenvalue of degree d) instead of the compact form.
        #[arg(long)]
        expand: bool,
    },
    /// Minimal realization.
    Minreal {
        file: PathBuf,
        #[arg(long, value_enum, default_value_t = MethodArg::Kalman)]
        method: MethodArg,
        /// `--method era` only: K x K block Hankel matrices (default: grown until the
        /// numerical rank is stable).
        #[arg(long)]
        hankel: Option<usize>,
        /// Minimal DESCRIPTOR realization (improper systems accepted), with `irreducible_order`.
        #[arg(long)]
        descriptor: bool,
    },
    /// Descriptor system to standard state space.
    Standard { file: PathBuf },
    /// Special coordinate basis.
    Scb { file: PathBuf },
    /// Mechanical normal form (second-order form of a first-order system).
    Mnf { file: PathBuf },
    /// Invariant zeros (with `E`: finite zeros and infinite zero orders).
    Zeros { file: PathBuf },
    /// Kronecker structure of the pencil A - sE.
    Pencil { file: PathBuf },
    /// Controllability structure of (A, B) (with `E`: finite and infinite).
    Ctrb { file: PathBuf },
    /// Observability structure of (C, A) (with `E`: finite and infinite).
    Obsv { file: PathBuf },
    /// Transfer matrix in lowest terms, McMillan degree, poles and transmission zeros.
    Tf { file: PathBuf },
    /// Modal table: eigenvalue, frequency, damping ratio, time constant, period.
    Modes { file: PathBuf },
    /// Frequency response.
    Freqresp {
        file: PathBuf,
        #[arg(long, default_value_t = 0.01)]
        from: f64,
        #[arg(long, default_value_t = 10.0)]
        to: f64,
        #[arg(long, default_value_t = 200)]
        points: usize,
        #[arg(long)]
        svg: Option<PathBuf>,
        #[arg(long)]
        csv: Option<PathBuf>,
    },
    /// Eigenvalues along one parameter (float, parallel), with plots.
    Sweep {
        file: PathBuf,
        /// The parameter swept (its value in the file is overridden).
        #[arg(long)]
        param: String,
        #[arg(long, allow_hyphen_values = true)]
        from: f64,
        #[arg(long, allow_hyphen_values = true)]
        to: f64,
        #[arg(long, default_value_t = 200)]
        points: usize,
        /// Real and imaginary parts against the parameter.
        #[arg(long)]
        svg: Option<PathBuf>,
        /// Root locus in the complex plane.
        #[arg(long)]
        locus_svg: Option<PathBuf>,
        #[arg(long)]
        csv: Option<PathBuf>,
    },
    /// Exact critical values of one parameter and the intervals between them.
    Critical {
        file: PathBuf,
        #[arg(long)]
        param: String,
        /// Exact number (decimal or fraction).
        #[arg(long, allow_hyphen_values = true)]
        from: String,
        #[arg(long, allow_hyphen_values = true)]
        to: String,
        /// Correct digits of the displayed critical values.
        #[arg(long, default_value_t = 20)]
        digits: usize,
    },
    /// Run the float path beside the exact path and compare.
    Check { file: PathBuf },
    /// Polynomials over Q.
    Poly {
        #[command(subcommand)]
        op: PolyCmd,
    },
    /// Exact linear algebra on the matrix A of a system file.
    Linalg {
        #[arg(value_enum)]
        op: LinalgOp,
        file: PathBuf,
    },
    /// Everything that applies, as one report (built-in sliding-mass example without FILE).
    Analyze { file: Option<PathBuf> },
    /// Structural bifurcations of a symbolic system: the generic result, then the result
    /// where each condition vanishes (solved for a parameter when linear in it).
    Bifurcations {
        file: PathBuf,
        /// The structure explored.
        #[arg(long = "of", value_enum, default_value_t = bifurcations::Of::Scb)]
        of: bifurcations::Of,
        /// Substitutions along one path.
        #[arg(long, default_value_t = 2)]
        depth: usize,
    },
}

/// A command's result: the report, and whether every exact check it made passed (read for
/// the exit status; float-only results and answers that an object does not exist count as
/// passed, as there is nothing exact to check).
#[derive(Debug)]
pub struct Outcome {
    pub report: Report,
    pub verified: bool,
    /// The float path disagrees with the exact one (`check`, ERA): exit 3.
    pub float_disagrees: bool,
}

impl Outcome {
    /// A report with its verification status.
    pub fn new(report: Report, verified: bool) -> Self {
        Outcome {
            report,
            verified,
            float_disagrees: false,
        }
    }
    /// A float-vs-exact report (`check`, ERA): `agree = false` exits 3.
    pub fn float_vs_exact(report: Report, agree: bool) -> Self {
        Outcome {
            report,
            verified: true,
            float_disagrees: !agree,
        }
    }
    /// A report without an exact check to fail (float results, tables, factorizations).
    pub fn plain(report: Report) -> Self {
        Outcome::new(report, true)
    }
}

/// A command failure: exit code and the one-line message.
#[derive(Debug)]
pub struct Failure {
    pub code: i32,
    pub message: String,
}

impl std::fmt::Display for Failure {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}", self.message)
    }
}

impl std::error::Error for Failure {}

impl From<Error> for Failure {
    fn from(e: Error) -> Self {
        let code = if matches!(e, Error::Verification(_)) {
            1
        } else {
            2
        };
        Failure {
            code,
            message: e.to_string(),
        }
    }
}

impl From<crate::io::InputError> for Failure {
    fn from(e: crate::io::InputError) -> Self {
        Failure {
            code: 2,
            message: e.to_string(),
        }
    }
}

/// Renders a report in the chosen format.
pub fn render(r: &Report, f: Format) -> String {
    match f {
        Format::Text => r.to_text(),
        Format::Json => serde_json::to_string_pretty(&r.to_json()).unwrap_or_default() + "\n",
        Format::Latex => r.to_latex(),
    }
}

/// Runs the command line; returns the process exit code.
pub fn run(cli: Cli) -> i32 {
    let format = cli.format;
    let limit = cli.max_seconds;
    let (tx, rx) = mpsc::channel();
    let handle = std::thread::Builder::new()
        .stack_size(256 << 20)
        .spawn(move || {
            let r =
                commands::execute_with(&cli.command, cli.symbolic.as_deref(), cli.at.as_deref());
            let _ = tx.send(r);
        });
    if handle.is_err() {
        eprintln!("exactlti: could not start the worker thread");
        return 1;
    }
    let wait = if limit.is_finite() && limit > 0.0 {
        Duration::from_secs_f64(limit.min(1e7))
    } else {
        Duration::from_secs(600)
    };
    match rx.recv_timeout(wait) {
        Ok(Ok(out)) => {
            print!("{}", render(&out.report, format));
            if !out.verified {
                eprintln!("exactlti: an exact verification failed (verified = false)");
                1
            } else if out.float_disagrees {
                // contract, second wave: 3 = the float path disagrees with the exact one
                eprintln!(
                    "exactlti: the float path disagrees with the exact path (see the report)"
                );
                3
            } else {
                0
            }
        }
        Ok(Err(f)) => {
            eprintln!("exactlti: {}", f.message);
            f.code
        }
        Err(mpsc::RecvTimeoutError::Timeout) => {
            eprintln!(
                "exactlti: stopped after --max-seconds {limit}: the exact computation did not finish in time"
            );
            2
        }
        Err(mpsc::RecvTimeoutError::Disconnected) => {
            eprintln!("exactlti: internal failure (the computation panicked)");
            1
        }
    }
}
