//! Symbolic parameters: a system file whose matrices live over $\mathbb{Q}(p_1, \dots, p_k)$.
//!
//! A parameter stays a symbol when its value is `null`, when the file names it in
//! `"symbols": ["m", "u"]`, or when the command line names it (`--symbolic m,u`; `--symbolic`
//! alone: every parameter). `--at "m=1500, u=20"` gives values first (they override the
//! file's). Valued parameters are substituted into the entries as exact text (decimals are
//! exact rationals); the entries are then parsed as rational functions in the symbols
//! ([`RatFuncField::parse`]). When no symbol is left, the file goes through the ordinary
//! reader ([`super::system_file`]) and is typed over $\mathbb{Q}$ or $\mathbb{Q}(\sqrt d)$ as
//! usual.
//!
//! # Examples
//! ```
//! use exactlti::field::ElemDisplay;
//! use exactlti::io::symbolic::{SymbolicOptions, load_symbolic_str};
//! use exactlti::io::{SystemFormat, TypedAny};
//!
//! let text = r#"{"parameters": {"m": null, "k": "2"},
//!                "A": [[0, 1], ["-k/m", 0]], "B": [[0], ["1/m"]], "C": [[1, 0]]}"#;
//! let l = load_symbolic_str(text, SystemFormat::Json, "x.json", &SymbolicOptions::default())
//!     .unwrap();
//! let TypedAny::RatFunc(t) = &l.system else { panic!() };
//! assert_eq!(t.ss.a.field().to_string(), "QQ(m)");
//! assert_eq!(t.ss.a.field().fmt_elem(t.ss.a.get(1, 0)), "-2/m");
//! ```

use super::keys::{check_keys, keys_of};
use super::load::{LoadedSystem, TypedAny, type_file, typed_from};
use super::raw::{Raw, from_text};
pub use super::refusal;
use super::system_file::{reserved_symbol, validate};
use super::{Ground, InputError, SignalNames, SystemFile, SystemFormat, split_matlab_matrix};
use crate::matrix::Matrix;
use crate::ratfunc::RatFuncField;
use std::collections::BTreeSet;
use std::path::Path;

use super::subst::Substitution;
pub use super::subst::SymbolicOptions;

/// Reads a system file with symbolic parameters (format as [`super::read_system_file`]).
///
/// # Errors
/// As [`load_symbolic_str`], and an unreadable file.
pub fn load_symbolic_path(path: &Path, opts: &SymbolicOptions) -> Result<LoadedSystem, InputError> {
    let shown = path.display().to_string();
    let text = super::read_text(path)?;
    let format = SystemFormat::of(path, &text);
    load_symbolic_str(&text, format, &shown, opts)
}

