//! The primary component of a simple eigenvalue (multiplicity 1) from Krylov vectors,
//! without any elimination over the number field.
//!
//! Let $\theta$ be a simple root of $\chi_A$ and $q(x) = \chi_A(x) / (x - \theta) =
//! \sum_{k<n} q_k(\theta) x^k$ (synthetic division: $q_{n-1} = 1$, $q_{k-1} = c_k +
//! \theta q_k$ for $\chi_A = \sum c_k x^k$). Cayley–Hamilton gives $(A - \theta I)\, q(A)
//! = \chi_A(A) = 0$, so for any vector $b$
//! $$v = q(A)\, b = \sum_k q_k(\theta)\, A^k b = K_b\, Q(\theta), \qquad
//! K_b = [b, A b, \dots, A^{n-1} b] \in \mathbb{Q}^{n \times n},$$
//! is an eigenvector or zero. $q(A)$ kills every generalized eigenspace but $\theta$'s and
//! acts on $\theta$'s (one-dimensional) eigenspace as $q(\theta) \ne 0$, so $v \ne 0$ as
//! soon as $b$ has a component along it; some unit vector $e_i$ does. The left eigenvector
//! is $w = e_j^T q(A)$ alike, and $W = w / (w v)$ gives $W V = 1$ ($w v \ne 0$ for a
//! simple eigenvalue).
//!
//! All work is over $\mathbb{Q}$ (Krylov matrices and one rational product $K_b C$ with
//! the coefficient matrix $C$ of $Q(t)$ in $K = \mathbb{Q}[t]/(p)$) plus $n$ products and
//! one inverse in $K$. For a dense $16 \times 16$ integer matrix with an irreducible
//! characteristic polynomial this replaces an elimination over a field of degree 16.
//! The component is checked exactly by [`PrimaryComponent::verify`] as every other one.

use super::coeffs::{coeff_cols, mul_matrix};
use super::primary::{PrimaryComponent, named_field};
use crate::algebraic::{NfElem, NumberField};
use crate::error::{Error, Result};
use crate::field::{Field, Q, Rational};
use crate::matrix::Matrix;
use crate::poly::Poly;
use num_traits::Zero;

/// $[x, M x, \dots, M^{n-1} x]$ as the columns of an $n \times n$ rational matrix.
fn krylov(m: &Matrix<Q>, x: Vec<Rational>) -> Matrix<Q> {
    let n = m.nrows();
    let mut cols = vec![x];
    for k in 1..n {
        let prev = &cols[k - 1];
        let next: Vec<Rational> = (0..n)
            .map(|i| {
                m.row(i)
                    .iter()
                    .zip(prev)
                    .filter(|(a, b)| !a.is_zero() && !b.is_zero())
                    .map(|(a, b)| a * b)
                    .sum()
            })
            .collect();
        cols.push(next);
    }
    Matrix::from_fn(Q, n, n, |i, j| cols[j][i].clone())
}

/// $v = K_b\, Q(t)$ over $K$: row $i$ is $\sum_k (K_b)_{ik} q_k(t)$.
fn apply(kb: &Matrix<Q>, coef: &Matrix<Q>, field: &NumberField) -> Vec<NfElem> {
    let prod = super::chains::mul(kb, coef);
    (0..prod.nrows())
        .map(|i| field.from_poly(&Poly::new(Q, prod.row(i).to_vec())))
        .collect()
}

/// The component of the simple irreducible factor `factor` of $\chi_A$ = `chi`
/// (multiplicity 1, degree $\ge 2$), as described in the module docs.
///
/// # Errors
/// `Verification` if no unit vector gives a nonzero eigenvector (impossible for a simple
/// factor; kept as a typed error rather than a panic).
pub(crate) fn simple_component(
    a: &Matrix<Q>,
    chi: &Poly<Q>,
    factor: &Poly<Q>,
    roots: Vec<(f64, f64)>,
) -> Result<PrimaryComponent> {
    let n = a.nrows();
    let d = factor.deg();
    let field = named_field(factor, roots[0], "t");
    let t = field.generator();
    // q_{n-1} = 1, q_{k-1} = c_k + t q_k (chi monic of degree n)
    let chi = chi.monic();
    let mut q = vec![field.zero(); n];
    q[n - 1] = field.one();
    for k in (1..n).rev() {
        let next = field.add(&field.from_rational(&chi.coeff(k)), &field.mul(&t, &q[k]));
        q[k - 1] = next;
    }
    let coef = Matrix::from_fn(Q, n, d, |k, j| {
        q[k].0.get(j).cloned().unwrap_or_else(Rational::zero)
    });
    let unit = |i: usize| {
        (0..n)
            .map(|r| {
                if r == i {
                    Rational::from_integer(1.into())
                } else {
                    Rational::zero()
                }
            })
            .collect::<Vec<_>>()
    };
    let first_nonzero = |m: &Matrix<Q>| -> Option<Vec<NfElem>> {
        (0..n).find_map(|i| {
            let v = apply(&krylov(m, unit(i)), &coef, &field);
            v.iter().any(|x| !field.is_zero(x)).then_some(v)
        })
    };
    let none = || {
        Error::Verification(format!(
            "no nonzero eigenvector from unit vectors for the simple factor {factor}"
        ))
    };
    let v = first_nonzero(a).ok_or_else(none)?;
    let w = first_nonzero(&a.transpose()).ok_or_else(none)?;
    // s = w v, then W = w / s as one rational solve: coeffs(W) = M_s^{-1} coeffs(w)
    let s = v.iter().zip(&w).fold(field.zero(), |acc, (x, y)| {
        field.add(&acc, &field.mul(x, y))
    });
    let ms_inv = mul_matrix(&field, &s)
        .inverse()
        .map_err(|_| Error::Verification(format!("w v = 0 for the simple factor {factor}")))?;
    let wm = super::chains::mul(&ms_inv, &coeff_cols(&w, d));
    let w: Vec<NfElem> = (0..n).map(|j| elem_of_col(&wm, j)).collect();
    Ok(PrimaryComponent {
        factor: factor.clone(),
        multiplicity: 1,
        roots,
        blocks: vec![1],
        kernel_dims: vec![1],
        chains: Matrix::from_vec(field.clone(), n, 1, v),
        left_chains: Matrix::from_vec(field.clone(), 1, n, w),
        field,
    })
}

/// Column `j` of a coefficient matrix as a canonical element.
fn elem_of_col(m: &Matrix<Q>, j: usize) -> NfElem {
    let mut c: Vec<Rational> = (0..m.nrows()).map(|k| m.get(k, j).clone()).collect();
    while c.last().is_some_and(|x| x.is_zero()) {
        c.pop();
    }
    crate::algebraic::ExtElem(c)
}
