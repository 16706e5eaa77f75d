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
//! entries exact in $E$ at $\theta_j$ (over $\mathbb{Q}(i)$ a non-real $A$ has no real
//! modal form). Over a real $K$ the **real modal** form is given as over $\mathbb{Q}$
//! ([`RealModalBlockK`]): real eigenvalues as they are, each pair $a \pm bi$ as blocks
//! $[[a, b], [-b, a]]$ in its real field $K(\operatorname{Re}\theta,
//! \operatorname{Im}\theta)$ when that has degree at most
//! [`crate::jordan::real::EXPAND_MAX_DEGREE`], otherwise in the compact form.
//!
//! # Verification
//! Exact: $\sum_g \mathrm{Tr}_{E/K}(C_g J_g^k B_g) = C A^k B$ for $k < n + r$ (the trace
//! over the roots of $g$ lies in $K$: $\mathrm{Tr}(\sum_i c_i t^i) = \sum_i c_i s_i$ with
//! the Newton power sums $s_i$ of $g$), and the order $r$ equals the McMillan degree (Hankel
//! rank), so the result is minimal. The real blocks are images of the complex ones under
//! an embedding $E \to F(i)$ checked exactly
//! ([`crate::jordan::over_k::pair_field`]); when every real entry lies in $K$ the real
//! realization's own Markov parameters are also compared
//! ([`JordanMinimalK::real_to_base`]).

use super::controllability::mcmillan_degree;
use super::minimal::minimal_kalman;
use crate::algebraic::{NfElem, NumberField};
use crate::error::Result;
use crate::field::{Field, Quadratic, QuadraticField};
use crate::jordan::chains::{jordan_block_matrix, jordan_chains};
use crate::jordan::over_k::pair_field::{PairField, pair_field};
use crate::jordan::over_k::response::power_sums;
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

/// One block of the real modal form over a real $K$ (as over $\mathbb{Q}$,
/// [`super::RealModalBlock`]).
#[derive(Clone, Debug)]
pub enum RealModalBlockK {
    /// A real eigenvalue: its modal block, real entries exact in $E$ at that root.
    Root(ModalBlockK),
    /// A complex pair $a \pm bi$ in its real field $F = K(\operatorname{Re}\theta,
    /// \operatorname{Im}\theta)$ ([`crate::jordan::over_k::pair_field`]): blocks
    /// $[[a, b], [-b, a]]$ with $I_2$ coupling, $x = [\mathrm{Re}\, z; -\mathrm{Im}\, z]$
    /// interleaved, $B_r = [\mathrm{Re}\, WB; -\mathrm{Im}\, WB]$, $C_r = [2\,\mathrm{Re}\,
    /// CV, 2\,\mathrm{Im}\, CV]$.
    Pair {
        eigenvalue: String,
        field: NumberField,
        a: Matrix<NumberField>,
        b: Matrix<NumberField>,
        c: Matrix<NumberField>,
    },
    /// A pair $a_0 \pm s\sqrt f$ of a rational quadratic factor ($f < 0$): the complex data of
    /// the upper root, whose entries $u + w\sqrt f$ ($u, w \in K$) have the exact real and
    /// imaginary parts $u$ and $w\sqrt{-f}$ (the real block is read off as for `Pair`, written
    /// with the radical).
    Radical(ModalBlockK),
    /// A complex pair whose real field is large: the complex modal data of the upper root,
    /// the real block read off as the real and imaginary parts of its entries (compact form).
    Compact(ModalBlockK),
}

impl RealModalBlockK {
    /// Order of the real block.
    pub fn order(&self) -> usize {
        match self {
            RealModalBlockK::Root(b) => b.a.nrows(),
            RealModalBlockK::Pair { a, .. } => a.nrows(),
            RealModalBlockK::Compact(b) | RealModalBlockK::Radical(b) => 2 * b.a.nrows(),
        }
    }
    /// Display of the eigenvalue(s).
    pub fn eigenvalue(&self) -> String {
        match self {
            RealModalBlockK::Root(b) => b.eigenvalue.clone(),
            RealModalBlockK::Pair { eigenvalue, .. } => format!("{eigenvalue} (and its conjugate)"),
            RealModalBlockK::Compact(b) | RealModalBlockK::Radical(b) => {
                format!("{} (and its conjugate)", b.eigenvalue)
            }
        }
    }
}

