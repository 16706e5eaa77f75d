//! The steps that the recorded methods (Rosenbrock's staircases, Ho–Kalman's Hankel
//! factorization, the minimal part of both) push while they run: their identities and their
//! records. Below [`super::rosenbrock`], [`super::ho_kalman`] and [`super::steps`] (which
//! re-exports the identities), so that the methods do not reach up into the derivations.

use super::controllability::mcmillan_degree;
use crate::field::Field;
use crate::jordan::derivation::{Object, Recorder, StepKind};
use crate::matrix::Matrix;
use crate::system::StateSpace;

/// The identity of a staircase step: $A T = T \tilde A$, $B = T \tilde B$, $\tilde C = C T$,
/// $\tilde A_{12} = 0$ (the $n - k$ unreached rows against the $k$ reached columns) and
/// $\tilde B_1 = 0$.
pub fn staircase_identity<K: Field>(
    sys: &StateSpace<K>,
    t: &Matrix<K>,
    st: &StateSpace<K>,
    k: usize,
) -> bool {
    let n = sys.nstates();
    let u = n - k;
    &sys.a * t == t * &st.a
        && sys.b == t * &st.b
        && st.c == &sys.c * t
        && st.a.submatrix(0, u, u, n).is_zero()
        && st.b.submatrix(0, u, 0, st.b.ncols()).is_zero()
}

/// Records one Rosenbrock staircase (on the system or on the dual of its controllable part).
pub(crate) fn staircase<K: Field>(
    rec: &mut Recorder<'_, K>,
    sys: &StateSpace<K>,
    t: &Matrix<K>,
    st: &StateSpace<K>,
    k: usize,
    dual: bool,
) {
    let ok = staircase_identity(sys, t, st, k);
    rec.push(
        StepKind::Staircase,
        None,
        vec![
            ("T", Object::Matrix(t.clone())),
            ("k", Object::Count(k)),
            ("At", Object::Matrix(st.a.clone())),
            ("Bt", Object::Matrix(st.b.clone())),
            ("Ct", Object::Matrix(st.c.clone())),
            ("dual", Object::Count(usize::from(dual))),
        ],
        Some(ok),
    );
}

/// Records the minimal part: Markov parameters equal ($k < n + r$), order = McMillan degree.
pub(crate) fn minimal_part<K: Field>(
    rec: &mut Recorder<'_, K>,
    sys: &StateSpace<K>,
    min: &StateSpace<K>,
) {
    let order = min.nstates();
    let mcm = mcmillan_degree(sys);
    let ok = sys.same_markov(min, sys.nstates() + order) && order == mcm;
    rec.push(
        StepKind::MinimalPart,
        None,
        vec![
            ("Am", Object::Matrix(min.a.clone())),
            ("Bm", Object::Matrix(min.b.clone())),
            ("Cm", Object::Matrix(min.c.clone())),
            ("order", Object::Count(order)),
            ("mcmillan", Object::Count(mcm)),
        ],
        Some(ok),
    );
}

/// Records the block Hankel matrix and its rank.
pub(crate) fn hankel<K: Field>(rec: &mut Recorder<'_, K>, h0: &Matrix<K>, rank: usize) {
    rec.push(
        StepKind::Hankel,
        None,
        vec![
            ("H", Object::Matrix(h0.clone())),
            ("rank", Object::Count(rank)),
        ],
        None,
    );
}

/// The identity of the Ho–Kalman factorization: $L R = H_0$, $L^+ L = I$, $R R^+ = I$,
/// $A_r = L^+ H_1 R^+$, $B_r$ = first columns of $R$, $C_r$ = first rows of $L$.
pub fn hankel_factor_identity<K: Field>(
    h: [&Matrix<K>; 2],
    lr: [&Matrix<K>; 2],
    inv: [&Matrix<K>; 2],
    min: &StateSpace<K>,
) -> bool {
    let ([h0, h1], [l, r], [li, ri]) = (h, lr, inv);
    let k = h0.field().clone();
    let n = l.ncols();
    let id = Matrix::identity(k, n);
    l * r == *h0
        && (li * l) == id
        && (r * ri) == id
        && min.a == &(li * h1) * ri
        && min.b == r.submatrix(0, n, 0, min.b.ncols())
        && min.c == l.submatrix(0, min.c.nrows(), 0, n)
}

/// Records the Ho–Kalman factorization.
pub(crate) fn hankel_factor<K: Field>(
    rec: &mut Recorder<'_, K>,
    h: [&Matrix<K>; 2],
    lr: [&Matrix<K>; 2],
    inv: [&Matrix<K>; 2],
    min: &StateSpace<K>,
) {
    let ok = hankel_factor_identity(h, lr, inv, min);
    rec.push(
        StepKind::HankelFactor,
        None,
        vec![
            ("H1", Object::Matrix(h[1].clone())),
            ("L", Object::Matrix(lr[0].clone())),
            ("R", Object::Matrix(lr[1].clone())),
            ("Am", Object::Matrix(min.a.clone())),
            ("Bm", Object::Matrix(min.b.clone())),
            ("Cm", Object::Matrix(min.c.clone())),
        ],
        Some(ok),
    );
}
