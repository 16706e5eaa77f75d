//! Gauss–Jordan elimination over any field: canonical RREF, rank, null spaces, inverse,
//! determinant and linear solves.
//!
//! The RREF $R$ of $A$ is unique (pivot entries 1, zeros above and below), so null-space
//! bases read off $R$ are canonical: one basis vector per free column $f$, with entry 1 at
//! $f$ and zeros at the other free columns (the SCB paper's sec. III-A.1 relies on this).

use super::Matrix;
use super::kernels;
use crate::error::{Error, Result};
use crate::field::Field;

/// Row-reduces `a` (row-major `m x n`) in place to canonical RREF; returns pivot columns.
pub(crate) fn rref_in_place<K: Field>(k: &K, m: usize, n: usize, a: &mut [K::Elem]) -> Vec<usize> {
    let mut pivots = Vec::new();
    let mut r = 0;
    for c in 0..n {
        if r == m {
            break;
        }
        let Some(p) = (r..m).find(|&i| !k.is_zero(&a[i * n + c])) else {
            continue;
        };
        if p != r {
            for j in 0..n {
                a.swap(p * n + j, r * n + j);
            }
        }
        let inv = k.inv(&a[r * n + c]).expect("non-zero pivot");
        for j in c..n {
            a[r * n + j] = k.mul(&a[r * n + j], &inv);
        }
        let prow: Vec<K::Elem> = a[r * n + c..(r + 1) * n].to_vec();
        for i in 0..m {
            if i == r || k.is_zero(&a[i * n + c]) {
                continue;
            }
            let f = a[i * n + c].clone();
            for (jj, pv) in prow.iter().enumerate() {
                if !k.is_zero(pv) {
                    k.mul_sub_assign(&mut a[i * n + c + jj], &f, pv);
                }
            }
        }
        pivots.push(c);
        r += 1;
    }
    pivots
}

