//! A matrix of exact entries from several fields under construction for a report (texts,
//! LaTeX and approximations): the $J$, $T$ of Jordan forms and the modal tables.

use crate::field::Field;
use crate::matrix::Matrix;
use crate::report::{MatrixOut, Value};

/// A matrix of exact texts, LaTeX and approximations under construction (entries of
/// several fields).
pub(super) struct Cells(pub MatrixOut);

impl Cells {
    pub fn zeros(nrows: usize, ncols: usize) -> Self {
        Cells(MatrixOut {
            exact: vec![vec!["0".to_string(); ncols]; nrows],
            latex: vec![vec!["0".to_string(); ncols]; nrows],
            approx: vec![vec![(0.0, 0.0); ncols]; nrows],
            values: vec![
                vec![
                    Some(crate::field::ElemValue::Rational(num_traits::Zero::zero()));
                    ncols
                ];
                nrows
            ],
            nrows,
            ncols,
        })
    }
    /// Entry `(i, j)` from an element of `k` (its display, LaTeX and approximation).
    pub fn put<K: Field>(&mut self, (i, j): (usize, usize), k: &K, x: &K::Elem) {
        self.0.exact[i][j] = k.fmt_elem(x);
        self.0.latex[i][j] = k.latex_elem(x);
        self.0.approx[i][j] = k.approx(x).unwrap_or((f64::NAN, 0.0));
        self.0.values[i][j] = k.elem_value(x);
    }
    /// Entry `(i, j)` from a text (also its LaTeX) and a real approximation.
    pub fn text(&mut self, (i, j): (usize, usize), text: String, approx: f64) {
        self.0.latex[i][j] = text.clone();
        self.0.exact[i][j] = text;
        self.0.approx[i][j] = (approx, 0.0);
        self.0.values[i][j] = None;
    }
    /// Writes `m` with its top left corner at `(r, c)`.
    pub fn block<K: Field>(&mut self, (r, c): (usize, usize), m: &Matrix<K>) {
        for i in 0..m.nrows() {
            for j in 0..m.ncols() {
                self.put((r + i, c + j), m.field(), m.get(i, j));
            }
        }
    }
    pub fn value(self) -> Value {
        Value::Matrix(Box::new(self.0))
    }
}
