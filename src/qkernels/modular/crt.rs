//! Chinese remaindering and rational reconstruction.
//!
//! [`Crt`] lifts residues $(r_0, \dots, r_{k-1})$ modulo distinct word primes to the unique
//! $x \in (-M/2, M/2]$, $M = \prod p_i$, with $x \equiv r_i \pmod{p_i}$, by Garner's
//! mixed-radix algorithm (all word arithmetic) and one limb-level Horner pass.
//!
//! [`rational_reconstruct`] finds $a/b$ with $a \equiv u b \pmod M$, $|a| \le N$,
//! $0 < b \le D$ (unique when $2ND < M$), by the half extended Euclidean algorithm.
//! [`CommonDenominator`] reconstructs a whole vector over one denominator, which costs one
//! multiplication per entry once the denominator has been found.

use crate::qkernels::prime::Prime;
use num_bigint::{BigInt, BigUint, Sign};
use num_integer::Integer;
use num_traits::{One, Signed, Zero};

/// Precomputed Garner constants for a fixed list of primes.
#[derive(Clone, Debug)]
pub struct Crt {
    primes: Vec<Prime>,
    /// `inv[j]` $= (p_0 \cdots p_{j-1})^{-1} \bmod p_j$, with its Shoup quotient.
    inv: Vec<(u64, u64)>,
    /// `pmod[j][i]` $= p_i \bmod p_j$ for $i < j$, with its Shoup quotient.
    pmod: Vec<Vec<(u64, u64)>>,
    modulus: BigInt,
    half: BigInt,
}

impl Crt {
    /// Constants for `primes` (distinct).
    pub fn new(primes: &[Prime]) -> Self {
        let mut inv = Vec::with_capacity(primes.len());
        let mut pmod = Vec::with_capacity(primes.len());
        let mut modulus = BigInt::one();
        for (j, pj) in primes.iter().enumerate() {
            let row: Vec<(u64, u64)> = primes[..j]
                .iter()
                .map(|pi| {
                    let v = pi.p % pj.p;
                    (v, pj.shoup(v))
                })
                .collect();
            let prod = row.iter().fold(1u64, |acc, &(v, _)| pj.mul(acc, v));
            let iv = pj.inv(prod).expect("distinct primes");
            inv.push((iv, pj.shoup(iv)));
            pmod.push(row);
            modulus *= pj.p;
        }
        let half = &modulus >> 1u32;
        Crt {
            primes: primes.to_vec(),
            inv,
            pmod,
            modulus,
            half,
        }
    }

    /// $M = \prod p_i$.
    pub fn modulus(&self) -> &BigInt {
        &self.modulus
    }

    /// The primes, in order.
    pub fn primes(&self) -> &[Prime] {
        &self.primes
    }

    /// The unique $x \in [0, M)$ with $x \equiv$ `res(i)` mod $p_i$.
    pub fn lift_nonneg(&self, res: impl Fn(usize) -> u64) -> BigInt {
        let k = self.primes.len();
        let mut digits = [0u64; 64];
        let mut dv = Vec::new();
        let digits: &mut [u64] = if k <= 64 {
            &mut digits[..k]
        } else {
            dv.resize(k, 0);
            &mut dv
        };
        let mut all_zero = true;
        for j in 0..k {
            let pj = &self.primes[j];
            // value of the mixed-radix prefix modulo p_j, by Horner from the top digit
            let mut s = 0u64;
            for i in (0..j).rev() {
                let (v, vs) = self.pmod[j][i];
                s = pj.add(pj.mul_shoup(v, vs, s), digits[i] % pj.p);
            }
            let (iv, ivs) = self.inv[j];
            let d = pj.mul_shoup(iv, ivs, pj.sub(res(j) % pj.p, s));
            all_zero &= d == 0;
            digits[j] = d;
        }
        if all_zero {
            return BigInt::zero();
        }
        // Horner over limbs: acc = acc * p_i + d_i, from the top digit down
        let mut limbs: Vec<u64> = Vec::with_capacity(k + 1);
        for i in (0..k).rev() {
            let pi = self.primes[i].p as u128;
            let mut carry = digits[i] as u128;
            for l in limbs.iter_mut() {
                let t = *l as u128 * pi + carry;
                *l = t as u64;
                carry = t >> 64;
            }
            if carry != 0 {
                limbs.push(carry as u64);
            }
        }
        let mut u32s = Vec::with_capacity(2 * limbs.len());
        for l in limbs {
            u32s.push(l as u32);
            u32s.push((l >> 32) as u32);
        }
        BigInt::from_biguint(Sign::Plus, BigUint::new(u32s))
    }

    /// The unique $x \in (-M/2, M/2]$ with $x \equiv$ `res(i)` mod $p_i$.
    pub fn lift(&self, res: impl Fn(usize) -> u64) -> BigInt {
        let x = self.lift_nonneg(res);
        if x > self.half { x - &self.modulus } else { x }
    }

    /// Symmetric representative of `x mod M`.
    pub fn symmetric(&self, x: &BigInt) -> BigInt {
        let r = x.mod_floor(&self.modulus);
        if r > self.half { r - &self.modulus } else { r }
    }

