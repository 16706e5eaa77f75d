//! The RREF of a rational matrix *guessed* from its images modulo word primes, for callers
//! that then check an exact identity which makes the guess a proof.
//!
//! Primes are taken one at a time; images on the best pivot profile (as in [`super::rref`])
//! are combined by CRT and rational reconstruction over a common denominator, and the
//! guess is returned once two successive prime sets reconstruct the same matrix. Unlike
//! [`super::rref::rref_int`], no bound on the input entries is waited for: the number of
//! primes follows the size of the result, which is small where the input is large but
//! structured (Krylov vectors, say). Nothing here is certified; e.g.
//! `realization::controllability_structure` checks $S C = R$ or $LB = 0$, $LA = \bar A L$
//! exactly with the guessed $C$ or $L$.

use super::crt::{CommonDenominator, Crt};
use super::rank::reduce_rational;
use super::rref::{ProfileImages, rref_mod_p};
use crate::field::Rational;
use crate::qkernels::gcd;
use crate::qkernels::prime::primes;
use num_bigint::BigInt;
use num_traits::Zero;

/// The guessed RREF of the `m x n` row-major `a`: pivot columns and the `r x n` nonzero
/// rows (row-major). `None` when `max_primes` primes give no stable reconstruction.
///
/// # Panics
/// When `a.len() != m * n`.
pub fn rref_guess(
    m: usize,
    n: usize,
    a: &[Rational],
    max_primes: usize,
) -> Option<(Vec<usize>, Vec<Rational>)> {
    assert_eq!(
        a.len(),
        m * n,
        "rref_guess: slice of length {} for {m}x{n}",
        a.len()
    );
    let mut st = ProfileImages::default();
    let mut last: Option<(Vec<BigInt>, BigInt)> = None;
    for pr in primes(20).take(max_primes) {
        let Some(mut red) = a
            .iter()
            .map(|x| reduce_rational(&pr, x))
            .collect::<Option<Vec<u64>>>()
        else {
            continue;
        };
        let piv = rref_mod_p(&pr, m, n, &mut red);
        match st.push(pr, piv, &red, n) {
            None => continue,
            Some(true) => last = None,
            Some(false) => {}
        }
        let (piv, free, images) = (st.pivots(), &st.free, &st.images);
        let r = piv.len();
        let crt = Crt::new(&st.used);
        let total = r * free.len();
        let us = (0..total).map(|i| crt.lift_nonneg(|t| images[t][i]));
        let Some(cd) = CommonDenominator::reconstruct(&crt, us) else {
            last = None;
            continue;
        };
        let now = (cd.nums, cd.den);
        if last.as_ref() != Some(&now) {
            last = Some(now);
            continue;
        }
        let (nums, den) = now;
        let mut out = vec![Rational::zero(); r * n];
        for (k, &c) in piv.iter().enumerate() {
            out[k * n + c] = Rational::from_integer(1.into());
        }
        let mut it = nums.into_iter();
        for k in 0..r {
            for &f in free {
                let x = it.next().expect("count");
                if !x.is_zero() {
                    out[k * n + f] = gcd::fraction(x, &den);
                }
            }
        }
        return Some((piv.to_vec(), out));
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn guess_small_rref() {
        let q = |x: i64| Rational::from_integer(x.into());
        // [[2, 4, 1], [1, 3, 0]] -> [[1, 0, 3/2], [0, 1, -1/2]]
        let a = [2, 4, 1, 1, 3, 0].map(q);
        let (piv, r) = rref_guess(2, 3, &a, 10).unwrap();
        assert_eq!(piv, vec![0, 1]);
        let h = |x: i64, y: i64| Rational::new(x.into(), y.into());
        assert_eq!(r, vec![q(1), q(0), h(3, 2), q(0), q(1), h(-1, 2)]);
        // one prime cannot confirm a guess
        assert!(rref_guess(2, 3, &a, 1).is_none());
    }
}
