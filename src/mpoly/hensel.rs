//! Multivariate Hensel lifting with imposed leading coefficients.
//!
//! Given a square-free $f \in \mathbb{Z}\lbrack x, y_1, \dots\rbrack$, primitive in $x$, a point
//! $a$ with $\operatorname{lc}_x f(a) \ne 0$ and pairwise coprime factors
//! $f(x, a) = c \prod_i u_i(x)$, we look for $f = \prod_i h_i$ with $h_i(x, a) \sim u_i$.
//!
//! Leading coefficients (Wang's problem) are handled by the classical device: lift
//! $F = \ell^{r-1} f$ with $\ell = \operatorname{lc}_x f$ and impose $\operatorname{lc}_x g_i = \ell$
//! on every factor, so the lifted $g_i$ are $\ell/\operatorname{lc}_x(h_i) \cdot h_i$ and
//! $h_i = \operatorname{pp}_x(g_i)$. After the shift $y \to y + a$ the lift runs in the ideal
//! $(y_1, \dots)$ **all variables at once**, by total degree $d = 1, \dots, \deg_y F$: the
//! degree-$d$ part of the error $F - \prod g_i$ is, monomial by monomial in $y$, a univariate
//! Diophantine equation $\sum_i \delta_i \prod_{j \ne i} g_j^{(0)} = e_m(x)$ (solved over $\mathbb{Q}$,
//! the solution must be integral),
//! solved with the partial-fraction cofactors $s_i$ of the $g_i^{(0)}$:
//! $\delta_i = s_i e_m \bmod g_i^{(0)}$. The lift is unique, so it reproduces a true
//! factorization whenever one exists with these images; the result is always verified by exact
//! division.

use super::MPoly;
use crate::field::{Q, Rational};
use crate::poly::Poly;
use crate::poly::zpoly::ZPoly;
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::Zero;
use std::collections::BTreeMap;

/// Degree of a monomial in all variables but `x`.
fn ydeg(n: usize, m: u128, x: usize) -> u32 {
    (0..n)
        .filter(|&i| i != x)
        .map(|i| super::exp(n, m, i))
        .sum()
}

/// The parts of `f` homogeneous in the variables other than `x`: `out[j]` holds the terms of
/// degree `j` there (`j <= top`; higher terms are dropped).
fn homogeneous_parts(f: &MPoly, x: usize, top: u32) -> Vec<MPoly> {
    let n = f.nvars();
    let mut parts: Vec<Vec<(u128, BigInt)>> = vec![Vec::new(); top as usize + 1];
    for (m, c) in f.terms() {
        let d = ydeg(n, *m, x);
        if d <= top {
            parts[d as usize].push((*m, c.clone()));
        }
    }
    parts.into_iter().map(|t| MPoly::from_terms(n, t)).collect()
}

/// The degree-`d` parts of the partial products $P_k = g_0 \cdots g_k$ ($k \ge 1$), from
/// the parts of degree $< d$ of the $P_{k-1}$ (fixed once the lift passed them) and the
/// current parts of the $g_k$: `prods[k][d]` $= \sum_{i \le d} \lbrack P_{k-1}\rbrack_i
/// \lbrack g_k\rbrack_{d-i}$, with $P_0 = g_0$.
fn product_level(gparts: &[Vec<MPoly>], prods: &mut [Vec<MPoly>], d: usize) {
    let n = gparts[0][0].nvars();
    for k in 1..gparts.len() {
        let mut acc = MPoly::zero(n);
        for i in 0..=d {
            let left = if k == 1 {
                &gparts[0][i]
            } else {
                &prods[k - 1][i]
            };
            let right = &gparts[k][d - i];
            if !left.is_zero() && !right.is_zero() {
                acc = acc.add(&left.mul(right));
            }
        }
        if prods[k].len() > d {
            prods[k][d] = acc;
        } else {
            prods[k].push(acc);
        }
    }
}

/// Shifts every variable but `x` by `a_j` (`back`: by `-a_j`).
fn shift_all(f: &MPoly, x: usize, a: &[BigInt], back: bool) -> MPoly {
    let mut g = f.clone();
    for (j, aj) in a.iter().enumerate() {
        if j != x && !aj.is_zero() {
            g = g.shift_var(j, &if back { -aj } else { aj.clone() });
        }
    }
    g
}

