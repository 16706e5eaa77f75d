//! Multifactor Hensel lifting over $\mathbb{Z}/p^k$.
//!
//! Given $f \in \mathbb{Z}\lbrack x\rbrack$ with $p \nmid \operatorname{lc}(f)$ and
//! $f \equiv \operatorname{lc}(f)\, g_1 \cdots g_r \pmod p$, $g_i$ monic and pairwise
//! coprime, compute monic $G_i \equiv g_i \pmod p$ with
//! $f \equiv \operatorname{lc}(f)\, G_1 \cdots G_r \pmod{p^k}$.
//!
//! The factor list is split in two halves $g = \operatorname{lc}(f) \prod_{A} g_i$,
//! $h = \prod_B g_i$ (a node of the factor tree); the pair $(g, h)$ and Bézout cofactors
//! $s g + t h \equiv 1$ are lifted quadratically $p \to p^2 \to \dots \to p^k$ by the Hensel
//! step of von zur Gathen & Gerhard (*Modern Computer Algebra*, Alg. 15.10), with the
//! corrections computed on the quotient $e / m$ (smaller numbers); then each half recurses.
//! Products use Kronecker substitution into one big integer multiplication.

use crate::poly::fp::{PolyP, Zp};
use num_bigint::{BigInt, BigUint, Sign};
use num_integer::Integer;
use num_traits::{One, Zero};

/// Polynomial over $\mathbb{Z}/m$, coefficients in $[0, m)$, low degree first.
pub(crate) type PolyM = Vec<BigInt>;

fn trim(a: &mut PolyM) {
    while a.last().is_some_and(|c| c.is_zero()) {
        a.pop();
    }
}

/// Exact product of polynomials with NONNEGATIVE coefficients, by Kronecker substitution:
/// pack each into one integer with 32-bit-aligned slots wide enough for every product
/// coefficient, multiply once, unpack.
pub(crate) fn kron_mul(a: &[BigInt], b: &[BigInt]) -> PolyM {
    if a.is_empty() || b.is_empty() {
        return Vec::new();
    }
    debug_assert!(a.iter().chain(b).all(|c| c.sign() != Sign::Minus));
    let ba = a.iter().map(|c| c.bits()).max().unwrap_or(0);
    let bb = b.iter().map(|c| c.bits()).max().unwrap_or(0);
    let len = a.len().min(b.len()) as u64;
    let bits = ba + bb + (64 - len.leading_zeros() as u64) + 1;
    let w = bits.div_ceil(32) as usize;
    let pack = |v: &[BigInt]| {
        let mut d = vec![0u32; v.len() * w];
        for (i, c) in v.iter().enumerate() {
            for (j, x) in c.iter_u32_digits().enumerate() {
                d[i * w + j] = x;
            }
        }
        BigUint::new(d)
    };
    let prod = pack(a) * pack(b);
    let digits = prod.to_u32_digits();
    let n = a.len() + b.len() - 1;
    let mut out = Vec::with_capacity(n);
    for i in 0..n {
        let lo = (i * w).min(digits.len());
        let hi = ((i + 1) * w).min(digits.len());
        out.push(BigInt::from_biguint(
            Sign::Plus,
            BigUint::from_slice(&digits[lo..hi]),
        ));
    }
    trim(&mut out);
    out
}

fn reduce(mut a: PolyM, m: &BigInt) -> PolyM {
    for c in a.iter_mut() {
        *c = c.mod_floor(m);
    }
    trim(&mut a);
    a
}

fn mul_mod(a: &[BigInt], b: &[BigInt], m: &BigInt) -> PolyM {
    reduce(kron_mul(a, b), m)
}

fn add_mod(a: &[BigInt], b: &[BigInt], m: &BigInt) -> PolyM {
    let n = a.len().max(b.len());
    let z = BigInt::zero();
    let v = (0..n)
        .map(|i| a.get(i).unwrap_or(&z) + b.get(i).unwrap_or(&z))
        .collect();
    reduce(v, m)
}

/// `a + m1 * b` for `b` reduced (the result stays in $[0, m_1 m')$ when $a < m_1$).
fn add_scaled(a: &[BigInt], b: &[BigInt], m1: &BigInt) -> PolyM {
    let n = a.len().max(b.len());
    let z = BigInt::zero();
    let mut v: PolyM = (0..n)
        .map(|i| a.get(i).unwrap_or(&z) + m1 * b.get(i).unwrap_or(&z))
        .collect();
    trim(&mut v);
    v
}

