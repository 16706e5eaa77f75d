//! $X = A^{-1} B$ for a nonsingular rational $A$ by Dixon's $p$-adic lifting (Dixon 1982,
//! "Exact solution of linear equations using p-adic expansions"), with output-sensitive
//! termination (rational reconstruction at growing step counts) as FLINT's
//! `fmpq_mat_solve_dixon` does.
//!
//! **Identity.** With $D = \operatorname{diag}(d_i)$, $d_i$ the lcm of the denominators of
//! row $i$ of $[A \mid B]$, the system is $A' X = B'$ over $\mathbb{Z}$ ($A' = DA$,
//! $B' = DB$). For one word prime $p$ with $\bar A'$ invertible modulo $p$ (then $A$ is
//! nonsingular) and $C = \bar A'^{-1}$, every step
//! $$\bar X_s = C R_s \bmod p, \qquad R_{s+1} = (R_s - A' \bar X_s) / p, \qquad R_0 = B'$$
//! is exact over $\mathbb{Z}$ ([`limbs`]) and keeps $A' X_s = B' - p^s R_s$ for
//! $X_s = \sum_{i<s} \bar X_i p^i$ ([`digits`]), so $X \equiv X_s \pmod{p^s}$.
//!
//! **Termination and certificate.** At growing step counts $s$ one entry of $X_s$ is
//! reconstructed as a fraction; when that succeeds, all entries are, over one common
//! denominator $\delta > 0$ ([`CommonDenominator`]): $N \equiv \delta X_s \pmod{p^s}$. Then
//! $A' N \equiv \delta A' X_s \equiv \delta B' \pmod{p^s}$, and the candidate $X = N/\delta$
//! is accepted on one of three proofs of $A' N = \delta B'$ over $\mathbb{Z}$:
//! - $R_s = 0$: $X_s$ itself is an integer solution ($\delta = 1$);
//! - $p^s > \beta = \max_i \sum_j |A'_{ij}| \cdot \max |N| + \delta \max |B'|$, which bounds
//!   $|A' N - \delta B'|$ (a multiple of $p^s$ below $p^s$ is zero);
//! - the product $A' N - \delta B'$ computed exactly, when that is cheaper than lifting on
//!   to the bound ($\max|N|$ has fewer limbs than the steps still missing).
//!
//! A wrong candidate (modulus still too small) is dropped and the lifting goes on. Once
//! $p^s$ exceeds $2H^2$ and $\beta$ for $H$ the Hadamard-type bound of every $|N|$ and
//! $\delta$ (Cramer's rule on $[A' \mid B']$), reconstruction returns the solution, so the
//! loop ends; past that many steps (a defect) the function gives up with `None`.
//!
//! Cost: one inverse modulo $p$ ($n^3$), then per step $n^2 k$ word products modulo $p$ and
//! $n^2 k$ products of a word by an entry of $A'$ (whose row lcm of $n$ denominators makes
//! it $n \log_2 q$ bits); the step count follows the size of the solution, not the
//! $n^2 \log_2 q$-bit bound of $\det A'$ that a multi-modular CRT solve lifts.

mod digits;
mod limbs;

use super::crt::{CommonDenominator, rational_reconstruct};
use super::inverse::inverse_mod_p;
use super::qimage::lcm_small;
use crate::field::Rational;
use crate::qkernels::gcd;
use crate::qkernels::prime::{PRIME_BITS, Prime, primes};
use digits::Digits;
use limbs::{LimbMat, Residual};
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

/// How many primes are tried for an invertible image before giving up (a nonsingular $A$
/// is singular modulo a random word prime with probability about $n / 2^{61}$).
const PRIME_TRIES: usize = 2;

/// $X = A^{-1} B$ (`a` is `n x n`, `b` is `n x k`, row-major, canonical fractions);
/// `None` when $A$ is singular modulo the primes tried (singular $A$ always gives `None`:
/// the caller decides with a certified method).
///
/// # Panics
/// When `a.len() != n * n` or `b.len() != n * k`.
pub fn solve_dixon(n: usize, k: usize, a: &[Rational], b: &[Rational]) -> Option<Vec<Rational>> {
    let (den, nums) = solve_dixon_int(n, k, a, b)?;
    Some(nums.into_iter().map(|x| gcd::fraction(x, &den)).collect())
}

