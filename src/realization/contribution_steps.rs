//! `contributions --steps` and `response --steps` over $\mathbb{Q}$ (issue 27): the
//! derivations of [`super::contribution`] and of the free response
//! ([`crate::jordan::StateResponse`]), recorded as a [`Derivation`].
//!
//! **Contributions**, per irreducible factor $p$ of $\chi_A$ (a mode): the spectral projector
//! $P_p = V_p R_p$ ($R_p V_p = I$, $A V_p = V_p A_p$, $P_p^2 = P_p$) and the part $(A_p, B_p,
//! C_p)$; the residues $H_k = C G_{\theta,k} B$ at the generic root $\theta$ ($\sum$ over the
//! conjugates of $H_0$ $= C_p B_p$); the weight $\|G_p\|_2^2 = \operatorname{tr}(C_p W C_p^T)$
//! with the Lyapunov identity $A_p W + W A_p^T + B_p B_p^T = 0$ substituted back (or zero /
//! infinite); then $\sum_p P_p = I$ and $\sum_p C_p A_p^k B_p = C A^k B$ ($k < 2n$) with the
//! ranking; with `--keep K` the truncated system and its error ($C B = C_K B_K + E_0$, the DC
//! gains adding up, the error's Lyapunov identity).
//!
//! **Free response** from $x_0$: per factor the vectors $g_k = G_{\theta,k} x_0$ of
//! $x(t) = \sum_\theta \sum_k t^k e^{\theta t} g_k$ with $A g_k = \theta g_k + (k+1) g_{k+1}$
//! (so $\dot x = A x$ term by term), then $x(0) = \sum_p \operatorname{Tr} g_{p,0} = x_0$.

use super::contribution::{Contributions, Weight, contributions};
use crate::algebraic::{Ext, NumberField};
use crate::error::Result;
use crate::field::{Field, Q, Rational};
use crate::jordan::derivation::{Derivation, Method, Object, Recorder, StepKind};
use crate::jordan::primary::{Component, rational_field};
use crate::matrix::Matrix;
use crate::poly::{Poly, newton_power_sums};
use crate::system::StateSpace;
use num_traits::Zero;

/// $\operatorname{Tr}_{E/\mathbb{Q}}$ of each entry ($E = \mathbb{Q}\[t\]/(p)$).
fn trace_q(m: &Matrix<NumberField>, p: &Poly<Q>) -> Matrix<Q> {
    let ps = newton_power_sums(p, p.deg().saturating_sub(1));
    m.map(&Q, |x| {
        x.0.iter()
            .zip(&ps)
            .fold(Rational::zero(), |acc, (a, b)| acc + a * b)
    })
}

fn lift(q: &NumberField, m: &Matrix<Q>) -> Matrix<NumberField> {
    m.map(q, |x| q.from_rational(x))
}

/// The columns side by side (an empty `rows x 0` matrix for none).
fn side_by_side<K: Field>(k: &K, rows: usize, ms: &[Matrix<K>]) -> Matrix<K> {
    ms.iter().fold(Matrix::zeros(k.clone(), rows, 0), |acc, m| {
        acc.hstack(m).unwrap_or(acc)
    })
}

/// `contributions --steps` (module docs); `keep` as `--keep`.
///
/// # Errors
/// As [`contributions`] and [`Contributions::truncate`].
pub fn contributions_steps(
    ss: &StateSpace<Q>,
    keep: Option<usize>,
) -> Result<Derivation<NumberField>> {
    let c = contributions(ss)?;
    let q = rational_field();
    let mut rec = Recorder::new(Method::Contributions, q.clone());
    let n = ss.nstates();
    let mut sum_p = Matrix::zeros(Q, n, n);
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
                (
                    "f",
                    Object::Poly(comp.factor.map(&q, |x| q.from_rational(x))),
                ),
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
    let mut markov_sum: Vec<Matrix<Q>> = (0..kmax)
        .map(|_| Matrix::zeros(Q, ss.noutputs(), ss.ninputs()))
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
        vec![("n", Object::Count(n)), ("ranked", Object::Counts(order))],
        Some(ok),
    );
    if let Some(k) = keep {
        truncation_step(&mut rec, &q, ss, &c, k)?;
    }
    Ok(rec.finish())
}

