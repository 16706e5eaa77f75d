//! Minimal realization step by step (`minreal --steps`), recorded as a
//! [`Derivation`](crate::jordan::derivation::Derivation).
//!
//! **Kalman** (any field, also $\mathbb{Q}(p)$ with the conditions of each step):
//! $\mathcal C = [B, AB, \dots, A^{n-1}B]$ and its rank; the controllable subspace
//! $\mathcal R$ = the pivot columns of the RREF of $\mathcal C$ (Krylov vectors; checked:
//! $\operatorname{im} B \subseteq \mathcal R$, $A\mathcal R \subseteq \mathcal R$);
//! $\mathcal O$ and its rank; $\mathcal N = \ker \mathcal O$ ($\mathcal O \mathcal N = 0$,
//! $A\mathcal N \subseteq \mathcal N$); the basis $T$ of [`super::kalman_decomposition`]
//! ($\dim$ parts add up, $T$ invertible); the Kalman form ($A T = T \tilde A$, $B = T \tilde B$,
//! $\tilde C = C T$ with its zero pattern); the minimal part and the Markov check
//! $C A^k B = C_2 A_{22}^k B_2$ ($k < n + r$), $r$ = McMillan degree.
//!
//! **Jordan method** (over $\mathbb{Q}$, one number field $K_p = \mathbb{Q}\[t\]/(p)$ per
//! irreducible factor; over $\mathbb{Q}(p)$ one $E = \mathbb{Q}(p)\[t\]/(g)$ per factor, with
//! the conditions of each step): per eigenvalue the modal data $(J_\theta, WB, CV)$; the states dropped
//! (after the last excited one in their block: not excited; before the first observed one:
//! not observed) with the check that the block's Markov parameters are unchanged; the
//! compaction of repeated modes (a minimal realization of $(N, WB, CV)$ in Jordan form, Markov
//! parameters unchanged); over $\mathbb{Q}(p)$ a simple factor of degree $\ge 2$ by its
//! restriction $(A_g, P B, C u)$ instead (no chains over $E$, as the command); the stages
//! (20 → 16 → 8 for the sliding masses), each written over the base field and checked to
//! reproduce $C A^k B$, and the command's realization with its check
//! ([`super::jordan_method_stages`]).

use super::controllability::{controllability_matrix, mcmillan_degree, observability_matrix};
use super::jordan_core::{base_times as rational_times, drop_modes, times_base as times_rational};
use super::jordan_method_primary::{components_qp_minimal, minimal_jordan_primary};
use super::jordan_method_stages::{StageParts, over_base, restriction_step, stages_step};
use super::kalman::kalman_decomposition;
use super::method::SystemField;
use super::minimal::minimal_kalman;
use crate::algebraic::{Ext, NumberField};
use crate::error::Result;
use crate::field::{Field, Q};
use crate::jordan::chains::{jordan_block_matrix, jordan_chains};
use crate::jordan::derivation::{AssumptionLog, Derivation, Method, Object, Recorder, StepKind};
use crate::jordan::primary::Component;
use crate::jordan::real_steps::{degree_one, lift_log};
use crate::matrix::Matrix;
use crate::ratfunc::RatFuncField;
use crate::system::StateSpace;

pub use super::steps_record::{hankel_factor_identity, staircase_identity};

