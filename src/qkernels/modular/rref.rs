//! Multi-modular reduced row echelon form of an integer matrix, with a certificate.
//!
//! For each prime $p$ the RREF $R_p$ of $B \bmod p$ is computed by Gauss–Jordan
//! elimination. Primes whose pivot profile is worse than the best seen (smaller rank, or
//! same rank and lexicographically later pivots) are *unlucky* and discarded: the rank of
//! every prefix $B_{:,0..j}$ can only drop modulo $p$. The images on the best profile are
//! combined by CRT and rational reconstruction over one common denominator $d$, giving
//! $R = N / d$.
//!
//! **Certificate.** $N \equiv d R_p$ and $B \equiv B_{:,P} R_p \pmod p$ for every prime
//! used, so $d B - B_{:,P} N \equiv 0 \pmod M$. Every entry of the left side is at most
//! $\beta = d \max|b_{ij}| + \max_i \sum_k |b_{i,P_k}| \cdot \max(d, \max|N|)$ in absolute
//! value; once $M > 2\beta$ the identity $d B = B_{:,P} N$ holds over $\mathbb{Z}$, so the
//! row space of $B$ lies in that of $R$. Since $\operatorname{rank}(B \bmod p) = r$ proves
//! $\operatorname{rank} B \ge r$, both row spaces are equal and $R$, which is in reduced
//! echelon form by construction, is *the* RREF of $B$.

use super::crt::{CommonDenominator, Crt};
use crate::qkernels::intmat::IntMat;
use crate::qkernels::prime::{Prime, primes};
use num_bigint::BigInt;
use num_traits::{Signed, Zero};

/// Borrow row `i` mutably and row `k` immutably (`i != k`) of a row-major matrix.
#[inline]
pub(crate) fn rows_mut(a: &mut [u64], n: usize, i: usize, k: usize) -> (&mut [u64], &[u64]) {
    debug_assert_ne!(i, k);
    if i < k {
        let (lo, hi) = a.split_at_mut(k * n);
        (&mut lo[i * n..(i + 1) * n], &hi[..n])
    } else {
        let (lo, hi) = a.split_at_mut(i * n);
        (&mut hi[..n], &lo[k * n..(k + 1) * n])
    }
}

/// Swap rows `i` and `k` of a row-major matrix with `n` columns.
#[inline]
pub(crate) fn swap_rows(a: &mut [u64], n: usize, i: usize, k: usize) {
    if i != k {
        let (i, k) = (i.min(k), i.max(k));
        let (lo, hi) = a.split_at_mut(k * n);
        lo[i * n..(i + 1) * n].swap_with_slice(&mut hi[..n]);
    }
}

/// RREF of the `m x n` row-major matrix `a` over $\mathbb{Z}/p$, in place; returns the
/// pivot columns. Rows `0..r` hold the nonzero rows, the rest become zero.
pub fn rref_mod_p(pr: &Prime, m: usize, n: usize, a: &mut [u64]) -> Vec<usize> {
    let mut pivots = Vec::new();
    let mut r = 0;
    for c in 0..n {
        if r == m {
            break;
        }
        let Some(i) = (r..m).find(|&i| a[i * n + c] != 0) else {
            continue;
        };
        swap_rows(a, n, i, r);
        let inv = pr.inv(a[r * n + c]).expect("nonzero pivot");
        pr.scale(&mut a[r * n + c..(r + 1) * n], inv);
        for i in r + 1..m {
            let f = a[i * n + c];
            if f != 0 {
                let (y, x) = rows_mut(a, n, i, r);
                pr.axpy_neg(&mut y[c..], &x[c..], f);
            }
        }
        pivots.push(c);
        r += 1;
    }
    // back substitution, bottom pivot first, touching only columns right of the pivot
    for k in (0..r).rev() {
        let c = pivots[k];
        for i in 0..k {
            let f = a[i * n + c];
            if f != 0 {
                let (y, x) = rows_mut(a, n, i, k);
                pr.axpy_neg(&mut y[c..], &x[c..], f);
            }
        }
    }
    pivots
}

/// The certified RREF of an integer matrix: `R = num / den` on its first `r` rows.
#[derive(Clone, Debug)]
pub struct IntRref {
    pub pivots: Vec<usize>,
    pub den: BigInt,
    /// `r x n` row-major numerators (pivot entries equal `den`).
    pub num: Vec<BigInt>,
}

