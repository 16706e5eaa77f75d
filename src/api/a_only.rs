//! Commands that need only the matrix `A` (`linalg`, `jordan`) on files that are not a
//! system in standard form: `linalg` on an m x n matrix, and both on an improper or singular
//! descriptor system (whose `A` is still a matrix). The report says so in a `note`.

use super::common::{linalg_report, with_path};
use super::{Command, Failure, Outcome};
use crate::error::Error;
use crate::field::{Field, Q};
use crate::io::system_file::read_matrix_key;
use crate::io::{FromScalars, Ground, InputError, read_system_file};
use crate::jordan::normalize::Normalization;
use crate::jordan::{EigenField, JordanField};
use crate::matrix::Matrix;
use crate::ratfunc::RatFuncField;
use crate::report::Value;
use std::path::Path;

/// `err` is the failure of the ordinary loader; answers it unless the file's `A` serves.
pub(super) fn fallback(cmd: &Command, path: &Path, err: InputError) -> Result<Outcome, Failure> {
    if matches!(cmd, Command::Jordan { .. })
        && let Some(out) = descriptor_jordan_path(cmd, path)
    {
        return out;
    }
    let Ok((entries, ground)) = read_matrix_key(path, "A") else {
        return Err(err.into());
    };
    let linalg = matches!(cmd, Command::Linalg { .. });
    let shown = path.display().to_string();
    let reason = err.to_string();
    let reason = reason
        .strip_prefix(&format!("{shown}: "))
        .unwrap_or(&reason)
        .to_string();
    let what = if linalg { "linalg" } else { "jordan" };
    let note = if read_system_file(path).is_ok() {
        // the file reads as a system but is not one in standard form (improper, singular)
        format!(
            "{what} uses only the matrix A as given: the file's system is refused by the other commands ({reason})"
        )
    } else if linalg && entries.nrows != entries.ncols {
        format!(
            "linalg reads A as a {}x{} matrix (not a system)",
            entries.nrows, entries.ncols
        )
    } else {
        return Err(err.into());
    };
    let run = |out: Option<Result<Outcome, Failure>>| -> Result<Outcome, Failure> {
        let mut out = out.ok_or_else(|| Failure::input(format!("{shown}: {reason}")))??;
        out.report.push("note", Value::Str(note.clone()));
        Ok(out)
    };
    match &ground {
        Ground::Rational => run(a_command(cmd, &Q.matrix_from_entries(&entries), path)),
        Ground::Quadratic(k) => run(a_command(cmd, &k.matrix_from_entries(&entries), path)),
        Ground::RatFunc(k) => run(a_command(cmd, &k.matrix_from_entries(&entries), path)),
        #[allow(unreachable_patterns)]
        _ => Err(with_path(
            path,
            Error::Unsupported(format!("this command over {ground}")),
        )),
    }
}

/// The commands that need only the matrix `A` (`jordan`, `linalg`); `None` for the others.
pub(super) fn a_command<K: JordanField>(
    cmd: &Command,
    a: &Matrix<K>,
    path: &Path,
) -> Option<Result<Outcome, Failure>> {
    Some(match cmd {
        Command::Jordan {
            real,
            expand,
            normalize,
            ..
        } => normalization(normalize.as_deref(), *real)
            .and_then(|norm| jordan_any(a, (*real, *expand), &norm, path)),
        Command::Linalg { op, .. } => linalg_report(*op, a, path).map(Outcome::plain),
        _ => return None,
    })
}

/// `jordan --normalize X`: the chains' normalisation (none without the option); refused
/// with `--real` (it normalises the chains of `jordan`, not the real form).
pub(super) fn normalization(arg: Option<&str>, real: bool) -> Result<Normalization, Failure> {
    match arg {
        None => Ok(Normalization::default()),
        Some(_) if real => Err(Failure::input(
            "--normalize: applies to the chains of `jordan`, not to the real form of `jordan --real`".to_string(),
        )),
        Some(n) => n.parse().map_err(Failure::input),
    }
}

/// `jordan [--real]` over every field with an exact Jordan form: Q, a quadratic field (over
/// Q when every entry is rational), and Q(p) (the symbolic Jordan form with its conditions,
/// as `jordan` on a system over Q(p)).
fn jordan_any<K: JordanField>(
    a: &Matrix<K>,
    how: (bool, bool),
    norm: &Normalization,
    path: &Path,
) -> Result<Outcome, Failure> {
    struct V<'a>((bool, bool), &'a Normalization, &'a Path);
    impl super::jordan_values::EigenVisitor for V<'_> {
        type Output = Result<Outcome, Failure>;
        fn visit<F: EigenField>(self, a: &Matrix<F>) -> Self::Output {
            jordan_cmd(a, self.0, self.1, self.2)
        }
        fn visit_qp(self, a: &Matrix<RatFuncField>) -> Self::Output {
            let V((real, _), norm, path) = self;
            let out = if !norm.is_none() {
                super::symbolic_jordan::normalized_outcome(a, norm)
            } else if real {
                super::symbolic_jordan::real_outcome(a)
            } else {
                super::symbolic_jordan::jordan_outcome(a)
            };
            out.map_err(|e| with_path(path, e))
        }
    }
    super::jordan_values::on_eigen_field(a, V(how, norm, path))
}

