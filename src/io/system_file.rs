//! System files (CLI contract, "The system file"): JSON or TOML with the same keys.
//!
//! ```json
//! { "name": "yaw plane, single wheel",
//!   "parameters": { "m": "1500", "u": "20", "cr": "80000" },
//!   "A": [["0", "u", "-1", "0"], ["0", 0, 0, -1], ["0", "0", "-cr/(m*u)", "-u"], [0, 0, 0, 0]],
//!   "B": [["0"], ["0"], ["1/m"], ["0"]], "C": [[1, 0, 0, 0]], "D": [[0]] }
//! ```
//!
//! First-order form $E x' = A x + B u$, $y = C x + D u$ (keys `A`, `B`, `C`, `D`, `E`), or
//! second-order form $M q'' + L q' + K q = F u$, $y = C [q; q'] + D u$ (keys `M`, `L`, `K`,
//! `F`, `C`, `D`). Shapes: `A` $n \times n$, `B` $n \times m$, `C` $p \times n$, `D`
//! $p \times m$, `E` $n \times n$; `M`, `L`, `K` $n_2 \times n_2$, `F` $n_2 \times m$ and
//! then `C` $p \times 2n_2$.
//!
//! Filled in when missing: `B` ($n \times m$ zeros, where $m$ is the column count of `D`,
//! else 0), `C` ($p \times n$ zeros, $p$ the row count of `D`, else 0), `D` ($p \times m$
//! zeros), and in the second-order form `L`, `K` (zeros) and `F` ($n_2 \times m$ zeros).
//! `E` stays `None` (the identity); `M` is required. An empty matrix `[]` is $0 \times 0$,
//! and is read as $n \times 0$ or $0 \times n$ where the shape rules leave a zero dimension.
//!
//! Matrices are arrays of rows or MATLAB-style strings (`"A": "[0 1; -2 -3]"`); entries are
//! numbers (exact text) or expression strings over `parameters` (see [`super::expr`]).
//! Parameters may refer to each other in any order; cycles are errors. All non-rational
//! values of the file (parameters included) must lie in one quadratic field, the
//! [`Ground`]. Keys other than the above are kept in [`SystemFile::extra`].
//!
//! **TOML numbers** are exact too: the integer and float tokens are read from their source
//! text (`toml::de::DeTable`), so `0.08` in TOML is $2/25$; `inf` and `nan` are rejected.

use super::expr::{self, Value, is_parameter_name, referenced_names};
use super::keys::{check_keys, keys_of};
use super::matlab::{FieldScan, ragged_msg, split_matlab_matrix};
use super::raw::{self, Raw};
use super::{ExactScalar, Ground, InputError, InputErrorKind, MatrixEntries, SignalNames};
use std::collections::HashMap;
use std::path::Path;

/// A validated system file. Matrices hold exact scalars of [`SystemFile::ground`].
#[derive(Clone, Debug, PartialEq)]
pub struct SystemFile {
    pub name: Option<String>,
    /// The file name used in messages.
    pub path: String,
    /// Parameters in file order, evaluated.
    pub parameters: Vec<(String, ExactScalar)>,
    /// The one field all values live in.
    pub ground: Ground,
    /// First-order form (`a`, `b`, `c`, `d` all `Some` when `a` is).
    pub a: Option<MatrixEntries>,
    pub b: Option<MatrixEntries>,
    pub c: Option<MatrixEntries>,
    pub d: Option<MatrixEntries>,
    /// Descriptor matrix; `None` means the identity.
    pub e: Option<MatrixEntries>,
    /// Second-order form (`m`, `l`, `k`, `f`, `c`, `d` all `Some` when `m` is).
    pub m: Option<MatrixEntries>,
    pub l: Option<MatrixEntries>,
    pub k: Option<MatrixEntries>,
    pub f: Option<MatrixEntries>,
    /// Keys this reader does not interpret itself (`G`, `symbols`, and the descriptive
    /// `inputs`, `outputs`, `states`), as JSON. Unknown keys are errors.
    pub extra: serde_json::Map<String, serde_json::Value>,
    /// Signal names (`inputs`, `outputs`, `states`), their counts checked against the system.
    pub signals: super::SignalNames,
}

