//! Minimal realization by the Jordan form over a quadratic field $K = \mathbb{Q}(i)$ /
//! $\mathbb{Q}(\sqrt d)$ (the method of [`super::minimal_jordan`] on the components of
//! [`crate::jordan::over_k`]).
//!
//! For each irreducible factor $g$ of $\chi_A$ over $K$, in $E = K\[t\]/(g)$: the modal data
//! $(J_t, W B, C V)$; per Jordan block the states from the first observed to the last
//! excited one are kept (the others never reach $y$ or are never excited); the repeated modes
//! are compacted by a Kalman minimal realization of $(N, WB, CV)$, $N$ the nilpotent part,
//! put back in Jordan form by its chains. The result is the **complex modal** realization:
//! one block per eigenvalue $\theta_j$ (a root of $g$ under the embeddings fixing $K$), its
//! entries exact in $E$ at $\theta_j$. (Over $\mathbb{Q}(i)$ a non-real $A$ has no real
//! modal form; over a real $K$ the pairs are also left complex.)
//!
//! # Verification
//! Exact: $\sum_g \mathrm{Tr}_{E/K}(C_g J_g^k B_g) = C A^k B$ for $k < n + r$ (the trace
//! over the roots of $g$ lies in $K$: $\mathrm{Tr}(\sum_i c_i t^i) = \sum_i c_i s_i$ with
//! the Newton power sums $s_i$ of $g$), and the order $r$ equals the McMillan degree (Hankel
//! rank), so the result is minimal.

use super::controllability::mcmillan_degree;
use super::minimal::minimal_kalman;
use crate::error::Result;
use crate::field::{Field, Quadratic, QuadraticField};
use crate::jordan::chains::{jordan_block_matrix, jordan_chains};
use crate::jordan::over_k::{JordanFormK, RelElem, RelField, jordan_over_k};
use crate::matrix::Matrix;
use crate::poly::Poly;
use crate::system::StateSpace;

/// One eigenvalue's block of the result, exact in $E$ at that eigenvalue.
#[derive(Clone, Debug)]
pub struct ModalBlockK {
    /// Display of the eigenvalue.
    pub eigenvalue: String,
    /// $E = K(\theta)$ marked at the eigenvalue.
    pub field: RelField,
    pub a: Matrix<RelField>,
    pub b: Matrix<RelField>,
    pub c: Matrix<RelField>,
}

/// The Jordan-method minimal realization over $K$.
#[derive(Clone, Debug)]
pub struct JordanMinimalK {
    /// Orders: original, after dropping non-contributing modes, after compaction.
    pub stages: [usize; 3],
    pub blocks: Vec<ModalBlockK>,
    pub d: Matrix<QuadraticField>,
    pub mcmillan_degree: usize,
    /// Symbols used in entries, with their definitions.
    pub symbols: Vec<(String, String)>,
    pub verified: bool,
}

impl JordanMinimalK {
    /// Order of the realization.
    pub fn order(&self) -> usize {
        self.blocks.iter().map(|b| b.a.nrows()).sum()
    }
}

/// Keeps, per Jordan block, the states from the first observed to the last excited one.
fn drop_modes<K: Field>(
    blocks: &[usize],
    b: &Matrix<K>,
    c: &Matrix<K>,
) -> (Vec<usize>, Vec<usize>) {
    let k = b.field().clone();
    let (mut keep, mut sizes, mut start) = (vec![], vec![], 0);
    for &s in blocks {
        let idx: Vec<usize> = (start..start + s).collect();
        let excited = idx
            .iter()
            .rposition(|&i| b.row(i).iter().any(|x| !k.is_zero(x)));
        let observed = idx
            .iter()
            .position(|&i| (0..c.nrows()).any(|r| !k.is_zero(c.get(r, i))));
        if let (Some(hi), Some(lo)) = (excited, observed)
            && lo <= hi
        {
            keep.extend(start + lo..=start + hi);
            sizes.push(hi - lo + 1);
        }
        start += s;
    }
    (keep, sizes)
}

