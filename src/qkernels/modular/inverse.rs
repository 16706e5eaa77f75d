//! Multi-modular inverse of an integer matrix, with a certificate.
//!
//! $B^{-1} \bmod p$ by Gauss–Jordan elimination in place for a growing set of primes; the
//! images are combined by CRT and rational reconstruction over one common denominator,
//! $B^{-1} = N / d$, as soon as a probe entry is stable.
//!
//! **Certificate.** $B N \equiv d I \pmod M$ holds by construction; every entry of
//! $B N - d I$ is at most $\beta = \max_i \sum_k |b_{ik}| \cdot \max|N| + d$, so $M > 2\beta$
//! proves $B N = d I$ over $\mathbb{Z}$, i.e. $N / d$ is the inverse. Singularity is decided
//! by the certified determinant.

use super::crt::{CommonDenominator, Crt};
use super::det::det_int;
use super::rref::{rows_mut, swap_rows};
use crate::qkernels::intmat::IntMat;
use crate::qkernels::prime::{Prime, primes};
use num_bigint::BigInt;
use num_traits::{Signed, Zero};

/// Inverse of the `n x n` row-major `a` over $\mathbb{Z}/p$, in place; `false` when
/// singular modulo `p` (then `a` is garbage).
pub fn inverse_mod_p(pr: &Prime, n: usize, a: &mut [u64]) -> bool {
    // Gauss-Jordan with the identity kept implicitly in the eliminated columns
    let mut perm: Vec<usize> = (0..n).collect();
    for c in 0..n {
        let Some(i) = (c..n).find(|&i| a[i * n + c] != 0) else {
            return false;
        };
        swap_rows(a, n, i, c);
        perm.swap(i, c);
        let inv = pr.inv(a[c * n + c]).expect("nonzero pivot");
        a[c * n + c] = 1;
        pr.scale(&mut a[c * n..(c + 1) * n], inv);
        for i in 0..n {
            if i == c {
                continue;
            }
            let f = a[i * n + c];
            if f != 0 {
                a[i * n + c] = 0;
                let (y, x) = rows_mut(a, n, i, c);
                pr.axpy_neg(y, x, f);
            }
        }
    }
    // rows were permuted: the result is inv(P B) = inv(B) P^T, so undo on the columns
    let mut out = vec![0u64; n * n];
    for r in 0..n {
        for (j, &pj) in perm.iter().enumerate() {
            out[r * n + pj] = a[r * n + j];
        }
    }
    a.copy_from_slice(&out);
    true
}

/// The certified inverse `num / den` of a square integer matrix, or `None` when singular.
pub fn inverse_int(b: &IntMat) -> Option<(Vec<BigInt>, BigInt)> {
    assert_eq!(b.m, b.n, "inverse_int: square matrix required");
    let n = b.n;
    let max_row: BigInt = (0..n)
        .map(|i| (0..n).map(|j| b.at(i, j).abs()).sum::<BigInt>())
        .max()
        .unwrap_or_default();
    let mut used: Vec<Prime> = Vec::new();
    let mut images: Vec<Vec<u64>> = Vec::new();
    let mut last_probe = None;
    let mut checked_det = false;
    let total = n * n;
    for pr in primes(0) {
        let mut a = b.reduce(&pr);
        if !inverse_mod_p(&pr, n, &mut a) {
            if !checked_det {
                if det_int(b).is_zero() {
                    return None;
                }
                checked_det = true;
            }
            continue; // unlucky prime
        }
        images.push(a);
        used.push(pr);
        let crt = Crt::new(&used);
        let probe_idx = [total.saturating_sub(1), total / 2, 0];
        let probe = if total == 0 {
            None
        } else {
            let us = probe_idx.iter().map(|&i| crt.lift_nonneg(|t| images[t][i]));
            CommonDenominator::reconstruct(&crt, us).map(|cd| (cd.nums, cd.den))
        };
        let stable = total == 0 || (probe.is_some() && probe == last_probe);
        last_probe = probe;
        if !stable {
            continue;
        }
        let us = (0..total).map(|i| crt.lift_nonneg(|t| images[t][i]));
        let Some(cd) = CommonDenominator::reconstruct(&crt, us) else {
            continue;
        };
        if crt.primes().iter().any(|p| (&cd.den % p.p).is_zero()) {
            continue;
        }
        let max_n = cd.nums.iter().map(|x| x.abs()).max().unwrap_or_default();
        let beta = &max_row * max_n + &cd.den;
        if *crt.modulus() > beta * 2u32 {
            return Some((cd.nums, cd.den));
        }
    }
    unreachable!("the prime sequence is endless")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn small_inverses() {
        // [[2, 1], [1, 1]]^-1 = [[1, -1], [-1, 2]]
        let b = IntMat::new(2, 2, [2, 1, 1, 1].map(BigInt::from).to_vec());
        let (num, den) = inverse_int(&b).unwrap();
        assert_eq!(den, BigInt::from(1));
        assert_eq!(num, [1, -1, -1, 2].map(BigInt::from).to_vec());
        // needs a row swap: [[0, 2], [1, 0]]^-1 = [[0, 1], [1/2, 0]]
        let b = IntMat::new(2, 2, [0, 2, 1, 0].map(BigInt::from).to_vec());
        let (num, den) = inverse_int(&b).unwrap();
        assert_eq!(den, BigInt::from(2));
        assert_eq!(num, [0, 2, 1, 0].map(BigInt::from).to_vec());
        let b = IntMat::new(2, 2, [1, 2, 2, 4].map(BigInt::from).to_vec());
        assert!(inverse_int(&b).is_none());
    }
}
