//! Coefficient-matrix kernels for elements of $E = K\[t\]/(g)$ over a quadratic field $K$
//! (the method of `jordan::coeffs` one level up): an element is its coefficient column in
//! the basis $1, t, \dots, t^{d-1}$ over $K$, multiplication by $x$ is the $d \times d$
//! matrix $M_x$ over $K$, so products in $E$ become matrix products over $K$, which run on
//! the integer kernel `matrix::over_k` instead of normalising rationals after every
//! multiply-add. Used by the simple-eigenvalue chains ([`super::simple`]) and their exact
//! check ([`verify_simple`], called from [`super::ComponentK::verify`]).

use super::{RelElem, RelField};
use crate::field::{Field, QuadraticField};
use crate::matrix::Matrix;

/// The $d \times n$ matrix over $K$ whose column $j$ holds the coefficients of `xs[j]`.
pub(crate) fn coeff_cols(e: &RelField, xs: &[RelElem]) -> Matrix<QuadraticField> {
    let k = e.base();
    Matrix::from_fn(k.clone(), e.degree(), xs.len(), |r, j| {
        xs[j].0.get(r).cloned().unwrap_or_else(|| k.zero())
    })
}

/// Column `j` of a coefficient matrix as a canonical element (no trailing zeros).
pub(crate) fn elem_of_col(m: &Matrix<QuadraticField>, j: usize) -> RelElem {
    let k = m.field();
    let mut c = m.col(j);
    while c.last().is_some_and(|x| k.is_zero(x)) {
        c.pop();
    }
    crate::algebraic::ExtElem(c)
}

/// Row `i` of a matrix whose rows are coefficient vectors, as a canonical element.
pub(crate) fn elem_of_row(m: &Matrix<QuadraticField>, i: usize) -> RelElem {
    let k = m.field();
    let mut c = m.row(i).to_vec();
    while c.last().is_some_and(|x| k.is_zero(x)) {
        c.pop();
    }
    crate::algebraic::ExtElem(c)
}

/// Multiplication by `x` on $E$ in the basis $1, t, \dots, t^{d-1}$: column $k$ holds the
/// coefficients of $x t^k$.
pub(crate) fn mul_matrix(e: &RelField, x: &RelElem) -> Matrix<QuadraticField> {
    let t = e.generator();
    let mut cols = vec![x.clone()];
    for k in 1..e.degree() {
        let next = e.mul(&cols[k - 1], &t);
        cols.push(next);
    }
    coeff_cols(e, &cols)
}

/// $\sum_i x_i y_i$ in $E$ as one product over $K$: $[M_{x_1} \cdots M_{x_n}]$ times the
/// stacked coefficient columns of the $y_i$.
pub(crate) fn dot(e: &RelField, xs: &[RelElem], ys: &[RelElem]) -> RelElem {
    let (d, n) = (e.degree(), xs.len());
    let k = e.base();
    let mut big = Matrix::zeros(k.clone(), d, n * d);
    for (i, x) in xs.iter().enumerate() {
        big.set_block(0, i * d, &mul_matrix(e, x));
    }
    let yc = coeff_cols(e, ys);
    let stacked = Matrix::from_fn(k.clone(), n * d, 1, |r, _| yc.get(r % d, r / d).clone());
    elem_of_col(&(&big * &stacked), 0)
}

/// Exact check of $A V = t V$, $W A = t W$, $W V = 1$ for a component of multiplicity 1
/// (`v` is $n \times 1$, `w` is $1 \times n$), on coefficient matrices over $K$: with $V_c$
/// ($d \times n$, column $i$ = coefficients of $V_i$), $M_t$ the multiplication matrix of
/// $t$ and $W_c$ likewise, $V_c A^T = M_t V_c$, $W_c A = M_t W_c$ and
/// $\sum_i V_i W_i = 1$ ([`dot`]).
pub(crate) fn verify_simple(
    e: &RelField,
    v: &Matrix<RelField>,
    w: &Matrix<RelField>,
    a: &Matrix<QuadraticField>,
) -> bool {
    let n = a.nrows();
    if v.shape() != (n, 1) || w.shape() != (1, n) {
        return false;
    }
    let vs: Vec<RelElem> = (0..n).map(|i| v.get(i, 0).clone()).collect();
    let ws: Vec<RelElem> = (0..n).map(|i| w.get(0, i).clone()).collect();
    if vs.iter().chain(&ws).any(|x| x.0.len() > e.degree()) {
        return false;
    }
    let (vc, wc) = (coeff_cols(e, &vs), coeff_cols(e, &ws));
    let mt = mul_matrix(e, &e.generator());
    &vc * &a.transpose() == &mt * &vc && &wc * a == &mt * &wc && e.is_one(&dot(e, &ws, &vs))
}