/// Newton power sums $s_0, \dots, s_{u-1}$ of the roots of the monic `g` over $K$.
fn power_sums(g: &Poly<QuadraticField>, u: usize) -> Vec<Quadratic> {
    let k = g.field();
    let d = g.deg();
    let a = |i: usize| g.coeff(i); // x^d + a_{d-1} x^{d-1} + ... + a_0
    let mut s = vec![k.from_i64(d as i64)];
    for j in 1..u {
        // s_j = -(j a_{d-j} [j <= d] + sum_{i=1}^{min(j-1, d)} a_{d-i} s_{j-i})
        let mut v = if j <= d {
            k.mul(&k.from_i64(j as i64), &a(d - j))
        } else {
            k.zero()
        };
        for i in 1..j.min(d + 1) {
            v = k.add(&v, &k.mul(&a(d - i), &s[j - i]));
        }
        s.push(k.neg(&v));
    }
    s
}

/// $\mathrm{Tr}_{E/K}(t^e x) = \sum_c x_c s_{e+c}$.
fn trace_shifted(x: &RelElem, e: usize, s: &[Quadratic], k: &QuadraticField) -> Quadratic {
    x.0.iter()
        .enumerate()
        .fold(k.zero(), |acc, (c, xc)| k.add(&acc, &k.mul(xc, &s[e + c])))
}

/// Adds $\mathrm{Tr}_{E/K}(C J^k B)$ to `sum[k]` for every $k$ without a product in $E$ per
/// $k$: inside a Jordan block $(J^k)_{l, l+r} = \binom kr t^{k-r}$, so each entry is
/// $\sum_r \binom kr \mathrm{Tr}(t^{k-r} x_r)$ with $x_r = \sum_l C_{il} B_{l+r,j}$
/// (products computed once) and the power sums `s` of $g$.
fn add_traces(c: &Compact, g: &Poly<QuadraticField>, sum: &mut [Matrix<QuadraticField>]) {
    let kmax = sum.len();
    let k = g.field().clone();
    let e = c.b.field();
    let (p, m) = (c.c.nrows(), c.b.ncols());
    let smax = c.blocks.iter().copied().max().unwrap_or(0);
    let s = power_sums(g, kmax + g.deg() + 1);
    // binomials C(kk, r) for kk < kmax, r < smax
    let mut binom = vec![vec![0i128; smax.max(1)]; kmax];
    for (kk, row) in binom.iter_mut().enumerate() {
        let mut b = 1i128;
        for (r, x) in row.iter_mut().enumerate() {
            if r > kk {
                break;
            }
            *x = b;
            b = b * (kk - r) as i128 / (r + 1) as i128;
        }
    }
    for i in 0..p {
        for j in 0..m {
            let mut x = vec![e.zero(); smax];
            let mut off = 0;
            for &bs in &c.blocks {
                for (r, xr) in x.iter_mut().enumerate().take(bs) {
                    for l in off..off + bs - r {
                        *xr = e.add(xr, &e.mul(c.c.get(i, l), c.b.get(l + r, j)));
                    }
                }
                off += bs;
            }
            for (kk, term) in sum.iter_mut().enumerate() {
                let mut v = term.get(i, j).clone();
                for (r, xr) in x.iter().enumerate().take(kk + 1) {
                    if e.is_zero(xr) {
                        continue;
                    }
                    let bin =
                        k.from_rational(&crate::field::Rational::from_integer(binom[kk][r].into()));
                    v = k.add(&v, &k.mul(&bin, &trace_shifted(xr, kk - r, &s, &k)));
                }
                term.set(i, j, v);
            }
        }
    }
}

/// One compacted component: $(J, B, C)$ over $E$ (marked at the first root), the index of
/// its component.
struct Compact {
    comp: usize,
    blocks: Vec<usize>,
    a: Matrix<RelField>,
    b: Matrix<RelField>,
    c: Matrix<RelField>,
}

