//! Integer matrices prepared from rational input, with fast reduction modulo word primes.
//!
//! Rational input is turned into an integer matrix $B$ either row by row
//! ($A_{i,:} = s_i B_{i,:}$ with $s_i = c_i / d_i$: $d_i$ the row's denominator lcm and $c_i$
//! the content of $d_i A_{i,:}$; rank, RREF and null space are invariant, the determinant
//! scales by $\prod s_i$) or globally ($A = B / s$; the characteristic polynomial scales
//! coefficient-wise).

use super::gcd;
use super::prime::Prime;
use crate::field::Rational;
use num_bigint::{BigInt, Sign};
use num_integer::Integer;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// A dense row-major integer matrix.
#[derive(Clone, Debug)]
pub struct IntMat {
    pub m: usize,
    pub n: usize,
    pub entries: Vec<BigInt>,
    /// `Some` when every entry fits in an `i64` (the common, fast case).
    small: Option<Vec<i64>>,
}

impl IntMat {
    /// Wraps `entries` (row-major, `m * n` of them).
    pub fn new(m: usize, n: usize, entries: Vec<BigInt>) -> Self {
        assert_eq!(entries.len(), m * n, "IntMat: entries do not match shape");
        let small: Option<Vec<i64>> = entries.iter().map(|x| x.to_i64()).collect();
        IntMat {
            m,
            n,
            entries,
            small,
        }
    }

    /// Entry `(i, j)`.
    pub fn at(&self, i: usize, j: usize) -> &BigInt {
        &self.entries[i * self.n + j]
    }

    /// The matrix modulo `pr`, row-major residues in $[0, p)$.
    pub fn reduce(&self, pr: &Prime) -> Vec<u64> {
        let p = pr.p;
        match &self.small {
            Some(s) => s
                .iter()
                .map(|&x| {
                    let u = x.unsigned_abs();
                    let r = if u < p { u } else { u % p };
                    if x < 0 { pr.neg(r) } else { r }
                })
                .collect(),
            None => self
                .entries
                .iter()
                .map(|x| {
                    let (s, l) = x.to_u64_digits();
                    pr.reduce_limbs(s == Sign::Minus, &l)
                })
                .collect(),
        }
    }

    /// $\max_{ij} |b_{ij}|$ (0 for an empty matrix).
    pub fn max_abs(&self) -> BigInt {
        self.entries
            .iter()
            .map(|x| x.abs())
            .max()
            .unwrap_or_else(BigInt::zero)
    }

    /// $\log_2$ of the Euclidean norm of each row (`-inf` for a zero row), rounded up by a
    /// safety margin so that $2^{\text{result}}$ bounds the true norm.
    pub fn row_norm_log2(&self) -> Vec<f64> {
        self.norms_log2::<true>()
    }

    /// As [`IntMat::row_norm_log2`] for the columns.
    pub fn col_norm_log2(&self) -> Vec<f64> {
        self.norms_log2::<false>()
    }

    /// [`IntMat::row_norm_log2`] (`ROWS`) or [`IntMat::col_norm_log2`]: line `o`, entry `k`
    /// is `(o, k)` for rows and `(k, o)` for columns.
    fn norms_log2<const ROWS: bool>(&self) -> Vec<f64> {
        let (lines, len) = if ROWS {
            (self.m, self.n)
        } else {
            (self.n, self.m)
        };
        let at = |o: usize, k: usize| if ROWS { (o, k) } else { (k, o) };
        if let Some(s) = &self.small
            && let Some(v) = (0..lines)
                .map(|o| {
                    norm_log2_small((0..len).map(|k| {
                        let (i, j) = at(o, k);
                        s[i * self.n + j]
                    }))
                })
                .collect()
        {
            return v;
        }
        (0..lines)
            .map(|o| {
                norm_log2((0..len).map(|k| {
                    let (i, j) = at(o, k);
                    self.at(i, j)
                }))
            })
            .collect()
    }
}

/// [`norm_log2`] for machine integers: the sum of squares is exact in `u128` up to $2^{64}$
/// terms.
fn norm_log2_small(mut xs: impl Iterator<Item = i64>) -> Option<f64> {
    let s = xs.try_fold(0u128, |s, x| {
        s.checked_add((x.unsigned_abs() as u128).pow(2))
    })?;
    if s == 0 {
        return Some(f64::NEG_INFINITY);
    }
    Some(log2_upper(&BigInt::from(s)) / 2.0)
}

/// Upper bound of $\log_2 \sqrt{\sum x^2}$; `-inf` when all are zero.
fn norm_log2<'a>(xs: impl Iterator<Item = &'a BigInt>) -> f64 {
    let s: BigInt = xs.map(|x| x * x).sum();
    if s.is_zero() {
        return f64::NEG_INFINITY;
    }
    log2_upper(&s) / 2.0
}

