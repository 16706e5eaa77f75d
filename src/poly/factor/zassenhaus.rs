//! Zassenhaus recombination of lifted modular factors.
//!
//! Let $f$ be square-free and primitive, $b = \operatorname{lc}(f)$, and
//! $f \equiv b\, G_1 \cdots G_r \pmod M$ with monic $G_i$, where $M/2$ exceeds
//! $|b| \cdot 2^{\lfloor n/2 \rfloor} \|f\|_2$ (Mignotte's bound for a factor of degree at
//! most $n/2$, scaled by $b$). Every irreducible factor $h$ of $f$ satisfies
//! $(b / \operatorname{lc} h)\, h \equiv b \prod_{i \in S} G_i \pmod M$ for one subset $S$, so
//! the symmetric residue of $b \prod_S G_i$ *is* that multiple of $h$ when
//! $\deg h \le n/2$; a factor of larger degree is found through the complement.
//!
//! Subsets are tried by increasing size $s \le |T|/2$; a subset is skipped unless its
//! degree is a possible factor degree (the intersection, over several primes, of the sets of
//! subset sums of modular factor degrees) and the constant term of the candidate divides
//! $b f(0)$; only then is the candidate formed and tried by exact division. Each factor
//! found is removed from $f$ and its modular factors from $T$.

use super::hensel::{PolyM, kron_mul};
use crate::poly::zpoly::ZPoly;
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};

/// Symmetric residue in $(-M/2, M/2]$.
fn symmetric(c: &BigInt, m: &BigInt, half: &BigInt) -> BigInt {
    let r = c.mod_floor(m);
    if &r > half { r - m } else { r }
}

/// Advances `idx` (a strictly increasing `s`-subset of `0..n`) to the next one in
/// lexicographic order; false when exhausted.
fn next_combination(idx: &mut [usize], n: usize) -> bool {
    let s = idx.len();
    for i in (0..s).rev() {
        if idx[i] < n - s + i {
            idx[i] += 1;
            for j in i + 1..s {
                idx[j] = idx[j - 1] + 1;
            }
            return true;
        }
    }
    false
}

/// The irreducible factors of `f` (square-free, primitive, positive leading coefficient,
/// $f(0) \ne 0$) from its monic modular factors `lifted` modulo `m`. `allowed[d]` says
/// whether degree `d` can be the degree of a factor of `f`.
pub(crate) fn recombine(f: &ZPoly, lifted: Vec<PolyM>, m: &BigInt, allowed: &[bool]) -> Vec<ZPoly> {
    let half = m / 2;
    let mut t = lifted;
    let mut rest = f.clone();
    let mut out = Vec::new();
    let mut s = 1;
    while 2 * s <= t.len() {
        match find_factor(&rest, &t, s, m, &half, allowed) {
            Some((subset, factor, cofactor)) => {
                out.push(factor);
                rest = cofactor;
                let mut keep = Vec::with_capacity(t.len() - s);
                for (i, g) in t.into_iter().enumerate() {
                    if !subset.contains(&i) {
                        keep.push(g);
                    }
                }
                t = keep;
            }
            None => s += 1,
        }
    }
    if rest.deg0() > 0 {
        out.push(rest);
    }
    out
}

/// Searches the `s`-subsets of `t` for a true factor of `rest`; returns the subset, the
/// factor (primitive, positive leading coefficient) and the cofactor.
fn find_factor(
    rest: &ZPoly,
    t: &[PolyM],
    s: usize,
    m: &BigInt,
    half: &BigInt,
    allowed: &[bool],
) -> Option<(Vec<usize>, ZPoly, ZPoly)> {
    let n = rest.deg0();
    let r = t.len();
    let b = rest.leading_coeff();
    let bf0 = &b * &rest.coeffs()[0];
    let degs: Vec<usize> = t.iter().map(|g| g.len() - 1).collect();
    let mut idx: Vec<usize> = (0..s).collect();
    loop {
        let d: usize = idx.iter().map(|&i| degs[i]).sum();
        if allowed[d] && allowed[n - d] {
            // form the candidate from the side of degree <= n/2
            let side: Vec<usize> = if 2 * d <= n {
                idx.clone()
            } else {
                (0..r).filter(|i| !idx.contains(i)).collect()
            };
            if let Some((g, q)) = try_candidate(rest, t, &side, &b, &bf0, m, half) {
                let (factor, cofactor) = if 2 * d <= n { (g, q) } else { (q, g) };
                let cofactor = cofactor.primitive_part();
                return Some((idx, factor.primitive_part(), cofactor));
            }
        }
        if !next_combination(&mut idx, r) {
            return None;
        }
    }
}

/// The candidate $\operatorname{pp}(b \prod_{side} G_i \bmod M)$ and the quotient of
/// `rest` by it, if it divides `rest`.
fn try_candidate(
    rest: &ZPoly,
    t: &[PolyM],
    side: &[usize],
    b: &BigInt,
    bf0: &BigInt,
    m: &BigInt,
    half: &BigInt,
) -> Option<(ZPoly, ZPoly)> {
    // constant term test: it must divide b * rest(0)
    let mut c0 = b.mod_floor(m);
    for &i in side {
        c0 = (c0 * &t[i][0]).mod_floor(m);
    }
    let c0 = symmetric(&c0, m, half);
    if c0.is_zero() || !bf0.is_multiple_of(&c0) {
        return None;
    }
    // leading term x-coefficient-free check passed; form the full candidate
    let mut prod: PolyM = vec![b.mod_floor(m)];
    for &i in side {
        prod = kron_mul(&prod, &t[i]);
        for c in prod.iter_mut() {
            *c = c.mod_floor(m);
        }
    }
    let g = ZPoly::new(prod.iter().map(|c| symmetric(c, m, half)).collect()).primitive_part();
    if g.deg0() == 0 {
        return None;
    }
    // the candidate's leading coefficient must divide lc(rest)
    if !b.abs().is_multiple_of(&g.leading_coeff()) && !g.leading_coeff().is_one() {
        return None;
    }
    let q = rest.div_exact(&g)?;
    Some((g, q))
}
