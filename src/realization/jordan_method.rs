//! Minimal realization by the Jordan form (minimal-realizations paper sec. 3.3), exactly, over
//! every field with a Jordan decomposition ([`crate::jordan::EigenField`]: $\mathbb{Q}$,
//! $\mathbb{Q}(\sqrt d)$, $\mathbb{Q}(i)$; the computation is [`super::jordan_core`]).
//!
//! In modal coordinates $z = W x$ of each eigenvalue $\theta$ (root of an irreducible factor
//! $p$ over the base field, worked once in $E = F[t]/(p)$, conjugates by embedding) the system
//! splits into Jordan blocks $(J_\theta, W B, C V)$. The method then:
//!
//! 1. **drops non-contributing modes**: in a block $z_i' = \theta z_i + z_{i+1} + b_i u$,
//!    $y \mathrel{+}= \sum c_i z_i$, the states below the last excited one ($i > \max\{j :
//!    b_j \ne 0\}$) stay zero and the states above the first observed one ($i < \min\{j : c_j
//!    \ne 0\}$) never reach $y$; what remains is again a Jordan chain (for the sliding masses the
//!    four modes at $\pm i\sqrt 2$ vanish: 20 → 16 states);
//! 2. **compacts repeated modes** (eq. 34-36, generalised to MIMO and to non-trivial blocks):
//!    the blocks of one eigenvalue are replaced by a minimal realization of $(N, WB, CV)$,
//!    $N = J_\theta - \theta I$ nilpotent, over $K$ (Kalman), put back in Jordan form by the
//!    chains of the reduced nilpotent matrix; for diagonalizable modes this is the exact rank
//!    factorization $b_5 c_5 = b_1 c_1 + b_3 c_3$ of eq. 36 (16 → 8 for the sliding masses);
//! 3. returns the complex modal realization (one block per eigenvalue, entries exact in $E$ at
//!    it) and, over a real field, the **real** Jordan realization: real eigenvalues as they are, each complex pair
//!    $a \pm b i$ as blocks $[[a, b], [-b, a]]$ with $2 \times 2$ identity coupling, with
//!    $x = [\mathrm{Re}\, z; -\mathrm{Im}\, z]$ interleaved, $B_r = [\mathrm{Re}\, B;
//!    -\mathrm{Im}\, B]$, $C_r = [2\,\mathrm{Re}\, C, 2\,\mathrm{Im}\, C]$. Entries are exact in
//!    a real field per eigenvalue: the field of a real root, or the real field of a complex
//!    pair ([`crate::jordan::pair_field`]) when it is small, else the compact form (the
//!    complex data, read off as real and imaginary parts); a pair $a_0 \pm s\sqrt f$ of a
//!    rational quadratic factor over $\mathbb{Q}(\sqrt d)$ keeps its radical form.
//!
//! # Verification
//! Exact: $\sum_p \mathrm{Tr}_{E_p/F}(C_p J_p^k B_p) = C A^k B$ for $k < n + r$ (the
//! trace over the conjugates of each factor lies in $F$), and the order equals the McMillan
//! degree (Hankel rank), so the result is minimal. The real blocks are images of the complex
//! ones under an embedding checked exactly; when every real entry lies in $F$ the real
//! realization's own Markov parameters are compared too ([`JordanMinimal::real_to_base`]).

use super::jordan_core::real_pair_block;
use super::jordan_result::{JordanMinimal, ModalBlock, RealModalBlock};
use crate::algebraic::{Ext, ExtElem, NumberField};
use crate::error::Result;
use crate::field::Q;
use crate::jordan::{EigenField, JordanForm};
use crate::matrix::Matrix;
use crate::system::StateSpace;

/// Minimal realization by the Jordan-form method, complex pairs expanded into their real
/// field only when it is small (degree at most [`crate::jordan::real::EXPAND_MAX_DEGREE`]),
/// otherwise in the compact form ([`RealModalBlock::Compact`]).
///
/// # Errors
/// Errors of the Jordan decomposition and of the Kalman decomposition.
pub fn minimal_jordan<F: EigenField>(sys: &StateSpace<F>) -> Result<JordanMinimal<F>> {
    minimal_jordan_with(sys, false)
}

