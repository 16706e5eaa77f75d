//! Images of a rational matrix modulo word primes, without clearing denominators first.
//!
//! For a prime $p$ that divides no denominator, every entry $a_{ij} = u_{ij}/v_{ij}$ lies in
//! $\mathbb{Z}_{(p)}$ and $\bar a_{ij} = u_{ij} v_{ij}^{-1} \bmod p$. The inverses of one
//! image cost one modular inversion in all (Montgomery's batch trick: prefix products, one
//! inverse, back-substitution), so an image costs $O(mn)$ word operations whatever the
//! size of the integer matrix $D A$ that row-wise denominator clearing would produce
//! ($n \log_2 10^6$ bits per entry on a matrix of fractions $p/q$ with $q \le 10^6$).
//!
//! Every determinant, rank, RREF, inverse or characteristic polynomial modulo $p$ is then
//! computed on $\bar A$ itself; [`RatMat::row_dens`] and [`RatMat::row_norm_log2`] give the
//! integer structure ($d_i A_{i,:} \in \mathbb{Z}^n$, $\|A_{i,:}\|_2$) that the certificates
//! need.

use crate::field::Rational;
use crate::qkernels::prime::Prime;
use num_bigint::{BigInt, Sign};
use num_integer::Integer;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// A rational matrix prepared for fast reduction modulo word primes.
#[derive(Clone, Debug)]
pub struct RatMat<'a> {
    pub m: usize,
    pub n: usize,
    pub a: &'a [Rational],
    /// `(numerator, denominator)` when both fit machine words, per entry.
    small: Option<Vec<(i64, u64)>>,
    /// Does any entry have a denominator other than 1?
    has_dens: bool,
}

fn limbs_mod(pr: &Prime, v: &BigInt) -> u64 {
    let (s, l) = v.to_u64_digits();
    pr.reduce_limbs(s == Sign::Minus, &l)
}

impl<'a> RatMat<'a> {
    /// Wraps the `m x n` row-major `a`.
    ///
    /// # Panics
    /// When `a.len() != m * n`.
    pub fn new(m: usize, n: usize, a: &'a [Rational]) -> Self {
        assert_eq!(
            a.len(),
            m * n,
            "RatMat: slice of length {} for {m}x{n}",
            a.len()
        );
        let small = a
            .iter()
            .map(|x| Some((x.numer().to_i64()?, x.denom().to_u64()?)))
            .collect();
        let has_dens = a.iter().any(|x| !x.denom().is_one());
        RatMat {
            m,
            n,
            a,
            small,
            has_dens,
        }
    }

    /// $\bar A \bmod p$ row-major; `None` when `p` divides a denominator.
    pub fn image(&self, pr: &Prime) -> Option<Vec<u64>> {
        let p = pr.p;
        let (mut nums, dens): (Vec<u64>, Vec<u64>) = match &self.small {
            Some(s) => s
                .iter()
                .map(|&(u, v)| {
                    let r = u.unsigned_abs() % p;
                    (if u < 0 { pr.neg(r) } else { r }, v % p)
                })
                .unzip(),
            None => self
                .a
                .iter()
                .map(|x| (limbs_mod(pr, x.numer()), limbs_mod(pr, x.denom())))
                .unzip(),
        };
        if !self.has_dens {
            return Some(nums);
        }
        // batch inversion: prefix[i] = d_0 ... d_{i-1}
        let mut prefix = Vec::with_capacity(dens.len());
        let mut acc = 1u64;
        for &d in &dens {
            prefix.push(acc);
            if d != 1 {
                acc = pr.mul(acc, d);
            }
        }
        let mut inv = pr.inv(acc)?; // None: p divides a denominator
        for i in (0..dens.len()).rev() {
            if dens[i] == 1 {
                continue;
            }
            // inv = (d_0 ... d_i)^{-1}; d_i^{-1} = inv * prefix[i]
            let di = pr.mul(inv, prefix[i]);
            inv = pr.mul(inv, dens[i]);
            nums[i] = pr.mul(nums[i], di);
        }
        Some(nums)
    }

    /// $d_i$: the lcm of the denominators of row `i` ($d_i A_{i,:}$ is integral).
    pub fn row_dens(&self) -> Vec<BigInt> {
        (0..self.m)
            .map(|i| {
                self.a[i * self.n..(i + 1) * self.n]
                    .iter()
                    .fold(BigInt::one(), |l, x| lcm_small(l, x.denom()))
            })
            .collect()
    }

