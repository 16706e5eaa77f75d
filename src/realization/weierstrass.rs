//! Weierstrass split of a regular descriptor system into its finite and infinite parts.
//!
//! As in [`super::descriptor_to_standard`]: with $\det(\lambda_0E - A) \ne 0$,
//! $M = (\lambda_0E - A)^{-1}$, $\hat E = ME$, the Fitting decomposition of $\hat E$,
//! $x = V_1z_1 + V_2z_2$, gives $\dot z_1 = A_fz_1 + B_fu$ and, with $N$ nilpotent,
//! $(I + sN)z_2 = B_\infty u$, so
//! $$G(s) = C_f(sI - A_f)^{-1}B_f + D + \sum_{k \ge 0} (-s)^k C_\infty N^k B_\infty .$$
//! Here the split is returned whole (improper systems included); the polynomial part is
//! $P(s) = \sum_k P_k s^k$ with $P_0 = D + C_\infty B_\infty$, $P_k = (-1)^kC_\infty N^kB_\infty$.
//!
//! **$E$ invertible** (decided by one inverse, the field's kernel over $\mathbb{Q}(p)$): there
//! is no infinite part and the split is the trivial one, $V_1 = I$, $A_f = E^{-1}A$,
//! $B_f = E^{-1}B$ (no shift $\lambda_0$, no $\hat E^n$: over $\mathbb{Q}(p)$ the powers of
//! $(\lambda_0E - A)^{-1}E$ and the inverse of their column basis are what made the general
//! route slow); its identity is $EA_f = A$, $EB_f = B$. $E = I$ (a standard system read as
//! a descriptor one) takes $A$ and $B$ as they are.

use crate::error::{Error, Result};
use crate::field::Field;
use crate::matrix::Matrix;
use crate::system::{Descriptor, StateSpace};

/// The finite part (a standard system without feedthrough) and the infinite part
/// $(N, B_\infty, C_\infty)$ of a regular descriptor system.
#[derive(Clone, Debug)]
pub struct WeierstrassSplit<K: Field> {
    /// $(A_f, B_f, C_f, 0)$.
    pub finite: StateSpace<K>,
    /// Nilpotent $N$ ($n_\infty \times n_\infty$).
    pub n: Matrix<K>,
    pub b_inf: Matrix<K>,
    pub c_inf: Matrix<K>,
    /// The feedthrough $D$ of the descriptor system.
    pub d: Matrix<K>,
}

impl<K: Field> WeierstrassSplit<K> {
    /// Coefficients $P_0, P_1, \dots, P_q$ of the polynomial part ($P_q \ne 0$ unless $q = 0$).
    pub fn polynomial_part(&self) -> Vec<Matrix<K>> {
        let mut out = vec![&self.d + &(&self.c_inf * &self.b_inf)];
        let mut nb = self.b_inf.clone();
        let mut sign = self.d.field().one();
        for _ in 0..self.n.nrows() {
            nb = &self.n * &nb;
            sign = self.d.field().neg(&sign);
            out.push((&self.c_inf * &nb).scale(&sign));
        }
        while out.len() > 1 && out.last().is_some_and(|p| p.is_zero()) {
            out.pop();
        }
        out
    }
}

/// The pieces of the Fitting split shared by [`weierstrass_split`] and
/// [`super::descriptor_to_standard`]: the shift $\lambda_0$, the bases $V_1$, $V_2$, the
/// finite part $(\lambda_0 I - \hat E_1^{-1}, \hat E_1^{-1}\hat B_1, CV_1)$, the nilpotent
/// $GN$ and $G\hat B_2$ with $G = (I - \lambda_0 N)^{-1}$, and whether $V^{-1}\hat E V$ is
/// block diagonal. For invertible $E$ (module docs): `lambda0` is `None`, $V_1 = I$, $V_2$,
/// $GN$, $G\hat B_2$ empty, and `decoupled` is the identity $EA_f = A$, $EB_f = B$.
///
/// Otherwise `decoupled` checks every identity the split's transfer matrix rests on:
/// $M(\lambda_0E - A) = I$, $V^{-1}V = I$, $V^{-1}\hat EV = \mathrm{diag}(\hat E_1, N)$,
/// $\hat E_1^{-1}\hat E_1 = I$ and $G(I - \lambda_0N) = I$. Then $L = V^{-1}M$ and $V$ are
/// invertible with $L(sE - A)V = \mathrm{diag}(s\hat E_1 - \lambda_0\hat E_1 + I,
/// sN - \lambda_0N + I)$, so $C(sE - A)^{-1}B + D = CV_1(sI - A_f)^{-1}B_f + CV_2(I +
/// sGN)^{-1}G\hat B_2 + D$ exactly: the transfer matrix of the split (finite part plus the
/// descriptor $(GN, -I, G\hat B_2, CV_2, D)$) is the input's, with no expansion of it.
pub(crate) struct FittingSplit<K: Field> {
    pub lambda0: Option<i64>,
    pub v1: Matrix<K>,
    pub v2: Matrix<K>,
    pub a_f: Matrix<K>,
    pub b_f: Matrix<K>,
    pub gn: Matrix<K>,
    pub gb: Matrix<K>,
    pub decoupled: bool,
}

