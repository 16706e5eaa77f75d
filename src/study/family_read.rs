//! Reading a family file: the matrices of a system file with one parameter symbolic, other
//! parameters exact (expressions over each other and over the parameter; `--at` values
//! first), the entries read by a [`ScalarReader`]: into $\mathbb{Q}(v)$ ([`RatFuncReader`],
//! [`super::ParamFamily`]) or into $K(v)$ for a quadratic field $K$
//! ([`super::critical::over_k`]). One resolver of parameter names (memoized, cycles
//! refused) for both.

use super::qv::eval_qv;
use crate::error::{Error, Result};
use crate::field::Field;
use crate::field::expr::parse_number;
use crate::io::raw::{self, Raw};
use crate::ratfunc::{RatFunc, RatFuncField};
use std::cell::RefCell;
use std::collections::HashMap;
use std::path::Path;

/// How the entries of a family file are read: into $\mathbb{Q}(v)$ ([`RatFuncReader`]) or
/// into a quadratic extension $K(v)$ of it (the critical values over $K$).
pub trait ScalarReader {
    type Value: Clone;
    /// The swept parameter $v$.
    fn var(&self) -> Self::Value;
    /// A number token (exact).
    ///
    /// # Errors
    /// A malformed number.
    fn number(&self, s: &str) -> Result<Self::Value>;
    /// The expression `text`, other names resolved by `lookup` (`Ok(None)`: unknown).
    ///
    /// # Errors
    /// The reader's errors (syntax, unknown names, division by zero, sizes).
    fn eval(
        &self,
        text: &str,
        lookup: &dyn Fn(&str) -> Result<Option<Self::Value>>,
    ) -> Result<Self::Value>;
}

/// Entries in $\mathbb{Q}(v)$ = `k` (one symbol); `sqrt` and `i` are refused.
pub struct RatFuncReader {
    pub k: RatFuncField,
}

impl ScalarReader for RatFuncReader {
    type Value = RatFunc;
    fn var(&self) -> RatFunc {
        self.k.var(0)
    }
    fn number(&self, s: &str) -> Result<RatFunc> {
        parse_number(s)
            .map(|q| self.k.from_rational(&q))
            .map_err(Error::Invalid)
    }
    fn eval(
        &self,
        text: &str,
        lookup: &dyn Fn(&str) -> Result<Option<RatFunc>>,
    ) -> Result<RatFunc> {
        eval_qv(&self.k, text, lookup)
    }
}

/// The matrices of a family file, read by a [`ScalarReader`] (each key present or not).
#[derive(Clone, Debug)]
pub struct FileMatrices<V> {
    /// The file's name as shown in messages.
    pub file: String,
    /// The system's `name`.
    pub name: Option<String>,
    /// The swept parameter's value in the file, when it has one.
    pub nominal: Option<V>,
    pub a: Option<Vec<Vec<V>>>,
    pub e: Option<Vec<Vec<V>>>,
    pub m: Option<Vec<Vec<V>>>,
    pub l: Option<Vec<Vec<V>>>,
    pub k: Option<Vec<Vec<V>>>,
}

/// Reads the family file at `path` with `param` symbolic and `at` values first (see
/// [`super::ParamFamily::from_file_at`]), its entries by `reader`.
///
/// # Errors
/// As [`super::ParamFamily::from_file_at`].
pub fn read_file_matrices<R: ScalarReader>(
    reader: &R,
    path: &Path,
    param: &str,
    at: &[(String, String)],
) -> Result<FileMatrices<R::Value>> {
    let shown = path.display().to_string();
    let text = crate::io::read::read_text(path).map_err(|e| Error::Invalid(e.to_string()))?;
    let toml = path
        .extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("toml"))
        || !text.trim_start().starts_with('{');
    let raw = if toml {
        raw::from_toml_text(&text, &shown)
    } else {
        raw::from_json_text(&text, &shown)
    }
    .map_err(|e| Error::Invalid(e.to_string()))?;
    read_matrices(reader, &with_values(raw, &shown, param, at)?, &shown, param)
}

fn read_matrices<R: ScalarReader>(
    reader: &R,
    raw: &Raw,
    file: &str,
    param: &str,
) -> Result<FileMatrices<R::Value>> {
    let Raw::Table(top) = raw else {
        return Err(Error::Invalid(format!("{file}: expected a table of keys")));
    };
    let get = |k: &str| top.iter().find(|(n, _)| n == k).map(|(_, v)| v);
    let params: Vec<(String, Raw)> = match get("parameters") {
        Some(Raw::Table(kv)) => kv.clone(),
        Some(_) => {
            return Err(Error::Invalid(format!(
                "{file}: key parameters: expected a table"
            )));
        }
        None => vec![],
    };
    if !crate::io::expr::is_parameter_name(param) {
        return Err(Error::Invalid(format!("'{param}' cannot name a parameter")));
    }
    let resolver = Resolver {
        reader,
        file,
        param,
        params: &params,
        memo: RefCell::new(HashMap::new()),
        active: RefCell::new(vec![]),
    };
    check_param_named(file, param, &params, get("symbols"))?;
    let nominal = match params.iter().find(|(n, _)| n == param) {
        Some((_, Raw::Other { kind: "null", .. })) | None => None,
        Some((_, r)) => Some(resolver.scalar(r, &format!("parameters.{param}"))?),
    };
    let mat = |k: &str| -> Result<Option<Vec<Vec<R::Value>>>> {
        get(k).map(|r| resolver.matrix(r, k)).transpose()
    };
    let name = match get("name") {
        Some(Raw::Str(s)) => Some(s.clone()),
        _ => None,
    };
    if get("G").is_some() {
        return Err(Error::Unsupported(format!(
            "{file}: a parameter study needs A or M, L, K (not a transfer matrix G)"
        )));
    }
    Ok(FileMatrices {
        file: file.to_string(),
        name,
        nominal,
        m: mat("M")?,
        l: mat("L")?,
        k: mat("K")?,
        a: mat("A")?,
        e: mat("E")?,
    })
}

