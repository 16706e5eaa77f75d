//! The SCB step by step (`scb --steps`, issue 27): what the algorithm records through its
//! [`Recorder`] while it runs (SCB paper sec. III), each step with the identity it establishes,
//! checked exactly from the recorded objects:
//!
//! * pre-transformation: $Y^{-1} D U = \operatorname{diag}(I_{m_0}, 0)$;
//! * $\bar S_i$: $[S_{ib}, S_{i2}]\,[\bar D_{i-1}; C_i \hat B] = 0$, of full row rank and as many
//!   rows as the left null space has dimensions; the ending chains are the rows of $I_{p_i}$
//!   that are not leading ones of $\mathrm{rref}(S_{i2})$ (the paper's deletion rule);
//! * $\bar\phi_i$: $\Phi\,[\text{rows found}; \bar C_i] = 0$, likewise;
//! * $x_s$: $T_s \hat B \Gamma_3$ has no $u_d$ columns and $T_s \hat A - X T_s$ lies in the row
//!   space of $\hat C$ (the derivative of $x_s$ depends on $x_s$, the outputs and $u_c$ only);
//! * the Kalman split: $P = [T_2, T_1]$ invertible, $P^{-1} X P$ block triangular and
//!   $P^{-1} B_{sc}$ zero in the $x_a$ rows;
//! * the SCB: every identity and pattern of eq. (4)-(6) ([`super::Scb::check`]);
//! * zero dynamics: $z(s) = \det(sI - A_{aa})$, $z(A_{aa}) = 0$.

use super::Scb;
use crate::field::Field;
use crate::jordan::derivation::{Object, Recorder, StepKind};
use crate::matrix::Matrix;

/// The columns of `m` that are not pivots of its RREF (the paper's leading-one deletion rule).
fn non_leading<K: Field>(m: &Matrix<K>) -> Vec<usize> {
    let (_, piv) = m.rref();
    (0..m.ncols()).filter(|c| !piv.contains(c)).collect()
}

/// An optional recorder (the algorithm runs the same with `None`).
pub(crate) type Rec<'r, 'a, K> = Option<&'r mut Recorder<'a, K>>;

/// `s` is a basis of the left null space of `m`: `s m = 0`, independent rows, as many as
/// `m.nrows() - rank m`.
pub fn is_left_null_basis<K: Field>(s: &Matrix<K>, m: &Matrix<K>) -> bool {
    s.ncols() == m.nrows()
        && (s * m).is_zero()
        && s.rank() == s.nrows()
        && s.nrows() == m.nrows() - m.rank()
}

pub(crate) fn pre_transform<K: Field>(
    rec: &mut Recorder<'_, K>,
    pre: (&Matrix<K>, &Matrix<K>, usize),
    d: &Matrix<K>,
    strict: [&Matrix<K>; 3],
) {
    let (u, yinv, m0) = pre;
    let k = d.field().clone();
    let dh = &(yinv * d) * u;
    let mut want = Matrix::zeros(k.clone(), d.nrows(), d.ncols());
    for i in 0..m0 {
        want.set(i, i, k.one());
    }
    let ok = dh == want;
    rec.push(
        StepKind::ScbPreTransform,
        None,
        vec![
            ("U", Object::Matrix(u.clone())),
            ("Yinv", Object::Matrix(yinv.clone())),
            ("Dh", Object::Matrix(dh)),
            ("m0", Object::Count(m0)),
            ("A1", Object::Matrix(strict[0].clone())),
            ("B1", Object::Matrix(strict[1].clone())),
            ("C1", Object::Matrix(strict[2].clone())),
        ],
        Some(ok),
    );
}

/// Step $\bar S_i$ (module docs); `Bottoms` are the bottom rows of the chains ended so far
/// ($\bar D_{i-1} = \text{Bottoms}\,\hat B$).
pub(crate) fn silverman_s<K: Field>(
    rec: &mut Recorder<'_, K>,
    (level, ended): (usize, &[Matrix<K>]),
    ci: &Matrix<K>,
    m: &Matrix<K>,
    s: &Matrix<K>,
    ending: &[usize],
) {
    let qbar = m.nrows() - ci.nrows();
    let s2 = s.submatrix(0, s.nrows(), qbar, s.ncols());
    let ok = is_left_null_basis(s, m) && ending == non_leading(&s2);
    let mut bottoms = Matrix::zeros(m.field().clone(), 0, ci.ncols());
    for ch in ended {
        bottoms = bottoms
            .vstack(&ch.select_rows(&[ch.nrows() - 1]))
            .unwrap_or(bottoms);
    }
    rec.push(
        StepKind::SilvermanS,
        Some(level - 1),
        vec![
            ("level", Object::Count(level)),
            ("Ci", Object::Matrix(ci.clone())),
            ("Bottoms", Object::Matrix(bottoms)),
            ("M", Object::Matrix(m.clone())),
            ("S", Object::Matrix(s.clone())),
            ("ending", Object::Counts(ending.to_vec())),
        ],
        Some(ok),
    );
}

