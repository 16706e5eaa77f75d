//! The condition sets of the commands over $\mathbb{Q}(p)$: each polynomial listed is one
//! where the result really changes or is undefined, with its [`Reason`] (issue 25 item 3).
//!
//! | command | the condition set is |
//! |---|---|
//! | every one | the denominators of the input's entries ([`Reason::InputDenominator`]): the model is undefined there |
//! | `tf` | input denominators; where the McMillan degree drops (the factors of the maximal minors of the Hankel matrix common to all, [`mcmillan`]); with `E`: where $\deg_s \det(sE - A)$ drops and where the pencil is singular. Nothing from the elimination's pivots: $G = C(sI - A)^{-1}B + D$ is an identity of rational functions wherever the input is defined |
//! | `minreal` (every method) | input denominators; where the McMillan degree drops (the order changes); the poles of the entries of the realization and of $T$ (it is undefined there) |
//! | `ctrb` / `obsv` | input denominators; where a Krylov rank $\operatorname{rank}[B, AB, \dots, A^{j-1}B]$ drops (gcd of its maximal minors): the indices or the controllable order change |
//! | `zeros` | input denominators; the poles of the monic zero polynomial's coefficients (a zero goes to infinity) |
//! | `scb` | as `zeros`, and the poles of the SCB matrices and of $\Gamma_1, \Gamma_2, \Gamma_3$, and where $\det \Gamma_i = 0$ (the basis as written is undefined or singular) |
//! | `linalg charpoly`, `det` | input denominators only (polynomial identities) |
//! | `linalg rank` | input denominators; the gcd of the maximal minors |
//!
//! Commands not in this table (`standard`, `pencil`, `minreal --descriptor`, `mnf`,
//! `analyze`, `linalg rref/inverse/nullspace/minpoly`, `jordan`) list the log of their
//! computation, each polynomial with the reason it was recorded for (a pivot, a proof minor,
//! a structure change of the Jordan form).

use crate::error::Result;
use crate::field::Field;
use crate::matrix::Matrix;
use crate::matrix::qp_conditions::{
    drop_factors, eval_at, expandable, independent_rows, random_point, test_factors,
};
use crate::mpoly::{MPoly, gcd};
use crate::ratfunc::{Part, RatFuncField, Reason, Structure};
use crate::system::{Descriptor, StateSpace};

/// A polynomial with its reason (before factoring).
pub(super) type Item = (MPoly, Reason);

type M = Matrix<RatFuncField>;

/// The denominators of `m`'s entries as [`Reason::InputDenominator`] (or, `result`,
/// [`Reason::PoleOfEntry`]) of `part`.
pub(super) fn denominators(part: Part, m: &M, result: bool) -> Vec<Item> {
    let mut out = vec![];
    for i in 0..m.nrows() {
        for j in 0..m.ncols() {
            let d = m.get(i, j).den();
            if !d.is_constant() {
                let why = if result {
                    Reason::PoleOfEntry {
                        part,
                        row: i,
                        col: j,
                    }
                } else {
                    Reason::InputDenominator {
                        part,
                        row: i,
                        col: j,
                    }
                };
                out.push((d.clone(), why));
            }
        }
    }
    out
}

/// The denominators of the input: `E, A, B, C, D` of the descriptor, else of `A..D`.
pub(super) fn input(
    ss: &StateSpace<RatFuncField>,
    desc: Option<&Descriptor<RatFuncField>>,
) -> Vec<Item> {
    let mats: Vec<(Part, &M)> = match desc {
        Some(d) => vec![
            (Part::E, &d.e),
            (Part::A, &d.a),
            (Part::B, &d.b),
            (Part::C, &d.c),
            (Part::D, &d.d),
        ],
        None => vec![
            (Part::A, &ss.a),
            (Part::B, &ss.b),
            (Part::C, &ss.c),
            (Part::D, &ss.d),
        ],
    };
    mats.into_iter()
        .flat_map(|(p, m)| denominators(p, m, false))
        .collect()
}

/// The poles of a result state space (`A, B, C, D`) and of `t`.
pub(super) fn result_poles(s: &StateSpace<RatFuncField>, t: Option<&M>) -> Vec<Item> {
    let mut out: Vec<Item> = [
        (Part::A, &s.a),
        (Part::B, &s.b),
        (Part::C, &s.c),
        (Part::D, &s.d),
    ]
    .into_iter()
    .flat_map(|(p, m)| denominators(p, m, true))
    .collect();
    if let Some(t) = t {
        out.extend(denominators(Part::T, t, true));
    }
    out
}

