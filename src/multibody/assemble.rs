//! Assembly of a [`Model`] into its descriptor system (see the module docs of
//! [`crate::multibody`] for the equations).

use super::geometry::{Vec3, add_block, dot3, point_map, scale3, skew, sparse_mul, sub3};
use super::preload::{load_stiffness, projections, tangent_stiffness};
use super::{Assembly, LineItem, LineKind, Model, PointItem, PointKind};
use crate::error::{Error, Result};
use crate::field::Field;
use crate::matrix::Matrix;
use crate::system::Descriptor;

const COORDS: [&str; 6] = ["x", "y", "z", "rx", "ry", "rz"];

/// The descriptor system of `m` and its derivation.
///
/// # Errors
/// `Invalid` for a body index out of range, an axis that is zero where a direction is
/// needed, an actuator or sensor whose two locations coincide or are an irrational
/// distance apart, a sensor `order` other than 1, 2 or 3; the errors of
/// [`Descriptor::new`].
pub fn assemble<K: Field>(m: &Model<K>) -> Result<Assembly<K>> {
    let k = &m.field;
    let nb = m.bodies.len();
    let d = 6 * nb;
    check_indices(m)?;
    let mass = mass_matrix(m);
    let (h, kd, cd) = deflection(m)?;
    let stiffness = weighted_gram(k, &h, &kd);
    let damping = weighted_gram(k, &h, &cd);
    let rigid = stack(k, d, m, PointKind::Rigid, true)?;
    let nh_constraint = stack(k, d, m, PointKind::Nonholonomic, false)?;
    let null_j = rigid.nullspace();
    let (velocity, momentum) = motion_terms(m);
    let (tangent, loads) = if m.loads.is_empty() {
        (
            Matrix::zeros(k.clone(), d, d),
            Matrix::zeros(k.clone(), d, d),
        )
    } else {
        let t = tangent_stiffness(m, &rigid, &null_j, &h, &kd, &stiffness)?;
        (t, load_stiffness(m))
    };
    let (f, fr) = inputs(m)?;
    let (out, feed, acc) = outputs(m, &velocity)?;
    let nin = f.ncols();
    let n = 2 * d + nin;
    // E_full, KC_full
    let mut ef = Matrix::zeros(k.clone(), n, n);
    let mut kc = Matrix::zeros(k.clone(), n, n);
    let ident = Matrix::identity(k.clone(), d);
    add_block(&mut ef, 0, 0, &ident, false);
    add_block(&mut ef, d, d, &mass, false);
    add_block(&mut ef, d, 2 * d, &fr, true);
    add_block(&mut kc, 0, 0, &velocity, false);
    add_block(&mut kc, 0, d, &ident, true);
    let kk = &(&stiffness + &tangent) + &loads;
    add_block(&mut kc, d, 0, &kk, false);
    add_block(&mut kc, d, d, &(&damping + &momentum), false);
    add_block(&mut kc, d, 2 * d, &f, true);
    add_block(
        &mut kc,
        2 * d,
        2 * d,
        &Matrix::identity(k.clone(), nin),
        false,
    );
    let (r, l) = bases(k, &rigid, &nh_constraint, &null_j, &velocity, nin);
    let lt = l.transpose();
    let e = sparse_mul(&lt, &sparse_mul(&ef, &r));
    let a = -&sparse_mul(&lt, &sparse_mul(&kc, &r));
    let mut bu = Matrix::zeros(k.clone(), n, nin);
    add_block(&mut bu, 2 * d, 0, &Matrix::identity(k.clone(), nin), false);
    let b = sparse_mul(&lt, &bu);
    let c = sparse_mul(&out, &r);
    let (e, a, b, c) = with_accelerations(k, [e, a, b, c], &acc, &r);
    let coordinate_names: Vec<String> = m
        .bodies
        .iter()
        .flat_map(|b| COORDS.iter().map(move |c| format!("{}.{c}", b.name)))
        .collect();
    let inputs: Vec<String> = m.actuators().map(|a| a.name.clone()).collect();
    let mut state_names = free_names(&r, &coordinate_names, &inputs);
    let sensor_names: Vec<String> = m.sensors().map(|s| s.name.clone()).collect();
    state_names.extend(acc.iter().map(|(i, _)| format!("a.{}", sensor_names[*i])));
    Ok(Assembly {
        descriptor: Descriptor::new(e, a, b, c, feed)?,
        state_names,
        input_names: inputs,
        output_names: sensor_names,
        coordinate_names,
        mass,
        stiffness,
        damping,
        tangent_stiffness: tangent,
        load_stiffness: loads,
        momentum,
        velocity,
        constraint: rigid,
        nh_constraint,
        right_basis: r,
        left_basis: l,
    })
}

