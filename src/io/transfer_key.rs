//! Key `G` for every command that needs a state-space system: the transfer matrix is
//! realized exactly and minimally ([`crate::realization::realize_transfer`]) and the
//! realization $(A, B, C, D)$ with $C (sI - A)^{-1} B + D = G(s)$ (checked by the
//! realization at sample points) stands in for the keys `A`..`D`. An improper `G` has no
//! such realization: it is refused with the commands that take it (`tf`, `pencil`, `ctrb`,
//! `obsv`, `zeros`, `minreal --descriptor`).

use super::raw::Raw;
use super::{ExactScalar, InputError, InputErrorKind, MatrixEntries};
use crate::field::{Q, Rational};
use crate::io::transfer_expr::{parse_rational_function, parse_rational_function_in};
use crate::io::transfer_written::parse_written_fraction_in;
use crate::matrix::Matrix;
use crate::realization::{
    Realize, TransferRealization, WrittenTransfer, realize_as_written, realize_transfer,
};
use crate::system::StateSpace;
use crate::system::transfer::TransferMatrix;

/// The refusal of an improper `G` (its minimal realization has an infinite part of order
/// `order`) by a command that needs a state-space system; `takers` names the commands that
/// take the file.
pub(crate) fn improper_g(file: &str, order: usize, takers: Option<&str>) -> InputError {
    let also = takers.map_or(String::new(), |t| format!("; {t}"));
    InputError::key(
        file,
        "G",
        format!(
            "improper transfer matrix (its minimal realization has an infinite part of order \
             {order}): this command needs a state-space system{also}"
        ),
    )
    .with_kind(InputErrorKind::Unsupported)
}

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
        if get("realize").is_some() {
            return Err(InputError::key(
                file,
                "realize",
                "only a transfer matrix G is realized: give G, or drop realize",
            ));
        }
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
    let var = g_variable(file, entries_raw)?;
    if realize_mode(file, entries_raw)? == Realize::AsWritten {
        let ss = realize_g_as_written(file, &g.to_json(), params.as_ref(), var)?;
        return Ok(vec![
            ("A", entries(&ss.a)),
            ("B", entries(&ss.b)),
            ("C", entries(&ss.c)),
            ("D", entries(&ss.d)),
        ]);
    }
    let (_, r) = realize_g(file, &g.to_json(), params.as_ref(), var)?;
    let Some(ss) = r.state_space else {
        let takers = "`tf`, `pencil`, `ctrb`, `obsv`, `zeros` and `minreal --descriptor` take it";
        return Err(improper_g(file, r.minimal.infinite_order, Some(takers)));
    };
    Ok(vec![
        ("A", entries(&ss.a)),
        ("B", entries(&ss.b)),
        ("C", entries(&ss.c)),
        ("D", entries(&ss.d)),
    ])
}

/// The variable a file's `G` is written in: `z` when the file has a sample time `dt`
/// (a sampled system), else `s`.
///
/// # Errors
/// A bad `dt` (as the system reader says).
pub(crate) fn g_variable(
    file: &str,
    entries: &[(String, Raw)],
) -> Result<&'static str, InputError> {
    Ok(if super::keys::read_dt(file, entries)?.is_some() {
        "z"
    } else {
        "s"
    })
}

/// Parameters of a `G` or pencil file, evaluated in order as rational constants.
pub(crate) fn eval_params(
    name: &str,
    params: Option<&serde_json::Value>,
) -> Result<Vec<(String, Rational)>, InputError> {
    let mut values: Vec<(String, Rational)> = Vec::new();
    if let Some(serde_json::Value::Object(ps)) = params {
        for (k, v) in ps {
            let text = scalar_text(v).ok_or_else(|| {
                InputError::key(
                    name,
                    "parameters",
                    format!("{k}: expected a number or a string"),
                )
            })?;
            let f = parse_rational_function(&text, &values)
                .map_err(|e| InputError::key(name, "parameters", format!("{k}: {e}")))?;
            if f.num.deg() > 0 || f.den.deg() > 0 {
                return Err(InputError::key(
                    name,
                    "parameters",
                    format!("{k}: must be a constant"),
                ));
            }
            values.push((k.clone(), f.num.coeff(0) / f.den.coeff(0)));
        }
    }
    Ok(values)
}

/// The text of a JSON scalar: a string as it is, a number as written.
pub(crate) fn scalar_text(v: &serde_json::Value) -> Option<String> {
    match v {
        serde_json::Value::String(s) => Some(s.clone()),
        serde_json::Value::Number(n) => Some(n.to_string()),
        _ => None,
    }
}

