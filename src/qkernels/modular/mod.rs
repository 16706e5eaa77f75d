//! Exact linear algebra over $\mathbb{Q}$ by multi-modular arithmetic.
//!
//! The input $A \in \mathbb{Q}^{m \times n}$ is first made integral (row by row for rank,
//! RREF, null space, determinant and inverse; by one global denominator for the
//! characteristic polynomial, see [`crate::qkernels::intmat`]). The integer problem is then
//! solved modulo word-size primes $2^{61} < p < 2^{62}$ ([`crate::qkernels::prime`]), the
//! images are combined by the Chinese remainder theorem and, for rational results, rational
//! reconstruction over a common denominator ([`crt`]). Every result is **certified**, never
//! guessed:
//!
//! | entry point | computes | certificate |
//! |---|---|---|
//! | [`rank_modular`] | $\operatorname{rank} A$ | that of [`rref_modular`] |
//! | [`pivot_solve::rref_pivot_solve`] | RREF from a nonsingular block, no reconstruction | $A_{i,:} = A_{i,P} X$ for the other rows, exactly ([`pivot_solve`]) |
//! | [`rank::rank_lower_bound`] | $\operatorname{rank}(A \bmod p) \le \operatorname{rank} A$ | none needed: a lower bound ([`rank`]) |
//! | [`guess::rref_guess`] | RREF guessed from stable images | none: the caller checks an identity ([`guess`]) |
//! | [`rref_modular`] | canonical RREF $R$ and pivot columns $P$ | [`pivot_solve`], else $dB = B_{:,P} N$ checked modulo $M > 2\beta$ ([`rref`]) |
//! | [`nullspace_modular`] | basis of $\{x : Ax = 0\}$ from the RREF | that of [`rref_modular`] |
//! | [`det_modular`] | $\det A$ | Hadamard bound ([`det`]) |
//! | [`charpoly_modular`] | $\det(xI - A)$, low degree first | principal-minor Hadamard bound ([`charpoly`]) |
//! | [`inverse_modular`] | $A^{-1}$ or `None` | $BN = dI$ checked modulo $M > 2\beta$ ([`inverse`]) |
//!
//! [`quadratic`] holds the determinant and characteristic polynomial over $\mathbb{Q}(\sqrt d)$
//! (images under $\sqrt d \mapsto \pm r$ modulo primes where $d$ is a square, the same
//! Hadamard-type certificates).
//!
//! [`direct`] holds the kernels that reduce the rational matrix itself modulo each prime
//! ([`qimage`]): determinant, characteristic polynomial, inverse, the full-rank test and the
//! cyclicity test of the minimal polynomial.
//!
//! These always take the multi-modular path; the size dispatch between them and the
//! fraction-free routines of [`crate::qkernels::fraction_free`] lives on the matrix side
//! (`crate::matrix::over_q`).
//!
//! Unlucky primes (lower rank or later pivots modulo $p$, singular modulo $p$ while $A$ is
//! not) are detected and discarded.
//!
//! All matrices are row-major slices; a slice whose length is not `m * n` (or `n * n`) is a
//! caller bug and panics.

pub mod charpoly;
pub mod crt;
pub mod det;
pub mod direct;
pub mod dixon;
pub(crate) mod guess;
pub mod inverse;
pub(crate) mod minpoly;
pub mod pivot_solve;
pub mod qimage;
pub mod quadratic;
pub(crate) mod rank;
pub mod rref;

use crate::field::Rational;
use crate::qkernels::gcd;
use crate::qkernels::intmat::{integer_rows, integer_scaled, scale_det, unscale_charpoly};
use crate::qkernels::prime;
use num_bigint::BigInt;
use num_traits::{One, Zero};

/// The integer matrix $DA$ ($D$ the row denominators, [`qimage::RatMat::row_dens`]) as
/// the RREF kernel sees it: its images are those of $A$ itself (same RREF modulo every
/// prime dividing no denominator, since $D$ is then a unit), its entries only enter the
/// certificate bound (issue 29: no reduction of $n \log_2 q$-bit entries per prime).
struct RatRows<'a> {
    rm: qimage::RatMat<'a>,
    abs: Vec<BigInt>,
}

impl<'a> RatRows<'a> {
    fn new(m: usize, n: usize, a: &'a [Rational]) -> Self {
        let rm = qimage::RatMat::new(m, n, a);
        let abs = rm.scaled_abs();
        RatRows { rm, abs }
    }
}

impl rref::RrefSource for RatRows<'_> {
    fn shape(&self) -> (usize, usize) {
        (self.rm.m, self.rm.n)
    }
    fn image(&self, pr: &prime::Prime) -> Option<Vec<u64>> {
        self.rm.image(pr)
    }
    fn abs_at(&self, i: usize, j: usize) -> BigInt {
        self.abs[i * self.rm.n + j].clone()
    }
    fn max_abs(&self) -> BigInt {
        self.abs.iter().max().cloned().unwrap_or_default()
    }
}

/// The certified RREF: [`pivot_solve::rref_pivot_solve`] (no rational reconstruction), or,
/// after an unlucky first prime, the reconstruction path [`rref::rref_int`].
fn certified_rref(m: usize, n: usize, a: &[Rational]) -> rref::IntRref {
    pivot_solve::rref_pivot_solve(m, n, a).unwrap_or_else(|| rref::rref_int(&RatRows::new(m, n, a)))
}

fn check_len(op: &str, len: usize, m: usize, n: usize) {
    assert_eq!(
        len,
        m * n,
        "{op}: slice of length {len} for a {m}x{n} matrix"
    );
}

/// [`rank_q`] by the multi-modular path, whatever the size.
///
/// # Panics
/// When `a.len() != m * n`.
pub fn rank_modular(m: usize, n: usize, a: &[Rational]) -> usize {
    check_len("rank_modular", a.len(), m, n);
    certified_rref(m, n, a).pivots.len()
}

/// [`rref_q`] by the multi-modular path, whatever the size.
///
/// # Panics
/// When `a.len() != m * n`.
pub fn rref_modular(m: usize, n: usize, a: &[Rational]) -> (Vec<Rational>, Vec<usize>) {
    check_len("rref_modular", a.len(), m, n);
    let res = certified_rref(m, n, a);
    let mut out = vec![Rational::zero(); m * n];
    for (x, nu) in out.iter_mut().zip(res.num) {
        if !nu.is_zero() {
            *x = gcd::fraction(nu, &res.den);
        }
    }
    (out, res.pivots)
}

/// [`nullspace_q`] by the multi-modular path, whatever the size.
///
/// # Panics
/// When `a.len() != m * n`.
pub fn nullspace_modular(m: usize, n: usize, a: &[Rational]) -> Vec<Vec<Rational>> {
    check_len("nullspace_modular", a.len(), m, n);
    let res = certified_rref(m, n, a);
    nullspace_from_integer_rref(n, &res.num, &res.den, &res.pivots)
}

/// The canonical null-space basis from an RREF given as `nums / den` (row-major, at least
/// the `pivots.len()` pivot rows, `n` columns).
pub fn nullspace_from_integer_rref(
    n: usize,
    nums: &[BigInt],
    den: &BigInt,
    pivots: &[usize],
) -> Vec<Vec<Rational>> {
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
                    v[c] = gcd::fraction(-x, den);
                }
            }
            v
        })
        .collect()
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
