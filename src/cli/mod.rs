//! The `exactlti` command line (contract: ../shared/CLI-CONTRACT.md).
//!
//! Thin: arguments → [`crate::io`] → library → [`crate::report::Report`] → text/JSON/LaTeX.
//! Exit status 0 on success; 2 for bad input or a request that cannot be met (one line on
//! stderr naming the file, key, row and column, or the violated condition); 1 for an
//! internal failure (an exact verification that failed). Long exact work is bounded by
//! `--max-seconds` (default 600).

mod a_only;
mod analyze;
mod args;
mod bifurcations;
pub mod budget;
mod commands;
mod common;
mod critical;
mod dcgain;
mod float_cmds;
mod float_compare;
mod interconnect;
pub mod memory;
mod pencil_cmds;
pub mod plots;
mod progress;
mod steps;
mod sweep;
mod sweep_stream;
mod symbolic;
mod symbolic_jordan;

pub use args::{LinalgOp, MethodArg, PolyCmd, TimeOpts};
/// One command run in-process (no output, no time bound): the report and its status.
pub use commands::execute;

use crate::error::Error;
use crate::report::Report;
use budget::Event;
use clap::{Parser, Subcommand, ValueEnum};
use std::path::PathBuf;
use std::sync::mpsc;
use std::time::{Duration, Instant};

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
    about = "Exact structure of linear time-invariant systems: Jordan forms, minimal realizations, special coordinate basis, mechanical normal form",
    after_help = "FILE is a system file: JSON, or TOML when it ends in .toml. Keys: A, B, C, D \
(x' = A x + B u, y = C x + D u), E for a descriptor system (E x' = A x + B u), or the \
second-order form M, L, K, F (M q'' + L q' + K q = F u), or G (a transfer matrix in s); \
entries exact (0.08 is 2/25) and may use `parameters`. Exit status: 0 success, 1 an exact \
check failed, 2 bad input or a request that cannot be met (one line on stderr), 3 the float \
path disagrees with the exact one (check, ERA)."
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
    /// Output format: text (for reading), json (every exact entry as a string plus
    /// `<name>_approx` numbers), latex (a fragment for an amsmath document).
    #[arg(long, global = true, value_enum, default_value_t = Format::Text)]
    pub format: Format,
    /// With `--format latex`: a complete LaTeX document instead of a fragment.
    #[arg(long, global = true)]
    pub standalone: bool,
    /// Upper bound on the wall time in seconds (a number > 0); exceeded: exit 2.
    #[arg(long, global = true, default_value_t = 600.0, value_name = "SECONDS", value_parser = parse_seconds, allow_hyphen_values = true)]
    pub max_seconds: f64,
    /// Memory budget in MiB (0: none). An allocation past it stops the command with one line
    /// on stderr and exit 2 instead of exhausting the machine (see `exactlti::cli::memory`).
    #[arg(long, global = true, default_value_t = memory::DEFAULT_MAX_MEMORY_MIB, value_name = "MIB")]
    pub max_memory: u64,
    /// Keep these parameters as symbols (comma separated; alone: every parameter).
    #[arg(long, global = true, num_args = 0..=1, default_missing_value = "", value_name = "NAMES")]
    pub symbolic: Option<String>,
    /// Values for parameters or symbols before the computation, e.g. "m=1500, u=20".
    #[arg(long, global = true, value_name = "VALUES", allow_hyphen_values = true)]
    pub at: Option<String>,
    /// Text output: print every matrix in full (by default a matrix wider than 100 columns
    /// or with long entries is shown approximately, with its shape and fields; JSON and
    /// LaTeX are always complete).
    #[arg(long, global = true)]
    pub full: bool,
    /// `jordan`, `minreal --method kalman|jordan`: the derivation step by step (each step's
    /// sentence, exact objects, identity and its check; over Q(p) what it assumes).
    #[arg(long, global = true)]
    pub steps: bool,
}

