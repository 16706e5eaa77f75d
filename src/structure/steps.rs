//! Invariant zeros step by step (`zeros --steps`, issue 27): the steps
//! [`super::zeros::invariant_zeros_recorded`] records while it runs, each with its identity
//! checked exactly:
//!
//! * compression: the pivot columns of $[B; D]$ (rows of $[C, D]$) are independent and as many
//!   as its rank;
//! * the system pencil $P(s) = P_0 - sE$, $P_0 = [A, B; C, D]$, $E = \operatorname{diag}(I_n, 0)$;
//! * the SCB's steps of the compressed system ([`super::scb::steps`]), ending with the zero
//!   dynamics $z(s) = \det(sI - A_{aa})$;
//! * the normal rank $\operatorname{rank} P(s_0)$ at an $s_0$ with $z(s_0) \ne 0$ (identity:
//!   $P(s_0) = P_0 - s_0 E$ and $z(s_0) \ne 0$);
//! * on the fallback path, the diagonal of $P(s)$ and $z = \operatorname{monic}\prod_i d_i$.

use crate::field::Field;
use crate::jordan::derivation::{Object, Recorder, StepKind};
use crate::matrix::Matrix;
use crate::poly::Poly;

/// $P_0 = [A, B; C, D]$ and $E = \operatorname{diag}(I_n, 0)$.
pub fn pencil<K: Field>(abcd: [&Matrix<K>; 4]) -> (Matrix<K>, Matrix<K>) {
    let [a, b, c, d] = abcd;
    let k = a.field().clone();
    let (n, m, p) = (a.nrows(), b.ncols(), c.nrows());
    let p0 = a
        .hstack(b)
        .and_then(|top| top.vstack(&c.hstack(d)?))
        .unwrap_or_else(|_| Matrix::zeros(k.clone(), n + p, n + m));
    let mut e = Matrix::zeros(k.clone(), n + p, n + m);
    for i in 0..n {
        e.set(i, i, k.one());
    }
    (p0, e)
}

pub(crate) fn compress<K: Field>(
    rec: &mut Recorder<'_, K>,
    abcd: [&Matrix<K>; 4],
    cols: &[usize],
    rows: &[usize],
) {
    let [_, b, c, d] = abcd;
    let (bd, cd) = (b.vstack(d), c.hstack(d));
    let (ri, ro) = (
        bd.as_ref().map_or(0, |m| m.rank()),
        cd.as_ref().map_or(0, |m| m.rank()),
    );
    let ok = cols.len() == ri
        && rows.len() == ro
        && bd.is_ok_and(|m| m.select_cols(cols).rank() == ri)
        && cd.is_ok_and(|m| m.select_rows(rows).rank() == ro);
    rec.push(
        StepKind::ZerosCompress,
        None,
        vec![
            ("cols", Object::Counts(cols.to_vec())),
            ("rows", Object::Counts(rows.to_vec())),
            ("rank_in", Object::Count(ri)),
            ("rank_out", Object::Count(ro)),
        ],
        Some(ok),
    );
    let (p0, e) = pencil(abcd);
    rec.push(
        StepKind::SystemPencil,
        None,
        vec![("P0", Object::Matrix(p0)), ("E", Object::Matrix(e))],
        None,
    );
}

pub(crate) fn normal_rank<K: Field>(
    rec: &mut Recorder<'_, K>,
    s0: &K::Elem,
    ps0: &Matrix<K>,
    rank: usize,
    z: &Poly<K>,
) {
    let k = ps0.field();
    let zs0 = z.eval(s0);
    let ok = !k.is_zero(&zs0) && ps0.rank() == rank;
    rec.push(
        StepKind::NormalRank,
        None,
        vec![
            ("s0", Object::Scalar(s0.clone())),
            ("z_s0", Object::Scalar(zs0)),
            ("Ps0", Object::Matrix(ps0.clone())),
            ("rank", Object::Count(rank)),
            ("z", Object::Poly(z.clone())),
        ],
        Some(ok),
    );
}

pub(crate) fn smith<K: Field>(rec: &mut Recorder<'_, K>, diag: &[Poly<K>], z: &Poly<K>) {
    let mut prod = Poly::one(z.field().clone());
    for d in diag {
        prod = prod.mul(d);
    }
    let ok = diag.iter().all(|d| !d.is_zero()) && prod.monic() == *z;
    rec.push(
        StepKind::SmithDiagonal,
        None,
        vec![
            ("diag", Object::Polys(diag.to_vec())),
            ("z", Object::Poly(z.clone())),
        ],
        Some(ok),
    );
}
