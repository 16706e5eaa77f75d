//! `contributions --steps` and `response --steps` over any field with a Jordan form
//! ($\mathbb{Q}$, $\mathbb{Q}(\sqrt d)$, $\mathbb{Q}(i)$, $\mathbb{Q}(p)$; issue 27): the
//! derivations of [`super::contribution`] and of the free response
//! ([`crate::jordan::StateResponse`]), recorded as a [`Derivation`].
//!
//! **Contributions**, per irreducible factor $p$ of $\chi_A$ (a mode): the spectral projector
//! $P_p = V_p R_p$ ($R_p V_p = I$, $A V_p = V_p A_p$, $P_p^2 = P_p$) and the part $(A_p, B_p,
//! C_p)$; the residues $H_k = C G_{\theta,k} B$ at the generic root $\theta$ ($\sum$ over the
//! conjugates of $H_0$ $= C_p B_p$); the weight $\|G_p\|_2^2 = \operatorname{tr}(C_p W C_p^T)$
//! with the Lyapunov identity $A_p W + W A_p^H + B_p B_p^H = 0$ substituted back (or zero /
//! infinite; over $\mathbb{Q}(p)$ the rational function, the norm where the part is stable:
//! [`super::contribution`]); then $\sum_p P_p = I$ and $\sum_p C_p A_p^k B_p = C A^k B$ ($k < 2n$) with the
//! ranking; with `--keep K` the truncated system and its error ($C B = C_K B_K + E_0$, the DC
//! gains adding up, the error's Lyapunov identity).
//!
//! **Free response** from $x_0$: per factor the vectors $g_k = G_{\theta,k} x_0$ of
//! $x(t) = \sum_\theta \sum_k t^k e^{\theta t} g_k$ with $A g_k = \theta g_k + (k+1) g_{k+1}$
//! (so $\dot x = A x$ term by term), then $x(0) = \sum_p \operatorname{Tr} g_{p,0} = x_0$.

use super::contribution::{Contributions, ModeContribution, Weight, adjoint, contributions_in};
use crate::algebraic::Ext;
use crate::error::Result;
use crate::field::{Field, Q};
use crate::jordan::JordanForm;
use crate::jordan::derivation::{Derivation, Method, Object, Recorder, StepKind};
use crate::jordan::primary::Component;
use crate::jordan::response::trace_down;
use crate::matrix::Matrix;
use crate::poly::Poly;
use crate::system::StateSpace;

/// $F$ as an extension of degree 1 of itself (the derivation's field; the residues and
/// free-response vectors of a factor of degree $\ge 2$ live in its own $F\[t\]/(p)$).
fn base_field<F: Field>(k: &F) -> Ext<F> {
    Ext::with_var(&Poly::x(k.clone()), (0.0, 0.0), "t")
}

fn lift<F: Field>(q: &Ext<F>, m: &Matrix<F>) -> Matrix<Ext<F>> {
    m.map(q, |x| q.from_base(x))
}

/// The columns side by side (an empty `rows x 0` matrix for none).
fn side_by_side<K: Field>(k: &K, rows: usize, ms: &[Matrix<K>]) -> Matrix<K> {
    ms.iter().fold(Matrix::zeros(k.clone(), rows, 0), |acc, m| {
        acc.hstack(m).unwrap_or(acc)
    })
}

/// `contributions --steps` over $\mathbb{Q}$ ([`contributions_steps_in`] with the Jordan
/// form of `ss.a`).
///
/// # Errors
/// As [`crate::jordan::jordan`] and [`contributions_steps_in`].
pub fn contributions_steps(ss: &StateSpace<Q>, keep: Option<usize>) -> Result<Derivation<Ext<Q>>> {
    contributions_steps_in(ss, crate::jordan::jordan(&ss.a)?, keep)
}