/// The Kalman minimal realization step by step (module docs); `log` gives the assumptions
/// made so far (over $\mathbb{Q}(p)$, see
/// [`crate::jordan::derivation::ratfunc_log`]).
///
/// # Errors
/// As [`super::kalman_decomposition`].
pub fn kalman_steps<'a, K: Field>(
    sys: &StateSpace<K>,
    log: Option<AssumptionLog<'a, K>>,
) -> Result<Derivation<K>> {
    let k = sys.field().clone();
    let mut rec = match log {
        Some(l) => Recorder::with_log(Method::Kalman, k.clone(), l),
        None => Recorder::new(Method::Kalman, k.clone()),
    };
    let n = sys.nstates();
    let ctrb = controllability_matrix(&sys.a, &sys.b);
    let piv = ctrb.pivots();
    let rc = piv.len();
    rec.push(
        StepKind::Controllability,
        None,
        vec![
            ("Ctrb", Object::Matrix(ctrb.clone())),
            ("rank", Object::Count(rc)),
        ],
        None,
    );
    let r = ctrb.select_cols(&piv);
    let ok =
        r.rank() == rc && r.hstack(&(&sys.a * &r))?.rank() == rc && r.hstack(&sys.b)?.rank() == rc;
    rec.push(
        StepKind::ControllableSubspace,
        None,
        vec![("R", Object::Matrix(r)), ("pivots", Object::Counts(piv))],
        Some(ok),
    );
    let obsv = observability_matrix(&sys.a, &sys.c);
    let ro = obsv.rank();
    rec.push(
        StepKind::Observability,
        None,
        vec![
            ("Obsv", Object::Matrix(obsv.clone())),
            ("rank", Object::Count(ro)),
        ],
        None,
    );
    let nn = obsv.nullspace();
    let ok = (&obsv * &nn).is_zero()
        && nn.ncols() == n - ro
        && nn.hstack(&(&sys.a * &nn))?.rank() == n - ro;
    rec.push(
        StepKind::UnobservableSubspace,
        None,
        vec![("Nobs", Object::Matrix(nn))],
        Some(ok),
    );
    let kd = kalman_decomposition(sys)?;
    let ok = kd.t.rank() == n && kd.dims[0] + kd.dims[1] == rc && kd.dims[0] + kd.dims[2] == n - ro;
    rec.push(
        StepKind::KalmanBasis,
        None,
        vec![
            ("T", Object::Matrix(kd.t.clone())),
            ("dims", Object::Counts(kd.dims.to_vec())),
        ],
        Some(ok),
    );
    let s = &kd.system;
    let ok = &sys.a * &kd.t == &kd.t * &s.a
        && sys.b == &kd.t * &s.b
        && s.c == &sys.c * &kd.t
        && kalman_pattern(s, kd.dims);
    rec.push(
        StepKind::KalmanForm,
        None,
        vec![
            ("At", Object::Matrix(s.a.clone())),
            ("Bt", Object::Matrix(s.b.clone())),
            ("Ct", Object::Matrix(s.c.clone())),
        ],
        Some(ok),
    );
    let min = kd.minimal_part();
    let order = min.nstates();
    let mcm = mcmillan_degree(sys);
    let ok = sys.same_markov(&min, n + order) && order == mcm;
    rec.push(
        StepKind::MinimalPart,
        None,
        vec![
            ("Am", Object::Matrix(min.a)),
            ("Bm", Object::Matrix(min.b)),
            ("Cm", Object::Matrix(min.c)),
            ("order", Object::Count(order)),
            ("mcmillan", Object::Count(mcm)),
        ],
        Some(ok),
    );
    Ok(rec.finish())
}

/// The zero blocks of the Kalman form with parts of sizes `dims` (in the order
/// $c\bar o, co, \bar c\bar o, \bar c o$): row part 2 only in column parts 2, 4; row part 3
/// only in 3, 4; row part 4 only in 4; $\tilde B$ zero in parts 3, 4; $\tilde C$ zero in 1, 3.
fn kalman_pattern<K: Field>(s: &StateSpace<K>, dims: [usize; 4]) -> bool {
    let k = s.field();
    let mut start = [0; 5];
    for i in 0..4 {
        start[i + 1] = start[i] + dims[i];
    }
    let part = |i: usize| (0..4).find(|&p| i < start[p + 1]).unwrap_or(3);
    let zero_a = |rp: usize, cp: usize| match rp {
        1 => cp == 0 || cp == 2,
        2 => cp < 2,
        3 => cp < 3,
        _ => false,
    };
    let n = s.nstates();
    let a_ok =
        (0..n).all(|i| (0..n).all(|j| !zero_a(part(i), part(j)) || k.is_zero(s.a.get(i, j))));
    let b_ok = (0..n).all(|i| part(i) < 2 || s.b.row(i).iter().all(|x| k.is_zero(x)));
    let c_ok =
        (0..n).all(|j| part(j) % 2 == 1 || (0..s.noutputs()).all(|i| k.is_zero(s.c.get(i, j))));
    a_ok && b_ok && c_ok
}

