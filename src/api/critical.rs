//! `exactlti critical FILE --param v --from a --to b [--digits N]`: exact critical values of
//! one parameter (zero eigenvalue, imaginary pair, double eigenvalue) as algebraic numbers,
//! and the intervals between them with stability and eigenvalue counts.

use super::{Failure, Outcome};
use crate::field::QuadraticField;
use crate::field::Rational;
use crate::report::critical_report as report;
use crate::study::critical::over_k::critical_values_of_file;
use crate::study::{ParamFamily, critical_values};
use std::path::Path;

/// Options of `critical`.
pub struct CriticalArgs<'a> {
    pub file: &'a Path,
    pub param: &'a str,
    /// `--at`: values of other parameters (overriding the file's).
    pub at: &'a [(String, String)],
    pub from: &'a str,
    pub to: &'a str,
    pub digits: usize,
}

impl<'a> CriticalArgs<'a> {
    /// The arguments of a `critical` command on the system at `file` (`None` for other
    /// commands).
    pub fn of(cmd: &'a super::Command, file: &'a Path, at: &'a [(String, String)]) -> Option<Self> {
        let super::Command::Critical {
            param,
            from,
            to,
            digits,
            ..
        } = cmd
        else {
            return None;
        };
        Some(CriticalArgs {
            file,
            param,
            at,
            from,
            to,
            digits: *digits,
        })
    }
}

fn bound(s: &str, what: &str) -> Result<Rational, Failure> {
    crate::io::expr::parse_number(s.trim())
        .map_err(|e| Failure::input(format!("critical: --{what} '{s}': {}", e.msg)))
}

/// The bounds and `--digits` of `critical`, checked.
fn checked(a: &CriticalArgs<'_>) -> Result<(Rational, Rational), Failure> {
    let (from, to) = (bound(a.from, "from")?, bound(a.to, "to")?);
    if from > to || !(1..=super::args::MAX_DIGITS).contains(&a.digits) {
        return Err(Failure::input(format!(
            "critical: need --from <= --to and 1 <= --digits <= {} (got {}, {}, {})",
            super::args::MAX_DIGITS,
            a.from,
            a.to,
            a.digits
        )));
    }
    Ok((from, to))
}

/// Runs `critical`.
pub fn run(a: &CriticalArgs<'_>) -> Result<Outcome, Failure> {
    let (from, to) = checked(a)?;
    // the file was read as a system by the caller ([`crate::api::System::open`]; the
    // parameter studied may be `null`: a symbol)
    let fam = ParamFamily::from_file_at(a.file, a.param, a.at)?;
    let cv = critical_values(&fam, &from, &to)?;
    Ok(Outcome::new(report(&cv, a.digits), cv.verified))
}

/// Runs `critical` on a system whose entries lie in `k` ($\mathbb{Q}(\sqrt d)$,
/// $\mathbb{Q}(i)$): the family read over $K(v)$ ([`critical_values_of_file`]).
pub fn run_field(a: &CriticalArgs<'_>, k: &QuadraticField) -> Result<Outcome, Failure> {
    let (from, to) = checked(a)?;
    let cv = critical_values_of_file(a.file, a.param, a.at, k, &from, &to)?;
    Ok(Outcome::new(report(&cv, a.digits), cv.verified))
}
