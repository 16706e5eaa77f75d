//! Equilibrium preload and the stiffness it adds (EoM's `preload`, `point_hessian`,
//! `line_stretch_hessian` and `force`).
//!
//! The applied loads $f$ (weights) are carried by the rigid constraints and the flexible
//! items: $[0, J; J^T, K] [\lambda; x] = [0; -f]$ (any solution: the forces $\lambda$ and
//! $k H x$ the items carry are unique when the constraints are independent, and so is the
//! stiffness built from them). An item carrying a force $F$ at radius $r$ then adds the
//! tangent stiffness of the rotated force ($[F]_\times$, $[r]_\times [F]_\times$ terms);
//! a rolling contact moves its reaction with the rolling; a revolute (2 moments) or a
//! constant-velocity joint (1 moment) turns its reaction moment; a preloaded spring or link
//! of length $L$ adds the string stiffness $T^T T \lambda / L$. A load $F$ at radius $r$
//! adds $-[F]_\times$ and $-[r]_\times [F]_\times - [M]_\times$.

use super::geometry::{
    Vec3, add_block, along, carried, carried_rows, dot3, skew, sparse_mul, sub3,
};
use super::{LineKind, Model, PointKind};
use crate::error::{Error, Result};
use crate::field::Field;
use crate::matrix::Matrix;

/// The applied load vector `f` (`6 n`).
fn load_vector<K: Field>(m: &Model<K>) -> Vec<K::Elem> {
    let k = &m.field;
    let mut f = vec![k.zero(); 6 * m.bodies.len()];
    for l in &m.loads {
        let r = sub3(k, &l.location, &m.origin(l.body));
        let rxf = skew(k, &r).try_mul(&Matrix::column(k.clone(), l.force.to_vec()));
        let rxf = rxf.expect("3x3 by 3x1");
        for j in 0..3 {
            let i = 6 * l.body;
            f[i + j] = k.add(&f[i + j], &l.force[j]);
            let mm = k.add(&l.moment[j], rxf.get(j, 0));
            f[i + 3 + j] = k.add(&f[i + 3 + j], &mm);
        }
    }
    f
}

/// $K_l$: the stiffness of the applied loads (fixed in the ground frame).
pub(super) fn load_stiffness<K: Field>(m: &Model<K>) -> Matrix<K> {
    let k = &m.field;
    let d = 6 * m.bodies.len();
    let mut out = Matrix::zeros(k.clone(), d, d);
    for l in &m.loads {
        let r = sub3(k, &l.location, &m.origin(l.body));
        let sf = skew(k, &l.force);
        let b = 6 * l.body;
        add_block(&mut out, b, b + 3, &sf, true);
        let rf = &(&skew(k, &r) * &sf) + &skew(k, &l.moment);
        add_block(&mut out, b + 3, b + 3, &rf, true);
    }
    out
}

/// The static equilibrium under the applied loads $f$: displacements $x = N y$ in the null
/// space $N$ of the rigid constraints with $N^T K N y = -N^T f$, then the constraint forces
/// from $J^T \lambda = -f - K x$ (consistent: its right side is orthogonal to $N$). This
/// is the KKT system $[0, J; J^T, K][\lambda; x] = [0; -f]$ solved in two small pieces
/// ($N$ has as many columns as the model has free coordinates). Returns $\lambda$ and $x$.
fn equilibrium<K: Field>(
    m: &Model<K>,
    rigid: &Matrix<K>,
    null_j: &Matrix<K>,
    stiffness: &Matrix<K>,
) -> Result<(Vec<K::Elem>, Matrix<K>)> {
    let k = &m.field;
    let none = || {
        Error::Invalid("the loads cannot be carried: the model has no static equilibrium".into())
    };
    let f = Matrix::column(k.clone(), load_vector(m));
    let nt = null_j.transpose();
    let red = sparse_mul(&nt, &sparse_mul(stiffness, null_j));
    let (y, _) = red.solve(&-&sparse_mul(&nt, &f))?.ok_or_else(none)?;
    let x = sparse_mul(null_j, &y);
    if rigid.nrows() == 0 {
        return Ok((vec![], x));
    }
    let g = -&(&f + &sparse_mul(stiffness, &x));
    let (lam, _) = rigid.transpose().solve(&g)?.ok_or_else(none)?;
    Ok(((0..lam.nrows()).map(|i| lam.get(i, 0).clone()).collect(), x))
}