/// The states of `blocks` not in `keep`: (not excited: after the last excited state of their
/// block; not observed: before the first observed one). A state may be both.
fn dropped<K: Field>(
    blocks: &[usize],
    keep: &[usize],
    b: &Matrix<K>,
    c: &Matrix<K>,
) -> (Vec<usize>, Vec<usize>) {
    let k = b.field();
    let excited = |i: usize| b.row(i).iter().any(|x| !k.is_zero(x));
    let observed = |i: usize| (0..c.nrows()).any(|r| !k.is_zero(c.get(r, i)));
    let (mut not_exc, mut not_obs) = (vec![], vec![]);
    let mut start = 0;
    for &s in blocks {
        let idx: Vec<usize> = (start..start + s).collect();
        let hi = idx.iter().rposition(|&i| excited(i));
        let lo = idx.iter().position(|&i| observed(i));
        for (pos, &i) in idx.iter().enumerate() {
            if keep.contains(&i) {
                continue;
            }
            if hi.is_none_or(|h| pos > h) {
                not_exc.push(i);
            }
            if lo.is_none_or(|l| pos < l) {
                not_obs.push(i);
            }
        }
        start += s;
    }
    (not_exc, not_obs)
}

/// The Jordan-form minimal realization step by step (module docs); the last step's
/// realization is the command's (`minreal --method jordan`, [`SystemField::jordan_method`]).
///
/// # Errors
/// As [`super::minimal_jordan`].
pub fn jordan_method_steps(sys: &StateSpace<Q>) -> Result<Derivation<NumberField>> {
    let q = crate::jordan::primary::rational_field();
    let rec = Recorder::new(Method::JordanMethod, q);
    jordan_method_recorded(
        sys,
        rec,
        || Ok(crate::jordan::jordan(&sys.a)?.components),
        |s, _| Ok(<Q as SystemField>::jordan_method(s)?.1),
    )
}

/// The Jordan-form minimal realization over $\mathbb{Q}(p)$ step by step, on the components
/// [`super::minimal_jordan_qp`] realizes: an eigenvalue in $\mathbb{Q}(p)$ or a repeated
/// factor by its chains (over $E = \mathbb{Q}(p)\[t\]/(g)$ at the generic root $t$ for
/// $\deg g \ge 2$), a simple factor of degree $\ge 2$ by its restriction $(A_g, P B, C u)$
/// (no chains over $E$; [`super::jordan_method_stages`]); then the stages and the
/// command's realization ([`super::minimal_jordan_primary`] on the same components). Every
/// step lists the polynomials in the parameters it assumes nonzero (the first one those of
/// the factorization and of the eliminations: leading coefficients, discriminants,
/// resultants, pivots).
///
/// # Errors
/// As [`super::minimal_jordan_qp`].
pub fn jordan_method_steps_qp(
    sys_in: &StateSpace<RatFuncField>,
) -> Result<Derivation<Ext<RatFuncField>>> {
    let k = sys_in.field().fresh();
    let m = |x: &Matrix<RatFuncField>| {
        Matrix::from_vec(k.clone(), x.nrows(), x.ncols(), x.as_slice().to_vec())
    };
    let sys = StateSpace::new(m(&sys_in.a), m(&sys_in.b), m(&sys_in.c), m(&sys_in.d))?;
    let e0 = degree_one(&k);
    let log = lift_log(&e0, crate::jordan::derivation::ratfunc_log(&k));
    let rec = Recorder::with_log(Method::JordanMethod, e0, log);
    jordan_method_recorded(
        &sys,
        rec,
        || components_qp_minimal(&sys.a),
        |s, comps| Ok(minimal_jordan_primary(s, comps)?.system),
    )
}

