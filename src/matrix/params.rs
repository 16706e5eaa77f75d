//! Matrices over $\mathbb{Q}(p_1, \dots, p_k)$ and $\mathbb{Z}\lbrack p\rbrack$: characteristic
//! polynomial by evaluation and interpolation, fraction-free (Bareiss) determinant.
//!
//! | entry point | computes | algorithm |
//! |---|---|---|
//! | [`charpoly_ratfunc`] | $\det(xI - A)$ over $\mathbb{Q}(p)$ | clear denominators ($A = B / D$, $B$ over $\mathbb{Z}\lbrack p\rbrack$), [`charpoly_zp`], $c_k = c'_k / D^{n-k}$ |
//! | [`charpoly_zp`] | $\det(xI - B)$ over $\mathbb{Z}\lbrack p\rbrack$ | multi-modular evaluation/interpolation ([`crate::ratfunc::kernels::interp`]) |
//! | [`rref_params`] | canonical RREF over $\mathbb{Q}(p)$, conditions recorded | fraction-free Gauss–Jordan over $\mathbb{Z}\lbrack p\rbrack$ |
//! | [`det_bareiss_zp`] | $\det B$ over $\mathbb{Z}\lbrack p\rbrack$ | Bareiss fraction-free elimination, exact multivariate divisions |
//!
//! [`charpoly_zp`] and its certificate (degree and coefficient bounds) live with the other
//! $\mathbb{Q}(p)$ kernels in [`crate::ratfunc::kernels`]; `Matrix::charpoly`, `det`, `rref`
//! and `rank` over $\mathbb{Q}(p)$ reach them through the field's kernel table.

use super::Matrix;
use crate::error::{Error, Result};
use crate::field::Field;
use crate::mpoly::MPoly;
use crate::mpoly::gcd::lcm;
use crate::poly::Poly;
use crate::ratfunc::RatFuncField;
use num_bigint::BigInt;
use num_traits::ToPrimitive;

pub use crate::ratfunc::kernels::charpoly_zp;
pub use crate::ratfunc::kernels::interp::MAX_GRID_POINTS;

/// $\det(xI - A)$ for a square matrix over $\mathbb{Q}(p)$ (low degree first, monic; no
/// conditions): the kernel [`crate::ratfunc::kernels::charpoly_qp`].
///
/// # Errors
/// `NotSquare`; `Limit` when the interpolation grid would exceed [`MAX_GRID_POINTS`].
pub fn charpoly_ratfunc(a: &Matrix<RatFuncField>) -> Result<Poly<RatFuncField>> {
    let (n, m) = a.shape();
    if n != m {
        return Err(Error::NotSquare {
            op: "charpoly",
            nrows: n,
            ncols: m,
        });
    }
    let c = crate::ratfunc::kernels::charpoly_qp(a.field(), n, a.as_slice())?;
    Ok(Poly::new(a.field().clone(), c))
}

/// $\det B$ over $\mathbb{Z}\lbrack p\rbrack$ by Bareiss's fraction-free elimination (every
/// division exact; row swaps change the sign).
pub fn det_bareiss_zp(nvars: usize, n: usize, b: &[MPoly]) -> MPoly {
    assert_eq!(b.len(), n * n);
    if n == 0 {
        return MPoly::one(nvars);
    }
    let mut a = b.to_vec();
    let mut prev = MPoly::one(nvars);
    let mut neg = false;
    for k in 0..n {
        let Some(p) = (k..n).find(|&i| !a[i * n + k].is_zero()) else {
            return MPoly::zero(nvars);
        };
        if p != k {
            for j in 0..n {
                a.swap(p * n + j, k * n + j);
            }
            neg = !neg;
        }
        for i in k + 1..n {
            for j in k + 1..n {
                let t = a[k * n + k]
                    .mul(&a[i * n + j])
                    .sub(&a[i * n + k].mul(&a[k * n + j]));
                a[i * n + j] = t.div_exact(&prev).expect("Bareiss division is exact");
            }
            a[i * n + k] = MPoly::zero(nvars);
        }
        prev = a[k * n + k].clone();
    }
    let d = a[n * n - 1].clone();
    if neg { d.neg() } else { d }
}