/// Lifts `f = prod h_i` from the univariate images `us` at the point `a` (entry `x` unused).
/// Returns the primitive factors $h_i$ (positive leading coefficients) when the lift gives an
/// exact factorization, else `None`.
///
/// All products are over $\mathbb{Z}$: the lifted $g_i = (\ell / \operatorname{lc}_x h_i) h_i$
/// are integral, so every correction must be integral too; a fractional correction proves
/// that no factorization with these images exists.
pub(crate) fn lift(f: &MPoly, x: usize, a: &[BigInt], us: &[ZPoly]) -> Option<Vec<MPoly>> {
    let n = f.nvars();
    let r = us.len();
    if r == 1 {
        return Some(vec![f.clone()]);
    }
    let lc = f.lc_in(x);
    let lca = lc.eval_all(a);
    if lca.is_zero() {
        return None;
    }
    let big_f = shift_all(&f.mul(&lc.pow(r as u32 - 1)), x, a, false);
    let lcs = shift_all(&lc, x, a, false);
    let sh = super::shift(n, x);
    // initial factors: lca / lc(u_i) * u_i, top coefficient replaced by lcs
    let mut g0: Vec<Poly<Q>> = Vec::with_capacity(r);
    let mut gs: Vec<MPoly> = Vec::with_capacity(r);
    for u in us {
        let (q, rem) = lca.div_rem(&u.leading_coeff());
        if !rem.is_zero() {
            return None;
        }
        let gz = u.scale(&q);
        let d = gz.deg0();
        g0.push(Poly::new(
            Q,
            gz.coeffs()
                .iter()
                .map(|c| Rational::from_integer(c.clone()))
                .collect(),
        ));
        let mut low = gz.coeffs().to_vec();
        low.truncate(d);
        let low = MPoly::from_zpoly(n, x, &ZPoly::new(low));
        let top = lcs.mul(&MPoly::var(n, x).pow(d as u32));
        gs.push(low.add(&top));
    }
    // partial-fraction cofactors: sum_i s_i prod_{j != i} g0_j = 1
    let mut s: Vec<Poly<Q>> = Vec::with_capacity(r);
    for i in 0..r {
        let mut b = Poly::one(Q);
        for (j, gj) in g0.iter().enumerate() {
            if j != i {
                b = b.mul(gj);
            }
        }
        let (gg, si, _) = b.xgcd(&g0[i]);
        if gg.deg() != 0 || gg.is_zero() {
            return None;
        }
        s.push(si.rem(&g0[i]));
    }
    let total: usize = g0.iter().map(|g| g.deg()).sum();
    let dmax = big_f
        .terms()
        .iter()
        .map(|(m, _)| ydeg(n, *m, x))
        .max()
        .unwrap_or(0);
    let xmask = !(((1u128 << super::width(n)) - 1) << sh);
    // the products degree by degree: the parts of degree < d of every g_i (and so of every
    // partial product) are final once step d - 1 is done, so each pair of parts is
    // multiplied once (twice with the corrections) instead of once per later degree
    let top = gs
        .iter()
        .flat_map(|g| g.terms().iter().map(|(m, _)| ydeg(n, *m, x)))
        .chain([dmax])
        .max()
        .unwrap_or(0);
    let fparts = homogeneous_parts(&big_f, x, top);
    let mut gparts: Vec<Vec<MPoly>> = gs.iter().map(|g| homogeneous_parts(g, x, top)).collect();
    let mut prods: Vec<Vec<MPoly>> = vec![Vec::new(); r];
    product_level(&gparts, &mut prods, 0);
    for d in 1..=dmax as usize {
        product_level(&gparts, &mut prods, d);
        // degree-d part of the error, grouped by monomials in the other variables
        let err = fparts[d].sub(&prods[r - 1][d]);
        let mut by_m: BTreeMap<u128, Vec<Rational>> = BTreeMap::new();
        for (m, c) in err.terms() {
            let e = super::exp(n, *m, x) as usize;
            let v = by_m.entry(m & xmask).or_default();
            if v.len() <= e {
                v.resize(e + 1, Rational::zero());
            }
            v[e] = Rational::from_integer(c.clone());
        }
        let corrected = !by_m.is_empty();
        for (m, v) in by_m {
            let e = Poly::new(Q, v);
            if e.deg() >= total {
                return None;
            }
            for i in 0..r {
                let delta = e.mul(&s[i]).rem(&g0[i]);
                if delta.is_zero() {
                    continue;
                }
                let mut terms = Vec::with_capacity(delta.coeffs().len());
                for (k, c) in delta.coeffs().iter().enumerate() {
                    if c.is_zero() {
                        continue;
                    }
                    if !c.is_integer() {
                        return None;
                    }
                    terms.push((m + ((k as u128) << sh), c.to_integer()));
                }
                gparts[i][d] = gparts[i][d].add(&MPoly::from_terms(n, terms));
            }
        }
        if corrected {
            product_level(&gparts, &mut prods, d);
        }
    }
    let gs: Vec<MPoly> = gparts
        .iter()
        .map(|ps| ps.iter().fold(MPoly::zero(n), |acc, p| acc.add(p)))
        .collect();
    // back to the original variables
    let mut hs = Vec::with_capacity(r);
    for g in &gs {
        let gz = shift_all(g, x, a, true);
        let h = super::gcd::primitive_in(&gz.primitive_part(), x);
        if h.deg(x) == 0 {
            return None;
        }
        hs.push(h);
    }
    let mut q = f.clone();
    for h in &hs {
        q = q.div_exact(h)?;
    }
    if !q.is_constant() {
        return None;
    }
    Some(hs)
}