#[derive(Subcommand, Debug)]
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
        /// Lowest frequency in Hz (> 0).
        #[arg(long, default_value_t = 0.01, value_name = "HZ")]
        from: f64,
        /// Highest frequency in Hz (> --from).
        #[arg(long, default_value_t = 10.0, value_name = "HZ")]
        to: f64,
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
    /// of A over Q (evaluated in floats), float matrix exponential otherwise; with the exact
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

/// `--max-seconds`: a finite number of seconds greater than zero (at most 10^7).
fn parse_seconds(text: &str) -> Result<f64, String> {
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

/// Renders a report in the chosen format (`--standalone` off, compact text).
pub fn render(r: &Report, f: Format) -> String {
    render_with(r, f, false)
}

/// Renders a report; `standalone` wraps LaTeX in a complete document. Text output shows
/// control characters in strings escaped (`\n`, `\u{1b}`), so that a name cannot forge
/// lines; JSON is escaped by serde; LaTeX escapes every string it prints.
pub fn render_with(r: &Report, f: Format, standalone: bool) -> String {
    render_full(r, f, standalone, false)
}

/// As [`render_with`]; `full` prints every matrix of the text output in full.
pub fn render_full(r: &Report, f: Format, standalone: bool, full: bool) -> String {
    match f {
        Format::Text => crate::report::escape::escape_control_report(r)
            .to_text_with(&crate::report::TextOptions::cli(full)),
        Format::Json => serde_json::to_string_pretty(&r.to_json()).unwrap_or_default() + "\n",
        Format::Latex if standalone => crate::report::latex::standalone(r),
        Format::Latex => crate::report::latex::fragment(r),
    }
}

/// One line on stderr (control characters escaped: a file name cannot break the one-line
/// contract); a closed stderr is ignored.
fn say(msg: &str) {
    use std::io::Write;
    let line = crate::report::escape::escape_control(msg);
    let _ = writeln!(std::io::stderr().lock(), "exactlti: {line}");
}

/// Writes the rendered output: `Ok` also when the reader went away (broken pipe: a quiet
/// stop, as `exactlti analyze | head -1` expects); any other write error is returned.
fn write_stdout(text: &str) -> std::io::Result<()> {
    use std::io::Write;
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
        other => other,
    }
}

/// The one line (contract) for an option-parser error, and its exit status: `None` for
/// `--help` / `--version`, which clap prints itself (exit 0).
pub fn parse_error_line(e: &clap::Error) -> Option<String> {
    use clap::error::ErrorKind;
    if matches!(e.kind(), ErrorKind::DisplayHelp | ErrorKind::DisplayVersion) {
        return None;
    }
    if e.kind() == ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand {
        return Some(
            "a command is required (jordan, minreal, scb, zeros, analyze, ...; see exactlti --help)"
                .into(),
        );
    }
    let text = e.render().to_string();
    let mut what = Vec::new();
    let mut usage = None;
    for l in text.lines().map(str::trim).filter(|l| !l.is_empty()) {
        if let Some(u) = l.strip_prefix("Usage:") {
            usage = Some(u.trim().to_string());
        } else if l.starts_with("For more information") {
            continue;
        } else if let Some(tip) = l.strip_prefix("tip:") {
            // "to pass '-x' as a value, use '-- -x'" is noise; near misses help
            if !tip.contains("as a value") {
                what.push(tip.trim().to_string());
            }
        } else {
            what.push(l.strip_prefix("error:").unwrap_or(l).trim().to_string());
        }
    }
    let mut line = String::new();
    for w in what {
        if !line.is_empty() {
            line.push_str(if line.ends_with(':') { " " } else { "; " });
        }
        line.push_str(&w);
    }
    if let Some(u) = usage {
        line.push_str(&format!(" (usage: {u})"));
    }
    Some(crate::report::escape::escape_control(&line))
}

/// Prints a parse error as one line (or clap's help/version) and returns the exit status.
pub fn report_parse_error(e: &clap::Error) -> i32 {
    match parse_error_line(e) {
        None => {
            let _ = e.print();
            0
        }
        Some(line) => {
            say(&line);
            2
        }
    }
}