/// The Jordan-method minimal realization over $K$.
#[derive(Clone, Debug)]
pub struct JordanMinimalK {
    /// Orders: original, after dropping non-contributing modes, after compaction.
    pub stages: [usize; 3],
    /// The complex modal form: one block per eigenvalue.
    pub blocks: Vec<ModalBlockK>,
    /// Over a real $K$: the real modal form (real eigenvalues, then pairs as real blocks).
    pub real: Option<Vec<RealModalBlockK>>,
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
        let (keep, sizes) = super::jordan_method::drop_modes(&comp.blocks, &bk, &ck);
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
    let mut real = k.is_real().then(Vec::new);
    let mut real_symbols = vec![];
    for c in &comps {
        for (ev, e) in jf.eigenvalues.iter().enumerate() {
            if e.component != c.comp {
                continue;
            }
            let f = jf.root_field(ev);
            let g = &jf.components[c.comp].factor;
            let own = (
                e.symbol.clone(),
                format!("{} (over {k}: root of {g})", e.value),
            );
            let named = g.deg() >= 2 && f.0.radical.is_none();
            if named {
                symbols.push(own.clone());
            }
            let conv = |mm: &Matrix<RelField>| mm.map(&f, |x| x.clone());
            let blk = ModalBlockK {
                eigenvalue: e.value.clone(),
                a: conv(&c.a),
                b: conv(&c.b),
                c: conv(&c.c),
                field: f,
            };
            if let Some(real) = real.as_mut() {
                if e.approx.1 == 0.0 || e.number.is_real() {
                    if named {
                        real_symbols.push(own);
                    }
                    real.push(RealModalBlockK::Root(blk.clone()));
                } else if e.approx.1 > 0.0 {
                    let kk = &e.symbol[1..];
                    let pf = if blk.field.0.radical.is_some() {
                        None
                    } else {
                        pair_field(g, e.approx, &format!("c{kk}"), false)
                            .ok()
                            .flatten()
                    };
                    match pf {
                        Some(pf) => {
                            if let Some(line) = pf.symbol() {
                                let (name, def) = line.split_once(" = ").unwrap_or_default();
                                real_symbols.push((name.into(), def.into()));
                            }
                            real.push(expand_pair(&blk, &pf));
                        }
                        None if blk.field.0.radical.is_some() => {
                            real.push(RealModalBlockK::Radical(blk.clone()));
                        }
                        None => {
                            real_symbols.push(own);
                            real_symbols.push((format!("a{kk}"), format!("Re {}", e.symbol)));
                            real_symbols.push((format!("b{kk}"), format!("Im {}", e.symbol)));
                            real.push(RealModalBlockK::Compact(blk.clone()));
                        }
                    }
                }
            }
            blocks.push(blk);
        }
    }
    if real.is_some() {
        symbols = real_symbols;
    }
    let mut out = JordanMinimalK {
        stages: [n, stage1, r],
        blocks,
        real,
        d: sys.d.clone(),
        mcmillan_degree: mcm,
        symbols,
        verified,
    };
    // the real form in one field K: its Markov parameters directly
    if let Some(rs) = out.real_to_base() {
        out.verified &= rs.markov(kmax) == markov && rs.nstates() == mcm;
    }
    Ok(out)
}

/// The real block of a pair from the complex block of its upper root (see
/// [`RealModalBlockK::Pair`]; the split of [`super::minimal_jordan`]).
fn expand_pair(blk: &ModalBlockK, pf: &PairField) -> RealModalBlockK {
    let f = &pf.field;
    let s = blk.a.nrows();
    let (m, p) = (blk.b.ncols(), blk.c.nrows());
    let two = f.from_i64(2);
    let mut a = Matrix::zeros(f.clone(), 2 * s, 2 * s);
    let mut b = Matrix::zeros(f.clone(), 2 * s, m);
    let mut c = Matrix::zeros(f.clone(), p, 2 * s);
    for i in 0..s {
        for j in 0..s {
            let (x, y) = pf.re_im(blk.a.get(i, j));
            a.set(2 * i, 2 * j, x.clone());
            a.set(2 * i, 2 * j + 1, y.clone());
            a.set(2 * i + 1, 2 * j, f.neg(&y));
            a.set(2 * i + 1, 2 * j + 1, x);
        }
        for col in 0..m {
            let (x, y) = pf.re_im(blk.b.get(i, col));
            b.set(2 * i, col, x);
            b.set(2 * i + 1, col, f.neg(&y));
        }
        for row in 0..p {
            let (x, y) = pf.re_im(blk.c.get(row, i));
            c.set(row, 2 * i, f.mul(&two, &x));
            c.set(row, 2 * i + 1, f.mul(&two, &y));
        }
    }
    RealModalBlockK::Pair {
        eigenvalue: blk.eigenvalue.clone(),
        field: f.clone(),
        a,
        b,
        c,
    }
}

