//! Zassenhaus recombination of lifted modular factors.
//!
//! Let $f$ be square-free and primitive, $b = \operatorname{lc}(f)$, and
//! $f \equiv b\, G_1 \cdots G_r \pmod M$ with monic $G_i$, where $M/2$ exceeds
//! $2^{\lfloor n/2 \rfloor} \|f\|_2$: for a factor $h$ of degree $d$, Mahler's measure
//! bounds the coefficients of $(b / \operatorname{lc} h)\, h$ by $2^d M(f) \le 2^d \|f\|_2$.
//! Every irreducible factor $h$ of $f$ satisfies
//! $(b / \operatorname{lc} h)\, h \equiv b \prod_{i \in S} G_i \pmod M$ for one subset $S$,
//! so the symmetric residue of $b \prod_S G_i$ *is* that multiple of $h$ when
//! $\deg h \le n/2$; a factor of larger degree is found through the complement.
//!
//! Subsets are tried by increasing size $s \le |T|/2$; a subset is skipped unless its
//! degree is a possible factor degree (the intersection, over several primes, of the sets of
//! subset sums of modular factor degrees), its subleading coefficient $b \sum_S a_i$ obeys
//! the bound (the "d−1 test", first in 64-bit fixed point) and the constant term of the
//! candidate divides $b f(0)$; only then is the candidate formed, its coefficients checked
//! against the bound, and tried by exact division. Each factor found is removed from $f$
//! and its modular factors from $T$.

use super::hensel::{PolyM, kron_mul};
use crate::poly::zpoly::ZPoly;
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{Signed, ToPrimitive, Zero};

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

/// Cheap per-subset data: degree, subleading coefficient, constant coefficient.
struct Summary {
    deg: usize,
    sub: BigInt,
    c0: BigInt,
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
    let sums: Vec<Summary> = t
        .iter()
        .map(|g| Summary {
            deg: g.len() - 1,
            sub: g[g.len() - 2].clone(),
            c0: g[0].clone(),
        })
        .collect();
    let total_sub: BigInt = sums.iter().map(|x| &x.sub).sum();
    // |coefficients of (b / lc h) h| <= 2^deg(h) M(rest) <= 2^deg(h) |rest|_2 for h | rest
    let norm = rest.norm2_squared().sqrt() + 1u32;
    let bounds: Vec<BigInt> = (0..=n).map(|d| &norm << d).collect();
    // The d-1 test in fixed point: u_i = floor(2^64 (b sub_i mod M) / M). A wrapping sum of
    // k of them is within k of 2^64 (b sum sub_i mod M) / M, so a subleading coefficient of
    // absolute value <= bound puts the sum within 2^64 bound / M + k of 0 (mod 2^64).
    let scaled = |x: &BigInt| ((x.mod_floor(m) << 64u32) / m).to_u64().unwrap_or(u64::MAX);
    let fr: Vec<u64> = sums.iter().map(|x| scaled(&(&b * &x.sub))).collect();
    let fr_total = fr.iter().fold(0u64, |a, &x| a.wrapping_add(x));
    let thr: Vec<u64> = bounds
        .iter()
        .map(|bd| scaled(bd).saturating_add(r as u64 + 2))
        .collect();
    let mut idx: Vec<usize> = (0..s).collect();
    loop {
        let d: usize = idx.iter().map(|&i| sums[i].deg).sum();
        let low = 2 * d <= n;
        let near_zero = || {
            let fs = idx.iter().fold(0u64, |a, &i| a.wrapping_add(fr[i]));
            let fside = if low { fs } else { fr_total.wrapping_sub(fs) };
            fside.min(fside.wrapping_neg()) <= thr[if low { d } else { n - d }]
        };
        if allowed[d] && allowed[n - d] && near_zero() {
            // form the candidate from the side of degree <= n/2
            let (side, ds, sub): (Vec<usize>, usize, BigInt) = if low {
                (idx.clone(), d, idx.iter().map(|&i| &sums[i].sub).sum())
            } else {
                let sub_s: BigInt = idx.iter().map(|&i| &sums[i].sub).sum();
                (
                    (0..r).filter(|i| !idx.contains(i)).collect(),
                    n - d,
                    &total_sub - sub_s,
                )
            };
            // the subleading coefficient of b * prod(side) is b * (sum of theirs)
            let c1 = symmetric(&(&b * sub), m, half);
            if c1.abs() <= bounds[ds] {
                let c = Check {
                    b: &b,
                    bf0: &bf0,
                    m,
                    half,
                    bound: &bounds[ds],
                };
                if let Some((g, q)) = try_candidate(rest, t, &sums, &side, &c) {
                    let (factor, cofactor) = if low { (g, q) } else { (q, g) };
                    let cofactor = cofactor.primitive_part();
                    return Some((idx, factor.primitive_part(), cofactor));
                }
            }
        }
        if !next_combination(&mut idx, r) {
            return None;
        }
    }
}

struct Check<'a> {
    b: &'a BigInt,
    bf0: &'a BigInt,
    m: &'a BigInt,
    half: &'a BigInt,
    bound: &'a BigInt,
}

/// The candidate $\operatorname{pp}(b \prod_{side} G_i \bmod M)$ and the quotient of
/// `rest` by it, if it divides `rest`. Cheap tests first: the constant term must divide
/// $b \cdot \text{rest}(0)$, every coefficient must obey the bound.
fn try_candidate(
    rest: &ZPoly,
    t: &[PolyM],
    sums: &[Summary],
    side: &[usize],
    c: &Check,
) -> Option<(ZPoly, ZPoly)> {
    let (m, half) = (c.m, c.half);
    let mut c0 = c.b.mod_floor(m);
    for &i in side {
        c0 = (c0 * &sums[i].c0).mod_floor(m);
    }
    let c0 = symmetric(&c0, m, half);
    if c0.is_zero() || !c.bf0.is_multiple_of(&c0) {
        return None;
    }
    let mut prod: PolyM = vec![c.b.mod_floor(m)];
    for &i in side {
        prod = kron_mul(&prod, &t[i]);
        for x in prod.iter_mut() {
            *x = x.mod_floor(m);
        }
    }
    let mut coeffs = Vec::with_capacity(prod.len());
    for x in &prod {
        let y = symmetric(x, m, half);
        if &y.abs() > c.bound {
            return None;
        }
        coeffs.push(y);
    }
    let g = ZPoly::new(coeffs).primitive_part();
    if g.deg0() == 0 || !c.b.is_multiple_of(&g.leading_coeff()) {
        return None;
    }
    let q = rest.div_exact(&g)?;
    Some((g, q))
}
