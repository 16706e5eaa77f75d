//! `linalg` on a plain rational matrix file: the command line's fast path (issue 29, where
//! the command line's floor, not the kernel, kept `linalg rank|rref|nullspace` of a 100x100
//! rational matrix above 2x python-flint).
//!
//! A JSON file holding only a square matrix `A` of plain rational entries is read in one
//! pass ([`plain_square_matrix`], no proxy tree, no expression parser) and its report is
//! built for the one output the command line prints ([`Target`]: no LaTeX strings, float
//! approximations only where shown). The report is the general path's (the system's `A`
//! through [`super::common::linalg_report`]); every other file, and every file with
//! `--symbolic` / `--at`, goes to the general reader, which also gives every error message.

use super::common::linalg_report_for;
use super::{Command, Failure, Format, Outcome, RunContext};
use crate::io::SystemFormat;
use crate::io::plain_matrix::plain_square_matrix;
use crate::io::symbolic::SymbolicOptions;
use crate::report::Target;

/// `linalg OP FILE` on a plain rational matrix file; `None` for every other command or file.
pub(super) fn fast(
    cmd: &Command,
    opts: &SymbolicOptions,
    ctx: &RunContext,
) -> Option<Result<Outcome, Failure>> {
    let Command::Linalg { op, file } = cmd else {
        return None;
    };
    if !opts.is_empty() {
        return None;
    }
    let text = crate::io::read_text(file).ok()?;
    if SystemFormat::of(file, &text) != SystemFormat::Json {
        return None;
    }
    let a = plain_square_matrix(&text, "A")?;
    drop(text);
    Some(linalg_report_for(*op, &a, file, target(ctx)).map(Outcome::plain))
}

/// The output the report is for: the command line's `--format` (and `--full`); every
/// rendering in process.
fn target(ctx: &RunContext) -> Target {
    match ctx.stdout {
        None => Target::Every,
        Some(Format::Json) => Target::Json,
        Some(Format::Text) => Target::Text { full: ctx.full },
        Some(Format::Latex) => Target::Latex,
    }
}
