//! `exactlti critical FILE --param v --from a --to b [--digits N]`: exact critical values of
//! one parameter (zero eigenvalue, imaginary pair, double eigenvalue) as algebraic numbers,
//! and the intervals between them with stability and eigenvalue counts.

use super::{Failure, Outcome};
use crate::algebraic::AlgebraicNumber;
use crate::field::QuadraticField;
use crate::field::{Rational, fmt_rational};
use crate::report::{Report, Value};
use crate::study::critical::over_k::critical_values_of_file;
use crate::study::{CriticalValues, ParamFamily, critical_values};
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
        .map_err(|e| Failure::input(format!("critical: --{what} '{s}': {}", e)))
}

fn number(a: &AlgebraicNumber, digits: usize) -> Report {
    // isolating interval refined to about the displayed precision
    let w = Rational::new(
        1.into(),
        num_bigint::BigInt::from(10).pow(digits.min(60) as u32),
    );
    let a = &a.refined(&w).unwrap_or_else(|_| a.clone());
    let (lo, hi) = a.interval().unwrap_or_default();
    Report::new()
        .str("value", a.value_string())
        .float("approx", a.approx().0)
        .str("digits", a.digits(digits).0)
        .str("minpoly", a.minpoly().to_string())
        .list(
            "interval",
            vec![Value::Str(fmt_rational(&lo)), Value::Str(fmt_rational(&hi))],
        )
}

/// The report of a [`CriticalValues`] (contract keys `critical_values[]`, `intervals[]`).
pub fn report(cv: &CriticalValues, digits: usize) -> Report {
    let doubled = cv.over_field.as_ref().is_some_and(|f| f.doubled);
    let crit: Vec<Value> = cv
        .critical
        .iter()
        .map(|c| {
            let mut r = number(&c.value, digits).str("kind", c.kind.name());
            if let Some(h) = &c.minpoly_over_field {
                r = r.str("minpoly_over_field", h.to_string());
            }
            if let Some(w) = c.omega {
                r = r.float("omega", w);
            }
            let eig: Vec<Value> = c
                .eigenvalues_at
                .iter()
                .map(|e| {
                    let mut o = Report::new()
                        .list(
                            "approx",
                            vec![Value::Float(e.approx.0), Value::Float(e.approx.1)],
                        )
                        .int("algebraic_multiplicity", e.multiplicity)
                        .list(
                            "blocks",
                            e.blocks.iter().map(|b| Value::Int(*b as i64)).collect(),
                        );
                    if !e.factor.is_empty() {
                        o = o.str("factor", e.factor.clone());
                    }
                    Value::Obj(o)
                })
                .collect();
            Value::Obj(r.bool("certified", c.certified).list("eigenvalues_at", eig))
        })
        .collect();
    let ivs: Vec<Value> = cv
        .intervals
        .iter()
        .map(|iv| {
            let c = &iv.counts;
            Value::Obj(
                Report::new()
                    .str("from", iv.from.value_string())
                    .str("to", iv.to.value_string())
                    .float("from_approx", iv.from.approx().0)
                    .float("to_approx", iv.to.approx().0)
                    .str("sample", fmt_rational(&iv.sample))
                    .bool("stable", iv.stable)
                    .int(
                        "unstable_eigenvalues",
                        if doubled {
                            c.unstable() / 2
                        } else {
                            c.unstable()
                        },
                    )
                    .int("real_negative", c.real_negative)
                    .int("zero", c.zero)
                    .int("real_positive", c.real_positive)
                    .int("complex_pairs_stable", c.complex_pairs_stable)
                    .int("imaginary_pairs", c.imaginary_pairs)
                    .int("complex_pairs_unstable", c.complex_pairs_unstable),
            )
        })
        .collect();
    let rejected: Vec<Value> = cv
        .rejected
        .iter()
        .map(|(a, why)| Value::Obj(number(a, digits).str("reason", why.clone())))
        .collect();
    let charpoly: Vec<Value> = match &cv.over_field {
        Some(f) => f
            .charpoly
            .iter()
            .map(|c| Value::Str(c.to_string_var(&cv.param)))
            .collect(),
        None => cv
            .charpoly
            .coeffs
            .iter()
            .map(|c| Value::Str(c.to_string_var(&cv.param)))
            .collect(),
    };
    let out = Report::titled(format!(
        "critical values of {} on [{}, {}]",
        cv.param,
        fmt_rational(&cv.from),
        fmt_rational(&cv.to)
    ))
    .str("param", cv.param.clone());
    let out = match &cv.over_field {
        Some(f) if f.doubled => out
            .str("field", f.field.to_string())
            .str(
                "counts_of",
                "A(v) and its complex conjugate (same real parts; unstable_eigenvalues is that of A(v))",
            ),
        Some(f) => out.str("field", f.field.to_string()),
        None => out,
    };
    out.list("critical_values", crit)
        .list("intervals", ivs)
        .list("rejected", rejected)
        .list(
            "singular_values",
            cv.singular
                .iter()
                .zip(&cv.singular_reasons)
                .map(|(a, why)| Value::Obj(number(a, digits).str("reason", why.name())))
                .collect(),
        )
        .list(
            "persistent",
            cv.persistent
                .iter()
                .map(|k| Value::Str(k.name().into()))
                .collect(),
        )
        .list("charpoly_coeffs", charpoly)
        .bool("verified", cv.verified)
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
