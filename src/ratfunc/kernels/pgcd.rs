//! The gcd kernel of $\mathbb{Q}(p)\lbrack s\rbrack$: Euclid's algorithm over
//! $\mathbb{Q}(p)$ replaced by a coprimality test at a point and, when that fails, one gcd in
//! $\mathbb{Z}\lbrack p, s\rbrack$.
//!
//! **Coprimality at a point.** Let $f, g \in \mathbb{Q}(p)\lbrack s\rbrack$ and $x$ a point
//! (modulo a word prime) where the denominators and the leading coefficients in $s$ of $f$
//! and $g$ do not vanish. Then $\gcd(f, g)$ specialises to a divisor of
//! $\gcd(f(x), g(x))$, so $\deg \gcd(f(x), g(x)) = 0$ proves $\gcd(f, g) = 1$.
//! **Otherwise** $f$ and $g$ are cleared of denominators into $\mathbb{Z}\lbrack p, s\rbrack$
//! (content in $s$ included), their gcd $h$ is taken there ([`crate::mpoly::gcd()`]) and
//! $h / \operatorname{lc}_s h$ is the monic gcd over $\mathbb{Q}(p)$ (Gauss's lemma: a gcd
//! in $\mathbb{Z}\lbrack p\rbrack\lbrack s\rbrack$ is one in $\mathbb{Q}(p)\lbrack s\rbrack$
//! up to a unit of $\mathbb{Q}(p)$).

use super::clear_common;
use crate::field::Field;
use crate::mpoly::modp::eval_mod_p as eval;
use crate::mpoly::{MAX_VARS, MPoly, gcd};
use crate::qkernels::prime::{Prime, nth_prime};
use crate::ratfunc::{RatFunc, RatFuncField};
use crate::rng::SplitMix64;

/// Degree of the gcd of two polynomials over $\mathbb{Z}/p$ (low degree first, nonzero
/// leading coefficients).
fn gcd_degree(pr: &Prime, a: &[u64], b: &[u64]) -> usize {
    let trim = |v: &mut Vec<u64>| {
        while v.last() == Some(&0) {
            v.pop();
        }
    };
    let (mut a, mut b) = (a.to_vec(), b.to_vec());
    trim(&mut a);
    trim(&mut b);
    while !b.is_empty() {
        // a = a mod b
        let inv = pr.inv(*b.last().expect("nonempty")).expect("nonzero");
        while a.len() >= b.len() {
            let q = pr.mul(*a.last().expect("nonempty"), inv);
            let off = a.len() - b.len();
            for (i, bi) in b.iter().enumerate() {
                a[off + i] = pr.sub(a[off + i], pr.mul(q, *bi));
            }
            trim(&mut a);
        }
        std::mem::swap(&mut a, &mut b);
    }
    a.len().saturating_sub(1)
}

/// `Some(true)` when a point proves $\gcd(f, g) = 1$; `None` when no point qualified.
fn coprime_at_a_point(k: &RatFuncField, f: &[RatFunc], g: &[RatFunc]) -> Option<bool> {
    let nv = k.nvars();
    for attempt in 0..2 {
        let pr = nth_prime(50 + attempt);
        let mut rng = SplitMix64(0x9cd + attempt as u64);
        let x: Vec<u64> = (0..nv).map(|_| rng.next_u64() % pr.p).collect();
        let image = |h: &[RatFunc]| -> Option<Vec<u64>> {
            let mut out = Vec::with_capacity(h.len());
            for c in h {
                let d = eval(&pr, c.den(), &x);
                let n = eval(&pr, c.num(), &x);
                out.push(pr.mul(n, pr.inv(d)?));
            }
            (*out.last()? != 0).then_some(out)
        };
        let (Some(a), Some(b)) = (image(f), image(g)) else {
            continue;
        };
        return Some(gcd_degree(&pr, &a, &b) == 0);
    }
    None
}

/// The monic gcd of `f` and `g` (coefficients low degree first, no trailing zeros, both
/// nonzero) over $\mathbb{Q}(p)$; `None`: leave it to Euclid's algorithm.
pub fn poly_gcd_qp(k: &RatFuncField, f: &[RatFunc], g: &[RatFunc]) -> Option<Vec<RatFunc>> {
    if f.is_empty() || g.is_empty() {
        return None;
    }
    if f.len() == 1 || g.len() == 1 || coprime_at_a_point(k, f, g) == Some(true) {
        return Some(vec![k.one()]);
    }
    let nv = k.nvars();
    if nv + 1 > MAX_VARS {
        return None;
    }
    let lift = |h: &[RatFunc]| {
        let (cs, _) = clear_common(nv, h);
        let cs: Vec<MPoly> = cs.iter().map(|c| c.extend_vars(nv + 1)).collect();
        MPoly::from_univariate(nv + 1, nv, &cs)
    };
    let h = gcd(&lift(f), &lift(g));
    let cs = h.to_univariate(nv);
    let lc = cs.last()?.clone();
    Some(
        cs.iter()
            .map(|c| k.frac(shrink(c, nv), shrink(&lc, nv)).expect("nonzero lc"))
            .collect(),
    )
}

/// A polynomial of $\mathbb{Z}\lbrack p, s\rbrack$ free of $s$ (the last variable), back in
/// $\mathbb{Z}\lbrack p\rbrack$.
fn shrink(c: &MPoly, nv: usize) -> MPoly {
    let terms = c
        .terms()
        .iter()
        .map(|(m, a)| {
            let e = c.exps(*m);
            (crate::mpoly::pack(nv, &e[..nv]), a.clone())
        })
        .collect();
    MPoly::from_terms(nv, terms)
}
