//! The integer side of Dixon's lifting: the integer matrix $A' = DA$ held as machine
//! limbs, and the exact residual update $R \leftarrow (R - A' \bar X) / p$.
//!
//! Every entry of $A'$ is stored as a sign and a magnitude of `width[i]` little-endian
//! 64-bit limbs (the widest entry of its row), every entry of $R$ in two's complement over
//! `rwidth[i]` limbs. The update is one multiply-accumulate of a word into a limb array per
//! entry of $A'$ (what GMP calls `addmul_1` / `submul_1`), and one exact division by the odd
//! prime $p$ per entry of $R$, by Hensel's method (multiplication by $p^{-1} \bmod 2^{64}$
//! from the low limb up), which is exact in two's complement too: if $v = pq$ and $q$ fits
//! the width, $v p^{-1} \equiv q \pmod{2^{64w}}$.
//!
//! **Width of $R$.** With $|R_s| \le \rho$ and $0 \le \bar x < p$,
//! $|R_s - A'\bar X| \le \rho + n p \max|A'_{i,:}|$ and $|R_{s+1}| \le \rho / p + n
//! \max|A'_{i,:}|$: from $R_0 = B'$ every residual of row $i$ stays below
//! $|B'_{i,:}| + 2n \max|A'_{i,:}|$, and the value before the division below $p$ times that.
//! Three limbs above the wider of $A'_{i,:}$ and $B'_{i,:}$ hold it for $n < 2^{60}$.

use crate::qkernels::prime::Prime;
use num_bigint::{BigInt, Sign};

/// A row-major integer matrix in limbs (sign and magnitude, one width per row).
pub(super) struct LimbMat {
    cols: usize,
    width: Vec<usize>,
    start: Vec<usize>,
    mag: Vec<u64>,
    neg: Vec<bool>,
}

impl LimbMat {
    /// The `rows x cols` row-major `ints`.
    pub(super) fn new(rows: usize, cols: usize, ints: &[BigInt]) -> Self {
        let width: Vec<usize> = (0..rows)
            .map(|i| {
                ints[i * cols..(i + 1) * cols]
                    .iter()
                    .map(|x| x.magnitude().bits().div_ceil(64) as usize)
                    .max()
                    .unwrap_or(0)
                    .max(1)
            })
            .collect();
        let mut start = Vec::with_capacity(rows);
        let mut mag = Vec::new();
        let mut neg = Vec::with_capacity(rows * cols);
        for (i, &w) in width.iter().enumerate() {
            start.push(mag.len());
            for x in &ints[i * cols..(i + 1) * cols] {
                let (s, l) = x.to_u64_digits();
                neg.push(s == Sign::Minus);
                mag.extend_from_slice(&l);
                mag.resize(mag.len() + w - l.len(), 0);
            }
        }
        LimbMat {
            cols,
            width,
            start,
            mag,
            neg,
        }
    }

    /// Limbs per entry of row `i`.
    pub(super) fn width(&self, i: usize) -> usize {
        self.width[i]
    }

    /// Magnitude and sign of entry `(i, j)`.
    #[inline]
    fn at(&self, i: usize, j: usize) -> (&[u64], bool) {
        let w = self.width[i];
        let s = self.start[i] + j * w;
        (&self.mag[s..s + w], self.neg[i * self.cols + j])
    }

    /// The image modulo `pr`, row-major.
    pub(super) fn reduce(&self, pr: &Prime) -> Vec<u64> {
        let rows = self.width.len();
        (0..rows)
            .flat_map(|i| (0..self.cols).map(move |j| (i, j)))
            .map(|(i, j)| {
                let (l, neg) = self.at(i, j);
                pr.reduce_limbs(neg, l)
            })
            .collect()
    }
}

/// The residual $R$ (`rows x k`), each entry in two's complement over its row's width.
pub(super) struct Residual {
    k: usize,
    rwidth: Vec<usize>,
    data: Vec<u64>,
}

