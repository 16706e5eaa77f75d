//! Mode contributions ranked and truncation by contribution (minimal-realizations paper
//! sec. 3.3, eq. 33), exactly over $\mathbb{Q}$.
//!
//! Eq. 33 judges a mode by the products $b_i c_i$ of its input and output coefficients in the
//! Jordan coordinates (and, in a $2 \times 2$ block, the cross products). These are the
//! residues $H_{\theta,k} = C\, G_{\theta,k}\, B$ of the transfer matrix
//! $G(s) = D + \sum_\theta \sum_k k!\, H_{\theta,k} / (s - \theta)^{k+1}$
//! ($G_{\theta,k} = (A - \theta I)^k P_\theta / k!$, [`crate::jordan::FreeResponse`]), exact
//! in $\mathbb{Q}(\theta)$. A single number per mode, exact over $\mathbb{Q}$, that ranks them:
//! the squared $H_2$ norm of the mode's part of $G$,
//! $$\|G_p\|_2^2 = \operatorname{tr}(C_p W_p C_p^T),\qquad A_p W_p + W_p A_p^T + B_p B_p^T = 0,$$
//! where $(A_p, B_p, C_p) = (R_p A V_p, R_p B, C V_p)$ is the system on the generalized
//! eigenspace of one irreducible factor $p$ of $\chi_A$ over $\mathbb{Q}$: its spectral
//! projector $P_p = \sum \operatorname{Tr}_{\mathbb{Q}(\theta)/\mathbb{Q}} G_{\theta,0}$ is
//! rational and $P_p = V_p R_p$ (pivot columns times the rows of its RREF). A mode is a whole
//! factor (a real eigenvalue, a complex pair, or all conjugates of a higher-degree factor),
//! so that every truncation stays over $\mathbb{Q}$. Weights: `Zero` when all Markov
//! parameters of the part vanish (eq. 33's $b c = 0$: non-contributing), `Infinite` when the
//! part contributes and is not asymptotically stable, else the exact $H_2^2$.
//!
//! Truncation to the $K$ heaviest modes keeps their parts; the error $E(s) = G(s) - G_K(s)$ is
//! the transfer matrix of the dropped parts, stated exactly: its $H_2^2$ (Lyapunov, when the
//! dropped parts are stable), its DC gain $E(0) = -C_D A_D^{-1} B_D$ and its first Markov
//! parameter $C_D B_D$. Checked exactly: $\sum_p P_p = I$, $R_p V_p = I$, $A V_p = V_p A_p$, and
//! each Lyapunov solution substituted back.

use super::gramian::{is_hurwitz, lyapunov};
use crate::algebraic::NumberField;
use crate::error::{Error, Result};
use crate::field::{Q, Rational};
use crate::jordan::{JordanForm, jordan};
use crate::matrix::Matrix;
use crate::poly::newton_power_sums;
use crate::system::StateSpace;
use num_traits::Zero;
use std::cmp::Ordering;

/// How much a mode contributes to $G$.
#[derive(Clone, Debug, PartialEq)]
pub enum Weight {
    /// Every Markov parameter of the mode's part is zero: it does not reach $y$ from $u$.
    Zero,
    /// $\|G_p\|_2^2$, exact.
    H2Squared(Rational),
    /// The part contributes and has an eigenvalue with $\operatorname{Re} \ge 0$ ($H_2 =
    /// \infty$): never dropped before the finite ones.
    Infinite,
}

impl Weight {
    fn rank_key(&self) -> (u8, Option<&Rational>) {
        match self {
            Weight::Infinite => (2, None),
            Weight::H2Squared(r) => (1, Some(r)),
            Weight::Zero => (0, None),
        }
    }
    /// Heavier first.
    fn heavier(&self, other: &Weight) -> Ordering {
        let (a, b) = (self.rank_key(), other.rank_key());
        b.0.cmp(&a.0).then_with(|| match (a.1, b.1) {
            (Some(x), Some(y)) => y.cmp(x),
            _ => Ordering::Equal,
        })
    }
}

