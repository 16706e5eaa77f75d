//! Special coordinate basis (SCB), exactly.
//!
//! For $\dot{\tilde x} = \hat A \tilde x + \tilde B \tilde u$, $\tilde y = \tilde C \tilde x + \tilde D \tilde u$
//! with $[\tilde B; \tilde D]$ of full column rank and $[\tilde C, \tilde D]$ of full row rank,
//! [`scb`] returns pre-transformations $U$, $Y$ (sec. II-D: $\hat B = \tilde B U$,
//! $\hat C = Y^{-1} \tilde C$, $\hat D = Y^{-1}\tilde D U = \mathrm{diag}(I_{m_0}, 0)$) and
//! $\hat x = \Gamma_1 x$, $\hat y = \Gamma_2 y$, $\hat u = \Gamma_3 u$ such that (Grip–Saberi
//! sec. II-C)
//! $$A = \Gamma_1^{-1}(\hat A - B_0 C_0)\Gamma_1,\quad B = \Gamma_1^{-1}\hat B\Gamma_3,\quad
//! C = \Gamma_2^{-1}\hat C\Gamma_1,\quad D = \Gamma_2^{-1}\hat D\Gamma_3$$
//! have the compact form of eq. (6): $x = (x_a, x_b, x_c, x_d)$, $y = (y_0, y_d, y_b)$,
//! $u = (u_0, u_d, u_c)$, $x_d$ made of integrator chains of lengths $q_i$ (the infinite zero
//! structure), $(A_{bb}, C_b)$ observable, $(A_{cc}, B_c)$ controllable. The invariant zeros
//! are the eigenvalues of $A_{aa}$; the system is left invertible iff $x_c$ is empty and
//! right invertible iff $x_b$ is empty (sec. II-E).
//!
//! | entry point | computes |
//! |---|---|
//! | [`scb`] | the SCB by the modified Silverman iterations (sec. III) |
//! | [`Scb::verify`] | every identity and zero/identity pattern of eq. (4)–(6), exactly |
//! | [`Scb::invariant_zero_polynomial`] | $\det(sI - A_{aa})$ |
//! | [`Scb::minimum_phase`] | Routh–Hurwitz on that polynomial, exact (real fields) |
//! | [`Scb::match_x_c`] | sec. VI's extra step: $A_{ca} = B_c E_{ca}$ |
//!
//! Deterministic: every basis is canonical (RREF) and every complement is chosen by the
//! leading-one deletion rule, so the same input always gives the same output.

mod extension;
mod nonstrict;
mod silverman;
mod split;
pub(crate) mod steps;
mod verify;

pub use verify::{Pattern, check_pattern};

use crate::error::{Error, Result};
use crate::field::Field;
use crate::matrix::Matrix;
use crate::poly::Poly;

/// An SCB of a system together with its transformations.
#[derive(Clone, Debug)]
pub struct Scb<K: Field> {
    /// SCB system matrices (compact form of eq. 6).
    pub a: Matrix<K>,
    pub b: Matrix<K>,
    pub c: Matrix<K>,
    pub d: Matrix<K>,
    /// $\hat x = \Gamma_1 x$.
    pub gamma1: Matrix<K>,
    /// $\hat y = \Gamma_2 y$.
    pub gamma2: Matrix<K>,
    /// $\hat u = \Gamma_3 u$.
    pub gamma3: Matrix<K>,
    /// $\tilde u = U \hat u$.
    pub u_pre: Matrix<K>,
    /// $\tilde y = Y \hat y$.
    pub y_pre: Matrix<K>,
    /// $(n_a, n_b, n_c, n_d)$.
    pub dims: [usize; 4],
    /// Lengths $q_i$ of the integrator chains of $x_d$, in state order.
    pub chains: Vec<usize>,
    /// $m_0 = \mathrm{rank}\,\tilde D$.
    pub m0: usize,
    pub left_invertible: bool,
    pub right_invertible: bool,
    /// True when [`Scb::verify`] passed (checked at construction).
    pub verified: bool,
    /// The system as given.
    pub orig: [Matrix<K>; 4],
    /// $\det(sI - A_{aa})$, once computed.
    zero_poly: std::sync::OnceLock<Poly<K>>,
}

