//! The library's front door: one [`System`] (standard or descriptor, over any exact field,
//! with the names of its signals) loaded once from a path, a string or matrices, and every
//! operation of the command line as a [`Command`] run on it ([`execute`]), returning a
//! [`Report`] with `verified` (and `field`, `conditions` over $\mathbb{Q}(p)$).
//!
//! Both front ends stand on this module: the command line ([`crate::cli`]) parses its
//! arguments into a [`Command`], calls [`execute_ctx`] and renders the report; the Python
//! package (`python/src`) builds the same [`Command`] and converts the same report into
//! Python values. Options are typed once here ([`Command`], [`MethodArg`], [`TimeOpts`],
//! [`crate::io::symbolic::SymbolicOptions`] for `--symbolic` / `--at`); the worker thread
//! with a deadline exists once ([`runner::Worker`]).

mod a_only;
mod analyze;
mod args;
mod bifurcations;
pub mod budget;
mod commands;
mod common;
mod connect_file;
mod connect_names;
mod critical;
mod dcgain;
mod discrete;
mod discrete_plots;
mod float_cmds;
mod float_compare;
mod freqresp_cmd;
mod ground;
mod interconnect;
mod interconnect_common;
pub mod jordan_values;
mod linalg;
mod pencil_cmds;
pub mod plots;
pub mod poles;
mod response;
pub mod runner;
pub mod steps;
mod sweep;
mod sweep_field;
mod sweep_stream;
mod symbolic;
mod symbolic_jordan;
mod system;
mod toolbox;
pub mod transfer;

pub use crate::io::{GroundField, NumericField};
pub use args::{LinalgOp, MethodArg, PolyCmd, TimeOpts};
pub use bifurcations::Of;
/// One command run in-process (no output, no time bound): the report and its status.
pub use commands::{
    BUILTIN_EXAMPLE, RunContext, execute, execute_ctx, execute_on, execute_on_many, execute_with,
};
pub use connect_names::{NamedConnection, connect_named};
pub use discrete::{C2dMethod, DiscreteCmd};
pub use interconnect::{InterconnectCmd, system_of as interconnect_system};
pub use response::ResponseCmd;
pub use sweep::sweep_file;
pub use system::{Options, System, SystemVisitor};
pub use toolbox::{GramArg, ToolboxCmd};

use crate::error::{Error, ErrorClass};
use crate::report::Report;
use clap::{Parser, Subcommand};
use std::path::PathBuf;

/// Output formats of a report (the command line's `--format`; a long `sweep` writes its
/// report in this format as it computes it, [`RunContext::stdout`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    #[default]
    Text,
    Json,
    Latex,
}

