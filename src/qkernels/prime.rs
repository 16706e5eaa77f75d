//! Word-size prime fields $\mathbb{Z}/p$ with $2^{61} < p < 2^{62}$.
//!
//! Residues are `u64` in $[0, p)$. Products use a full `u128` product; the hot loops of the
//! elimination kernels multiply a whole row by one constant $f$, for which Shoup's
//! precomputed quotient $f' = \lfloor f 2^{64} / p \rfloor$ replaces the division by two
//! multiplications ([`Prime::axpy`]).
//!
//! The primes come from [`primes`], a deterministic, cached sequence (largest first below
//! $2^{62}$), each one certified by the Miller–Rabin test with a base set that is proven
//! deterministic for all 64-bit integers.

use std::sync::{Mutex, OnceLock};

/// A prime modulus with its precomputed helpers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Prime {
    /// The modulus; $2^{61} < p < 2^{62}$ for the primes of [`nth_prime`] (other moduli
    /// work too, without the Barrett products).
    pub p: u64,
    /// Barrett's constant $\lfloor 2^{125} / p \rfloor$ when $2^{61} < p < 2^{62}$, else 0.
    barrett: u64,
}

impl Prime {
    /// The modulus `p` (at least 2) with its precomputed constants.
    pub const fn new(p: u64) -> Self {
        let barrett = if p > 1 << 61 && p < 1 << 62 {
            ((1u128 << 125) / p as u128) as u64
        } else {
            0
        };
        Prime { p, barrett }
    }

    /// `a + b mod p` for reduced `a`, `b`.
    #[inline(always)]
    pub fn add(&self, a: u64, b: u64) -> u64 {
        let s = a + b;
        s.min(s.wrapping_sub(self.p))
    }

    /// `a - b mod p` for reduced `a`, `b`.
    #[inline(always)]
    pub fn sub(&self, a: u64, b: u64) -> u64 {
        let s = a + self.p - b;
        s.min(s.wrapping_sub(self.p))
    }

    /// `-a mod p`.
    #[inline(always)]
    pub fn neg(&self, a: u64) -> u64 {
        if a == 0 { 0 } else { self.p - a }
    }

    /// `a * b mod p` (any `a`, `b < 2^64`).
    ///
    /// For $x = ab < 2^{125}$ and $2^{61} < p < 2^{62}$ (Barrett): with $m = \lfloor 2^{125}/p
    /// \rfloor < 2^{64}$, $\hat q = \lfloor \lfloor x / 2^{61} \rfloor m / 2^{64} \rfloor$
    /// satisfies $q - 2 \le \hat q \le q = \lfloor x/p \rfloor$, so $x - \hat q p < 3p <
    /// 2^{64}$ and two conditional subtractions give the residue (no division).
    #[inline(always)]
    pub fn mul(&self, a: u64, b: u64) -> u64 {
        let x = a as u128 * b as u128;
        if self.barrett == 0 || x >> 125 != 0 {
            return (x % self.p as u128) as u64;
        }
        let q = (((x >> 61) as u64 as u128 * self.barrett as u128) >> 64) as u64;
        let r = (x as u64).wrapping_sub(q.wrapping_mul(self.p));
        let r = r.min(r.wrapping_sub(self.p));
        r.min(r.wrapping_sub(self.p))
    }

    /// Shoup's quotient $\lfloor f 2^{64} / p \rfloor$ for a reduced constant `f`.
    ///
    /// With Barrett's $m$: $\hat q = \lfloor f m / 2^{61} \rfloor$ is within 2 below the
    /// quotient ($f 2^{64}/p - f m / 2^{61} < f / 2^{61} < 2$), corrected by at most two
    /// comparisons (no division).
    #[inline(always)]
    pub fn shoup(&self, f: u64) -> u64 {
        if self.barrett == 0 || f >= self.p {
            return (((f as u128) << 64) / self.p as u128) as u64;
        }
        let mut q = ((f as u128 * self.barrett as u128) >> 61) as u64;
        let mut r = ((f as u128) << 64) - q as u128 * self.p as u128;
        while r >= self.p as u128 {
            r -= self.p as u128;
            q += 1;
        }
        q
    }

    /// `f * x mod p` given `fs = shoup(f)`; any `x < 2^64`.
    #[inline(always)]
    pub fn mul_shoup(&self, f: u64, fs: u64, x: u64) -> u64 {
        let q = ((fs as u128 * x as u128) >> 64) as u64;
        let r = f.wrapping_mul(x).wrapping_sub(q.wrapping_mul(self.p));
        r.min(r.wrapping_sub(self.p))
    }