/// The steps of the Jordan method over any field with [`Component`]s of $A$ (computed by
/// `components` after the recorder started, so that their conditions are recorded): per
/// component its chain steps or its restriction step, then the stages with the method's
/// realization `realize(sys, components)`.
fn jordan_method_recorded<F: Field + 'static>(
    sys: &StateSpace<F>,
    mut rec: Recorder<'_, Ext<F>>,
    components: impl FnOnce() -> Result<Vec<Component<F>>>,
    realize: impl FnOnce(&StateSpace<F>, Vec<Component<F>>) -> Result<StateSpace<F>>,
) -> Result<Derivation<Ext<F>>> {
    let comps = components()?;
    let mut parts = vec![];
    for (part, comp) in comps.iter().enumerate() {
        parts.push(if comp.has_chains() {
            component_steps(&mut rec, part, sys, comp)?
        } else {
            restriction_step(&mut rec, part, sys, comp)?
        });
    }
    let system = realize(sys, comps)?;
    stages_step(&mut rec, sys, &parts, &system)?;
    Ok(rec.finish())
}

/// The modal data, dropped modes and compaction of one component; returns its part over
/// $F$ at each stage (modal, kept, compacted).
fn component_steps<F: Field + 'static>(
    rec: &mut Recorder<'_, Ext<F>>,
    part: usize,
    sys: &StateSpace<F>,
    comp: &Component<F>,
) -> Result<StageParts<F>> {
    let k = comp.field.clone();
    let d = comp.degree();
    let theta = comp.root_elem();
    let bk = times_rational(&comp.left_chains, &sys.b);
    let ck = rational_times(&sys.c, &comp.chains);
    let j = comp.jordan_matrix();
    let m = j.nrows();
    let stage0 = over_base(comp, part, &j, &bk, &ck);
    rec.push(
        StepKind::ModalData,
        Some(part),
        vec![
            ("theta", Object::Scalar(theta.clone())),
            ("deg", Object::Count(d)),
            ("J", Object::Matrix(j.clone())),
            ("WB", Object::Matrix(bk.clone())),
            ("CV", Object::Matrix(ck.clone())),
        ],
        None,
    );
    let (keep, sizes) = drop_modes(&comp.blocks, &bk, &ck);
    let (not_exc, not_obs) = dropped(&comp.blocks, &keep, &bk, &ck);
    let jk = jordan_block_matrix(&k, &theta, &sizes);
    let (bkk, ckk) = (bk.select_rows(&keep), ck.select_cols(&keep));
    let full = StateSpace::new_strictly_proper(j, bk, ck)?;
    let kept = StateSpace::new_strictly_proper(jk.clone(), bkk.clone(), ckk.clone())?;
    let ok = full.same_markov(&kept, 2 * m + 1);
    let stage1 = (!keep.is_empty()).then(|| over_base(comp, part, &jk, &bkk, &ckk));
    rec.push(
        StepKind::DropModes,
        Some(part),
        vec![
            ("kept", Object::Counts(keep.clone())),
            ("not_excited", Object::Counts(not_exc)),
            ("not_observed", Object::Counts(not_obs)),
            ("deg", Object::Count(d)),
            ("Jk", Object::Matrix(jk)),
            ("Bk", Object::Matrix(bkk.clone())),
            ("Ck", Object::Matrix(ckk.clone())),
        ],
        Some(ok),
    );
    if keep.is_empty() {
        return Ok([Some(stage0), None, None]);
    }
    let nilp = jordan_block_matrix(&k, &k.zero(), &sizes);
    let min = minimal_kalman(&StateSpace::new_strictly_proper(nilp, bkk, ckk)?)?.system;
    let r = min.nstates();
    let (jn, bn, cn) = if r == 0 {
        let z = |a, b| Matrix::zeros(k.clone(), a, b);
        (z(0, 0), z(0, sys.ninputs()), z(sys.noutputs(), 0))
    } else {
        let ch = jordan_chains(&min.a, r)?;
        (
            jordan_block_matrix(&k, &theta, &ch.blocks),
            &ch.w * &min.b,
            &min.c * &ch.v,
        )
    };
    let compact = StateSpace::new_strictly_proper(jn.clone(), bn.clone(), cn.clone())?;
    let ok = kept.same_markov(&compact, 2 * m + 1);
    let stage2 = (r > 0).then(|| over_base(comp, part, &jn, &bn, &cn));
    // a real root: the first root's approximation (over QQ(p): an eigenvalue in QQ(p))
    let real = comp.roots.first().map_or(d == 1, |z| z.1 == 0.0);
    let norm_step = (r > 0 && r < keep.len() && real).then(|| (kept.clone(), compact.clone()));
    rec.push(
        StepKind::Compaction,
        Some(part),
        vec![
            ("J", Object::Matrix(jn)),
            ("B", Object::Matrix(bn)),
            ("C", Object::Matrix(cn)),
            ("order", Object::Count(r)),
            ("deg", Object::Count(d)),
        ],
        Some(ok),
    );
    if let Some((kept, compact)) = norm_step {
        norm_match(rec, part, &kept, &compact);
    }
    Ok([Some(stage0), stage1, stage2])
}

