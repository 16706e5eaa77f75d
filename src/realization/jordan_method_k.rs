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

/// Newton power sums $s_0, \dots, s_{d-1}$ of the roots of the monic `g` over $K$.
fn power_sums(g: &Poly<QuadraticField>) -> Vec<Quadratic> {
    let k = g.field();
    let d = g.deg();
    let a = |i: usize| g.coeff(i); // x^d + a_{d-1} x^{d-1} + ... + a_0
    let mut s = vec![k.from_i64(d as i64)];
    for j in 1..d {
        // s_j = -(j a_{d-j} + sum_{i=1}^{j-1} a_{d-i} s_{j-i})
        let mut v = k.mul(&k.from_i64(j as i64), &a(d - j));
        for i in 1..j {
            v = k.add(&v, &k.mul(&a(d - i), &s[j - i]));
        }
        s.push(k.neg(&v));
    }
    s
}

/// $\mathrm{Tr}_{E/K}(x)$.
fn trace(x: &RelElem, s: &[Quadratic], k: &QuadraticField) -> Quadratic {
    x.0.iter()
        .zip(s)
        .fold(k.zero(), |acc, (c, p)| k.add(&acc, &k.mul(c, p)))
}

/// One compacted component: $(J, B, C)$ over $E$ (marked at the first root), the index of
/// its component.
struct Compact {
    comp: usize,
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
        let s = power_sums(&jf.components[c.comp].factor);
        let mut jb = c.b.clone();
        for term in sum.iter_mut() {
            let h = &c.c * &jb;
            for i in 0..p {
                for j in 0..m {
                    let v = k.add(term.get(i, j), &trace(h.get(i, j), &s, &k));
                    term.set(i, j, v);
                }
            }
            jb = &c.a * &jb;
        }
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