/// Loads a system file, keeping the symbols of the file and of `opts` as symbols; without
/// symbols the result is that of [`super::load_system_str`] (with `--at` values applied).
///
/// # Errors
/// Every error of the ordinary reader; an unknown name in `--symbolic` or `--at`; a
/// `symbols` key that is not a list of names; an entry that is not a rational function of
/// the symbols (named by key, row and column); parameters that depend on each other in a
/// cycle.
pub fn load_symbolic_str(
    text: &str,
    format: SystemFormat,
    name: &str,
    opts: &SymbolicOptions,
) -> Result<LoadedSystem, InputError> {
    let raw = from_text(text, format, name)?;
    let Raw::Table(entries) = raw else {
        return validate(raw, name).and_then(type_file);
    };
    if entries.iter().any(|(k, _)| k == "bodies") {
        return super::load::load_model_str(text, format, name, opts);
    }
    check_keys(name, &keys_of(&entries))?;
    let signals = SignalNames::read(name, &entries)?;
    let mut params: Vec<(String, Option<String>)> = vec![];
    let mut symbols: BTreeSet<String> = BTreeSet::new();
    let mut rest: Vec<(String, Raw)> = vec![];
    for (key, v) in entries {
        match (key.as_str(), v) {
            ("parameters", Raw::Table(kv)) => {
                for (n, v) in kv {
                    let val = match v {
                        Raw::Number(s) | Raw::Str(s) => Some(s),
                        Raw::Other { json, .. } if json.is_null() => None,
                        other => {
                            return Err(InputError::key(
                                name,
                                &format!("parameters.{n}"),
                                format!(
                                    "expected a number, a string or null, found {}",
                                    other.kind()
                                ),
                            ));
                        }
                    };
                    if super::expr::RESERVED.contains(&n.as_str()) {
                        return Err(InputError::key(
                            name,
                            &format!("parameters.{n}"),
                            format!("'{n}' is reserved and cannot name a parameter"),
                        ));
                    }
                    params.push((n, val));
                }
            }
            ("symbols", Raw::Array(xs)) => {
                for x in xs {
                    let Raw::Str(s) = x else {
                        return Err(InputError::key(name, "symbols", "expected a list of names"));
                    };
                    reserved_symbol(name, &s)?;
                    symbols.insert(s);
                }
            }
            ("symbols", _) => {
                return Err(InputError::key(name, "symbols", "expected a list of names"));
            }
            (_, v) => rest.push((key, v)),
        }
    }
    opts.apply_to(name, &mut params, &mut symbols)?;
    // a symbol is a symbol even when the file also gives it a value
    let valued: Vec<(String, String)> = params
        .iter()
        .filter(|(n, _)| !symbols.contains(n))
        .filter_map(|(n, v)| v.clone().map(|v| (n.clone(), v)))
        .collect();
    if symbols.is_empty() {
        let mut table = vec![(
            "parameters".to_string(),
            Raw::Table(
                valued
                    .iter()
                    .map(|(n, v)| (n.clone(), Raw::Str(v.clone())))
                    .collect(),
            ),
        )];
        table.extend(rest);
        return validate(Raw::Table(table), name).and_then(type_file);
    }
    let k = field_of(name, &symbols)?;
    let subst = Substitution::new(name, &valued)?;
    let mut mats: Vec<(&'static str, Matrix<RatFuncField>)> = vec![];
    if rest.iter().any(|(k, _)| k == "G") {
        // a transfer matrix in s over Q(p): its minimal realization stands in for A..D
        let read = |key: &str, v: &Raw, f: &RatFuncField| read_matrix(name, key, v, f, &subst);
        mats = super::transfer_symbolic::realize_g_symbolic(name, &rest, &k, read)?;
    }
    let mut extra = serde_json::Map::new();
    let mut sys_name = None;
    for (key, v) in rest {
        if key == "G" {
            continue;
        }
        if let Some(mk) = MATRIX_KEYS.iter().find(|m| **m == key) {
            mats.push((mk, read_matrix(name, mk, &v, &k, &subst)?));
        } else if key == "name" {
            if let Raw::Str(s) = v {
                sys_name = Some(s);
            }
        } else {
            extra.insert(key, v.to_json());
        }
    }
    // as the ordinary reader: with `A` given, a missing `B` is n x m, `C` p x n (m, p from
    // `D`, else 0), `D` zero
    let has =
        |mats: &[(&str, Matrix<RatFuncField>)], key: &str| mats.iter().any(|(m, _)| *m == key);
    let (p_d, m_d) = mats
        .iter()
        .find(|(m, _)| *m == "D")
        .map_or((0, 0), |(_, d)| d.shape());
    if let Some(n) = mats.iter().find(|(m, _)| *m == "A").map(|(_, a)| a.nrows()) {
        if !has(&mats, "B") {
            mats.push(("B", Matrix::zeros(k.clone(), n, m_d)));
        }
        if !has(&mats, "C") {
            mats.push(("C", Matrix::zeros(k.clone(), p_d, n)));
        }
    }
    let b_cols = mats.iter().find(|(m, _)| *m == "B").map(|(_, b)| b.ncols());
    let c_rows = mats.iter().find(|(m, _)| *m == "C").map(|(_, c)| c.nrows());
    if let (Some(m), Some(p)) = (b_cols, c_rows)
        && !has(&mats, "D")
        && has(&mats, "A")
    {
        mats.push(("D", Matrix::zeros(k.clone(), p, m)));
    }
    let get = |key: &str| mats.iter().find(|(m, _)| *m == key).map(|(_, x)| x.clone());
    let typed = typed_from(name, &get)?;
    let mut file = SystemFile::without_matrices(name, Ground::RatFunc(k), extra, signals);
    file.name = sys_name;
    let t = &typed.ss;
    file.signals
        .check(name, t.nstates(), t.ninputs(), t.noutputs())?;
    Ok(LoadedSystem {
        file,
        system: TypedAny::RatFunc(typed),
    })
}

/// Whether a file keeps parameters as symbols by itself: a `symbols` key, or a parameter
/// whose value is `null` (read from the parsed table; text that does not parse is `false`,
/// and the ordinary reader reports it).
pub fn declares_symbols(text: &str, format: SystemFormat, name: &str) -> bool {
    let raw = from_text(text, format, name);
    let Ok(Raw::Table(entries)) = raw else {
        return false;
    };
    let null = |v: &Raw| matches!(v, Raw::Other { json, .. } if json.is_null());
    entries.iter().any(|(k, v)| match (k.as_str(), v) {
        ("symbols", _) => true,
        ("parameters", Raw::Table(kv)) => kv.iter().any(|(_, x)| null(x)),
        _ => false,
    })
}

const MATRIX_KEYS: [&str; 9] = ["A", "B", "C", "D", "E", "M", "L", "K", "F"];

fn field_of(name: &str, symbols: &BTreeSet<String>) -> Result<RatFuncField, InputError> {
    let vars: Vec<&str> = symbols.iter().map(String::as_str).collect();
    RatFuncField::new(&vars).map_err(|e| InputError::key(name, "symbols", e.to_string()))
}

fn read_matrix(
    file: &str,
    key: &str,
    v: &Raw,
    k: &RatFuncField,
    subst: &Substitution,
) -> Result<Matrix<RatFuncField>, InputError> {
    let rows: Vec<Vec<String>> = match v {
        Raw::Str(s) => {
            split_matlab_matrix(s).map_err(|e| InputError::key(file, key, e.to_string()))?
        }
        Raw::Array(rs) => {
            let mut rows = vec![];
            for (i, r) in rs.iter().enumerate() {
                let Raw::Array(xs) = r else {
                    return Err(InputError::key(
                        file,
                        key,
                        format!("row {}: expected an array, found {}", i + 1, r.kind()),
                    ));
                };
                let mut row = vec![];
                for (j, x) in xs.iter().enumerate() {
                    match x {
                        Raw::Number(s) | Raw::Str(s) => row.push(s.clone()),
                        other => {
                            return Err(InputError::key(
                                file,
                                key,
                                format!(
                                    "row {}, column {}: expected a number or a string, found {}",
                                    i + 1,
                                    j + 1,
                                    other.kind()
                                ),
                            ));
                        }
                    }
                }
                rows.push(row);
            }
            rows
        }
        other => {
            return Err(InputError::key(
                file,
                key,
                format!("expected a matrix, found {}", other.kind()),
            ));
        }
    };
    let nrows = rows.len();
    let ncols = rows.first().map_or(0, Vec::len);
    let mut data = Vec::with_capacity(nrows * ncols);
    for (i, r) in rows.iter().enumerate() {
        if r.len() != ncols {
            return Err(InputError::key(
                file,
                key,
                format!("row {} has {} entries, row 1 has {ncols}", i + 1, r.len()),
            ));
        }
        for (j, t) in r.iter().enumerate() {
            let at = |m: String| {
                InputError::key(file, key, format!("row {}, column {}: {m}", i + 1, j + 1))
            };
            super::expr::too_long(t).map_err(|e| at(e.to_string()))?;
            let text = subst.apply(t).map_err(at)?;
            data.push(k.parse(&text).map_err(|e| at(e.to_string()))?);
        }
    }
    Ok(Matrix::from_vec(k.clone(), nrows, ncols, data))
}
