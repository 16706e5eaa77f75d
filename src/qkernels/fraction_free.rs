//! Fraction-free exact linear algebra over $\mathbb{Q}$: the classical integer algorithms.
//!
//! The rational input is made integral first (row-wise or by a global denominator, see
//! [`crate::qkernels::intmat`]); every intermediate value is then an integer minor
//! of that matrix, so no gcd is ever taken during elimination.
//!
//! | entry point | computes | algorithm | cost ($n$ = size) |
//! |---|---|---|---|
//! | [`det_bareiss`] | $\det A$ | Bareiss one-step elimination | $O(n^3)$ exact integer ops |
//! | [`rref_bareiss`] | canonical RREF and pivots | fraction-free Gauss–Jordan | $O(mn\min(m,n))$ |
//! | [`rank_bareiss`] | $\operatorname{rank} A$ | fraction-free Gauss–Jordan | as above |
//! | [`inverse_bareiss`] | $A^{-1}$ or `None` | fraction-free Gauss–Jordan on $[B \mid I]$ | $O(n^3)$ |
//! | [`charpoly_berkowitz`] | $\det(xI - A)$, low degree first | Berkowitz (division-free) | $O(n^4)$ |
//!
//! These are the oracle of [`crate::qkernels::modular`] and its path for small sizes.

use crate::field::Rational;
use crate::qkernels::intmat::unscale_charpoly;
use crate::qkernels::intmat::{integer_rows, integer_scaled};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Zero};

/// `(a * b - c * d) / e`, exact.
#[inline]
fn cross_div(a: &BigInt, b: &BigInt, c: &BigInt, d: &BigInt, e: &BigInt) -> BigInt {
    let t = a * b - c * d;
    if e.is_one() {
        return t;
    }
    let (q, r) = t.div_rem(e);
    debug_assert!(r.is_zero(), "fraction-free division is exact");
    q
}

/// Determinant of the `n x n` row-major `a` by Bareiss elimination (1 for `n = 0`).
///
/// # Panics
/// When `a.len() != n * n`.
pub fn det_bareiss(n: usize, a: &[Rational]) -> Rational {
    let (b, scales) = integer_rows(n, n, a);
    let mut m = b.entries;
    let Some((d, neg)) = bareiss(n, &mut m, BigInt::one()) else {
        return Rational::zero();
    };
    let d = if neg { -d } else { d };
    crate::qkernels::intmat::scale_det(d, &scales)
}

/// Bareiss's one-step elimination on the `n x n` row-major `m` over an integral domain, in
/// place (`one` its unit): `Some((d, neg))` with $\det = \pm d$ (`neg`: an odd number of
/// row swaps; `d = one` for `n = 0`), `None` for a singular matrix. Every division is exact.
pub fn bareiss<R: FractionFree>(n: usize, m: &mut [R], one: R) -> Option<(R, bool)> {
    let mut neg = false;
    let mut prev = one;
    for k in 0..n {
        let i = (k..n).find(|&i| !m[i * n + k].vanishes())?;
        if i != k {
            for j in 0..n {
                m.swap(i * n + j, k * n + j);
            }
            neg = !neg;
        }
        for i in k + 1..n {
            for j in k + 1..n {
                m[i * n + j] = R::cross_div(
                    &m[k * n + k],
                    &m[i * n + j],
                    &m[i * n + k],
                    &m[k * n + j],
                    &prev,
                );
            }
        }
        prev = m[k * n + k].clone();
    }
    Some((prev, neg))
}

/// An integral domain for fraction-free elimination: $\mathbb{Z}$ ([`BigInt`]) here,
/// $\mathbb{Z}\lbrack p\rbrack$ in [`crate::matrix::params::rref_params`].
pub trait FractionFree: Clone {
    fn vanishes(&self) -> bool;
    /// $(a b - c d) / e$, the division exact.
    fn cross_div(a: &Self, b: &Self, c: &Self, d: &Self, e: &Self) -> Self;
}

impl FractionFree for BigInt {
    fn vanishes(&self) -> bool {
        self.is_zero()
    }
    fn cross_div(a: &Self, b: &Self, c: &Self, d: &Self, e: &Self) -> Self {
        cross_div(a, b, c, d, e)
    }
}

/// Fraction-free Gauss–Jordan on an `m x n` matrix over an integral domain in place
/// (`one` its unit). Afterwards the first `r` rows hold `den * R` (every pivot entry equals
/// `den`, the last pivot); returns `(pivots, den)`. `on_pivot(r, i, piv)` sees each pivot
/// after row `i` was swapped into row `r` (`i == r`: no swap), before the elimination.
pub fn ff_gauss_jordan<R: FractionFree>(
    m: usize,
    n: usize,
    a: &mut [R],
    one: R,
    mut on_pivot: impl FnMut(usize, usize, &R),
) -> (Vec<usize>, R) {
    let mut pivots = Vec::new();
    let mut den = one;
    let mut r = 0;
    for c in 0..n {
        if r == m {
            break;
        }
        let Some(i) = (r..m).find(|&i| !a[i * n + c].vanishes()) else {
            continue;
        };
        if i != r {
            for j in 0..n {
                a.swap(i * n + j, r * n + j);
            }
        }
        let piv = a[r * n + c].clone();
        on_pivot(r, i, &piv);
        for i in 0..m {
            if i == r {
                continue;
            }
            let f = a[i * n + c].clone();
            for j in 0..n {
                // columns left of c in row r are zero; the update there is a pure rescale
                a[i * n + j] = R::cross_div(&piv, &a[i * n + j], &f, &a[r * n + j], &den);
            }
        }
        den = piv;
        pivots.push(c);
        r += 1;
    }
    (pivots, den)
}