/// The residues of one mode at its generic root, checked against $C_p B_p$.
fn residue_step(
    rec: &mut Recorder<'_, NumberField>,
    comp: &Component<Q>,
    mode: &super::contribution::ModeContribution,
    cp: &Matrix<Q>,
    bp: &Matrix<Q>,
) {
    let e = comp.field.clone();
    let rows = mode.residues.first().map_or(0, |h| h.nrows());
    let h = side_by_side(&e, rows, &mode.residues);
    let ok = mode
        .residues
        .first()
        .is_some_and(|h0| trace_q(h0, &comp.factor) == cp * bp);
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
fn weight_step(
    rec: &mut Recorder<'_, NumberField>,
    q: &NumberField,
    mode: &super::contribution::ModeContribution,
) -> Result<()> {
    let p = &mode.part;
    let (objects, holds) = match &mode.weight {
        Weight::Zero => {
            let zero = p.markov(p.nstates().max(1)).iter().all(|m| m.is_zero());
            (vec![("zero", Object::Count(1))], Some(zero))
        }
        Weight::Infinite => (vec![("infinite", Object::Count(1))], None),
        Weight::H2Squared(h) => {
            let bbt = &p.b * &p.b.transpose();
            let w = super::gramian::lyapunov(&p.a, &bbt)?;
            let ok = (&(&(&p.a * &w) + &(&w * &p.a.transpose())) + &bbt).is_zero();
            let cwc = &(&p.c * &w) * &p.c.transpose();
            let tr = (0..cwc.nrows()).fold(Rational::zero(), |acc, i| acc + cwc.get(i, i));
            (
                vec![
                    ("W", Object::Matrix(lift(q, &w))),
                    ("h2", Object::Scalar(q.from_rational(h))),
                ],
                Some(ok && tr == *h),
            )
        }
    };
    rec.push(StepKind::ModeWeight, Some(mode.component), objects, holds);
    Ok(())
}

/// The truncation to the `keep` heaviest modes and its error.
fn truncation_step(
    rec: &mut Recorder<'_, NumberField>,
    q: &NumberField,
    ss: &StateSpace<Q>,
    c: &Contributions,
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
        objects.push(("h2", Object::Scalar(q.from_rational(h))));
    }
    rec.push(StepKind::TruncationError, None, objects, Some(ok));
    Ok(())
}

/// `response --steps` from the exact initial state `x0` ($n \times 1$) (module docs).
///
/// # Errors
/// As [`crate::jordan::jordan`].
pub fn response_steps(a: &Matrix<Q>, x0: &Matrix<Q>) -> Result<Derivation<NumberField>> {
    let jf = crate::jordan::jordan(a)?;
    let sr = jf.free_response().from_state(x0);
    let q = rational_field();
    let mut rec = Recorder::new(Method::FreeResponse, q.clone());
    let n = a.nrows();
    let mut sum0 = Matrix::zeros(Q, n, 1);
    for (ci, comp) in jf.components.iter().enumerate() {
        let e: Ext<Q> = comp.field.clone();
        let mut gs: Vec<(usize, &Matrix<NumberField>)> = sr
            .terms
            .iter()
            .filter(|(c, _, _)| *c == ci)
            .map(|(_, k, g)| (*k, g))
            .collect();
        gs.sort_by_key(|(k, _)| *k);
        let theta = comp.root_elem();
        let ae = comp.lift(a);
        let zero = Matrix::zeros(e.clone(), n, 1);
        let ok = gs.iter().enumerate().all(|(i, (k, g))| {
            let next = gs
                .get(i + 1)
                .filter(|(k1, _)| *k1 == k + 1)
                .map_or(zero.clone(), |(_, h)| h.scale(&e.from_i64(*k as i64 + 1)));
            &ae * *g == &g.scale(&theta) + &next
        });
        if let Some((0, g0)) = gs.first() {
            sum0 = &sum0 + &trace_q(g0, &comp.factor);
        }
        let cols: Vec<Matrix<NumberField>> = gs.iter().map(|(_, g)| (*g).clone()).collect();
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
    Ok(rec.finish())
}