fn invalid<T>(msg: String) -> Result<T> {
    Err(Error::Invalid(msg))
}

fn check_indices<K: Field>(m: &Model<K>) -> Result<()> {
    let nb = m.bodies.len();
    let bad = m
        .points
        .iter()
        .map(|p| (&p.name, p.bodies))
        .chain(m.lines.iter().map(|l| (&l.name, l.bodies)))
        .find(|(_, b)| b[0] > nb || b[1] > nb || b[0] == b[1]);
    if let Some((name, _)) = bad {
        return invalid(format!(
            "{name}: the two bodies must be different bodies of the model"
        ));
    }
    if let Some(l) = m.loads.iter().find(|l| l.body >= nb) {
        return invalid(format!("{}: unknown body", l.name));
    }
    Ok(())
}

fn mass_matrix<K: Field>(m: &Model<K>) -> Matrix<K> {
    let k = &m.field;
    let mut mm = Matrix::zeros(k.clone(), 6 * m.bodies.len(), 6 * m.bodies.len());
    for (i, b) in m.bodies.iter().enumerate() {
        for j in 0..3 {
            mm.set(6 * i + j, 6 * i + j, b.mass.clone());
        }
        add_block(&mut mm, 6 * i + 3, 6 * i + 3, &b.inertia, false);
    }
    mm
}

/// Places `rows * T(r)` at body `b1` and its negative at body `b2` (each at its own point).
fn two_body_rows<K: Field>(
    m: &Model<K>,
    rows: &Matrix<K>,
    bodies: [usize; 2],
    at: [&Vec3<K>; 2],
) -> Matrix<K> {
    let k = &m.field;
    let nb = m.bodies.len();
    let mut out = Matrix::zeros(k.clone(), rows.nrows(), 6 * nb);
    for (side, (&b, p)) in bodies.iter().zip(at).enumerate() {
        if b < nb {
            let r = sub3(k, p, &m.origin(b));
            let blk = rows * &point_map(k, &r);
            add_block(&mut out, 0, 6 * b, &blk, side == 1);
        }
    }
    out
}

/// The rows `[Pf 0; 0 Pm] T` of a point item: the 6 rows of the projections for a flexible
/// item (its stiffness is `k T^T P T`), the independent rows of [`super::geometry::carried_rows`] for a
/// constraint (one equation per carried direction).
pub(super) fn point_rows<K: Field>(m: &Model<K>, p: &PointItem<K>) -> Result<Matrix<K>> {
    let k = &m.field;
    let (pf, pm) = projections(k, p, p.kind == PointKind::Flexible)?;
    let mut p6 = Matrix::zeros(k.clone(), pf.nrows() + pm.nrows(), 6);
    add_block(&mut p6, 0, 0, &pf, false);
    add_block(&mut p6, pf.nrows(), 3, &pm, false);
    Ok(two_body_rows(m, &p6, p.bodies, [&p.location, &p.location]))
}

/// The row `e^T T` of a line item along `dir` (`e = [dir; 0]`, or `[0; dir]` with twist).
fn line_row<K: Field>(m: &Model<K>, l: &LineItem<K>, dir: &Vec3<K>) -> Matrix<K> {
    let k = &m.field;
    let mut e = Matrix::zeros(k.clone(), 1, 6);
    let off = if l.twist { 3 } else { 0 };
    for (j, x) in dir.iter().enumerate() {
        e.set(0, off + j, x.clone());
    }
    two_body_rows(m, &e, l.bodies, [&l.locations[0], &l.locations[1]])
}

