//! Key `G` with symbols: a transfer matrix whose entries are rational functions of `s` with
//! coefficients in $\mathbb{Q}(p_1, \dots, p_k)$, realized exactly and minimally over
//! $\mathbb{Q}(p)$ ([`crate::realization::realize_transfer`], generic over the field): the
//! realization $(A, B, C, D)$ with $C (sI - A)^{-1} B + D = G(s)$ stands in for the keys
//! `A`..`D`, as [`super::transfer_key`] does over $\mathbb{Q}$.
//!
//! Each entry is read as an element of $\mathbb{Q}(p_1, \dots, p_k, s)$ (valued parameters
//! substituted first), then split into numerator and denominator polynomials in $s$ over
//! $\mathbb{Z}\lbrack p\rbrack$. An improper `G` (no state-space realization) is refused
//! with the same message as over $\mathbb{Q}$.

use super::InputError;
use super::InputErrorKind;
use super::raw::Raw;
use crate::matrix::Matrix;
use crate::mpoly::MPoly;
use crate::poly::Poly;
use crate::ratfunc::RatFuncField;
use crate::realization::realize_transfer;
use crate::system::transfer::{RationalFunction, TransferMatrix};

/// The state-space keys a `G` cannot be combined with.
const STATE_KEYS: [&str; 9] = ["A", "B", "C", "D", "E", "M", "L", "K", "F"];

/// `(A, B, C, D)` over `k` of a minimal realization of the file's `G` (keys `rest`);
/// `read(key, value, field)` reads a matrix key over a field (the symbolic reader's).
///
/// # Errors
/// `G` beside a state-space key; an entry that is not a rational function of `s` and the
/// symbols (named by row and column); ragged rows; an improper `G`; a realization failure.
pub(super) fn realize_g_symbolic(
    file: &str,
    rest: &[(String, Raw)],
    k: &RatFuncField,
    read: impl Fn(&str, &Raw, &RatFuncField) -> Result<Matrix<RatFuncField>, InputError>,
) -> Result<Vec<(&'static str, Matrix<RatFuncField>)>, InputError> {
    if let Some(key) = STATE_KEYS
        .into_iter()
        .find(|key| rest.iter().any(|(n, _)| n == key))
    {
        return Err(InputError::key(
            file,
            key,
            "a transfer matrix G cannot be combined with the state-space keys",
        )
        .with_kind(InputErrorKind::Shape));
    }
    let g = rest
        .iter()
        .find(|(n, _)| n == "G")
        .map(|(_, v)| v)
        .ok_or_else(|| InputError::key(file, "G", "missing"))?;
    if k.vars().iter().any(|v| v == "s") {
        return Err(InputError::key(
            file,
            "parameters.s",
            "'s' is the variable of the transfer matrix G and cannot name a symbol",
        ));
    }
    let nv = k.nvars();
    let mut vars: Vec<String> = k.vars().to_vec();
    vars.push("s".into());
    let ks = RatFuncField::new(&vars).map_err(|e| InputError::key(file, "G", e.to_string()))?;
    let gm = read("G", g, &ks)?;
    if gm.nrows() == 0 || gm.ncols() == 0 {
        return Err(InputError::key(
            file,
            "G",
            "rows must be non-empty and of equal length",
        ));
    }
    let keep: Vec<usize> = (0..nv).collect();
    // a polynomial in (p, s) as a polynomial in s over Z[p] (inside Q(p))
    let in_s = |f: &MPoly| -> Poly<RatFuncField> {
        let cs = f
            .to_univariate(nv)
            .iter()
            .map(|c| k.from_mpoly(c.remap(nv, &keep)))
            .collect();
        Poly::new(k.clone(), cs)
    };
    let entries = (0..gm.nrows())
        .map(|i| {
            (0..gm.ncols())
                .map(|j| {
                    let e = gm.get(i, j);
                    RationalFunction::new(in_s(e.num()), in_s(e.den()))
                })
                .collect()
        })
        .collect();
    let tm = TransferMatrix { entries };
    let r = realize_transfer(&tm).map_err(|e| InputError::key(file, "G", e.to_string()))?;
    let Some(ss) = r.state_space else {
        return Err(super::transfer_key::improper_g(
            file,
            r.minimal.infinite_order,
            None,
        ));
    };
    Ok(vec![("A", ss.a), ("B", ss.b), ("C", ss.c), ("D", ss.d)])
}