/// Steps 1-4 of [`super::descriptor_to_standard`]'s module docs.
///
/// # Errors
/// `Invalid` when $\det(sE - A) \equiv 0$ (singular pencil).
pub(crate) fn fitting_split<K: Field>(sys: &Descriptor<K>) -> Result<FittingSplit<K>> {
    if let Some(split) = invertible_split(sys) {
        return Ok(split);
    }
    let fld = sys.a.field().clone();
    let n = sys.nstates();
    let mut found = None;
    for t in 0..=n as i64 {
        let l0 = if t % 2 == 1 { (t + 1) / 2 } else { -(t / 2) };
        if let Ok(m) = (&sys.e.scale(&fld.from_i64(l0)) - &sys.a).inverse() {
            found = Some((l0, m));
            break;
        }
    }
    let Some((l0, m)) = found else {
        return Err(Error::Invalid(
            "singular pencil: det(sE - A) is identically zero, the descriptor system has no unique solution".into(),
        ));
    };
    let eh = &m * &sys.e;
    let bh = &m * &sys.b;
    let (v1, v2) = fitting_bases(sys, l0, &eh)?;
    let v = v1.hstack(&v2)?;
    let vi = v.inverse()?;
    let et = &(&vi * &eh) * &v;
    let bt = &vi * &bh;
    let r = v1.ncols();
    let l0e = fld.from_i64(l0);
    let e11 = et.submatrix(0, r, 0, r);
    let e1i = e11.inverse()?;
    let nil = et.submatrix(r, n, r, n);
    let a_f = &Matrix::identity(fld.clone(), r).scale(&l0e) - &e1i;
    let b_f = &e1i * &bt.submatrix(0, r, 0, sys.b.ncols());
    // N z2' = (l0 N - I) z2 + B2 u  <=>  (I + s G N) z2 = G B2 u with G = (I - l0 N)^-1
    let ig = &Matrix::identity(fld.clone(), n - r) - &nil.scale(&l0e);
    let g = ig.inverse()?;
    // the identities the split's transfer matrix rests on (the struct docs): block diagonal
    // V^-1 Eh V, and the four inverses
    let decoupled = et.submatrix(0, r, r, n).is_zero()
        && et.submatrix(r, n, 0, r).is_zero()
        && (&m * &(&sys.e.scale(&l0e) - &sys.a)).is_identity()
        && (&vi * &v).is_identity()
        && (&e1i * &e11).is_identity()
        && (&g * &ig).is_identity();
    Ok(FittingSplit {
        lambda0: Some(l0),
        a_f,
        b_f,
        gn: &g * &nil,
        gb: &g * &bt.submatrix(r, n, 0, sys.b.ncols()),
        v1,
        v2,
        decoupled,
    })
}

