//! Exact minimal realization of a transfer matrix given as rational functions.
//!
//! Each entry $g_{ij} = n/d$ ($d$ monic) splits as $q + r/d$ (division with remainder).
//! $r/d$ gets a controllable companion realization, the polynomial $q(s) = \sum_k q_ks^k$ a
//! nilpotent chain ($E = $ shift, $A = I$, $C(sE - A)^{-1}B = -\sum_k s^kCE^kB$); the
//! blocks are stacked into one descriptor system and reduced by
//! [`super::minimal_descriptor`]. For a proper $G$ the result is a standard state-space
//! system of order = McMillan degree.
//!
//! # Verification
//! The realization evaluated exactly at rational points ($C(s_0E - A)^{-1}B + D$) equals
//! $G(s_0)$ at more points than the degree of any entry of the difference, so the transfer
//! matrices are equal; plus the checks of [`super::minimal_descriptor`].

use super::descriptor_minimal::{DescriptorMinimal, minimal_descriptor};
use super::weierstrass::eval_transfer;
use crate::error::{Error, Result};
use crate::field::{Field, Rational};
use crate::matrix::Matrix;
use crate::system::transfer::TransferMatrix;
use crate::system::{Descriptor, StateSpace};

/// A minimal realization of a transfer matrix.
#[derive(Clone, Debug)]
pub struct TransferRealization<K: Field> {
    /// The minimal descriptor realization (with $E = I$ when $G$ is proper).
    pub minimal: DescriptorMinimal<K>,
    /// The standard realization when $G$ is proper.
    pub state_space: Option<StateSpace<K>>,
    /// McMillan degree: finite poles plus the orders of the poles at infinity.
    pub mcmillan_degree: usize,
    /// Realization equals $G$ at enough points, and the minimality checks held.
    pub verified: bool,
}

/// Realizes $G$ exactly and minimally.
///
/// # Errors
/// `Invalid` for an empty matrix with inconsistent rows or a zero denominator.
pub fn realize_transfer<K: Field>(g: &TransferMatrix<K>) -> Result<TransferRealization<K>> {
    let p = g.entries.len();
    let m = g.entries.first().map_or(0, |r| r.len());
    if g.entries.iter().any(|r| r.len() != m) {
        return Err(Error::Invalid(
            "transfer matrix rows differ in length".into(),
        ));
    }
    let fld = match g.entries.first().and_then(|r| r.first()) {
        Some(f) => f.num.field().clone(),
        None => return Err(Error::Invalid("empty transfer matrix".into())),
    };
    if p == 1
        && m == 1
        && let Some(r) = siso_companion(g, &fld)?
    {
        return Ok(r);
    }
    let big = stacked(g, &fld, p, m)?;
    let minimal = minimal_descriptor(&big)?;
    let sys = &minimal.system;
    let state_space = (minimal.infinite_order == 0).then(|| {
        StateSpace::new(sys.a.clone(), sys.b.clone(), sys.c.clone(), sys.d.clone())
            .expect("shapes of a descriptor system")
    });
    let mcmillan_degree = minimal.finite_order + infinite_pole_degree(&minimal);
    let verified = minimal.verified && equals_at_points(g, sys, &fld);
    Ok(TransferRealization {
        minimal,
        state_space,
        mcmillan_degree,
        verified,
    })
}

