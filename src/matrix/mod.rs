//! Exact dense matrices over any [`Field`].
//!
//! [`Matrix<K>`] stores its domain value `K` and its entries row-major. Operators `+ - *`
//! act on references and panic on shape mismatch (as nalgebra); `try_*` methods return
//! [`Error::Shape`] instead.
//!
//! | entry point | computes |
//! |---|---|
//! | [`Matrix::rref`] | canonical reduced row echelon form $R = P A$ and pivot columns |
//! | [`Matrix::rank`], [`Matrix::nullspace`], [`Matrix::left_nullspace`] | from the RREF |
//! | [`Matrix::inverse`], [`Matrix::det`], [`Matrix::solve`] | Gauss–Jordan over `K` |
//! | [`Matrix::charpoly`], [`Matrix::minpoly`] | $\det(xI - A)$ (Hessenberg), minimal polynomial |
//! | [`Matrix::eval_poly`] | $p(A)$ by Horner |
//!
//! The heavy operations first ask the field for a registered kernel ([`crate::field::Kernels`],
//! dispatched in one place per operation by `kernels`): over $\mathbb{Q}$ the fraction-free
//! and multi-modular kernels of [`crate::qkernels`] (chosen by size in [`over_q`]), over
//! $\mathbb{Q}(\sqrt d)$ those of [`over_k`], over $\mathbb{Q}(p)$ evaluation/interpolation
//! ([`crate::ratfunc::kernels`]).

mod charpoly;
mod kernels;
mod ops;
pub mod over_k;
pub mod over_q;
pub mod params;
pub mod qp_conditions;
mod rref;

pub(crate) use rref::nullspace_from_rref;

use crate::error::{Error, Result};
use crate::field::{Field, Q, Rational};

/// A dense matrix over the field `K`, row-major.
#[derive(Clone, Debug, PartialEq)]
pub struct Matrix<K: Field> {
    field: K,
    nrows: usize,
    ncols: usize,
    data: Vec<K::Elem>,
}

