//! Structural operations and arithmetic: blocks, stacking, transpose, products, powers,
//! Kronecker products, `vec`/`unvec`, similarity.

use super::Matrix;
use crate::error::{Error, Result};
use crate::field::Field;
use std::ops::{Add, Mul, Neg, Sub};

impl<K: Field> Matrix<K> {
    pub fn transpose(&self) -> Self {
        Matrix::from_fn(self.field.clone(), self.ncols, self.nrows, |i, j| {
            self.get(j, i).clone()
        })
    }
    /// Rows `r0..r1`, columns `c0..c1`.
    pub fn submatrix(&self, r0: usize, r1: usize, c0: usize, c1: usize) -> Self {
        Matrix::from_fn(self.field.clone(), r1 - r0, c1 - c0, |i, j| {
            self.get(r0 + i, c0 + j).clone()
        })
    }
    pub fn select_rows(&self, rows: &[usize]) -> Self {
        Matrix::from_fn(self.field.clone(), rows.len(), self.ncols, |i, j| {
            self.get(rows[i], j).clone()
        })
    }
    pub fn select_cols(&self, cols: &[usize]) -> Self {
        Matrix::from_fn(self.field.clone(), self.nrows, cols.len(), |i, j| {
            self.get(i, cols[j]).clone()
        })
    }
    /// Writes `b` into `self` with its top-left corner at `(r, c)`.
    pub fn set_block(&mut self, r: usize, c: usize, b: &Matrix<K>) {
        for i in 0..b.nrows {
            for j in 0..b.ncols {
                self.set(r + i, c + j, b.get(i, j).clone());
            }
        }
    }
    /// `[self, b]`.
    ///
    /// # Errors
    /// `Shape` when row counts differ.
    pub fn hstack(&self, b: &Matrix<K>) -> Result<Self> {
        if self.nrows != b.nrows {
            return Err(Error::Shape {
                op: "hstack",
                expected: (self.nrows, b.ncols),
                found: b.shape(),
            });
        }
        let mut m = Matrix::zeros(self.field.clone(), self.nrows, self.ncols + b.ncols);
        m.set_block(0, 0, self);
        m.set_block(0, self.ncols, b);
        Ok(m)
    }
    /// `[self; b]`.
    ///
    /// # Errors
    /// `Shape` when column counts differ.
    pub fn vstack(&self, b: &Matrix<K>) -> Result<Self> {
        if self.ncols != b.ncols {
            return Err(Error::Shape {
                op: "vstack",
                expected: (b.nrows, self.ncols),
                found: b.shape(),
            });
        }
        let mut data = self.data.clone();
        data.extend(b.data.iter().cloned());
        Ok(Matrix::from_vec(
            self.field.clone(),
            self.nrows + b.nrows,
            self.ncols,
            data,
        ))
    }
    /// Block matrix from a grid of blocks (each block row shares a row count, each block
    /// column a column count).
    ///
    /// # Errors
    /// `Shape` when the blocks do not fit.
    pub fn block(field: K, grid: &[Vec<&Matrix<K>>]) -> Result<Self> {
        let mut rows: Option<Matrix<K>> = None;
        for brow in grid {
            let mut acc: Option<Matrix<K>> = None;
            for b in brow {
                acc = Some(match acc {
                    None => (*b).clone(),
                    Some(a) => a.hstack(b)?,
                });
            }
            let acc = acc.unwrap_or_else(|| Matrix::zeros(field.clone(), 0, 0));
            rows = Some(match rows {
                None => acc,
                Some(r) => r.vstack(&acc)?,
            });
        }
        Ok(rows.unwrap_or_else(|| Matrix::zeros(field, 0, 0)))
    }
    /// Block-diagonal matrix.
    pub fn block_diag(field: K, blocks: &[Matrix<K>]) -> Self {
        let n: usize = blocks.iter().map(|b| b.nrows).sum();
        let m: usize = blocks.iter().map(|b| b.ncols).sum();
        let mut out = Matrix::zeros(field, n, m);
        let (mut r, mut c) = (0, 0);
        for b in blocks {
            out.set_block(r, c, b);
            r += b.nrows;
            c += b.ncols;
        }
        out
    }
    /// Entry-wise combination of two matrices of the same shape.
    fn zip_with(
        &self,
        b: &Matrix<K>,
        op: &'static str,
        f: impl Fn(&K::Elem, &K::Elem) -> K::Elem,
    ) -> Result<Self> {
        b.check_shape(op, self.shape())?;
        let data = self
            .data
            .iter()
            .zip(&b.data)
            .map(|(x, y)| f(x, y))
            .collect();
        Ok(Matrix::from_vec(
            self.field.clone(),
            self.nrows,
            self.ncols,
            data,
        ))
    }
    /// # Errors
    /// `Shape` on mismatch.
    pub fn try_add(&self, b: &Matrix<K>) -> Result<Self> {
        self.zip_with(b, "add", |x, y| self.field.add(x, y))
    }
    /// # Errors
    /// `Shape` on mismatch.
    pub fn try_sub(&self, b: &Matrix<K>) -> Result<Self> {
        self.zip_with(b, "sub", |x, y| self.field.sub(x, y))
    }
    /// Matrix product.
    ///
    /// # Errors
    /// `Shape` when `self.ncols != b.nrows`.
    pub fn try_mul(&self, b: &Matrix<K>) -> Result<Self> {
        if self.ncols != b.nrows {
            return Err(Error::Shape {
                op: "mul",
                expected: (self.ncols, b.ncols),
                found: b.shape(),
            });
        }
        let k = &self.field;
        if let Some(p) = super::kernels::mul(self, b) {
            return Ok(p);
        }
        let mut out = vec![k.zero(); self.nrows * b.ncols];
        for i in 0..self.nrows {
            let orow = &mut out[i * b.ncols..(i + 1) * b.ncols];
            for l in 0..self.ncols {
                let a = self.get(i, l);
                if k.is_zero(a) {
                    continue;
                }
                let brow = b.row(l);
                for j in 0..b.ncols {
                    k.mul_add_assign(&mut orow[j], a, &brow[j]);
                }
            }
        }
        Ok(Matrix::from_vec(k.clone(), self.nrows, b.ncols, out))
    }
    pub fn scale(&self, c: &K::Elem) -> Self {
        let k = &self.field;
        Matrix::from_vec(
            k.clone(),
            self.nrows,
            self.ncols,
            self.data.iter().map(|x| k.mul(x, c)).collect(),
        )
    }
    /// $A^e$ (square matrices).
    ///
    /// # Errors
    /// `NotSquare`.
    pub fn pow(&self, e: u32) -> Result<Self> {
        self.check_square("pow")?;
        let one = Matrix::identity(self.field.clone(), self.nrows);
        Ok(crate::field::pow_by_squaring(self, e, one, |a, b| a * b))
    }
    /// Kronecker product $A \otimes B$.
    pub fn kron(&self, b: &Matrix<K>) -> Self {
        let k = &self.field;
        Matrix::from_fn(
            k.clone(),
            self.nrows * b.nrows,
            self.ncols * b.ncols,
            |i, j| {
                k.mul(
                    self.get(i / b.nrows, j / b.ncols),
                    b.get(i % b.nrows, j % b.ncols),
                )
            },
        )
    }
    /// Column-stacking $\mathrm{vec}(A)$ as an `(m n) x 1` matrix.
    pub fn vec(&self) -> Self {
        let t = self.transpose();
        Matrix::from_vec(self.field.clone(), self.nrows * self.ncols, 1, t.data)
    }
    /// Inverse of [`Matrix::vec`]: an `nrows x ncols` matrix from a column of length
    /// `nrows * ncols`.
    ///
    /// # Errors
    /// `Shape` when the length does not match.
    pub fn unvec(&self, nrows: usize, ncols: usize) -> Result<Self> {
        self.check_shape("unvec", (nrows * ncols, 1))?;
        Ok(Matrix::from_fn(self.field.clone(), nrows, ncols, |i, j| {
            self.data[j * nrows + i].clone()
        }))
    }
    /// $T^{-1} A T$ (the matrix of $A$ in coordinates $x = T z$).
    ///
    /// # Errors
    /// `Singular` when `T` is not invertible; `Shape` on mismatch.
    pub fn similar_by(&self, t: &Matrix<K>) -> Result<Self> {
        let ti = t.inverse()?;
        ti.try_mul(&self.try_mul(t)?)
    }
}

impl<K: Field> Add for &Matrix<K> {
    type Output = Matrix<K>;
    fn add(self, b: &Matrix<K>) -> Matrix<K> {
        self.try_add(b).expect("matrix add: shape mismatch")
    }
}
impl<K: Field> Sub for &Matrix<K> {
    type Output = Matrix<K>;
    fn sub(self, b: &Matrix<K>) -> Matrix<K> {
        self.try_sub(b).expect("matrix sub: shape mismatch")
    }
}
impl<K: Field> Mul for &Matrix<K> {
    type Output = Matrix<K>;
    fn mul(self, b: &Matrix<K>) -> Matrix<K> {
        self.try_mul(b).expect("matrix mul: shape mismatch")
    }
}
impl<K: Field> Neg for &Matrix<K> {
    type Output = Matrix<K>;
    fn neg(self) -> Matrix<K> {
        let k = &self.field;
        Matrix::from_vec(
            k.clone(),
            self.nrows,
            self.ncols,
            self.data.iter().map(|x| k.neg(x)).collect(),
        )
    }
}
