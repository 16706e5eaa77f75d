//! `exactlti sweep FILE --param v --from a --to b --points N [--svg F] [--locus-svg F]
//! [--csv F]`: float eigenvalues of $A(v)$ along the parameter, in parallel, with a progress
//! bar when stderr is a terminal.

use super::{Failure, Outcome};
use crate::report::plot::sweep::{root_locus_svg, sweep_svg};
use crate::report::{Report, Value};
use crate::study::{ParamFamily, PointStatus, SweepResult, sweep, sweep_values};
use std::io::IsTerminal;
use std::path::Path;

/// Options of `sweep`.
pub struct SweepArgs<'a> {
    pub file: &'a Path,
    pub param: &'a str,
    /// `--at`: values of other parameters (overriding the file's).
    pub at: &'a [(String, String)],
    pub from: f64,
    pub to: f64,
    pub points: usize,
    pub svg: Option<&'a Path>,
    pub locus_svg: Option<&'a Path>,
    pub csv: Option<&'a Path>,
}

fn write(p: &Path, text: &str) -> Result<(), Failure> {
    std::fs::write(p, text).map_err(|e| Failure {
        code: 2,
        message: format!("{}: cannot write: {e}", p.display()),
    })
}

/// Runs `sweep`.
pub fn run(a: &SweepArgs<'_>) -> Result<Outcome, Failure> {
    if !(a.from.is_finite()
        && a.to.is_finite()
        && a.from <= a.to
        && (1..=1_000_000).contains(&a.points))
    {
        return Err(Failure {
            code: 2,
            message: format!(
                "sweep: need finite --from <= --to and 1 <= --points <= 1000000 (got {}, {}, {})",
                a.from, a.to, a.points
            ),
        });
    }
    crate::io::read_system_file(a.file)?; // the file is a valid system
    let fam = ParamFamily::from_file_at(a.file, a.param, a.at)?;
    let values = sweep_values(a.from, a.to, a.points);
    let bar = std::io::stderr().is_terminal().then(|| {
        let b = indicatif::ProgressBar::new(values.len() as u64);
        b.set_style(
            indicatif::ProgressStyle::with_template(
                "sweep {bar:40} {pos}/{len} {per_sec} eta {eta}",
            )
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
        );
        b
    });
    let tick = |k: usize| {
        if let Some(b) = &bar
            && k.is_multiple_of(64)
        {
            b.set_position(k as u64);
        }
    };
    let sw = sweep(&fam, &values, Some(&tick))?;
    if let Some(b) = bar {
        b.finish_and_clear();
    }
    let name = fam
        .name
        .clone()
        .unwrap_or_else(|| a.file.display().to_string());
    let xlabel = format!("{} (parameter)", a.param);
    if let Some(p) = a.svg {
        write(
            p,
            &sweep_svg(
                &sw,
                &format!("{name}: eigenvalues against {}", a.param),
                &xlabel,
                &[],
            ),
        )?;
    }
    if let Some(p) = a.locus_svg {
        write(
            p,
            &root_locus_svg(&sw, &format!("{name}: root locus in {}", a.param)),
        )?;
    }
    if let Some(p) = a.csv {
        write(p, &sw.to_csv())?;
    }
    let r = Report::titled(format!("sweep of {} over [{}, {}]", a.param, a.from, a.to))
        .str("param", a.param)
        .int("points", values.len());
    let r = status_fields(r, &sw, a.param);
    let stable = sw
        .eigenvalues
        .iter()
        .filter(|ev| !ev.is_empty() && ev.iter().all(|z| z.re < 0.0))
        .count();
    let r = r
        .int("stable_points", stable)
        .list("values", values.iter().map(|v| Value::Float(*v)).collect())
        .list(
            "eigenvalues_approx",
            sw.eigenvalues
                .iter()
                .map(|ev| {
                    Value::List(
                        ev.iter()
                            .map(|z| Value::List(vec![Value::Float(z.re), Value::Float(z.im)]))
                            .collect(),
                    )
                })
                .collect(),
        );
    Ok(Outcome::plain(r))
}

/// `method`, and where needed `infinite_eigenvalues[]` (per point) and `notes[]` (one per
/// point without eigenvalues: `index`, `value`, `reason`, `note`).
fn status_fields(r: Report, sw: &SweepResult, param: &str) -> Report {
    let descriptor = sw
        .status
        .iter()
        .any(|s| matches!(s, PointStatus::Descriptor { .. }));
    let method = if descriptor {
        "finite eigenvalues of the pencil det(sE - A) = 0: their number exact, their values by shift-and-invert in floating point; eigenvalues of A(v) where E(v) is invertible"
    } else {
        "eigenvalues of A(v) in floating point (balanced real Schur)"
    };
    let mut r = r.str("method", method);
    if descriptor {
        let inf = sw.status.iter().map(|s| match s {
            PointStatus::Descriptor { infinite } => Value::Int(*infinite as i64),
            _ => Value::Int(0),
        });
        r = r.list("infinite_eigenvalues", inf.collect());
    }
    let notes: Vec<Value> = sw
        .status
        .iter()
        .zip(&sw.values)
        .enumerate()
        .filter_map(|(i, (s, v))| {
            let (reason, why) = match s {
                PointStatus::Pole => ("pole", "an entry of the matrices has a pole"),
                PointStatus::SingularPencil => (
                    "singular_pencil",
                    "det(sE - A) = 0 for every s (a singular pencil)",
                ),
                PointStatus::Failed => ("failed", "the float eigenvalue computation failed"),
                _ => return None,
            };
            Some(Value::Obj(
                Report::new()
                    .int("index", i)
                    .float("value", *v)
                    .str("reason", reason)
                    .str("note", format!("{param} = {v}: {why}; no eigenvalues")),
            ))
        })
        .collect();
    if !notes.is_empty() {
        r = r.list("notes", notes);
    }
    r
}