/// Is the pivot profile `a` better (rank higher, or equal rank with earlier pivots) than `b`?
fn better(a: &[usize], b: &[usize]) -> bool {
    a.len() > b.len() || (a.len() == b.len() && a < b)
}

/// The free-column entries of the RREF modulo each prime on the best pivot profile seen so
/// far: a prime with a worse profile is unlucky and discarded, a better profile drops the
/// earlier images. Shared by [`rref_int`] and [`super::guess::rref_guess`].
#[derive(Default)]
pub(super) struct ProfileImages {
    best: Option<Vec<usize>>,
    /// The non-pivot columns of the best profile.
    pub free: Vec<usize>,
    /// The primes of `images`.
    pub used: Vec<Prime>,
    /// `images[t][k * free.len() + f]`: free-column entries of row `k` modulo `used[t]`.
    pub images: Vec<Vec<u64>>,
}

impl ProfileImages {
    /// Records the RREF `red` (row-major, `n` columns, pivot columns `piv`) modulo `pr`:
    /// `None` when the prime is unlucky, else `Some(restarted)`, `true` when `piv` became
    /// the best profile and the images of earlier primes were dropped.
    pub(super) fn push(
        &mut self,
        pr: Prime,
        piv: Vec<usize>,
        red: &[u64],
        n: usize,
    ) -> Option<bool> {
        let restarted = match &self.best {
            Some(bp) if *bp == piv => false,
            Some(bp) if !better(&piv, bp) => return None,
            _ => {
                self.free = (0..n).filter(|c| !piv.contains(c)).collect();
                self.best = Some(piv);
                self.used.clear();
                self.images.clear();
                true
            }
        };
        let r = self.pivots().len();
        let free = &self.free;
        let img: Vec<u64> = (0..r)
            .flat_map(|k| free.iter().map(move |&f| (k, f)))
            .map(|(k, f)| red[k * n + f])
            .collect();
        self.images.push(img);
        self.used.push(pr);
        Some(restarted)
    }
    /// The best pivot profile (empty before the first prime).
    pub(super) fn pivots(&self) -> &[usize] {
        self.best.as_deref().unwrap_or_default()
    }
}

/// An integer matrix $B$ as the RREF kernel sees it: its images modulo primes (of $B$ or of
/// a matrix with the same RREF modulo that prime) and the sizes its certificate bounds.
pub trait RrefSource {
    /// `(m, n)`.
    fn shape(&self) -> (usize, usize);
    /// A row-major `m x n` matrix over $\mathbb{Z}/p$ with the RREF of $B \bmod p$ (`None`:
    /// skip the prime).
    fn image(&self, pr: &Prime) -> Option<Vec<u64>>;
    /// $|b_{ij}|$.
    fn abs_at(&self, i: usize, j: usize) -> BigInt;
    /// $\max_{ij} |b_{ij}|$.
    fn max_abs(&self) -> BigInt;
}

impl RrefSource for IntMat {
    fn shape(&self) -> (usize, usize) {
        (self.m, self.n)
    }
    fn image(&self, pr: &Prime) -> Option<Vec<u64>> {
        Some(self.reduce(pr))
    }
    fn abs_at(&self, i: usize, j: usize) -> BigInt {
        self.at(i, j).abs()
    }
    fn max_abs(&self) -> BigInt {
        IntMat::max_abs(self)
    }
}