fn line_dir<K: Field>(m: &Model<K>, l: &LineItem<K>) -> Result<Vec3<K>> {
    let d = sub3(&m.field, &l.locations[1], &l.locations[0]);
    if d.iter().all(|x| m.field.is_zero(x)) {
        return invalid(format!("{}: the two locations coincide", l.name));
    }
    Ok(d)
}

/// The unit vector along a line item; the distance must be rational.
fn line_unit<K: Field>(m: &Model<K>, l: &LineItem<K>) -> Result<Vec3<K>> {
    let k = &m.field;
    let d = line_dir(m, l)?;
    let len = k
        .to_rational(&dot3(k, &d, &d))
        .and_then(|q| rational_sqrt(&q))
        .ok_or_else(|| {
            Error::Invalid(format!(
                "{}: the distance between the two locations must be a rational number",
                l.name
            ))
        })?;
    let inv = k.inv(&k.from_rational(&len)).expect("non-zero length");
    Ok(scale3(k, &inv, &d))
}

fn rational_sqrt(q: &crate::field::Rational) -> Option<crate::field::Rational> {
    use num_traits::Signed;
    if q.is_negative() {
        return None;
    }
    let (n, dd) = (q.numer().sqrt(), q.denom().sqrt());
    (&n * &n == *q.numer() && &dd * &dd == *q.denom()).then(|| crate::field::Rational::new(n, dd))
}

/// Deflection Jacobian `H` of the flexible items with their stiffness and damping weights.
type Weighted<K> = (Matrix<K>, Vec<<K as Field>::Elem>, Vec<<K as Field>::Elem>);

fn deflection<K: Field>(m: &Model<K>) -> Result<Weighted<K>> {
    let k = &m.field;
    let mut h = Matrix::zeros(k.clone(), 0, 6 * m.bodies.len());
    let (mut kd, mut cd) = (vec![], vec![]);
    for p in m.points.iter().filter(|p| p.kind == PointKind::Flexible) {
        h = h.vstack(&point_rows(m, p)?)?;
        for j in 0..6 {
            kd.push(p.stiffness[j / 3].clone());
            cd.push(p.damping[j / 3].clone());
        }
    }
    for l in &m.lines {
        if let LineKind::Spring { stiffness, damping } = &l.kind {
            let dir = line_dir(m, l)?;
            let inv = k.inv(&dot3(k, &dir, &dir)).expect("non-zero direction");
            h = h.vstack(&line_row(m, l, &dir))?;
            kd.push(k.mul(stiffness, &inv));
            cd.push(k.mul(damping, &inv));
        }
    }
    Ok((h, kd, cd))
}

/// `H^T diag(w) H`.
pub(super) fn weighted_gram<K: Field>(k: &K, h: &Matrix<K>, w: &[K::Elem]) -> Matrix<K> {
    let mut hw = h.clone();
    for (i, wi) in w.iter().enumerate() {
        for j in 0..h.ncols() {
            let x = k.mul(h.get(i, j), wi);
            hw.set(i, j, x);
        }
    }
    sparse_mul(&h.transpose(), &hw)
}

/// Constraint rows of the point items of one kind (with the rigid links when `links`).
fn stack<K: Field>(
    k: &K,
    d: usize,
    m: &Model<K>,
    kind: PointKind,
    links: bool,
) -> Result<Matrix<K>> {
    let mut j = Matrix::zeros(k.clone(), 0, d);
    for p in m.points.iter().filter(|p| p.kind == kind) {
        j = j.vstack(&point_rows(m, p)?)?;
    }
    if links {
        for l in m.lines.iter().filter(|l| matches!(l.kind, LineKind::Link)) {
            j = j.vstack(&line_row(m, l, &line_dir(m, l)?))?;
        }
    }
    Ok(j)
}