/// Step $\bar\phi_i$ (module docs).
pub(crate) fn silverman_phi<K: Field>(
    rec: &mut Recorder<'_, K>,
    level: usize,
    rows: &Matrix<K>,
    cbar: &Matrix<K>,
    phi: &Matrix<K>,
    going_on: &[usize],
) {
    let ok = rows.vstack(cbar).is_ok_and(|m| is_left_null_basis(phi, &m))
        && going_on == non_leading(&phi.submatrix(0, phi.nrows(), rows.nrows(), phi.ncols()));
    rec.push(
        StepKind::SilvermanPhi,
        Some(level - 1),
        vec![
            ("level", Object::Count(level)),
            ("Rows", Object::Matrix(rows.clone())),
            ("Cbar", Object::Matrix(cbar.clone())),
            ("Phi", Object::Matrix(phi.clone())),
            ("going_on", Object::Counts(going_on.to_vec())),
        ],
        Some(ok),
    );
}

/// The identity of the $x_s$ step: $T_s \hat B \Gamma_3$ zero in the first `md` columns and
/// $T_s \hat A - X T_s$ in the row space of $\hat C$.
pub fn states_identity<K: Field>(
    abc: [&Matrix<K>; 3],
    ts: &Matrix<K>,
    x: &Matrix<K>,
    g3: &Matrix<K>,
    md: usize,
) -> bool {
    let [a, b, c] = abc;
    let tb = &(ts * b) * g3;
    let no_ud = tb.submatrix(0, tb.nrows(), 0, md).is_zero();
    let rest = &(ts * a) - &(x * ts);
    no_ud && c.vstack(&rest).is_ok_and(|s| s.rank() == c.rank())
}

pub(crate) fn states<K: Field>(
    rec: &mut Recorder<'_, K>,
    abc: [&Matrix<K>; 3],
    ts: [&Matrix<K>; 2],
    x: &Matrix<K>,
    g3: &Matrix<K>,
    md: usize,
) {
    let [ts0, ts] = ts;
    let ok = states_identity(abc, ts, x, g3, md);
    rec.push(
        StepKind::ScbStates,
        None,
        vec![
            ("Ts0", Object::Matrix(ts0.clone())),
            ("Ts", Object::Matrix(ts.clone())),
            ("X", Object::Matrix(x.clone())),
            ("G3", Object::Matrix(g3.clone())),
            ("md", Object::Count(md)),
        ],
        Some(ok),
    );
}

/// The identity of the Kalman split: $P$ invertible, $(P^{-1} X P)_{ac} = 0$,
/// $(P^{-1} B_{sc})_a = 0$.
pub fn split_identity<K: Field>(x: &Matrix<K>, bsc: &Matrix<K>, p: &Matrix<K>, na: usize) -> bool {
    let ns = x.nrows();
    let Ok(pinv) = p.inverse() else {
        return false;
    };
    let xt = &(&pinv * x) * p;
    let bt = &pinv * bsc;
    xt.submatrix(0, na, na, ns).is_zero() && bt.submatrix(0, na, 0, bt.ncols()).is_zero()
}

pub(crate) fn kalman_split<K: Field>(
    rec: &mut Recorder<'_, K>,
    x: &Matrix<K>,
    bsc: &Matrix<K>,
    ctr: &Matrix<K>,
    p: &Matrix<K>,
    na: usize,
) {
    let ok = split_identity(x, bsc, p, na);
    rec.push(
        StepKind::ScbKalmanSplit,
        None,
        vec![
            ("Bsc", Object::Matrix(bsc.clone())),
            ("Ctr", Object::Matrix(ctr.clone())),
            ("rank", Object::Count(ctr.rank())),
            ("P", Object::Matrix(p.clone())),
            ("na", Object::Count(na)),
        ],
        Some(ok),
    );
}

/// The SCB itself and its zero dynamics.
pub(crate) fn form<K: Field>(rec: &mut Recorder<'_, K>, s: &Scb<K>) {
    let ok = s.check().is_ok();
    rec.push(
        StepKind::ScbForm,
        None,
        vec![
            ("A", Object::Matrix(s.a.clone())),
            ("B", Object::Matrix(s.b.clone())),
            ("C", Object::Matrix(s.c.clone())),
            ("D", Object::Matrix(s.d.clone())),
            ("Gamma1", Object::Matrix(s.gamma1.clone())),
            ("Gamma2", Object::Matrix(s.gamma2.clone())),
            ("Gamma3", Object::Matrix(s.gamma3.clone())),
            ("dims", Object::Counts(s.dims.to_vec())),
            ("chains", Object::Counts(s.chains.clone())),
            ("m0", Object::Count(s.m0)),
        ],
        Some(ok),
    );
    let aaa = s.a_aa();
    let z = s.invariant_zero_polynomial();
    let ok = z.deg() == aaa.nrows() && aaa.eval_poly(&z).is_ok_and(|m| m.is_zero());
    rec.push(
        StepKind::ZeroDynamics,
        None,
        vec![("Aaa", Object::Matrix(aaa)), ("z", Object::Poly(z))],
        Some(ok),
    );
}
