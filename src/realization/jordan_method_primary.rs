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
//! # Verification
//! Exact, over $F$: the trace identity of the compaction, the order equals the McMillan
//! degree, and the realization's own Markov parameters $C_F A_F^k B_F$ equal $C A^k B$ for
//! $k < n + r$ (with the feedthrough $D$ unchanged).

use super::jordan_core::{Compact, Compacted, compact_components, trace_shifted};
use crate::algebraic::{Ext, ExtElem};
use crate::error::Result;
use crate::field::Field;
use crate::jordan::primary::Component;
use crate::matrix::Matrix;
use crate::poly::{Poly, newton_power_sums};
use crate::ratfunc::RatFuncField;
use crate::system::StateSpace;

/// One retained component in the realization over $F$.
#[derive(Clone, Debug, PartialEq)]
pub struct PrimaryBlock<F: Field> {
    /// Index into [`PrimaryJordanMinimal::components`].
    pub component: usize,
    /// Jordan block sizes of each root after the compaction, largest first.
    pub blocks: Vec<usize>,
    /// First state of the block in [`PrimaryJordanMinimal::system`] and its number of states
    /// (sum of `blocks` times the degree of the factor).
    pub offset: usize,
    pub order: usize,
    /// $(J, B, C)$ over $E$ (marked as the component's field) before the regular
    /// representation.
    pub modal: [Matrix<Ext<F>>; 3],
}

/// The Jordan-method minimal realization over $F$ (module docs).
#[derive(Clone, Debug)]
pub struct PrimaryJordanMinimal<F: Field> {
    /// Orders: original, after dropping non-contributing modes, after compaction.
    pub stages: [usize; 3],
    /// One component per irreducible factor of $\chi_A$ over $F$.
    pub components: Vec<Component<F>>,
    /// The retained components, in the order of their states.
    pub blocks: Vec<PrimaryBlock<F>>,
    /// The minimal realization $(A_F, B_F, C_F, D)$.
    pub system: StateSpace<F>,
    pub mcmillan_degree: usize,
    /// The checks of the module docs held exactly.
    pub verified: bool,
}

/// The coefficients of `x` in $1, t, \dots, t^{d-1}$.
fn coefficients<F: Field>(e: &Ext<F>, x: &ExtElem<F::Elem>) -> Vec<F::Elem> {
    let mut v = x.0.clone();
    v.resize(e.degree(), e.base().zero());
    v
}

/// $(A_F, B_F, C_F)$ of one compacted component (module docs).
fn regular_representation<F: Field>(
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

/// The Jordan-method minimal realization over $F$ from the components of $A$ (module docs).
///
/// # Errors
/// Those of the Kalman decomposition in the compaction.
pub fn minimal_jordan_primary<F: Field + 'static>(
    sys: &StateSpace<F>,
    components: Vec<Component<F>>,
) -> Result<PrimaryJordanMinimal<F>> {
    let Compacted {
        comps,
        stages,
        mcmillan_degree,
        markov,
        mut verified,
    } = compact_components(sys, &components)?;
    let k = sys.a.field().clone();
    let (mut aa, mut bb, mut cc) = (vec![], vec![], vec![]);
    let mut blocks = vec![];
    let mut offset = 0;
    for c in &comps {
        let (a, b, cf) = regular_representation(c, &components[c.comp]);
        let order = a.nrows();
        blocks.push(PrimaryBlock {
            component: c.comp,
            blocks: c.blocks.clone(),
            offset,
            order,
            modal: [c.a.clone(), c.b.clone(), c.c.clone()],
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
    verified &= system.markov(markov.len()) == markov && system.nstates() == mcmillan_degree;
    Ok(PrimaryJordanMinimal {
        stages,
        components,
        blocks,
        system,
        mcmillan_degree,
        verified,
    })
}

/// The Jordan-method minimal realization over $\mathbb{Q}(p)$: components from
/// [`crate::jordan::over_qp::components_qp`] (their conditions recorded in `sys`'s field),
/// then [`minimal_jordan_primary`].
///
/// # Errors
/// Those of the decomposition over $\mathbb{Q}(p)$ and of the compaction.
pub fn minimal_jordan_qp(
    sys: &StateSpace<RatFuncField>,
) -> Result<PrimaryJordanMinimal<RatFuncField>> {
    let (_, comps) = crate::jordan::over_qp::components_qp(&sys.a)?;
    minimal_jordan_primary(sys, comps)
}