/// Where the McMillan degree (the order `r` of the minimal realization `min` of `input`)
/// drops: the candidates are the factors of one nonzero minor $\det O_I \det K_J$ of the
/// Hankel matrix $O_N K_N$ of `min` ($N$ = the input's order, so that its Markov parameters
/// are the input's), each tested by the rank of the input's Hankel matrix at points on its
/// zero set ([`drop_factors`]).
pub(super) fn mcmillan(
    min: &StateSpace<RatFuncField>,
    input: &StateSpace<RatFuncField>,
) -> Result<Vec<Item>> {
    let r = min.a.nrows();
    let n = input.a.nrows();
    if r == 0 {
        return Ok(vec![]);
    }
    let k = min.a.field().clone();
    let why = Reason::StructureChange(Structure::McMillanDegree { degree: r });
    if r == n {
        // already minimal: every maximal minor of the Hankel matrix is det O_I det K_J, so
        // the factors of the Krylov minors that proved the order (the log, factored once)
        // are complete candidates
        let fs = k.explained()?.into_iter().map(|c| c.poly).collect();
        let found = test_factors(&k, fs, r, false, &|p| hankel_rank(input, n, p));
        return Ok(found.all().into_iter().map(|f| (f, why)).collect());
    }
    let o = krylov(&min.a.transpose(), &min.c.transpose(), n)?.transpose();
    let kk = krylov(&min.a, &min.b, n)?;
    let mut rng = crate::rng::SplitMix64(0x25c0_4d19);
    let Some((rows, cols)) = (0..16).find_map(|_| {
        let p = random_point(k.nvars(), &mut rng);
        let (oq, kq) = (eval_at(&o, &p)?, eval_at(&kk, &p)?);
        let rows = independent_rows(&oq);
        let cols = independent_rows(&kq.transpose());
        (rows.len() == r && cols.len() == r).then_some((rows, cols))
    }) else {
        return Ok(vec![]);
    };
    let (os, ks) = (o.select_rows(&rows), kk.select_cols(&cols));
    let minor = k.mul(&os.det()?, &ks.det()?);
    let exact = o.nrows() == r && kk.ncols() == r;
    let found = drop_factors(&k, minor.num(), r, exact, &|p| hankel_rank(input, n, p))?;
    Ok(found.all().into_iter().map(|f| (f, why)).collect())
}

/// The rank of the Hankel matrix $O_N K_N$ of `s` at the point `p` (over $\mathbb{Q}$);
/// `None` where `s` is undefined.
fn hankel_rank(
    s: &StateSpace<RatFuncField>,
    n: usize,
    p: &[crate::field::Rational],
) -> Option<usize> {
    let (a, b, c) = (eval_at(&s.a, p)?, eval_at(&s.b, p)?, eval_at(&s.c, p)?);
    let o = krylov(&a.transpose(), &c.transpose(), n).ok()?.transpose();
    let kk = krylov(&a, &b, n).ok()?;
    Some(o.try_mul(&kk).ok()?.rank())
}

/// $[B, AB, \dots, A^{j-1} B]$.
fn krylov<F: Field>(a: &Matrix<F>, b: &Matrix<F>, j: usize) -> Result<Matrix<F>> {
    let mut out = b.clone();
    let mut cur = b.clone();
    for _ in 1..j {
        cur = a.try_mul(&cur)?;
        out = out.hstack(&cur)?;
    }
    Ok(out)
}

/// Where a Krylov rank of $(A, B)$ drops (`dual`: of $(A^T, C^T)$, observability): for
/// $j = 1, 2, \dots$ while the rank grows, the gcd of the maximal minors of
/// $[B, \dots, A^{j-1} B]$; the last one is the controllable (observable) order.
pub(super) fn krylov_drops(a: &M, b: &M, dual: bool) -> Result<Vec<Item>> {
    let n = a.nrows();
    // the largest minor the loop would expand first, its size checked before any work: the
    // full Krylov matrix at a random point gives its rows and columns (`Limit`: too large)
    let full = krylov(a, b, n.max(1))?;
    let mut rng = crate::rng::SplitMix64(0x25c0_4d1a);
    if let Some(q) = eval_at(&full, &random_point(a.field().nvars(), &mut rng)) {
        let rows = independent_rows(&q);
        let cols = independent_rows(&q.select_rows(&rows).transpose());
        expandable(&full.select_rows(&rows).select_cols(&cols))?;
    }
    let mut out = vec![];
    let (mut prev, mut cur, mut kry) = (0, b.clone(), b.clone());
    for j in 1..=n.max(1) {
        let r = kry.rank();
        if r == prev && j > 1 {
            break;
        }
        let why = Reason::StructureChange(Structure::Krylov {
            blocks: j,
            rank: r,
            dual,
        });
        out.extend(kry.rank_drop(r)?.all().into_iter().map(|f| (f, why)));
        prev = r;
        if r == n {
            break;
        }
        cur = a.try_mul(&cur)?;
        kry = kry.hstack(&cur)?;
    }
    // the last rank is the controllable (observable) order
    let dim = prev;
    for item in out.iter_mut() {
        if let Reason::StructureChange(Structure::Krylov { rank, .. }) = item.1
            && rank == dim
        {
            item.1 = Reason::StructureChange(if dual {
                Structure::Observable { dim }
            } else {
                Structure::Controllable { dim }
            });
        }
    }
    Ok(out)
}

