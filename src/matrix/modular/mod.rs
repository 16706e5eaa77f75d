//! Exact linear algebra over $\mathbb{Q}$ by multi-modular arithmetic.
//!
//! The input $A \in \mathbb{Q}^{m \times n}$ is first made integral (row by row for rank,
//! RREF, null space, determinant and inverse; by one global denominator for the
//! characteristic polynomial, see [`intmat`]). The integer problem is then solved modulo
//! word-size primes $2^{61} < p < 2^{62}$ ([`prime`]), the images are combined by the
//! Chinese remainder theorem and, for rational results, rational reconstruction over a
//! common denominator ([`crt`]). Every result is **certified**, never guessed:
//!
//! | entry point | computes | certificate |
//! |---|---|---|
//! | [`rank_q`] | $\operatorname{rank} A$ | that of [`rref_q`] |
//! | [`rref_q`] | canonical RREF $R$ and pivot columns $P$ | $dB = B_{:,P} N$ checked modulo $M > 2\beta$ ([`rref`]) |
//! | [`nullspace_q`] | basis of $\{x : Ax = 0\}$ from the RREF | that of [`rref_q`] |
//! | [`det_q`] | $\det A$ | Hadamard bound ([`det`]) |
//! | [`charpoly_q`] | $\det(xI - A)$, low degree first | principal-minor Hadamard bound ([`charpoly`]) |
//! | [`inverse_q`] | $A^{-1}$ or `None` | $BN = dI$ checked modulo $M > 2\beta$ ([`inverse`]) |
//!
//! Each `*_q` dispatches by size (below); the `*_modular` variants ([`rank_modular`],
//! [`rref_modular`], [`nullspace_modular`], [`det_modular`], [`charpoly_modular`],
//! [`inverse_modular`]) force the multi-modular path, the fraction-free variants live in
//! [`crate::matrix::fraction_free`].
//!
//! Unlucky primes (lower rank or later pivots modulo $p$, singular modulo $p$ while $A$ is
//! not) are detected and discarded.
//!
//! **Dispatch.** Small problems go to the fraction-free routines of
//! [`crate::matrix::fraction_free`] (Bareiss elimination, Berkowitz), which have no
//! per-prime overhead: square matrices with $n \le$ [`SMALL_N`] and RREF inputs with
//! $mn \le$ [`SMALL_MN`] (thresholds measured with `benches/matrix.rs`). Larger inputs take
//! the multi-modular path, whose cost is output-sensitive for RREF, null space and inverse
//! (primes are added until the reconstruction is stable and certified).
//!
//! All matrices are row-major slices; a slice whose length is not `m * n` (or `n * n`) is a
//! caller bug and panics.

pub mod charpoly;
pub mod crt;
pub mod det;
pub mod gcd;
pub mod intmat;
pub mod inverse;
pub mod prime;
pub mod rref;

use crate::field::Rational;
use crate::matrix::fraction_free;
use intmat::{integer_rows, integer_scaled};
use num_bigint::BigInt;
use num_traits::{One, Zero};

/// Square matrices up to this size use the fraction-free path.
pub const SMALL_N: usize = 8;
/// RREF inputs with at most this many entries use the fraction-free path.
pub const SMALL_MN: usize = 64;

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
    rank_modular(m, n, a)
}

/// [`rank_q`] by the multi-modular path, whatever the size.
///
/// # Panics
/// When `a.len() != m * n`.
pub fn rank_modular(m: usize, n: usize, a: &[Rational]) -> usize {
    check_len("rank_modular", a.len(), m, n);
    let (b, _) = integer_rows(m, n, a);
    rref::rref_int(&b).pivots.len()
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
    rref_modular(m, n, a)
}

/// [`rref_q`] by the multi-modular path, whatever the size.
///
/// # Panics
/// When `a.len() != m * n`.
pub fn rref_modular(m: usize, n: usize, a: &[Rational]) -> (Vec<Rational>, Vec<usize>) {
    check_len("rref_modular", a.len(), m, n);
    let (b, _) = integer_rows(m, n, a);
    let res = rref::rref_int(&b);
    let mut out = vec![Rational::zero(); m * n];
    for (x, nu) in out.iter_mut().zip(res.num) {
        if !nu.is_zero() {
            *x = gcd::fraction(nu, &res.den);
        }
    }
    (out, res.pivots)
}

/// Basis of the right null space $\{x \in \mathbb{Q}^n : Ax = 0\}$, canonical: one vector
/// per non-pivot column $f$ of the RREF $R$, with $x_f = 1$, $x_{P_k} = -R_{k,f}$ and zeros
/// elsewhere (in increasing order of $f$).
///
/// # Panics
/// When `a.len() != m * n`.
pub fn nullspace_q(m: usize, n: usize, a: &[Rational]) -> Vec<Vec<Rational>> {
    check_len("nullspace_q", a.len(), m, n);
    nullspace_impl(m, n, a, m * n <= SMALL_MN)
}