    /// `y -= f * x` elementwise (mod p). The elimination kernel of every routine here.
    #[inline]
    pub fn axpy_neg(&self, y: &mut [u64], x: &[u64], f: u64) {
        if f == 0 {
            return;
        }
        let fs = self.shoup(f);
        let p = self.p;
        for (yj, &xj) in y.iter_mut().zip(x) {
            let q = ((fs as u128 * xj as u128) >> 64) as u64;
            let r = f.wrapping_mul(xj).wrapping_sub(q.wrapping_mul(p));
            let r = r.min(r.wrapping_sub(p));
            let v = *yj + p - r;
            *yj = v.min(v.wrapping_sub(p));
        }
    }

    /// `y += f * x` elementwise (mod p).
    #[inline]
    pub fn axpy(&self, y: &mut [u64], x: &[u64], f: u64) {
        self.axpy_neg(y, x, self.neg(f));
    }

    /// `x *= f` elementwise (mod p).
    #[inline]
    pub fn scale(&self, x: &mut [u64], f: u64) {
        let fs = self.shoup(f);
        for xj in x.iter_mut() {
            *xj = self.mul_shoup(f, fs, *xj);
        }
    }

    /// `a^e mod p`.
    pub fn pow(&self, a: u64, e: u64) -> u64 {
        pow_by(a, e, 1 % self.p, |x, y| self.mul(x, y))
    }

    /// A square root of `a` modulo the odd prime `p` (Tonelli–Shanks): `Some(r)` with
    /// $r^2 \equiv a$, `None` when `a` is a non-residue (Euler's criterion
    /// $a^{(p-1)/2} \ne 1$). `Some(0)` for $a \equiv 0$.
    pub fn sqrt(&self, a: u64) -> Option<u64> {
        let (p, a) = (self.p, a % self.p);
        if a == 0 {
            return Some(0);
        }
        if p == 2 {
            return Some(a);
        }
        if self.pow(a, (p - 1) / 2) != 1 {
            return None;
        }
        // p - 1 = q 2^s with q odd; z a non-residue (exists: half of 1..p-1 are)
        let s = (p - 1).trailing_zeros();
        let q = (p - 1) >> s;
        let z = (2..p)
            .find(|&z| self.pow(z, (p - 1) / 2) == p - 1)
            .expect("an odd prime has a non-residue");
        let (mut m, mut c) = (s, self.pow(z, q));
        let (mut t, mut r) = (self.pow(a, q), self.pow(a, q.div_ceil(2)));
        // invariant: r^2 = a t, t of order dividing 2^(m-1), c of order 2^m
        while t != 1 {
            let mut i = 0;
            let mut t2 = t;
            while t2 != 1 {
                t2 = self.mul(t2, t2);
                i += 1;
            }
            let b = self.pow(c, 1 << (m - i - 1));
            m = i;
            c = self.mul(b, b);
            t = self.mul(t, c);
            r = self.mul(r, b);
        }
        Some(r)
    }

    /// Inverse of `a` modulo `p`; `None` when `a ≡ 0`.
    pub fn inv(&self, a: u64) -> Option<u64> {
        let a = a % self.p;
        if a == 0 {
            return None;
        }
        if self.p >= 1 << 63 {
            return Some(self.inv_wide(a));
        }
        // Extended Euclid on machine words: remainders below p, Bezout coefficients at
        // most p in absolute value (p < 2^63 fits i64).
        let (mut r0, mut r1) = (self.p, a);
        let (mut t0, mut t1) = (0i64, 1i64);
        while r1 != 0 {
            let q = r0 / r1;
            (r0, r1) = (r1, r0 - q * r1);
            (t0, t1) = (t1, t0 - (q as i64) * t1);
        }
        debug_assert_eq!(r0, 1);
        Some(if t0 < 0 {
            self.p - t0.unsigned_abs()
        } else {
            t0 as u64
        })
    }

    /// [`Prime::inv`] of a reduced nonzero `a` on 128-bit values (moduli of 63 and 64 bits).
    fn inv_wide(&self, a: u64) -> u64 {
        let (mut r0, mut r1) = (self.p as i128, a as i128);
        let (mut t0, mut t1) = (0i128, 1i128);
        while r1 != 0 {
            let q = r0 / r1;
            (r0, r1) = (r1, r0 - q * r1);
            (t0, t1) = (t1, t0 - q * t1);
        }
        t0.rem_euclid(self.p as i128) as u64
    }

