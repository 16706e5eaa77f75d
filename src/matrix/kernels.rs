//! The kernel dispatch: for each heavy operation, the one place that asks the field which
//! kernels it registered ([`Field::kernels`], see [`crate::field::kernels`]) and calls them.
//!
//! | field entry | kernels |
//! |---|---|
//! | `Rational` ($\mathbb{Q}$) | [`super::over_q`]: charpoly, minpoly, det, RREF, rank, rank bound modulo $p$, null space, inverse, solve, product |
//! | `Quadratic` ($\mathbb{Q}(\sqrt d)$) | [`super::over_k`]: charpoly, det (multi-modular, both embeddings $\sqrt d \mapsto \pm r$), RREF (and with it the null space), rank, rank bound modulo $p$, inverse, product |
//! | `Table` (e.g. $\mathbb{Q}(p)$) | the field's [`crate::field::KernelTable`] (with the generic rank bound) |
//! | `Generic` | none |
//!
//! Two kernels only guess (their callers check every guess exactly): the image modulo a word
//! prime and an RREF reconstructed from such images ($\mathbb{Q}$ only).
//!
//! Each function returns `None` when no kernel applies; the caller then runs the generic
//! algorithm of [`Matrix`], which computes the same canonical result.

use super::{Matrix, over_k, over_q};
use crate::error::{Error, Result};
use crate::field::{Field, Kernels};
use crate::poly::Poly;
use crate::qkernels::modular::guess::rref_guess as rref_guess_q;
use crate::qkernels::modular::rank::reduce_rational;
use crate::qkernels::prime::Prime;

/// $\det(xI - A)$ (square `a`).
pub(super) fn charpoly<K: Field>(a: &Matrix<K>) -> Option<Result<Poly<K>>> {
    let (k, n) = (&a.field, a.nrows);
    let c = match k.kernels() {
        Kernels::Rational(w) => Ok(w.back(over_q::charpoly_q(n, w.view(&a.data)))),
        Kernels::Quadratic(w, d) => Ok(w.back(over_k::charpoly_k(d, n, w.view(&a.data))?)),
        Kernels::Table(t) => t.charpoly(k, n, &a.data)?,
        Kernels::Generic => return None,
    };
    Some(c.map(|c| Poly::new(k.clone(), c)))
}

/// The minimal polynomial (square `a`).
pub(super) fn minpoly<K: Field>(a: &Matrix<K>) -> Option<Poly<K>> {
    let (k, n) = (&a.field, a.nrows);
    match k.kernels() {
        Kernels::Rational(w) => {
            let c = over_q::minpoly_q(n, w.view(&a.data))?;
            Some(Poly::new(k.clone(), w.back(c)))
        }
        Kernels::Quadratic(..) | Kernels::Table(_) | Kernels::Generic => None,
    }
}

/// Does an image modulo a word prime prove $\mathrm{rank}\,A \ge r$ (`0 < r <= min(m, n)`)?
/// `false` decides nothing.
pub(super) fn rank_at_least_mod_p<K: Field>(a: &Matrix<K>, r: usize) -> bool {
    let (k, m, n) = (&a.field, a.nrows, a.ncols);
    match k.kernels() {
        Kernels::Rational(w) => over_q::rank_at_least_mod_p(m, n, w.view(&a.data), r),
        Kernels::Quadratic(w, d) => over_k::rank_at_least_mod_p(d, m, n, w.view(&a.data), r),
        Kernels::Table(_) | Kernels::Generic => false,
    }
}

/// The image of $A$ modulo the word prime `pr` (row-major), when the field registers a
/// reduction ($\mathbb{Q}$: `None` when `pr` divides a denominator).
pub(super) fn image_mod_p<K: Field>(a: &Matrix<K>, pr: &Prime) -> Option<Vec<u64>> {
    match a.field.kernels() {
        Kernels::Rational(w) => w
            .view(&a.data)
            .iter()
            .map(|x| reduce_rational(pr, x))
            .collect(),
        Kernels::Quadratic(..) | Kernels::Table(_) | Kernels::Generic => None,
    }
}

/// A guess of the canonical RREF (pivot columns, the nonzero rows) from images modulo
/// primes and rational reconstruction, unchecked, when the field registers one
/// ($\mathbb{Q}$: `max_primes` word primes).
pub(super) fn rref_guess<K: Field>(
    a: &Matrix<K>,
    max_primes: usize,
) -> Option<(Vec<usize>, Matrix<K>)> {
    let (k, m, n) = (&a.field, a.nrows, a.ncols);
    match k.kernels() {
        Kernels::Rational(w) => {
            let (piv, r) = rref_guess_q(m, n, w.view(&a.data), max_primes)?;
            let rows = piv.len();
            Some((piv, Matrix::from_vec(k.clone(), rows, n, w.back(r))))
        }
        Kernels::Quadratic(..) | Kernels::Table(_) | Kernels::Generic => None,
    }
}

/// The field's cheap lower bound of the generic rank
/// ([`crate::field::KernelTable::rank_lower_bound`]).
pub(super) fn generic_rank_lower_bound<K: Field>(a: &Matrix<K>) -> Option<usize> {
    match a.field.kernels() {
        Kernels::Table(t) => t.rank_lower_bound(&a.field, a.nrows, a.ncols, &a.data),
        Kernels::Rational(_) | Kernels::Quadratic(..) | Kernels::Generic => None,
    }
}