/// `contributions --steps` over $\mathbb{Q}(p)$: the system carried into the field of its
/// Jordan form ([`crate::jordan::jordan_qp`]), so that one condition log holds every
/// division; the derivation's last step lists those conditions as its assumptions.
///
/// # Errors
/// As [`crate::jordan::jordan_qp`] and [`contributions_steps_in`].
pub fn contributions_steps_qp(
    ss: &StateSpace<crate::ratfunc::RatFuncField>,
    keep: Option<usize>,
) -> Result<Derivation<Ext<crate::ratfunc::RatFuncField>>> {
    let jf = crate::jordan::jordan_qp(&ss.a)?;
    let k = jf.base().clone();
    let ss = super::contribution::in_field(ss, &k)?;
    let mut d = contributions_steps_in(&ss, jf, keep)?;
    assume_conditions(&mut d, &k)?;
    Ok(d)
}

/// `response --steps` over $\mathbb{Q}(p)$ from `x0` (entries in the field of `a`).
///
/// # Errors
/// As [`crate::jordan::jordan_qp`].
pub fn response_steps_qp(
    a: &Matrix<crate::ratfunc::RatFuncField>,
    x0: &Matrix<crate::ratfunc::RatFuncField>,
) -> Result<Derivation<Ext<crate::ratfunc::RatFuncField>>> {
    let jf = crate::jordan::jordan_qp(a)?;
    let k = jf.base().clone();
    let x0 = Matrix::from_vec(k.clone(), x0.nrows(), x0.ncols(), x0.as_slice().to_vec());
    let mut d = response_steps_in(&jf, &x0);
    assume_conditions(&mut d, &k)?;
    Ok(d)
}

/// The conditions of the field's log (every pivot and division of the derivation) as the
/// assumptions of its last step.
fn assume_conditions(
    d: &mut Derivation<Ext<crate::ratfunc::RatFuncField>>,
    k: &crate::ratfunc::RatFuncField,
) -> Result<()> {
    let conds = k.conditions()?;
    let e = d.field.clone();
    if let Some(last) = d.steps.last_mut() {
        last.assumes = conds
            .into_iter()
            .map(|p| e.from_base(&k.from_mpoly(p)))
            .collect();
    }
    Ok(())
}

/// `contributions --steps` (module docs) over $F$ from the Jordan form `jf` of `ss.a`; `keep`
/// as `--keep`.
///
/// # Errors
/// As [`contributions_in`] and [`Contributions::truncate`].
pub fn contributions_steps_in<F: Field + 'static>(
    ss: &StateSpace<F>,
    jf: JordanForm<F>,
    keep: Option<usize>,
) -> Result<Derivation<Ext<F>>> {
    let c = contributions_in(ss, jf)?;
    let k = ss.field().clone();
    let q = base_field(&k);
    let mut rec = Recorder::new(Method::Contributions, q.clone());
    let n = ss.nstates();
    let mut sum_p = Matrix::zeros(k.clone(), n, n);
    let mut order = vec![];
    for mode in &c.modes {
        let comp = &c.jordan.components[mode.component];
        order.push(mode.component);
        let part = Some(mode.component);
        let (v, r, p) = (&mode.basis, &mode.rows, &mode.part);
        let proj = v * r;
        sum_p = &sum_p + &proj;
        let ok = (r * v).is_identity()
            && &ss.a * v == v * &p.a
            && &proj * &proj == proj
            && p.b == r * &ss.b
            && p.c == &ss.c * v;
        rec.push(
            StepKind::SpectralProjector,
            part,
            vec![
                ("f", Object::Poly(comp.factor.map(&q, |x| q.from_base(x)))),
                ("P", Object::Matrix(lift(&q, &proj))),
                ("V", Object::Matrix(lift(&q, v))),
                ("R", Object::Matrix(lift(&q, r))),
                ("Ap", Object::Matrix(lift(&q, &p.a))),
                ("Bp", Object::Matrix(lift(&q, &p.b))),
                ("Cp", Object::Matrix(lift(&q, &p.c))),
            ],
            Some(ok),
        );
        residue_step(&mut rec, comp, mode, &p.c, &p.b);
        weight_step(&mut rec, &q, mode)?;
    }
    let kmax = 2 * n.max(1);
    let mut markov_sum: Vec<Matrix<F>> = (0..kmax)
        .map(|_| Matrix::zeros(k.clone(), ss.noutputs(), ss.ninputs()))
        .collect();
    for m in &c.modes {
        for (acc, h) in markov_sum.iter_mut().zip(m.part.markov(kmax)) {
            *acc = &*acc + &h;
        }
    }
    let ok = sum_p.is_identity() && markov_sum == ss.markov(kmax) && c.verified;
    rec.push(
        StepKind::ModeRanking,
        None,
        if c.ranked {
            vec![("n", Object::Count(n)), ("ranked", Object::Counts(order))]
        } else {
            vec![
                ("n", Object::Count(n)),
                ("ranked", Object::Counts(order)),
                ("unranked", Object::Count(1)),
            ]
        },
        Some(ok),
    );
    if let Some(kk) = keep {
        truncation_step(&mut rec, &q, ss, &c, kk)?;
    }
    Ok(rec.finish())
}