    /// The reconstruction bound $N = D = \lfloor \sqrt{(M-1)/2} \rfloor$, so $2ND < M$.
    pub fn rr_bound(&self) -> BigInt {
        ((&self.modulus - 1u32) >> 1u32).sqrt()
    }
}

/// Rational reconstruction: `Some((a, b))` with $a \equiv u b \pmod m$, $|a| \le N$,
/// $0 < b \le D$, $\gcd(a, b) = 1$; `None` when no such pair exists.
pub fn rational_reconstruct(
    u: &BigInt,
    m: &BigInt,
    n_bound: &BigInt,
    d_bound: &BigInt,
) -> Option<(BigInt, BigInt)> {
    let mut r0 = m.clone();
    let mut r1 = u.mod_floor(m);
    let (mut t0, mut t1) = (BigInt::zero(), BigInt::one());
    while &r1 > n_bound {
        let (q, r) = r0.div_rem(&r1);
        r0 = std::mem::replace(&mut r1, r);
        let t = &t0 - &q * &t1;
        t0 = std::mem::replace(&mut t1, t);
    }
    let (a, b) = if t1.is_negative() {
        (-r1, -t1)
    } else {
        (r1, t1)
    };
    if b.is_zero() || &b > d_bound || !crate::qkernels::gcd::gcd(&a, &b).is_one() {
        return None;
    }
    Some((a, b))
}

/// Reconstruction of a vector of rationals over one common denominator.
#[derive(Clone, Debug)]
pub struct CommonDenominator {
    /// The common denominator $d > 0$.
    pub den: BigInt,
    /// Numerators $n_i$ with $n_i \equiv d u_i \pmod M$ and $|n_i| \le N$.
    pub nums: Vec<BigInt>,
}

impl CommonDenominator {
    /// Reconstructs $u_i \equiv n_i / d$ for the lifted residues `us` (any representative).
    /// `None` when some entry has no reconstruction within the bounds of `crt`.
    pub fn reconstruct(crt: &Crt, us: impl Iterator<Item = BigInt>) -> Option<Self> {
        Self::reconstruct_mod(crt.modulus(), us)
    }

    /// [`CommonDenominator::reconstruct`] modulo any $M \ge 2$ (bounds
    /// $N = D = \lfloor \sqrt{(M-1)/2} \rfloor$, as [`Crt::rr_bound`]).
    pub fn reconstruct_mod(m: &BigInt, us: impl Iterator<Item = BigInt>) -> Option<Self> {
        let bound = ((m - 1u32) >> 1u32).sqrt();
        let half = m >> 1u32;
        let symmetric = |x: &BigInt| {
            let r = x.mod_floor(m);
            if r > half { r - m } else { r }
        };
        let mut den = BigInt::one();
        let mut nums: Vec<BigInt> = Vec::new();
        for u in us {
            let v = if den.is_one() {
                symmetric(&u)
            } else {
                symmetric(&(u * &den))
            };
            if v.abs() <= bound {
                nums.push(v);
                continue;
            }
            let (a, b) = rational_reconstruct(&v, m, &bound, &bound)?;
            den *= &b;
            if den > bound {
                return None;
            }
            for x in nums.iter_mut() {
                *x *= &b;
            }
            nums.push(a);
        }
        Some(CommonDenominator { den, nums })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::qkernels::prime::primes;

    #[test]
    fn lift_roundtrip() {
        let ps: Vec<Prime> = primes(0).take(5).collect();
        let crt = Crt::new(&ps);
        let x: BigInt = "-123456789012345678901234567890123456789012345"
            .parse()
            .unwrap();
        let res: Vec<u64> = ps
            .iter()
            .map(|p| {
                let (s, l) = x.to_u64_digits();
                p.reduce_limbs(s == Sign::Minus, &l)
            })
            .collect();
        assert_eq!(crt.lift(|i| res[i]), x);
        assert_eq!(crt.lift(|_| 0), BigInt::zero());
        assert_eq!(crt.lift(|i| ps[i].p - 1), BigInt::from(-1));
    }

    #[test]
    fn reconstruct_fractions() {
        let ps: Vec<Prime> = primes(0).take(4).collect();
        let crt = Crt::new(&ps);
        let m = crt.modulus().clone();
        let b = crt.rr_bound();
        let (num, den) = (BigInt::from(-355_113i64), BigInt::from(1_130_000_009i64));
        let u = (&num * den.modinv(&m).unwrap()).mod_floor(&m);
        assert_eq!(
            rational_reconstruct(&u, &m, &b, &b),
            Some((num, den.clone()))
        );
        let us = vec![
            (BigInt::from(3) * den.modinv(&m).unwrap()).mod_floor(&m),
            BigInt::from(7),
            (BigInt::from(-2) * den.modinv(&m).unwrap()).mod_floor(&m),
        ];
        let cd = CommonDenominator::reconstruct(&crt, us.into_iter()).unwrap();
        assert_eq!(cd.den, den);
        assert_eq!(cd.nums[1], BigInt::from(7) * &den);
        assert_eq!(cd.nums[2], BigInt::from(-2));
    }
}