/// As [`minimal_jordan`]; `expand` writes every complex pair in its real field (a pair whose
/// field cannot be built stays compact).
///
/// # Errors
/// Errors of the Jordan decomposition and of the Kalman decomposition.
pub fn minimal_jordan_with<F: EigenField>(
    sys: &StateSpace<F>,
    expand: bool,
) -> Result<JordanMinimal<F>> {
    let core = super::jordan_core::jordan_core(sys)?;
    let jf = &core.jf;
    let k = sys.a.field().clone();
    let mut blocks = vec![];
    let mut real = k.is_real().then(Vec::new);
    for c in &core.comps {
        for (ev, e) in jf.eigenvalues.iter().enumerate() {
            if e.component != c.comp {
                continue;
            }
            let (f, emb) = jf.root_map(ev);
            let conv = |m: &Matrix<Ext<F>>| m.map(&f, |x: &ExtElem<F::Elem>| emb(x));
            let blk = ModalBlock {
                eigenvalue: ev,
                a: conv(&c.a),
                b: conv(&c.b),
                c: conv(&c.c),
                field: f.clone(),
            };
            if let Some(real) = real.as_mut() {
                if e.approx.1 == 0.0 || e.number.is_real() {
                    real.push(RealModalBlock::Root(blk.clone()));
                } else if e.approx.1 > 0.0 {
                    real.push(real_pair(jf, ev, (c, blk.clone()), expand));
                }
            }
            blocks.push(blk);
        }
    }
    let mut out = JordanMinimal {
        stages: core.stages,
        blocks,
        real,
        d: sys.d.clone(),
        mcmillan_degree: core.mcmillan_degree,
        verified: core.verified,
        jordan: core.jf,
    };
    // the real form in the base field: its Markov parameters directly
    if let Some(rs) = out.real_to_base() {
        out.verified &=
            rs.markov(core.markov.len()) == core.markov && rs.nstates() == out.mcmillan_degree;
    }
    Ok(out)
}

/// The real block of the pair of eigenvalue `ev` from the compacted component `c` (complex
/// data in the component field) and the complex block of its upper root.
fn real_pair<F: EigenField>(
    jf: &JordanForm<F>,
    ev: usize,
    (c, blk): (&super::jordan_core::Compact<F>, ModalBlock<F>),
    expand: bool,
) -> RealModalBlock<F> {
    let k = jf.base();
    let comp = &jf.components[c.comp];
    let radical = comp.factor.deg() == 2
        && comp.minpoly.as_ref().is_some_and(|m| m.deg() == 2)
        && blk.field.0.radical.is_some();
    match F::real_pair(jf, ev, expand) {
        Ok(Some(pf)) => {
            let f = pf.field.clone();
            let [a, b, cc] = real_pair_block(&f, [&c.a, &c.b, &c.c], |x| pf.re_im(k, x));
            RealModalBlock::Pair {
                eigenvalue: ev,
                pair: pf,
                a,
                b,
                c: cc,
            }
        }
        _ if radical => RealModalBlock::Radical(blk),
        _ => RealModalBlock::Compact(blk),
    }
}