/// The residues of one mode at its generic root, checked against $C_p B_p$.
fn residue_step<F: Field>(
    rec: &mut Recorder<'_, Ext<F>>,
    comp: &Component<F>,
    mode: &ModeContribution<F>,
    cp: &Matrix<F>,
    bp: &Matrix<F>,
) {
    let e = comp.field.clone();
    let rows = mode.residues.first().map_or(0, |h| h.nrows());
    let h = side_by_side(&e, rows, &mode.residues);
    let ok = mode
        .residues
        .first()
        .is_some_and(|h0| trace_down(h0, &comp.factor, cp.field()) == cp * bp);
    rec.push(
        StepKind::ModeResidues,
        Some(mode.component),
        vec![
            ("theta", Object::Scalar(comp.root_elem())),
            ("H", Object::Matrix(h)),
            ("deg", Object::Count(comp.degree())),
        ],
        Some(ok),
    );
}

/// The weight of one mode with its Lyapunov identity.
fn weight_step<F: Field>(
    rec: &mut Recorder<'_, Ext<F>>,
    q: &Ext<F>,
    mode: &ModeContribution<F>,
) -> Result<()> {
    let p = &mode.part;
    let k = p.field();
    let (objects, holds) = match &mode.weight {
        Weight::Zero => {
            let zero = p.markov(p.nstates().max(1)).iter().all(|m| m.is_zero());
            (vec![("zero", Object::Count(1))], Some(zero))
        }
        Weight::Infinite => (vec![("infinite", Object::Count(1))], None),
        Weight::H2Squared(h) | Weight::H2SquaredWhereStable(h) => {
            let bbh = &p.b * &adjoint(&p.b);
            let w = super::contribution::lyapunov_h(&p.a, &bbh)?;
            let ok = (&(&(&p.a * &w) + &(&w * &adjoint(&p.a))) + &bbh).is_zero();
            let cwc = &(&p.c * &w) * &adjoint(&p.c);
            let tr = (0..cwc.nrows()).fold(k.zero(), |acc, i| k.add(&acc, cwc.get(i, i)));
            let mut objects = vec![
                ("W", Object::Matrix(lift(q, &w))),
                ("h2", Object::Scalar(q.from_base(h))),
            ];
            if matches!(mode.weight, Weight::H2SquaredWhereStable(_)) {
                objects.push(("where_stable", Object::Count(1)));
            }
            (objects, Some(ok && tr == *h))
        }
    };
    rec.push(StepKind::ModeWeight, Some(mode.component), objects, holds);
    Ok(())
}