impl SystemFile {
    /// Is the system given in the second-order form?
    pub fn is_second_order(&self) -> bool {
        self.m.is_some()
    }
    /// Number of states: $n$, or $2 n_2$ in the second-order form.
    pub fn nstates(&self) -> usize {
        match (&self.a, &self.m) {
            (Some(a), _) => a.nrows,
            (None, Some(m)) => 2 * m.nrows,
            (None, None) => 0,
        }
    }
    /// Number of inputs $m$.
    pub fn ninputs(&self) -> usize {
        self.d.as_ref().map_or(0, |d| d.ncols)
    }
    /// Number of outputs $p$.
    pub fn noutputs(&self) -> usize {
        self.d.as_ref().map_or(0, |d| d.nrows)
    }
    /// A file with its field, extra keys and signal names but no name, parameters or
    /// matrices yet (the readers fill them in).
    pub(crate) fn without_matrices(
        path: &str,
        ground: Ground,
        extra: serde_json::Map<String, serde_json::Value>,
        signals: SignalNames,
    ) -> SystemFile {
        SystemFile {
            name: None,
            path: path.to_string(),
            parameters: vec![],
            ground,
            a: None,
            b: None,
            c: None,
            d: None,
            e: None,
            m: None,
            l: None,
            k: None,
            f: None,
            extra,
            signals,
        }
    }
    /// The value of a parameter.
    pub fn parameter(&self, name: &str) -> Option<&ExactScalar> {
        self.parameters
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, x)| x)
    }
}

/// Reads a system file; `.toml` files are TOML, `.json` JSON, others by their first
/// character (`{` means JSON).
///
/// # Errors
/// An unreadable file, and every error of [`parse_system_json`] / [`parse_system_toml`].
pub fn read_system_file(path: &Path) -> Result<SystemFile, InputError> {
    let shown = path.display().to_string();
    let text = super::read_text(path)?;
    match super::read::SystemFormat::of(path, &text) {
        super::read::SystemFormat::Json => parse_system_json(&text, &shown),
        super::read::SystemFormat::Toml => parse_system_toml(&text, &shown),
    }
}

/// Parses and validates a JSON system file; `path` is only used in messages.
///
/// # Examples
/// ```
/// use exactlti::io::parse_system_json;
/// let s = parse_system_json(r#"{"parameters": {"k": "2"}, "A": "[0 1; -k -0.5]"}"#, "x.json")
///     .unwrap();
/// assert_eq!(s.a.as_ref().unwrap().display(&s.ground), "[[0, 1], [-2, -1/2]]");
/// assert_eq!((s.ninputs(), s.noutputs()), (0, 0));
/// let e = parse_system_json(r#"{"A": [[1, "k"]]}"#, "x.json").unwrap_err();
/// assert_eq!(e.to_string(), "x.json: key A, row 1, column 2: unknown parameter 'k'");
/// ```
///
/// # Errors
/// An [`InputError`] naming file, key, row and column: invalid JSON, bad parameter names,
/// parameter cycles, bad entries (see [`super::eval_expr`]), ragged rows, values from two
/// quadratic fields, shapes that do not agree, and a file with neither `A` nor `M`.
pub fn parse_system_json(text: &str, path: &str) -> Result<SystemFile, InputError> {
    validate(raw::from_json_text(text, path)?, path)
}

/// Parses and validates a TOML system file (same keys as JSON; numbers read exactly from
/// their text); `path` is only used in messages.
///
/// # Errors
/// As [`parse_system_json`], with invalid TOML instead of invalid JSON.
pub fn parse_system_toml(text: &str, path: &str) -> Result<SystemFile, InputError> {
    validate(raw::from_toml_text(text, path)?, path)
}

const MATRIX_KEYS: [&str; 9] = ["A", "B", "C", "D", "E", "M", "L", "K", "F"];