/// [`solve_dixon`] before the division: $(\delta, N)$ with $\delta > 0$ and $X = N /
/// \delta$ (`N` row-major `n x k`), certified as in the module docs.
///
/// # Panics
/// When `a.len() != n * n` or `b.len() != n * k`.
pub fn solve_dixon_int(
    n: usize,
    k: usize,
    a: &[Rational],
    b: &[Rational],
) -> Option<(BigInt, Vec<BigInt>)> {
    assert_eq!(a.len(), n * n, "solve_dixon: A is not {n} x {n}");
    assert_eq!(b.len(), n * k, "solve_dixon: B is not {n} x {k}");
    if n == 0 {
        return Some((BigInt::one(), Vec::new()));
    }
    let (ai, bi) = scale_rows(n, k, a, b);
    let am = LimbMat::new(n, n, &ai);
    let (pr, c) = invertible_image(&am, n)?;
    if k == 0 {
        return Some((BigInt::one(), Vec::new()));
    }
    let bound = Bound::new(n, k, &ai, &bi);
    let mut r = Residual::new(&am, k, &bi);
    let mut digits = Digits::new(&pr, n * k);
    let mut next = 1;
    loop {
        let x = mul_mod(&pr, n, k, &c, &r.reduce(&pr));
        r.update(&am, &x, &pr);
        digits.push(&x);
        let s = digits.steps();
        if r.is_zero() {
            let nums = (0..n * k).map(|e| digits.value(e)).collect();
            return Some((BigInt::one(), nums));
        }
        if s < next {
            continue;
        }
        let last = s >= bound.max_steps;
        next = match attempt(&mut digits, &bound, &ai, &bi) {
            Attempt::Done(den, nums) => return Some((den, nums)),
            // past the proven bound: a defect, let the caller decide
            _ if last => return None,
            Attempt::LiftTo(t) => t,
            Attempt::Failed => s + (s / 4).max(1),
        }
        .clamp(s + 1, bound.max_steps);
    }
}

/// $A' = DA$ and $B' = DB$, row-major integers (module docs).
fn scale_rows(n: usize, k: usize, a: &[Rational], b: &[Rational]) -> (Vec<BigInt>, Vec<BigInt>) {
    let (mut ai, mut bi) = (Vec::with_capacity(n * n), Vec::with_capacity(n * k));
    for i in 0..n {
        let (ra, rb) = (&a[i * n..(i + 1) * n], &b[i * k..(i + 1) * k]);
        let d = ra
            .iter()
            .chain(rb)
            .fold(BigInt::one(), |l, x| lcm_small(l, x.denom()));
        let scale = |x: &Rational| {
            if x.numer().is_zero() {
                BigInt::zero()
            } else if x.denom().is_one() {
                x.numer() * &d
            } else {
                x.numer() * (&d / x.denom())
            }
        };
        ai.extend(ra.iter().map(scale));
        bi.extend(rb.iter().map(scale));
    }
    (ai, bi)
}

/// The first prime (of [`PRIME_TRIES`]) with $\bar A'$ invertible, and the inverse.
fn invertible_image(am: &LimbMat, n: usize) -> Option<(Prime, Vec<u64>)> {
    primes(0).take(PRIME_TRIES).find_map(|pr| {
        let mut img = am.reduce(&pr);
        inverse_mod_p(&pr, n, &mut img).then_some((pr, img))
    })
}

/// $C R \bmod p$ (`n x n` times `n x k`), with products summed in `u128` and reduced every
/// 15 terms ($15 p^2 < 2^{128}$ for $p < 2^{62}$).
fn mul_mod(pr: &Prime, n: usize, k: usize, c: &[u64], r: &[u64]) -> Vec<u64> {
    let p = pr.p as u128;
    let mut out = vec![0u64; n * k];
    for i in 0..n {
        let row = &c[i * n..(i + 1) * n];
        for (col, o) in out[i * k..(i + 1) * k].iter_mut().enumerate() {
            let mut acc = 0u128;
            for (t, (&cij, j)) in row.iter().zip(0..).enumerate() {
                acc += cij as u128 * r[j * k + col] as u128;
                if t % 15 == 14 {
                    acc %= p;
                }
            }
            *o = (acc % p) as u64;
        }
    }
    out
}