impl<K: Field> Matrix<K> {
    /// From row-major data.
    ///
    /// # Panics
    /// When `data.len() != nrows * ncols`.
    pub fn from_vec(field: K, nrows: usize, ncols: usize, data: Vec<K::Elem>) -> Self {
        assert_eq!(data.len(), nrows * ncols, "matrix data length");
        Matrix {
            field,
            nrows,
            ncols,
            data,
        }
    }
    /// From rows.
    ///
    /// # Errors
    /// `Shape` when rows have different lengths.
    pub fn from_rows(field: K, rows: Vec<Vec<K::Elem>>) -> Result<Self> {
        let nrows = rows.len();
        let ncols = rows.first().map_or(0, |r| r.len());
        let mut data = Vec::with_capacity(nrows * ncols);
        for (i, r) in rows.into_iter().enumerate() {
            if r.len() != ncols {
                return Err(Error::Invalid(format!(
                    "row {} has {} entries, expected {ncols}",
                    i + 1,
                    r.len()
                )));
            }
            data.extend(r);
        }
        Ok(Matrix {
            field,
            nrows,
            ncols,
            data,
        })
    }
    pub fn from_fn(
        field: K,
        nrows: usize,
        ncols: usize,
        mut f: impl FnMut(usize, usize) -> K::Elem,
    ) -> Self {
        let mut data = Vec::with_capacity(nrows * ncols);
        for i in 0..nrows {
            for j in 0..ncols {
                data.push(f(i, j));
            }
        }
        Matrix {
            field,
            nrows,
            ncols,
            data,
        }
    }
    pub fn zeros(field: K, nrows: usize, ncols: usize) -> Self {
        let z = field.zero();
        Matrix {
            data: vec![z; nrows * ncols],
            field,
            nrows,
            ncols,
        }
    }
    pub fn identity(field: K, n: usize) -> Self {
        let mut m = Self::zeros(field, n, n);
        for i in 0..n {
            m.data[i * n + i] = m.field.one();
        }
        m
    }
    pub fn diagonal(field: K, d: &[K::Elem]) -> Self {
        let n = d.len();
        let mut m = Self::zeros(field, n, n);
        for (i, x) in d.iter().enumerate() {
            m.data[i * n + i] = x.clone();
        }
        m
    }
    /// Column vector.
    pub fn column(field: K, v: Vec<K::Elem>) -> Self {
        let n = v.len();
        Matrix {
            field,
            nrows: n,
            ncols: 1,
            data: v,
        }
    }
    pub fn field(&self) -> &K {
        &self.field
    }
    pub fn nrows(&self) -> usize {
        self.nrows
    }
    pub fn ncols(&self) -> usize {
        self.ncols
    }
    pub fn shape(&self) -> (usize, usize) {
        (self.nrows, self.ncols)
    }
    pub fn is_square(&self) -> bool {
        self.nrows == self.ncols
    }
    pub fn as_slice(&self) -> &[K::Elem] {
        &self.data
    }
    pub fn into_vec(self) -> Vec<K::Elem> {
        self.data
    }
    pub fn get(&self, i: usize, j: usize) -> &K::Elem {
        &self.data[i * self.ncols + j]
    }
    pub fn get_mut(&mut self, i: usize, j: usize) -> &mut K::Elem {
        &mut self.data[i * self.ncols + j]
    }
    pub fn set(&mut self, i: usize, j: usize, v: K::Elem) {
        self.data[i * self.ncols + j] = v;
    }
    pub fn row(&self, i: usize) -> &[K::Elem] {
        &self.data[i * self.ncols..(i + 1) * self.ncols]
    }
    pub fn col(&self, j: usize) -> Vec<K::Elem> {
        (0..self.nrows).map(|i| self.get(i, j).clone()).collect()
    }
    pub fn rows(&self) -> Vec<Vec<K::Elem>> {
        (0..self.nrows).map(|i| self.row(i).to_vec()).collect()
    }
    pub fn is_zero(&self) -> bool {
        self.data.iter().all(|x| self.field.is_zero(x))
    }
    pub fn is_identity(&self) -> bool {
        self.is_square()
            && (0..self.nrows).all(|i| (0..self.ncols).all(|j| self.is_delta(i, j, i == j)))
    }
    /// Do the columns `cols`, in this order, form the identity (one per row)?
    pub fn is_identity_on_cols(&self, cols: &[usize]) -> bool {
        cols.len() == self.nrows
            && cols
                .iter()
                .enumerate()
                .all(|(k, &c)| (0..self.nrows).all(|i| self.is_delta(i, c, i == k)))
    }
    /// Do the rows `rows`, in this order, form the identity (one per column)?
    pub fn is_identity_on_rows(&self, rows: &[usize]) -> bool {
        rows.len() == self.ncols
            && rows
                .iter()
                .enumerate()
                .all(|(k, &r)| (0..self.ncols).all(|j| self.is_delta(r, j, j == k)))
    }
    /// Entry `(i, j)` is one (`one`) or zero (not `one`).
    fn is_delta(&self, i: usize, j: usize, one: bool) -> bool {
        let x = self.get(i, j);
        if one {
            self.field.is_one(x)
        } else {
            self.field.is_zero(x)
        }
    }
    /// Converts every entry into another field.
    pub fn map<L: Field>(&self, to: &L, f: impl Fn(&K::Elem) -> L::Elem) -> Matrix<L> {
        Matrix {
            field: to.clone(),
            nrows: self.nrows,
            ncols: self.ncols,
            data: self.data.iter().map(f).collect(),
        }
    }
    /// Shape check helper.
    pub(crate) fn check_shape(&self, op: &'static str, expected: (usize, usize)) -> Result<()> {
        if self.shape() != expected {
            return Err(Error::Shape {
                op,
                expected,
                found: self.shape(),
            });
        }
        Ok(())
    }
    pub(crate) fn check_square(&self, op: &'static str) -> Result<()> {
        if !self.is_square() {
            return Err(Error::NotSquare {
                op,
                nrows: self.nrows,
                ncols: self.ncols,
            });
        }
        Ok(())
    }
    /// Entry-wise floating-point approximation (real parts), for `_approx` outputs; NaN for
    /// an entry the field cannot approximate ([`Field::approx`] is `None`), see
    /// [`Matrix::try_to_approx_complex`].
    pub fn to_approx(&self) -> Vec<Vec<f64>> {
        self.to_approx_complex()
            .into_iter()
            .map(|row| row.into_iter().map(|z| z.0).collect())
            .collect()
    }
    /// Entry-wise floating-point approximation `(re, im)`; `(NaN, NaN)` for an entry the
    /// field cannot approximate.
    pub fn to_approx_complex(&self) -> Vec<Vec<(f64, f64)>> {
        (0..self.nrows)
            .map(|i| {
                self.row(i)
                    .iter()
                    .map(|x| self.field.approx(x).unwrap_or((f64::NAN, f64::NAN)))
                    .collect()
            })
            .collect()
    }
    /// Entry-wise floating-point approximation `(re, im)`; `None` when the field has no
    /// numeric embedding for some entry.
    pub fn try_to_approx_complex(&self) -> Option<Vec<Vec<(f64, f64)>>> {
        (0..self.nrows)
            .map(|i| self.row(i).iter().map(|x| self.field.approx(x)).collect())
            .collect()
    }
}

impl Matrix<Q> {
    /// From integer rows.
    pub fn from_i64_rows(rows: &[&[i64]]) -> Self {
        let nrows = rows.len();
        let ncols = rows.first().map_or(0, |r| r.len());
        Matrix::from_fn(Q, nrows, ncols, |i, j| {
            Rational::from_integer(rows[i][j].into())
        })
    }
    /// Lifts a rational matrix into any field.
    pub fn convert_to<L: Field>(&self, to: &L) -> Matrix<L> {
        self.map(to, |x| to.from_rational(x))
    }
}

/// Converts a matrix whose entries all lie in $\mathbb{Q}$ down to `Matrix<Q>`.
pub fn to_rational_matrix<K: Field>(m: &Matrix<K>) -> Option<Matrix<Q>> {
    let data: Option<Vec<Rational>> = m
        .as_slice()
        .iter()
        .map(|x| m.field().to_rational(x))
        .collect();
    Some(Matrix::from_vec(Q, m.nrows(), m.ncols(), data?))
}

// `qmat!` (integers, rationals and exact text such as "0.08") is defined in crate::io::qmat.