/// $K_t$: tangent stiffness of the preloaded connections (`null_j`: the null space of the
/// rigid constraint Jacobian `rigid`).
pub(super) fn tangent_stiffness<K: Field>(
    m: &Model<K>,
    rigid: &Matrix<K>,
    null_j: &Matrix<K>,
    h: &Matrix<K>,
    kd: &[K::Elem],
    stiffness: &Matrix<K>,
) -> Result<Matrix<K>> {
    let k = &m.field;
    let d = 6 * m.bodies.len();
    let (lam, x) = equilibrium(m, rigid, null_j, stiffness)?;
    let hx = sparse_mul(h, &x);
    let lam_f: Vec<K::Elem> = (0..h.nrows())
        .map(|i| k.mul(&kd[i], hx.get(i, 0)))
        .collect();
    let mut out = Matrix::zeros(k.clone(), d, d);
    let (mut ir, mut iff) = (0, 0);
    // EoM's order: links, springs, flexible points, rigid points (the sum does not care)
    for p in &m.points {
        let (src, at, full) = match p.kind {
            PointKind::Rigid => (&lam, &mut ir, false),
            PointKind::Flexible => (&lam_f, &mut iff, true),
            PointKind::Nonholonomic => continue,
        };
        let (frc, mmt, used) = carried_load(m, p, &src[*at..], full)?;
        *at += used;
        point_hessian(m, p, &frc, &mmt, &mut out)?;
    }
    for l in &m.lines {
        let (src, at) = match l.kind {
            LineKind::Link => (&lam, &mut ir),
            LineKind::Spring { .. } => (&lam_f, &mut iff),
            _ => continue,
        };
        let t = src[*at].clone();
        *at += 1;
        line_hessian(m, l, &t, &mut out);
    }
    Ok(out)
}

/// The projections `(Pf, Pm)` of a point item's forces and moments: the full ones
/// ([`carried`], a flexible item) or their independent rows ([`carried_rows`], a
/// constraint).
///
/// # Errors
/// `Invalid` when a projection needs the item's axis and it is missing or zero.
pub(super) fn projections<K: Field>(
    k: &K,
    p: &super::PointItem<K>,
    full: bool,
) -> Result<(Matrix<K>, Matrix<K>)> {
    let proj = |n: u8| {
        let r = if full {
            carried(k, n, &p.axis)
        } else {
            carried_rows(k, n, &p.axis)
        };
        r.ok_or_else(|| {
            Error::Invalid(format!(
                "{}: an axis is needed (and must be non-zero)",
                p.name
            ))
        })
    };
    Ok((proj(p.forces)?, proj(p.moments)?))
}

/// The force and moment a point item carries from its multipliers `lam` (the 6 of a
/// flexible item's projections, `full`, or one per independent row of a constraint):
/// $P^T \lambda$; and how many multipliers it used.
fn carried_load<K: Field>(
    m: &Model<K>,
    p: &super::PointItem<K>,
    lam: &[K::Elem],
    full: bool,
) -> Result<(Vec3<K>, Vec3<K>, usize)> {
    let k = &m.field;
    let (pf, pm) = projections(k, p, full)?;
    let (nf, nm) = (pf.nrows(), pm.nrows());
    let vec3 = |pr: &Matrix<K>, l: &[K::Elem]| -> Vec3<K> {
        let v = &pr.transpose() * &Matrix::column(k.clone(), l.to_vec());
        [
            v.get(0, 0).clone(),
            v.get(1, 0).clone(),
            v.get(2, 0).clone(),
        ]
    };
    Ok((vec3(&pf, &lam[..nf]), vec3(&pm, &lam[nf..nf + nm]), nf + nm))
}

/// Adds `s * b` at the block (`rb`, `cb`) of 3x3 blocks when neither is the ground.
fn put<K: Field>(
    out: &mut Matrix<K>,
    nb: usize,
    rb: (usize, usize),
    cb: (usize, usize),
    b: &Matrix<K>,
    neg: bool,
) {
    if rb.0 < nb && cb.0 < nb {
        add_block(out, 6 * rb.0 + rb.1, 6 * cb.0 + cb.1, b, neg);
    }
}