/// `(a - m1 * b) mod m2`.
fn sub_scaled(a: &[BigInt], b: &[BigInt], m1: &BigInt, m2: &BigInt) -> PolyM {
    let n = a.len().max(b.len());
    let z = BigInt::zero();
    let v = (0..n)
        .map(|i| a.get(i).unwrap_or(&z) - m1 * b.get(i).unwrap_or(&z))
        .collect();
    reduce(v, m2)
}

/// Quotient and remainder modulo `m` by a MONIC `h` (leading coefficient 1 mod `m`).
/// Lazy reduction: only the coefficient that becomes a quotient digit is reduced.
fn divrem_monic(a: &[BigInt], h: &[BigInt], m: &BigInt) -> (PolyM, PolyM) {
    let dh = h.len() - 1;
    if a.len() <= dh {
        return (Vec::new(), a.to_vec());
    }
    let mut r = a.to_vec();
    let mut q = vec![BigInt::zero(); a.len() - dh];
    for k in (0..q.len()).rev() {
        let t = r[k + dh].mod_floor(m);
        if !t.is_zero() {
            for j in 0..dh {
                r[k + j] -= &t * &h[j];
            }
        }
        q[k] = t;
    }
    r.truncate(dh);
    (reduce(q, m), reduce(r, m))
}

/// `(a - b) / m1 mod mp`: the exact quotient of a difference known to vanish mod `m1`.
fn diff_quotient(a: &[BigInt], b: &[BigInt], m1: &BigInt, mp: &BigInt) -> PolyM {
    let n = a.len().max(b.len());
    let z = BigInt::zero();
    let v = (0..n)
        .map(|i| {
            let d = a.get(i).unwrap_or(&z) - b.get(i).unwrap_or(&z);
            let (q, r) = d.div_rem(m1);
            debug_assert!(r.is_zero(), "Hensel: congruence lost");
            q
        })
        .collect();
    reduce(v, mp)
}

struct Pair {
    g: PolyM,
    h: PolyM,
    s: PolyM,
    t: PolyM,
}

/// One Hensel step from modulus `m1` to `m2 = m1 * mp` (`mp | m1`); `f` reduced mod a
/// multiple of `m2`. With `last`, the cofactors are not lifted.
fn step(f: &[BigInt], x: Pair, m1: &BigInt, mp: &BigInt, last: bool) -> Pair {
    let Pair { g, h, s, t } = x;
    let e = diff_quotient(f, &kron_mul(&g, &h), m1, mp);
    let (q, r) = divrem_monic(&mul_mod(&s, &e, mp), &h, mp);
    let corr_g = add_mod(&kron_mul(&t, &e), &kron_mul(&q, &g), mp);
    let g2 = add_scaled(&g, &corr_g, m1);
    let h2 = add_scaled(&h, &r, m1);
    if last {
        return Pair { g: g2, h: h2, s, t };
    }
    let one = [BigInt::one()];
    let sg_th = add_mod(&kron_mul(&s, &g2), &kron_mul(&t, &h2), &(m1 * mp));
    let b = diff_quotient(&sg_th, &one, m1, mp);
    let (c, d) = divrem_monic(&mul_mod(&s, &b, mp), &h2, mp);
    let corr_t = add_mod(&kron_mul(&t, &b), &kron_mul(&c, &g2), mp);
    let m2 = m1 * mp;
    Pair {
        s: sub_scaled(&s, &d, m1, &m2),
        t: sub_scaled(&t, &corr_t, m1, &m2),
        g: g2,
        h: h2,
    }
}

fn to_polym(a: &[u64]) -> PolyM {
    a.iter().map(|&c| BigInt::from(c)).collect()
}

/// The exponents $1 = k_0 < k_1 < \dots < k_j = k$ with $k_{i+1} \le 2 k_i$.
fn exponent_chain(k: u32) -> Vec<u32> {
    let mut ks = vec![k];
    while *ks.last().unwrap() > 1 {
        let l = *ks.last().unwrap();
        ks.push(l.div_ceil(2));
    }
    ks.reverse();
    ks
}

