//! Modular gcd of univariate integer polynomials (the base case of the heuristic gcd).
//!
//! For primitive $f, g$ with $\gamma = \gcd(\operatorname{lc} f, \operatorname{lc} g)$: modulo
//! 31-bit primes not dividing both leading coefficients, $h_p = \gamma \cdot$ the monic gcd of the
//! images; images of too large degree are unlucky and dropped, a smaller degree restarts the
//! Chinese remaindering. When the combined image stops changing, its primitive part is
//! accepted only if it divides both $f$ and $g$ exactly (Brown's univariate scheme), so the
//! answer is always the gcd; `None` after a bounded number of primes.

use crate::poly::fp::Zp;
use crate::poly::zpoly::ZPoly;
use num_bigint::{BigInt, Sign};
use num_integer::Integer;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// Deterministic Miller–Rabin for $n < 2^{32}$ (bases 2, 7, 61).
fn is_prime_u32(n: u64) -> bool {
    if n < 2 {
        return false;
    }
    for p in [2u64, 3, 5, 7, 11, 13] {
        if n % p == 0 {
            return n == p;
        }
    }
    let (mut d, mut s) = (n - 1, 0);
    while d % 2 == 0 {
        d /= 2;
        s += 1;
    }
    let pw = |mut a: u64, mut e: u64| {
        let mut r = 1u64;
        a %= n;
        while e > 0 {
            if e & 1 == 1 {
                r = r * a % n;
            }
            a = a * a % n;
            e >>= 1;
        }
        r
    };
    'outer: for a in [2u64, 7, 61] {
        if a % n == 0 {
            continue;
        }
        let mut x = pw(a, d);
        if x == 1 || x == n - 1 {
            continue;
        }
        for _ in 1..s {
            x = x * x % n;
            if x == n - 1 {
                continue 'outer;
            }
        }
        return false;
    }
    true
}

fn reduce(c: &BigInt, p: u64) -> u64 {
    let r = c.mod_floor(&BigInt::from(p));
    r.to_u64().unwrap_or(0)
}

/// gcd of primitive `f`, `g` (degrees >= 1) with positive leading coefficient, or `None` when
/// the prime budget runs out.
pub(crate) fn gcd_modular(f: &ZPoly, g: &ZPoly) -> Option<ZPoly> {
    let gamma = f.leading_coeff().gcd(&g.leading_coeff());
    let bits = f.max_norm().bits().max(g.max_norm().bits()) as usize;
    let cap = 2 * (bits + f.deg0().max(g.deg0()) * 2) / 30 + 40;
    let mut m = BigInt::one();
    let mut h: Vec<BigInt> = Vec::new();
    let mut dcur = usize::MAX;
    let mut p: u64 = (1 << 31) - 1;
    let mut used = 0;
    while used < cap {
        p -= 2;
        if !is_prime_u32(p) {
            continue;
        }
        let zp = Zp::new(p);
        if reduce(&f.leading_coeff(), p) == 0 || reduce(&g.leading_coeff(), p) == 0 {
            continue;
        }
        used += 1;
        let a: Vec<u64> = f.coeffs().iter().map(|c| reduce(c, p)).collect();
        let b: Vec<u64> = g.coeffs().iter().map(|c| reduce(c, p)).collect();
        let hp = zp.gcd(&a, &b);
        let d = hp.len() - 1;
        if d == 0 {
            return Some(ZPoly::one());
        }
        if d > dcur {
            continue;
        }
        let gm = reduce(&gamma, p);
        let hp: Vec<u64> = hp.iter().map(|c| zp.mulm(*c, gm)).collect();
        if d < dcur {
            dcur = d;
            m = BigInt::one();
            h = vec![BigInt::zero(); d + 1];
        }
        // CRT: x' = x + m * ((r - x) / m mod p), symmetric modulo m p
        let minv = zp.inv(reduce(&m, p));
        let mp = &m * BigInt::from(p);
        let half = &mp >> 1u32;
        let mut changed = false;
        for (x, &r) in h.iter_mut().zip(&hp) {
            let t = zp.mulm(zp.subm(r, reduce(x, p)), minv);
            if t != 0 {
                let mut y = &*x + &m * BigInt::from(t);
                if y > half {
                    y -= &mp;
                } else if y < -&half {
                    y += &mp;
                }
                if y != *x {
                    changed = true;
                }
                *x = y;
            }
        }
        m = mp;
        if !changed && used > 1 {
            let cand = ZPoly::new(h.clone()).primitive_part();
            if f.div_exact(&cand).is_some() && g.div_exact(&cand).is_some() {
                return Some(if cand.leading_coeff().sign() == Sign::Minus {
                    -cand
                } else {
                    cand
                });
            }
        }
    }
    None
}

/// gcd of integer polynomials (contents included, positive leading coefficient).
pub(crate) fn gcd_zpoly(f: &ZPoly, g: &ZPoly) -> ZPoly {
    if f.is_zero() || g.is_zero() || f.deg0() == 0 || g.deg0() == 0 {
        return f.gcd(g);
    }
    let c = f.content().abs().gcd(&g.content().abs());
    let (pf, pg) = (f.primitive_part(), g.primitive_part());
    match gcd_modular(&pf, &pg) {
        Some(h) => h.scale(&c),
        None => f.gcd(g),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn modular_matches_prs() {
        let a = ZPoly::from_i64s(&[3, -7, 0, 12, 5]);
        let b = ZPoly::from_i64s(&[-1, 4, 9]);
        let c = ZPoly::from_i64s(&[2, 0, -5, 1]);
        let big = ZPoly::from_i64s(&[1 << 40, -(1 << 50), 3]);
        let f = &(&a * &b) * &big;
        let g = &(&a * &c) * &big;
        assert_eq!(gcd_zpoly(&f, &g), f.gcd(&g));
        assert_eq!(gcd_zpoly(&b, &c), ZPoly::one());
        assert_eq!(
            gcd_zpoly(&f.scale(&6.into()), &g.scale(&4.into())),
            f.gcd(&g).scale(&2.into())
        );
        assert!(is_prime_u32(2147483647) && !is_prime_u32(2147483649));
    }
}
