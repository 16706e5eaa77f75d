//! `exactlti sweep FILE --param v --from a --to b --points N [--svg F] [--locus-svg F]
//! [--csv F]`: float eigenvalues of $A(v)$ along the parameter, in parallel, with a progress
//! bar when stderr is a terminal.

use super::sweep_field::FieldFamily;
use super::sweep_stream::{CsvSink, Sink};
use super::{Failure, Outcome};
use crate::report::plot::sweep::{root_locus_svg, sweep_svg};
use crate::report::{Report, Value};
use crate::study::{ParamFamily, PointStatus, SweepResult, sweep, sweep_values};
use num_complex::Complex;
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

impl<'a> SweepArgs<'a> {
    /// The arguments of a `sweep` command on the system at `file` (`None` for other commands).
    pub fn of(cmd: &'a super::Command, file: &'a Path, at: &'a [(String, String)]) -> Option<Self> {
        let super::Command::Sweep {
            param,
            from,
            to,
            points,
            svg,
            locus_svg,
            csv,
            ..
        } = cmd
        else {
            return None;
        };
        Some(SweepArgs {
            file,
            param,
            at,
            from: *from,
            to: *to,
            points: *points,
            svg: svg.as_deref(),
            locus_svg: locus_svg.as_deref(),
            csv: csv.as_deref(),
        })
    }
}

fn write(p: &Path, text: &str) -> Result<(), Failure> {
    std::fs::write(p, text)
        .map_err(|e| Failure::input(format!("{}: cannot write: {e}", p.display())))
}

/// Parameter values computed per batch (each batch in parallel, then written out).
const BATCH: usize = 4096;

/// Sweeps with more points than this write their report row by row (`--format json|text` on
/// stdout), so that memory does not grow with `--points`.
pub const STREAM_POINTS: usize = 10_000;

/// At most this many rows are kept for the plots (evenly spaced; the plots draw 1500).
const PLOT_ROWS: usize = 15_000;

/// The number of eigenvalues of the family (columns of the CSV).
fn family_dim(fam: &ParamFamily) -> usize {
    fam.nstates()
}

/// The family swept: exact over $\mathbb{Q}(v)$ ([`ParamFamily`]), or read again over its
/// extension field at each value ([`FieldFamily`]).
enum Family<'a> {
    Exact(Box<ParamFamily>),
    Field(FieldFamily<'a>),
}

impl Family<'_> {
    fn dim(&self) -> usize {
        match self {
            Family::Exact(f) => family_dim(f),
            Family::Field(f) => f.dim(),
        }
    }
    fn name(&self) -> Option<String> {
        match self {
            Family::Exact(f) => f.name.clone(),
            Family::Field(f) => f.name(),
        }
    }
    /// The finite limits of the eigenvalue branches as the parameter grows without bound:
    /// the roots of [`crate::study::bivar::BiPolyOver::lead_in_v`] of $\det(xE(v) - A(v))$
    /// (exact polynomial, roots approximated from their certified regions). Empty for an
    /// extension-field family, or when the polynomial cannot be formed within its limits
    /// (the plot then marks only the sweep's ends).
    fn limits(&self) -> Vec<Complex<f64>> {
        let Family::Exact(f) = self else {
            return vec![];
        };
        let Ok(p) = crate::study::bivar::charpoly_xv(f) else {
            return vec![];
        };
        let lead = p.lead_in_v();
        if lead.degree().unwrap_or(0) == 0 {
            return vec![];
        }
        crate::algebraic::roots(&lead)
            .map(|rs| {
                rs.iter()
                    .map(|(r, _)| {
                        let (re, im) = r.approx();
                        Complex::new(re, im)
                    })
                    .collect()
            })
            .unwrap_or_default()
    }
    fn sweep(&self, batch: &[f64], tick: &(dyn Fn(usize) + Sync)) -> Result<SweepResult, Failure> {
        match self {
            Family::Exact(f) => Ok(sweep(f, batch, Some(tick))?),
            Family::Field(f) => f.sweep(batch, tick),
        }
    }
}

/// Runs `sweep` of a system whose entries lie in an extension field (the system as read;
/// see [`FieldFamily`]); as [`run`] otherwise.
pub fn run_field(
    a: &SweepArgs<'_>,
    sys: &super::System,
    stream: Option<super::Format>,
) -> Result<Outcome, Failure> {
    check_args(a)?;
    let fam = Family::Field(FieldFamily::new(sys, a.param)?);
    run_family(a, &fam, stream)
}

