//! Size dispatch of the $\mathbb{Q}$ kernels of [`crate::qkernels`] (the matrix-side choice
//! of method, as SymPy's `_dm_rref_choose_method` and FLINT's `gr_mat` do).
//!
//! Larger inputs reduce the rational matrix itself modulo each prime
//! ([`crate::qkernels::modular::direct`], issue 29: no row-wise denominator clearing, whose
//! integer entries have $n \log_2 q$ bits on a matrix of fractions): determinant,
//! characteristic polynomial, inverse, the full-rank shortcut of rank / RREF / null space
//! (one image of rank $n$ proves them), and the minimal polynomial (a Krylov sequence of
//! rank $n$ modulo a prime proves $\mu_A = \chi_A$, otherwise the multi-modular Krylov
//! method of [`crate::qkernels::modular::minpoly`]).
//!
//! Small problems go to the fraction-free routines of [`crate::qkernels::fraction_free`]
//! (Bareiss elimination, Berkowitz), which have no per-prime overhead: square matrices with
//! $n \le$ [`SMALL_N`] and RREF inputs with $mn \le$ [`SMALL_MN`] (thresholds measured with
//! `benches/matrix.rs`). Larger inputs take the certified multi-modular path of
//! [`crate::qkernels::modular`], whose cost is output-sensitive for RREF, null space and
//! inverse; a rank-deficient RREF (and with it rank and null space) is first solved on one
//! nonsingular pivot block ([`crate::qkernels::modular::pivot_solve`], no rational
//! reconstruction; the other rows are checked exactly to lie in the span). Products with inner dimension $\ge$ [`MUL_MIN_K`] use the integer kernel
//! [`crate::qkernels::intmul`].
//!
//! Each function computes the same canonical result as the generic algorithm of
//! [`crate::matrix::Matrix`] over $\mathbb{Q}$ (RREF, rank, null space, $\det A$,
//! $\det(xI - A)$ low degree first, $A^{-1}$ or `None`, $AB$).
//!
//! All matrices are row-major slices; a slice whose length is not `m * n` (or `n * n`) is a
//! caller bug and panics.

use crate::field::Rational;
use crate::qkernels::modular::direct;
use crate::qkernels::{fraction_free, intmul, modular};
use num_bigint::BigInt;
use num_traits::{One, Zero};

/// Square matrices up to this size use the fraction-free path.
pub const SMALL_N: usize = 8;
/// RREF inputs with at most this many entries use the fraction-free path.
pub const SMALL_MN: usize = 64;
/// Products whose inner dimension is at least this (and with at least 4 entries) use the
/// integer product kernel.
pub const MUL_MIN_K: usize = 4;

fn check_len(op: &str, len: usize, m: usize, n: usize) {
    assert_eq!(
        len,
        m * n,
        "{op}: slice of length {len} for a {m}x{n} matrix"
    );
}

/// Rank of the `m x n` row-major matrix `a`.
///
/// # Panics
/// When `a.len() != m * n`.
pub fn rank_q(m: usize, n: usize, a: &[Rational]) -> usize {
    check_len("rank_q", a.len(), m, n);
    if m * n <= SMALL_MN {
        return fraction_free::rank_bareiss(m, n, a);
    }
    direct::rank_if_full(m, n, a).unwrap_or_else(|| modular::rank_modular(m, n, a))
}

/// Canonical reduced row echelon form (`m x n`, pivots 1, zeros above and below them,
/// zero rows last) and the pivot columns.
///
/// # Panics
/// When `a.len() != m * n`.
pub fn rref_q(m: usize, n: usize, a: &[Rational]) -> (Vec<Rational>, Vec<usize>) {
    check_len("rref_q", a.len(), m, n);
    if m * n <= SMALL_MN {
        return fraction_free::rref_bareiss(m, n, a);
    }
    if n <= m && direct::rank_if_full(m, n, a) == Some(n) {
        // rank n: the RREF is the identity over zero rows
        let mut r = vec![Rational::zero(); m * n];
        (0..n).for_each(|k| r[k * n + k] = Rational::one());
        return (r, (0..n).collect());
    }
    modular::rref_modular(m, n, a)
}

/// Basis of the right null space $\{x \in \mathbb{Q}^n : Ax = 0\}$, canonical: one vector
/// per non-pivot column $f$ of the RREF $R$, with $x_f = 1$, $x_{P_k} = -R_{k,f}$ and zeros
/// elsewhere (in increasing order of $f$).
///
/// # Panics
/// When `a.len() != m * n`.
pub fn nullspace_q(m: usize, n: usize, a: &[Rational]) -> Vec<Vec<Rational>> {
    check_len("nullspace_q", a.len(), m, n);
    if m * n > SMALL_MN {
        if n <= m && direct::rank_if_full(m, n, a) == Some(n) {
            return vec![];
        }
        return modular::nullspace_modular(m, n, a);
    }
    let (r, p) = fraction_free::rref_bareiss(m, n, a);
    let den = r.iter().fold(BigInt::one(), |l, x| {
        num_integer::Integer::lcm(&l, x.denom())
    });
    let nums: Vec<BigInt> = r[..p.len() * n]
        .iter()
        .map(|x| x.numer() * (&den / x.denom()))
        .collect();
    modular::nullspace_from_integer_rref(n, &nums, &den, &p)
}