pub(crate) fn validate(raw: Raw, file: &str) -> Result<SystemFile, InputError> {
    let Raw::Table(entries) = raw else {
        return Err(InputError::file(
            file,
            format!("expected a table of keys, found {}", raw.kind()),
        ));
    };
    check_keys(file, &keys_of(&entries))?;
    let signals = SignalNames::read(file, &entries)?;
    let g_realization = super::transfer_key::realize_g_key(file, &entries)?;
    let mut name = None;
    let mut params_raw = Vec::new();
    let mut mats: HashMap<&'static str, Raw> = HashMap::new();
    let mut extra = serde_json::Map::new();
    for (key, v) in entries {
        if let Some(k) = MATRIX_KEYS.iter().find(|k| **k == key) {
            mats.insert(k, v);
        } else if key == "name" {
            match v {
                Raw::Str(s) => name = Some(s),
                other => {
                    return Err(InputError::key(
                        file,
                        "name",
                        format!("expected a string, found {}", other.kind()),
                    ));
                }
            }
        } else if key == "parameters" {
            match v {
                Raw::Table(kv) => params_raw = kv,
                other => {
                    return Err(InputError::key(
                        file,
                        "parameters",
                        format!("expected a table of name: value, found {}", other.kind()),
                    ));
                }
            }
        } else if MATRIX_KEYS.contains(&key.to_ascii_uppercase().as_str()) {
            let up = key.to_ascii_uppercase();
            return Err(InputError::key(
                file,
                &key,
                format!("matrix keys are upper case: did you mean '{up}'?"),
            ));
        } else {
            if let (true, Raw::Array(xs)) = (key == "symbols", &v) {
                for x in xs {
                    if let Raw::Str(s) = x {
                        reserved_symbol(file, s)?;
                    }
                }
            }
            extra.insert(key, v.to_json());
        }
    }
    let mut scan = FieldScan::default();
    let params = eval_parameters(file, &params_raw, &mut scan)?;
    let lookup = |n: &str| params.iter().find(|(p, _)| p == n).map(|(_, v)| v.clone());
    let mut got: HashMap<&'static str, MatrixEntries> = HashMap::new();
    for key in MATRIX_KEYS {
        if let Some(r) = mats.get(key) {
            got.insert(key, read_matrix(file, key, r, &lookup, &mut scan)?);
        }
    }
    got.extend(g_realization);
    let mut sys = SystemFile::without_matrices(file, scan.ground(), extra, signals);
    sys.name = name;
    sys.parameters = params
        .into_iter()
        .map(|(n, v)| (n, ExactScalar { a: v.a, b: v.b }))
        .collect();
    check_shapes(file, got, &mut sys)?;
    sys.signals
        .check(file, sys.nstates(), sys.ninputs(), sys.noutputs())?;
    Ok(sys)
}

/// Evaluates the parameters in dependency order (any file order allowed).
fn eval_parameters(
    file: &str,
    raw: &[(String, Raw)],
    scan: &mut FieldScan,
) -> Result<Vec<(String, Value)>, InputError> {
    let key = |n: &str| format!("parameters.{n}");
    for (i, (n, v)) in raw.iter().enumerate() {
        if expr::RESERVED.contains(&n.as_str()) {
            return Err(InputError::key(
                file,
                &key(n),
                format!("'{n}' is reserved and cannot name a parameter"),
            ));
        }
        if !is_parameter_name(n) {
            return Err(InputError::key(
                file,
                &key(n),
                format!(
                    "'{n}' is not a valid parameter name (letters, digits, '_'; not starting with a digit)"
                ),
            ));
        }
        if raw[..i].iter().any(|(m, _)| m == n) {
            return Err(InputError::key(file, &key(n), "parameter defined twice"));
        }
        if !matches!(v, Raw::Number(_) | Raw::Str(_)) {
            return Err(InputError::key(
                file,
                &key(n),
                format!("expected a number or a string, found {}", v.kind()),
            ));
        }
    }
    let index: HashMap<&str, usize> = raw
        .iter()
        .enumerate()
        .map(|(i, (n, _))| (n.as_str(), i))
        .collect();
    let deps: Vec<Vec<usize>> = raw
        .iter()
        .map(|(_, v)| match v {
            Raw::Str(s) => referenced_names(s)
                .iter()
                .filter_map(|n| index.get(n.as_str()).copied())
                .collect(),
            _ => Vec::new(),
        })
        .collect();
    // iterative depth-first topological order; state 1 = on the stack, 2 = done
    let mut state = vec![0u8; raw.len()];
    let mut values: Vec<Option<Value>> = vec![None; raw.len()];
    for root in 0..raw.len() {
        let mut stack: Vec<(usize, usize)> = vec![(root, 0)];
        while let Some(&(v, next)) = stack.last() {
            if state[v] == 2 {
                stack.pop();
                continue;
            }
            state[v] = 1;
            if let Some(&w) = deps[v].get(next) {
                stack.last_mut().expect("non-empty").1 += 1;
                if state[w] == 1 {
                    let start = stack.iter().position(|&(u, _)| u == w).unwrap_or(0);
                    let mut cycle: Vec<&str> = stack[start..]
                        .iter()
                        .map(|&(u, _)| raw[u].0.as_str())
                        .collect();
                    cycle.push(&raw[w].0);
                    return Err(InputError::key(
                        file,
                        &key(&raw[w].0),
                        format!(
                            "parameters depend on each other in a cycle: {}",
                            cycle.join(" -> ")
                        ),
                    ));
                }
                if state[w] == 0 {
                    stack.push((w, 0));
                }
                continue;
            }
            let lookup = |n: &str| index.get(n).and_then(|&j| values[j].clone());
            let val = eval_scalar(&raw[v].1, &lookup)
                .map_err(|m| InputError::key(file, &key(&raw[v].0), m))?;
            values[v] = Some(val);
            state[v] = 2;
            stack.pop();
        }
    }
    let mut out = Vec::with_capacity(raw.len());
    for ((n, _), v) in raw.iter().zip(values) {
        let v = v.expect("every parameter evaluated");
        scan.admit(&v, &format!("parameter '{n}'"))
            .map_err(|m| InputError::key(file, &key(n), m))?;
        out.push((n.clone(), v));
    }
    Ok(out)
}

