//! Exact arithmetic of transfer matrices: $F + G$, $F - G$, $F G$, $\mathrm{diag}(F, G)$,
//! the identity and constant matrices, entries kept in lowest terms with monic denominators
//! (so that two equal rational matrices are equal as values).
//!
//! Used to state interconnection identities on transfer matrices ($G_2 G_1$,
//! $G_1 + G_2$, $(I - \sigma G K) G_{fb} = G$) independently of the state-space formulas.

use super::transfer::{RationalFunction, TransferMatrix};
use crate::error::{Error, Result};
use crate::field::Field;
use crate::matrix::Matrix;
use crate::poly::Poly;

impl<K: Field> RationalFunction<K> {
    /// The constant `c`.
    pub fn constant(k: &K, c: K::Elem) -> Self {
        RationalFunction::new(Poly::constant(k.clone(), c), Poly::one(k.clone()))
    }
    /// `self + g`.
    pub fn add(&self, g: &Self) -> Self {
        if self.den == g.den {
            return RationalFunction::new(self.num.add(&g.num), self.den.clone());
        }
        let num = self.num.mul(&g.den).add(&g.num.mul(&self.den));
        RationalFunction::new(num, self.den.mul(&g.den))
    }
    /// `-self`.
    pub fn neg(&self) -> Self {
        RationalFunction {
            num: self.num.neg(),
            den: self.den.clone(),
        }
    }
    /// `self - g`.
    pub fn sub(&self, g: &Self) -> Self {
        self.add(&g.neg())
    }
    /// `self * g`.
    pub fn mul(&self, g: &Self) -> Self {
        RationalFunction::new(self.num.mul(&g.num), self.den.mul(&g.den))
    }
    pub fn is_zero(&self) -> bool {
        self.num.is_zero()
    }
}

impl<K: Field> TransferMatrix<K> {
    /// (rows, columns).
    pub fn shape(&self) -> (usize, usize) {
        (
            self.entries.len(),
            self.entries.first().map_or(0, |r| r.len()),
        )
    }
    /// The constant matrix `m`.
    pub fn constant(m: &Matrix<K>) -> Self {
        let k = m.field();
        TransferMatrix {
            entries: (0..m.nrows())
                .map(|i| {
                    m.row(i)
                        .iter()
                        .map(|x| RationalFunction::constant(k, x.clone()))
                        .collect()
                })
                .collect(),
        }
    }
    /// The `n x n` identity.
    pub fn identity(k: &K, n: usize) -> Self {
        Self::constant(&Matrix::identity(k.clone(), n))
    }
    fn zip(
        &self,
        g: &Self,
        op: &'static str,
        f: impl Fn(&RationalFunction<K>, &RationalFunction<K>) -> RationalFunction<K>,
    ) -> Result<Self> {
        if self.shape() != g.shape() {
            return Err(Error::Shape {
                op,
                expected: self.shape(),
                found: g.shape(),
            });
        }
        Ok(TransferMatrix {
            entries: self
                .entries
                .iter()
                .zip(&g.entries)
                .map(|(r, s)| r.iter().zip(s).map(|(x, y)| f(x, y)).collect())
                .collect(),
        })
    }
    /// `self + g`.
    ///
    /// # Errors
    /// `Shape` on mismatch.
    pub fn try_add(&self, g: &Self) -> Result<Self> {
        self.zip(g, "transfer matrix sum", RationalFunction::add)
    }
    /// `self - g`.
    ///
    /// # Errors
    /// `Shape` on mismatch.
    pub fn try_sub(&self, g: &Self) -> Result<Self> {
        self.zip(g, "transfer matrix difference", RationalFunction::sub)
    }
    /// `self * g`; `k` is the field (for an empty inner dimension).
    ///
    /// # Errors
    /// `Shape` when the columns of `self` are not the rows of `g`.
    pub fn try_mul(&self, g: &Self, k: &K) -> Result<Self> {
        let ((p, r), (r2, m)) = (self.shape(), g.shape());
        if r != r2 && !(p == 0 || m == 0) {
            return Err(Error::Shape {
                op: "transfer matrix product",
                expected: (r, m),
                found: (r2, m),
            });
        }
        let zero = RationalFunction::constant(k, k.zero());
        let entries = (0..p)
            .map(|i| {
                (0..m)
                    .map(|j| {
                        (0..r).fold(zero.clone(), |acc, l| {
                            acc.add(&self.entries[i][l].mul(&g.entries[l][j]))
                        })
                    })
                    .collect()
            })
            .collect();
        Ok(TransferMatrix { entries })
    }
    /// Every entry times the constant `c`.
    pub fn scale(&self, k: &K, c: &K::Elem) -> Self {
        let c = RationalFunction::constant(k, c.clone());
        TransferMatrix {
            entries: self
                .entries
                .iter()
                .map(|r| r.iter().map(|x| x.mul(&c)).collect())
                .collect(),
        }
    }
    /// $\mathrm{diag}(G_1, G_2, \dots)$.
    pub fn block_diag(k: &K, blocks: &[Self]) -> Self {
        let cols: usize = blocks.iter().map(|b| b.shape().1).sum();
        let zero = RationalFunction::constant(k, k.zero());
        let mut entries = Vec::new();
        let mut c0 = 0;
        for b in blocks {
            let (_, bc) = b.shape();
            for row in &b.entries {
                let mut r = vec![zero.clone(); cols];
                r[c0..c0 + bc].clone_from_slice(row);
                entries.push(r);
            }
            c0 += bc;
        }
        TransferMatrix { entries }
    }
}