/// Bases $V_1$ of $\mathrm{range}\,\hat E^k$ and $V_2$ of $\ker \hat E^k$ for the index $k$
/// of $\hat E$'s nilpotent part (the first $k$ with $\ker \hat E^k = \ker \hat E^{k+1}$; from
/// there on range and kernel stay those of $\hat E^n$), without a power of $\hat E$ (over
/// $\mathbb{Q}(p)$ the entries of $\hat E^n$ are what made the singular-$E$ route run out of
/// memory) and with no elimination on $M = (\lambda_0E - A)^{-1}$:
///
/// * kernels from the input's entries: $\ker \hat E = \ker E$ ($M$ is invertible) and
///   $\ker \hat E^{j+1} = \{x : Ex \in P\ker \hat E^j\}$ with $P = \lambda_0E - A$, i.e. the
///   $x$-part of $\ker\,[E, -PK_j]$ (injective: $PK_jy = 0$ forces $y = 0$);
/// * ranges: $\hat E X = M(EX)$ has the pivot columns of $EX$, so $\mathrm{range}\,\hat E =
///   M\,E_{:,P}$ ($P$ the pivots of $E$) and $R_{j+1} = (\hat ER_j)_{:,P_j}$ ($P_j$ the pivots of
///   $ER_j$), $k - 1$ times.
///
/// Their dimensions add up to $n$ (rank-nullity for $\hat E^k$), checked.
fn fitting_bases<K: Field>(
    sys: &Descriptor<K>,
    l0: i64,
    eh: &Matrix<K>,
) -> Result<(Matrix<K>, Matrix<K>)> {
    let n = sys.nstates();
    let fld = sys.a.field().clone();
    let pencil = &sys.e.scale(&fld.from_i64(l0)) - &sys.a;
    let mut kern = sys.e.nullspace();
    let mut index = 1;
    while kern.ncols() > 0 && kern.ncols() < n {
        let ns = sys.e.hstack(&-&(&pencil * &kern))?.nullspace();
        if ns.ncols() == kern.ncols() {
            break;
        }
        kern = ns.submatrix(0, n, 0, ns.ncols());
        index += 1;
    }
    let mut range = eh.select_cols(&sys.e.pivots());
    for _ in 1..index {
        let piv = (&sys.e * &range).pivots();
        range = (eh * &range).select_cols(&piv);
    }
    if range.ncols() + kern.ncols() != n {
        return Err(Error::Verification(
            "Fitting split: dim range + dim kernel of the shifted E differ from n".into(),
        ));
    }
    Ok((range, kern))
}

/// The trivial split of a system with invertible $E$ (module docs); `None` when $E$ is
/// singular (the general route then runs).
fn invertible_split<K: Field>(sys: &Descriptor<K>) -> Option<FittingSplit<K>> {
    let fld = sys.a.field().clone();
    let (n, m) = (sys.nstates(), sys.b.ncols());
    let (a_f, b_f) = if sys.e.is_identity() {
        (sys.a.clone(), sys.b.clone())
    } else {
        let ei = sys.e.inverse().ok()?;
        (&ei * &sys.a, &ei * &sys.b)
    };
    let decoupled = &sys.e * &a_f == sys.a && &sys.e * &b_f == sys.b;
    Some(FittingSplit {
        lambda0: None,
        v1: Matrix::identity(fld.clone(), n),
        v2: Matrix::zeros(fld.clone(), n, 0),
        a_f,
        b_f,
        gn: Matrix::zeros(fld.clone(), 0, 0),
        gb: Matrix::zeros(fld, 0, m),
        decoupled,
    })
}

/// Splits a regular descriptor system.
///
/// # Errors
/// `Invalid` when $\det(sE - A) \equiv 0$ (singular pencil).
pub fn weierstrass_split<K: Field>(sys: &Descriptor<K>) -> Result<WeierstrassSplit<K>> {
    from_fitting(sys, fitting_split(sys)?)
}

/// The split of `sys` from its Fitting split `f` ([`weierstrass_split`]).
///
/// # Errors
/// As [`weierstrass_split`].
pub(crate) fn from_fitting<K: Field>(
    sys: &Descriptor<K>,
    f: FittingSplit<K>,
) -> Result<WeierstrassSplit<K>> {
    Ok(WeierstrassSplit {
        finite: StateSpace::new_strictly_proper(f.a_f, f.b_f, &sys.c * &f.v1)?,
        n: f.gn,
        b_inf: f.gb,
        c_inf: &sys.c * &f.v2,
        d: sys.d.clone(),
    })
}

/// $G(s_0) = C(s_0E - A)^{-1}B + D$, or `None` when $s_0E - A$ is singular.
pub fn eval_transfer<K: Field>(sys: &Descriptor<K>, s0: &K::Elem) -> Option<Matrix<K>> {
    let p = &sys.e.scale(s0) - &sys.a;
    let x = p.inverse().ok()?;
    Some(&(&(&sys.c * &x) * &sys.b) + &sys.d)
}

