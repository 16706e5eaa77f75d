//! The `exactlti` command line (contract: ../shared/CLI-CONTRACT.md).
//!
//! Thin: arguments → a [`crate::api::Command`] → [`crate::api::execute_ctx`] (the library's
//! front door) → [`crate::report::Report`] → text/JSON/LaTeX.
//! Exit status 0 on success; 2 for bad input or a request that cannot be met (one line on
//! stderr naming the file, key, row and column, or the violated condition); 1 for an
//! internal failure (an exact verification that failed). Long exact work is bounded by
//! `--max-seconds` (default 600).

pub mod memory;
mod progress;

pub use crate::api::{
    Command, Failure, Format, LinalgOp, MethodArg, Outcome, PolyCmd, TimeOpts, budget, execute,
    plots,
};

use crate::api::runner::{Poll, Worker};
use crate::report::Report;
use clap::Parser;
use std::sync::mpsc;
use std::time::{Duration, Instant};

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
    #[arg(long, global = true, default_value_t = 600.0, value_name = "SECONDS", value_parser = crate::api::parse_seconds, allow_hyphen_values = true)]
    pub max_seconds: f64,
    /// Memory budget in MiB (0: none). An allocation past it stops the command with one line
    /// on stderr and exit 2 instead of exhausting the machine (see `exactlti::cli::memory`).
    #[arg(long, global = true, default_value_t = memory::DEFAULT_MAX_MEMORY_MIB, value_name = "MIB")]
    pub max_memory: u64,
    /// Keep these parameters as symbols (comma separated; alone: every parameter). A word
    /// after `--symbolic` that is not a list of names (a path such as `x.toml`, or an
    /// existing file) is not taken as NAMES: `--symbolic FILE` is `--symbolic` alone and the
    /// FILE; `--symbolic=NAMES` always takes NAMES.
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

impl Cli {
    /// Parses the command line ([`symbolic_alone`] first, then clap).
    ///
    /// # Errors
    /// clap's error (help and version included).
    pub fn try_parse_args(
        args: impl IntoIterator<Item = std::ffi::OsString>,
    ) -> Result<Self, clap::Error> {
        use clap::{CommandFactory, FromArgMatches};
        let mut cmd = Self::command();
        let parsed = cmd
            .try_get_matches_from_mut(symbolic_alone(args.into_iter().collect()))
            .and_then(|mut m| Self::from_arg_matches_mut(&mut m));
        // the command tree (every subcommand and option) is not needed again and the
        // process ends after this command: not freed piece by piece (1.5% of a short run)
        std::mem::forget(cmd);
        parsed
    }
}

/// Is `w` a value of `--symbolic` (names separated by commas or spaces, at least one; not a
/// file that exists)?
fn names_list(w: &std::ffi::OsStr) -> bool {
    let Some(w) = w.to_str() else {
        return false;
    };
    let mut any = false;
    for name in w.split([',', ' ']).filter(|x| !x.is_empty()) {
        let mut cs = name.chars();
        let first_ok = cs
            .next()
            .is_some_and(|c| c.is_ascii_alphabetic() || c == '_');
        if !first_ok || !cs.all(|c| c.is_ascii_alphanumeric() || c == '_') {
            return false;
        }
        any = true;
    }
    any && !std::path::Path::new(w).is_file()
}

/// `--symbolic WORD` with a WORD that is not a list of names ([`names_list`]: a path such as
/// `data/models/x.toml`, or an existing file) becomes `--symbolic=` (every parameter) and
/// the WORD stays an argument of its own (the FILE); without this the optional value of
/// `--symbolic` swallowed the file (`analyze --symbolic x.toml` read `x.toml` as names).
/// `--symbolic=NAMES` is left as written. Arguments after `--` are not looked at.
pub fn symbolic_alone(mut args: Vec<std::ffi::OsString>) -> Vec<std::ffi::OsString> {
    let mut i = 1;
    while i + 1 < args.len() {
        if args[i] == "--" {
            break;
        }
        if args[i] == "--symbolic" && !args[i + 1].to_string_lossy().starts_with('-') {
            if !names_list(&args[i + 1]) {
                args[i] = "--symbolic=".into();
            }
            i += 1;
        }
        i += 1;
    }
    args
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
        Format::Text => crate::report::escape::escaped_report(r)
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

use crate::api::write_stdout;

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
    let ctx = crate::api::RunContext {
        start,
        max_seconds: limit,
        events: streams.then_some(tx),
        full,
        stdout: Some(format),
    };
    let deadline = start + Duration::from_secs_f64(limit.clamp(1e-3, 1e7));
    let work = move || {
        let (sym, at) = (cli.symbolic.as_deref(), cli.at.as_deref());
        if with_steps {
            crate::api::steps::execute(&cli.command, sym, at, format, standalone)
        } else {
            crate::api::execute_ctx(&cli.command, sym, at, &ctx)
        }
    };
    let worker = match Worker::spawn("exactlti-worker", Some(deadline), work) {
        Ok(w) => w,
        Err(m) => {
            say(&m);
            return 1;
        }
    };
    let mut printer = progress::Printer::new(full);
    let tick = Duration::from_millis(if streams { 20 } else { 100 });
    let stopped = |printer: &mut progress::Printer| {
        printer.clear();
        say(&format!(
            "stopped after --max-seconds {limit}: the exact computation did not finish in time"
        ));
        2
    };
    loop {
        // the streamed sections first (in order), then the result; what arrives after the
        // bound (this thread was not scheduled in time) is not printed: --max-seconds holds
        // however the threads are scheduled
        while let Ok(ev) = rx.try_recv() {
            if Instant::now() > deadline {
                return stopped(&mut printer);
            }
            if let Err(e) = printer.event(ev) {
                printer.clear();
                say(&format!("cannot write the output: {e}"));
                return 2;
            }
        }
        match worker.poll(tick) {
            Poll::Pending => printer.tick(start.elapsed()),
            Poll::Done(_) if Instant::now() > deadline => return stopped(&mut printer),
            Poll::Done(r) => {
                for ev in rx.try_iter() {
                    if let Err(e) = printer.event(ev) {
                        printer.clear();
                        say(&format!("cannot write the output: {e}"));
                        return 2;
                    }
                }
                printer.clear();
                return finish(r, &mut printer, format, standalone);
            }
            Poll::TimedOut => return stopped(&mut printer),
            Poll::Panicked(_) => {
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
