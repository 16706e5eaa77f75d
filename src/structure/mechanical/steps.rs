//! The mechanical normal form step by step (`mnf --steps`, issue 27): the steps
//! [`super::mechanical_normal_form_recorded`] records while it runs, each identity checked
//! exactly from the recorded objects:
//!
//! * input compression $B = B_1 R$ (only when $\operatorname{rank} B < p$): $B_1 R = B$;
//! * existence: $U_{B,2}^T B = 0$ with $n - p$ independent rows, $K = U_{B,2}^T A B$ of rank
//!   $p$ (i.e. $\operatorname{rank}[B, AB] = 2p$), Theorem 2.1's $G$ (reported, not
//!   decisive: it is not similarity invariant) and the largest geometric multiplicity of the
//!   uncontrollable part ($\le n/2 - p$ decides);
//! * eq. 15/16 $L\,\mathrm{vec}(T) = R$: $[I\ 0]\,T_0 A = [0\ I]\,T_0 F$, $T_0 B = [0; I_p]$ and
//!   the homogeneous equations for every direction $T_k$;
//! * the invertible member $T = T_0 + \sum_k \alpha_k T_k$, $\det T \ne 0$ (or $T = I$ when
//!   the system is already in normal form: eq. 15 holds for $I$);
//! * the form: $\tilde A\,(TF) = T A$, $\tilde B = T B$, $\tilde C\,(TF) = C$, equal Markov
//!   parameters ([`super::MechanicalNormalForm::verify`]).

use super::MechanicalForm;
use super::existence::{Existence, ExistenceParts};
use super::transform::{SearchOutcome, TransformationFamily, identity_solves};
use crate::field::Field;
use crate::jordan::derivation::{Object, Recorder, StepKind};
use crate::matrix::Matrix;

/// Largest $n$ for which $L$ (an $(n/2 + p) n \times n^2$ matrix) is recorded.
const L_MAX_N: usize = 4;
/// Most directions $T_k$ recorded side by side.
const DIRECTIONS_MAX: usize = 4;

pub(crate) fn compression<K: Field>(
    rec: &mut Recorder<'_, K>,
    b: &Matrix<K>,
    b1: &Matrix<K>,
    r: &Matrix<K>,
) {
    let ok = b1.try_mul(r).is_ok_and(|m| m == *b);
    rec.push(
        StepKind::MnfCompression,
        None,
        vec![
            ("B", Object::Matrix(b.clone())),
            ("B1", Object::Matrix(b1.clone())),
            ("R", Object::Matrix(r.clone())),
        ],
        Some(ok),
    );
}

pub(crate) fn existence<K: Field>(
    rec: &mut Recorder<'_, K>,
    e: &Existence<K>,
    parts: ExistenceParts<K>,
    descriptor: bool,
) {
    let (n, p) = (e.n, e.p);
    let mut objects = vec![
        ("n", Object::Count(n)),
        ("p", Object::Count(p)),
        ("descriptor", Object::Count(usize::from(descriptor))),
    ];
    if let Some(rb) = parts.rank_b {
        objects.push(("rank_b", Object::Count(rb)));
    }
    let mut ok = true;
    if let Some(u) = parts.ub2t {
        // U_B2^T B = 0 with independent rows, as many as n - rank B
        ok &= (&u * &parts.b).is_zero()
            && u.rank() == u.nrows()
            && Some(u.nrows()) == parts.rank_b.map(|r| n - r);
        objects.push(("UB2t", Object::Matrix(u)));
    }
    if let Some(k) = parts.k {
        let rk = k.rank();
        ok &= k.nrows() + p == n && k.ncols() == p;
        objects.push(("K", Object::Matrix(k)));
        objects.push(("rank_k", Object::Count(rk)));
    }
    if let Some(g) = parts.g {
        let rg = g.rank();
        objects.push(("G", Object::Matrix(g)));
        objects.push(("rank_g", Object::Count(rg)));
    }
    if let Some(geo) = parts.geo {
        objects.push(("geo", Object::Count(geo)));
    }
    objects.push(("exists", Object::Count(usize::from(e.exists))));
    rec.push(StepKind::MnfExistence, None, objects, Some(ok));
}