    /// The residue of a signed machine integer.
    #[inline]
    pub fn reduce_i64(&self, x: i64) -> u64 {
        let r = (x as i128).rem_euclid(self.p as i128);
        r as u64
    }

    /// The residue of a big integer given by its sign and little-endian 64-bit limbs.
    pub fn reduce_limbs(&self, negative: bool, limbs: &[u64]) -> u64 {
        let r = match limbs {
            [] => 0,
            [l] => l % self.p,
            _ => {
                // Horner in base 2^64: r <- r * (2^64 mod p) + l, one Shoup product per limb
                let t = ((1u128 << 64) % self.p as u128) as u64;
                let ts = self.shoup(t);
                limbs
                    .iter()
                    .rev()
                    .fold(0u64, |r, &l| self.add(self.mul_shoup(t, ts, r), l % self.p))
            }
        };
        if negative { self.neg(r) } else { r }
    }
}

/// Deterministic Miller–Rabin for 64-bit integers (bases of Jim Sinclair, proven for
/// all $n < 2^{64}$).
pub fn is_prime_u64(n: u64) -> bool {
    if n < 2 {
        return false;
    }
    for q in [2u64, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37] {
        if n.is_multiple_of(q) {
            return n == q;
        }
    }
    let pr = Prime::new(n);
    let (mut d, mut s) = (n - 1, 0);
    while d % 2 == 0 {
        d /= 2;
        s += 1;
    }
    'bases: for a in [2u64, 325, 9375, 28178, 450775, 9780504, 1795265022] {
        let a = a % n;
        if a == 0 {
            continue;
        }
        let mut x = pr.pow(a, d);
        if x == 1 || x == n - 1 {
            continue;
        }
        for _ in 1..s {
            x = pr.mul(x, x);
            if x == n - 1 {
                continue 'bases;
            }
        }
        return false;
    }
    true
}

static PRIMES: OnceLock<Mutex<Vec<u64>>> = OnceLock::new();

/// The `i`-th prime below $2^{62}$ in decreasing order (0-based), cached process-wide.
pub fn nth_prime(i: usize) -> Prime {
    let cache = PRIMES.get_or_init(|| Mutex::new(Vec::new()));
    let mut v = cache.lock().unwrap_or_else(|e| e.into_inner());
    let mut c = v.last().copied().unwrap_or(1u64 << 62);
    while v.len() <= i {
        c -= if c % 2 == 0 { 1 } else { 2 };
        if is_prime_u64(c) {
            v.push(c);
        }
    }
    Prime::new(v[i])
}

/// An endless iterator over the primes of [`nth_prime`], starting at index `start`.
pub fn primes(start: usize) -> impl Iterator<Item = Prime> {
    (start..).map(nth_prime)
}

/// $\log_2 p$ lower bound used when counting how many primes a bound needs.
pub const PRIME_BITS: f64 = 61.0;

