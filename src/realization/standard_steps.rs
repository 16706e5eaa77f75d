//! A descriptor system to standard form step by step (`standard --steps`, issue 27): the
//! steps [`super::descriptor_to_standard_recorded`] records while it runs, each identity
//! checked exactly from the recorded objects:
//!
//! * the compression $U E V = \operatorname{diag}(E_{11}, 0)$ with $E_{11}$, $U$, $V$
//!   invertible, and the rank $k$ of the algebraic block $\hat A_{22}$ (index $\le 1$ iff
//!   $k = n - r$);
//! * (index 1) the elimination of the algebraic states with $X = \hat A_{IJ}$ invertible and the
//!   reduced $E' = E_{11}$ invertible;
//! * (index $> 1$) the Weierstrass split: $V^{-1}\hat E V$ block diagonal and $GN$ nilpotent
//!   (for `minreal --descriptor` with $E$ invertible the trivial split, $EA_f = A$, $EB_f = B$);
//! * the standard form with the certificate of its route: $x = V_1 z + W u$ maps solutions
//!   (index $\le 1$), or equal transfer matrices (Weierstrass,
//!   [`super::weierstrass::same_transfer`]).

use super::descriptor_elim::CompressedE;
use super::weierstrass::FittingSplit;
use crate::field::Field;
use crate::jordan::derivation::{Object, Recorder, StepKind};
use crate::matrix::Matrix;
use crate::system::{Descriptor, StateSpace};

/// Whether `m` is square with a nonzero determinant.
fn invertible<K: Field>(m: &Matrix<K>) -> bool {
    m.is_square() && m.det().is_ok_and(|d| !m.field().is_zero(&d))
}

pub(crate) fn compress<K: Field>(
    rec: &mut Recorder<'_, K>,
    sys: &Descriptor<K>,
    c: &CompressedE<K>,
    k: usize,
) {
    let n = sys.nstates();
    let r = c.rank;
    let uev = &c.system.e;
    let zero_outside = uev.submatrix(0, r, r, n).is_zero() && uev.submatrix(r, n, 0, n).is_zero();
    let ok = zero_outside
        && invertible(&uev.submatrix(0, r, 0, r))
        && invertible(&c.u)
        && invertible(&c.v);
    rec.push(
        StepKind::DescriptorCompress,
        None,
        vec![
            ("E", Object::Matrix(sys.e.clone())),
            ("r", Object::Count(r)),
            ("U", Object::Matrix(c.u.clone())),
            ("V", Object::Matrix(c.v.clone())),
            ("UEV", Object::Matrix(uev.clone())),
            ("UAV", Object::Matrix(c.system.a.clone())),
            ("k", Object::Count(k)),
        ],
        Some(ok),
    );
}

pub(crate) fn eliminate<K: Field>(
    rec: &mut Recorder<'_, K>,
    c: &CompressedE<K>,
    (rows, cols): (&[usize], &[usize]),
    red: &Descriptor<K>,
) {
    let x = c.system.a.select_rows(rows).select_cols(cols);
    let ok = invertible(&x) && invertible(&red.e);
    rec.push(
        StepKind::DescriptorEliminate,
        None,
        vec![
            ("eqs", Object::Counts(rows.to_vec())),
            ("states", Object::Counts(cols.to_vec())),
            ("X", Object::Matrix(x)),
            ("Er", Object::Matrix(red.e.clone())),
            ("Ar", Object::Matrix(red.a.clone())),
            ("Br", Object::Matrix(red.b.clone())),
            ("Cr", Object::Matrix(red.c.clone())),
            ("Dr", Object::Matrix(red.d.clone())),
        ],
        Some(ok),
    );
}

pub(crate) fn fitting<K: Field>(rec: &mut Recorder<'_, K>, s: &FittingSplit<K>) {
    let k = s.a_f.field().clone();
    let Some(l0) = s.lambda0 else {
        // E invertible: the trivial split, checked by E Af = A, E Bf = B
        rec.push(
            StepKind::DescriptorFitting,
            None,
            vec![
                ("Af", Object::Matrix(s.a_f.clone())),
                ("Bf", Object::Matrix(s.b_f.clone())),
            ],
            Some(s.decoupled),
        );
        return;
    };
    let ninf = s.gn.nrows();
    let nilpotent = ninf == 0 || s.gn.pow(ninf as u32).is_ok_and(|m| m.is_zero());
    rec.push(
        StepKind::DescriptorFitting,
        None,
        vec![
            ("lambda0", Object::Scalar(k.from_i64(l0))),
            ("V1", Object::Matrix(s.v1.clone())),
            ("V2", Object::Matrix(s.v2.clone())),
            ("Af", Object::Matrix(s.a_f.clone())),
            ("Bf", Object::Matrix(s.b_f.clone())),
            ("GN", Object::Matrix(s.gn.clone())),
            ("GB", Object::Matrix(s.gb.clone())),
        ],
        Some(s.decoupled && nilpotent),
    );
}

/// `route`: 0 for $E$ invertible, 1 for index 1, 2 for the Weierstrass split.
pub(crate) fn form<K: Field>(
    rec: &mut Recorder<'_, K>,
    s: &StateSpace<K>,
    (v1, w): (&Matrix<K>, Option<&Matrix<K>>),
    (removed, route): (usize, usize),
    verified: bool,
) {
    let mut objects = vec![
        ("As", Object::Matrix(s.a.clone())),
        ("Bs", Object::Matrix(s.b.clone())),
        ("Cs", Object::Matrix(s.c.clone())),
        ("Ds", Object::Matrix(s.d.clone())),
        ("V1", Object::Matrix(v1.clone())),
    ];
    if let Some(w) = w {
        objects.push(("W", Object::Matrix(w.clone())));
    }
    objects.push(("removed", Object::Count(removed)));
    objects.push(("route", Object::Count(route)));
    rec.push(StepKind::StandardForm, None, objects, Some(verified));
}