/// The data of the bound $\beta$ and of the step cap (module docs).
struct Bound {
    /// $\max_i \sum_j |A'_{ij}|$.
    row_sum: BigInt,
    /// $\max |B'_{ij}|$.
    max_b: BigInt,
    /// Steps after which reconstruction and the bound certificate must have succeeded.
    max_steps: usize,
}

impl Bound {
    fn new(n: usize, k: usize, ai: &[BigInt], bi: &[BigInt]) -> Self {
        let row_sum = (0..n)
            .map(|i| {
                ai[i * n..(i + 1) * n]
                    .iter()
                    .map(|x| x.abs())
                    .sum::<BigInt>()
            })
            .max()
            .unwrap_or_default();
        let max_b = bi.iter().map(|x| x.abs()).max().unwrap_or_default();
        // Hadamard: |N|, delta <= prod_i ||[A' | B']_i||_2 <= prod_i sqrt(n + k) 2^(bits_i)
        let half_log = 0.5 * ((n + k) as f64).log2();
        let h: f64 = (0..n)
            .map(|i| {
                let ra = ai[i * n..(i + 1) * n].iter();
                let bits = ra.chain(&bi[i * k..(i + 1) * k]).map(|x| x.bits()).max();
                bits.unwrap_or(0) as f64 + half_log
            })
            .sum();
        let beta = h + 1.0 + (&row_sum + &max_b).bits() as f64;
        let need = (2.0 * h + 1.0).max(beta);
        Bound {
            row_sum,
            max_b,
            max_steps: (need / PRIME_BITS).ceil() as usize + 2,
        }
    }

    /// $\log_2 \beta$ rounded up, for the candidate $(\delta, N)$.
    fn beta_bits(&self, den: &BigInt, max_n: &BigInt) -> u64 {
        (&self.row_sum * max_n + den * &self.max_b).bits() + 1
    }
}

/// What one reconstruction attempt gives.
enum Attempt {
    /// Certified $(\delta, N)$.
    Done(BigInt, Vec<BigInt>),
    /// A candidate that the bound certifies once the modulus reaches this many steps.
    LiftTo(usize),
    /// No candidate (or a wrong one).
    Failed,
}

/// Reconstruction at the current step count and the certificate of the module docs.
fn attempt(digits: &mut Digits, bound: &Bound, ai: &[BigInt], bi: &[BigInt]) -> Attempt {
    let m = digits.modulus();
    let rr = ((&m - 1u32) >> 1u32).sqrt();
    // one entry first: most attempts fail here, at the cost of one reconstruction
    if rational_reconstruct(&digits.value(0), &m, &rr, &rr).is_none() {
        return Attempt::Failed;
    }
    let entries = bi.len();
    let us: Vec<BigInt> = (0..entries).map(|e| digits.value(e)).collect();
    let Some(cd) = CommonDenominator::reconstruct_mod(&m, us.into_iter()) else {
        return Attempt::Failed;
    };
    let max_n = cd.nums.iter().map(|x| x.abs()).max().unwrap_or_default();
    let need = bound.beta_bits(&cd.den, &max_n);
    if m.bits() > need {
        return Attempt::Done(cd.den, cd.nums);
    }
    // p > 2^61: p^t > 2^need for t = ceil(need / 61)
    let steps_missing = ((need as f64 / PRIME_BITS).ceil() as usize).saturating_sub(digits.steps());
    let n_limbs = max_n.bits().div_ceil(64) as usize;
    if n_limbs <= steps_missing {
        return if verify(ai, bi, &cd.den, &cd.nums) {
            Attempt::Done(cd.den, cd.nums)
        } else {
            Attempt::Failed
        };
    }
    Attempt::LiftTo(digits.steps() + steps_missing)
}

/// $A' N = \delta B'$ exactly ($A'$ is `n x n`, `N` and $B'$ are `n x k`, $n \ge 1$).
fn verify(ai: &[BigInt], bi: &[BigInt], den: &BigInt, nums: &[BigInt]) -> bool {
    let n = ai.len().isqrt();
    let k = bi.len() / n;
    (0..n).all(|i| {
        (0..k).all(|c| {
            let lhs: BigInt = (0..n)
                .filter(|&j| !ai[i * n + j].is_zero() && !nums[j * k + c].is_zero())
                .map(|j| &ai[i * n + j] * &nums[j * k + c])
                .sum();
            lhs == den * &bi[i * k + c]
        })
    })
}
