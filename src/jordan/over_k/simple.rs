//! Chains of a simple eigenvalue over $K$ from Krylov vectors, without elimination in
//! $E = K\[t\]/(g)$ (the method of `jordan::simple` over a quadratic field).
//!
//! For a simple root $t$ of $\chi_A$ and $q(x) = \chi_A(x)/(x - t) = \sum_k q_k(t) x^k$
//! (synthetic division in $E$), $(A - tI)\,q(A) = 0$, so $v = q(A)\,b = K_b\,(q_k)_k$ with the
//! Krylov matrix $K_b = [b, Ab, \dots, A^{n-1}b]$ over $K$ is an eigenvector or zero; some
//! unit vector $b$ gives $v \ne 0$. The left eigenvector $w$ is the same for $A^T$, and
//! $W = w / (w v)$ gives $W V = 1$. Work: Krylov matrices over $K$, $n^2$ products of an
//! element of $K$ by one of $E$, $n$ products and one inverse in $E$. The component is
//! checked exactly like every other one ([`super::ComponentK::verify`]).

use super::{RelElem, RelField};
use crate::error::{Error, Result};
use crate::field::{Field, QuadraticField};
use crate::matrix::Matrix;
use crate::poly::Poly;

/// $K_b$ for `b = e_i`: column $j$ is $M^j e_i$.
fn krylov(m: &Matrix<QuadraticField>, i: usize) -> Vec<Vec<crate::field::Quadratic>> {
    let k = m.field();
    let n = m.nrows();
    let mut x: Vec<_> = (0..n)
        .map(|r| if r == i { k.one() } else { k.zero() })
        .collect();
    let mut cols = vec![x.clone()];
    for _ in 1..n {
        x = (0..n)
            .map(|r| {
                m.row(r)
                    .iter()
                    .zip(&x)
                    .filter(|(a, b)| !k.is_zero(a) && !k.is_zero(b))
                    .fold(k.zero(), |acc, (a, b)| k.add(&acc, &k.mul(a, b)))
            })
            .collect();
        cols.push(x.clone());
    }
    cols
}

/// $v = K_b\, (q_k)$ over $E$.
fn apply(e: &RelField, cols: &[Vec<crate::field::Quadratic>], q: &[RelElem]) -> Vec<RelElem> {
    let n = cols.len();
    (0..n)
        .map(|r| {
            (0..n).fold(e.zero(), |acc, kk| {
                e.add(&acc, &e.scale(&cols[kk][r], &q[kk]))
            })
        })
        .collect()
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
    let first = |m: &Matrix<QuadraticField>| {
        (0..n).find_map(|i| {
            let v = apply(e, &krylov(m, i), &q);
            v.iter().any(|x| !e.is_zero(x)).then_some(v)
        })
    };
    let none = || Error::Verification(format!("no eigenvector for the simple factor {}", e));
    let v = first(a).ok_or_else(none)?;
    let w = first(&a.transpose()).ok_or_else(none)?;
    let s = v
        .iter()
        .zip(&w)
        .fold(e.zero(), |acc, (x, y)| e.add(&acc, &e.mul(x, y)));
    let si = e
        .inv(&s)
        .ok_or_else(|| Error::Verification(format!("w v = 0 for the simple factor {e}")))?;
    let w: Vec<RelElem> = w.iter().map(|x| e.mul(x, &si)).collect();
    Ok((
        Matrix::from_vec(e.clone(), n, 1, v),
        Matrix::from_vec(e.clone(), 1, n, w),
    ))
}
