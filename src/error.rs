//! The crate error: one enum, two families (see STYLE.md 7.4).
//!
//! *Input invalid or result undefined* (shape, field mismatch, singular, parse, ...) versus
//! *we cannot* (`Unsupported`, `Limit`): only the second family may be retried with the float
//! backend.

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
    /// Any other invalid input, with a message naming the condition.
    Invalid(String),
    // ---- the implementation cannot do it ----
    /// A case this implementation does not (yet) handle.
    Unsupported(String),
    /// A resource limit (time, size) was reached.
    Limit(String),
    /// An exact verification failed: an internal error.
    Verification(String),
}

/// The crate's result type.
pub type Result<T> = std::result::Result<T, Error>;

impl Error {
    /// True for the "we cannot" family (a float retry may help).
    pub fn is_unable(&self) -> bool {
        matches!(self, Error::Unsupported(_) | Error::Limit(_))
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
            Error::Invalid(m) => write!(f, "{m}"),
            Error::Unsupported(m) => write!(f, "unsupported: {m}"),
            Error::Limit(m) => write!(f, "limit reached: {m}"),
            Error::Verification(m) => write!(f, "verification failed: {m}"),
        }
    }
}

impl std::error::Error for Error {}
