//! Characteristic and minimal polynomials; evaluation of a polynomial at a matrix.
//!
//! * `companion_charpoly`: read off a companion matrix ($O(n^2)$ to recognize it).
//! * `charpoly_hessenberg`: similarity reduction to upper Hessenberg form $H = S^{-1} A S$ by
//!   elementary transformations, then the recurrence $p_{k}(x) = (x - h_{kk}) p_{k-1}(x) -
//!   \sum_{i<k} h_{ik} \prod_{j=i+1}^{k} h_{j,j-1}\, p_{i-1}(x)$: $O(n^3)$ field operations.
//! * `charpoly_berkowitz`: division-free, $O(n^4)$ ring operations (an independent oracle).
//! * `minpoly`: lcm over the unit vectors $e_j$ of the minimal polynomials of the Krylov
//!   sequences $e_j, A e_j, A^2 e_j, \dots$.

use super::Matrix;
use crate::error::Result;
use crate::field::Field;
use crate::poly::Poly;

impl<K: Field> Matrix<K> {
    /// $\det(xI - A)$, monic of degree $n$.
    ///
    /// # Errors
    /// `NotSquare`.
    pub fn charpoly(&self) -> Result<Poly<K>> {
        self.check_square("charpoly")?;
        if let Some(c) = self.companion_charpoly() {
            return Ok(c);
        }
        if let Some(c) = super::kernels::charpoly(self) {
            return c;
        }
        self.charpoly_hessenberg()
    }
    /// $\det(xI - A) = x^n + \sum_i c_i x^i$ read off a companion matrix (ones on the
    /// subdiagonal, $A_{i,n-1} = -c_i$, zeros elsewhere: the Krylov form of a controllable
    /// single-input system, whose entries over $\mathbb{Q}(p)$ are the large coefficients
    /// themselves); `None` for any other matrix.
    pub fn companion_charpoly(&self) -> Option<Poly<K>> {
        let (k, n) = (&self.field, self.nrows);
        if n < 2 || self.ncols != n {
            return None;
        }
        for i in 0..n {
            for j in 0..n - 1 {
                let want_one = i == j + 1;
                let x = &self.data[i * n + j];
                if (want_one && !k.is_one(x)) || (!want_one && !k.is_zero(x)) {
                    return None;
                }
            }
        }
        let mut c: Vec<K::Elem> = (0..n).map(|i| k.neg(&self.data[i * n + n - 1])).collect();
        c.push(k.one());
        Some(Poly::new(k.clone(), c))
    }
    /// Characteristic polynomial through the Hessenberg form.
    ///
    /// # Errors
    /// `NotSquare`.
    pub fn charpoly_hessenberg(&self) -> Result<Poly<K>> {
        self.check_square("charpoly")?;
        let k = self.field.clone();
        let n = self.nrows;
        let mut h = self.data.clone();
        // reduce to upper Hessenberg
        for c in 0..n.saturating_sub(2) {
            let Some(p) = (c + 1..n).find(|&i| !k.is_zero(&h[i * n + c])) else {
                continue;
            };
            if p != c + 1 {
                // swap rows p, c+1 and columns p, c+1
                for j in 0..n {
                    h.swap(p * n + j, (c + 1) * n + j);
                }
                for i in 0..n {
                    h.swap(i * n + p, i * n + c + 1);
                }
            }
            let inv = k.inv(&h[(c + 1) * n + c]).expect("non-zero");
            for i in c + 2..n {
                if k.is_zero(&h[i * n + c]) {
                    continue;
                }
                let f = k.mul(&h[i * n + c], &inv);
                // row_i -= f * row_{c+1}
                for j in 0..n {
                    let v = h[(c + 1) * n + j].clone();
                    k.mul_sub_assign(&mut h[i * n + j], &f, &v);
                }
                // col_{c+1} += f * col_i
                for r in 0..n {
                    let v = h[r * n + i].clone();
                    k.mul_add_assign(&mut h[r * n + c + 1], &f, &v);
                }
            }
        }
        // recurrence
        let mut ps: Vec<Poly<K>> = vec![Poly::one(k.clone())];
        for m in 0..n {
            let xm = Poly::new(k.clone(), vec![k.neg(&h[m * n + m]), k.one()]);
            let mut pm = xm.mul(&ps[m]);
            let mut t = k.one();
            for i in (0..m).rev() {
                t = k.mul(&t, &h[(i + 1) * n + i]);
                if k.is_zero(&t) {
                    break;
                }
                let c = k.mul(&t, &h[i * n + m]);
                pm = pm.sub(&ps[i].scale(&c));
            }
            ps.push(pm);
        }
        Ok(ps.pop().unwrap())
    }
    /// Characteristic polynomial by Berkowitz's division-free algorithm.
    ///
    /// # Errors
    /// `NotSquare`.
    pub fn charpoly_berkowitz(&self) -> Result<Poly<K>> {
        self.check_square("charpoly")?;
        let k = self.field.clone();
        let n = self.nrows;
        if n == 0 {
            return Ok(Poly::one(k));
        }
        // vector v holds coefficients high degree first
        let mut v = vec![k.one(), k.neg(self.get(0, 0))];
        for r in 1..n {
            // Toeplitz column for the leading (r+1)x(r+1) block
            let a = self.get(r, r).clone();
            let rrow: Vec<K::Elem> = (0..r).map(|j| self.get(r, j).clone()).collect();
            let mut col: Vec<K::Elem> = (0..r).map(|i| self.get(i, r).clone()).collect();
            let mut t = vec![k.one(), k.neg(&a)];
            // t_k = -R A^{k-2} C
            for _ in 0..r {
                let s = rrow
                    .iter()
                    .zip(&col)
                    .fold(k.zero(), |acc, (x, y)| k.add(&acc, &k.mul(x, y)));
                t.push(k.neg(&s));
                col = (0..r)
                    .map(|i| {
                        (0..r).fold(k.zero(), |acc, j| {
                            k.add(&acc, &k.mul(self.get(i, j), &col[j]))
                        })
                    })
                    .collect();
            }
            let mut nv = vec![k.zero(); r + 2];
            for i in 0..r + 2 {
                for j in 0..=i.min(v.len() - 1) {
                    if i - j < t.len() {
                        k.mul_add_assign(&mut nv[i], &t[i - j], &v[j]);
                    }
                }
            }
            v = nv;
        }
        v.reverse();
        Ok(Poly::new(k, v))
    }
    /// $p(A)$ by Horner's rule.
    ///
    /// # Errors
    /// `NotSquare`.
    pub fn eval_poly(&self, p: &Poly<K>) -> Result<Matrix<K>> {
        self.check_square("eval_poly")?;
        let n = self.nrows;
        let mut acc = Matrix::zeros(self.field.clone(), n, n);
        for c in p.coeffs().iter().rev() {
            acc = &acc * self;
            for i in 0..n {
                let v = self.field.add(acc.get(i, i), c);
                acc.set(i, i, v);
            }
        }
        Ok(acc)
    }
    /// Minimal polynomial (monic), as the lcm of the Krylov minimal polynomials of the unit
    /// vectors.
    ///
    /// # Errors
    /// `NotSquare`.
    pub fn minpoly(&self) -> Result<Poly<K>> {
        self.check_square("minpoly")?;
        if let Some(p) = super::kernels::minpoly(self) {
            return Ok(p);
        }
        let k = self.field.clone();
        let n = self.nrows;
        let mut acc = Poly::one(k.clone());
        for j in 0..n {
            // skip e_j if acc(A) e_j = 0 already
            let mut e = vec![k.zero(); n];
            e[j] = k.one();
            let pe = self.eval_poly(&acc)?;
            if pe.col(j).iter().all(|x| k.is_zero(x)) {
                continue;
            }
            let local = krylov_minpoly(self, e);
            let g = acc.gcd(&local);
            acc = acc.mul(&local.quo(&g));
        }
        Ok(acc)
    }
}