/// The minimal realization of the transfer matrix `g` of the state-space system `s`, from
/// `s` itself (Kalman: [`super::minimal_kalman`]) instead of from `g`'s entries: realizing
/// entry by entry stacks one companion block per entry and reduces the stack as a descriptor
/// system, which is slow when the coefficients are large (a 4-state system with one entry
/// $10^{300}$ ran for minutes).
///
/// `verified`: the Kalman checks held, and the Markov parameters of `g` equal those of `s`
/// and of the minimal system ([`TransferMatrix::matches_markov`]).
///
/// # Errors
/// Those of [`super::minimal_kalman`].
pub fn realize_state_space<K: Field>(
    s: &StateSpace<K>,
    g: &TransferMatrix<K>,
) -> Result<TransferRealization<K>> {
    let min = super::minimal_kalman(s)?;
    let m = &min.system;
    let k = m.a.field().clone();
    let n = m.a.nrows();
    let system = Descriptor::new(
        Matrix::identity(k, n),
        m.a.clone(),
        m.b.clone(),
        m.c.clone(),
        m.d.clone(),
    )?;
    let verified = min.verified && g.matches_markov(s) && g.matches_markov(m);
    Ok(TransferRealization {
        minimal: DescriptorMinimal {
            system,
            order: min.order,
            finite_order: min.order,
            infinite_order: 0,
            irreducible_order: min.order,
            original_order: min.original_order,
            polynomial_degree: 0,
            verified: min.verified,
        },
        state_space: Some(m.clone()),
        mcmillan_degree: min.order,
        verified,
    })
}

/// A proper SISO $G = n/d$ with $\gcd(n, d) = 1$: the controllable companion realization of
/// $n/d$ is minimal as it stands (the companion pair is controllable; it is observable
/// exactly when $n$ and $d$ are coprime), so it is returned without the descriptor reduction
/// (degree 60: 0.01 s instead of a minute). `verified`: coprimality checked exactly and the
/// Markov parameters equal those of $G$ up to $2n$ ([`TransferMatrix::matches_markov`]).
/// `None` when $G$ is improper or $n/d$ is not in lowest terms (the general path).
fn siso_companion<K: Field>(
    g: &TransferMatrix<K>,
    fld: &K,
) -> Result<Option<TransferRealization<K>>> {
    let f = &g.entries[0][0];
    if f.den.is_zero() || (!f.num.is_zero() && f.num.deg() > f.den.deg()) {
        return Ok(None);
    }
    let coprime = f.num.is_zero() || f.num.gcd(&f.den).is_constant();
    if !coprime {
        return Ok(None);
    }
    let sys = stacked(g, fld, 1, 1)?;
    let n = sys.nstates();
    let ss = StateSpace::new(sys.a.clone(), sys.b.clone(), sys.c.clone(), sys.d.clone())?;
    let verified = g.matches_markov(&ss);
    Ok(Some(TransferRealization {
        minimal: DescriptorMinimal {
            system: sys,
            order: n,
            finite_order: n,
            infinite_order: 0,
            irreducible_order: n,
            original_order: n,
            polynomial_degree: 0,
            verified,
        },
        state_space: Some(ss),
        mcmillan_degree: n,
        verified,
    }))
}

/// One entry's block: (E, A, b column, c row, input j, output i).
type Block<K> = (
    Matrix<K>,
    Matrix<K>,
    Vec<<K as Field>::Elem>,
    Vec<<K as Field>::Elem>,
    usize,
    usize,
);