/// Special coordinate basis of $(A, B, C, D)$.
///
/// # Algorithm
/// Grip–Saberi sec. III: pre-transformation (III-C), modified Silverman iterations with
/// canonical left null spaces (III-A), elimination of $u_d$ from $x_s$ and Kalman split
/// (III-B). $O(n^4)$ field operations in the worst case.
///
/// # Errors
/// `Shape`/`NotSquare` for inconsistent shapes; `Invalid` when $[B; D]$ is not of full column
/// rank or $[C, D]$ not of full row rank (remove the redundant inputs/outputs first, as the
/// paper's sec. II assumes); `Verification` if the exact check fails (an internal error).
///
/// # Examples
/// ```
/// use exactlti::qmat;
/// use exactlti::structure::scb::scb;
/// // double integrator with position output: one chain of length 2
/// let s = scb(&qmat![[0, 1], [0, 0]], &qmat![[0], [1]], &qmat![[1, 0]], &qmat![[0]]).unwrap();
/// assert_eq!(s.dims, [0, 0, 0, 2]);
/// assert_eq!(s.chains, vec![2]);
/// assert!(s.verified);
/// ```
pub fn scb<K: Field>(a: &Matrix<K>, b: &Matrix<K>, c: &Matrix<K>, d: &Matrix<K>) -> Result<Scb<K>> {
    scb_recorded(a, b, c, d, None)
}

/// [`scb`], recording its steps (SCB paper sec. III) into `rec` ([`steps`]): the
/// pre-transformation, every $\bar S_i$ and $\bar\phi_i$, the states $x_s$, the Kalman split,
/// the SCB and its zero dynamics.
///
/// # Errors
/// As [`scb`].
pub fn scb_recorded<K: Field>(
    a: &Matrix<K>,
    b: &Matrix<K>,
    c: &Matrix<K>,
    d: &Matrix<K>,
    mut rec: steps::Rec<'_, '_, K>,
) -> Result<Scb<K>> {
    check_shapes(a, b, c, d)?;
    let k = a.field().clone();
    let (n, m, p) = (a.nrows(), b.ncols(), c.nrows());
    if b.vstack(d)?.rank() < m {
        return Err(Error::Invalid(format!(
            "scb: [B; D] has rank {} < {m} inputs: remove the redundant inputs (the SCB assumes [B; D] of full column rank)",
            b.vstack(d)?.rank()
        )));
    }
    if c.hstack(d)?.rank() < p {
        return Err(Error::Invalid(format!(
            "scb: [C, D] has rank {} < {p} outputs: remove the redundant outputs (the SCB assumes [C, D] of full row rank)",
            c.hstack(d)?.rank()
        )));
    }
    let pre = nonstrict::pre_transform(d)?;
    let m0 = pre.m0;
    let bh = b * &pre.u;
    let ch = &pre.yinv * c;
    let b0 = bh.submatrix(0, n, 0, m0);
    let c0 = ch.submatrix(0, m0, 0, n);
    let a1 = a - &(&b0 * &c0);
    let b1 = bh.submatrix(0, n, m0, m);
    let c1 = ch.submatrix(m0, p, 0, n);
    if let Some(r) = rec.as_deref_mut() {
        steps::pre_transform(r, (&pre.u, &pre.yinv, m0), d, [&a1, &b1, &c1]);
    }
    let sp = split::strictly_proper(&a1, &b1, &c1, rec.as_deref_mut())?;
    let gamma1 = sp.t.inverse()?;
    let id0 = Matrix::identity(k.clone(), m0);
    let gamma2 = Matrix::block_diag(k.clone(), &[id0.clone(), sp.g2inv.inverse()?]);
    let gamma3 = Matrix::block_diag(k.clone(), &[id0, sp.g3.clone()]);
    let g2inv = Matrix::block_diag(k.clone(), &[Matrix::identity(k.clone(), m0), sp.g2inv]);
    let dh = &(&pre.yinv * d) * &pre.u;
    let mut s = Scb {
        a: &(&sp.t * &a1) * &gamma1,
        b: &(&sp.t * &bh) * &gamma3,
        c: &(&g2inv * &ch) * &gamma1,
        d: &(&g2inv * &dh) * &gamma3,
        gamma1,
        gamma2,
        gamma3,
        u_pre: pre.u,
        y_pre: pre.y,
        dims: sp.dims,
        chains: sp.chains,
        m0,
        left_invertible: sp.dims[2] == 0,
        right_invertible: sp.dims[1] == 0,
        verified: false,
        orig: [a.clone(), b.clone(), c.clone(), d.clone()],
        zero_poly: std::sync::OnceLock::new(),
    };
    s.check()?;
    s.verified = true;
    if let Some(r) = rec {
        steps::form(r, &s);
    }
    Ok(s)
}

