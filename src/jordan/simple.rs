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
//! The same holds over any base field $F$ with $E = F\[t\]/(g)$ ([`simple_chains`], used
//! over $\mathbb{Q}$ and over $\mathbb{Q}(\sqrt d)$). All work is over $F$ (Krylov
//! matrices, one product $K_b C$ with the coefficient matrix $C$ of the $q_k(t)$, $w v$ and
//! $W$ as products and one $d \times d$ inverse, [`super::coeffs`]: the product kernels of
//! the matrix layer) plus the $n$ steps of $q$ in $E$. For a dense $16 \times 16$ integer matrix with an irreducible
//! characteristic polynomial this replaces an elimination over a field of degree 16.
//! The component is checked exactly as every other one.

use super::coeffs::{coeff_cols, dot, elem_of_col, elem_of_row, mul_matrix};
use crate::algebraic::{Ext, ExtElem};
use crate::error::{Error, Result};
use crate::field::Field;
use crate::matrix::Matrix;
use crate::poly::Poly;

/// Right ($n \times 1$) and left ($1 \times n$) chains over $F\[t\]/(g)$.
pub(crate) type ChainPair<F> = (Matrix<Ext<F>>, Matrix<Ext<F>>);

/// $K_b$ for `b = e_i` ($n \times n$, column $j$ is $M^j e_i$), each product on the
/// product kernel of the matrix layer.
fn krylov<F: Field>(m: &Matrix<F>, i: usize) -> Matrix<F> {
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
pub(crate) fn simple_chains<F: Field>(
    a: &Matrix<F>,
    chi: &Poly<F>,
    e: &Ext<F>,
) -> Result<ChainPair<F>> {
    let n = a.nrows();
    let t = e.generator();
    let chi = chi.monic();
    let mut q = vec![e.zero(); n];
    q[n - 1] = e.one();
    for k in (1..n).rev() {
        q[k - 1] = e.add(&e.from_base(&chi.coeff(k)), &e.mul(&t, &q[k]));
    }
    // the coefficients of q_k(t) as the rows of an n x d matrix over F: v = K_b Q
    let qc = coeff_cols(e, &q).transpose();
    let first = |m: &Matrix<F>| {
        (0..n).find_map(|i| {
            let kq = &krylov(m, i) * &qc;
            let v: Vec<ExtElem<F::Elem>> = (0..n).map(|r| elem_of_row(&kq, r)).collect();
            v.iter().any(|x| !e.is_zero(x)).then_some(v)
        })
    };
    let none = || {
        Error::Verification(format!(
            "no nonzero eigenvector from unit vectors for the simple factor {}",
            e.modulus()
        ))
    };
    let v = first(a).ok_or_else(none)?;
    let w = first(&a.transpose()).ok_or_else(none)?;
    // s = w v, then W = w / s as one solve over F: coeffs(W) = M_s^{-1} coeffs(w)
    let s = dot(e, &v, &w);
    let ms_inv = mul_matrix(e, &s).inverse().map_err(|_| {
        Error::Verification(format!("w v = 0 for the simple factor {}", e.modulus()))
    })?;
    let wc = &ms_inv * &coeff_cols(e, &w);
    let w: Vec<ExtElem<F::Elem>> = (0..n).map(|j| elem_of_col(&wc, j)).collect();
    Ok((
        Matrix::from_vec(e.clone(), n, 1, v),
        Matrix::from_vec(e.clone(), 1, n, w),
    ))
}