/// `V` (kinematic) and `C_m` (momentum) from the bodies' nominal velocities.
fn motion_terms<K: Field>(m: &Model<K>) -> (Matrix<K>, Matrix<K>) {
    let k = &m.field;
    let d = 6 * m.bodies.len();
    let (mut v, mut mv) = (
        Matrix::zeros(k.clone(), d, d),
        Matrix::zeros(k.clone(), d, d),
    );
    for (i, b) in m.bodies.iter().enumerate() {
        let w = &b.angular_velocity;
        let h = b
            .inertia
            .try_mul(&Matrix::column(k.clone(), w.to_vec()))
            .expect("3x3 by 3x1");
        let h: Vec3<K> = [
            h.get(0, 0).clone(),
            h.get(1, 0).clone(),
            h.get(2, 0).clone(),
        ];
        add_block(&mut mv, 6 * i + 3, 6 * i + 3, &skew(k, &h), true);
        add_block(
            &mut mv,
            6 * i,
            6 * i + 3,
            &skew(k, &scale3(k, &b.mass, &b.velocity)),
            true,
        );
        add_block(&mut v, 6 * i, 6 * i + 3, &skew(k, &b.velocity), false);
    }
    (v, mv)
}

/// `F` and `F_r` (`d x nin`): the actuators' forces per unit input and input rate.
fn inputs<K: Field>(m: &Model<K>) -> Result<(Matrix<K>, Matrix<K>)> {
    let k = &m.field;
    let d = 6 * m.bodies.len();
    let acts: Vec<&LineItem<K>> = m.actuators().collect();
    let (mut f, mut fr) = (
        Matrix::zeros(k.clone(), d, acts.len()),
        Matrix::zeros(k.clone(), d, acts.len()),
    );
    for (j, a) in acts.iter().enumerate() {
        let LineKind::Actuator { gain, rate_gain } = &a.kind else {
            continue;
        };
        let row = line_row(m, a, &line_unit(m, a)?);
        for i in 0..d {
            let x = row.get(0, i);
            f.set(i, j, k.neg(&k.mul(gain, x)));
            fr.set(i, j, k.neg(&k.mul(rate_gain, x)));
        }
    }
    Ok((f, fr))
}

/// The output matrix over the full state `[p; w; u]`, the feedthrough `D` and, for each
/// acceleration sensor (`order` 3), its index and its velocity row (whose derivative it
/// reads).
type Outputs<K> = (Matrix<K>, Matrix<K>, Vec<(usize, Matrix<K>)>);

fn outputs<K: Field>(m: &Model<K>, v: &Matrix<K>) -> Result<Outputs<K>> {
    let k = &m.field;
    let d = 6 * m.bodies.len();
    let nin = m.actuators().count();
    let sensors: Vec<&LineItem<K>> = m.sensors().collect();
    let mut c = Matrix::zeros(k.clone(), sensors.len(), 2 * d + nin);
    let mut dd = Matrix::zeros(k.clone(), sensors.len(), nin);
    let mut acc = vec![];
    for (i, s) in sensors.iter().enumerate() {
        let LineKind::Sensor {
            gain,
            order,
            local,
            actuator,
        } = &s.kind
        else {
            continue;
        };
        let row = line_row(m, s, &line_unit(m, s)?).scale(&k.neg(gain));
        // velocity: w in the body's frame, p' = w - V p in the ground's
        let mut vel = Matrix::zeros(k.clone(), 1, 2 * d + nin);
        add_block(&mut vel, 0, d, &row, false);
        if !local {
            add_block(&mut vel, 0, 0, &(&row * v), true);
        }
        match order {
            1 => add_block(&mut c, i, 0, &row, false),
            2 => add_block(&mut c, i, 0, &vel, false),
            3 => acc.push((i, vel)),
            _ => {
                return invalid(format!(
                    "{}: order must be 1 (position), 2 (velocity) or 3 (acceleration)",
                    s.name
                ));
            }
        }
        if let Some((a, g)) = actuator {
            dd.set(i, *a, k.neg(g));
        }
    }
    Ok((c, dd, acc))
}