/// $[I\ 0]\,T A - [0\ I]\,T F$ and $T B$.
fn residuals<K: Field>(
    (f, a, b): (Option<&Matrix<K>>, &Matrix<K>, &Matrix<K>),
    t: &Matrix<K>,
) -> (Matrix<K>, Matrix<K>) {
    let n = a.nrows();
    let h = n / 2;
    let ta = t * a;
    let tf = match f {
        None => t.clone(),
        Some(f) => t * f,
    };
    (&ta.submatrix(0, h, 0, n) - &tf.submatrix(h, n, 0, n), t * b)
}

pub(crate) fn equation<K: Field>(
    rec: &mut Recorder<'_, K>,
    sys: (Option<&Matrix<K>>, &Matrix<K>, &Matrix<K>),
    l: Matrix<K>,
    family: &TransformationFamily<K>,
) {
    let (_, a, b) = sys;
    let k = a.field().clone();
    let (n, p) = (a.nrows(), b.ncols());
    let mut target = Matrix::zeros(k.clone(), n, p);
    for j in 0..p {
        target.set(n - p + j, j, k.one());
    }
    let (r0, tb0) = residuals(sys, &family.particular);
    let mut ok = r0.is_zero() && tb0 == target;
    for t in &family.directions {
        let (r, tb) = residuals(sys, t);
        ok &= r.is_zero() && tb.is_zero();
    }
    let rank_l = n * n - family.directions.len();
    let mut objects = vec![];
    if n <= L_MAX_N {
        objects.push(("L", Object::Matrix(l)));
    }
    objects.push(("rank_L", Object::Count(rank_l)));
    objects.push(("T0", Object::Matrix(family.particular.clone())));
    objects.push(("s", Object::Count(family.directions.len())));
    if !family.directions.is_empty() && family.directions.len() <= DIRECTIONS_MAX {
        let mut side = Matrix::zeros(k, n, 0);
        for t in &family.directions {
            side = side.hstack(t).unwrap_or(side);
        }
        objects.push(("Tk", Object::Matrix(side)));
    }
    rec.push(StepKind::MnfEquation, None, objects, Some(ok));
}

pub(crate) fn search<K: Field>(
    rec: &mut Recorder<'_, K>,
    sys: (Option<&Matrix<K>>, &Matrix<K>, &Matrix<K>),
    family: &TransformationFamily<K>,
    found: &SearchOutcome<K>,
) {
    let (f, a, b) = sys;
    let k = a.field().clone();
    let taken_i = found.candidates == 0;
    let member_ok = if taken_i {
        identity_solves(f, a, b) && found.t.is_identity()
    } else {
        family.member(&found.alpha) == found.t
    };
    let ok = member_ok && !k.is_zero(&found.det);
    let alpha = Matrix::from_vec(
        k.clone(),
        1,
        found.alpha.len(),
        found.alpha.iter().map(|&x| k.from_i64(x)).collect(),
    );
    rec.push(
        StepKind::MnfSearch,
        None,
        vec![
            ("t_equals_i", Object::Count(usize::from(taken_i))),
            ("alpha", Object::Matrix(alpha)),
            ("candidates", Object::Count(found.candidates as usize)),
            ("T", Object::Matrix(found.t.clone())),
            ("det", Object::Scalar(found.det.clone())),
        ],
        Some(ok),
    );
}

pub(crate) fn form<K: Field>(rec: &mut Recorder<'_, K>, m: &MechanicalForm<K>, verified: bool) {
    rec.push(
        StepKind::MnfForm,
        None,
        vec![
            ("At", Object::Matrix(m.a_tilde.clone())),
            ("Bt", Object::Matrix(m.b_tilde.clone())),
            ("Ct", Object::Matrix(m.output.clone())),
            ("Mq", Object::Matrix(m.mass.clone())),
            ("Dq", Object::Matrix(m.damping.clone())),
            ("Kq", Object::Matrix(m.stiffness.clone())),
            ("W", Object::Matrix(m.input.clone())),
        ],
        Some(verified),
    );
}
