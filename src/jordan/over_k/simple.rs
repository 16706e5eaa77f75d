//! Chains of a simple eigenvalue over $K$ from Krylov vectors, without elimination in
//! $E = K\[t\]/(g)$ (the method of `jordan::simple` over a quadratic field).
//!
//! For a simple root $t$ of $\chi_A$ and $q(x) = \chi_A(x)/(x - t) = \sum_k q_k(t) x^k$
//! (synthetic division in $E$), $(A - tI)\,q(A) = 0$, so $v = q(A)\,b = K_b\,(q_k)_k$ with the
//! Krylov matrix $K_b = [b, Ab, \dots, A^{n-1}b]$ over $K$ is an eigenvector or zero; some
//! unit vector $b$ gives $v \ne 0$. The left eigenvector $w$ is the same for $A^T$, and
//! $W = w / (w v)$ gives $W V = 1$. Work: Krylov matrices over $K$, the product
//! $K_b\,(q_k)$ with the coefficient matrix of the $q_k$, $w v$ and $W$ as products and
//! one $d \times d$ inverse over $K$ ([`super::coeffs`]: the integer kernels of the matrix
//! layer, no arithmetic in $E$ but the $n$ steps of $q$ and the multiplication matrices). The component is
//! checked exactly like every other one ([`super::ComponentK::verify`]).

use super::coeffs::{coeff_cols, dot, elem_of_col, elem_of_row, mul_matrix};
use super::{RelElem, RelField};
use crate::error::{Error, Result};
use crate::field::{Field, QuadraticField};
use crate::matrix::Matrix;
use crate::poly::Poly;

/// $K_b$ for `b = e_i` ($n \times n$, column $j$ is $M^j e_i$), each product on the
/// integer kernel of the matrix layer.
fn krylov(m: &Matrix<QuadraticField>, i: usize) -> Matrix<QuadraticField> {
    let k = m.field();
    let n = m.nrows();
    let mut x = Matrix::zeros(k.clone(), n, 1);
    x.set(i, 0, k.one());
    let mut out = Matrix::zeros(k.clone(), n, n);
    for j in 0..n {
        if j > 0 {
            x = m * &x;
        }
        out.set_block(0, j, &x);
    }
    out
}

/// Right and left chains ($n \times 1$, $1 \times n$) of the simple factor `e.modulus()` of
/// `chi` $= \chi_A$.
///
/// # Errors
/// `Verification` if no unit vector gives an eigenvector or $w v = 0$ (impossible for a
/// simple root; a typed error rather than a panic).
pub(crate) fn simple_chains(
    a: &Matrix<QuadraticField>,
    chi: &Poly<QuadraticField>,
    e: &RelField,
) -> Result<(Matrix<RelField>, Matrix<RelField>)> {
    let n = a.nrows();
    let t = e.generator();
    let chi = chi.monic();
    let mut q = vec![e.zero(); n];
    q[n - 1] = e.one();
    for k in (1..n).rev() {
        q[k - 1] = e.add(&e.from_base(&chi.coeff(k)), &e.mul(&t, &q[k]));
    }
    // the coefficients of q_k(t) as the rows of an n x d matrix over K: v = K_b Q
    let qc = coeff_cols(e, &q).transpose();
    let first = |m: &Matrix<QuadraticField>| {
        (0..n).find_map(|i| {
            let kq = &krylov(m, i) * &qc;
            let v: Vec<RelElem> = (0..n).map(|r| elem_of_row(&kq, r)).collect();
            v.iter().any(|x| !e.is_zero(x)).then_some(v)
        })
    };
    let none = || Error::Verification(format!("no eigenvector for the simple factor {}", e));
    let v = first(a).ok_or_else(none)?;
    let w = first(&a.transpose()).ok_or_else(none)?;
    // s = w v, then W = w / s as one solve over K: coeffs(W) = M_s^{-1} coeffs(w)
    let s = dot(e, &v, &w);
    let ms_inv = mul_matrix(e, &s)
        .inverse()
        .map_err(|_| Error::Verification(format!("w v = 0 for the simple factor {e}")))?;
    let wc = &ms_inv * &coeff_cols(e, &w);
    let w: Vec<RelElem> = (0..n).map(|j| elem_of_col(&wc, j)).collect();
    Ok((
        Matrix::from_vec(e.clone(), n, 1, v),
        Matrix::from_vec(e.clone(), 1, n, w),
    ))
}