/// One entry: a number (exact text) or an expression string.
fn eval_scalar(r: &Raw, lookup: &dyn Fn(&str) -> Option<Value>) -> Result<Value, String> {
    match r {
        // the same size limits as the text form (a bare 1e9999 is refused like "1e9999")
        Raw::Number(s) => expr::parse_number(s)
            .and_then(|q| Value::rational(q).checked())
            .map_err(|e| e.to_string()),
        Raw::Str(s) => expr::eval_with(s, lookup).map_err(|e| e.to_string()),
        other => Err(format!(
            "expected a number or a string, found {}",
            other.kind()
        )),
    }
}

fn read_matrix(
    file: &str,
    key: &str,
    r: &Raw,
    lookup: &dyn Fn(&str) -> Option<Value>,
    scan: &mut FieldScan,
) -> Result<MatrixEntries, InputError> {
    let owned: Vec<Vec<Raw>>;
    let single;
    let cells: Vec<&[Raw]> = match r {
        Raw::Str(s) => {
            owned = split_matlab_matrix(s)
                .map_err(|e| super::matlab::key_error(file, key, e))?
                .into_iter()
                .map(|row| row.into_iter().map(Raw::Str).collect())
                .collect();
            owned.iter().map(Vec::as_slice).collect()
        }
        Raw::Number(_) => {
            single = [r.clone()];
            vec![&single[..]]
        }
        Raw::Array(rows) => {
            let mut out: Vec<&[Raw]> = Vec::with_capacity(rows.len());
            for (i, row) in rows.iter().enumerate() {
                let Raw::Array(xs) = row else {
                    let msg = format!(
                        "expected a row (an array of entries, e.g. [[1, 2], [3, 4]]), found {}",
                        row.kind()
                    );
                    return Err(InputError {
                        row: Some(i + 1),
                        ..InputError::key(file, key, msg)
                    });
                };
                if let Some(first) = out.first()
                    && first.len() != xs.len()
                {
                    let msg = ragged_msg(xs.len(), first.len());
                    return Err(InputError {
                        row: Some(i + 1),
                        ..InputError::key(file, key, msg)
                    });
                }
                out.push(xs);
            }
            out
        }
        other => {
            let msg = format!(
                "expected a matrix (an array of rows or a string like \"[0 1; -2 -3]\"), found {}",
                other.kind()
            );
            return Err(InputError::key(file, key, msg));
        }
    };
    let nrows = cells.len();
    let ncols = cells.first().map_or(0, |r| r.len());
    let mut data = Vec::with_capacity(nrows * ncols);
    for (i, row) in cells.iter().enumerate() {
        for (j, x) in row.iter().enumerate() {
            let at = |m: String| InputError::entry(file, key, i + 1, j + 1, m);
            let v = eval_scalar(x, lookup).map_err(at)?;
            // the place text is only needed for a non-rational value (most are rational)
            if v.k.is_some() {
                scan.admit(&v, &format!("key {key}, row {}, column {}", i + 1, j + 1))
                    .map_err(at)?;
            }
            data.push(ExactScalar { a: v.a, b: v.b });
        }
    }
    Ok(MatrixEntries { nrows, ncols, data })
}