/// The real block of a radical pair over $K$ when $\sqrt{-f} \in K$ ($-f = 1$ or $-f = d$):
/// $(A_r, B_r, C_r)$ as in [`expand_pair`], from the exact parts $u$, $w\sqrt{-f}$.
fn radical_to_base(
    b: &ModalBlockK,
    k: &QuadraticField,
) -> Option<(
    Matrix<QuadraticField>,
    Matrix<QuadraticField>,
    Matrix<QuadraticField>,
)> {
    let (a0, s, fd) = b.field.0.radical.clone()?;
    let g = -fd;
    let unit = if g == 1.into() {
        k.one()
    } else if &g == k.d() {
        k.gen_elem()
    } else {
        return None;
    };
    let parts = |x: &RelElem| {
        let c0 = x.0.first().cloned().unwrap_or_else(|| k.zero());
        let c1 = x.0.get(1).cloned().unwrap_or_else(|| k.zero());
        let re = k.add(&c0, &k.mul(&k.from_rational(&a0), &c1));
        let im = k.mul(&k.mul(&k.from_rational(&s), &c1), &unit);
        (re, im)
    };
    let sz = b.a.nrows();
    let (m, p) = (b.b.ncols(), b.c.nrows());
    let two = k.from_i64(2);
    let mut a = Matrix::zeros(k.clone(), 2 * sz, 2 * sz);
    let mut bb = Matrix::zeros(k.clone(), 2 * sz, m);
    let mut c = Matrix::zeros(k.clone(), p, 2 * sz);
    for i in 0..sz {
        for j in 0..sz {
            let (x, y) = parts(b.a.get(i, j));
            a.set(2 * i, 2 * j, x.clone());
            a.set(2 * i, 2 * j + 1, y.clone());
            a.set(2 * i + 1, 2 * j, k.neg(&y));
            a.set(2 * i + 1, 2 * j + 1, x);
        }
        for col in 0..m {
            let (x, y) = parts(b.b.get(i, col));
            bb.set(2 * i, col, x);
            bb.set(2 * i + 1, col, k.neg(&y));
        }
        for row in 0..p {
            let (x, y) = parts(b.c.get(row, i));
            c.set(row, 2 * i, k.mul(&two, &x));
            c.set(row, 2 * i + 1, k.mul(&two, &y));
        }
    }
    Some((a, bb, c))
}

impl JordanMinimalK {
    /// The real modal form as one system over $K$ when every entry lies in $K$ (real
    /// roots in $K$, pairs whose real field is $\mathbb{Q}$ or $K$ itself).
    pub fn real_to_base(&self) -> Option<StateSpace<QuadraticField>> {
        let k = self.d.field().clone();
        let d = Poly::new(
            crate::field::Q,
            vec![
                crate::field::Rational::from_integer(-k.d().clone()),
                crate::field::Rational::default(),
                crate::field::Rational::from_integer(1.into()),
            ],
        );
        let nf = |f: &NumberField, x: &NfElem| -> Option<Quadratic> {
            let c = |i: usize| x.0.get(i).cloned().unwrap_or_default();
            match f.degree() {
                1 => f
                    .to_rational(x)
                    .map(|q| Quadratic::new(q, Default::default())),
                2 if *f.modulus() == d => Some(Quadratic::new(c(0), c(1))),
                _ => None,
            }
        };
        let mut parts = vec![];
        for blk in self.real.as_ref()? {
            parts.push(match blk {
                RealModalBlockK::Root(b) => {
                    let f = &b.field;
                    let to = |m: &Matrix<RelField>| {
                        let v: Option<Vec<Quadratic>> =
                            m.as_slice().iter().map(|x| f.to_base(x)).collect();
                        Some(Matrix::from_vec(k.clone(), m.nrows(), m.ncols(), v?))
                    };
                    (to(&b.a)?, to(&b.b)?, to(&b.c)?)
                }
                RealModalBlockK::Pair { field, a, b, c, .. } => {
                    let to = |m: &Matrix<NumberField>| {
                        let v: Option<Vec<Quadratic>> =
                            m.as_slice().iter().map(|x| nf(field, x)).collect();
                        Some(Matrix::from_vec(k.clone(), m.nrows(), m.ncols(), v?))
                    };
                    (to(a)?, to(b)?, to(c)?)
                }
                RealModalBlockK::Radical(b) => radical_to_base(b, &k)?,
                RealModalBlockK::Compact(_) => return None,
            });
        }
        let (p, m) = (self.d.nrows(), self.d.ncols());
        let mut bs = Matrix::zeros(k.clone(), 0, m);
        let mut cs = Matrix::zeros(k.clone(), p, 0);
        let mut a_s = vec![];
        for (a, b, c) in parts {
            a_s.push(a);
            bs = bs.vstack(&b).ok()?;
            cs = cs.hstack(&c).ok()?;
        }
        StateSpace::new(Matrix::block_diag(k, &a_s), bs, cs, self.d.clone()).ok()
    }
}