/// The non-minimal stacked realization of every entry.
fn stacked<K: Field>(g: &TransferMatrix<K>, fld: &K, p: usize, m: usize) -> Result<Descriptor<K>> {
    let mut d = Matrix::zeros(fld.clone(), p, m);
    // per block: (E, A, b column, c row, input j, output i)
    let mut blocks: Vec<Block<K>> = Vec::new();
    for (i, row) in g.entries.iter().enumerate() {
        for (j, f) in row.iter().enumerate() {
            if f.den.is_zero() {
                return Err(Error::Invalid(
                    "zero denominator in the transfer matrix".into(),
                ));
            }
            let (q, r) = f.num.divrem(&f.den)?;
            let dn = f.den.deg();
            let lc = f.den.lc();
            if dn > 0 && !r.is_zero() {
                let a = Matrix::from_fn(fld.clone(), dn, dn, |a, b| {
                    if a + 1 == dn {
                        fld.neg(&fld.div(&f.den.coeff(b), &lc).expect("lc"))
                    } else if b == a + 1 {
                        fld.one()
                    } else {
                        fld.zero()
                    }
                });
                let mut bcol = vec![fld.zero(); dn];
                bcol[dn - 1] = fld.one();
                let crow: Vec<K::Elem> = (0..dn)
                    .map(|k| fld.div(&r.coeff(k), &lc).expect("lc"))
                    .collect();
                blocks.push((Matrix::identity(fld.clone(), dn), a, bcol, crow, j, i));
            }
            d.set(i, j, q.coeff(0));
            if q.deg() >= 1 {
                let l = q.deg() + 1;
                let e = Matrix::from_fn(fld.clone(), l, l, |a, b| {
                    if b == a + 1 { fld.one() } else { fld.zero() }
                });
                let mut bcol = vec![fld.zero(); l];
                bcol[l - 1] = fld.one();
                let mut crow = vec![fld.zero(); l];
                for k in 1..l {
                    crow[l - 1 - k] = fld.neg(&q.coeff(k));
                }
                blocks.push((e, Matrix::identity(fld.clone(), l), bcol, crow, j, i));
            }
        }
    }
    let n: usize = blocks.iter().map(|b| b.0.nrows()).sum();
    let mut e = Matrix::zeros(fld.clone(), n, n);
    let mut a = Matrix::zeros(fld.clone(), n, n);
    let mut b = Matrix::zeros(fld.clone(), n, m);
    let mut c = Matrix::zeros(fld.clone(), p, n);
    let mut off = 0;
    for (be, ba, bcol, crow, j, i) in blocks {
        let k = be.nrows();
        e.set_block(off, off, &be);
        a.set_block(off, off, &ba);
        for t in 0..k {
            b.set(off + t, j, bcol[t].clone());
            c.set(i, off + t, crow[t].clone());
        }
        off += k;
    }
    Descriptor::new(e, a, b, c, d)
}

/// $\sum \mu_i$ over the poles at infinity: the rank of the block Hankel matrix of
/// $P_1, \dots, P_q$ (the McMillan degree of $P(1/z) - P_0$).
fn infinite_pole_degree<K: Field>(min: &DescriptorMinimal<K>) -> usize {
    let Ok(split) = super::weierstrass::weierstrass_split(&min.system) else {
        return 0;
    };
    let poly = split.polynomial_part();
    let q = poly.len() - 1;
    if q == 0 {
        return 0;
    }
    let (p, m) = poly[0].shape();
    let fld = poly[0].field().clone();
    let mut h = Matrix::zeros(fld, q * p, q * m);
    for i in 0..q {
        for j in 0..q - i {
            h.set_block(i * p, j * m, &poly[i + j + 1]);
        }
    }
    h.rank()
}

/// $G(s_0) = $ realization at $s_0$ for enough rational points (poles skipped).
fn equals_at_points<K: Field>(g: &TransferMatrix<K>, sys: &Descriptor<K>, fld: &K) -> bool {
    let degs: usize = g
        .entries
        .iter()
        .flatten()
        .map(|f| f.num.deg() + f.den.deg())
        .sum();
    let need = degs + 2 * sys.nstates() + 1;
    let mut agree = 0;
    let mut t: i64 = 0;
    let limit = (need + degs + sys.nstates() + 1) as i64;
    while agree < need && t < limit {
        let s0 = fld.from_rational(&Rational::new((3 * t + 1).into(), 5.into()));
        t += 1;
        let mut vals = Vec::new();
        for f in g.entries.iter().flatten() {
            match fld.div(&f.num.eval(&s0), &f.den.eval(&s0)) {
                Some(v) => vals.push(v),
                None => break,
            }
        }
        let Some(r) = (vals.len() == g.entries.len() * g.entries[0].len())
            .then(|| eval_transfer(sys, &s0))
            .flatten()
        else {
            continue;
        };
        if r.as_slice() != vals.as_slice() {
            return false;
        }
        agree += 1;
    }
    agree >= need
}