/// Every operation on a system, with its options (the command line's subcommands).
// `defer`: a subcommand's arguments are defined only when it is the one parsed (or its help
// is shown), so a start builds one subcommand's definition, not all of them. (A plain
// comment: a second doc paragraph here would become the program's `long_about`.)
#[derive(Subcommand, Debug, Clone)]
#[command(defer = true)]
pub enum Command {
    /// Exact Jordan decomposition of A.
    Jordan {
        /// System file (JSON or TOML; see "FILE" in `exactlti --help`).
        file: PathBuf,
        /// Real Jordan form (2x2 blocks [[a, b], [-b, a]] for complex pairs).
        #[arg(long)]
        real: bool,
        /// With --real: write every complex pair in an explicit real field (degree up to
        /// d(d-1) for an eigenvalue of degree d) instead of the compact form.
        #[arg(long)]
        expand: bool,
        /// With --steps: normalise the chains, a comma list of `orth` (generalized
        /// eigenvectors orthogonal to the eigenvector, minimal-realization paper eq. 31),
        /// `entry` or `entry:<row>` (that entry of the eigenvector = 1), `unit` (unit-length
        /// eigenvectors, exact or in closed form); `paper` = `orth,unit` (eq. 32).
        #[arg(long, value_name = "LIST")]
        normalize: Option<String>,
    },
    /// Minimal realization.
    Minreal {
        /// System file (JSON or TOML; see "FILE" in `exactlti --help`).
        file: PathBuf,
        /// Algorithm: kalman (staircase), rosenbrock, ho-kalman, jordan (modal) are exact;
        /// era is the float eigensystem realization, compared with the exact McMillan degree.
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
    Standard {
        /// System file (JSON or TOML; see "FILE" in `exactlti --help`).
        file: PathBuf,
    },
    /// Special coordinate basis.
    Scb {
        /// System file (JSON or TOML; see "FILE" in `exactlti --help`).
        file: PathBuf,
    },
    /// Mechanical normal form (second-order form of a first-order system).
    Mnf {
        /// System file (JSON or TOML; see "FILE" in `exactlti --help`).
        file: PathBuf,
    },
    /// Invariant zeros (with `E`: finite zeros and infinite zero orders).
    Zeros {
        /// System file (JSON or TOML; see "FILE" in `exactlti --help`).
        file: PathBuf,
    },
    /// Kronecker structure of the pencil A - sE.
    Pencil {
        /// System file (JSON or TOML; see "FILE" in `exactlti --help`).
        file: PathBuf,
    },
    /// Controllability structure of (A, B) (with `E`: finite and infinite).
    Ctrb {
        /// System file (JSON or TOML; see "FILE" in `exactlti --help`).
        file: PathBuf,
    },
    /// Observability structure of (C, A) (with `E`: finite and infinite).
    Obsv {
        /// System file (JSON or TOML; see "FILE" in `exactlti --help`).
        file: PathBuf,
    },
    /// Transfer matrix in lowest terms, McMillan degree, poles and transmission zeros.
    Tf {
        /// System file (JSON or TOML; see "FILE" in `exactlti --help`).
        file: PathBuf,
    },
    /// Modal table: eigenvalue, frequency, damping ratio, time constant, period.
    Modes {
        /// System file (JSON or TOML; see "FILE" in `exactlti --help`).
        file: PathBuf,
    },
    /// Frequency response.
    Freqresp {
        /// System file (JSON or TOML; see "FILE" in `exactlti --help`).
        file: PathBuf,
        /// Lowest frequency in Hz (> 0); default: a decade below the slowest pole or zero
        /// (0.01 Hz when there is none besides 0).
        #[arg(long, value_name = "HZ")]
        from: Option<f64>,
        /// Highest frequency in Hz (> --from); default: a decade above the fastest pole or
        /// zero (10 Hz when there is none besides 0).
        #[arg(long, value_name = "HZ")]
        to: Option<f64>,
        /// Number of frequencies, logarithmically spaced from --from to --to (2 to 100000;
        /// points x outputs x inputs at most 1000000).
        #[arg(long, default_value_t = 200, value_name = "N")]
        points: usize,
        /// Also write a Bode plot as SVG: magnitude [dB] and unwrapped phase [deg] against Hz,
        /// channels named from the file, the grid refined near lightly damped poles; for a
        /// complex system over f < 0 (mirrored log axis) and f > 0 side by side.
        #[arg(long, value_name = "OUT.svg")]
        svg: Option<PathBuf>,
        /// Also write the response as CSV (frequency in Hz, real and imaginary parts).
        #[arg(long, value_name = "OUT.csv")]
        csv: Option<PathBuf>,
    },
    /// Poles (eigenvalues of A) and invariant zeros, exact over Q; `--svg` draws the
    /// pole-zero map (poles x, zeros o, equal axis scales, title from the file's `name`).
    Pzmap {
        /// System file (JSON or TOML; see "FILE" in `exactlti --help`).
        file: PathBuf,
        /// Write the pole-zero map as SVG.
        #[arg(long, value_name = "OUT.svg")]
        svg: Option<PathBuf>,
    },
    /// Step response of every input -> output channel: exact closed form from the Jordan form
    /// of A over its field, Q, Q(sqrt d), Q(i) (evaluated in floats), float matrix exponential
    /// with --float; with the exact
    /// DC gain D - C A^-1 B (the final value of a stable system).
    Step {
        /// System file (JSON or TOML; see "FILE" in `exactlti --help`).
        file: PathBuf,
        #[command(flatten)]
        opts: TimeOpts,
    },
    /// Impulse response C e^(At) B of every channel (D delta(t) left out), as `step`; the
    /// exact value at t = 0 is C B.
    Impulse {
        /// System file (JSON or TOML; see "FILE" in `exactlti --help`).
        file: PathBuf,
        #[command(flatten)]
        opts: TimeOpts,
    },
    /// Eigenvalues along one parameter (float, parallel), with plots.
    Sweep {
        /// System file (JSON or TOML; see "FILE" in `exactlti --help`).
        file: PathBuf,
        /// The parameter swept (its value in the file is overridden).
        #[arg(long)]
        param: String,
        /// First value of the parameter (in the file's units).
        #[arg(long, allow_hyphen_values = true)]
        from: f64,
        /// Last value of the parameter.
        #[arg(long, allow_hyphen_values = true)]
        to: f64,
        /// Number of parameter values, evenly spaced.
        #[arg(long, default_value_t = 200, value_name = "N")]
        points: usize,
        /// Real and imaginary parts against the parameter, written as SVG.
        #[arg(long, value_name = "OUT.svg")]
        svg: Option<PathBuf>,
        /// Root locus in the complex plane, written as SVG.
        #[arg(long, value_name = "OUT.svg")]
        locus_svg: Option<PathBuf>,
        /// The eigenvalues (real, imaginary parts) per parameter value, written as CSV.
        #[arg(long, value_name = "OUT.csv")]
        csv: Option<PathBuf>,
    },
    /// Exact critical values of one parameter and the intervals between them.
    Critical {
        /// System file (JSON or TOML; see "FILE" in `exactlti --help`).
        file: PathBuf,
        /// The parameter (a name from the file's `parameters`).
        #[arg(long)]
        param: String,
        /// Lower end of the interval: an exact number (decimal or fraction).
        #[arg(long, allow_hyphen_values = true)]
        from: String,
        /// Upper end of the interval: an exact number (decimal or fraction).
        #[arg(long, allow_hyphen_values = true)]
        to: String,
        /// Correct digits of the displayed critical values (1 to 200).
        #[arg(long, default_value_t = 20)]
        digits: usize,
    },
    /// Run the float path beside the exact path and compare.
    Check {
        /// System file (JSON or TOML; see "FILE" in `exactlti --help`).
        file: PathBuf,
    },
    /// Polynomials over Q.
    Poly {
        #[command(subcommand)]
        op: PolyCmd,
    },
    /// Exact linear algebra on the matrix A of a system file.
    Linalg {
        /// The operation; rank, rref and nullspace take any m x n matrix A.
        #[arg(value_enum)]
        op: LinalgOp,
        /// A file with the key A (JSON or TOML; the other keys of a system may be present).
        file: PathBuf,
    },
    /// Everything that applies, as one report (built-in sliding-mass example without FILE).
    Analyze {
        /// System file (JSON or TOML); without it, the built-in sliding-mass example.
        file: Option<PathBuf>,
        /// Time budget of each section in seconds (a section out of time is reported as
        /// skipped, with the command that insists); `--max-seconds` bounds the whole.
        #[arg(long, default_value_t = budget::DEFAULT_SECTION_SECONDS, value_name = "SECONDS", value_parser = parse_seconds, allow_hyphen_values = true)]
        section_seconds: f64,
    },
    /// Exact DC gain G(0) = D - C A^-1 B per channel (`inf` where the channel has a pole at
    /// s = 0), python-control's `dcgain`.
    Dcgain {
        /// System file (JSON or TOML; see "FILE" in `exactlti --help`), or a file with only D.
        file: PathBuf,
    },
    /// Interconnections: series, parallel, feedback, append (exact, python-control's
    /// conventions), with `--minreal` and `--out`.
    #[command(flatten)]
    Interconnect(interconnect::InterconnectCmd),
    /// Margins, step characteristics, damping table, Gramians (python-control's `margin`,
    /// `step_info`, `damp`, `gram`).
    #[command(flatten)]
    Toolbox(toolbox::ToolboxCmd),
    /// Discrete time: exact stability, c2d, d2c.
    #[command(flatten)]
    Discrete(discrete::DiscreteCmd),
    /// Free response from x0 in closed form; modes ranked by contribution and truncation.
    #[command(flatten)]
    Response(response::ResponseCmd),
    /// Structural bifurcations of a symbolic system: the generic result, then the result
    /// where each condition vanishes (solved for a parameter when linear in it).
    Bifurcations {
        /// System file (JSON or TOML; see "FILE" in `exactlti --help`).
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
    /// The report is printed but `--max-seconds` cut part of it: exit 2 with this line.
    pub stopped: Option<String>,
    /// The report was already written to stdout as it was computed (long sweeps).
    pub streamed: bool,
}

impl Outcome {
    /// A report with its verification status.
    pub fn new(report: Report, verified: bool) -> Self {
        Outcome {
            report,
            verified,
            float_disagrees: false,
            stopped: None,
            streamed: false,
        }
    }
    /// A float-vs-exact report (`check`, ERA): `agree = false` exits 3.
    pub fn float_vs_exact(report: Report, agree: bool) -> Self {
        Outcome {
            report,
            verified: true,
            float_disagrees: !agree,
            stopped: None,
            streamed: false,
        }
    }
    /// A report without an exact check to fail (float results, tables, factorizations).
    pub fn plain(report: Report) -> Self {
        Outcome::new(report, true)
    }
}

/// A command failure: exit code, the class of the error ([`ErrorClass`]: the command
/// line's exit status and Python's exception type follow it) and the one-line message.
/// A failure made from a library [`Error`] keeps it as its `source()`.
#[derive(Debug)]
pub struct Failure {
    pub code: i32,
    pub class: ErrorClass,
    pub message: String,
    /// The library error this failure reports, if it came from one.
    cause: Option<Box<Error>>,
}

impl Failure {
    /// A failure of class `class`, its exit status ([`ErrorClass::exit_code`]).
    pub fn new(class: ErrorClass, message: String) -> Self {
        Failure {
            code: class.exit_code(),
            class,
            message,
            cause: None,
        }
    }
    /// Bad input or an undefined result (exit 2).
    pub fn input(message: String) -> Self {
        Self::new(ErrorClass::Input, message)
    }
    /// A case this implementation does not handle (exit 2).
    pub fn unsupported(message: String) -> Self {
        Self::new(ErrorClass::Unsupported, message)
    }
    /// A size or time bound of the library (exit 2).
    pub fn limit(message: String) -> Self {
        Self::new(ErrorClass::Limit, message)
    }
    /// A failed exact check or an internal inconsistency (exit 1).
    pub fn verification(message: String) -> Self {
        Self::new(ErrorClass::Verification, message)
    }
    /// The same failure with the file's name in front of its message.
    pub fn in_file(self, path: &std::path::Path) -> Self {
        Failure {
            message: format!("{}: {}", path.display(), self.message),
            ..self
        }
    }
}

impl std::fmt::Display for Failure {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}", self.message)
    }
}