/// An upper bound of $\log_2 x$ for $x > 0$ (within $10^{-9}$ of the truth).
pub fn log2_upper(x: &BigInt) -> f64 {
    let bits = x.bits();
    let shift = bits.saturating_sub(60);
    let top = (x >> shift).to_f64().unwrap_or(f64::MAX);
    // top has at most 60 bits, so it is exact; log2 is within a few ulps
    top.log2() + shift as f64 + 1e-9
}

/// Row-wise integer form: `A[i,:] = scale[i] * B[i,:]`, each row of `B` primitive
/// (content 1) or zero. A zero row gets scale 1.
pub fn integer_rows(m: usize, n: usize, a: &[Rational]) -> (IntMat, Vec<Rational>) {
    assert_eq!(a.len(), m * n, "matrix slice length must be m * n");
    if let Some(res) = small_integer_rows(m, n, a) {
        return res;
    }
    let mut entries = Vec::with_capacity(m * n);
    let mut scales = Vec::with_capacity(m);
    for i in 0..m {
        let row = &a[i * n..(i + 1) * n];
        let den = row.iter().fold(BigInt::one(), |l, x| l.lcm(x.denom()));
        let ints: Vec<BigInt> = row.iter().map(|x| x.numer() * (&den / x.denom())).collect();
        let content = ints.iter().fold(BigInt::zero(), |g, x| g.gcd(x));
        if content.is_zero() {
            entries.extend(ints);
            scales.push(Rational::one());
        } else {
            entries.extend(ints.into_iter().map(|x| x / &content));
            scales.push(Rational::new(content, den));
        }
    }
    (IntMat::new(m, n, entries), scales)
}

/// [`integer_rows`] when every entry is an integer fitting an `i64` (no big-integer gcds).
fn small_integer_rows(m: usize, n: usize, a: &[Rational]) -> Option<(IntMat, Vec<Rational>)> {
    let small: Vec<i64> = a
        .iter()
        .map(|x| {
            if x.is_integer() {
                x.numer().to_i64()
            } else {
                None
            }
        })
        .collect::<Option<_>>()?;
    let mut entries = Vec::with_capacity(m * n);
    let mut scales = Vec::with_capacity(m);
    for i in 0..m {
        let row = &small[i * n..(i + 1) * n];
        let g = row.iter().fold(0u64, |g, &x| g.gcd(&x.unsigned_abs()));
        if g <= 1 {
            entries.extend(row.iter().map(|&x| BigInt::from(x)));
            scales.push(Rational::one());
        } else {
            // g divides every |x| <= 2^63, so x / g is exact and fits
            entries.extend(row.iter().map(|&x| BigInt::from(x / g as i64)));
            scales.push(Rational::from_integer(g.into()));
        }
    }
    Some((IntMat::new(m, n, entries), scales))
}

/// Global integer form: `A = B / s` with `s` the lcm of all denominators.
pub fn integer_scaled(m: usize, n: usize, a: &[Rational]) -> (IntMat, BigInt) {
    assert_eq!(a.len(), m * n, "matrix slice length must be m * n");
    let s = a.iter().fold(BigInt::one(), |l, x| l.lcm(x.denom()));
    let entries = a.iter().map(|x| x.numer() * (&s / x.denom())).collect();
    (IntMat::new(m, n, entries), s)
}

/// How many primes of [`super::prime::PRIME_BITS`] bits give a product above $2^{bits}$.
pub fn primes_for_bits(bits: f64) -> usize {
    if bits <= 0.0 {
        1
    } else {
        (bits / super::prime::PRIME_BITS).floor() as usize + 1
    }
}

/// $d \prod_i s_i$ as a canonical fraction (one gcd, not one per row).
pub fn scale_det(d: BigInt, scales: &[Rational]) -> Rational {
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

/// Coefficients of $\det(xI - B/s)$ from those of $\det(xI - B)$: $c_k / s^{n-k}$.
pub fn unscale_charpoly(c: Vec<BigInt>, s: &BigInt) -> Vec<Rational> {
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

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> Rational {
        Rational::new(n.into(), d.into())
    }

    #[test]
    fn row_and_global_scaling() {
        let a = vec![q(1, 2), q(3, 4), q(0, 1), q(0, 1), q(6, 1), q(-9, 1)];
        let (b, s) = integer_rows(3, 2, &a);
        assert_eq!(b.entries, [2, 3, 0, 0, 2, -3].map(BigInt::from));
        assert_eq!(s, vec![q(1, 4), q(1, 1), q(3, 1)]);
        let (g, s) = integer_scaled(3, 2, &a);
        assert_eq!(s, BigInt::from(4));
        assert_eq!(g.entries, [2, 3, 0, 0, 24, -36].map(BigInt::from));
        let pr = super::super::prime::nth_prime(0);
        assert_eq!(b.reduce(&pr)[5], pr.p - 3);
        let big = IntMat::new(1, 1, vec![-(BigInt::one() << 200u32)]);
        let r = big.reduce(&pr)[0];
        assert_eq!(pr.add(r, pr.pow(2, 200)), 0);
        assert!(log2_upper(&BigInt::from(1024)) >= 10.0);
        assert!(log2_upper(&BigInt::from(1024)) < 10.0 + 1e-6);
    }
}