/// Minimal realization of a system over $K$ by the Jordan-form method (module docs).
///
/// # Errors
/// Those of [`jordan_over_k`] and of the Kalman decomposition.
pub fn minimal_jordan_over_k(sys: &StateSpace<QuadraticField>) -> Result<JordanMinimalK> {
    let n = sys.nstates();
    let jf: JordanFormK = jordan_over_k(&sys.a)?;
    let mut stage1 = 0;
    let mut comps = vec![];
    for (ci, comp) in jf.components.iter().enumerate() {
        let e = &comp.field;
        let lift = |m: &Matrix<QuadraticField>| m.map(e, |x| e.from_base(x));
        let bk = &comp.left_chains * &lift(&sys.b);
        let ck = &lift(&sys.c) * &comp.chains;
        let (keep, sizes) = drop_modes(&comp.blocks, &bk, &ck);
        stage1 += keep.len() * comp.factor.deg();
        if keep.is_empty() {
            continue;
        }
        let theta = comp.root_elem();
        if keep.len() == 1 {
            // one excited and observed mode (a simple eigenvalue): already minimal
            comps.push(Compact {
                comp: ci,
                blocks: vec![1],
                a: Matrix::from_vec(e.clone(), 1, 1, vec![theta]),
                b: bk.select_rows(&keep),
                c: ck.select_cols(&keep),
            });
            continue;
        }
        let nilp = jordan_block_matrix(e, &e.zero(), &sizes);
        let trimmed =
            StateSpace::new_strictly_proper(nilp, bk.select_rows(&keep), ck.select_cols(&keep))?;
        let min = minimal_kalman(&trimmed)?.system;
        let r = min.nstates();
        if r == 0 {
            continue;
        }
        let ch = jordan_chains(&min.a, r)?;
        comps.push(Compact {
            comp: ci,
            a: jordan_block_matrix(e, &theta, &ch.blocks),
            blocks: ch.blocks,
            b: &ch.w * &min.b,
            c: &min.c * &ch.v,
        });
    }
    // exact verification through traces over K
    let r: usize = comps
        .iter()
        .map(|c| c.a.nrows() * jf.components[c.comp].factor.deg())
        .sum();
    let kmax = n + r;
    let k = sys.a.field().clone();
    let markov = sys.markov(kmax);
    let (p, m) = (sys.noutputs(), sys.ninputs());
    let mut sum: Vec<Matrix<QuadraticField>> =
        (0..kmax).map(|_| Matrix::zeros(k.clone(), p, m)).collect();
    for c in &comps {
        add_traces(c, &jf.components[c.comp].factor, &mut sum);
    }
    let mcm = mcmillan_degree(sys);
    let verified = sum == markov && r == mcm;
    // one block per eigenvalue, marked at it
    let mut blocks = vec![];
    let mut symbols = vec![];
    for c in &comps {
        for (ev, e) in jf.eigenvalues.iter().enumerate() {
            if e.component != c.comp {
                continue;
            }
            let f = jf.root_field(ev);
            let g = &jf.components[c.comp].factor;
            if g.deg() >= 2 && f.0.radical.is_none() {
                symbols.push((
                    e.symbol.clone(),
                    format!("{} (over {k}: root of {g})", e.value),
                ));
            }
            let conv = |mm: &Matrix<RelField>| mm.map(&f, |x| x.clone());
            blocks.push(ModalBlockK {
                eigenvalue: e.value.clone(),
                a: conv(&c.a),
                b: conv(&c.b),
                c: conv(&c.c),
                field: f,
            });
        }
    }
    Ok(JordanMinimalK {
        stages: [n, stage1, r],
        blocks,
        d: sys.d.clone(),
        mcmillan_degree: mcm,
        symbols,
        verified,
    })
}