fn point_hessian<K: Field>(
    m: &Model<K>,
    p: &super::PointItem<K>,
    frc: &Vec3<K>,
    mmt: &Vec3<K>,
    out: &mut Matrix<K>,
) -> Result<()> {
    let k = &m.field;
    let nb = m.bodies.len();
    let bad = || {
        Error::Invalid(format!(
            "{}: an axis is needed (and must be non-zero)",
            p.name
        ))
    };
    let [b1, b2] = p.bodies;
    let rs = sub3(k, &p.location, &m.origin(b1));
    let re = sub3(k, &p.location, &m.origin(b2));
    let b3 = if p.moments < 2 && (p.forces == 1 || p.forces == 2) && p.rolling_axis.is_none() {
        b2
    } else {
        nb
    };
    let ff = skew(k, frc);
    let ff1 = &skew(k, &rs) * &ff;
    let ff2 = &skew(k, &re) * &ff;
    let (t, r) = (0, 3);
    let mut add = |rb, cb, b: &Matrix<K>, neg| put(out, nb, rb, cb, b, neg);
    add((b1, t), (b1, r), &ff, true);
    add((b1, t), (b3, r), &ff, false);
    add((b2, t), (b2, r), &ff, false);
    add((b2, t), (b3, r), &ff, true);
    add((b1, r), (b1, r), &ff1, true);
    add((b1, r), (b3, r), &ff1, false);
    add((b2, r), (b2, r), &ff2, false);
    add((b2, r), (b3, r), &ff2, true);
    add((b2, r), (b1, t), &ff, true);
    add((b2, r), (b2, t), &ff, false);
    add((b2, r), (b1, r), &ff1.transpose(), false);
    add((b2, r), (b2, r), &ff2.transpose(), true);
    if let Some(ra) = &p.rolling_axis {
        let rr = along(k, ra).ok_or_else(bad)?;
        let g = -&(&ff1.transpose() * &rr);
        add((b1, r), (b1, r), &g, true);
        add((b1, r), (b2, r), &g, false);
        add((b2, r), (b2, r), &g, true);
        add((b2, r), (b1, r), &g, false);
    } else if p.moments == 2 {
        let g = &skew(k, mmt) * &along(k, &p.axis).ok_or_else(bad)?;
        add((b1, r), (b1, r), &g, true);
        add((b2, r), (b2, r), &g, false);
    } else if p.moments == 1 {
        let half = k.inv(&k.from_i64(2)).expect("2 is invertible");
        let g = skew(k, mmt).scale(&half);
        add((b1, r), (b1, r), &g, true);
        add((b1, r), (b2, r), &g, false);
        add((b2, r), (b2, r), &g, false);
        add((b2, r), (b1, r), &g, true);
    }
    Ok(())
}

/// A spring or link along `dir = loc2 - loc1` carrying `t` (its multiplier for the
/// unnormalised row: tension / length).
fn line_hessian<K: Field>(m: &Model<K>, l: &super::LineItem<K>, t: &K::Elem, out: &mut Matrix<K>) {
    let k = &m.field;
    let nb = m.bodies.len();
    let d = 6 * nb;
    let dir = sub3(k, &l.locations[1], &l.locations[0]);
    let [b1, b2] = l.bodies;
    let rs = sub3(k, &l.locations[0], &m.origin(b1));
    let re = sub3(k, &l.locations[1], &m.origin(b2));
    let su = skew(k, &dir);
    let mut t1 = Matrix::zeros(k.clone(), 3, 6);
    add_block(&mut t1, 0, 0, &su, true);
    add_block(&mut t1, 0, 3, &(&su * &skew(k, &rs)), false);
    let mut t2 = Matrix::zeros(k.clone(), 3, 6);
    add_block(&mut t2, 0, 0, &su, false);
    add_block(&mut t2, 0, 3, &(&su * &skew(k, &re)), true);
    let mut tmp = Matrix::zeros(k.clone(), 3, d);
    if b1 < nb {
        add_block(&mut tmp, 0, 6 * b1, &t1, false);
    }
    if b2 < nb {
        add_block(&mut tmp, 0, 6 * b2, &t2, false);
    }
    let inv = k.inv(&dot3(k, &dir, &dir)).expect("non-zero direction");
    let g = sparse_mul(&tmp.transpose(), &tmp).scale(&k.mul(t, &inv));
    add_block(out, 0, 0, &g, false);
    if b1 < nb {
        add_block(out, 6 * b1, 6 * b1 + 3, &t1.transpose().scale(t), true);
    }
    if b2 < nb {
        add_block(out, 6 * b2, 6 * b2 + 3, &t2.transpose().scale(t), true);
    }
}