/// Runs the command line; returns the process exit code.
///
/// The command runs in a worker thread; this thread waits at most `--max-seconds`, prints
/// what streams (the sections of `analyze` in text mode, as each is done) and shows a
/// progress line on stderr when stderr is a terminal and the work takes more than a second.
pub fn run(cli: Cli) -> i32 {
    let start = Instant::now();
    let format = cli.format;
    let standalone = cli.standalone;
    let full = cli.full;
    let with_steps = cli.steps;
    let limit = cli.max_seconds;
    memory::set_max_memory_mib(cli.max_memory);
    let (tx, rx) = mpsc::channel();
    let streams = format == Format::Text && matches!(cli.command, Command::Analyze { .. });
    let ctx = commands::RunContext {
        start,
        max_seconds: limit,
        events: streams.then(|| tx.clone()),
        full,
        stdout: Some(format),
    };
    let handle = std::thread::Builder::new()
        .stack_size(256 << 20)
        .spawn(move || {
            let (sym, at) = (cli.symbolic.as_deref(), cli.at.as_deref());
            let r = if with_steps {
                steps::execute(&cli.command, sym, at, format, standalone)
            } else {
                commands::execute_ctx(&cli.command, sym, at, &ctx)
            };
            let _ = tx.send(Event::Finished(Box::new(r)));
        });
    if handle.is_err() {
        say("could not start the worker thread");
        return 1;
    }
    let wait = if limit.is_finite() && limit > 0.0 {
        Duration::from_secs_f64(limit.min(1e7))
    } else {
        Duration::from_secs(600)
    };
    let deadline = start + wait;
    let mut printer = progress::Printer::new(full);
    loop {
        let now = Instant::now();
        let Some(left) = deadline
            .checked_duration_since(now)
            .filter(|d| !d.is_zero())
        else {
            printer.clear();
            say(&format!(
                "stopped after --max-seconds {limit}: the exact computation did not finish in time"
            ));
            return 2;
        };
        let got = rx.recv_timeout(left.min(Duration::from_millis(100)));
        if got.is_ok() && Instant::now() > deadline {
            // what arrives after the bound (this thread was not scheduled in time) is not
            // printed: --max-seconds holds however the threads are scheduled
            printer.clear();
            say(&format!(
                "stopped after --max-seconds {limit}: the exact computation did not finish in time"
            ));
            return 2;
        }
        match got {
            Ok(Event::Finished(r)) => {
                printer.clear();
                return finish(*r, &mut printer, format, standalone);
            }
            Ok(ev) => {
                if let Err(e) = printer.event(ev) {
                    printer.clear();
                    say(&format!("cannot write the output: {e}"));
                    return 2;
                }
            }
            Err(mpsc::RecvTimeoutError::Timeout) => printer.tick(start.elapsed()),
            Err(mpsc::RecvTimeoutError::Disconnected) => {
                printer.clear();
                say("internal failure (the computation panicked)");
                return 1;
            }
        }
    }
}

/// Prints the rest of the result (what did not stream) and returns the exit status.
fn finish(
    r: Result<Outcome, Failure>,
    printer: &mut progress::Printer,
    format: Format,
    standalone: bool,
) -> i32 {
    match r {
        Ok(out) => {
            let written = if out.streamed {
                Ok(())
            } else if printer.streamed() {
                printer.rest(&out.report)
            } else {
                write_stdout(&render_full(&out.report, format, standalone, printer.full))
            };
            if let Err(e) = written {
                say(&format!("cannot write the output: {e}"));
                return 2;
            }
            if !out.verified {
                say("an exact verification failed (verified = false)");
                1
            } else if out.float_disagrees {
                // contract, second wave: 3 = the float path disagrees with the exact one
                say("the float path disagrees with the exact path (see the report)");
                3
            } else if let Some(m) = &out.stopped {
                say(m);
                2
            } else {
                0
            }
        }
        Err(f) => {
            say(&f.message);
            f.code
        }
    }
}