/// [`nullspace_q`] by the multi-modular path, whatever the size.
///
/// # Panics
/// When `a.len() != m * n`.
pub fn nullspace_modular(m: usize, n: usize, a: &[Rational]) -> Vec<Vec<Rational>> {
    check_len("nullspace_modular", a.len(), m, n);
    nullspace_impl(m, n, a, false)
}

fn nullspace_impl(m: usize, n: usize, a: &[Rational], small: bool) -> Vec<Vec<Rational>> {
    let (nums, den, pivots): (Vec<BigInt>, BigInt, Vec<usize>) = if small {
        let (r, p) = fraction_free::rref_bareiss(m, n, a);
        let den = r.iter().fold(BigInt::one(), |l, x| {
            num_integer::Integer::lcm(&l, x.denom())
        });
        let nums = r[..p.len() * n]
            .iter()
            .map(|x| x.numer() * (&den / x.denom()))
            .collect();
        (nums, den, p)
    } else {
        let (b, _) = integer_rows(m, n, a);
        let res = rref::rref_int(&b);
        (res.num, res.den, res.pivots)
    };
    let mut is_pivot = vec![false; n];
    pivots.iter().for_each(|&c| is_pivot[c] = true);
    (0..n)
        .filter(|&f| !is_pivot[f])
        .map(|f| {
            let mut v = vec![Rational::zero(); n];
            v[f] = Rational::one();
            for (k, &c) in pivots.iter().enumerate() {
                let x = &nums[k * n + f];
                if !x.is_zero() {
                    v[c] = gcd::fraction(-x, &den);
                }
            }
            v
        })
        .collect()
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
    det_modular(n, a)
}

/// [`det_q`] by the multi-modular path, whatever the size.
///
/// # Panics
/// When `a.len() != n * n`.
pub fn det_modular(n: usize, a: &[Rational]) -> Rational {
    check_len("det_modular", a.len(), n, n);
    let (b, scales) = integer_rows(n, n, a);
    let d = det::det_int(&b);
    scale_det(d, &scales)
}

/// $d \prod_i s_i$ as a canonical fraction (one gcd, not one per row).
pub(crate) fn scale_det(d: BigInt, scales: &[Rational]) -> Rational {
    if d.is_zero() {
        return Rational::zero();
    }
    let mut num = d;
    let mut den = BigInt::one();
    for s in scales {
        if !s.numer().is_one() {
            num *= s.numer();
        }
        if !s.denom().is_one() {
            den *= s.denom();
        }
    }
    gcd::fraction(num, &den)
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
    charpoly_modular(n, a)
}

/// [`charpoly_q`] by the multi-modular path, whatever the size.
///
/// # Panics
/// When `a.len() != n * n`.
pub fn charpoly_modular(n: usize, a: &[Rational]) -> Vec<Rational> {
    check_len("charpoly_modular", a.len(), n, n);
    let (b, s) = integer_scaled(n, n, a);
    let c = charpoly::charpoly_int(&b);
    unscale_charpoly(c, &s)
}

/// Coefficients of $\det(xI - B/s)$ from those of $\det(xI - B)$: $c_k / s^{n-k}$.
pub(crate) fn unscale_charpoly(c: Vec<BigInt>, s: &BigInt) -> Vec<Rational> {
    let n = c.len() - 1;
    if s.is_one() {
        return c.into_iter().map(Rational::from_integer).collect();
    }
    let mut out = vec![Rational::zero(); n + 1];
    let mut pow = BigInt::one();
    for k in (0..=n).rev() {
        out[k] = Rational::new(c[k].clone(), pow.clone());
        pow *= s;
    }
    out
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
    inverse_modular(n, a)
}

/// [`inverse_q`] by the multi-modular path, whatever the size.
///
/// # Panics
/// When `a.len() != n * n`.
pub fn inverse_modular(n: usize, a: &[Rational]) -> Option<Vec<Rational>> {
    check_len("inverse_modular", a.len(), n, n);
    // A = S B with S = diag(scales), so A^{-1} = B^{-1} S^{-1}: column j divided by s_j
    let (b, scales) = integer_rows(n, n, a);
    let (num, den) = inverse::inverse_int(&b)?;
    // entry (i, j) is num_ij / (den s_j) = num_ij d_j / (den c_j), s_j = c_j / d_j
    let col_den: Vec<BigInt> = scales.iter().map(|s| &den * s.numer()).collect();
    Some(
        num.into_iter()
            .enumerate()
            .map(|(idx, x)| {
                let j = idx % n;
                if scales[j].denom().is_one() {
                    gcd::fraction(x, &col_den[j])
                } else {
                    gcd::fraction(x * scales[j].denom(), &col_den[j])
                }
            })
            .collect(),
    )
}
