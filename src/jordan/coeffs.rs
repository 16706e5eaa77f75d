//! Coefficient-matrix kernels for elements of $K = \mathbb{Q}[t]/(p)$: an element is its
//! coefficient column in the basis $1, t, \dots, t^{d-1}$, multiplication by $x$ is the
//! $d \times d$ rational matrix $M_x$, so products in $K$ become rational matrix products
//! (the integer product kernel). Used by the simple-eigenvalue component ([`super::simple`])
//! and its exact check (called from [`super::primary::PrimaryComponent::verify`]).

use super::chains::mul;
use crate::algebraic::{NfElem, NumberField};
use crate::field::{Field, Q, Rational};
use crate::matrix::Matrix;
use num_traits::Zero;

/// The $d \times n$ matrix whose column $j$ holds the coefficients of `xs[j]`.
pub(crate) fn coeff_cols(xs: &[NfElem], d: usize) -> Matrix<Q> {
    Matrix::from_fn(Q, d, xs.len(), |k, j| {
        xs[j].0.get(k).cloned().unwrap_or_else(Rational::zero)
    })
}

/// Multiplication by `x` on $K = \mathbb{Q}[t]/(p)$ in the basis $1, t, \dots,
/// t^{d-1}$: column $k$ holds the coefficients of $x t^k$.
pub(crate) fn mul_matrix(field: &NumberField, x: &NfElem) -> Matrix<Q> {
    let d = field.degree();
    let t = field.generator();
    let mut cols = vec![x.clone()];
    for k in 1..d {
        let next = field.mul(&cols[k - 1], &t);
        cols.push(next);
    }
    coeff_cols(&cols, d)
}

/// Exact check of $A V = t V$, $W A = t W$, $W V = 1$ for a component of multiplicity 1,
/// done on coefficient matrices over $\mathbb{Q}$ (the integer product kernel) instead of
/// entry-wise products in $K$: with $V_c$ ($d \times n$, column $i$ = coefficients of
/// $V_i$), $M_t$ the multiplication matrix of $t$ and $W_c$ likewise,
/// $V_c A^T = M_t V_c$, $W_c A = M_t W_c$ and $\sum_i M_{V_i} W_{c,i} = e_0$.
pub(crate) fn verify_simple(
    f: &NumberField,
    v: &Matrix<NumberField>,
    w: &Matrix<NumberField>,
    a: &Matrix<Q>,
) -> bool {
    let n = a.nrows();
    let d = f.degree();
    if v.shape() != (n, 1) || w.shape() != (1, n) {
        return false;
    }
    let vs: Vec<NfElem> = (0..n).map(|i| v.get(i, 0).clone()).collect();
    let ws: Vec<NfElem> = (0..n).map(|i| w.get(0, i).clone()).collect();
    let (vc, wc) = (coeff_cols(&vs, d), coeff_cols(&ws, d));
    let mt = mul_matrix(f, &f.generator());
    if mul(&vc, &a.transpose()) != mul(&mt, &vc) || mul(&wc, a) != mul(&mt, &wc) {
        return false;
    }
    // W V = sum_i V_i W_i: [M_{V_1} ... M_{V_n}] times the stacked coefficients of W
    let mut big = Matrix::zeros(Q, d, n * d);
    for (i, x) in vs.iter().enumerate() {
        big.set_block(0, i * d, &mul_matrix(f, x));
    }
    let stacked = Matrix::from_fn(Q, n * d, 1, |r, _| wc.get(r % d, r / d).clone());
    let wv = mul(&big, &stacked);
    (0..d).all(|k| {
        if k == 0 {
            num_traits::One::is_one(wv.get(0, 0))
        } else {
            wv.get(k, 0).is_zero()
        }
    })
}
