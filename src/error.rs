//! The crate error: one enum, two families (see STYLE.md 7.4).
//!
//! *Input invalid or result undefined* (shape, field mismatch, singular, parse, a bad input
//! file with its place: [`Error::Input`], ...) versus *we cannot* (`Unsupported`, `Limit`):
//! only the second family may be retried with the float backend. [`Error::class`] is what
//! the command line (exit status, [`Error::exit_code`]) and the Python package (the
//! exception class) map; both map this one type.
//!
//! [`Error`] is the one error type of the library: every exact operation, loader and parser
//! returns it (an invalid expression is [`Error::Invalid`], a bad matrix text
//! [`Error::MatrixText`] with its row and column, a syntax error [`Error::Parse`] or
//! `Invalid` as the reader reports it). [`InputError`] is the payload of [`Error::Input`], reached by
//! `std::error::Error::source`; the command layer's `api::Failure` wraps an [`Error`] the same
//! way (its `source()` is the library error it came from).

use std::fmt;

/// Errors of every exact operation in the crate.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum Error {
    // ---- input outside the operation's domain / result undefined ----
    /// Shapes do not agree: `op` expected `expected`, found `found` (rows, cols).
    Shape {
        op: &'static str,
        expected: (usize, usize),
        found: (usize, usize),
    },
    /// A square matrix was required.
    NotSquare {
        op: &'static str,
        nrows: usize,
        ncols: usize,
    },
    /// Elements or matrices of two different fields were mixed.
    FieldMismatch,
    /// Division by zero in a field.
    DivisionByZero,
    /// A singular matrix where an invertible one is required.
    Singular,
    /// A modulus that is not irreducible (or not of degree >= 1) for a number field.
    NotIrreducible(String),
    /// A transfer matrix or descriptor system that is not proper where one is required.
    ImproperTransfer(String),
    /// A system is unstable where stability is required (e.g. Gramians).
    Unstable(String),
    /// An interconnection whose algebraic loop has no unique solution (feedback with
    /// $I - \sigma D_2 D_1$ singular).
    IllPosed(String),
    /// Text that does not parse: 1-based line and column, and what is wrong.
    Parse {
        line: usize,
        col: usize,
        msg: String,
    },
    /// A bad MATLAB-style matrix text (`"[1 2; 3]"`): the 1-based row and column when the
    /// error is about one row or entry, and what is wrong.
    MatrixText {
        row: Option<usize>,
        col: Option<usize>,
        msg: String,
    },
    /// Any other invalid input, with a message naming the condition (also an invalid
    /// expression: its `Display` is the message itself).
    Invalid(String),
    // ---- the implementation cannot do it ----
    /// A case this implementation does not (yet) handle.
    Unsupported(String),
    /// A resource limit (time, size) was reached.
    Limit(String),
    /// An exact verification failed: an internal error.
    Verification(String),
    /// A bad input file, with the place (file, key, row, column) and the kind.
    Input(Box<InputError>),
}

/// What a caller does with an [`Error`]: the command line's exit status and the Python
/// exception class follow it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ErrorClass {
    /// Bad input or an undefined result (exit 2; `ValueError`).
    Input,
    /// A case this implementation does not handle (exit 2; `NotImplementedError`).
    Unsupported,
    /// A size or time bound of the library (exit 2; `TimeoutError`).
    Limit,
    /// An exact identity failed: an internal error (exit 1; `VerificationError`).
    Verification,
}

/// The crate's result type.
pub type Result<T> = std::result::Result<T, Error>;

impl Error {
    /// True for the "we cannot" family (a float retry may help).
    pub fn is_unable(&self) -> bool {
        matches!(self, Error::Unsupported(_) | Error::Limit(_))
    }
    /// The class of the error ([`ErrorClass`]).
    pub fn class(&self) -> ErrorClass {
        match self {
            Error::Unsupported(_) => ErrorClass::Unsupported,
            Error::Limit(_) => ErrorClass::Limit,
            Error::Verification(_) => ErrorClass::Verification,
            _ => ErrorClass::Input,
        }
    }
    /// The command line's exit status: 1 for a failed exact check, 2 otherwise.
    pub fn exit_code(&self) -> i32 {
        self.class().exit_code()
    }
}

impl ErrorClass {
    /// The command line's exit status of the class: 1 for `Verification`, 2 otherwise.
    pub fn exit_code(self) -> i32 {
        if self == ErrorClass::Verification {
            1
        } else {
            2
        }
    }
}

