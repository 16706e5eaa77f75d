//! Key `G` for every command that needs a state-space system: the transfer matrix is
//! realized exactly and minimally ([`crate::realization::realize_transfer`]) and the
//! realization $(A, B, C, D)$ with $C (sI - A)^{-1} B + D = G(s)$ (checked by the
//! realization at sample points) stands in for the keys `A`..`D`. An improper `G` has no
//! such realization: it is refused with the commands that take it (`tf`, `pencil`, `ctrb`,
//! `obsv`, `zeros`, `minreal --descriptor`).

use super::raw::Raw;
use super::{ExactScalar, InputError, InputErrorKind, MatrixEntries};
use crate::field::Q;
use crate::matrix::Matrix;

fn entries(m: &Matrix<Q>) -> MatrixEntries {
    MatrixEntries {
        nrows: m.nrows(),
        ncols: m.ncols(),
        data: (0..m.nrows())
            .flat_map(|i| (0..m.ncols()).map(move |j| (i, j)))
            .map(|(i, j)| ExactScalar::from_rational(m.get(i, j).clone()))
            .collect(),
    }
}

/// The matrices `A`, `B`, `C`, `D` of a minimal realization of the file's `G`.
///
/// # Errors
/// `G` beside a state-space key, every error of the `G` reader, and an improper `G`.
pub(crate) fn realize_g_key(
    file: &str,
    entries_raw: &[(String, Raw)],
) -> Result<Vec<(&'static str, MatrixEntries)>, InputError> {
    let get = |k: &str| entries_raw.iter().find(|(n, _)| n == k).map(|(_, v)| v);
    let Some(g) = get("G") else {
        return Ok(vec![]);
    };
    if let Some(k) = ["A", "B", "C", "D", "E", "M", "L", "K", "F"]
        .into_iter()
        .find(|k| get(k).is_some())
    {
        return Err(InputError::key(
            file,
            k,
            "a transfer matrix G cannot be combined with the state-space keys",
        )
        .with_kind(InputErrorKind::Shape));
    }
    let params = get("parameters").map(Raw::to_json);
    let (_, r) = super::load_descriptor::realize_g(file, &g.to_json(), params.as_ref())?;
    let Some(ss) = r.state_space else {
        return Err(InputError::key(
            file,
            "G",
            format!(
                "improper transfer matrix (its minimal realization has an infinite part of order {}): \
                 this command needs a \
                 state-space system; `tf`, `pencil`, `ctrb`, `obsv`, `zeros` and \
                 `minreal --descriptor` take it",
                r.minimal.infinite_order
            ),
        )
        .with_kind(InputErrorKind::Unsupported));
    };
    Ok(vec![
        ("A", entries(&ss.a)),
        ("B", entries(&ss.b)),
        ("C", entries(&ss.c)),
        ("D", entries(&ss.d)),
    ])
}
