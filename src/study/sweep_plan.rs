//! Exact bookkeeping for a sweep: the number of finite eigenvalues of the family, and the
//! sweep values where the family has a pole, a singular pencil, or fewer finite eigenvalues
//! than usual, decided exactly.
//!
//! A sweep value is a binary rational, so it is a root of a polynomial over $\mathbb{Q}$
//! only when it is one of that polynomial's rational roots: the rational roots of the
//! denominators (poles), of $\det E(v)$ resp. $\det M(v)$ (rows made polynomial), and,
//! when that determinant vanishes identically, of the leading coefficient and the content
//! of $\det(xE - A)$ ([`charpoly_xv_content`]) are found once; at each of them the status
//! is decided exactly from the finite part $A_f(v_0)$ ([`ParamFamily::state_matrix_q`]).
//! Everywhere else the count is the generic one: $n$ when $\det E \not\equiv 0$, else
//! $r = \deg_x P$.

use super::bivar::charpoly_xv_content;
use super::family::{FamilyForm, ParamFamily, RatMatrix};
use super::qv::upoly;
use crate::algebraic::factor_q;
use crate::error::{Error, Result};
use crate::field::{Q, Rational};
use crate::poly::Poly;
use crate::ratfunc::kernels::{clear_rows, det_zp};

/// What a sweep found at one parameter value.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PointStatus {
    /// The eigenvalues of $A(v)$ ($E(v)$, $M(v)$ invertible).
    Regular,
    /// $E(v)$ (or $M(v)$) singular: the finite eigenvalues of the pencil; `infinite` of
    /// the $n$ eigenvalues are infinite.
    Descriptor { infinite: usize },
    /// An entry of the matrices has a pole at $v$: no eigenvalues.
    Pole,
    /// $\det(xE(v) - A(v)) = 0$ for every $x$: no eigenvalues.
    SingularPencil,
    /// The float computation failed (non-finite values): no eigenvalues.
    Failed,
}

/// The exact part of a sweep (module docs).
#[derive(Clone, Debug)]
pub struct SweepPlan {
    /// Number of states $n$.
    pub nstates: usize,
    /// The status at a generic value.
    pub generic: PointStatus,
    /// Rational values with another status.
    pub special: Vec<(Rational, PointStatus)>,
}

impl SweepPlan {
    /// Computes the plan of `fam`.
    ///
    /// # Errors
    /// Errors of the exact determinants and factorizations ([`charpoly_xv_content`]).
    pub fn new(fam: &ParamFamily) -> Result<SweepPlan> {
        let n = fam.nstates();
        let mut special: Vec<(Rational, PointStatus)> = vec![];
        for d in fam.denominators() {
            for r in rational_roots(&d)? {
                push_new(&mut special, r, PointStatus::Pole);
            }
        }
        let lead = match &fam.form {
            FamilyForm::First { e: None, .. } => None,
            FamilyForm::First { e: Some(e), .. } => Some(e),
            FamilyForm::Second { m, .. } => Some(m),
        };
        let Some(lead) = lead else {
            return Ok(SweepPlan {
                nstates: n,
                generic: PointStatus::Regular,
                special,
            });
        };
        let ldet = row_scaled_det(lead)?;
        let (generic, exceptional) = if !ldet.is_zero() {
            (PointStatus::Regular, rational_roots(&ldet)?)
        } else {
            match charpoly_xv_content(fam) {
                Ok((p, content)) => {
                    let mut ex = rational_roots(&p.lead())?;
                    ex.extend(rational_roots(&content)?);
                    let infinite = n - p.deg_x();
                    (PointStatus::Descriptor { infinite }, ex)
                }
                Err(Error::Singular) => (PointStatus::SingularPencil, vec![]),
                Err(e) => return Err(e),
            }
        };
        for r in exceptional {
            if special.iter().any(|(x, _)| *x == r) {
                continue;
            }
            let status = status_at(fam, &r, n)?;
            if status != generic {
                special.push((r, status));
            }
        }
        Ok(SweepPlan {
            nstates: n,
            generic,
            special,
        })
    }

    /// The status at the value `v` (exact comparison with the special values).
    pub fn status(&self, v: f64) -> PointStatus {
        if !v.is_finite() {
            return PointStatus::Failed;
        }
        if self.special.is_empty() {
            return self.generic;
        }
        let Some(q) = Rational::from_float(v) else {
            return PointStatus::Failed;
        };
        self.special
            .iter()
            .find(|(x, _)| *x == q)
            .map_or(self.generic, |(_, s)| *s)
    }
}

fn push_new(out: &mut Vec<(Rational, PointStatus)>, r: Rational, s: PointStatus) {
    if !out.iter().any(|(x, _)| *x == r) {
        out.push((r, s));
    }
}

/// The exact status at the rational `v0` from the finite part $A_f(v_0)$.
fn status_at(fam: &ParamFamily, v0: &Rational, n: usize) -> Result<PointStatus> {
    match fam.state_matrix_q(v0) {
        Ok(af) if af.nrows() == n => Ok(PointStatus::Regular),
        Ok(af) => Ok(PointStatus::Descriptor {
            infinite: n - af.nrows(),
        }),
        Err(Error::Singular) => Ok(PointStatus::SingularPencil),
        Err(Error::DivisionByZero) => Ok(PointStatus::Pole),
        Err(e) => Err(e),
    }
}

/// The rational roots of `p` (none for a constant or zero `p`).
fn rational_roots(p: &Poly<Q>) -> Result<Vec<Rational>> {
    if p.degree().unwrap_or(0) == 0 {
        return Ok(vec![]);
    }
    Ok(factor_q(p)?
        .1
        .into_iter()
        .filter(|(f, _)| f.deg() == 1)
        .map(|(f, _)| -f.monic().coeff(0))
        .collect())
}

/// $\det$ of the matrix of rational functions `m` with each row multiplied by the lcm of
/// its denominators: a polynomial in $v$ with the same zeros away from the poles (the
/// tower's row clearing and evaluation/interpolation kernel
/// [`crate::ratfunc::kernels::det_zp`]).
fn row_scaled_det(m: &RatMatrix) -> Result<Poly<Q>> {
    let n = m.nrows();
    if n == 0 {
        return Ok(Poly::one(Q));
    }
    let (b, _) = clear_rows(1, n, n, m.as_slice());
    let bound: u32 = (0..n)
        .map(|i| (0..n).map(|j| b[i * n + j].deg(0)).max().unwrap_or(0))
        .sum();
    if bound as usize > super::bivar::MAX_BIDEGREE {
        return Err(Error::Limit(format!(
            "det E(v) of degree up to {bound} in the parameter"
        )));
    }
    Ok(upoly(&det_zp(1, n, &b)?))
}
