//! The transfer matrix step by step (`tf --steps`, issue 27): the steps
//! [`super::StateSpace::transfer_matrix_recorded`] records while it runs (Faddeev–LeVerrier
//! through the Markov parameters), each identity checked exactly:
//!
//! * $\chi(s) = \det(sI - A)$ with $\chi(A) = 0$ (Cayley–Hamilton, up to $n = 40$);
//! * the Markov parameters $h_j = C A^j B$, $j < n$;
//! * the numerators $N(s) = C \operatorname{adj}(sI - A) B$, checked at a point $s_0$ with
//!   $\chi(s_0) \ne 0$: $N(s_0) = \chi(s_0)\, C (s_0 I - A)^{-1} B$ (an independent solve);
//! * the entries in lowest terms, checked by their Laurent coefficients at infinity
//!   (`TransferMatrix::matches_markov`, passed in by the caller).

use super::StateSpace;
use crate::field::Field;
use crate::jordan::derivation::{Object, Recorder, StepKind};
use crate::matrix::Matrix;
use crate::poly::Poly;

/// Largest $n$ for which Cayley–Hamilton is checked (an $n \times n$ polynomial evaluation).
const CAYLEY_MAX: usize = 40;

pub(crate) fn charpoly<K: Field>(rec: &mut Recorder<'_, K>, a: &Matrix<K>, chi: &Poly<K>) {
    crate::jordan::steps::charpoly_step(rec, a, chi, CAYLEY_MAX);
}

pub(crate) fn markov<K: Field>(rec: &mut Recorder<'_, K>, s: &StateSpace<K>, h: &[Matrix<K>]) {
    let k = s.field().clone();
    let mut hh = Matrix::zeros(k, s.noutputs(), 0);
    for m in h {
        hh = hh.hstack(m).unwrap_or(hh);
    }
    rec.push(
        StepKind::Markov,
        None,
        vec![("H", Object::Matrix(hh)), ("n", Object::Count(s.nstates()))],
        None,
    );
}

/// The first $s_0 \in \{0, 1, -1, 2, \dots\}$ with $p(s_0) \ne 0$.
pub fn nonroot<K: Field>(p: &Poly<K>) -> K::Elem {
    let k = p.field();
    let mut s0 = 0i64;
    while k.is_zero(&p.eval(&k.from_i64(s0))) {
        s0 = if s0 > 0 { -s0 } else { 1 - s0 };
    }
    k.from_i64(s0)
}

/// $N(s_0) = \chi(s_0)\, C (s_0 I - A)^{-1} B$ for the numerators `num` (row-major).
pub fn numerators_identity<K: Field>(s: &StateSpace<K>, num: &[Poly<K>], chi: &Poly<K>) -> bool {
    let k = s.field().clone();
    let n = s.nstates();
    let m = s.ninputs();
    if num.len() != s.noutputs() * m {
        return false;
    }
    if n == 0 {
        return num.iter().all(|p| p.is_zero());
    }
    let s0 = nonroot(chi);
    let shifted = Matrix::identity(k.clone(), n).scale(&s0);
    let Ok(Ok(inv)) = shifted.try_sub(&s.a).map(|m| m.inverse()) else {
        return false;
    };
    let g = (&(&s.c * &inv) * &s.b).scale(&chi.eval(&s0));
    (0..num.len()).all(|i| num[i].eval(&s0) == *g.get(i / m, i % m))
}

pub(crate) fn numerators<K: Field>(
    rec: &mut Recorder<'_, K>,
    s: &StateSpace<K>,
    num: &[Vec<Vec<K::Elem>>],
    chi: &Poly<K>,
) {
    let k = s.field().clone();
    let polys: Vec<Poly<K>> = num
        .iter()
        .flat_map(|row| row.iter())
        .map(|c| {
            if s.nstates() == 0 {
                Poly::zero(k.clone())
            } else {
                Poly::new(k.clone(), c.clone())
            }
        })
        .collect();
    let ok = numerators_identity(s, &polys, chi);
    rec.push(
        StepKind::Numerators,
        None,
        vec![
            ("N", Object::Polys(polys)),
            ("chi", Object::Poly(chi.clone())),
            ("p", Object::Count(s.noutputs())),
        ],
        Some(ok),
    );
}

pub(crate) fn entries<K: Field>(
    rec: &mut Recorder<'_, K>,
    s: &StateSpace<K>,
    (num, den): (Vec<Poly<K>>, Vec<Poly<K>>),
    matches_markov: bool,
) {
    rec.push(
        StepKind::TransferEntries,
        None,
        vec![
            ("num", Object::Polys(num)),
            ("den", Object::Polys(den)),
            ("p", Object::Count(s.noutputs())),
        ],
        Some(matches_markov),
    );
}