/// The truncation to the `keep` heaviest modes and its error.
fn truncation_step<F: Field>(
    rec: &mut Recorder<'_, Ext<F>>,
    q: &Ext<F>,
    ss: &StateSpace<F>,
    c: &Contributions<F>,
    keep: usize,
) -> Result<()> {
    let t = c.truncate(keep)?;
    let s = &t.system;
    // C B = C_K B_K + E_0; the DC gains add up when A is invertible
    let mut ok = t.verified && &ss.c * &ss.b == &(&s.c * &s.b) + &t.error_markov0;
    if let (Ok(ai), Ok(ki), Some(dc)) = (ss.a.inverse(), s.a.inverse(), &t.error_dc) {
        let g0 = -&(&(&ss.c * &ai) * &ss.b);
        let k0 = -&(&(&s.c * &ki) * &s.b);
        ok &= g0 == &k0 + dc;
    }
    let kept: Vec<usize> = t.kept.iter().map(|&i| c.modes[i].component).collect();
    let mut objects = vec![
        ("kept_modes", Object::Counts(kept)),
        ("Ak", Object::Matrix(lift(q, &s.a))),
        ("Bk", Object::Matrix(lift(q, &s.b))),
        ("Ck", Object::Matrix(lift(q, &s.c))),
        ("M0", Object::Matrix(lift(q, &t.error_markov0))),
    ];
    if let Some(dc) = &t.error_dc {
        objects.push(("dc", Object::Matrix(lift(q, dc))));
    }
    if let Some(h) = &t.error_h2_squared {
        objects.push(("h2", Object::Scalar(q.from_base(h))));
    }
    rec.push(StepKind::TruncationError, None, objects, Some(ok));
    Ok(())
}

/// `response --steps` over $\mathbb{Q}$ ([`response_steps_in`] with the Jordan form of `a`).
///
/// # Errors
/// As [`crate::jordan::jordan`].
pub fn response_steps(a: &Matrix<Q>, x0: &Matrix<Q>) -> Result<Derivation<Ext<Q>>> {
    Ok(response_steps_in(&crate::jordan::jordan(a)?, x0))
}

/// `response --steps` from the exact initial state `x0` ($n \times 1$ over $F$) with the
/// Jordan form `jf` of $A$ (module docs).
pub fn response_steps_in<F: Field + 'static>(
    jf: &JordanForm<F>,
    x0: &Matrix<F>,
) -> Derivation<Ext<F>> {
    let a = &jf.a;
    let k = a.field().clone();
    let sr = jf.free_response().from_state(x0);
    let q = base_field(&k);
    let mut rec = Recorder::new(Method::FreeResponse, q.clone());
    let n = a.nrows();
    let mut sum0 = Matrix::zeros(k.clone(), n, 1);
    for (ci, comp) in jf.components.iter().enumerate() {
        let e: Ext<F> = comp.field.clone();
        let mut gs: Vec<(usize, &Matrix<Ext<F>>)> = sr
            .terms
            .iter()
            .filter(|(c, _, _)| *c == ci)
            .map(|(_, k, g)| (*k, g))
            .collect();
        gs.sort_by_key(|(k, _)| *k);
        let theta = comp.root_elem();
        let ae = comp.lift(a);
        let zero = Matrix::zeros(e.clone(), n, 1);
        let ok = !gs.is_empty()
            && gs.iter().enumerate().all(|(i, (kk, g))| {
                let next = gs
                    .get(i + 1)
                    .filter(|(k1, _)| *k1 == kk + 1)
                    .map_or(zero.clone(), |(_, h)| h.scale(&e.from_i64(*kk as i64 + 1)));
                &ae * *g == &g.scale(&theta) + &next
            });
        if let Some((0, g0)) = gs.first() {
            sum0 = &sum0 + &trace_down(g0, &comp.factor, &k);
        }
        let cols: Vec<Matrix<Ext<F>>> = gs.iter().map(|(_, g)| (*g).clone()).collect();
        rec.push(
            StepKind::FreeTerms,
            Some(ci),
            vec![
                ("theta", Object::Scalar(theta)),
                ("g", Object::Matrix(side_by_side(&e, n, &cols))),
                ("deg", Object::Count(comp.degree())),
            ],
            Some(ok),
        );
    }
    rec.push(
        StepKind::InitialState,
        None,
        vec![("x0", Object::Matrix(lift(&q, x0)))],
        Some(sum0 == *x0 && jf.verified),
    );
    rec.finish()
}