impl std::error::Error for Failure {
    /// The library [`Error`] the failure was made from (`None` for a command-line refusal).
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        self.cause
            .as_deref()
            .map(|e| e as &(dyn std::error::Error + 'static))
    }
}

impl From<Error> for Failure {
    /// The exit status of the error's class ([`Error::exit_code`]) and its line; the error
    /// is kept as the source.
    fn from(e: Error) -> Self {
        let f = Failure::new(e.class(), e.to_string());
        Failure {
            cause: Some(Box::new(e)),
            ..f
        }
    }
}

impl From<crate::io::InputError> for Failure {
    fn from(e: crate::io::InputError) -> Self {
        Error::from(e).into()
    }
}

/// `--max-seconds`: a finite number of seconds greater than zero (at most 10^7).
pub fn parse_seconds(text: &str) -> Result<f64, String> {
    let x: f64 = text
        .trim()
        .parse()
        .map_err(|_| format!("'{text}' is not a number of seconds"))?;
    if x.is_finite() && x > 0.0 && x <= 1e7 {
        Ok(x)
    } else {
        Err(format!(
            "must be a number of seconds > 0 and <= 10000000 (got '{text}')"
        ))
    }
}

/// The arguments of one command as the command line spells them, without the program name
/// and without the global options (`["minreal", "FILE", "--method", "jordan"]`).
#[derive(Parser, Debug)]
#[command(name = "exactlti", no_binary_name = true)]
struct Args {
    #[command(subcommand)]
    command: Command,
}

impl Command {
    /// Parses one command from its arguments (as the command line spells them).
    ///
    /// # Errors
    /// An unknown command or option, a missing or bad value: clap's message on one line.
    ///
    /// # Examples
    /// ```
    /// use exactlti::api::{Command, MethodArg};
    /// let c = Command::parse_args(&["minreal", "x.json", "--method", "jordan"]).unwrap();
    /// assert!(matches!(c, Command::Minreal { method: MethodArg::Jordan, .. }));
    /// assert!(Command::parse_args(&["minreal", "x.json", "--method", "magic"]).is_err());
    /// ```
    pub fn parse_args<S: AsRef<str>>(args: &[S]) -> Result<Command, String> {
        Args::try_parse_from(args.iter().map(|s| s.as_ref().to_string()))
            .map(|a| a.command)
            .map_err(|e| {
                let t = e.render().to_string();
                let first = t.lines().find(|l| !l.trim().is_empty()).unwrap_or("");
                first.trim().trim_start_matches("error:").trim().to_string()
            })
    }
}

/// Writes the rendered output: `Ok` also when the reader went away (broken pipe: a quiet
/// stop, as `exactlti analyze | head -1` expects); any other write error is returned.
pub fn write_stdout(text: &str) -> std::io::Result<()> {
    use std::io::Write;
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
        other => other,
    }
}