/// `jordan [--real]` ([`crate::jordan::jordan_over`]); `--real` of a matrix over a field
/// that is not real (Q(i)) is refused, naming its first entry outside Q.
fn jordan_cmd<F: EigenField>(
    a: &Matrix<F>,
    (real, expand): (bool, bool),
    norm: &Normalization,
    path: &Path,
) -> Result<Outcome, Failure> {
    let e = |err| with_path(path, err);
    let k = a.field();
    if real && !k.is_real() {
        let (i, j) = (0..a.nrows())
            .flat_map(|i| (0..a.ncols()).map(move |j| (i, j)))
            .find(|&(i, j)| k.to_rational(a.get(i, j)).is_none())
            .unwrap_or((0, 0));
        return Err(Failure::input(format!(
            "{}: A is not real (entry ({}, {}) = {}), so it has no real Jordan form; \
                 `jordan` gives its Jordan form over {k}",
            path.display(),
            i + 1,
            j + 1,
            k.fmt_elem(a.get(i, j))
        )));
    }
    let mut jf = crate::jordan::jordan_over(a).map_err(e)?;
    if !norm.is_none() {
        let closed = crate::jordan::normalize::normalize_form(&mut jf, norm).map_err(e)?;
        let r = crate::report::steps_norm::normalized_form_report(&jf, norm, &closed);
        return Ok(Outcome::new(r, jf.verified));
    }
    if real {
        let rf = jf.real_form_with(expand).map_err(e)?;
        // a real form left in complex coordinates (exact = false) is not checked
        return Ok(Outcome::new(rf.report(), !rf.exact || rf.verified));
    }
    Ok(Outcome::new(jf.report(), jf.verified))
}

/// `jordan` of a file with `E`: the Jordan form of the pencil's finite dynamics (the finite
/// eigenvalues of $sE - A$ with their blocks) beside the sizes of its infinite blocks (from
/// the Kronecker structure, [`crate::pencil::kronecker_structure`]). A singular pencil has
/// no Jordan structure and is refused with the reason (exit 2).
pub(super) fn descriptor_jordan<K: JordanField>(
    cmd: &Command,
    d: &crate::system::Descriptor<K>,
    path: &Path,
) -> Result<Outcome, Failure> {
    descriptor_jordan_with(d, path, |af| {
        a_command(cmd, af, path).expect("jordan is an A-only command")
    })
}

/// [`descriptor_jordan`] with the Jordan form of the finite part's `A` made by `run` (over
/// $\mathbb{Q}(p)$ the symbolic Jordan form).
pub(super) fn descriptor_jordan_with<K: Field + 'static>(
    d: &crate::system::Descriptor<K>,
    path: &Path,
    run: impl FnOnce(&Matrix<K>) -> Result<Outcome, Failure>,
) -> Result<Outcome, Failure> {
    let fp = super::jordan_values::finite_part(d, path)?;
    let mut out = run(&fp.a)?;
    let blocks = fp.infinite_blocks.iter().map(|&k| Value::Int(k as i64));
    out.report
        .push("infinite_blocks", Value::List(blocks.collect()));
    out.report.push("note", Value::Str(fp.note));
    out.verified = out.verified && fp.verified;
    Ok(out)
}

/// `jordan` of a file with `E` whose system the ordinary loader refuses (improper or
/// singular): [`descriptor_jordan`] on the file read as a descriptor system.
pub(super) fn descriptor_jordan_path(
    cmd: &Command,
    path: &Path,
) -> Option<Result<Outcome, Failure>> {
    struct Visit<'a>(&'a Command, &'a Path);
    impl crate::io::load_descriptor::DescriptorVisitor for Visit<'_> {
        type Output = Result<Outcome, Failure>;
        fn visit<K: crate::io::GroundField>(
            self,
            _: &crate::io::load_descriptor::LoadedDescriptor,
            s: &crate::system::Descriptor<K>,
            _: Option<&crate::io::load_descriptor::GivenTransfer<K>>,
        ) -> Self::Output {
            descriptor_jordan(self.0, s, self.1)
        }
    }
    let l = crate::io::load_descriptor::load_descriptor_path(path).ok()?;
    (l.has_e && l.pencil.is_none() && l.transfer.is_none()).then(|| l.run(Visit(cmd, path)))
}
