//! The Jordan-method minimal realization written over the base field $F$ itself, for any
//! field with [`Component`]s of $A$ (over $\mathbb{Q}(p)$ from
//! [`crate::jordan::over_qp::components_qp`]): eigenvalues in $F$ as Jordan blocks, the
//! roots of an irreducible factor $g$ of degree $d \ge 2$ as one primary block.
//!
//! The compaction is the generic one ([`super::jordan_core::compact_components`]: drop the
//! non-contributing modes, compact the repeated ones, over $E = F\[t\]/(g)$). A compacted
//! component $(J, B, C)$ over $E$ ($r$ states) is written over $F$ by the regular
//! representation of $E$ in the basis $1, t, \dots, t^{d-1}$ ($r d$ states):
//! $$A_F = [M_{J_{ij}}]_{ij}, \qquad (B_F)_{(i, l), j} = [t^l] B_{ij}, \qquad
//! (C_F)_{i, (j, l)} = \mathrm{Tr}_{E/F}(C_{ij} t^l),$$
//! with $M_x$ the matrix of $y \mapsto x y$. Then $C_F A_F^k B_F = \mathrm{Tr}_{E/F}(C J^k B)$
//! (the trace is $F$-linear), so the sum over the components is $C A^k B$: the realization
//! over $F$ is minimal of the same order $\sum_g r_g d_g$. For $d = 1$ it is the Jordan block
//! itself.
//!
//! A simple factor ($e = 1$) of degree $d \ge 2$ needs no chains over $E$ (over
//! $\mathbb{Q}(p)$ their normalisation $W V = I$ inverts elements of $E$ whose coefficients
//! are huge rational functions: > 300 s on the 7-symbol yaw plane): its block is the
//! restriction $(A_g, P B, C u)$ ($u$ a basis of $\ker g(A)$, $A u = u A_g$, $P$ the
//! projector along $\operatorname{im} g(A)$), kept when $P B \ne 0$ and $C u \ne 0$ ($g$
//! irreducible: then it is controllable and observable), $d$ states
//! ([`crate::jordan::over_qp::simple_primary_component`], used by [`minimal_jordan_qp`]).
//!
//! # Verification
//! Exact, over $F$: the order equals the McMillan degree, and the realization's own Markov
//! parameters $C_F A_F^k B_F$ equal $C A^k B$ for $k < n + r$ (with the feedthrough $D$
//! unchanged; for the regular-representation blocks this is the trace identity
//! $\sum_g \mathrm{Tr}_{E/F}(C_g J_g^k B_g) = C A^k B$).

use super::controllability::mcmillan_degree;
use super::jordan_core::{Compact, compact_component, trace_shifted};
use super::jordan_result::{PrimaryBlock, PrimaryJordanMinimal};
use crate::algebraic::{Ext, ExtElem};
use crate::error::Result;
use crate::field::Field;
use crate::jordan::primary::Component;
use crate::matrix::Matrix;
use crate::poly::{Poly, newton_power_sums};
use crate::ratfunc::RatFuncField;
use crate::system::StateSpace;

/// The coefficients of `x` in $1, t, \dots, t^{d-1}$.
fn coefficients<F: Field>(e: &Ext<F>, x: &ExtElem<F::Elem>) -> Vec<F::Elem> {
    let mut v = x.0.clone();
    v.resize(e.degree(), e.base().zero());
    v
}

/// $(A_F, B_F, C_F)$ of one compacted component (module docs).
pub(super) fn regular_representation<F: Field>(
    c: &Compact<F>,
    comp: &Component<F>,
) -> (Matrix<F>, Matrix<F>, Matrix<F>) {
    let e = &comp.field;
    let k = e.base().clone();
    let d = e.degree();
    let (r, m, p) = (c.a.nrows(), c.b.ncols(), c.c.nrows());
    let powers: Vec<ExtElem<F::Elem>> = (0..d)
        .map(|l| {
            let mut x = vec![k.zero(); l];
            x.push(k.one());
            e.from_poly(&Poly::new(k.clone(), x))
        })
        .collect();
    let s = newton_power_sums(&comp.factor.monic(), 2 * d);
    let mut a = Matrix::zeros(k.clone(), r * d, r * d);
    for i in 0..r {
        for j in 0..r {
            let x = c.a.get(i, j);
            if e.is_zero(x) {
                continue;
            }
            for (l, tl) in powers.iter().enumerate() {
                for (row, v) in coefficients(e, &e.mul(x, tl)).into_iter().enumerate() {
                    a.set(i * d + row, j * d + l, v);
                }
            }
        }
    }
    let mut b = Matrix::zeros(k.clone(), r * d, m);
    for i in 0..r {
        for j in 0..m {
            for (l, v) in coefficients(e, c.b.get(i, j)).into_iter().enumerate() {
                b.set(i * d + l, j, v);
            }
        }
    }
    let mut cf = Matrix::zeros(k.clone(), p, r * d);
    for i in 0..p {
        for j in 0..r {
            for l in 0..d {
                cf.set(i, j * d + l, trace_shifted(&k, c.c.get(i, j), l, &s));
            }
        }
    }
    (a, b, cf)
}

/// One retained block over $F$: its Jordan block sizes, $(J, B, C)$ over $E$ (empty for a
/// restriction block) and $(A_F, B_F, C_F)$.
type Part<F> = (Vec<usize>, [Matrix<Ext<F>>; 3], [Matrix<F>; 3]);