impl<F: EigenField> JordanMinimal<F> {
    /// The real modal form as one system over the base field when every entry lies in it
    /// (real roots in $F$, pairs whose real field is $\mathbb{Q}$ or $F$ itself, radical
    /// pairs whose imaginary unit $\sqrt{-f}$ lies in $F$).
    pub fn real_to_base(&self) -> Option<StateSpace<F>> {
        let k = self.d.field().clone();
        let mut parts = vec![];
        for blk in self.real.as_ref()? {
            parts.push(match blk {
                RealModalBlock::Root(b) => {
                    let f = &b.field;
                    let to = |m: &Matrix<Ext<F>>| {
                        let v: Option<Vec<F::Elem>> =
                            m.as_slice().iter().map(|x| f.to_base(x)).collect();
                        Some(Matrix::from_vec(k.clone(), m.nrows(), m.ncols(), v?))
                    };
                    [to(&b.a)?, to(&b.b)?, to(&b.c)?]
                }
                RealModalBlock::Pair { pair, a, b, c, .. } => {
                    let to = |m: &Matrix<NumberField>| {
                        let v: Option<Vec<F::Elem>> = m
                            .as_slice()
                            .iter()
                            .map(|x| k.from_real(&pair.field, x))
                            .collect();
                        Some(Matrix::from_vec(k.clone(), m.nrows(), m.ncols(), v?))
                    };
                    [to(a)?, to(b)?, to(c)?]
                }
                RealModalBlock::Radical(b) => radical_to_base(b, &k)?,
                RealModalBlock::Compact(_) => return None,
            });
        }
        let (p, m) = (self.d.nrows(), self.d.ncols());
        let mut bs = Matrix::zeros(k.clone(), 0, m);
        let mut cs = Matrix::zeros(k.clone(), p, 0);
        let mut a_s = vec![];
        for [a, b, c] in parts {
            a_s.push(a);
            bs = bs.vstack(&b).ok()?;
            cs = cs.hstack(&c).ok()?;
        }
        StateSpace::new(Matrix::block_diag(k, &a_s), bs, cs, self.d.clone()).ok()
    }
}

/// The real block of a radical pair over $F$ when $\sqrt{-f} \in F$ ($-f = 1$, or $F$
/// contains it: [`EigenField::from_real`] of $\mathbb{Q}(\sqrt{-f})$'s generator):
/// $(A_r, B_r, C_r)$ from the exact parts $u$, $w\sqrt{-f}$.
fn radical_to_base<F: EigenField>(b: &ModalBlock<F>, k: &F) -> Option<[Matrix<F>; 3]> {
    let (a0, s, fd) = b.field.0.radical.clone()?;
    let g = -fd;
    let unit = if g == 1.into() {
        k.one()
    } else {
        let qf = crate::jordan::quadratic_field(&g);
        k.from_real(&qf, &qf.generator())?
    };
    let parts = |x: &ExtElem<F::Elem>| {
        let c0 = x.0.first().cloned().unwrap_or_else(|| k.zero());
        let c1 = x.0.get(1).cloned().unwrap_or_else(|| k.zero());
        let re = k.add(&c0, &k.mul(&k.from_rational(&a0), &c1));
        let im = k.mul(&k.mul(&k.from_rational(&s), &c1), &unit);
        (re, im)
    };
    Some(real_pair_block(k, [&b.a, &b.b, &b.c], parts))
}

/// The Jordan-method minimal realization as a rational state-space system, verified like
/// every [`super::MinimalRealization`] (Markov parameters up to $2n$, controllable,
/// observable); available when every mode's block is rational (all retained eigenvalues
/// rational, or complex blocks whose real form is rational).
///
/// # Errors
/// `Unsupported` when some block has entries outside $\mathbb{Q}$ (then use
/// [`minimal_jordan`], whose blocks keep their fields); errors of [`minimal_jordan`].
pub fn minimal_jordan_rational(sys: &StateSpace<Q>) -> Result<super::MinimalRealization<Q>> {
    let jm = minimal_jordan(sys)?;
    let Some(min) = jm.real_to_base() else {
        let blk = jm
            .real
            .iter()
            .flatten()
            .find(|b| !matches!(b, RealModalBlock::Root(b) if b.field.degree() == 1))
            .map(|b| jm.jordan.eigenvalues[b.eigenvalue()].number.to_string())
            .unwrap_or_default();
        return Err(crate::error::Error::Unsupported(format!(
            "the Jordan-method realization has entries outside QQ (mode {blk}): use \
             realization::minimal_jordan"
        )));
    };
    Ok(super::MinimalRealization::new(
        sys,
        min,
        super::MinrealMethod::Jordan,
        None,
    ))
}
