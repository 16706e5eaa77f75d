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
//! Diophantine equation $\sum_i \delta_i \prod_{j \ne i} g_j^{(0)} = e_m(x)$ over $\mathbb{Q}$,
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
use num_traits::{One, Zero};
use std::collections::BTreeMap;

/// Polynomial in $y$ (packed monomials, $x$ exponent zero) with coefficients in $\mathbb{Q}\lbrack x\rbrack$.
type TPoly = BTreeMap<u128, Poly<Q>>;

fn tdeg(f: &MPoly, m: u128) -> u32 {
    (0..f.nvars()).map(|i| f.exp(m, i)).sum()
}

/// Splits an [`MPoly`] by monomials in the other variables.
fn to_tpoly(f: &MPoly, x: usize) -> TPoly {
    let n = f.nvars();
    let sh = super::shift(n, x);
    let mask = !(((1u128 << super::width(n)) - 1) << sh);
    let mut out: BTreeMap<u128, Vec<Rational>> = BTreeMap::new();
    for (m, c) in f.terms() {
        let e = f.exp(*m, x) as usize;
        let v = out.entry(m & mask).or_default();
        if v.len() <= e {
            v.resize(e + 1, Rational::zero());
        }
        v[e] = Rational::from_integer(c.clone());
    }
    out.into_iter().map(|(k, v)| (k, Poly::new(Q, v))).collect()
}

/// Product truncated at total $y$-degree `d`.
fn trunc_mul(a: &TPoly, b: &TPoly, d: u32, f: &MPoly) -> TPoly {
    let mut out: TPoly = BTreeMap::new();
    for (ma, pa) in a {
        let da = tdeg(f, *ma);
        if da > d {
            continue;
        }
        for (mb, pb) in b {
            if da + tdeg(f, *mb) > d {
                continue;
            }
            let p = pa.mul(pb);
            let e = out.entry(ma + mb).or_insert_with(|| Poly::zero(Q));
            *e = e.add(&p);
        }
    }
    out.retain(|_, p| !p.is_zero());
    out
}

/// Shifts every variable but `x` by `a_j` (`sign` = -1 shifts back).
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
    let big_f = f.mul(&lc.pow(r as u32 - 1));
    let fs = to_tpoly(&shift_all(&big_f, x, a, false), x);
    let lcs = shift_all(&lc, x, a, false);
    // initial factors: lca / lc(u_i) * u_i, top coefficient replaced by lcs
    let mut g0: Vec<Poly<Q>> = Vec::with_capacity(r);
    for u in us {
        let (q, rem) = lca.div_rem(&u.leading_coeff());
        if !rem.is_zero() {
            return None;
        }
        g0.push(Poly::new(
            Q,
            u.coeffs()
                .iter()
                .map(|c| Rational::from_integer(c * &q))
                .collect(),
        ));
    }
    let mut gs: Vec<TPoly> = g0
        .iter()
        .map(|g| {
            let mut t: TPoly = BTreeMap::new();
            t.insert(0, g.clone());
            let dg = g.deg();
            for (m, c) in lcs.terms() {
                if *m != 0 {
                    t.insert(
                        *m,
                        Poly::monomial(Q, Rational::from_integer(c.clone()), dg),
                    );
                }
            }
            t
        })
        .collect();
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
    let dmax = fs.keys().map(|m| tdeg(f, *m)).max().unwrap_or(0);
    for d in 1..=dmax {
        let mut prod = gs[0].clone();
        for g in &gs[1..] {
            prod = trunc_mul(&prod, g, d, f);
        }
        let mut keys: Vec<u128> = fs
            .keys()
            .chain(prod.keys())
            .copied()
            .filter(|m| tdeg(f, *m) == d)
            .collect();
        keys.sort_unstable();
        keys.dedup();
        for m in keys {
            let fm = fs.get(&m).cloned().unwrap_or_else(|| Poly::zero(Q));
            let pm = prod.get(&m).cloned().unwrap_or_else(|| Poly::zero(Q));
            let e = fm.sub(&pm);
            if e.is_zero() {
                continue;
            }
            if e.deg() >= total {
                return None;
            }
            for i in 0..r {
                let delta = e.mul(&s[i]).rem(&g0[i]);
                if delta.is_zero() {
                    continue;
                }
                let slot = gs[i].entry(m).or_insert_with(|| Poly::zero(Q));
                *slot = slot.add(&delta);
            }
        }
    }
    // back to Z[x, y]
    let sh = super::shift(n, x);
    let mut hs = Vec::with_capacity(r);
    for g in &gs {
        let mut den = BigInt::one();
        for p in g.values() {
            for c in p.coeffs() {
                den = den.lcm(c.denom());
            }
        }
        let mut terms = Vec::new();
        for (m, p) in g {
            for (k, c) in p.coeffs().iter().enumerate() {
                if !c.is_zero() {
                    terms.push((m + ((k as u128) << sh), (c * &den).to_integer()));
                }
            }
        }
        let gz = MPoly::from_terms(n, terms);
        let gz = shift_all(&gz, x, a, true);
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