/// Appends one state $\xi_j$ per acceleration sensor $i$: the equation $v_i R \dot x = \xi_j$
/// ($v_i$ its velocity row) and the output $y_i = \xi_j$. $\xi_j$ is algebraic (a zero
/// column of $E$), so the standard form eliminates it and $y_i$ is the velocity's derivative
/// (EoM's order 3), with the feedthrough the dynamics give it.
fn with_accelerations<K: Field>(
    k: &K,
    [e, a, b, c]: [Matrix<K>; 4],
    acc: &[(usize, Matrix<K>)],
    r: &Matrix<K>,
) -> (Matrix<K>, Matrix<K>, Matrix<K>, Matrix<K>) {
    if acc.is_empty() {
        return (e, a, b, c);
    }
    let (n, na) = (e.nrows(), acc.len());
    let grow = |x: &Matrix<K>, rows: usize, cols: usize| {
        let mut y = Matrix::zeros(k.clone(), rows, cols);
        add_block(&mut y, 0, 0, x, false);
        y
    };
    let (mut e2, mut a2) = (grow(&e, n + na, n + na), grow(&a, n + na, n + na));
    let b2 = grow(&b, n + na, b.ncols());
    let mut c2 = grow(&c, c.nrows(), n + na);
    for (j, (i, vel)) in acc.iter().enumerate() {
        add_block(&mut e2, n + j, 0, &sparse_mul(vel, r), false);
        a2.set(n + j, n + j, k.one());
        c2.set(*i, n + j, k.one());
    }
    (e2, a2, b2, c2)
}

/// The right and left bases `R`, `L`: the canonical null spaces of
/// `J_r = [J 0; -J V, J; 0 J_n]` and `J_l = [J 0; 0 J; 0 J_n]` (with `nin` zero columns).
/// `J_l` is block diagonal, so its canonical basis is `diag(null J, null [J; J_n], I)` (the
/// RREF of a block-diagonal matrix is block diagonal); so is `J_r` when its block
/// `J V` vanishes. `null_j` is `null J`.
fn bases<K: Field>(
    k: &K,
    j: &Matrix<K>,
    jn: &Matrix<K>,
    null_j: &Matrix<K>,
    v: &Matrix<K>,
    nin: usize,
) -> (Matrix<K>, Matrix<K>) {
    let d = j.ncols();
    let null_w = if jn.nrows() == 0 {
        null_j.clone()
    } else {
        j.vstack(jn).expect("same columns").nullspace()
    };
    let (f1, f2) = (null_j.ncols(), null_w.ncols());
    let mut l = Matrix::zeros(k.clone(), 2 * d + nin, f1 + f2 + nin);
    add_block(&mut l, 0, 0, null_j, false);
    add_block(&mut l, d, f1, &null_w, false);
    add_block(
        &mut l,
        2 * d,
        f1 + f2,
        &Matrix::identity(k.clone(), nin),
        false,
    );
    let jv = sparse_mul(j, v);
    if jv.is_zero() {
        return (l.clone(), l);
    }
    let (q, t) = (j.nrows(), jn.nrows());
    let mut jr = Matrix::zeros(k.clone(), 2 * q + t, 2 * d + nin);
    add_block(&mut jr, 0, 0, j, false);
    add_block(&mut jr, q, d, j, false);
    add_block(&mut jr, 2 * q, d, jn, false);
    add_block(&mut jr, q, 0, &jv, true);
    (jr.nullspace(), l)
}

/// Names of the free coordinates of the canonical null space basis `r`: its columns are
/// the unit vectors at the free positions, completed.
fn free_names(r: &Matrix<impl Field>, coords: &[String], inputs: &[String]) -> Vec<String> {
    let k = r.field();
    let d = coords.len();
    (0..r.ncols())
        .map(|j| {
            // the free coordinate is the last row with a one that no other column has
            let i = (0..r.nrows())
                .rev()
                .find(|&i| {
                    k.is_one(r.get(i, j))
                        && (0..r.ncols()).all(|c| c == j || k.is_zero(r.get(i, c)))
                })
                .unwrap_or(0);
            if i < d {
                coords[i].clone()
            } else if i < 2 * d {
                format!("v.{}", coords[i - d])
            } else {
                format!("u.{}", inputs.get(i - 2 * d).map_or("?", String::as_str))
            }
        })
        .collect()
}
