//! Lower bounds of the rank over $\mathbb{Q}$ from one elimination modulo a word prime.
//!
//! If $p$ divides no denominator of $A \in \mathbb{Q}^{m \times n}$, every entry lies in the
//! local ring $\mathbb{Z}_{(p)}$ and reduces to $\bar A \in \mathbb{F}_p^{m \times n}$. An
//! $r \times r$ minor of $\bar A$ is the residue of the same minor of $A$, so a nonzero
//! minor modulo $p$ is a nonzero minor over $\mathbb{Q}$:
//! $\operatorname{rank}_{\mathbb{F}_p} \bar A \le \operatorname{rank}_{\mathbb{Q}} A$,
//! always, whatever $p$. The bound is exact as a lower bound (no probability involved);
//! only its sharpness depends on $p$ (it is sharp unless $p$ divides every nonzero
//! $r \times r$ minor). One forward elimination costs $O(mn\min(m, n))$ word operations,
//! against the many primes (one elimination each) that the certified RREF of
//! [`super::rref`] needs when its entries are large.

use crate::field::Rational;
use crate::qkernels::prime::Prime;
use num_bigint::{BigInt, Sign};

/// The residue of `x` modulo `pr`; `None` when `pr` divides the denominator.
pub fn reduce_rational(pr: &Prime, x: &Rational) -> Option<u64> {
    let red = |v: &BigInt| {
        let (s, l) = v.to_u64_digits();
        pr.reduce_limbs(s == Sign::Minus, &l)
    };
    let num = red(x.numer());
    if num_traits::One::is_one(x.denom()) {
        return Some(num);
    }
    let d = pr.inv(red(x.denom()))?;
    Some(pr.mul(num, d))
}

/// Rank over $\mathbb{F}_p$ of the `m x n` row-major `a` (forward elimination in place;
/// the contents of `a` are destroyed).
pub fn rank_mod_p(pr: &Prime, m: usize, n: usize, a: &mut [u64]) -> usize {
    eliminate_mod_p(pr, m, n, a, n)
}

/// Forward elimination of the columns `0..upto` only, in place: returns the number `r` of
/// pivots found there; rows `r..m` are then zero in those columns (and hold the rest).
pub fn eliminate_mod_p(pr: &Prime, m: usize, n: usize, a: &mut [u64], upto: usize) -> usize {
    assert_eq!(
        a.len(),
        m * n,
        "rank_mod_p: slice of length {} for {m}x{n}",
        a.len()
    );
    let mut r = 0;
    for c in 0..upto.min(n) {
        if r == m {
            break;
        }
        let Some(i) = (r..m).find(|&i| a[i * n + c] != 0) else {
            continue;
        };
        super::rref::swap_rows(a, n, i, r);
        let inv = pr.inv(a[r * n + c]).expect("nonzero pivot");
        pr.scale(&mut a[r * n + c..(r + 1) * n], inv);
        for i in r + 1..m {
            let f = a[i * n + c];
            if f != 0 {
                let (y, x) = super::rref::rows_mut(a, n, i, r);
                pr.axpy_neg(&mut y[c..], &x[c..], f);
            }
        }
        r += 1;
    }
    r
}

/// $\operatorname{rank}(A \bmod p)$ of a rational `m x n` row-major matrix, a lower bound
/// of its rank over $\mathbb{Q}$ (module docs); `None` when `pr` divides a denominator.
///
/// # Panics
/// When `a.len() != m * n`.
pub fn rank_lower_bound(pr: &Prime, m: usize, n: usize, a: &[Rational]) -> Option<usize> {
    assert_eq!(
        a.len(),
        m * n,
        "rank_lower_bound: slice of length {} for {m}x{n}",
        a.len()
    );
    let mut red: Vec<u64> = a
        .iter()
        .map(|x| reduce_rational(pr, x))
        .collect::<Option<_>>()?;
    Some(rank_mod_p(pr, m, n, &mut red))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::qkernels::prime::nth_prime;

    fn q(a: i64, b: i64) -> Rational {
        Rational::new(a.into(), b.into())
    }

    #[test]
    fn lower_bound_of_small_ranks() {
        let pr = nth_prime(3);
        // [[1/2, 1], [1, 2], [0, 1]]: rank 2
        let a = [q(1, 2), q(1, 1), q(1, 1), q(2, 1), q(0, 1), q(1, 1)];
        assert_eq!(rank_lower_bound(&pr, 3, 2, &a), Some(2));
        // rank 1: the second row is twice the first
        let b = [q(1, 3), q(-2, 5), q(2, 3), q(-4, 5)];
        assert_eq!(rank_lower_bound(&pr, 2, 2, &b), Some(1));
        // the prime as a denominator has no residue
        let c = [Rational::new(1.into(), BigInt::from(pr.p))];
        assert_eq!(rank_lower_bound(&pr, 1, 1, &c), None);
        // p itself is zero modulo p: rank 0 modulo p, 1 over Q (a lower bound, not sharp)
        let d = [Rational::from_integer(BigInt::from(pr.p))];
        assert_eq!(rank_lower_bound(&pr, 1, 1, &d), Some(0));
    }
}
