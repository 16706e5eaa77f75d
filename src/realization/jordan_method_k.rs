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

use super::jordan_core::real_pair_block;
use crate::algebraic::{NfElem, NumberField};
use crate::error::Result;
use crate::field::{Field, Quadratic, QuadraticField};
use crate::jordan::over_k::pair_field::{PairField, pair_field};
use crate::jordan::over_k::{JordanFormK, RelElem, RelField};
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

/// Minimal realization of a system over $K$ by the Jordan-form method (module docs).
///
/// # Errors
/// Those of [`jordan_over_k`] and of the Kalman decomposition.
pub fn minimal_jordan_over_k(sys: &StateSpace<QuadraticField>) -> Result<JordanMinimalK> {
    let core = super::jordan_core::jordan_core(sys)?;
    let jf: &JordanFormK = &core.jf;
    let k = sys.a.field().clone();
    // one block per eigenvalue, marked at it
    let mut blocks = vec![];
    let mut symbols = vec![];
    let mut real = k.is_real().then(Vec::new);
    let mut real_symbols = vec![];
    for c in &core.comps {
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
    let mcm = core.mcmillan_degree;
    let mut out = JordanMinimalK {
        stages: core.stages,
        blocks,
        real,
        d: sys.d.clone(),
        mcmillan_degree: mcm,
        symbols,
        verified: core.verified,
    };
    // the real form in one field K: its Markov parameters directly
    if let Some(rs) = out.real_to_base() {
        out.verified &= rs.markov(core.markov.len()) == core.markov && rs.nstates() == mcm;
    }
    Ok(out)
}

/// The real block of a pair from the complex block of its upper root (see
/// [`RealModalBlockK::Pair`]; the split of [`super::minimal_jordan`]).
fn expand_pair(blk: &ModalBlockK, pf: &PairField) -> RealModalBlockK {
    let f = &pf.field;
    let [a, b, c] = real_pair_block(f, [&blk.a, &blk.b, &blk.c], |x| pf.re_im(x));
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
    let [a, bb, c] = real_pair_block(k, [&b.a, &b.b, &b.c], parts);
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