/// The minimal-realization paper's choice after eq. 36: the compacted block $(J, \tilde B,
/// \tilde C)$ scaled to $(J, a\tilde B, \tilde C/a)$ (Markov parameters unchanged) with $|a
/// \tilde B| = |B|$, $B$ the block's input matrix before compaction (Frobenius norms, a real
/// eigenvalue). $a^2 = |B|^2/|\tilde B|^2$; $a$ is applied when it is rational, else the
/// step keeps $a^2$ (closed form $a = \sqrt{a^2}$).
fn norm_match<K: Field>(
    rec: &mut Recorder<'_, K>,
    part: usize,
    kept: &StateSpace<K>,
    compact: &StateSpace<K>,
) {
    let k = kept.a.field().clone();
    let sq = |m: &Matrix<K>| crate::jordan::normalize::dot(&k, m.as_slice(), m.as_slice());
    let (nb, nbt) = (sq(&kept.b), sq(&compact.b));
    let Some(a2) = k.div(&nb, &nbt) else {
        return;
    };
    let a = k
        .to_rational(&a2)
        .and_then(|q| crate::jordan::normalize::rational_sqrt(&q))
        .map(|q| k.from_rational(&q));
    let (bt, ct) = match &a {
        Some(a) => (
            compact.b.scale(a),
            compact.c.scale(&k.inv(a).expect("a != 0")),
        ),
        None => (compact.b.clone(), compact.c.clone()),
    };
    let ok = match &a {
        Some(_) => {
            let scaled = StateSpace::new_strictly_proper(compact.a.clone(), bt.clone(), ct.clone());
            sq(&bt) == nb && scaled.is_ok_and(|s| s.same_markov(kept, 2 * kept.nstates() + 1))
        }
        None => k.mul(&a2, &nbt) == nb,
    };
    let mut objects = vec![
        ("nB", Object::Scalar(nb)),
        ("nBt", Object::Scalar(nbt)),
        ("a2", Object::Scalar(a2)),
    ];
    if let Some(a) = a {
        objects.push(("a", Object::Scalar(a)));
    }
    objects.push(("Bt", Object::Matrix(bt)));
    objects.push(("Ct", Object::Matrix(ct)));
    rec.push(StepKind::NormMatch, Some(part), objects, Some(ok));
}