/// Certified RREF of `b` by the multi-modular method (see the module docs).
pub fn rref_int<S: RrefSource>(b: &S) -> IntRref {
    let (m, n) = b.shape();
    let mut st = ProfileImages::default();
    let mut last_probe: Option<(Vec<BigInt>, BigInt)> = None;
    let max_a = b.max_abs();
    let mut next_check = 1usize;
    for pr in primes(0) {
        let Some(mut a) = b.image(&pr) else {
            continue;
        };
        let piv = rref_mod_p(&pr, m, n, &mut a);
        match st.push(pr, piv, &a, n) {
            None => continue,
            Some(true) => (last_probe, next_check) = (None, 1),
            Some(false) => {}
        }
        // checkpoints at geometrically spaced prime counts: a probe costs O(k^2) for k
        // primes, so probing after every prime would cost O(k^3)
        if st.used.len() < next_check {
            continue;
        }
        next_check = st.used.len() + (st.used.len() / 8).max(1);
        let (piv, free, used, images) = (st.pivots(), &st.free, &st.used, &st.images);
        let r = piv.len();
        let crt = Crt::new(used);
        let total = r * free.len();
        // probe a few entries for stability before the full reconstruction
        let probe_idx: Vec<usize> = if total == 0 {
            vec![]
        } else {
            vec![total - 1, total / 2, 0]
        };
        let probe = probe_reconstruct(&crt, &probe_idx, images);
        let stable = total == 0 || (probe.is_some() && probe == last_probe);
        // entries whose reconstruction survives one more prime have (very likely) been found
        last_probe = probe;
        if !stable {
            continue;
        }
        if let Some(res) = try_certify(b, piv, free, &crt, images, &max_a) {
            return res;
        }
    }
    unreachable!("the prime sequence is endless")
}

/// Common-denominator reconstruction of the probe entries, if it exists.
fn probe_reconstruct(
    crt: &Crt,
    idx: &[usize],
    images: &[Vec<u64>],
) -> Option<(Vec<BigInt>, BigInt)> {
    let us = idx.iter().map(|&i| crt.lift_nonneg(|t| images[t][i]));
    CommonDenominator::reconstruct(crt, us).map(|cd| (cd.nums, cd.den))
}

/// Full reconstruction and the certificate check; `None` when more primes are needed.
fn try_certify<S: RrefSource>(
    b: &S,
    piv: &[usize],
    free: &[usize],
    crt: &Crt,
    images: &[Vec<u64>],
    max_a: &BigInt,
) -> Option<IntRref> {
    let ((m, n), r) = (b.shape(), piv.len());
    let total = r * free.len();
    let us = (0..total).map(|i| crt.lift_nonneg(|t| images[t][i]));
    let cd = CommonDenominator::reconstruct(crt, us)?;
    let den = cd.den;
    if crt.primes().iter().any(|p| (&den % p.p).is_zero()) {
        return None;
    }
    let max_n = cd.nums.iter().map(|x| x.abs()).max().unwrap_or_default();
    let max_n = max_n.max(den.clone());
    let max_row_piv: BigInt = (0..m)
        .map(|i| piv.iter().map(|&c| b.abs_at(i, c)).sum::<BigInt>())
        .max()
        .unwrap_or_default();
    let beta = &den * max_a + max_row_piv * max_n;
    if *crt.modulus() <= beta * 2u32 {
        return None;
    }
    let mut num = vec![BigInt::zero(); r * n];
    for (k, &c) in piv.iter().enumerate() {
        num[k * n + c] = den.clone();
    }
    let mut it = cd.nums.into_iter();
    for k in 0..r {
        for &f in free {
            num[k * n + f] = it.next().expect("count");
        }
    }
    Some(IntRref {
        pivots: piv.to_vec(),
        den,
        num,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::qkernels::prime::nth_prime;

    #[test]
    fn rref_mod_p_small() {
        let pr = nth_prime(0);
        // [[0, 2, 4], [0, 1, 2], [1, 1, 1]] -> pivots 0, 1; rows [1,0,-1],[0,1,2],[0,0,0]
        let mut a: Vec<u64> = [0i64, 2, 4, 0, 1, 2, 1, 1, 1]
            .iter()
            .map(|&x| pr.reduce_i64(x))
            .collect();
        let piv = rref_mod_p(&pr, 3, 3, &mut a);
        assert_eq!(piv, vec![0, 1]);
        let want: Vec<u64> = [1i64, 0, -1, 0, 1, 2, 0, 0, 0]
            .iter()
            .map(|&x| pr.reduce_i64(x))
            .collect();
        assert_eq!(a, want);
    }

    #[test]
    fn rref_int_small() {
        let b = IntMat::new(2, 3, [2, 4, 1, 1, 3, 0].map(BigInt::from).to_vec());
        let res = rref_int(&b);
        assert_eq!(res.pivots, vec![0, 1]);
        // rref = [[1, 0, 3/2], [0, 1, -1/2]]
        assert_eq!(res.den, BigInt::from(2));
        assert_eq!(res.num, [2, 0, 3, 0, 2, -1].map(BigInt::from).to_vec());
    }
}