impl Residual {
    /// $R_0 = B'$ (`rows x k` row-major `b`), rows as wide as [`LimbMat`] `a`'s plus three
    /// limbs (module docs).
    pub(super) fn new(a: &LimbMat, k: usize, b: &[BigInt]) -> Self {
        let rows = a.width.len();
        let rwidth: Vec<usize> = (0..rows)
            .map(|i| {
                let wb = b[i * k..(i + 1) * k]
                    .iter()
                    .map(|x| x.magnitude().bits().div_ceil(64) as usize)
                    .max()
                    .unwrap_or(0);
                a.width(i).max(wb) + 3
            })
            .collect();
        let mut data = Vec::with_capacity(rwidth.iter().sum::<usize>() * k);
        for (i, &w) in rwidth.iter().enumerate() {
            for x in &b[i * k..(i + 1) * k] {
                let at = data.len();
                let (s, l) = x.to_u64_digits();
                data.extend_from_slice(&l);
                data.resize(at + w, 0);
                if s == Sign::Minus {
                    negate(&mut data[at..]);
                }
            }
        }
        Residual { k, rwidth, data }
    }

    /// Is every entry zero?
    pub(super) fn is_zero(&self) -> bool {
        self.data.iter().all(|&l| l == 0)
    }

    /// $R \bmod p$ (`rows x k` row-major).
    pub(super) fn reduce(&self, pr: &Prime) -> Vec<u64> {
        let mut out = Vec::with_capacity(self.rwidth.len() * self.k);
        let mut at = 0;
        let base = ((1u128 << 64) % pr.p as u128) as u64;
        for &w in &self.rwidth {
            // v = V - 2^(64 w) for a negative entry read as the unsigned V
            let wrap = pr.pow(base, w as u64);
            for _ in 0..self.k {
                let e = &self.data[at..at + w];
                let r = pr.reduce_limbs(false, e);
                out.push(if e[w - 1] >> 63 == 1 {
                    pr.sub(r, wrap)
                } else {
                    r
                });
                at += w;
            }
        }
        out
    }

    /// $R \leftarrow (R - A' \bar X) / p$ for the `rows x k` digits `x` ($0 \le x < p$);
    /// the division is exact because $A' \bar X \equiv R \pmod p$.
    pub(super) fn update(&mut self, a: &LimbMat, x: &[u64], pr: &Prime) {
        let k = self.k;
        let pinv = inverse_mod_word(pr.p);
        let mut at = 0;
        for (i, &w) in self.rwidth.iter().enumerate() {
            let row = &mut self.data[at..at + w * k];
            for j in 0..a.cols {
                let (mag, neg) = a.at(i, j);
                if mag.iter().all(|&l| l == 0) {
                    continue;
                }
                for (c, acc) in row.chunks_exact_mut(w).enumerate() {
                    let xv = x[j * k + c];
                    if xv == 0 {
                        continue;
                    }
                    if neg {
                        addmul_1(acc, mag, xv);
                    } else {
                        submul_1(acc, mag, xv);
                    }
                }
            }
            for acc in row.chunks_exact_mut(w) {
                divexact_1(acc, pr.p, pinv);
            }
            at += w * k;
        }
    }
}

/// Two's complement negation in place.
fn negate(a: &mut [u64]) {
    let mut carry = true;
    for l in a.iter_mut() {
        let (v, c) = (!*l).overflowing_add(carry as u64);
        *l = v;
        carry = c;
    }
}

/// `acc += a * x` (wrapping at the top of `acc`, which is at least as long as `a`).
#[inline]
fn addmul_1(acc: &mut [u64], a: &[u64], x: u64) {
    let mut carry = 0u64;
    let (lo, hi) = acc.split_at_mut(a.len());
    for (r, &l) in lo.iter_mut().zip(a) {
        let t = l as u128 * x as u128 + *r as u128 + carry as u128;
        *r = t as u64;
        carry = (t >> 64) as u64;
    }
    for r in hi {
        if carry == 0 {
            break;
        }
        let (v, c) = r.overflowing_add(carry);
        *r = v;
        carry = c as u64;
    }
}

/// `acc -= a * x` (wrapping at the top of `acc`).
#[inline]
fn submul_1(acc: &mut [u64], a: &[u64], x: u64) {
    let mut borrow = 0u64;
    let (lo, hi) = acc.split_at_mut(a.len());
    for (r, &l) in lo.iter_mut().zip(a) {
        let t = l as u128 * x as u128 + borrow as u128;
        let (v, b) = r.overflowing_sub(t as u64);
        *r = v;
        borrow = (t >> 64) as u64 + b as u64;
    }
    for r in hi {
        if borrow == 0 {
            break;
        }
        let (v, b) = r.overflowing_sub(borrow);
        *r = v;
        borrow = b as u64;
    }
}