/// Determinant of the `n x n` row-major matrix `a` (1 for `n = 0`).
///
/// # Panics
/// When `a.len() != n * n`.
pub fn det_q(n: usize, a: &[Rational]) -> Rational {
    check_len("det_q", a.len(), n, n);
    if n <= SMALL_N {
        return fraction_free::det_bareiss(n, a);
    }
    direct::det_direct(n, a)
}

/// Characteristic polynomial $\det(xI - A)$: coefficients low degree first, monic, length
/// `n + 1`.
///
/// # Panics
/// When `a.len() != n * n`.
pub fn charpoly_q(n: usize, a: &[Rational]) -> Vec<Rational> {
    check_len("charpoly_q", a.len(), n, n);
    if n <= SMALL_N {
        return fraction_free::charpoly_berkowitz(n, a);
    }
    direct::charpoly_direct(n, a)
}

/// Inverse of the `n x n` row-major matrix `a`; `None` when `a` is singular.
///
/// # Panics
/// When `a.len() != n * n`.
pub fn inverse_q(n: usize, a: &[Rational]) -> Option<Vec<Rational>> {
    check_len("inverse_q", a.len(), n, n);
    if n <= SMALL_N {
        return fraction_free::inverse_bareiss(n, a);
    }
    direct::inverse_direct(n, a)
}

/// Row-major product of `m x k` and `k x n`; `None` when the generic loop is the better
/// choice (inner dimension below [`MUL_MIN_K`] or fewer than 4 entries).
pub fn mul_q(
    m: usize,
    k: usize,
    n: usize,
    a: &[Rational],
    b: &[Rational],
) -> Option<Vec<Rational>> {
    (k >= MUL_MIN_K && m * n >= 4).then(|| intmul::mul_q(m, k, n, a, b))
}

/// $X = A^{-1} B$ for a square `a` (`n x n`, `b` is `n x k`) when $A$ is nonsingular and
/// the size calls for a kernel ($n >$ [`SMALL_N`]): Dixon's $p$-adic lifting
/// ([`modular::dixon`]); `None` otherwise (singular $A$, or small: the caller takes the
/// RREF of $[A \mid B]$). The solve kernel of the field hooks ([`crate::matrix::Matrix::solve`]).
///
/// # Panics
/// When `a.len() != n * n` or `b.len() != n * k`.
pub fn solve_square_q(n: usize, k: usize, a: &[Rational], b: &[Rational]) -> Option<Vec<Rational>> {
    check_len("solve_square_q", a.len(), n, n);
    check_len("solve_square_q", b.len(), n, k);
    (n > SMALL_N).then(|| modular::dixon::solve_dixon(n, k, a, b))?
}

/// Solution of $AX = B$ (`a` is `m x n`, `b` is `m x k`): one particular solution `n x k`
/// (free variables zero), or `None` when the system is inconsistent. A nonsingular square
/// $A$ takes [`solve_square_q`]; the others the RREF of $[A \mid B]$.
///
/// # Panics
/// When `a.len() != m * n` or `b.len() != m * k`.
pub fn solve_q(
    m: usize,
    n: usize,
    k: usize,
    a: &[Rational],
    b: &[Rational],
) -> Option<Vec<Rational>> {
    check_len("solve_q", a.len(), m, n);
    check_len("solve_q", b.len(), m, k);
    if m == n
        && let Some(x) = solve_square_q(n, k, a, b)
    {
        return Some(x);
    }
    let mut aug = Vec::with_capacity(m * (n + k));
    for i in 0..m {
        aug.extend_from_slice(&a[i * n..(i + 1) * n]);
        aug.extend_from_slice(&b[i * k..(i + 1) * k]);
    }
    let (r, piv) = rref_q(m, n + k, &aug);
    if piv.last().is_some_and(|&p| p >= n) {
        return None;
    }
    let mut x = vec![Rational::zero(); n * k];
    for (i, &p) in piv.iter().enumerate() {
        x[p * k..(p + 1) * k].clone_from_slice(&r[i * (n + k) + n..(i + 1) * (n + k)]);
    }
    Some(x)
}

/// Minimal polynomial of the `n x n` matrix `a` (monic, low degree first): the
/// characteristic polynomial when one Krylov sequence modulo a prime certifies that they
/// are equal ([`direct::is_cyclic`]), otherwise the multi-modular Krylov method of
/// [`modular::minpoly`]; `None` when that found no certified candidate (the caller takes
/// the generic path).
///
/// # Panics
/// When `a.len() != n * n`.
pub fn minpoly_q(n: usize, a: &[Rational]) -> Option<Vec<Rational>> {
    check_len("minpoly_q", a.len(), n, n);
    if direct::is_cyclic(n, a) {
        return Some(charpoly_q(n, a));
    }
    modular::minpoly::minpoly_modular(n, a)
}

/// Does one elimination modulo a word prime (two at most) prove $\mathrm{rank}\,A \ge r$?
/// A prime dividing no denominator maps every nonzero minor modulo $p$ to a nonzero minor
/// over $\mathbb{Q}$ ([`crate::qkernels::modular::rank`]), so the rank modulo $p$ is a
/// lower bound. `false` decides nothing.
///
/// # Panics
/// When `a.len() != m * n`.
pub fn rank_at_least_mod_p(m: usize, n: usize, a: &[Rational], r: usize) -> bool {
    check_len("rank_at_least_mod_p", a.len(), m, n);
    crate::qkernels::prime::primes(11)
        .take(2)
        .any(|pr| modular::rank::rank_lower_bound(&pr, m, n, a).is_some_and(|rp| rp >= r))
}