/// Runs `sweep`; `stream`: the output format when the report may be written to stdout row by
/// row (the command line; `None` in process).
pub fn run(a: &SweepArgs<'_>, stream: Option<super::Format>) -> Result<Outcome, Failure> {
    check_args(a)?;
    // the file was read as a system by the caller ([`crate::api::System::open`]; the
    // parameter swept may be `null`: a symbol)
    let fam = Family::Exact(Box::new(ParamFamily::from_file_at(a.file, a.param, a.at)?));
    run_family(a, &fam, stream)
}

/// The eigenvalues along `param` at each of `values`, the file at `path` read as the command
/// line reads it for `sweep` (one loader, [`super::System::open`] with `opts`): a system
/// over $\mathbb{Q}(\sqrt d)$ or $\mathbb{Q}(i)$ is read again at each value
/// ([`FieldFamily`]), a system over $\mathbb{Q}$ (or with the swept parameter a symbol) is
/// studied over $\mathbb{Q}(v)$ ([`ParamFamily`]); a file the reader refuses at its nominal
/// values (a pole, an improper pencil) is studied when the study reads it, as on the command
/// line.
///
/// # Errors
/// The file's reading errors; a parameter the file does not name (the message lists those
/// it has); a failure of the float eigenvalues other than at one point.
pub fn sweep_file(
    path: &Path,
    param: &str,
    opts: &super::Options,
    values: &[f64],
) -> Result<SweepResult, Failure> {
    let opened = super::System::open(path, opts);
    if let Ok(sys) = &opened
        && matches!(sys.file().ground, crate::io::Ground::Quadratic(_))
    {
        return FieldFamily::new(sys, param)?.sweep(values, &|_| {});
    }
    // over Q(v): the study's family (it names the parameters of a file without `param`)
    let fam = ParamFamily::from_file_at(path, param, &opts.at)?;
    if let Err(err) = opened
        && (!opts.is_empty() || super::common::check_study_file(path).is_err())
    {
        return Err(err.into());
    }
    Ok(sweep(&fam, values, None)?)
}

/// `--from`, `--to`, `--points` in range.
fn check_args(a: &SweepArgs<'_>) -> Result<(), Failure> {
    if !(a.from.is_finite()
        && a.to.is_finite()
        && a.from <= a.to
        && (1..=1_000_000).contains(&a.points))
    {
        return Err(Failure::input(format!(
            "sweep: need finite --from <= --to and 1 <= --points <= 1000000 (got {}, {}, {})",
            a.from, a.to, a.points
        )));
    }
    Ok(())
}