/// Canonical RREF and pivot columns of an `m x n` matrix over $\mathbb{Q}(p)$ by
/// fraction-free Gauss–Jordan elimination over $\mathbb{Z}\lbrack p\rbrack$ (each row first
/// multiplied by the lcm of its denominators, which does not change the RREF; every division
/// $(\pi a_{ij} - f a_{rj}) / \pi_{\text{prev}}$ is exact). The result equals
/// [`Matrix::rref`]; the conditions recorded in the field are the numerators of the leading
/// minors $M_r$ used as pivots (the generic pivots are $M_r / M_{r-1}$), so the RREF holds
/// wherever none of them vanishes.
pub fn rref_params(a: &Matrix<RatFuncField>) -> (Matrix<RatFuncField>, Vec<usize>) {
    let k = a.field().clone();
    let nv = k.nvars();
    let (m, n) = a.shape();
    let mut e: Vec<MPoly> = Vec::with_capacity(m * n);
    let mut scale: Vec<MPoly> = Vec::with_capacity(m);
    for i in 0..m {
        let row = a.row(i);
        let mut d = MPoly::one(nv);
        for x in row {
            if !x.den().is_one() {
                d = lcm(&d, x.den());
            }
        }
        for x in row {
            e.push(if x.den() == &d {
                x.num().clone()
            } else {
                x.num().mul(&d.div_exact(x.den()).expect("lcm"))
            });
        }
        scale.push(d);
    }
    let mut pivots = Vec::new();
    let mut den = MPoly::one(nv);
    let mut sprod = MPoly::one(nv);
    let mut r = 0;
    for c in 0..n {
        if r == m {
            break;
        }
        let Some(i) = (r..m).find(|&i| !e[i * n + c].is_zero()) else {
            continue;
        };
        if i != r {
            for j in 0..n {
                e.swap(i * n + j, r * n + j);
            }
            scale.swap(i, r);
        }
        let piv = e[r * n + c].clone();
        // the leading minor M_r(A) = piv / (product of the row scalings)
        sprod = sprod.mul(&scale[r]);
        if let Some(minor) = k.frac(piv.clone(), sprod.clone()) {
            k.record_condition(minor.num());
        }
        for i in 0..m {
            if i == r {
                continue;
            }
            let f = e[i * n + c].clone();
            for j in 0..n {
                let t = if f.is_zero() {
                    piv.mul(&e[i * n + j])
                } else {
                    piv.mul(&e[i * n + j]).sub(&f.mul(&e[r * n + j]))
                };
                e[i * n + j] = if den.is_one() {
                    t
                } else {
                    t.div_exact(&den).expect("fraction-free division is exact")
                };
            }
        }
        den = piv;
        pivots.push(c);
        r += 1;
    }
    let out: Vec<_> = e
        .into_iter()
        .enumerate()
        .map(|(idx, x)| {
            if idx >= r * n || x.is_zero() {
                k.zero()
            } else {
                k.frac(x, den.clone()).expect("nonzero pivot")
            }
        })
        .collect();
    (Matrix::from_vec(k, m, n, out), pivots)
}

/// The matrix of numerators times the common denominator: $A = B / D$ with $B$ over
/// $\mathbb{Z}\lbrack p\rbrack$; returns `(B, D)`.
pub fn clear_denominators(a: &Matrix<RatFuncField>) -> (Vec<MPoly>, MPoly) {
    crate::ratfunc::kernels::clear_common(a.field().nvars(), a.as_slice())
}

/// A small-integer check used by tests: the value of a polynomial entry at a point.
pub fn eval_entry_i64(f: &MPoly, point: &[i64]) -> Option<i64> {
    f.eval_all(&point.iter().map(|&x| BigInt::from(x)).collect::<Vec<_>>())
        .to_i64()
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn small() {
        let k = RatFuncField::new(&["a", "b"]).unwrap();
        let rows = [["a", "1"], ["b", "a + b"]];
        let m = Matrix::from_rows(
            k.clone(),
            rows.iter()
                .map(|r| r.iter().map(|s| k.parse(s).unwrap()).collect())
                .collect(),
        )
        .unwrap();
        let c = charpoly_ratfunc(&m).unwrap();
        let g = m.charpoly_berkowitz().unwrap();
        assert_eq!(c, g);
        let (b, _) = clear_denominators(&m);
        let det = det_bareiss_zp(2, 2, &b);
        assert_eq!(k.from_mpoly(det), m.det().unwrap());
        assert_eq!(rref_params(&m), m.rref());
    }
}
