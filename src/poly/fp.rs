//! Polynomials over a word-size prime field $\mathbb{F}_p$, $p < 2^{32}$: the $\mathbb{F}_p[x]$
//! toolkit of the factoring code and the modular gcd of [`crate::poly::zpoly`] (a leaf:
//! it depends on nothing else in the crate).
//!
//! Elements are `u64` in $[0, p)$; products fit in `u64`, and convolutions accumulate in
//! `u128` with a single reduction per output coefficient. A polynomial is a `Vec<u64>`, low
//! degree first, without trailing zeros (the zero polynomial is empty).
//!
//! | function | computes |
//! |---|---|
//! | [`Zp::mul`], [`Zp::sub`], [`Zp::divrem`], [`Zp::rem`] | ring operations, division with remainder |
//! | [`Zp::gcd`], [`Zp::xgcd`] | monic gcd; $s a + t b = \gcd(a, b)$ |
//! | [`Zp::powmod`] | $a^e \bmod m$ for a multi-word exponent |
//! | [`Zp::reduce`] | the image of an integer polynomial |

use num_bigint::{BigInt, BigUint};
use num_traits::Zero;

/// Polynomial over $\mathbb{F}_p$, low degree first, normalized.
pub(crate) type PolyP = Vec<u64>;

/// The prime field $\mathbb{F}_p$ as a context value.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Zp {
    pub p: u64,
}

pub(crate) fn trim(a: &mut PolyP) {
    while a.last() == Some(&0) {
        a.pop();
    }
}

impl Zp {
    /// # Panics
    /// If `p` is not below $2^{32}$ (primality is the caller's duty).
    pub fn new(p: u64) -> Self {
        assert!((2..1 << 32).contains(&p), "Zp: modulus out of range");
        Zp { p }
    }

    #[inline]
    pub fn mulm(&self, a: u64, b: u64) -> u64 {
        a * b % self.p
    }

    #[inline]
    pub fn subm(&self, a: u64, b: u64) -> u64 {
        if a >= b { a - b } else { a + self.p - b }
    }

    pub fn powu(&self, a: u64, e: u64) -> u64 {
        crate::qkernels::prime::pow_by(a, e, 1 % self.p, |x, y| self.mulm(x, y))
    }

    /// Inverse of a nonzero element (Fermat).
    pub fn inv(&self, a: u64) -> u64 {
        debug_assert!(!a.is_multiple_of(self.p));
        self.powu(a, self.p - 2)
    }

    /// Reduction modulo $p$ of an integer polynomial given by its coefficients (low degree
    /// first).
    pub fn reduce(&self, coeffs: &[BigInt]) -> PolyP {
        let pb = BigInt::from(self.p);
        let mut v: PolyP = coeffs
            .iter()
            .map(|c| {
                let r = c % &pb;
                let r = if r.sign() == num_bigint::Sign::Minus {
                    r + &pb
                } else {
                    r
                };
                r.iter_u64_digits().next().unwrap_or(0)
            })
            .collect();
        trim(&mut v);
        v
    }

    pub fn sub(&self, a: &[u64], b: &[u64]) -> PolyP {
        let n = a.len().max(b.len());
        let mut v: PolyP = (0..n)
            .map(|i| self.subm(*a.get(i).unwrap_or(&0), *b.get(i).unwrap_or(&0)))
            .collect();
        trim(&mut v);
        v
    }

    pub fn scale(&self, a: &[u64], c: u64) -> PolyP {
        let mut v: PolyP = a.iter().map(|&x| self.mulm(x, c)).collect();
        trim(&mut v);
        v
    }

    /// Schoolbook product with `u128` accumulation.
    pub fn mul(&self, a: &[u64], b: &[u64]) -> PolyP {
        if a.is_empty() || b.is_empty() {
            return Vec::new();
        }
        let n = a.len() + b.len() - 1;
        let mut v = Vec::with_capacity(n);
        let p = self.p as u128;
        for k in 0..n {
            let lo = k.saturating_sub(b.len() - 1);
            let hi = k.min(a.len() - 1);
            let mut acc: u128 = 0;
            for i in lo..=hi {
                acc += (a[i] * b[k - i]) as u128;
            }
            v.push((acc % p) as u64);
        }
        trim(&mut v);
        v
    }

