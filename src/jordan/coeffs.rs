//! Coefficient-matrix kernels for elements of $E = F\[t\]/(g)$ over any field $F$: an
//! element is its coefficient column in the basis $1, t, \dots, t^{d-1}$, multiplication by
//! $x$ is the $d \times d$ matrix $M_x$ over $F$, so products in $E$ become matrix products
//! over $F$, which run on the field's product kernel (the integer kernels over $\mathbb{Q}$
//! and $\mathbb{Q}(\sqrt d)$) instead of normalising after every multiply-add. Used by the
//! simple-eigenvalue chains ([`super::simple`]) and their exact check ([`verify_simple`]).

use crate::algebraic::{Ext, ExtElem};
use crate::field::Field;
use crate::matrix::Matrix;

/// The $d \times n$ matrix over $F$ whose column $j$ holds the coefficients of `xs[j]`.
pub(crate) fn coeff_cols<F: Field>(e: &Ext<F>, xs: &[ExtElem<F::Elem>]) -> Matrix<F> {
    let k = e.base();
    Matrix::from_fn(k.clone(), e.degree(), xs.len(), |r, j| {
        xs[j].0.get(r).cloned().unwrap_or_else(|| k.zero())
    })
}

/// `v` without trailing zeros: a canonical element.
fn canonical<F: Field>(k: &F, mut c: Vec<F::Elem>) -> ExtElem<F::Elem> {
    while c.last().is_some_and(|x| k.is_zero(x)) {
        c.pop();
    }
    ExtElem(c)
}

/// Column `j` of a coefficient matrix as a canonical element (no trailing zeros).
pub(crate) fn elem_of_col<F: Field>(m: &Matrix<F>, j: usize) -> ExtElem<F::Elem> {
    canonical(m.field(), m.col(j))
}

/// Row `i` of a matrix whose rows are coefficient vectors, as a canonical element.
pub(crate) fn elem_of_row<F: Field>(m: &Matrix<F>, i: usize) -> ExtElem<F::Elem> {
    canonical(m.field(), m.row(i).to_vec())
}

/// Multiplication by `x` on $E$ in the basis $1, t, \dots, t^{d-1}$: column $k$ holds the
/// coefficients of $x t^k$.
pub(crate) fn mul_matrix<F: Field>(e: &Ext<F>, x: &ExtElem<F::Elem>) -> Matrix<F> {
    let t = e.generator();
    let mut cols = vec![x.clone()];
    for k in 1..e.degree() {
        let next = e.mul(&cols[k - 1], &t);
        cols.push(next);
    }
    coeff_cols(e, &cols)
}

/// $\sum_i x_i y_i$ in $E$ as one product over $F$: $[M_{x_1} \cdots M_{x_n}]$ times the
/// stacked coefficient columns of the $y_i$.
pub(crate) fn dot<F: Field>(
    e: &Ext<F>,
    xs: &[ExtElem<F::Elem>],
    ys: &[ExtElem<F::Elem>],
) -> ExtElem<F::Elem> {
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
/// (`v` is $n \times 1$, `w` is $1 \times n$), on coefficient matrices over $F$: with $V_c$
/// ($d \times n$, column $i$ = coefficients of $V_i$), $M_t$ the multiplication matrix of
/// $t$ and $W_c$ likewise, $V_c A^T = M_t V_c$, $W_c A = M_t W_c$ and
/// $\sum_i V_i W_i = 1$ ([`dot`]).
pub(crate) fn verify_simple<F: Field>(
    e: &Ext<F>,
    v: &Matrix<Ext<F>>,
    w: &Matrix<Ext<F>>,
    a: &Matrix<F>,
) -> bool {
    let n = a.nrows();
    if v.shape() != (n, 1) || w.shape() != (1, n) {
        return false;
    }
    let vs: Vec<ExtElem<F::Elem>> = (0..n).map(|i| v.get(i, 0).clone()).collect();
    let ws: Vec<ExtElem<F::Elem>> = (0..n).map(|i| w.get(0, i).clone()).collect();
    if vs.iter().chain(&ws).any(|x| x.0.len() > e.degree()) {
        return false;
    }
    let (vc, wc) = (coeff_cols(e, &vs), coeff_cols(e, &ws));
    let mt = mul_matrix(e, &e.generator());
    &vc * &a.transpose() == &mt * &vc && &wc * a == &mt * &wc && e.is_one(&dot(e, &ws, &vs))
}
