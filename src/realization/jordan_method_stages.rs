//! The Jordan method step by step, the parts written over the base field $F$: the
//! restriction step of a simple factor and the stages (`minreal --method jordan --steps`).
//!
//! **Restriction** (a simple irreducible factor $g$ of degree $d \ge 2$, no chains over
//! $E = F\[t\]/(g)$, [`crate::jordan::over_qp::simple_primary_component`]): $u$ a basis of
//! $\ker g(A)$ and $A_g$ with $A u = u A_g$; $P$ the projector along $\operatorname{im} g(A)$
//! with $P u = I_d$ and $P A = A_g P$. The part $(A_g, P B, C u)$ is the factor's share of
//! $C (sI - A)^{-1} B$; it is kept iff $P B \ne 0$ (excited) and $C u \ne 0$ (observed), and
//! then it is minimal: $g$ irreducible, so the only $A_g$-invariant subspaces are $0$ and
//! $F^d$, and the controllable subspace (containing $\operatorname{im} P B \ne 0$) is
//! everything, the unobservable one (missing a vector with $C u x \ne 0$) is $0$. For $d = n$
//! the part is $(A, B, C)$ itself ($u = P = I$).
//!
//! **Stages.** Stage $s$ (original, after dropping, after compacting) is the block-diagonal
//! realization over $F$ of the components' parts at that stage: a part $(J, B, C)$ over $E$
//! by the regular representation of $E$ ([`super::jordan_method_primary`]), a restriction
//! part as it is. Each stage reproduces the Markov parameters exactly,
//! $C_s A_s^k B_s = C A^k B$ for $k < 2n$ (both orders are $\le n$, so the transfer matrices
//! are equal); the method's realization $(A_r, B_r, C_r, D)$ (the command's result) does too,
//! with order = McMillan degree = the last stage's order.

use super::controllability::mcmillan_degree;
use super::jordan_core::Compact;
use super::jordan_method_primary::regular_representation;
use crate::algebraic::Ext;
use crate::error::Result;
use crate::field::Field;
use crate::jordan::derivation::{Object, Recorder, StepKind};
use crate::jordan::primary::Component;
use crate::matrix::Matrix;
use crate::system::StateSpace;

/// $(A, B, C)$ of one part over $F$.
pub(super) type Triple<F> = [Matrix<F>; 3];

/// A component's parts at the three stages (`None`: nothing left of it at that stage).
pub(super) type StageParts<F> = [Option<Triple<F>>; 3];

/// A part $(J, B, C)$ over the component's field written over $F$ (regular representation).
pub(super) fn over_base<F: Field>(
    comp: &Component<F>,
    part: usize,
    j: &Matrix<Ext<F>>,
    b: &Matrix<Ext<F>>,
    c: &Matrix<Ext<F>>,
) -> Triple<F> {
    let c = Compact {
        comp: part,
        blocks: vec![],
        a: j.clone(),
        b: b.clone(),
        c: c.clone(),
    };
    let (a, b, c) = regular_representation(&c, comp);
    [a, b, c]
}

/// A matrix over $F$ in the derivation's field (the degree-one extension $F\[t\]/(t)$).
fn lift<F: Field>(e: &Ext<F>, m: &Matrix<F>) -> Matrix<Ext<F>> {
    m.map(e, |x| e.from_base(x))
}

