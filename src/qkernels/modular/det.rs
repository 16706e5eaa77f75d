//! Multi-modular determinant of an integer matrix.
//!
//! $\det B \bmod p$ by Gaussian elimination for enough primes that $M = \prod p >
//! 2 H$, where $H = \min\left(\prod_i \|B_{i,:}\|_2, \prod_j \|B_{:,j}\|_2\right)$ is
//! Hadamard's bound; the symmetric CRT lift is then $\det B$ itself (a proof, not a
//! heuristic).

use super::crt::Crt;
use super::rref::{rows_mut, swap_rows};
use crate::qkernels::intmat::{IntMat, primes_for_bits};
use crate::qkernels::prime::{Prime, primes};
use num_bigint::BigInt;
use num_traits::Zero;

/// $\det a$ over $\mathbb{Z}/p$ for the `n x n` row-major `a` (destroyed).
pub fn det_mod_p(pr: &Prime, n: usize, a: &mut [u64]) -> u64 {
    let mut det = 1u64;
    for c in 0..n {
        let Some(i) = (c..n).find(|&i| a[i * n + c] != 0) else {
            return 0;
        };
        if i != c {
            swap_rows(a, n, i, c);
            det = pr.neg(det);
        }
        let piv = a[c * n + c];
        det = pr.mul(det, piv);
        let inv = pr.inv(piv).expect("nonzero pivot");
        for i in c + 1..n {
            let f = a[i * n + c];
            if f != 0 {
                let f = pr.mul(f, inv);
                let (y, x) = rows_mut(a, n, i, c);
                pr.axpy_neg(&mut y[c + 1..], &x[c + 1..], f);
            }
        }
    }
    det
}

/// $\log_2$ of Hadamard's bound for `b` (`-inf` when a row or column is zero).
pub fn hadamard_log2(b: &IntMat) -> f64 {
    let rows: f64 = b.row_norm_log2().iter().sum();
    let cols: f64 = b.col_norm_log2().iter().sum();
    rows.min(cols)
}

/// Exact $\det b$ for a square integer matrix.
pub fn det_int(b: &IntMat) -> BigInt {
    assert_eq!(b.m, b.n, "det_int: square matrix required");
    let h = hadamard_log2(b);
    if h == f64::NEG_INFINITY {
        return BigInt::zero();
    }
    let k = primes_for_bits(h + 1.0);
    let ps: Vec<Prime> = primes(0).take(k).collect();
    let dets: Vec<u64> = ps
        .iter()
        .map(|pr| det_mod_p(pr, b.n, &mut b.reduce(pr)))
        .collect();
    Crt::new(&ps).lift(|i| dets[i])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn small_determinants() {
        let b = IntMat::new(3, 3, [2, 0, 1, 1, 3, 2, 1, 1, 2].map(BigInt::from).to_vec());
        assert_eq!(det_int(&b), BigInt::from(6));
        let b = IntMat::new(2, 2, [0, 1, 1, 0].map(BigInt::from).to_vec());
        assert_eq!(det_int(&b), BigInt::from(-1));
        let b = IntMat::new(2, 2, [1, 2, 2, 4].map(BigInt::from).to_vec());
        assert_eq!(det_int(&b), BigInt::zero());
        assert_eq!(det_int(&IntMat::new(0, 0, vec![])), BigInt::from(1));
    }
}