    /// Quotient and remainder of `a` by nonzero `b`.
    pub fn divrem(&self, a: &[u64], b: &[u64]) -> (PolyP, PolyP) {
        assert!(!b.is_empty(), "Zp::divrem: division by zero polynomial");
        if a.len() < b.len() {
            return (Vec::new(), a.to_vec());
        }
        let db = b.len() - 1;
        let inv = self.inv(b[db]);
        let mut r = a.to_vec();
        let mut q = vec![0; a.len() - db];
        for k in (0..q.len()).rev() {
            let t = self.mulm(r[k + db], inv);
            q[k] = t;
            if t != 0 {
                let nt = self.p - t;
                for j in 0..db {
                    r[k + j] = (r[k + j] + nt * b[j]) % self.p;
                }
            }
            r[k + db] = 0;
        }
        r.truncate(db);
        trim(&mut r);
        trim(&mut q);
        (q, r)
    }

    pub fn rem(&self, a: &[u64], b: &[u64]) -> PolyP {
        self.divrem(a, b).1
    }

    pub fn monic(&self, a: &[u64]) -> PolyP {
        match a.last() {
            None => Vec::new(),
            Some(&l) => self.scale(a, self.inv(l)),
        }
    }

    /// Monic gcd (zero if both are zero).
    pub fn gcd(&self, a: &[u64], b: &[u64]) -> PolyP {
        let (mut a, mut b) = (a.to_vec(), b.to_vec());
        while !b.is_empty() {
            let r = self.rem(&a, &b);
            a = b;
            b = r;
        }
        self.monic(&a)
    }

    /// Extended Euclid: $(g, s, t)$ with $s a + t b = g$ monic, $\deg s < \deg b$,
    /// $\deg t < \deg a$ (for $\deg a, \deg b \ge 1$).
    pub fn xgcd(&self, a: &[u64], b: &[u64]) -> (PolyP, PolyP, PolyP) {
        let (mut r0, mut r1) = (a.to_vec(), b.to_vec());
        let (mut s0, mut s1) = (vec![1], Vec::new());
        let (mut t0, mut t1) = (Vec::new(), vec![1]);
        while !r1.is_empty() {
            let (q, r) = self.divrem(&r0, &r1);
            let s2 = self.sub(&s0, &self.mul(&q, &s1));
            let t2 = self.sub(&t0, &self.mul(&q, &t1));
            r0 = std::mem::replace(&mut r1, r);
            s0 = std::mem::replace(&mut s1, s2);
            t0 = std::mem::replace(&mut t1, t2);
        }
        let Some(&l) = r0.last() else {
            return (r0, s0, t0);
        };
        let li = self.inv(l);
        (
            self.scale(&r0, li),
            self.scale(&s0, li),
            self.scale(&t0, li),
        )
    }

    /// Formal derivative.
    pub fn derivative(&self, a: &[u64]) -> PolyP {
        let mut v: PolyP = a
            .iter()
            .enumerate()
            .skip(1)
            .map(|(i, &c)| self.mulm(c, i as u64 % self.p))
            .collect();
        trim(&mut v);
        v
    }

    /// $a^e \bmod m$ ($m$ of degree $\ge 1$).
    pub fn powmod(&self, a: &[u64], e: &BigUint, m: &[u64]) -> PolyP {
        let mut r: PolyP = vec![1];
        if e.is_zero() {
            return self.rem(&r, m);
        }
        let base = self.rem(a, m);
        for i in (0..e.bits()).rev() {
            r = self.rem(&self.mul(&r, &r), m);
            if e.bit(i) {
                r = self.rem(&self.mul(&r, &base), m);
            }
        }
        r
    }

    /// Square-free test of a nonzero polynomial: $\gcd(a, a') = 1$.
    pub fn is_squarefree(&self, a: &[u64]) -> bool {
        let d = self.derivative(a);
        !d.is_empty() && self.gcd(a, &d).len() == 1
    }
}

/// The primes $\ge$ `start`, in increasing order, by trial division (used for short lists).
pub(crate) fn primes_from(start: u64) -> impl Iterator<Item = u64> {
    (start.max(2)..).filter(|&n| {
        let mut d = 2;
        while d * d <= n {
            if n % d == 0 {
                return false;
            }
            d += 1;
        }
        true
    })
}
