//! Exact input: system files (JSON, TOML), MATLAB-style matrix text and exact expressions.
//!
//! Everything read here is exact. A number is taken from the text as written (`0.08` is
//! $2/25$, `1.5e-3` is $3/2000$): JSON numbers through serde_json's `arbitrary_precision`
//! text, TOML integers and floats through the raw token text of `toml::de::DeTable`, never
//! through a binary float. String entries are expressions over the file's parameters with
//! `+ - * / ^` (integer exponents), parentheses, the imaginary unit `i` and square roots
//! `sqrt(r)` of rationals. Every value of a file lies in one *ground field*: $\mathbb{Q}$ or
//! one quadratic field $\mathbb{Q}(\sqrt d)$ ($d = -1$ is $\mathbb{Q}(i)$), and each value
//! is stored as an [`ExactScalar`] $a + b\sqrt d$ with $a, b \in \mathbb{Q}$.
//!
//! | entry point | reads |
//! |---|---|
//! | [`read_system_file`] | a system file (format chosen by extension, `.toml` or JSON) |
//! | [`parse_system_json`], [`parse_system_toml`] | system file text |
//! | [`parse_matlab_matrix`] | `"[0 1; -2 -3]"`, `"[1, 2/3; 0.5 -1e-2]"`, `"[]"` |
//! | [`split_matlab_matrix`] | the same, entries left as text (for evaluation over parameters) |
//! | [`load_system_str`], [`load_system_path`] | a system file → [`LoadedSystem`] (typed over its field; [`LoadedSystem::run`] dispatches generic code) |
//! | [`combine::common_field`], [`combine::gain_text`] | several files over one field (interconnection); a file with only `D` as a static gain |
//! | [`write::system_file_json`], [`write::system_file_text`] | a system back as a system file |
//! | [`plain_matrix::plain_square_matrix`] | a JSON file with only a plain rational square matrix, in one pass (the fast path of `linalg`; declines every other file) |
//! | [`eval_expr`] | one exact expression, e.g. `"-(a*cf - b*cr)/(Izz*u)"`, `"1 - sqrt(2)/2"` |
//!
//! Every failure is an [`InputError`] whose `Display` is one line naming the file, key, row
//! and column (1-based), e.g. `yaw.json: key A, row 2, column 3: unknown parameter 'cf'`;
//! the command-line program prints it and exits with status 2.
//!
//! Pipeline (STYLE.md 7.4): text → raw proxy tree (`raw.rs`, one shape for JSON and TOML)
//! → validation (`system_file.rs`: parameters in dependency order, entries, ground field,
//! shapes) → [`SystemFile`]. There is no unchecked path from text to a system.

pub(crate) mod combine;
pub(crate) mod expr;
pub mod ground;
pub(crate) mod keys;
pub(crate) mod load;
pub mod load_descriptor;
pub(crate) mod matlab;
pub mod model_file;
pub mod plain_matrix;
pub mod qmat;
pub(crate) mod raw;
pub mod read;
mod subst;
pub mod symbolic;
pub(crate) mod system_file;
pub mod transfer_expr;
mod transfer_key;
mod transfer_symbolic;
pub mod transfer_written;
mod value;
pub(crate) mod write;

pub use expr::eval_expr;
pub use ground::{GroundField, NumericField};
pub use keys::SignalNames;
pub use load::{
    FromScalars, LoadedSystem, SystemFormat, TypedAny, TypedSystem, as_rational, load_model_str,
    load_system_path, load_system_str,
};
pub use matlab::{parse_matlab_matrix, split_matlab_matrix};
pub use read::read_text;
pub use system_file::{SystemFile, parse_system_json, parse_system_toml, read_system_file};

use crate::field::{ElemDisplay, Q, Quadratic, QuadraticField, Rational};
use num_bigint::BigInt;
use num_traits::Zero;
use std::fmt;

/// An exact scalar of a system file: $a + b\sqrt d$ where `d` is the file's radicand
/// (the [`Ground`]); `b` is zero for every value when the ground is $\mathbb{Q}$.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct ExactScalar {
    pub a: Rational,
    pub b: Rational,
}

impl ExactScalar {
    /// The rational `q` (with `b = 0`).
    pub fn from_rational(q: Rational) -> Self {
        ExactScalar {
            a: q,
            b: Rational::zero(),
        }
    }
    /// The integer `n`.
    pub fn from_i64(n: i64) -> Self {
        Self::from_rational(Rational::from_integer(n.into()))
    }
    /// Zero.
    pub fn zero() -> Self {
        Self::from_i64(0)
    }
    /// Is the value rational (`b = 0`)?
    pub fn is_rational(&self) -> bool {
        self.b.is_zero()
    }
    /// Is the value zero?
    pub fn is_zero(&self) -> bool {
        self.a.is_zero() && self.b.is_zero()
    }
    /// `Some(a)` when the value is rational.
    pub fn to_rational(&self) -> Option<Rational> {
        self.is_rational().then(|| self.a.clone())
    }
    /// The element of [`QuadraticField`] with the same coordinates.
    pub fn to_quadratic(&self) -> Quadratic {
        Quadratic::new(self.a.clone(), self.b.clone())
    }
}