/// The transfer matrix of key `G` (parameters evaluated first) and its exact minimal
/// realization.
///
/// # Errors
/// An entry that does not parse (named by row and column), ragged or empty rows, a
/// realization failure.
pub(crate) fn realize_g(
    name: &str,
    g: &serde_json::Value,
    params: Option<&serde_json::Value>,
    var: &str,
) -> Result<(TransferMatrix<Q>, TransferRealization<Q>), InputError> {
    let entries = g_entries(name, g, params, var, parse_rational_function_in)?;
    let ncols = entries.first().map_or(0, |r| r.len());
    if entries.is_empty() || ncols == 0 || entries.iter().any(|r| r.len() != ncols) {
        return Err(InputError::key(
            name,
            "G",
            "rows must be non-empty and of equal length",
        ));
    }
    let tm = TransferMatrix { entries };
    let r = realize_transfer(&tm).map_err(|e| InputError::key(name, "G", e.to_string()))?;
    Ok((tm, r))
}

/// The file key `realize`: `"minimal"` (the default) or `"as_written"`.
///
/// # Errors
/// Any other value, named.
pub(crate) fn realize_mode(
    file: &str,
    entries_raw: &[(String, Raw)],
) -> Result<Realize, InputError> {
    let Some((_, v)) = entries_raw.iter().find(|(k, _)| k == "realize") else {
        return Ok(Realize::Minimal);
    };
    let text = match v {
        Raw::Str(s) => s.as_str(),
        _ => "",
    };
    Realize::parse(text).ok_or_else(|| {
        InputError::key(
            file,
            "realize",
            "expected \"minimal\" (cancel common factors, the default) or \"as_written\" \
             (keep every written denominator)",
        )
    })
}

/// The realization of key `G` as written ([`realize_as_written`]: every written denominator
/// kept, nothing cancelled), checked (`det(sI - A)` = the column denominators' product,
/// Markov parameters = those of `G`).
///
/// # Errors
/// An entry that does not parse (named by row and column), ragged or empty rows, an improper
/// entry, a failed check.
pub(crate) fn realize_g_as_written(
    name: &str,
    g: &serde_json::Value,
    params: Option<&serde_json::Value>,
    var: &str,
) -> Result<StateSpace<Q>, InputError> {
    let rows = g_entries(name, g, params, var, parse_written_fraction_in)?;
    let w = WrittenTransfer { entries: rows };
    let r = realize_as_written(&w).map_err(|e| {
        InputError::key(name, "G", format!("realize = \"as_written\": {e}"))
            .with_kind(InputErrorKind::Unsupported)
    })?;
    if !r.verified {
        return Err(InputError::key(
            name,
            "G",
            "realize = \"as_written\": the realization failed its exact check",
        ));
    }
    Ok(r.system)
}

/// The entries of key `G`, parameters evaluated first, each read by `parse` (with the
/// parameter values and the variable); an entry that does not parse is named by row and
/// column.
fn g_entries<T>(
    name: &str,
    g: &serde_json::Value,
    params: Option<&serde_json::Value>,
    var: &str,
    parse: impl Fn(&str, &[(String, Rational)], &str) -> crate::error::Result<T>,
) -> Result<Vec<Vec<T>>, InputError> {
    let values = eval_params(name, params)?;
    let texts = g_texts(name, g)?;
    let mut entries = Vec::new();
    for (i, row) in texts.iter().enumerate() {
        let mut out = Vec::new();
        for (j, text) in row.iter().enumerate() {
            out.push(
                parse(text, &values, var)
                    .map_err(|e| InputError::entry(name, "G", i + 1, j + 1, e.to_string()))?,
            );
        }
        entries.push(out);
    }
    Ok(entries)
}

/// The entries of `G` as text, row by row: from an array of rows or a MATLAB-style string
/// (`"[1/(s+1) 2; 0 s/(s+2)]"`), the two matrix forms of every key.
fn g_texts(name: &str, g: &serde_json::Value) -> Result<Vec<Vec<String>>, InputError> {
    if let serde_json::Value::String(s) = g {
        return super::matlab::split_matlab_matrix(s)
            .map_err(|e| super::matlab::key_error(name, "G", e));
    }
    let rows = g
        .as_array()
        .ok_or_else(|| InputError::key(name, "G", "expected a list of rows"))?;
    let mut out = Vec::new();
    for (i, row) in rows.iter().enumerate() {
        let row = row
            .as_array()
            .ok_or_else(|| InputError::key(name, "G", format!("row {} is not a list", i + 1)))?;
        let mut r = Vec::new();
        for (j, x) in row.iter().enumerate() {
            r.push(scalar_text(x).ok_or_else(|| {
                InputError::entry(name, "G", i + 1, j + 1, "expected a number or a string")
            })?);
        }
        out.push(r);
    }
    Ok(out)
}