impl<K: Field> Matrix<K> {
    /// Canonical reduced row echelon form and pivot columns (Gauss–Jordan, $O(m n \min(m,n))$
    /// field operations).
    pub fn rref(&self) -> (Matrix<K>, Vec<usize>) {
        if let Some(r) = kernels::rref(self) {
            return r;
        }
        self.rref_gauss_jordan()
    }
    /// Classical Gauss–Jordan RREF (the generic path; the oracle for the fast kernels).
    pub fn rref_gauss_jordan(&self) -> (Matrix<K>, Vec<usize>) {
        let mut r = self.clone();
        let piv = rref_in_place(&self.field, self.nrows, self.ncols, &mut r.data);
        (r, piv)
    }
    /// The pivot columns of the canonical RREF (the column rank profile).
    pub fn pivots(&self) -> Vec<usize> {
        if let Some(p) = kernels::pivots(self) {
            return p;
        }
        self.rref().1
    }
    pub fn rank(&self) -> usize {
        if let Some(r) = kernels::rank(self) {
            return r;
        }
        if self.nrows.min(self.ncols) <= 1 {
            // a row or a column (or empty): rank 1 exactly when some entry is nonzero, with
            // no pivot inverse (an extended gcd in a number field)
            return usize::from(self.data.iter().any(|x| !self.field.is_zero(x)));
        }
        self.rref().1.len()
    }
    /// Is $\mathrm{rank}\,A \ge r$? Exact. Over $\mathbb{Q}$ a rank modulo a word prime that
    /// divides no denominator is a lower bound of the rank (every nonzero minor modulo $p$
    /// is a nonzero minor over $\mathbb{Q}$, [`crate::qkernels::modular::rank`]), so one
    /// elimination modulo $p$ usually decides; when two primes fall short, the certified
    /// rank does. Other fields: the exact rank.
    pub fn rank_at_least(&self, r: usize) -> bool {
        self.rank_at_least_mod_p(r) || (r <= self.nrows.min(self.ncols) && self.rank() >= r)
    }
    /// The modular half of [`Matrix::rank_at_least`]: `true` proves $\mathrm{rank}\,A \ge r$;
    /// `false` decides nothing (a prime too few, or a field without such a kernel). The
    /// field's kernel decides (`kernels::rank_at_least_mod_p`: over $\mathbb{Q}$ the rank
    /// modulo a word prime, over $\mathbb{Q}(\sqrt d)$ that of the regular representation).
    pub fn rank_at_least_mod_p(&self, r: usize) -> bool {
        if r == 0 {
            return true;
        }
        if r > self.nrows.min(self.ncols) {
            return false;
        }
        kernels::rank_at_least_mod_p(self, r)
    }
    /// The image of the matrix (row-major) under a reduction modulo the word prime `pr`
    /// that the field registers ($\mathbb{Q}$); `None` without one, or when `pr` divides a
    /// denominator. A guess for algorithms that check their results exactly.
    pub fn image_mod_p(&self, pr: &crate::qkernels::prime::Prime) -> Option<Vec<u64>> {
        kernels::image_mod_p(self, pr)
    }
    /// A guess of the canonical RREF: its pivot columns and nonzero rows, reconstructed from
    /// images modulo up to `max_primes` word primes when the field registers that kernel
    /// ($\mathbb{Q}$); `None` without one or without a stable reconstruction. Unchecked:
    /// the caller checks what it uses.
    pub fn rref_guess(&self, max_primes: usize) -> Option<(Vec<usize>, Matrix<K>)> {
        kernels::rref_guess(self, max_primes)
    }
    /// Is the generic rank at least `r`, proved cheaply and recording nothing? Over
    /// $\mathbb{Q}$ as [`Matrix::rank_at_least_mod_p`]; over a field with a cheap bound
    /// ([`crate::field::KernelTable::rank_lower_bound`]; $\mathbb{Q}(p)$: the rank at a
    /// point modulo a prime) `true` proves the rank for generic parameter values but says
    /// nothing of where it drops, so only a result that does not depend on those values
    /// (a diagnostic) may use it. `false` decides nothing.
    pub fn generic_rank_at_least(&self, r: usize) -> bool {
        if self.rank_at_least_mod_p(r) {
            return true;
        }
        if r > self.nrows.min(self.ncols) {
            return false;
        }
        kernels::generic_rank_lower_bound(self).is_some_and(|rp| rp >= r)
    }
    /// Canonical basis of the right null space $\{v : A v = 0\}$, as the columns of an
    /// `ncols x nullity` matrix.
    pub fn nullspace(&self) -> Matrix<K> {
        if let Some(n) = kernels::nullspace(self) {
            return n;
        }
        let (r, piv) = self.rref();
        nullspace_from_rref(&r, &piv)
    }
    /// Canonical basis of the left null space $\{w : w A = 0\}$, as the rows of a
    /// `(nrows - rank) x nrows` matrix in RREF.
    pub fn left_nullspace(&self) -> Matrix<K> {
        let n = self.transpose().nullspace().transpose();
        n.rref().0.submatrix(0, n.nrows(), 0, n.ncols())
    }
    /// Basis of the column space: the pivot columns of `A`.
    pub fn column_space(&self) -> Matrix<K> {
        let piv = self.pivots();
        self.select_cols(&piv)
    }
    /// Canonical basis of the row space: the non-zero rows of the RREF.
    pub fn row_space(&self) -> Matrix<K> {
        let (r, piv) = self.rref();
        r.submatrix(0, piv.len(), 0, self.ncols)
    }
    /// Unit vectors completing the columns of `self` (assumed independent) to a basis of
    /// $K^n$: the $e_j$ that are not pivots of the RREF of $[V, I]$, as columns.
    pub fn complete_basis(&self) -> Matrix<K> {
        let n = self.nrows;
        let vi = self
            .hstack(&Matrix::identity(self.field.clone(), n))
            .expect("same rows");
        let piv = vi.pivots();
        let extra: Vec<usize> = piv
            .into_iter()
            .filter(|&c| c >= self.ncols)
            .map(|c| c - self.ncols)
            .collect();
        Matrix::identity(self.field.clone(), n).select_cols(&extra)
    }
    /// Inverse by Gauss–Jordan on $[A, I]$.
    ///
    /// # Errors
    /// `NotSquare`, `Singular`.
    pub fn inverse(&self) -> Result<Matrix<K>> {
        self.check_square("inverse")?;
        let n = self.nrows;
        if let Some(r) = kernels::inverse(self) {
            return r;
        }
        let aug = self.hstack(&Matrix::identity(self.field.clone(), n))?;
        let (r, piv) = aug.rref();
        if piv.len() < n || (n > 0 && piv[n - 1] != n - 1) {
            return Err(Error::Singular);
        }
        Ok(r.submatrix(0, n, n, 2 * n))
    }
    /// Determinant: the field's kernel when it registers one, else [`Matrix::det_gauss`].
    ///
    /// # Errors
    /// `NotSquare`.
    pub fn det(&self) -> Result<K::Elem> {
        self.check_square("det")?;
        if let Some(d) = kernels::det(self) {
            return d;
        }
        self.det_gauss()
    }
    /// Determinant by Gaussian elimination over the field (no kernel: the generic
    /// algorithm, also the oracle of the kernels' tests).
    ///
    /// # Errors
    /// `NotSquare`.
    pub fn det_gauss(&self) -> Result<K::Elem> {
        self.check_square("det")?;
        let k = &self.field;
        let n = self.nrows;
        let mut a = self.data.clone();
        let mut det = k.one();
        for c in 0..n {
            let Some(p) = (c..n).find(|&i| !k.is_zero(&a[i * n + c])) else {
                return Ok(k.zero());
            };
            if p != c {
                for j in 0..n {
                    a.swap(p * n + j, c * n + j);
                }
                det = k.neg(&det);
            }
            det = k.mul(&det, &a[c * n + c]);
            let inv = k.inv(&a[c * n + c]).expect("non-zero");
            for i in c + 1..n {
                if k.is_zero(&a[i * n + c]) {
                    continue;
                }
                let f = k.mul(&a[i * n + c], &inv);
                for j in c..n {
                    let pv = a[c * n + j].clone();
                    k.mul_sub_assign(&mut a[i * n + j], &f, &pv);
                }
            }
        }
        Ok(det)
    }
    /// Solves $A X = B$: `Some((X0, N))` with a particular solution `X0` and the null space
    /// `N` of `A` (all solutions are `X0 + N Y`), or `None` when there is no solution.
    ///
    /// # Errors
    /// `Shape` when `B` has a different number of rows.
    pub fn solve(&self, b: &Matrix<K>) -> Result<Option<(Matrix<K>, Matrix<K>)>> {
        if b.nrows != self.nrows {
            return Err(Error::Shape {
                op: "solve",
                expected: (self.nrows, b.ncols),
                found: b.shape(),
            });
        }
        let n = self.ncols;
        if self.nrows == n
            && let Some(x) = kernels::solve_square(self, b)
        {
            // A nonsingular: X is the only solution, the null space is {0}
            return Ok(Some((x, Matrix::zeros(self.field.clone(), n, 0))));
        }
        let aug = self.hstack(b)?;
        let (r, piv) = aug.rref();
        if piv.last().is_some_and(|&p| p >= n) {
            return Ok(None);
        }
        let mut x = Matrix::zeros(self.field.clone(), n, b.ncols);
        for (i, &p) in piv.iter().enumerate() {
            for j in 0..b.ncols {
                x.set(p, j, r.get(i, n + j).clone());
            }
        }
        let rr = r.submatrix(0, self.nrows, 0, n);
        Ok(Some((x, nullspace_from_rref(&rr, &piv))))
    }
}

/// Null-space basis (columns) from an RREF `r` with pivot columns `piv`.
pub(crate) fn nullspace_from_rref<K: Field>(r: &Matrix<K>, piv: &[usize]) -> Matrix<K> {
    let k = r.field();
    let n = r.ncols();
    let free: Vec<usize> = (0..n).filter(|c| !piv.contains(c)).collect();
    let mut out = Matrix::zeros(k.clone(), n, free.len());
    for (j, &f) in free.iter().enumerate() {
        out.set(f, j, k.one());
        for (i, &p) in piv.iter().enumerate() {
            out.set(p, j, k.neg(r.get(i, f)));
        }
    }
    out
}