/// One mode (one irreducible factor of $\chi_A$) and its part of the system.
#[derive(Clone, Debug)]
pub struct ModeContribution {
    /// Index into the Jordan form's components.
    pub component: usize,
    /// Indices into the Jordan form's eigenvalues (the conjugates of the factor).
    pub eigenvalues: Vec<usize>,
    /// The part on the generalized eigenspace: $(A_p, B_p, C_p)$, order $\deg p \cdot$ mult.
    pub part: StateSpace<Q>,
    /// The spectral projector $P_p = V_p R_p$: $V_p$ (its pivot columns) and $R_p$ (the rows of
    /// its RREF), $R_p V_p = I$, $A V_p = V_p A_p$.
    pub basis: Matrix<Q>,
    pub rows: Matrix<Q>,
    /// Residues $H_{\theta,k} = C G_{\theta,k} B$ in the component field, $k = 0, 1, \dots$.
    pub residues: Vec<Matrix<NumberField>>,
    pub weight: Weight,
}

/// The modes ranked, heaviest first.
#[derive(Clone, Debug)]
pub struct Contributions {
    pub jordan: JordanForm,
    pub modes: Vec<ModeContribution>,
    pub d: Matrix<Q>,
    /// The identities of the module docs held exactly.
    pub verified: bool,
}

/// The truncated realization and its exact error.
#[derive(Clone, Debug)]
pub struct Truncation {
    /// Indices into [`Contributions::modes`] kept.
    pub kept: Vec<usize>,
    pub system: StateSpace<Q>,
    /// $\|G - G_K\|_2^2$ (the dropped parts stable), `None` otherwise.
    pub error_h2_squared: Option<Rational>,
    /// $E(0) = -C_D A_D^{-1} B_D$ (`None` when $A_D$ is singular).
    pub error_dc: Option<Matrix<Q>>,
    /// $C_D B_D$, the error's first Markov parameter (its impulse response at $0^+$).
    pub error_markov0: Matrix<Q>,
    /// The Lyapunov solution of the error substituted back.
    pub verified: bool,
}

/// $\|C (sI - A)^{-1} B\|_2^2$ exactly (A Hurwitz) and whether $A W + W A^T + B B^T = 0$ held.
fn h2_squared(s: &StateSpace<Q>) -> Result<(Rational, bool)> {
    if s.a.nrows() == 0 {
        return Ok((Rational::zero(), true));
    }
    let bbt = &s.b * &s.b.transpose();
    let w = lyapunov(&s.a, &bbt)?;
    let ok = (&(&(&s.a * &w) + &(&w * &s.a.transpose())) + &bbt).is_zero();
    let cwc = &(&s.c * &w) * &s.c.transpose();
    let tr = (0..cwc.nrows()).fold(Rational::zero(), |acc, i| acc + cwc.get(i, i));
    Ok((tr, ok))
}

/// The Markov parameters $C A^k B$, $k < n$, all zero?
fn markov_zero(s: &StateSpace<Q>) -> bool {
    let mut ak_b = s.b.clone();
    for _ in 0..s.a.nrows().max(1) {
        if !(&s.c * &ak_b).is_zero() {
            return false;
        }
        ak_b = &s.a * &ak_b;
    }
    true
}

