//! Helpers shared by the command modules (a leaf: it imports no other command module).

use super::{Failure, LinalgOp};
use crate::error::Error;
use crate::field::Field;
use crate::matrix::Matrix;
use crate::report::{Report, Target, Value};
use std::path::Path;

/// The error as a failure whose message starts with the file's path.
pub(super) fn with_path(path: &Path, e: Error) -> Failure {
    Failure::from(e).in_file(path)
}

/// The report of `linalg OP` on `a`, with every rendering ([`Target::Every`]).
pub(super) fn linalg_report<K: Field>(
    op: LinalgOp,
    a: &Matrix<K>,
    path: &Path,
) -> Result<Report, Failure> {
    linalg_report_for(op, a, path, Target::Every)
}

/// The report of `linalg OP` on `a`, its matrices built for `target` only.
pub(super) fn linalg_report_for<K: Field>(
    op: LinalgOp,
    a: &Matrix<K>,
    path: &Path,
    target: Target,
) -> Result<Report, Failure> {
    let e = |err| with_path(path, err);
    let r = Report::titled(format!("linalg {op:?}").to_lowercase());
    Ok(match op {
        LinalgOp::Rank => r.int("rank", a.rank()),
        LinalgOp::Det => r.str("det", a.field().fmt_elem(&a.det().map_err(e)?)),
        LinalgOp::Charpoly => r.str("charpoly", a.charpoly().map_err(e)?.to_string()),
        LinalgOp::Minpoly => r.str("minpoly", a.minpoly().map_err(e)?.to_string()),
        LinalgOp::Inverse => r.matrix_for("matrix", &a.inverse().map_err(e)?, target),
        LinalgOp::Rref => {
            let (m, piv) = a.rref();
            r.matrix_for("matrix", &m, target)
                .with(
                    "pivots",
                    Value::List(piv.iter().map(|&p| Value::Int(p as i64 + 1)).collect()),
                )
                .int("rank", piv.len())
        }
        LinalgOp::Nullspace => {
            let n = a.nullspace();
            let basis = (0..n.ncols())
                .map(|j| {
                    Value::List(
                        n.col(j)
                            .iter()
                            .map(|x| Value::Str(a.field().fmt_elem(x)))
                            .collect(),
                    )
                })
                .collect();
            r.with("basis", Value::List(basis))
                .int("nullity", n.ncols())
        }
    })
}

/// The report with matrices as lists of exact strings: over $\mathbb{Q}(p)$ there are no
/// `approx` fields (the contract: only when every symbol has a value).
pub(super) fn exact_only(r: Report) -> Report {
    fn value(v: Value) -> Value {
        match v {
            Value::Matrix(m) => Value::List(
                m.exact
                    .into_iter()
                    .map(|row| Value::List(row.into_iter().map(Value::Str).collect()))
                    .collect(),
            ),
            Value::List(xs) => Value::List(xs.into_iter().map(value).collect()),
            Value::Obj(r) => Value::Obj(exact_only(r)),
            v => v,
        }
    }
    Report {
        title: r.title,
        items: r
            .items
            .into_iter()
            .filter(|(k, _)| !k.contains("approx"))
            .map(|(k, v)| (k, value(v)))
            .collect(),
    }
}

/// Checks that a file swept by `sweep`/`critical` is a valid system: read exactly (any
/// standard or descriptor form, also improper pencils), or, where its swept parameter is
/// `null`, as a system over Q(p). The exact reader's error is kept when both refuse.
pub(super) fn check_study_file(file: &Path) -> Result<(), crate::io::InputError> {
    match crate::io::read_system_file(file) {
        Ok(_) => Ok(()),
        Err(e) => crate::io::symbolic::load_symbolic_path(file, &Default::default())
            .map(|_| ())
            .map_err(|_| e),
    }
}