/// A `[]` given where the shape rules leave a zero dimension takes the shape `(rows, cols)`.
fn fit_empty(x: MatrixEntries, rows: Option<usize>, cols: Option<usize>) -> MatrixEntries {
    if x.nrows == 0 && x.ncols == 0 {
        let (r, c) = (rows.unwrap_or(0), cols.unwrap_or(0));
        if r == 0 || c == 0 {
            return MatrixEntries::zeros(r, c);
        }
    }
    x
}

fn shape_err(file: &str, key: &str, want: String, x: &MatrixEntries) -> InputError {
    InputError::key(
        file,
        key,
        format!("{key} must {want}, found {}x{}", x.nrows, x.ncols),
    )
    .with_kind(InputErrorKind::Shape)
}

fn check_shapes(
    file: &str,
    mut got: HashMap<&'static str, MatrixEntries>,
    sys: &mut SystemFile,
) -> Result<(), InputError> {
    let first = ["A", "B", "E"].into_iter().find(|k| got.contains_key(k));
    let second = ["M", "L", "K", "F"]
        .into_iter()
        .find(|k| got.contains_key(k));
    if let (Some(_), Some(k2)) = (first, second) {
        return Err(InputError::key(
            file,
            k2,
            "cannot mix the first-order form (A, B, E) with the second-order form (M, L, K, F)",
        )
        .with_kind(InputErrorKind::Shape));
    }
    // (states n, "what A is" for messages, input-matrix key)
    let (n, what, input_key) = if let Some(k2) = second {
        let Some(m) = got.remove("M") else {
            return Err(InputError::key(
                file,
                k2,
                "the second-order form needs the mass matrix M",
            ));
        };
        if m.nrows != m.ncols {
            return Err(shape_err(file, "M", "be square".into(), &m));
        }
        let n2 = m.nrows;
        for key in ["L", "K"] {
            let x = got.remove(key).map_or_else(
                || MatrixEntries::zeros(n2, n2),
                |x| fit_empty(x, Some(n2), Some(n2)),
            );
            if (x.nrows, x.ncols) != (n2, n2) {
                return Err(shape_err(file, key, format!("be {n2}x{n2} like M"), &x));
            }
            if key == "L" {
                sys.l = Some(x)
            } else {
                sys.k = Some(x)
            }
        }
        sys.m = Some(m);
        (
            2 * n2,
            format!("the state [q; q'] has {} entries", 2 * n2),
            "F",
        )
    } else {
        let Some(a) = got.remove("A") else {
            return Err(match first {
                Some(k) => InputError::key(file, k, "A is required with the first-order form"),
                None => InputError::file(
                    file,
                    "no system: give A (first-order form) or M, L, K, F (second-order form)",
                )
                .with_kind(InputErrorKind::NotASystem),
            });
        };
        if a.nrows != a.ncols {
            return Err(shape_err(file, "A", "be square".into(), &a));
        }
        let n = a.nrows;
        if let Some(e) = got.remove("E") {
            let e = fit_empty(e, Some(n), Some(n));
            if (e.nrows, e.ncols) != (n, n) {
                return Err(shape_err(file, "E", format!("be {n}x{n} like A"), &e));
            }
            sys.e = Some(e);
        }
        sys.a = Some(a);
        (n, format!("A is {n}x{n}"), "B")
    };
    // input matrix B (n x m) or F (n2 x m)
    let rows_in = if input_key == "F" { n / 2 } else { n };
    let d = got.remove("D");
    let input = match got.remove(input_key) {
        Some(x) => {
            // `[]` with no states takes its input count from D (a static gain)
            let x = fit_empty(x, Some(rows_in), d.as_ref().map(|d| d.ncols));
            if x.nrows != rows_in {
                let why = if input_key == "F" {
                    format!("M is {rows_in}x{rows_in}")
                } else {
                    what.clone()
                };
                return Err(shape_err(
                    file,
                    input_key,
                    format!("have {rows_in} rows ({why})"),
                    &x,
                ));
            }
            x
        }
        None => MatrixEntries::zeros(rows_in, d.as_ref().map_or(0, |d| d.ncols)),
    };
    let m = input.ncols;
    let c = match got.remove("C") {
        Some(x) => {
            let x = fit_empty(x, d.as_ref().map(|d| d.nrows), Some(n));
            if x.ncols != n {
                return Err(shape_err(
                    file,
                    "C",
                    format!("have {n} columns ({what})"),
                    &x,
                ));
            }
            x
        }
        None => MatrixEntries::zeros(d.as_ref().map_or(0, |d| d.nrows), n),
    };
    let p = c.nrows;
    let d = match d {
        Some(x) => {
            let x = fit_empty(x, Some(p), Some(m));
            if (x.nrows, x.ncols) != (p, m) {
                return Err(shape_err(
                    file,
                    "D",
                    format!("be {p}x{m} (outputs x inputs)"),
                    &x,
                ));
            }
            x
        }
        None => MatrixEntries::zeros(p, m),
    };
    if input_key == "F" {
        sys.f = Some(input)
    } else {
        sys.b = Some(input)
    }
    sys.c = Some(c);
    sys.d = Some(d);
    Ok(())
}

