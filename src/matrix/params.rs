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
use crate::poly::Poly;
use crate::qkernels::fraction_free::{FractionFree, bareiss, ff_gauss_jordan};
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
    match bareiss(n, &mut a, MPoly::one(nvars)) {
        None => MPoly::zero(nvars),
        Some((d, neg)) => {
            if neg {
                d.neg()
            } else {
                d
            }
        }
    }
}

/// $\mathbb{Z}\lbrack p\rbrack$ for [`ff_gauss_jordan`] (a zero `c` skips its product).
impl FractionFree for MPoly {
    fn vanishes(&self) -> bool {
        self.is_zero()
    }
    fn cross_div(a: &Self, b: &Self, c: &Self, d: &Self, e: &Self) -> Self {
        let t = if c.is_zero() {
            a.mul(b)
        } else {
            a.mul(b).sub(&c.mul(d))
        };
        if e.is_one() {
            t
        } else {
            t.div_exact(e).expect("fraction-free division is exact")
        }
    }
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
    let (mut e, mut scale) = crate::ratfunc::kernels::clear_rows(nv, m, n, a.as_slice());
    let mut sprod = MPoly::one(nv);
    let (pivots, den) = ff_gauss_jordan(m, n, &mut e, MPoly::one(nv), |r, i, piv| {
        if i != r {
            scale.swap(i, r);
        }
        // the leading minor M_r(A) = piv / (product of the row scalings)
        sprod = sprod.mul(&scale[r]);
        if let Some(minor) = k.frac(piv.clone(), sprod.clone()) {
            k.record_condition(minor.num());
        }
    });
    let r = pivots.len();
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