/// Do two descriptor systems have the same transfer matrix? Exact, by two expansions:
///
/// * **both $E_i$ invertible**: $D_1 = D_2$ and the Markov parameters
///   $C_i(E_i^{-1}A_i)^kE_i^{-1}B_i$ agree for $k < n_1 + n_2$ (the difference of the
///   strictly proper parts has a realization of order $n_1 + n_2$, so by Cayley-Hamilton its
///   first $n_1 + n_2$ Markov parameters decide all). Products only: no point, no inverse
///   but $E_i^{-1}$ ($E_i = I$: none), and over $\mathbb{Q}(p)$ no condition recorded.
/// * **otherwise**: the Taylor coefficients at a rational $s_0$ where both pencils are
///   regular, $G_i(s_0 + h) = D_i + \sum_k (-h)^k C_i(F_iE_i)^kF_iB_i$ with
///   $F_i = (s_0E_i - A_i)^{-1}$, for $k \le n_1 + n_2$: each entry of $G_i$ is $p_i/d_i$ with
///   $\deg p_i, \deg d_i \le n_i$ and $d_i(s_0) \ne 0$, so the numerator of
///   $(G_1 - G_2)d_1d_2$ has degree $\le n_1 + n_2$ and vanishes to that order at $s_0$: it is
///   zero. One inverse per system (at most $n_1 + n_2 + 2$ values of $s_0$ tried; a singular
///   pencil has none and gives `false`).
pub fn same_transfer<K: Field>(s1: &Descriptor<K>, s2: &Descriptor<K>) -> bool {
    if s1.d.shape() != s2.d.shape() {
        return false;
    }
    let need = s1.nstates() + s2.nstates();
    if let (Some(m1), Some(m2)) = (markov_of(s1, need), markov_of(s2, need)) {
        return s1.d == s2.d && m1 == m2;
    }
    let fld = s1.a.field().clone();
    for t in 0..need as i64 + 2 {
        let s0 = fld.from_rational(&crate::field::Rational::new((2 * t + 1).into(), 7.into()));
        let (Some(g1), Some(g2)) = (moments(s1, &s0, need + 1), moments(s2, &s0, need + 1)) else {
            continue;
        };
        return g1 == g2;
    }
    false
}

/// $C(E^{-1}A)^kE^{-1}B$ for $k < $ `count` when $E$ is invertible, else `None`.
fn markov_of<K: Field>(sys: &Descriptor<K>, count: usize) -> Option<Vec<Matrix<K>>> {
    let (a, b) = if sys.e.is_identity() {
        (sys.a.clone(), sys.b.clone())
    } else {
        let ei = sys.e.inverse().ok()?;
        (&ei * &sys.a, &ei * &sys.b)
    };
    let ss = StateSpace::new_strictly_proper(a, b, sys.c.clone()).ok()?;
    Some(ss.markov(count))
}

/// $G(s_0)$ and $C(FE)^kFB$, $k = 1..$ `count` $- 1$, with $F = (s_0E - A)^{-1}$; `None`
/// when $s_0E - A$ is singular.
fn moments<K: Field>(sys: &Descriptor<K>, s0: &K::Elem, count: usize) -> Option<Vec<Matrix<K>>> {
    let f = (&sys.e.scale(s0) - &sys.a).inverse().ok()?;
    let w = &f * &sys.e;
    let mut x = &f * &sys.b;
    let mut out = vec![&(&sys.c * &x) + &sys.d];
    for _ in 1..count {
        x = &w * &x;
        out.push(&sys.c * &x);
    }
    Some(out)
}

/// The exact transfer matrix of a regular descriptor system (improper included):
/// $C_f(sI - A_f)^{-1}B_f$ plus the polynomial part, each entry in lowest terms.
///
/// # Errors
/// `Invalid` for a singular pencil.
pub fn descriptor_transfer_matrix<K: Field>(
    sys: &Descriptor<K>,
) -> Result<crate::system::transfer::TransferMatrix<K>> {
    use crate::poly::Poly;
    use crate::system::transfer::RationalFunction;
    let split = weierstrass_split(sys)?;
    let fin = split.finite.transfer_matrix()?;
    let poly = split.polynomial_part();
    let fld = sys.a.field().clone();
    let entries = fin
        .entries
        .iter()
        .enumerate()
        .map(|(i, row)| {
            row.iter()
                .enumerate()
                .map(|(j, f)| {
                    let cs: Vec<K::Elem> = poly.iter().map(|pk| pk.get(i, j).clone()).collect();
                    let pp = Poly::new(fld.clone(), cs);
                    RationalFunction::new(f.num.add(&pp.mul(&f.den)), f.den.clone())
                })
                .collect()
        })
        .collect();
    Ok(crate::system::transfer::TransferMatrix { entries })
}
