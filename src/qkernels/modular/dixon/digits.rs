//! The $p$-adic digits of Dixon's lifting and their integers.
//!
//! After $s$ steps entry $e$ of the solution is known modulo $p^s$ as
//! $X_e = \sum_{i < s} x_{i,e}\, p^i$ with digits $0 \le x_{i,e} < p$. The digits are kept
//! as words; an integer is built only when a reconstruction needs it, by splitting the
//! digit string in halves at a power of two, $X = X_{lo} + p^{2^t} X_{hi}$ (the powers
//! $p^{2^t}$ computed once), so that the cost is that of a few big products instead of
//! the $O(s^2)$ of Horner's rule.

use crate::qkernels::prime::Prime;
use num_bigint::{BigInt, BigUint};
use num_traits::{One, Zero};

/// Digits of `entries` numbers in base `p`, one row of words per step.
pub(super) struct Digits {
    p: u64,
    entries: usize,
    words: Vec<u64>,
    /// `pows[t]` $= p^{2^t}$.
    pows: Vec<BigUint>,
}

/// Below this many digits Horner's rule is used.
const HORNER: usize = 16;

impl Digits {
    pub(super) fn new(pr: &Prime, entries: usize) -> Self {
        Digits {
            p: pr.p,
            entries,
            words: Vec::new(),
            pows: vec![BigUint::from(pr.p)],
        }
    }

    /// Appends the digits of the next step (`entries` words).
    pub(super) fn push(&mut self, x: &[u64]) {
        debug_assert_eq!(x.len(), self.entries);
        self.words.extend_from_slice(x);
    }

    /// The number of steps $s$.
    pub(super) fn steps(&self) -> usize {
        self.words.len().checked_div(self.entries).unwrap_or(0)
    }

    /// $p^{2^t}$, extending the table as needed.
    fn pow2(&mut self, t: usize) -> &BigUint {
        while self.pows.len() <= t {
            let last = &self.pows[self.pows.len() - 1];
            let next = last * last;
            self.pows.push(next);
        }
        &self.pows[t]
    }

    /// $p^s$ for the current number of steps.
    pub(super) fn modulus(&mut self) -> BigInt {
        let s = self.steps();
        let mut m = BigUint::one();
        for t in 0..usize::BITS as usize {
            if s >> t & 1 == 1 {
                m *= self.pow2(t);
            }
        }
        BigInt::from(m)
    }

    /// $X_e \in [0, p^s)$.
    pub(super) fn value(&mut self, e: usize) -> BigInt {
        let ds: Vec<u64> = self
            .words
            .iter()
            .skip(e)
            .step_by(self.entries)
            .copied()
            .collect();
        BigInt::from(self.combine(&ds))
    }

    fn combine(&mut self, ds: &[u64]) -> BigUint {
        if ds.len() <= HORNER {
            return ds
                .iter()
                .rev()
                .fold(BigUint::zero(), |acc, &d| acc * self.p + d);
        }
        // the largest power of two below the length
        let t = (usize::BITS - 1 - (ds.len() - 1).leading_zeros()) as usize;
        let (lo, hi) = ds.split_at(1 << t);
        let lo = self.combine(lo);
        let hi = self.combine(hi);
        hi * self.pow2(t) + lo
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::qkernels::prime::nth_prime;

    #[test]
    fn values_match_horner() {
        let pr = nth_prime(0);
        let mut d = Digits::new(&pr, 2);
        let mut want = [BigInt::zero(), BigInt::zero()];
        let mut pw = BigInt::one();
        for s in 0..70u64 {
            let x = [s * 0x1234_5678_9abc % pr.p, pr.p - 1 - s];
            d.push(&x);
            for e in 0..2 {
                want[e] += &pw * x[e];
            }
            pw *= pr.p;
            assert_eq!(d.steps(), s as usize + 1);
            assert_eq!(d.modulus(), pw);
            for (e, w) in want.iter().enumerate() {
                assert_eq!(&d.value(e), w, "step {s} entry {e}");
            }
        }
    }
}
