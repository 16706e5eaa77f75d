//! Multi-modular characteristic polynomial $\det(xI - B)$ of an integer matrix.
//!
//! Modulo each prime: reduction to upper Hessenberg form $H = T^{-1} B T$ by elementary
//! similarity transformations (Cohen, *A Course in Computational Algebraic Number Theory*,
//! Alg. 2.2.9), then the recurrence
//! $p_m(x) = (x - h_{m,m})\, p_{m-1}(x) - \sum_{i<m} h_{i,m} \left(\prod_{j=i+1}^{m}
//! h_{j,j-1}\right) p_{i-1}(x)$, all in $O(n^3)$.
//!
//! **Bound.** The coefficient of $x^{n-k}$ is $\pm$ the sum of the $\binom nk$ principal
//! $k \times k$ minors, each at most the product of the $k$ largest row norms (Hadamard;
//! likewise for columns). Enough primes are taken for twice the largest such bound, so the
//! symmetric CRT lift is exact.

use super::crt::Crt;
use super::rref::{rows_mut, swap_rows};
use crate::qkernels::intmat::{IntMat, primes_for_bits};
use crate::qkernels::prime::{Prime, primes};
use num_bigint::BigInt;

/// Characteristic polynomial of the `n x n` row-major `a` (destroyed) over $\mathbb{Z}/p$,
/// low degree first, monic, length `n + 1`.
pub fn charpoly_mod_p(pr: &Prime, n: usize, a: &mut [u64]) -> Vec<u64> {
    hessenberg_mod_p(pr, n, a);
    charpoly_hessenberg_mod_p(pr, n, a)
}

/// Reduces `a` in place to an upper Hessenberg matrix similar to it.
pub fn hessenberg_mod_p(pr: &Prime, n: usize, a: &mut [u64]) {
    for m in 1..n.saturating_sub(1) {
        let Some(i) = (m..n).find(|&i| a[i * n + m - 1] != 0) else {
            continue;
        };
        if i != m {
            swap_rows(a, n, i, m);
            for r in 0..n {
                a.swap(r * n + i, r * n + m);
            }
        }
        let inv = pr.inv(a[m * n + m - 1]).expect("nonzero pivot");
        for i in m + 1..n {
            let u = a[i * n + m - 1];
            if u == 0 {
                continue;
            }
            let u = pr.mul(u, inv);
            // row_i -= u row_m (T^{-1} on the left) ...
            let (y, x) = rows_mut(a, n, i, m);
            pr.axpy_neg(&mut y[m - 1..], &x[m - 1..], u);
            // ... and col_m += u col_i (T on the right)
            let us = pr.shoup(u);
            for r in 0..n {
                let t = pr.mul_shoup(u, us, a[r * n + i]);
                a[r * n + m] = pr.add(a[r * n + m], t);
            }
        }
    }
}

/// Characteristic polynomial of an upper Hessenberg `h` modulo `p`.
pub fn charpoly_hessenberg_mod_p(pr: &Prime, n: usize, h: &[u64]) -> Vec<u64> {
    // p_m = charpoly of the leading m x m block (low degree first, length m + 1), all in one
    // buffer at offset m (m + 1) / 2 (one allocation, not one per m: this runs once per
    // evaluation point of the Q(p) kernels)
    let off = |m: usize| m * (m + 1) / 2;
    let mut buf = vec![0u64; off(n + 1)];
    buf[0] = 1 % pr.p;
    // y -= f x: Shoup's products on long rows, plain ones on the short rows of small n
    let axpy_neg = |y: &mut [u64], x: &[u64], f: u64| {
        if x.len() >= 16 {
            pr.axpy_neg(y, x, f);
        } else {
            for (yj, &xj) in y.iter_mut().zip(x) {
                *yj = pr.sub(*yj, pr.mul(f, xj));
            }
        }
    };
    for m in 0..n {
        let (done, rest) = buf.split_at_mut(off(m + 1));
        let next = &mut rest[..m + 2];
        // (x - h_mm) p_m
        let prev = &done[off(m)..];
        next[1..].copy_from_slice(prev);
        axpy_neg(&mut next[..m + 1], prev, h[m * n + m]);
        // - sum_{i<m} h_{i,m} (prod_{j=i+1}^{m} h_{j,j-1}) p_i
        let mut t = 1u64;
        for i in (0..m).rev() {
            t = pr.mul(t, h[(i + 1) * n + i]);
            if t == 0 {
                break;
            }
            let c = pr.mul(h[i * n + m], t);
            axpy_neg(&mut next[..i + 1], &done[off(i)..off(i) + i + 1], c);
        }
    }
    buf.split_off(off(n))
}

/// $\log_2$ bound of $\max_k |c_k|$ over the coefficients of $\det(xI - B)$.
pub fn charpoly_bound_log2(b: &IntMat) -> f64 {
    let n = b.n;
    let sorted = |mut v: Vec<f64>| {
        // norms below 1 only occur for zero rows: bound them by 1 (log 0)
        v.iter_mut().for_each(|x| *x = x.max(0.0));
        v.sort_by(|x, y| y.total_cmp(x));
        v
    };
    let rows = sorted(b.row_norm_log2());
    let cols = sorted(b.col_norm_log2());
    let (mut best, mut sr, mut sc, mut lbin) = (0.0f64, 0.0, 0.0, 0.0);
    for k in 1..=n {
        sr += rows[k - 1];
        sc += cols[k - 1];
        // log2 binom(n, k), accumulated with a small upward margin
        lbin += ((n - k + 1) as f64 / k as f64).log2() + 1e-12;
        best = best.max(lbin + sr.min(sc));
    }
    best
}

/// Exact characteristic polynomial of a square integer matrix, low degree first.
pub fn charpoly_int(b: &IntMat) -> Vec<BigInt> {
    assert_eq!(b.m, b.n, "charpoly_int: square matrix required");
    let n = b.n;
    let k = primes_for_bits(charpoly_bound_log2(b) + 1.0);
    let ps: Vec<Prime> = primes(0).take(k).collect();
    let images: Vec<Vec<u64>> = ps
        .iter()
        .map(|pr| charpoly_mod_p(pr, n, &mut b.reduce(pr)))
        .collect();
    let crt = Crt::new(&ps);
    (0..=n).map(|j| crt.lift(|i| images[i][j])).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn small_charpolys() {
        // [[1, 2], [3, 4]]: x^2 - 5x - 2
        let b = IntMat::new(2, 2, [1, 2, 3, 4].map(BigInt::from).to_vec());
        assert_eq!(charpoly_int(&b), [-2, -5, 1].map(BigInt::from).to_vec());
        // companion-like 3x3 needing a row swap: [[0,0,1],[0,0,0],[1,1,0]]
        let b = IntMat::new(3, 3, [0, 0, 1, 0, 0, 0, 1, 1, 0].map(BigInt::from).to_vec());
        // det(xI - B) = x^3 - x
        assert_eq!(charpoly_int(&b), [0, -1, 0, 1].map(BigInt::from).to_vec());
        assert_eq!(
            charpoly_int(&IntMat::new(0, 0, vec![])),
            vec![BigInt::from(1)]
        );
    }
}
