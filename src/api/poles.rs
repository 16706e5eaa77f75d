//! Exact roots as the commands show them (`pzmap`'s poles and zeros, Python's `poles()`):
//! the roots of a polynomial over a field with certified eigenvalues ([`roots_over`]), and
//! the eigenvalues of a matrix over the field the api decomposes it in ([`eigenvalues`],
//! through [`super::jordan_values::on_eigen_field`]).
//!
//! Each root is a certified algebraic number (its minimal polynomial over $\mathbb{Q}$ and an
//! isolating box) with its multiplicity, the multiplicity of its irreducible factor over the
//! field; real roots ascending, then complex ones by real and imaginary part.

use super::jordan_values::{EigenVisitor, on_eigen_field};
use crate::algebraic::AlgebraicNumber;
use crate::error::Result;
use crate::jordan::{EigenField, JordanField};
use crate::matrix::Matrix;
use crate::poly::Poly;

/// A root: the certified number, its approximation `(re, im)`, its multiplicity.
pub type ExactRoot = (AlgebraicNumber, (f64, f64), usize);

/// The roots of `p` over `F` (those of `p`, not of its conjugate over a non-real field),
/// certified, with multiplicities; real ones ascending, then complex ones by real and
/// imaginary part. A constant has none.
///
/// # Errors
/// Those of the factorization and of root isolation.
pub fn roots_over<F: EigenField>(p: &Poly<F>) -> Result<Vec<ExactRoot>> {
    if p.deg() == 0 {
        return Ok(vec![]);
    }
    let mut out: Vec<ExactRoot> = vec![];
    for (_, e, _, roots) in F::eigen_factors(&p.monic())? {
        for (z, approx) in roots {
            out.push((z, approx, e));
        }
    }
    let key = |r: &ExactRoot| (r.1.1 != 0.0, r.1.0, r.1.1);
    out.sort_by(|x, y| {
        key(x)
            .partial_cmp(&key(y))
            .unwrap_or(std::cmp::Ordering::Equal)
    });
    Ok(out)
}

/// The eigenvalues of the square `a` ([`roots_over`] of $\chi_A$) over the field the api
/// decomposes it in ($\mathbb{Q}$ when every entry is rational, else $\mathbb{Q}(\sqrt d)$ /
/// $\mathbb{Q}(i)$); `None` over a field without certified eigenvalues
/// ($\mathbb{Q}(p_1, \dots, p_k)$).
///
/// # Errors
/// `NotSquare`; those of [`roots_over`].
pub fn eigenvalues<K: JordanField>(a: &Matrix<K>) -> Option<Result<Vec<ExactRoot>>> {
    struct V;
    impl EigenVisitor for V {
        type Output = Option<Result<Vec<ExactRoot>>>;
        fn visit<F: EigenField>(self, a: &Matrix<F>) -> Self::Output {
            Some(a.charpoly().and_then(|p| roots_over(&p)))
        }
        fn visit_qp(self, _: &Matrix<crate::ratfunc::RatFuncField>) -> Self::Output {
            // not numbers: the factors of det(sI - A) over Q(p) (`modes`, `jordan`)
            None
        }
    }
    on_eigen_field(a, V)
}