/// $\det A$ (square `a`).
pub(super) fn det<K: Field>(a: &Matrix<K>) -> Option<Result<K::Elem>> {
    let (k, n) = (&a.field, a.nrows);
    match k.kernels() {
        Kernels::Rational(w) => Some(Ok(w.back_one(over_q::det_q(n, w.view(&a.data))))),
        Kernels::Quadratic(w, d) => {
            let x = over_k::det_k(d, n, w.view(&a.data))?;
            Some(Ok(w.back(vec![x]).pop().expect("one element in, one out")))
        }
        Kernels::Table(t) => t.det(k, n, &a.data),
        Kernels::Generic => None,
    }
}

/// Canonical RREF and pivot columns.
pub(super) fn rref<K: Field>(a: &Matrix<K>) -> Option<(Matrix<K>, Vec<usize>)> {
    let (k, m, n) = (&a.field, a.nrows, a.ncols);
    let (d, piv) = match k.kernels() {
        Kernels::Rational(w) => {
            let (d, piv) = over_q::rref_q(m, n, w.view(&a.data));
            (w.back(d), piv)
        }
        Kernels::Quadratic(w, dd) => {
            let (d, piv) = over_k::rref_k(dd, m, n, w.view(&a.data));
            (w.back(d), piv)
        }
        Kernels::Table(t) => t.rref(k, m, n, &a.data)?,
        Kernels::Generic => return None,
    };
    Some((Matrix::from_vec(k.clone(), m, n, d), piv))
}

/// The pivot columns of the RREF, when the field certifies them without the RREF.
pub(super) fn pivots<K: Field>(a: &Matrix<K>) -> Option<Vec<usize>> {
    match a.field.kernels() {
        Kernels::Table(t) => t.pivots(&a.field, a.nrows, a.ncols, &a.data),
        Kernels::Rational(_) | Kernels::Quadratic(..) | Kernels::Generic => None,
    }
}

/// $\operatorname{rank} A$.
pub(super) fn rank<K: Field>(a: &Matrix<K>) -> Option<usize> {
    let (k, m, n) = (&a.field, a.nrows, a.ncols);
    match k.kernels() {
        Kernels::Rational(w) => Some(over_q::rank_q(m, n, w.view(&a.data))),
        Kernels::Quadratic(w, d) => Some(over_k::rank_k(d, m, n, w.view(&a.data))),
        Kernels::Table(t) => t.rank(k, m, n, &a.data),
        Kernels::Generic => None,
    }
}

/// The canonical null-space basis as the columns of an `ncols x nullity` matrix.
pub(super) fn nullspace<K: Field>(a: &Matrix<K>) -> Option<Matrix<K>> {
    let (k, m, n) = (&a.field, a.nrows, a.ncols);
    let vs = match k.kernels() {
        Kernels::Rational(w) => over_q::nullspace_q(m, n, w.view(&a.data))
            .into_iter()
            .map(|v| w.back(v))
            .collect(),
        Kernels::Table(t) => t.nullspace(k, m, n, &a.data)?,
        Kernels::Quadratic(..) | Kernels::Generic => return None,
    };
    Some(Matrix::from_fn(k.clone(), n, vs.len(), |i, j| {
        vs[j][i].clone()
    }))
}

/// $A^{-1}$; `Err(Singular)` when $A$ is singular (square `a`).
pub(super) fn inverse<K: Field>(a: &Matrix<K>) -> Option<Result<Matrix<K>>> {
    let (k, n) = (&a.field, a.nrows);
    let inv = match k.kernels() {
        Kernels::Rational(w) => over_q::inverse_q(n, w.view(&a.data)).map(|d| w.back(d)),
        Kernels::Quadratic(w, d) => over_k::inverse_k(d, n, w.view(&a.data)).map(|x| w.back(x)),
        Kernels::Table(t) => t.inverse(k, n, &a.data)?,
        Kernels::Generic => return None,
    };
    Some(
        inv.map(|d| Matrix::from_vec(k.clone(), n, n, d))
            .ok_or(Error::Singular),
    )
}

/// $X = A^{-1} B$ when the field's kernel proves $A$ (square) nonsingular; `None` otherwise
/// (the caller's RREF of $[A \mid B]$ then decides).
pub(super) fn solve_square<K: Field>(a: &Matrix<K>, b: &Matrix<K>) -> Option<Matrix<K>> {
    let k = &a.field;
    let (n, c) = (a.nrows, b.ncols);
    let x = match k.kernels() {
        Kernels::Rational(w) => w.back(over_q::solve_square_q(
            n,
            c,
            w.view(&a.data),
            w.view(&b.data),
        )?),
        Kernels::Quadratic(..) | Kernels::Table(_) | Kernels::Generic => return None,
    };
    Some(Matrix::from_vec(k.clone(), n, c, x))
}

/// $AB$ (shapes already checked).
pub(super) fn mul<K: Field>(a: &Matrix<K>, b: &Matrix<K>) -> Option<Matrix<K>> {
    let k = &a.field;
    let (m, l, n) = (a.nrows, a.ncols, b.ncols);
    let v = match k.kernels() {
        Kernels::Rational(w) => w.back(over_q::mul_q(m, l, n, w.view(&a.data), w.view(&b.data))?),
        Kernels::Quadratic(w, d) => {
            w.back(over_k::mul_k(d, m, l, n, w.view(&a.data), w.view(&b.data))?)
        }
        Kernels::Table(t) => t.mul(k, (m, l, n), &a.data, &b.data)?,
        Kernels::Generic => return None,
    };
    Some(Matrix::from_vec(k.clone(), m, n, v))
}