/// The one-line refusal of a command that does not yet work over $\mathbb{Q}(p)$.
pub fn refusal(what: &str, k: &crate::ratfunc::RatFuncField) -> String {
    format!("symbolic parameters: {what} is not yet supported over {k}; give values with --at")
}

/// The one field all values of a system file live in.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Ground {
    /// $\mathbb{Q}$: every value is rational.
    Rational,
    /// $\mathbb{Q}(\sqrt d)$ (`d = -1` is $\mathbb{Q}(i)$).
    Quadratic(QuadraticField),
    /// $\mathbb{Q}(p_1, \dots, p_k)$: symbolic parameters (see [`symbolic`]).
    RatFunc(crate::ratfunc::RatFuncField),
}

impl Ground {
    /// The radicand `d`, or `None` for $\mathbb{Q}$.
    pub fn radicand(&self) -> Option<&BigInt> {
        match self {
            Ground::Rational => None,
            Ground::Quadratic(k) => Some(k.d()),
            Ground::RatFunc(_) => None,
        }
    }
    /// Exact display of a scalar of this field, e.g. `-8/3`, `1 - sqrt(2)/2`, `2 + i`.
    pub fn fmt_scalar(&self, x: &ExactScalar) -> String {
        match self {
            Ground::Quadratic(k) => k.fmt_elem(&x.to_quadratic()),
            Ground::Rational | Ground::RatFunc(_) if x.is_rational() => Q.fmt_elem(&x.a),
            // a scalar that does not belong to Q: show its coordinates rather than lie
            Ground::Rational | Ground::RatFunc(_) => {
                format!("{} + {}*sqrt(?)", Q.fmt_elem(&x.a), Q.fmt_elem(&x.b))
            }
        }
    }
}

impl fmt::Display for Ground {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Ground::Rational => write!(f, "QQ"),
            Ground::Quadratic(k) => write!(f, "{k}"),
            Ground::RatFunc(k) => write!(f, "{k}"),
        }
    }
}

/// A dense matrix of exact scalars, row-major (`data[i * ncols + j]` is entry `(i, j)`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MatrixEntries {
    pub nrows: usize,
    pub ncols: usize,
    pub data: Vec<ExactScalar>,
}

impl MatrixEntries {
    /// The `nrows x ncols` zero matrix (either dimension may be 0).
    pub fn zeros(nrows: usize, ncols: usize) -> Self {
        MatrixEntries {
            nrows,
            ncols,
            data: vec![ExactScalar::zero(); nrows * ncols],
        }
    }
    /// The `n x n` identity.
    pub fn identity(n: usize) -> Self {
        let mut m = Self::zeros(n, n);
        for i in 0..n {
            m.data[i * n + i] = ExactScalar::from_i64(1);
        }
        m
    }
    /// Entry `(i, j)`, 0-based.
    ///
    /// # Panics
    /// When `i >= nrows` or `j >= ncols`.
    pub fn get(&self, i: usize, j: usize) -> &ExactScalar {
        assert!(i < self.nrows && j < self.ncols, "index out of bounds");
        &self.data[i * self.ncols + j]
    }
    /// Are all entries rational?
    pub fn is_rational(&self) -> bool {
        self.data.iter().all(ExactScalar::is_rational)
    }
    /// The rows as rationals, or `None` when some entry is not rational.
    pub fn to_rational_rows(&self) -> Option<Vec<Vec<Rational>>> {
        (0..self.nrows)
            .map(|i| {
                (0..self.ncols)
                    .map(|j| self.get(i, j).to_rational())
                    .collect()
            })
            .collect()
    }
    /// The rows as elements $a + b\sqrt d$ of a quadratic field.
    pub fn to_quadratic_rows(&self) -> Vec<Vec<Quadratic>> {
        (0..self.nrows)
            .map(|i| {
                (0..self.ncols)
                    .map(|j| self.get(i, j).to_quadratic())
                    .collect()
            })
            .collect()
    }
    /// Exact display `[[a, b], [c, d]]` with scalars shown in `ground`.
    pub fn display(&self, ground: &Ground) -> String {
        let rows: Vec<String> = (0..self.nrows)
            .map(|i| {
                let r: Vec<String> = (0..self.ncols)
                    .map(|j| ground.fmt_scalar(self.get(i, j)))
                    .collect();
                format!("[{}]", r.join(", "))
            })
            .collect();
        format!("[{}]", rows.join(", "))
    }
}

pub use crate::error::{InputError, InputErrorKind};