impl From<InputError> for Error {
    fn from(e: InputError) -> Self {
        Error::Input(Box::new(e))
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Shape {
                op,
                expected,
                found,
            } => write!(
                f,
                "{op}: expected {}x{}, found {}x{}",
                expected.0, expected.1, found.0, found.1
            ),
            Error::NotSquare { op, nrows, ncols } => {
                write!(f, "{op}: matrix must be square, found {nrows}x{ncols}")
            }
            Error::FieldMismatch => write!(f, "elements of different fields were mixed"),
            Error::DivisionByZero => write!(f, "division by zero"),
            Error::Singular => write!(f, "matrix is singular"),
            Error::NotIrreducible(p) => write!(f, "modulus {p} is not irreducible over Q"),
            Error::ImproperTransfer(m) => write!(f, "improper system: {m}"),
            Error::Unstable(m) => write!(f, "unstable system: {m}"),
            Error::IllPosed(m) => write!(f, "ill-posed interconnection: {m}"),
            Error::Parse { line, col, msg } => write!(f, "line {line}, column {col}: {msg}"),
            Error::MatrixText { row, col, msg } => {
                if let Some(r) = row {
                    write!(f, "row {r}, ")?;
                }
                if let Some(c) = col {
                    write!(f, "column {c}, ")?;
                }
                write!(f, "{msg}")
            }
            Error::Invalid(m) => write!(f, "{m}"),
            Error::Unsupported(m) => write!(f, "unsupported: {m}"),
            Error::Limit(m) => write!(f, "limit reached: {m}"),
            Error::Verification(m) => write!(f, "verification failed: {m}"),
            Error::Input(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for Error {
    /// The bad input file's error for [`Error::Input`] (its place and kind); `None` otherwise.
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Error::Input(e) => Some(e.as_ref()),
            _ => None,
        }
    }
}

/// A bad input file: where (file, key, 1-based row and column) and what.
///
/// `Display` is a single line such as
/// `yaw.json: key A, row 2, column 3: unknown parameter 'cf'`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct InputError {
    pub file: String,
    pub key: Option<String>,
    pub row: Option<usize>,
    pub col: Option<usize>,
    pub msg: String,
    /// What kind of failure, for callers that must tell cases apart (the message is for
    /// people).
    pub kind: InputErrorKind,
}

/// The kind of an [`InputError`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum InputErrorKind {
    /// A bad value: an entry or parameter that does not evaluate, a wrong type, a cycle.
    #[default]
    Value,
    /// Text that is not valid JSON/TOML/expression syntax.
    Syntax,
    /// The file cannot be read (missing, unreadable, not UTF-8).
    Read,
    /// The file is larger than `crate::io::read::MAX_FILE_BYTES`.
    TooLarge,
    /// A key this format does not know (with a suggestion when one is close).
    UnknownKey,
    /// A key given twice.
    DuplicateKey,
    /// Matrix shapes that do not agree, or a missing required matrix.
    Shape,
    /// Valid data that is not a system file (e.g. the bicycle benchmark's raw matrices).
    NotASystem,
    /// A feature or field the reader or the loader does not support here.
    Unsupported,
}

impl InputError {
    /// An error about the whole file.
    pub fn file(file: &str, msg: impl Into<String>) -> Self {
        InputError {
            file: file.to_string(),
            key: None,
            row: None,
            col: None,
            msg: msg.into(),
            kind: InputErrorKind::Value,
        }
    }
    /// The same error with kind `kind`.
    pub fn with_kind(self, kind: InputErrorKind) -> Self {
        InputError { kind, ..self }
    }
    /// An error about one key of the file.
    pub fn key(file: &str, key: &str, msg: impl Into<String>) -> Self {
        InputError {
            key: Some(key.to_string()),
            ..Self::file(file, msg)
        }
    }
    /// An error about one entry (1-based `row`, `col`) of a matrix key.
    pub fn entry(file: &str, key: &str, row: usize, col: usize, msg: impl Into<String>) -> Self {
        InputError {
            row: Some(row),
            col: Some(col),
            ..Self::key(file, key, msg)
        }
    }
}

impl fmt::Display for InputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: ", self.file)?;
        let mut parts = Vec::new();
        if let Some(k) = &self.key {
            parts.push(format!("key {k}"));
        }
        if let Some(r) = self.row {
            parts.push(format!("row {r}"));
        }
        if let Some(c) = self.col {
            parts.push(format!("column {c}"));
        }
        if !parts.is_empty() {
            write!(f, "{}: ", parts.join(", "))?;
        }
        // one line, always
        write!(f, "{}", self.msg.replace(['\n', '\r'], " "))
    }
}

impl std::error::Error for InputError {}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every variant has the class the command line and Python map: exit 1 only for a failed
    /// exact check; an input error keeps its place and says the one line of the file error.
    #[test]
    fn classes_and_exit_codes() {
        let input = InputError::entry("f.json", "A", 2, 3, "unknown parameter 'cf'")
            .with_kind(InputErrorKind::Value);
        let cases = [
            (Error::Singular, ErrorClass::Input),
            (Error::Invalid("x".into()), ErrorClass::Input),
            (Error::Input(Box::new(input.clone())), ErrorClass::Input),
            (Error::Unsupported("x".into()), ErrorClass::Unsupported),
            (Error::Limit("x".into()), ErrorClass::Limit),
            (Error::Verification("x".into()), ErrorClass::Verification),
        ];
        for (e, class) in cases {
            assert_eq!(e.class(), class, "{e}");
            assert_eq!(
                e.exit_code(),
                if class == ErrorClass::Verification {
                    1
                } else {
                    2
                }
            );
            assert_eq!(
                e.is_unable(),
                matches!(class, ErrorClass::Unsupported | ErrorClass::Limit)
            );
        }
        let e = Error::from(input.clone());
        assert_eq!(
            e.to_string(),
            "f.json: key A, row 2, column 3: unknown parameter 'cf'"
        );
        assert_eq!(e, Error::Input(Box::new(input.clone())));
        let boxed: Box<dyn std::error::Error> = Box::new(e);
        assert!(boxed.to_string().starts_with("f.json: "));
        // the place is reachable as the source; other variants have none
        let src = boxed
            .source()
            .expect("an input error has its file error as source");
        assert_eq!(src.to_string(), input.to_string());
        assert!(std::error::Error::source(&Error::Singular).is_none());
    }
}