/// The modes of a rational system ranked by contribution.
///
/// # Errors
/// As [`jordan`]; `Singular` from a Lyapunov solve (not for a Hurwitz part).
pub fn contributions(ss: &StateSpace<Q>) -> Result<Contributions> {
    let jf = jordan(&ss.a)?;
    let fr = jf.free_response();
    let n = jf.n();
    let mut sum_p = Matrix::zeros(Q, n, n);
    let mut verified = jf.verified;
    let mut modes = vec![];
    for (ci, comp) in jf.components.iter().enumerate() {
        let e = &comp.field;
        let ps = newton_power_sums(&comp.factor, comp.factor.deg().saturating_sub(1));
        let terms: Vec<_> = fr.terms.iter().filter(|t| t.component == ci).collect();
        let g0 = &terms
            .iter()
            .find(|t| t.power == 0)
            .ok_or_else(|| Error::Verification("a component without G_0".into()))?
            .coeff;
        let p = g0.map(&Q, |x| {
            x.0.iter()
                .zip(&ps)
                .fold(Rational::zero(), |acc, (a, b)| acc + a * b)
        });
        sum_p = &sum_p + &p;
        let (rr, piv) = p.rref();
        let v = p.select_cols(&piv);
        let r = rr.submatrix(0, piv.len(), 0, n);
        let a_p = &(&r * &ss.a) * &v;
        verified &= (&r * &v).is_identity() && &ss.a * &v == &v * &a_p;
        let part = StateSpace::new(
            a_p,
            &r * &ss.b,
            &ss.c * &v,
            Matrix::zeros(Q, ss.c.nrows(), ss.b.ncols()),
        )?;
        let (cb, bb) = (ss.c.convert_to(e), ss.b.convert_to(e));
        let residues = terms.iter().map(|t| &(&cb * &t.coeff) * &bb).collect();
        let weight = if markov_zero(&part) {
            Weight::Zero
        } else if is_hurwitz(&comp.factor) {
            let (h, ok) = h2_squared(&part)?;
            verified &= ok;
            Weight::H2Squared(h)
        } else {
            Weight::Infinite
        };
        let eigenvalues = (0..jf.eigenvalues.len())
            .filter(|&i| jf.eigenvalues[i].component == ci)
            .collect();
        modes.push(ModeContribution {
            component: ci,
            eigenvalues,
            part,
            basis: v,
            rows: r,
            residues,
            weight,
        });
    }
    verified &= sum_p.is_identity();
    modes.sort_by(|a, b| a.weight.heavier(&b.weight));
    Ok(Contributions {
        jordan: jf,
        modes,
        d: ss.d.clone(),
        verified,
    })
}

/// The parts `idx` stacked block-diagonally (with `d`).
fn stack(modes: &[ModeContribution], idx: &[usize], d: &Matrix<Q>) -> Result<StateSpace<Q>> {
    let parts: Vec<&StateSpace<Q>> = idx.iter().map(|&i| &modes[i].part).collect();
    let a = Matrix::block_diag(Q, &parts.iter().map(|p| p.a.clone()).collect::<Vec<_>>());
    let mut b = Matrix::zeros(Q, 0, d.ncols());
    let mut c = Matrix::zeros(Q, d.nrows(), 0);
    for p in &parts {
        b = b.vstack(&p.b)?;
        c = c.hstack(&p.c)?;
    }
    StateSpace::new(a, b, c, d.clone())
}

impl Contributions {
    /// Keeps the `keep` heaviest modes (all when `keep` exceeds their number).
    ///
    /// # Errors
    /// Shape errors (none expected); `Singular` from the error's Lyapunov solve.
    pub fn truncate(&self, keep: usize) -> Result<Truncation> {
        let keep = keep.min(self.modes.len());
        let kept: Vec<usize> = (0..keep).collect();
        // the dropped parts that reach y (a part of weight Zero has a zero transfer matrix)
        let dropped: Vec<usize> = (keep..self.modes.len())
            .filter(|&i| self.modes[i].weight != Weight::Zero)
            .collect();
        let system = stack(&self.modes, &kept, &self.d)?;
        let zero_d = Matrix::zeros(Q, self.d.nrows(), self.d.ncols());
        let err = stack(&self.modes, &dropped, &zero_d)?;
        let error_markov0 = &err.c * &err.b;
        let stable = dropped
            .iter()
            .all(|&i| matches!(self.modes[i].weight, Weight::H2Squared(_)));
        let mut verified = true;
        let error_h2_squared = if stable {
            let (h, ok) = h2_squared(&err)?;
            verified &= ok;
            Some(h)
        } else {
            None
        };
        let error_dc = match err.a.inverse() {
            Ok(inv) => Some(-&(&(&err.c * &inv) * &err.b)),
            Err(_) if err.a.nrows() == 0 => Some(zero_d),
            Err(_) => None,
        };
        Ok(Truncation {
            kept,
            system,
            error_h2_squared,
            error_dc,
            error_markov0,
            verified,
        })
    }
}