    /// $|d_i a_{ij}|$ row-major: the integer matrix $DA$ of [`RatMat::row_dens`], in
    /// absolute value (what the certificates bound).
    pub fn scaled_abs(&self) -> Vec<BigInt> {
        let dens = self.row_dens();
        (0..self.m * self.n)
            .map(|t| {
                let x = &self.a[t];
                let d = &dens[t / self.n];
                let s = if x.denom().is_one() {
                    d.clone()
                } else {
                    d / x.denom()
                };
                x.numer().abs() * s
            })
            .collect()
    }

    /// Upper bounds of $\log_2 \|A_{i,:}\|_2$ per row (`-inf` for a zero row), within a
    /// relative $10^{-9}$ above the truth.
    pub fn row_norm_log2(&self) -> Vec<f64> {
        (0..self.m)
            .map(|i| norm_log2(&self.a[i * self.n..(i + 1) * self.n]))
            .collect()
    }

    /// Upper bounds of $\log_2 \|A_{:,j}\|_2$ per column.
    pub fn col_norm_log2(&self) -> Vec<f64> {
        (0..self.n)
            .map(|j| {
                let col: Vec<Rational> = (0..self.m)
                    .map(|i| self.a[i * self.n + j].clone())
                    .collect();
                norm_log2(&col)
            })
            .collect()
    }
}

/// $\operatorname{lcm}(l, d)$ for $d > 0$, with the gcd taken on $(d, l \bmod d)$ (words
/// when $d$ fits one): a row lcm grows to $n \log_2 q$ bits while each $d \le q$ is small,
/// and a binary gcd on the long operand would shift it bit by bit.
pub(crate) fn lcm_small(l: BigInt, d: &BigInt) -> BigInt {
    if d.is_one() {
        return l;
    }
    let r = &l % d;
    if r.is_zero() {
        return l;
    }
    let g = match (d.to_u64(), r.to_u64()) {
        (Some(x), Some(y)) => BigInt::from(x.gcd(&y)),
        _ => d.gcd(&r),
    };
    l * (d / g)
}

/// $\log_2$ of a positive integer rounded up (within $10^{-9}$), `-inf` for zero.
pub fn log2_int(x: &BigInt) -> f64 {
    if x.is_zero() {
        return f64::NEG_INFINITY;
    }
    crate::qkernels::intmat::log2_upper(&x.abs())
}

/// An upper bound of $\log_2 \sqrt{\sum x_j^2}$ for rationals $x_j$.
fn norm_log2(xs: &[Rational]) -> f64 {
    // |u/v| <= 2^(log2|u| - log2 v + eps): sum in floating point with a margin
    let logs: Vec<f64> = xs
        .iter()
        .filter(|x| !x.numer().is_zero())
        .map(|x| log2_int(x.numer()) - lower_log2(x.denom()))
        .collect();
    let Some(top) = logs.iter().cloned().reduce(f64::max) else {
        return f64::NEG_INFINITY;
    };
    let s: f64 = logs.iter().map(|l| (2.0 * (l - top)).exp2()).sum();
    top + s.log2() / 2.0 + 1e-6
}

/// A lower bound of $\log_2 v$ for $v \ge 1$.
fn lower_log2(v: &BigInt) -> f64 {
    let bits = v.bits();
    let shift = bits.saturating_sub(60);
    let top = (v >> shift).to_f64().unwrap_or(1.0);
    (top.log2() + shift as f64 - 1e-9).max(0.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::qkernels::modular::rank::reduce_rational;
    use crate::qkernels::prime::nth_prime;

    fn q(a: i64, b: i64) -> Rational {
        Rational::new(a.into(), b.into())
    }

    #[test]
    fn images_match_entrywise_reduction() {
        let big = Rational::new(BigInt::from(3) << 100u32, (BigInt::from(7) << 70u32) + 1);
        let a = vec![q(1, 2), q(-3, 4), q(0, 1), q(5, 1), big, q(-7, 999_983)];
        let pr = nth_prime(2);
        for rm in [RatMat::new(2, 3, &a), RatMat::new(2, 2, &a[..4])] {
            let want: Vec<u64> =
                rm.a.iter()
                    .map(|x| reduce_rational(&pr, x).unwrap())
                    .collect();
            assert_eq!(rm.image(&pr).unwrap(), want);
        }
        let bad = vec![q(1, 1), Rational::new(1.into(), BigInt::from(pr.p))];
        assert_eq!(RatMat::new(1, 2, &bad).image(&pr), None);
        let rm = RatMat::new(2, 3, &a);
        assert_eq!(rm.row_dens()[0], BigInt::from(4));
        let l = rm.row_norm_log2();
        let exact0 = (0.25f64 + 9.0 / 16.0).sqrt().log2();
        assert!(l[0] >= exact0 && l[0] < exact0 + 1e-5);
        assert_eq!(
            RatMat::new(1, 1, &[q(0, 1)]).row_norm_log2()[0],
            f64::NEG_INFINITY
        );
    }
}