/// `a^e` by square-and-multiply with the modular product `mul` and its unit `one` (the one
/// loop of [`Prime::pow`] and of `Fp::powu` in `poly::fp`).
#[inline]
pub fn pow_by(mut a: u64, mut e: u64, one: u64, mul: impl Fn(u64, u64) -> u64) -> u64 {
    let mut r = one;
    while e > 0 {
        if e & 1 == 1 {
            r = mul(r, a);
        }
        a = mul(a, a);
        e >>= 1;
    }
    r
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn primes_are_prime_and_decreasing() {
        let ps: Vec<u64> = primes(0).take(20).map(|p| p.p).collect();
        for w in ps.windows(2) {
            assert!(w[0] > w[1]);
        }
        for &p in &ps {
            assert!(p > 1 << 61 && p < 1 << 62);
            // a non-trivial Fermat check with a base outside the Miller-Rabin set
            assert_eq!(Prime::new(p).pow(3, p - 1), 1);
        }
        assert!(is_prime_u64(2_305_843_009_213_693_951)); // 2^61 - 1
        assert!(!is_prime_u64(3_215_031_751)); // strong pseudoprime to bases 2, 3, 5, 7
        assert!(!is_prime_u64(1 << 62));
    }

    /// Barrett products and word-size inverses against `u128` remainders: every prime of
    /// the sequence, small and 63/64-bit moduli (the `%` and wide paths), reduced and
    /// unreduced operands, the extremes `0, 1, p - 1`.
    #[test]
    fn products_and_inverses_match_u128() {
        let mut rng = crate::rng::SplitMix64(0x9e37);
        let moduli = (0..8).map(|i| nth_prime(i).p).chain([
            10007,
            65537,
            (1 << 61) - 1,
            (1 << 63) + 29,
            u64::MAX - 58,
        ]);
        for p in moduli {
            let pr = Prime::new(p);
            let mut xs = vec![0, 1, p - 1, p / 2];
            xs.extend((0..300).map(|_| rng.next_u64() % p));
            for (i, &x) in xs.iter().enumerate() {
                let y = xs[(i * 7 + 3) % xs.len()];
                assert_eq!(pr.mul(x, y), ((x as u128 * y as u128) % p as u128) as u64);
                assert_eq!(pr.shoup(x), (((x as u128) << 64) / p as u128) as u64);
                let (ux, uy) = (rng.next_u64(), rng.next_u64());
                assert_eq!(
                    pr.mul(ux, uy),
                    ((ux as u128 * uy as u128) % p as u128) as u64
                );
                if x != 0 {
                    let v = pr.inv(x).expect("nonzero");
                    assert!(v < p);
                    assert_eq!((x as u128 * v as u128) % p as u128, 1);
                }
            }
            assert_eq!(pr.inv(0), None);
            assert_eq!(pr.inv(p), None);
        }
    }

    /// Tonelli–Shanks: r^2 = a for residues, `None` exactly for non-residues (Euler's
    /// criterion), on the word primes (p = 3 and p = 1 mod 4 among them) and small primes
    /// with a large power of 2 in p - 1.
    #[test]
    fn square_roots_modulo_primes() {
        let moduli = (0..6)
            .map(|i| nth_prime(i).p)
            .chain([3, 5, 13, 17, 97, 193, 65537, 7681]);
        for p in moduli {
            let pr = Prime::new(p);
            let mut found = [0usize; 2];
            for a in (0..200u64).chain([p - 1, p - 2, p / 3]) {
                let a = a % p;
                match pr.sqrt(a) {
                    Some(r) => {
                        assert!(r < p);
                        assert_eq!(pr.mul(r, r), a, "sqrt({a}) mod {p}");
                        found[0] += 1;
                    }
                    None => {
                        assert_eq!(pr.pow(a, (p - 1) / 2), p - 1, "{a} mod {p}");
                        found[1] += 1;
                    }
                }
            }
            assert!(found[0] > 0 && found[1] > 0, "both kinds met modulo {p}");
        }
    }

    #[test]
    fn arithmetic_matches_u128() {
        let pr = nth_prime(0);
        let p = pr.p;
        let mut x = 0x1234_5678_9abc_def1u64 % p;
        for _ in 0..1000 {
            x = (x
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407))
                % p;
            let y = x.rotate_left(17) % p;
            let want = ((x as u128 * y as u128) % p as u128) as u64;
            assert_eq!(pr.mul_shoup(x, pr.shoup(x), y), want);
            assert_eq!(pr.add(x, y), ((x as u128 + y as u128) % p as u128) as u64);
            assert_eq!(pr.add(pr.sub(x, y), y), x);
            if x != 0 {
                assert_eq!(pr.mul(x, pr.inv(x).unwrap()), 1);
            }
            let mut row = [y, x, 0];
            pr.axpy_neg(&mut row, &[x, y, 5], y);
            assert_eq!(row[0], pr.sub(y, pr.mul(x, y)));
            assert_eq!(row[2], pr.neg(pr.mul(5, y)));
        }
        assert_eq!(pr.reduce_i64(-1), p - 1);
        assert_eq!(
            pr.reduce_limbs(false, &[0, 1]),
            ((1u128 << 64) % p as u128) as u64
        );
        // many limbs (the Shoup Horner path) against big-integer remainders
        for limbs in [
            vec![u64::MAX, u64::MAX, u64::MAX],
            vec![1, 2, 3, 4, 5, u64::MAX - 7],
            vec![p, p - 1, p + 1, 0],
        ] {
            let big = num_bigint::BigUint::from_slice(
                &limbs
                    .iter()
                    .flat_map(|&l| [l as u32, (l >> 32) as u32])
                    .collect::<Vec<_>>(),
            );
            let want: u64 = (&big % p).try_into().unwrap();
            assert_eq!(pr.reduce_limbs(false, &limbs), want);
            assert_eq!(pr.reduce_limbs(true, &limbs), pr.neg(want));
        }
    }
}