/// The restriction step of a simple component without chains (module docs); returns its
/// part at each stage.
///
/// # Errors
/// `Verification` when the restriction was computed without its projector.
pub(super) fn restriction_step<F: Field>(
    rec: &mut Recorder<'_, Ext<F>>,
    part: usize,
    sys: &StateSpace<F>,
    comp: &Component<F>,
) -> Result<StageParts<F>> {
    let e = rec.peek().field.clone();
    let k = sys.a.field().clone();
    let (u, ag, p) = match &comp.restriction {
        Some(r) => (r.u.clone(), r.ap.clone(), r.projector()?.clone()),
        None => {
            let i = Matrix::identity(k.clone(), sys.nstates());
            (i.clone(), sys.a.clone(), i)
        }
    };
    let (pb, cu) = (p.try_mul(&sys.b)?, sys.c.try_mul(&u)?);
    let (excited, observed) = (!pb.is_zero(), !cu.is_zero());
    let d = ag.nrows();
    let ok = sys.a.try_mul(&u)? == u.try_mul(&ag)?
        && p.try_mul(&u)? == Matrix::identity(k.clone(), d)
        && p.try_mul(&sys.a)? == ag.try_mul(&p)?;
    let mut objects = vec![
        ("g", Object::Poly(comp.factor.map(&e, |x| e.from_base(x)))),
        ("deg", Object::Count(comp.degree())),
    ];
    if comp.restriction.is_some() {
        objects.push(("u", Object::Matrix(lift(&e, &u))));
    }
    objects.push(("Ag", Object::Matrix(lift(&e, &ag))));
    if comp.restriction.is_some() {
        objects.push(("P", Object::Matrix(lift(&e, &p))));
    }
    objects.extend([
        ("PB", Object::Matrix(lift(&e, &pb))),
        ("Cu", Object::Matrix(lift(&e, &cu))),
        ("excited", Object::Count(usize::from(excited))),
        ("observed", Object::Count(usize::from(observed))),
    ]);
    rec.push(StepKind::Restriction, Some(part), objects, Some(ok));
    let all = [ag, pb, cu];
    let kept = (excited && observed).then(|| all.clone());
    Ok([Some(all), kept.clone(), kept])
}

/// The block-diagonal realization of `parts` over $F$ (strictly proper).
///
/// # Errors
/// Shape errors only (the parts come from one system).
pub(super) fn stage_system<F: Field>(
    sys: &StateSpace<F>,
    parts: &[Triple<F>],
) -> Result<StateSpace<F>> {
    let k = sys.a.field().clone();
    let blocks: Vec<Matrix<F>> = parts.iter().map(|p| p[0].clone()).collect();
    let a = Matrix::block_diag(k.clone(), &blocks);
    let n = a.nrows();
    let mut b = Matrix::zeros(k.clone(), n, sys.ninputs());
    let mut c = Matrix::zeros(k, sys.noutputs(), n);
    let mut off = 0;
    for [pa, pb, pc] in parts {
        b.set_block(off, 0, pb);
        c.set_block(0, off, pc);
        off += pa.nrows();
    }
    StateSpace::new_strictly_proper(a, b, c)
}

/// The stages step (module docs): the orders of the stages, each stage's Markov check, the
/// method's realization `system` (the command's result) and its check.
///
/// # Errors
/// Shape errors only.
pub(super) fn stages_step<F: Field>(
    rec: &mut Recorder<'_, Ext<F>>,
    sys: &StateSpace<F>,
    parts: &[StageParts<F>],
    system: &StateSpace<F>,
) -> Result<()> {
    let e = rec.peek().field.clone();
    let n = sys.nstates();
    let kmax = 2 * n.max(1);
    let want = sys.markov(kmax);
    let strictly = |s: &StateSpace<F>| s.markov(kmax);
    let mut orders = vec![];
    let mut ok = true;
    for s in 0..3 {
        let at: Vec<Triple<F>> = parts.iter().filter_map(|p| p[s].clone()).collect();
        let st = stage_system(sys, &at)?;
        orders.push(st.nstates());
        ok &= strictly(&st) == want;
    }
    let mcmillan = mcmillan_degree(sys);
    let r = system.nstates();
    ok &= system.markov(kmax) == want
        && system.d == sys.d
        && r == mcmillan
        && orders[0] == n
        && orders[2] == r;
    rec.push(
        StepKind::Stages,
        None,
        vec![
            ("stages", Object::Counts(orders)),
            ("mcmillan", Object::Count(mcmillan)),
            ("Ar", Object::Matrix(lift(&e, &system.a))),
            ("Br", Object::Matrix(lift(&e, &system.b))),
            ("Cr", Object::Matrix(lift(&e, &system.c))),
            ("Dr", Object::Matrix(lift(&e, &system.d))),
        ],
        Some(ok),
    );
    Ok(())
}