/// Canonical RREF of the `m x n` row-major `a` and its pivot columns, by fraction-free
/// Gauss–Jordan elimination.
///
/// # Panics
/// When `a.len() != m * n`.
pub fn rref_bareiss(m: usize, n: usize, a: &[Rational]) -> (Vec<Rational>, Vec<usize>) {
    let (b, _) = integer_rows(m, n, a);
    let mut e = b.entries;
    let (pivots, den) = ff_gauss_jordan(m, n, &mut e, BigInt::one(), |_, _, _| {});
    let r = pivots.len();
    let out = e
        .into_iter()
        .enumerate()
        .map(|(idx, x)| {
            if idx >= r * n || x.is_zero() {
                Rational::zero()
            } else {
                Rational::new(x, den.clone())
            }
        })
        .collect();
    (out, pivots)
}

/// Rank of the `m x n` row-major `a` by fraction-free elimination.
///
/// # Panics
/// When `a.len() != m * n`.
pub fn rank_bareiss(m: usize, n: usize, a: &[Rational]) -> usize {
    let (b, _) = integer_rows(m, n, a);
    let mut e = b.entries;
    ff_gauss_jordan(m, n, &mut e, BigInt::one(), |_, _, _| {})
        .0
        .len()
}

/// Inverse of the `n x n` row-major `a` (`None` when singular), by fraction-free
/// Gauss–Jordan elimination of $[B \mid I]$ where $A = SB$ row-wise.
///
/// # Panics
/// When `a.len() != n * n`.
pub fn inverse_bareiss(n: usize, a: &[Rational]) -> Option<Vec<Rational>> {
    let (b, scales) = integer_rows(n, n, a);
    let w = 2 * n;
    let mut e = vec![BigInt::zero(); n * w];
    for i in 0..n {
        for j in 0..n {
            e[i * w + j] = b.entries[i * n + j].clone();
        }
        e[i * w + n + i] = BigInt::one();
    }
    let (pivots, den) = ff_gauss_jordan(n, w, &mut e, BigInt::one(), |_, _, _| {});
    // invertible iff the first n pivots are the columns of B
    if n > 0 && pivots.get(n - 1) != Some(&(n - 1)) {
        return None;
    }
    // A^{-1} = B^{-1} S^{-1}: column j divided by scale j
    let mut out = Vec::with_capacity(n * n);
    for i in 0..n {
        for j in 0..n {
            let x = &e[i * w + n + j];
            out.push(if x.is_zero() {
                Rational::zero()
            } else {
                Rational::new(x.clone(), den.clone()) / &scales[j]
            });
        }
    }
    Some(out)
}

/// Characteristic polynomial $\det(xI - A)$ by Berkowitz's division-free algorithm on the
/// integer matrix $B = sA$; coefficients low degree first, monic, length `n + 1`.
///
/// # Panics
/// When `a.len() != n * n`.
pub fn charpoly_berkowitz(n: usize, a: &[Rational]) -> Vec<Rational> {
    let (b, s) = integer_scaled(n, n, a);
    let c = berkowitz_int(n, &b.entries);
    unscale_charpoly(c, &s)
}

/// Berkowitz over $\mathbb{Z}$: low degree first.
///
/// The leading $(r+1) \times (r+1)$ block is $\begin{pmatrix} A_r & c \\ R & a \end{pmatrix}$
/// and its characteristic polynomial is $T p_r$ with $T$ the lower triangular Toeplitz
/// matrix of first column $(1, -a, -Rc, -RA_rc, \dots, -RA_r^{r-1}c)$.
fn berkowitz_int(n: usize, b: &[BigInt]) -> Vec<BigInt> {
    // poly: high degree first while building
    let mut poly = vec![BigInt::one()];
    for r in 0..n {
        let mut t = Vec::with_capacity(r + 2);
        t.push(BigInt::one());
        t.push(-&b[r * n + r]);
        let mut v: Vec<BigInt> = (0..r).map(|i| b[i * n + r].clone()).collect();
        for k in 0..r {
            let rv: BigInt = (0..r).map(|j| &b[r * n + j] * &v[j]).sum();
            t.push(-rv);
            if k + 1 < r {
                v = (0..r)
                    .map(|i| (0..r).map(|j| &b[i * n + j] * &v[j]).sum())
                    .collect();
            }
        }
        let next: Vec<BigInt> = (0..r + 2)
            .map(|i| {
                (0..=i.min(r))
                    .filter(|&j| i - j < t.len())
                    .map(|j| &t[i - j] * &poly[j])
                    .sum()
            })
            .collect();
        poly = next;
    }
    poly.reverse();
    poly
}