/// The swept parameter must be one the file names (in `parameters` or `symbols`):
/// otherwise the study would run on a constant system and call it a result.
///
/// # Errors
/// `Invalid` naming the file, the key and the parameters the file has.
fn check_param_named(
    file: &str,
    param: &str,
    params: &[(String, Raw)],
    symbols: Option<&Raw>,
) -> Result<()> {
    let mut names: Vec<&str> = params.iter().map(|(n, _)| n.as_str()).collect();
    if let Some(Raw::Array(xs)) = symbols {
        for x in xs {
            if let Raw::Str(s) = x
                && !names.contains(&s.as_str())
            {
                names.push(s);
            }
        }
    }
    if names.contains(&param) {
        return Ok(());
    }
    let has = if names.is_empty() {
        "the file has no parameters".to_string()
    } else {
        format!("the file has: {}", names.join(", "))
    };
    Err(Error::Invalid(format!(
        "{file}: key parameters: no parameter '{param}' to vary ({has})"
    )))
}

struct Resolver<'a, R: ScalarReader> {
    reader: &'a R,
    file: &'a str,
    param: &'a str,
    params: &'a [(String, Raw)],
    memo: RefCell<HashMap<String, R::Value>>,
    active: RefCell<Vec<String>>,
}

impl<R: ScalarReader> Resolver<'_, R> {
    fn lookup(&self, n: &str) -> Result<Option<R::Value>> {
        if n == self.param {
            return Ok(Some(self.reader.var()));
        }
        if let Some(v) = self.memo.borrow().get(n) {
            return Ok(Some(v.clone()));
        }
        let Some((_, r)) = self.params.iter().find(|(m, _)| m == n) else {
            return Ok(None);
        };
        if self.active.borrow().iter().any(|m| m == n) {
            return Err(Error::Invalid(format!(
                "{}: key parameters.{n}: parameters depend on each other in a cycle",
                self.file
            )));
        }
        self.active.borrow_mut().push(n.into());
        let v = self.scalar(r, &format!("parameters.{n}"));
        self.active.borrow_mut().pop();
        let v = v?;
        self.memo.borrow_mut().insert(n.into(), v.clone());
        Ok(Some(v))
    }

    fn scalar(&self, r: &Raw, at: &str) -> Result<R::Value> {
        let wrap = |e: Error| match e {
            Error::Invalid(m) if !m.starts_with(self.file) => {
                Error::Invalid(format!("{}: {at}: {m}", self.file))
            }
            Error::Unsupported(m) => Error::Unsupported(format!("{}: {at}: {m}", self.file)),
            e => e,
        };
        match r {
            Raw::Number(s) => self.reader.number(s).map_err(wrap),
            Raw::Str(s) => self.reader.eval(s, &|n| self.lookup(n)).map_err(wrap),
            other => Err(Error::Invalid(format!(
                "{}: {at}: expected a number or a string, found {}",
                self.file,
                other.kind()
            ))),
        }
    }

    fn matrix(&self, r: &Raw, key: &str) -> Result<Vec<Vec<R::Value>>> {
        let cells: Vec<Vec<Raw>> = match r {
            Raw::Str(s) => crate::io::split_matlab_matrix(s)
                .map_err(|e| {
                    let m = crate::io::matlab::message(&e);
                    Error::Invalid(format!("{}: key {key}: {m}", self.file))
                })?
                .into_iter()
                .map(|row| row.into_iter().map(Raw::Str).collect())
                .collect(),
            Raw::Number(_) => vec![vec![r.clone()]],
            Raw::Array(rows) => rows
                .iter()
                .map(|row| match row {
                    Raw::Array(xs) => Ok(xs.clone()),
                    _ => Err(Error::Invalid(format!(
                        "{}: key {key}: expected an array of rows",
                        self.file
                    ))),
                })
                .collect::<Result<_>>()?,
            _ => {
                return Err(Error::Invalid(format!(
                    "{}: key {key}: expected a matrix",
                    self.file
                )));
            }
        };
        cells
            .iter()
            .enumerate()
            .map(|(i, row)| {
                row.iter()
                    .enumerate()
                    .map(|(j, x)| {
                        self.scalar(x, &format!("key {key}, row {}, column {}", i + 1, j + 1))
                    })
                    .collect()
            })
            .collect()
    }
}

/// The file's table with `--at` values written into its `parameters`.
fn with_values(raw: Raw, file: &str, param: &str, at: &[(String, String)]) -> Result<Raw> {
    if at.is_empty() {
        return Ok(raw);
    }
    let Raw::Table(mut top) = raw else {
        return Ok(raw);
    };
    let Some((_, Raw::Table(params))) = top.iter_mut().find(|(k, _)| k == "parameters") else {
        let (n, _) = &at[0];
        return Err(Error::Invalid(format!(
            "{file}: --at: unknown parameter '{n}'"
        )));
    };
    for (n, v) in at {
        if n == param {
            return Err(Error::Invalid(format!(
                "{file}: --at gives a value to '{n}', the parameter studied"
            )));
        }
        match params.iter_mut().find(|(p, _)| p == n) {
            Some(slot) => slot.1 = Raw::Str(v.clone()),
            None => {
                return Err(Error::Invalid(format!(
                    "{file}: --at: unknown parameter '{n}'"
                )));
            }
        }
    }
    Ok(Raw::Table(top))
}