/// $p^{-1} \bmod 2^{64}$ for odd `p` (Newton: each step doubles the correct low bits).
fn inverse_mod_word(p: u64) -> u64 {
    let mut inv = p; // correct to 3 bits: p * p = 1 mod 8
    for _ in 0..5 {
        inv = inv.wrapping_mul(2u64.wrapping_sub(p.wrapping_mul(inv)));
    }
    debug_assert_eq!(p.wrapping_mul(inv), 1);
    inv
}

/// `a /= p` for an `a` divisible by the odd `p` (two's complement; see the module docs).
fn divexact_1(a: &mut [u64], p: u64, pinv: u64) {
    let mut borrow = 0u64;
    for l in a.iter_mut() {
        let (s, b) = l.overflowing_sub(borrow);
        let q = s.wrapping_mul(pinv);
        *l = q;
        borrow = ((q as u128 * p as u128) >> 64) as u64 + b as u64;
    }
}

/// The integer of a two's complement limb array.
#[cfg(test)]
fn to_bigint(a: &[u64]) -> BigInt {
    let negative = a.last().is_some_and(|&l| l >> 63 == 1);
    let mut v = a.to_vec();
    if negative {
        negate(&mut v);
    }
    let mag = num_bigint::BigUint::from_slice(
        &v.iter()
            .flat_map(|&l| [l as u32, (l >> 32) as u32])
            .collect::<Vec<_>>(),
    );
    let x = BigInt::from_biguint(Sign::Plus, mag);
    if negative { -x } else { x }
}

impl Residual {
    /// The entries as integers (tests).
    #[cfg(test)]
    fn to_ints(&self) -> Vec<BigInt> {
        let mut out = Vec::new();
        let mut at = 0;
        for &w in &self.rwidth {
            for _ in 0..self.k {
                out.push(to_bigint(&self.data[at..at + w]));
                at += w;
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::qkernels::prime::nth_prime;
    use num_traits::Zero;

    #[test]
    fn update_matches_big_integers() {
        let pr = nth_prime(1);
        let big = |s: &str| s.parse::<BigInt>().unwrap();
        let a = vec![
            big("-123456789012345678901234567890"),
            big("7"),
            big("0"),
            big("340282366920938463463374607431768211455"),
        ];
        let (n, k) = (2, 2);
        let am = LimbMat::new(n, n, &a);
        let b = vec![
            big("-5"),
            big("99999999999999999999999"),
            big("1"),
            big("0"),
        ];
        let mut r = Residual::new(&am, k, &b);
        assert_eq!(r.to_ints(), b);
        // digits chosen so that R - A X = 0 mod p: X = A^{-1} R mod p
        let mut ai = am.reduce(&pr);
        assert!(crate::qkernels::modular::inverse::inverse_mod_p(
            &pr, n, &mut ai
        ));
        let rb = r.reduce(&pr);
        for (got, want) in rb.iter().zip(&b) {
            let (s, l) = want.to_u64_digits();
            assert_eq!(*got, pr.reduce_limbs(s == Sign::Minus, &l));
        }
        let x: Vec<u64> = (0..n * k)
            .map(|t| {
                let (i, c) = (t / k, t % k);
                (0..n).fold(0, |s, j| pr.add(s, pr.mul(ai[i * n + j], rb[j * k + c])))
            })
            .collect();
        r.update(&am, &x, &pr);
        let p = BigInt::from(pr.p);
        let want: Vec<BigInt> = (0..n * k)
            .map(|t| {
                let (i, c) = (t / k, t % k);
                let ax: BigInt = (0..n).map(|j| &a[i * n + j] * x[j * k + c]).sum();
                let v = &b[t] - ax;
                assert!((&v % &p).is_zero());
                v / &p
            })
            .collect();
        assert_eq!(r.to_ints(), want);
        assert!(!r.is_zero());
    }
}