/// Minimal polynomial of `v` with respect to `a`: the first linear dependency among the
/// Krylov vectors $v, Av, A^2v, \dots$.
fn krylov_minpoly<K: Field>(a: &Matrix<K>, v: Vec<K::Elem>) -> Poly<K> {
    let k = a.field().clone();
    let n = a.nrows();
    // basis in echelon form, each with its combination of Krylov vectors (as a polynomial)
    let mut basis: Vec<(usize, Vec<K::Elem>, Poly<K>)> = vec![];
    let mut cur = v;
    let mut d = 0;
    loop {
        let mut w = cur.clone();
        let mut comb = Poly::monomial(k.clone(), k.one(), d);
        for (p, b, pc) in &basis {
            if !k.is_zero(&w[*p]) {
                let f = w[*p].clone();
                for i in 0..n {
                    k.mul_sub_assign(&mut w[i], &f, &b[i]);
                }
                comb = comb.sub(&pc.scale(&f));
            }
        }
        match (0..n).find(|&i| !k.is_zero(&w[i])) {
            None => return comb.monic(),
            Some(p) => {
                let inv = k.inv(&w[p]).unwrap();
                let w: Vec<K::Elem> = w.iter().map(|x| k.mul(x, &inv)).collect();
                basis.push((p, w, comb.scale(&inv)));
            }
        }
        cur = (0..n)
            .map(|i| (0..n).fold(k.zero(), |s, j| k.add(&s, &k.mul(a.get(i, j), &cur[j]))))
            .collect();
        d += 1;
    }
}