fn run_family(
    a: &SweepArgs<'_>,
    fam: &Family<'_>,
    stream: Option<super::Format>,
) -> Result<Outcome, Failure> {
    let stream = stream.filter(|_| a.points > STREAM_POINTS);
    if stream == Some(super::Format::Latex) {
        return Err(Failure::limit(format!(
            "sweep: --format latex takes at most {STREAM_POINTS} points (got {}; use --format json or --csv)",
            a.points
        )));
    }
    let values = sweep_values(a.from, a.to, a.points);
    let title = format!("sweep of {} over [{}, {}]", a.param, a.from, a.to);
    let mut sink = match stream {
        Some(f) => Some(Sink::start(
            f == super::Format::Json,
            &title,
            a.param,
            &values,
        )?),
        None => None,
    };
    let mut csv = match a.csv {
        Some(p) => Some(CsvSink::start(p, a.param, fam.dim())?),
        None => None,
    };
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
    let keep_every = values.len().div_ceil(PLOT_ROWS).max(1);
    let plots = a.svg.is_some() || a.locus_svg.is_some();
    let mut kept = SweepResult {
        param: a.param.to_string(),
        values: vec![],
        eigenvalues: vec![],
        status: vec![],
    };
    // points without eigenvalues (poles, singular pencils, failures): few, kept for the notes
    let mut notes: Vec<(usize, f64, PointStatus)> = vec![];
    let mut descriptor = false;
    let mut stable = 0usize;
    for (b, batch) in values.chunks(BATCH).enumerate() {
        let offset = b * BATCH;
        let tick = |k: usize| {
            if let Some(bar) = &bar
                && k.is_multiple_of(64)
            {
                bar.set_position((offset + k) as u64);
            }
        };
        let sw = fam.sweep(batch, &tick)?;
        let rows = batch.iter().zip(sw.eigenvalues).zip(sw.status);
        for (k, ((v, ev), st)) in rows.enumerate() {
            let i = offset + k;
            descriptor |= matches!(st, PointStatus::Descriptor { .. });
            if note_of(&st).is_some() {
                notes.push((i, *v, st));
            }
            if !ev.is_empty() && ev.iter().all(|z| z.re < 0.0) {
                stable += 1;
            }
            if let Some(c) = csv.as_mut() {
                c.row(*v, &ev)?;
            }
            if let Some(s) = sink.as_mut() {
                s.row(&ev)?;
            }
            let for_plot = plots && (i.is_multiple_of(keep_every) || i + 1 == values.len());
            if sink.is_none() || for_plot {
                kept.values.push(*v);
                kept.eigenvalues.push(ev);
                kept.status.push(st);
            }
        }
    }
    if let Some(b) = bar {
        b.finish_and_clear();
    }
    if let Some(c) = csv {
        c.finish()?;
    }
    let name = fam.name().unwrap_or_else(|| a.file.display().to_string());
    let xlabel = format!("{} (parameter)", a.param);
    let drawn = match (plots, sink.is_none() && values.len() > PLOT_ROWS) {
        (false, _) => SweepResult {
            param: String::new(),
            values: vec![],
            eigenvalues: vec![],
            status: vec![],
        },
        (true, true) => thin(&kept, keep_every),
        (true, false) => kept.clone(),
    };
    if let Some(p) = a.svg {
        write(
            p,
            &sweep_svg(
                &drawn,
                &format!("{name}: eigenvalues against {}", a.param),
                &xlabel,
                &[],
            ),
        )?;
    }
    if let Some(p) = a.locus_svg {
        write(
            p,
            &root_locus_svg(
                &drawn,
                &format!("{name}: root locus in {}", a.param),
                &fam.limits(),
            ),
        )?;
    }
    let notes: Vec<Value> = notes
        .iter()
        .filter_map(|(i, v, st)| note_value(*i, *v, st, a.param))
        .collect();
    if let Some(s) = sink {
        let method = Value::Str(method_of(descriptor, fam).into());
        s.finish(&[("method", method), ("notes", Value::List(notes))], stable)?;
        let mut out = Outcome::plain(Report::titled(title));
        out.streamed = true;
        return Ok(out);
    }
    let mut r = Report::titled(title)
        .str("param", a.param)
        .int("points", values.len())
        .str("method", method_of(descriptor, fam));
    if descriptor {
        let inf = kept.status.iter().map(|s| match s {
            PointStatus::Descriptor { infinite } => Value::Int(*infinite as i64),
            _ => Value::Int(0),
        });
        r = r.list("infinite_eigenvalues", inf.collect());
    }
    if !notes.is_empty() {
        r = r.list("notes", notes);
    }
    let r = r
        .int("stable_points", stable)
        .list("values", values.iter().map(|v| Value::Float(*v)).collect())
        .list(
            "eigenvalues_approx",
            kept.eigenvalues
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

/// Every `step`-th row of `sw` and its last row (the rows drawn).
fn thin(sw: &SweepResult, step: usize) -> SweepResult {
    let n = sw.values.len();
    let keep = |i: &usize| i.is_multiple_of(step) || i + 1 == n;
    SweepResult {
        param: sw.param.clone(),
        values: (0..n).filter(keep).map(|i| sw.values[i]).collect(),
        eigenvalues: (0..n)
            .filter(keep)
            .map(|i| sw.eigenvalues[i].clone())
            .collect(),
        status: (0..n).filter(keep).map(|i| sw.status[i]).collect(),
    }
}

/// How the eigenvalues were computed (`method`).
fn method_of(descriptor: bool, fam: &Family<'_>) -> &'static str {
    if let Family::Field(_) = fam {
        return "the system read over its field at each value, its eigenvalues in floating point (complex Schur where A(v) is not real; a descriptor system: the finite eigenvalues, those of its standard form)";
    }
    if descriptor {
        "finite eigenvalues of the pencil det(sE - A) = 0: their number exact, their values by shift-and-invert in floating point; eigenvalues of A(v) where E(v) is invertible"
    } else {
        "eigenvalues of A(v) in floating point (balanced real Schur)"
    }
}

/// `(reason, why)` of a point without eigenvalues; `None` for a point that has them.
fn note_of(s: &PointStatus) -> Option<(&'static str, &'static str)> {
    match s {
        PointStatus::Pole => Some(("pole", "an entry of the matrices has a pole")),
        PointStatus::SingularPencil => Some((
            "singular_pencil",
            "det(sE - A) = 0 for every s (a singular pencil)",
        )),
        PointStatus::Failed => Some(("failed", "the float eigenvalue computation failed")),
        _ => None,
    }
}

/// One entry of `notes[]`: `index`, `value`, `reason`, `note`.
fn note_value(i: usize, v: f64, s: &PointStatus, param: &str) -> Option<Value> {
    let (reason, why) = note_of(s)?;
    Some(Value::Obj(
        Report::new()
            .int("index", i)
            .float("value", v)
            .str("reason", reason)
            .str("note", format!("{param} = {v}: {why}; no eigenvalues")),
    ))
}