/// Reads only the matrix under `key` (with the parameters it uses) from a system file, of
/// any shape and whatever the other keys say: for commands on a plain matrix (`linalg`),
/// where the shape rules of a system do not apply.
///
/// # Errors
/// An unreadable or invalid file, a missing `key`, a bad entry or parameter.
pub fn read_matrix_key(
    path: &Path,
    key: &str,
) -> Result<(MatrixEntries, super::Ground), InputError> {
    let shown = path.display().to_string();
    let text = super::read::read_text(path)?;
    let raw = raw::from_text(&text, super::read::SystemFormat::of(path, &text), &shown)?;
    let Raw::Table(entries) = raw else {
        return Err(InputError::file(&shown, "expected a table of keys"));
    };
    let (mut ms, ground) = matrices_of_table(&shown, &entries, &[key])?;
    match ms.pop().flatten() {
        Some(m) => Ok((m, ground)),
        None => Err(InputError::key(&shown, key, "missing")),
    }
}

/// The matrices under `keys` of a file's table (`None` for a key it lacks), of any shape,
/// read by the one matrix reader of system files (arrays of rows or MATLAB-style strings,
/// entries over the file's `parameters`), and the field they lie in.
///
/// # Errors
/// A bad parameter or entry, ragged rows, values from two quadratic fields.
pub(crate) fn matrices_of_table(
    file: &str,
    entries: &[(String, Raw)],
    keys: &[&str],
) -> Result<(Vec<Option<MatrixEntries>>, super::Ground), InputError> {
    let params_raw = match entries.iter().find(|(k, _)| k == "parameters") {
        Some((_, Raw::Table(kv))) => kv.clone(),
        _ => Vec::new(),
    };
    let mut scan = FieldScan::default();
    let params = eval_parameters(file, &params_raw, &mut scan)?;
    let lookup = |n: &str| params.iter().find(|(p, _)| p == n).map(|(_, v)| v.clone());
    let mut out = Vec::with_capacity(keys.len());
    for key in keys {
        out.push(match entries.iter().find(|(k, _)| k == key) {
            Some((_, m)) => Some(read_matrix(file, key, m, &lookup, &mut scan)?),
            None => None,
        });
    }
    Ok((out, scan.ground()))
}

/// Refuses a reserved name (`i`, `sqrt`, `pi`) in the `symbols` key: as a symbol it would
/// change what the entries mean (`i^2 + 1` a polynomial instead of 0).
pub(crate) fn reserved_symbol(file: &str, s: &str) -> Result<(), InputError> {
    match crate::field::expr::reserved_meaning(s) {
        Some(m) => Err(InputError::key(
            file,
            "symbols",
            format!("'{s}' is reserved ({m}) and cannot name a symbol"),
        )),
        None => Ok(()),
    }
}