/// Lifts the factorization `f ≡ lc(f) * prod(factors) (mod p)` to modulus $p^k$; `f` must
/// be reduced modulo $p^k$ with its leading coefficient a unit. Returns the monic lifts in
/// the order of `factors`, coefficients in $[0, p^k)$.
pub(crate) fn lift(zp: &Zp, f: &[BigInt], factors: &[PolyP], k: u32) -> Vec<PolyM> {
    let p = BigInt::from(zp.p);
    let big_m = num_traits::pow(p.clone(), k as usize);
    if factors.len() == 1 {
        let lc = f.last().expect("Hensel: nonzero f");
        let inv = lc.modinv(&big_m).expect("Hensel: unit leading coefficient");
        return vec![reduce(f.iter().map(|c| c * &inv).collect(), &big_m)];
    }
    // split by degree into two halves of about equal total degree
    let total: usize = factors.iter().map(|g| g.len() - 1).sum();
    let mut mid = 0;
    let mut acc = 0;
    while mid < factors.len() - 1 && 2 * (acc + factors[mid].len() - 1) <= total {
        acc += factors[mid].len() - 1;
        mid += 1;
    }
    let mid = mid.max(1);
    let (fa, fb) = factors.split_at(mid);
    let lcp = {
        let c = f.last().unwrap().mod_floor(&p);
        c.iter_u64_digits().next().unwrap_or(0)
    };
    let g0 = fa.iter().fold(vec![lcp], |acc, g| zp.mul(&acc, g));
    let h0 = fb.iter().fold(vec![1], |acc, g| zp.mul(&acc, g));
    let (d, s0, t0) = zp.xgcd(&g0, &h0);
    debug_assert_eq!(d, vec![1], "Hensel: factors not coprime mod p");
    let mut pair = Pair {
        g: to_polym(&g0),
        h: to_polym(&h0),
        s: to_polym(&s0),
        t: to_polym(&t0),
    };
    let chain = exponent_chain(k);
    for w in chain.windows(2) {
        let m1 = num_traits::pow(p.clone(), w[0] as usize);
        let mp = num_traits::pow(p.clone(), (w[1] - w[0]) as usize);
        let last = w[1] == k;
        pair = step(f, pair, &m1, &mp, last);
    }
    let mut out = lift(zp, &pair.g, fa, k);
    out.extend(lift(zp, &pair.h, fb, k));
    out
}

/// Reduction of integer coefficients into $[0, m)$.
pub(crate) fn reduce_coeffs(c: &[BigInt], m: &BigInt) -> PolyM {
    reduce(c.to_vec(), m)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::poly::factor::cantor_zassenhaus::factor_squarefree;
    use crate::poly::zpoly::ZPoly;

    #[test]
    fn kron_mul_matches_schoolbook() {
        let a: Vec<BigInt> = [3u64, 0, u64::MAX, 7].iter().map(|&c| c.into()).collect();
        let b: Vec<BigInt> = [1u64, 1 << 40, 5].iter().map(|&c| c.into()).collect();
        let want = ZPoly::new(a.clone()) * ZPoly::new(b.clone());
        assert_eq!(kron_mul(&a, &b), want.into_coeffs());
    }

    #[test]
    fn lifted_factors_multiply_back() {
        // f = (3x^2 + 5)(x^3 - 7x + 11)(2x + 9), square-free mod 13
        let f = ZPoly::from_i64s(&[5, 0, 3])
            * ZPoly::from_i64s(&[11, -7, 0, 1])
            * ZPoly::from_i64s(&[9, 2]);
        let zp = Zp::new(13);
        let fp = zp.monic(&zp.reduce(f.coeffs()));
        let facs = factor_squarefree(&zp, &fp);
        for k in [1, 2, 5, 9] {
            let m = num_traits::pow(BigInt::from(13), k as usize);
            let fm = reduce_coeffs(f.coeffs(), &m);
            let lifted = lift(&zp, &fm, &facs, k);
            let lc = vec![f.leading_coeff()];
            let prod = lifted.iter().fold(lc, |acc, g| mul_mod(&acc, g, &m));
            assert_eq!(prod, fm, "k = {k}");
        }
    }
}
