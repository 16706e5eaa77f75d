//! Factorization of square-free polynomials over $\mathbb{F}_p$, $p$ an odd prime.
//!
//! *Distinct-degree factorization*: $x^{p^i} - x$ is the product of all monic irreducibles
//! of degree dividing $i$, so $\gcd(f, x^{p^i} - x)$, with the factors of degree $< i$
//! already removed, is the product of the degree-$i$ factors of $f$. The powers
//! $x^{p^i} \bmod f$ are iterated with the Frobenius matrix $Q$ (row $j$ is
//! $x^{jp} \bmod f$), one vector–matrix product per step.
//!
//! *Equal-degree factorization* (Cantor–Zassenhaus): for $g$ a product of $r \ge 2$
//! irreducibles of degree $d$ and random $a$, $\gcd(g, a^{(p^d-1)/2} - 1)$ is a proper
//! factor with probability about $1/2$.
//!
//! | function | computes |
//! |---|---|
//! | [`distinct_degree`] | $[(g_i, i)]$, $g_i$ = product of the degree-$i$ factors |
//! | [`factor_squarefree`] | the monic irreducible factors of a monic square-free $f$ |

use crate::poly::fp::{PolyP, Zp, trim};
use num_bigint::BigUint;

/// The deterministic generator for the random splitting polynomials.
pub(crate) use crate::rng::SplitMix64 as SplitMix;

/// Rows $x^{jp} \bmod f$ for $0 \le j < \deg f$.
fn frobenius_rows(k: &Zp, f: &[u64]) -> Vec<PolyP> {
    let n = f.len() - 1;
    let xp = k.powmod(&[0, 1], &BigUint::from(k.p), f);
    let mut rows = Vec::with_capacity(n);
    let mut cur: PolyP = k.rem(&[1], f);
    for _ in 0..n {
        rows.push(cur.clone());
        cur = k.rem(&k.mul(&cur, &xp), f);
    }
    rows
}

/// $h^p \bmod f = \sum_j h_j x^{jp} \bmod f$.
fn frobenius_apply(k: &Zp, rows: &[PolyP], h: &[u64], n: usize) -> PolyP {
    let mut acc = vec![0u128; n];
    for (j, &hj) in h.iter().enumerate() {
        if hj == 0 {
            continue;
        }
        for (a, &r) in acc.iter_mut().zip(rows[j].iter()) {
            *a += (hj * r) as u128;
        }
    }
    let p = k.p as u128;
    let mut v: PolyP = acc.into_iter().map(|a| (a % p) as u64).collect();
    trim(&mut v);
    v
}

/// Distinct-degree factorization of a monic square-free `f` of degree $\ge 1$: pairs
/// $(g_i, i)$ where $g_i \ne 1$ is the product of the irreducible factors of degree $i$.
pub(crate) fn distinct_degree(k: &Zp, f: &[u64]) -> Vec<(PolyP, usize)> {
    let n = f.len() - 1;
    let mut out = Vec::new();
    if n == 1 {
        out.push((f.to_vec(), 1));
        return out;
    }
    let rows = frobenius_rows(k, f);
    let x: PolyP = vec![0, 1];
    let mut h = x.clone();
    let mut rest = f.to_vec();
    let mut i = 0;
    loop {
        i += 1;
        let dr = rest.len() - 1;
        if 2 * i > dr {
            if dr > 0 {
                out.push((rest, dr));
            }
            break;
        }
        h = frobenius_apply(k, &rows, &h, n);
        let g = k.gcd(&rest, &k.sub(&h, &x));
        if g.len() > 1 {
            rest = k.divrem(&rest, &g).0;
            out.push((g, i));
        }
    }
    out
}

/// Splits `g`, a monic product of irreducibles of degree `d`, into those factors.
fn equal_degree(k: &Zp, g: PolyP, d: usize, rng: &mut SplitMix, out: &mut Vec<PolyP>) {
    let n = g.len() - 1;
    if n == d {
        out.push(g);
        return;
    }
    let e = (BigUint::from(k.p).pow(d as u32) - 1u32) / 2u32;
    loop {
        let mut a: PolyP = (0..n).map(|_| rng.next_u64() % k.p).collect();
        trim(&mut a);
        if a.len() < 2 {
            continue;
        }
        let b = k.sub(&k.powmod(&a, &e, &g), &[1]);
        let h = k.gcd(&g, &b);
        if h.len() > 1 && h.len() < g.len() {
            let q = k.divrem(&g, &h).0;
            equal_degree(k, h, d, rng, out);
            equal_degree(k, q, d, rng, out);
            return;
        }
    }
}

/// The monic irreducible factors of a monic square-free `f`, given its distinct-degree
/// factorization `ddf`, sorted by degree then coefficients.
pub(crate) fn factor_from_ddf(k: &Zp, ddf: Vec<(PolyP, usize)>, seed: u64) -> Vec<PolyP> {
    assert!(k.p > 2, "equal-degree splitting needs an odd prime");
    let mut rng = SplitMix(seed);
    let mut out = Vec::new();
    for (g, d) in ddf {
        equal_degree(k, g, d, &mut rng, &mut out);
    }
    out.sort_by(|a, b| a.len().cmp(&b.len()).then_with(|| a.cmp(b)));
    out
}

/// The monic irreducible factors of a monic square-free `f` over $\mathbb{F}_p$, $p$ odd.
#[cfg(test)]
pub(crate) fn factor_squarefree(k: &Zp, f: &[u64]) -> Vec<PolyP> {
    factor_from_ddf(k, distinct_degree(k, f), 0x5EED)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn factors_multiply_back_and_are_irreducible() {
        let k = Zp::new(101);
        let mut rng = SplitMix(7);
        for _ in 0..30 {
            let n = 1 + (rng.next_u64() % 12) as usize;
            let mut f: PolyP = (0..n).map(|_| rng.next_u64() % 101).collect();
            f.push(1);
            if !k.is_squarefree(&f) {
                continue;
            }
            let fs = factor_squarefree(&k, &f);
            let prod = fs.iter().fold(vec![1], |acc, g| k.mul(&acc, g));
            assert_eq!(prod, f);
            for g in &fs {
                // a single distinct-degree class of full degree: irreducible
                let dd = distinct_degree(&k, g);
                assert_eq!(dd.len(), 1);
                assert_eq!(dd[0].1, g.len() - 1, "{g:?}");
            }
        }
    }

    #[test]
    fn x_pow_p_minus_x_splits_into_linears() {
        let k = Zp::new(13);
        let mut f = vec![0u64; 14];
        f[13] = 1;
        f[1] = 12;
        let fs = factor_squarefree(&k, &f);
        assert_eq!(fs.len(), 13);
        assert!(fs.iter().all(|g| g.len() == 2));
    }
}