/// The block of a simple component given by its restriction (no chains over $E$,
/// [`crate::jordan::over_qp::simple_primary_component`]): $(A_g, P B, C u)$, or `None` when
/// $P B = 0$ or $C u = 0$ (the roots of $g$ are not excited or not observed).
fn restriction_part<F: Field>(sys: &StateSpace<F>, comp: &Component<F>) -> Result<Option<Part<F>>> {
    let (a, b, c) = match &comp.restriction {
        Some(r) => (
            r.ap.clone(),
            r.projector()?.try_mul(&sys.b)?,
            sys.c.try_mul(&r.u)?,
        ),
        None => (sys.a.clone(), sys.b.clone(), sys.c.clone()),
    };
    if b.is_zero() || c.is_zero() {
        return Ok(None);
    }
    let e = &comp.field;
    let empty = || Matrix::zeros(e.clone(), 0, 0);
    Ok(Some((vec![1], [empty(), empty(), empty()], [a, b, c])))
}

/// The Jordan-method minimal realization over $F$ from the components of $A$ (module docs):
/// a component with chains over $E$ compacted and written by the regular representation, a
/// simple component without chains by its restriction ([`restriction_part`]).
///
/// # Errors
/// Those of the Kalman decomposition in the compaction.
pub fn minimal_jordan_primary<F: Field + 'static>(
    sys: &StateSpace<F>,
    components: Vec<Component<F>>,
) -> Result<PrimaryJordanMinimal<F>> {
    let n = sys.nstates();
    let k = sys.a.field().clone();
    let mut stage1 = 0;
    let mut parts: Vec<(usize, Part<F>)> = vec![];
    for (ci, comp) in components.iter().enumerate() {
        let part = if comp.has_chains() {
            compact_component(sys, ci, comp, &mut stage1)?.map(|c| {
                let (a, b, cf) = regular_representation(&c, comp);
                (c.blocks, [c.a, c.b, c.c], [a, b, cf])
            })
        } else {
            let p = restriction_part(sys, comp)?;
            stage1 += p.as_ref().map_or(0, |p| p.2[0].nrows());
            p
        };
        parts.extend(part.map(|p| (ci, p)));
    }
    let (mut aa, mut bb, mut cc) = (vec![], vec![], vec![]);
    let mut blocks = vec![];
    let mut offset = 0;
    for (ci, (sizes, modal, [a, b, cf])) in parts {
        let order = a.nrows();
        blocks.push(PrimaryBlock {
            component: ci,
            blocks: sizes,
            offset,
            order,
            modal,
        });
        offset += order;
        aa.push(a);
        bb.push(b);
        cc.push(cf);
    }
    let a = Matrix::block_diag(k.clone(), &aa);
    let mut b = Matrix::zeros(k.clone(), offset, sys.ninputs());
    let mut c = Matrix::zeros(k.clone(), sys.noutputs(), offset);
    let mut off = 0;
    for (bi, ci) in bb.iter().zip(&cc) {
        b.set_block(off, 0, bi);
        c.set_block(0, off, ci);
        off += bi.nrows();
    }
    let system = StateSpace::new(a, b, c, sys.d.clone())?;
    let mcmillan_degree = mcmillan_degree(sys);
    let kmax = n + offset;
    let verified = system.markov(kmax) == sys.markov(kmax) && system.nstates() == mcmillan_degree;
    Ok(PrimaryJordanMinimal {
        stages: [n, stage1, offset],
        components,
        blocks,
        system,
        mcmillan_degree,
        verified,
    })
}

/// The Jordan-method minimal realization over $\mathbb{Q}(p)$: the factors of
/// [`crate::jordan::over_qp::charpoly_factors`] (their conditions recorded in `sys`'s field),
/// a simple factor of degree $\ge 2$ by its restriction
/// ([`crate::jordan::over_qp::simple_primary_component`]), every other one by
/// [`Component::compute`] (chains over $\mathbb{Q}(p)$ or $E$), then
/// [`minimal_jordan_primary`].
///
/// # Errors
/// Those of the decomposition over $\mathbb{Q}(p)$ and of the compaction.
pub fn minimal_jordan_qp(
    sys: &StateSpace<RatFuncField>,
) -> Result<PrimaryJordanMinimal<RatFuncField>> {
    minimal_jordan_primary(sys, components_qp_minimal(&sys.a)?)
}

/// The components [`minimal_jordan_qp`] realizes (and its `--steps` derivation derives): one
/// per factor of [`crate::jordan::over_qp::charpoly_factors`] (conditions recorded in `a`'s
/// field), a simple factor of degree $\ge 2$ by its restriction
/// ([`crate::jordan::over_qp::simple_primary_component`], no chains), every other one by
/// [`Component::compute`].
///
/// # Errors
/// Those of the decomposition over $\mathbb{Q}(p)$.
pub(super) fn components_qp_minimal(
    a: &Matrix<RatFuncField>,
) -> Result<Vec<Component<RatFuncField>>> {
    let cp = crate::jordan::over_qp::charpoly_factors(a)?;
    cp.factors
        .iter()
        .map(|f| {
            if f.monic.deg() >= 2 && f.multiplicity == 1 {
                crate::jordan::over_qp::simple_primary_component(a, &f.monic)
            } else {
                Component::compute(a, &f.monic, f.multiplicity, None, vec![], true)
            }
        })
        .collect()
}