fn check_shapes<K: Field>(
    a: &Matrix<K>,
    b: &Matrix<K>,
    c: &Matrix<K>,
    d: &Matrix<K>,
) -> Result<()> {
    a.check_square("scb")?;
    let n = a.nrows();
    b.check_shape("scb (B)", (n, b.ncols()))?;
    c.check_shape("scb (C)", (c.nrows(), n))?;
    d.check_shape("scb (D)", (c.nrows(), b.ncols()))?;
    if b.field() != a.field() || c.field() != a.field() || d.field() != a.field() {
        return Err(Error::FieldMismatch);
    }
    Ok(())
}

impl<K: Field> Scb<K> {
    /// Number of states.
    pub fn nstates(&self) -> usize {
        self.a.nrows()
    }
    /// State index ranges of $x_a, x_b, x_c, x_d$.
    pub fn ranges(&self) -> [std::ops::Range<usize>; 4] {
        let [na, nb, nc, nd] = self.dims;
        [
            0..na,
            na..na + nb,
            na + nb..na + nb + nc,
            na + nb + nc..na + nb + nc + nd,
        ]
    }
    /// $A_{aa}$ (zero dynamics).
    pub fn a_aa(&self) -> Matrix<K> {
        let na = self.dims[0];
        self.a.submatrix(0, na, 0, na)
    }
    /// The invariant zero polynomial $\det(sI - A_{aa})$ (monic; `1` when there are no
    /// finite invariant zeros).
    pub fn invariant_zero_polynomial(&self) -> Poly<K> {
        self.zero_poly
            .get_or_init(|| self.a_aa().charpoly().expect("A_aa is square"))
            .clone()
    }
    /// Minimum phase (all invariant zeros in the open left half plane), decided exactly by
    /// the Routh–Hurwitz test; `None` when the field is not real (no exact sign).
    pub fn minimum_phase(&self) -> Option<bool> {
        hurwitz(&self.invariant_zero_polynomial())
    }
    /// Exact check of every identity of sec. II-C and the pattern of eq. (4)–(6).
    pub fn verify(&self) -> bool {
        self.check().is_ok()
    }
    /// As [`Scb::verify`], naming the first identity that fails.
    ///
    /// # Errors
    /// `Verification` with the failed condition.
    pub fn check(&self) -> Result<()> {
        verify::check(self)
    }
}

/// Routh–Hurwitz: are all roots of `p` in the open left half plane? `None` when the field
/// has no exact sign for an entry it needs (over $\mathbb{Q}(p)$: a sign that depends on the
/// parameters). The constant polynomial counts as Hurwitz (no roots). A coefficient that is
/// zero, or two of opposite signs, decide `false` first (necessary condition).
///
/// A polynomial with positive leading coefficient is Hurwitz iff every entry of the first
/// column of its Routh array is positive; a zero entry means it is not.
pub fn hurwitz<K: Field>(p: &Poly<K>) -> Option<bool> {
    let k = p.field();
    let n = p.degree()?;
    if n == 0 {
        return Some(true);
    }
    // necessary: every coefficient nonzero, all of one sign (decided where the field can)
    let signs: Vec<Option<std::cmp::Ordering>> = (0..=n).map(|i| k.sign(&p.coeff(i))).collect();
    if signs.contains(&Some(std::cmp::Ordering::Equal))
        || (signs.contains(&Some(std::cmp::Ordering::Less))
            && signs.contains(&Some(std::cmp::Ordering::Greater)))
    {
        return Some(false);
    }
    let lc = p.lc();
    let neg = k.sign(&lc)? == std::cmp::Ordering::Less;
    let cs: Vec<K::Elem> = (0..=n)
        .rev()
        .map(|i| if neg { k.neg(&p.coeff(i)) } else { p.coeff(i) })
        .collect();
    let mut r0: Vec<K::Elem> = cs.iter().step_by(2).cloned().collect();
    let mut r1: Vec<K::Elem> = cs.iter().skip(1).step_by(2).cloned().collect();
    for _ in 0..n {
        let h = r1.first().cloned().unwrap_or_else(|| k.zero());
        if k.sign(&h)? != std::cmp::Ordering::Greater {
            return Some(false);
        }
        let mut r2 = Vec::with_capacity(r0.len());
        for j in 0..r0.len().saturating_sub(1) {
            let a = k.mul(&h, &r0[j + 1]);
            let b = k.mul(&r0[0], r1.get(j + 1).unwrap_or(&k.zero()));
            r2.push(k.div(&k.sub(&a, &b), &h).expect("h non-zero"));
        }
        r0 = std::mem::replace(&mut r1, r2);
        if r1.is_empty() {
            break;
        }
    }
    // also the first entry of every remaining row (the last row is the constant term)
    Some(
        r0.first()
            .is_none_or(|x| k.sign(x) == Some(std::cmp::Ordering::Greater)),
    )
}