/// Where a coefficient of the monic zero polynomial `z` has a pole (a zero escapes to
/// infinity).
pub(super) fn zero_escapes(z: &crate::poly::Poly<RatFuncField>) -> Vec<Item> {
    let degree = z.deg();
    z.coeffs()
        .iter()
        .filter(|c| !c.den().is_constant())
        .map(|c| {
            (
                c.den().clone(),
                Reason::StructureChange(Structure::ZeroEscapes { degree }),
            )
        })
        .collect()
}

/// With `E`: where $\deg_s \det(sE - A)$ drops (the numerator of its leading coefficient)
/// and where the pencil is singular (the gcd of the numerators of all coefficients);
/// $\det(sE - A)$ interpolated from its values at $s = 0, \dots, n$ (determinants over
/// $\mathbb{Q}(p)$, no conditions).
pub(super) fn pencil(d: &Descriptor<RatFuncField>) -> Result<Vec<Item>> {
    let k = d.a.field().clone();
    let n = d.a.nrows();
    let xs: Vec<i64> = (0..=n as i64).collect();
    let mut ys = vec![];
    for &x in &xs {
        let m = d.e.scale(&k.from_i64(x)).try_sub(&d.a)?;
        ys.push(m.det()?);
    }
    let cs = newton(&k, &xs, ys);
    let Some(top) = cs.iter().rposition(|c| !k.is_zero(c)) else {
        return Ok(vec![]);
    };
    let mut out = vec![(
        cs[top].num().clone(),
        Reason::StructureChange(Structure::FiniteEigenvalues { degree: top }),
    )];
    let g = cs[..=top]
        .iter()
        .filter(|c| !k.is_zero(c))
        .fold(MPoly::zero(k.nvars()), |g, c| gcd(&g, c.num()));
    out.push((g, Reason::StructureChange(Structure::SingularPencil)));
    Ok(out)
}

/// The coefficients (low first) of the polynomial through `(xs[i], ys[i])` (Newton form,
/// expanded).
fn newton(
    k: &RatFuncField,
    xs: &[i64],
    mut ys: Vec<crate::ratfunc::RatFunc>,
) -> Vec<crate::ratfunc::RatFunc> {
    let n = xs.len();
    for j in 1..n {
        for i in (j..n).rev() {
            let diff = k.sub(&ys[i], &ys[i - 1]);
            let h = k.from_i64(xs[i] - xs[i - j]);
            ys[i] = k.div_unrecorded(&diff, &h).expect("distinct nodes");
        }
    }
    // expand sum ys[j] prod_{i<j} (s - xs[i]) by Horner from the top
    let mut cs = vec![k.zero(); n];
    for j in (0..n).rev() {
        // cs <- cs * (s - xs[j]) + ys[j]
        let mut next = vec![k.zero(); n];
        for (t, c) in cs.iter().enumerate() {
            if t + 1 < n {
                next[t + 1] = k.add(&next[t + 1], c);
            }
            next[t] = k.sub(&next[t], &k.mul(c, &k.from_i64(xs[j])));
        }
        next[0] = k.add(&next[0], &ys[j]);
        cs = next;
    }
    cs
}

/// The first column of the Routh array of `g` (leading coefficient made positive by
/// dividing by it): every root of `g` lies in the open left half plane exactly when every
/// entry is positive (stopping at an entry that is identically zero: the test degenerates,
/// the entries so far are returned).
pub(super) fn routh_first_column(
    g: &crate::poly::Poly<RatFuncField>,
) -> Vec<crate::ratfunc::RatFunc> {
    let k = g.field().clone();
    let n = g.deg();
    let lc = g.coeff(n);
    let c = |i: usize| k.div_unrecorded(&g.coeff(i), &lc).expect("nonzero lc");
    let mut r0: Vec<_> = (0..=n).rev().step_by(2).map(c).collect();
    let mut r1: Vec<_> = (0..n).rev().step_by(2).map(c).collect();
    let mut out = vec![];
    while let Some(h) = r1.first().cloned() {
        if k.is_zero(&h) {
            break;
        }
        out.push(h.clone());
        let r2: Vec<_> = (0..r0.len().saturating_sub(1))
            .map(|j| {
                let a = k.mul(&h, &r0[j + 1]);
                let b = k.mul(&r0[0], r1.get(j + 1).unwrap_or(&k.zero()));
                k.div_unrecorded(&k.sub(&a, &b), &h).expect("h nonzero")
            })
            .collect();
        r0 = std::mem::replace(&mut r1, r2);
    }
    out
}
