//! Rational matrices from literals and text: [`qmat!`](crate::qmat) and
//! [`Matrix::<Q>::from_str_rows`](crate::matrix::Matrix::from_str_rows).
//!
//! Text entries are read exactly, as in system files: `"0.08"` is $2/25$, `"1.5e-3"` is
//! $3/2000$, `"-3/7"` is $-3/7$, with the reader's size bounds.

use super::expr::parse_number;
use crate::error::{Error, Result};
use crate::field::{Q, Rational};
use crate::matrix::Matrix;

/// An entry accepted by [`qmat!`](crate::qmat): an integer, a [`Rational`], or exact text.
pub trait QEntry {
    /// The exact rational value, or what is wrong with the text.
    fn to_q(self) -> std::result::Result<Rational, String>;
}

macro_rules! int_entry {
    ($($t:ty),*) => {$(
        impl QEntry for $t {
            fn to_q(self) -> std::result::Result<Rational, String> {
                Ok(Rational::from_integer(self.into()))
            }
        }
    )*};
}
int_entry!(
    i8, i16, i32, i64, i128, u8, u16, u32, u64, u128, isize, usize
);

impl QEntry for Rational {
    fn to_q(self) -> std::result::Result<Rational, String> {
        Ok(self)
    }
}

impl QEntry for &Rational {
    fn to_q(self) -> std::result::Result<Rational, String> {
        Ok(self.clone())
    }
}

impl QEntry for &str {
    fn to_q(self) -> std::result::Result<Rational, String> {
        let t = self.trim();
        // a leading sign and one fraction bar around exact decimals
        let (neg, body) = match t.strip_prefix('-') {
            Some(rest) => (true, rest.trim_start()),
            None => (false, t.strip_prefix('+').unwrap_or(t).trim_start()),
        };
        let q = match body.split_once('/') {
            Some((n, d)) => {
                let n = parse_number(n.trim()).map_err(|e| e.to_string())?;
                let d = parse_number(d.trim()).map_err(|e| e.to_string())?;
                if d == Rational::from_integer(0.into()) {
                    return Err(format!("division by zero in '{self}'"));
                }
                n / d
            }
            None => parse_number(body).map_err(|e| e.to_string())?,
        };
        Ok(if neg { -q } else { q })
    }
}

impl QEntry for &String {
    fn to_q(self) -> std::result::Result<Rational, String> {
        self.as_str().to_q()
    }
}

impl QEntry for String {
    fn to_q(self) -> std::result::Result<Rational, String> {
        self.as_str().to_q()
    }
}

impl Matrix<Q> {
    /// A rational matrix from rows of exact text entries (`"0.08"`, `"-3/7"`, `"1e-3"`).
    ///
    /// # Examples
    /// ```
    /// use exactlti::field::Q;
    /// use exactlti::matrix::Matrix;
    /// let a = Matrix::<Q>::from_str_rows(&[["0", "1"], ["-2", "-0.08"]]).unwrap();
    /// assert_eq!(a.to_string(), "[[0, 1], [-2, -2/25]]");
    /// assert!(Matrix::<Q>::from_str_rows(&[["1", "x"]]).is_err());
    /// ```
    ///
    /// # Errors
    /// `Parse` naming the 1-based row and column of an entry that is not an exact number;
    /// `Invalid` for ragged rows.
    pub fn from_str_rows<R: AsRef<[S]>, S: AsRef<str>>(rows: &[R]) -> Result<Self> {
        let rows: Vec<Vec<Rational>> = rows
            .iter()
            .enumerate()
            .map(|(i, r)| {
                r.as_ref()
                    .iter()
                    .enumerate()
                    .map(|(j, x)| {
                        x.as_ref().to_q().map_err(|msg| Error::Parse {
                            line: i + 1,
                            col: j + 1,
                            msg,
                        })
                    })
                    .collect()
            })
            .collect::<Result<_>>()?;
        Matrix::from_rows(Q, rows)
    }
}

/// Builds the matrix of [`qmat!`](crate::qmat).
///
/// # Panics
/// With the row, column and reason when an entry is not an exact number or the rows are
/// ragged (entries are program text, like the literals of `vec!`).
#[doc(hidden)]
pub fn qmat_from_entries(rows: Vec<Vec<std::result::Result<Rational, String>>>) -> Matrix<Q> {
    let rows: Vec<Vec<Rational>> = rows
        .into_iter()
        .enumerate()
        .map(|(i, r)| {
            r.into_iter()
                .enumerate()
                .map(|(j, x)| {
                    x.unwrap_or_else(|e| panic!("qmat!: row {}, column {}: {e}", i + 1, j + 1))
                })
                .collect()
        })
        .collect();
    if rows.is_empty() {
        return Matrix::zeros(Q, 0, 0);
    }
    Matrix::from_rows(Q, rows).unwrap_or_else(|e| panic!("qmat!: {e}"))
}

/// A rational matrix from rows of integers, [`Rational`]s or exact text:
/// `qmat![[0, 1], [-2, "-0.08"]]` is `[[0, 1], [-2, -2/25]]`.
///
/// # Examples
/// ```
/// use exactlti::qmat;
/// let a = qmat![[0, 1], ["-1/3", "0.08"]];
/// assert_eq!(a.to_string(), "[[0, 1], [-1/3, 2/25]]");
/// ```
///
/// # Panics
/// When an entry is not an exact number or the rows are ragged.
#[macro_export]
macro_rules! qmat {
    ($([$($x:expr),* $(,)?]),* $(,)?) => {
        $crate::io::qmat::qmat_from_entries(vec![$(vec![$($crate::io::qmat::QEntry::to_q($x)),*]),*])
    };
}
