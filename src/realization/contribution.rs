//! Mode contributions ranked and truncation by contribution (minimal-realizations paper
//! sec. 3.3, eq. 33), exactly over any field $F$ with a Jordan form: $\mathbb{Q}$,
//! $\mathbb{Q}(\sqrt d)$, $\mathbb{Q}(i)$, $\mathbb{Q}(p)$ (written once, generic over $F$;
//! [`contributions`] over $\mathbb{Q}$, [`contributions_in`] given the Jordan form over $F$).
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
//! Over a field that is not real ($\mathbb{Q}(i)$) the transposes are conjugate transposes:
//! $\|G_p\|_2^2 = \operatorname{tr}(C_p W_p C_p^H)$, $A_p W_p + W_p A_p^H + B_p B_p^H = 0$.
//! Whether a part is asymptotically stable is decided exactly and the same way in every field
//! (Lyapunov's theorem): $A_p X + X A_p^H = -I$ has a solution $X$ that is positive definite
//! (every leading principal minor $> 0$, a sign in $F$); a singular Lyapunov operator
//! ($\lambda_i + \bar\lambda_j = 0$) means not stable. Over $\mathbb{Q}(p)$ these signs are
//! signs of rational functions of the parameters: undecided in general, so the weight is
//! [`Weight::H2SquaredWhereStable`], the exact rational function $\operatorname{tr}(C_p W_p
//! C_p^T)$, which is $\|G_p\|_2^2$ exactly for the parameter values where $A_p$ is Hurwitz
//! (where it is not, the $H_2$ norm is infinite and the function means nothing). Such
//! weights are not ordered (which mode is heavier changes with the parameters), so the modes
//! stay in the Jordan form's order and a truncation "to the $K$ heaviest" is refused.
//!
//! Truncation to the $K$ heaviest modes keeps their parts; the error $E(s) = G(s) - G_K(s)$ is
//! the transfer matrix of the dropped parts, stated exactly: its $H_2^2$ (Lyapunov, when the
//! dropped parts are stable), its DC gain $E(0) = -C_D A_D^{-1} B_D$ and its first Markov
//! parameter $C_D B_D$. Checked exactly: $\sum_p P_p = I$, $R_p V_p = I$, $A V_p = V_p A_p$, and
//! each Lyapunov solution substituted back.

pub(crate) use super::gramian::{adjoint, hurwitz, lyapunov_h};
use crate::algebraic::Ext;
use crate::error::{Error, Result};
use crate::field::{Field, Q};
use crate::jordan::{JordanForm, jordan};
use crate::matrix::Matrix;
use crate::system::StateSpace;
use std::cmp::Ordering;

/// How much a mode contributes to $G$ (`E`: the field's elements).
#[derive(Clone, Debug, PartialEq)]
pub enum Weight<E = crate::field::Rational> {
    /// Every Markov parameter of the mode's part is zero: it does not reach $y$ from $u$.
    Zero,
    /// $\|G_p\|_2^2$, exact (the part is asymptotically stable).
    H2Squared(E),
    /// The part contributes and has an eigenvalue with $\operatorname{Re} \ge 0$ ($H_2 =
    /// \infty$): never dropped before the finite ones.
    Infinite,
    /// Over $\mathbb{Q}(p)$: $\operatorname{tr}(C_p W_p C_p^T)$ as a rational function, equal to
    /// $\|G_p\|_2^2$ where the part is asymptotically stable (undecided in symbols; module docs).
    H2SquaredWhereStable(E),
}

impl<E> Weight<E> {
    fn class(&self) -> u8 {
        match self {
            Weight::Infinite => 3,
            Weight::H2Squared(_) => 2,
            Weight::H2SquaredWhereStable(_) => 1,
            Weight::Zero => 0,
        }
    }
}

/// Heavier first; `None` when the order is not decided (a weight in symbols).
fn heavier<F: Field>(k: &F, a: &Weight<F::Elem>, b: &Weight<F::Elem>) -> Option<Ordering> {
    match (a, b) {
        (Weight::H2SquaredWhereStable(_), _) | (_, Weight::H2SquaredWhereStable(_)) => None,
        (Weight::H2Squared(x), Weight::H2Squared(y)) => k.sign(&k.sub(y, x)),
        _ => Some(b.class().cmp(&a.class())),
    }
}

/// One mode (one irreducible factor of $\chi_A$ over $F$) and its part of the system.
#[derive(Clone, Debug)]
pub struct ModeContribution<F: Field = Q> {
    /// Index into the Jordan form's components.
    pub component: usize,
    /// Indices into the Jordan form's eigenvalues (the conjugates of the factor; empty over
    /// $\mathbb{Q}(p)$, whose roots are functions of the parameters).
    pub eigenvalues: Vec<usize>,
    /// The part on the generalized eigenspace: $(A_p, B_p, C_p)$, order $\deg p \cdot$ mult.
    pub part: StateSpace<F>,
    /// The spectral projector $P_p = V_p R_p$: $V_p$ (its pivot columns) and $R_p$ (the rows of
    /// its RREF), $R_p V_p = I$, $A V_p = V_p A_p$.
    pub basis: Matrix<F>,
    pub rows: Matrix<F>,
    /// Residues $H_{\theta,k} = C G_{\theta,k} B$ in the component field, $k = 0, 1, \dots$.
    pub residues: Vec<Matrix<Ext<F>>>,
    pub weight: Weight<F::Elem>,
}

/// The modes ranked, heaviest first.
#[derive(Clone, Debug)]
pub struct Contributions<F: Field = Q> {
    pub jordan: JordanForm<F>,
    pub modes: Vec<ModeContribution<F>>,
    pub d: Matrix<F>,
    /// Every weight was compared exactly (false over $\mathbb{Q}(p)$ with a weight in
    /// symbols: the modes are then in the Jordan form's order).
    pub ranked: bool,
    /// The identities of the module docs held exactly.
    pub verified: bool,
}

/// The truncated realization and its exact error.
#[derive(Clone, Debug)]
pub struct Truncation<F: Field = Q> {
    /// Indices into [`Contributions::modes`] kept.
    pub kept: Vec<usize>,
    pub system: StateSpace<F>,
    /// $\|G - G_K\|_2^2$ (the dropped parts stable), `None` otherwise.
    pub error_h2_squared: Option<F::Elem>,
    /// $E(0) = -C_D A_D^{-1} B_D$ (`None` when $A_D$ is singular).
    pub error_dc: Option<Matrix<F>>,
    /// $C_D B_D$, the error's first Markov parameter (its impulse response at $0^+$).
    pub error_markov0: Matrix<F>,
    /// The Lyapunov solution of the error substituted back.
    pub verified: bool,
}

/// $\|C (sI - A)^{-1} B\|_2^2 = \operatorname{tr}(C W C^H)$ with $A W + W A^H + B B^H = 0$
/// (A Hurwitz, or over $\mathbb{Q}(p)$ where it is), and whether that identity held.
pub(crate) fn h2_squared<F: Field>(s: &StateSpace<F>) -> Result<(F::Elem, bool)> {
    let k = s.field();
    if s.a.nrows() == 0 {
        return Ok((k.zero(), true));
    }
    let bbh = &s.b * &adjoint(&s.b);
    let w = lyapunov_h(&s.a, &bbh)?;
    let ok = (&(&(&s.a * &w) + &(&w * &adjoint(&s.a))) + &bbh).is_zero();
    let cwc = &(&s.c * &w) * &adjoint(&s.c);
    let tr = (0..cwc.nrows()).fold(k.zero(), |acc, i| k.add(&acc, cwc.get(i, i)));
    Ok((tr, ok))
}

/// The Markov parameters $C A^k B$, $k < n$, all zero?
fn markov_zero<F: Field>(s: &StateSpace<F>) -> bool {
    s.markov(s.a.nrows().max(1)).iter().all(|m| m.is_zero())
}

/// The modes of a rational system ranked by contribution ([`contributions_in`] with
/// [`jordan`]).
///
/// # Errors
/// As [`jordan`] and [`contributions_in`].
pub fn contributions(ss: &StateSpace<Q>) -> Result<Contributions> {
    contributions_in(ss, jordan(&ss.a)?)
}

/// The modes of a system over $\mathbb{Q}(p)$ ([`contributions_in`] with
/// [`crate::jordan::jordan_qp`]): the system is carried into the Jordan form's field, so
/// every division of the contributions (the projectors' RREF, the Lyapunov solves) joins
/// the Jordan form's conditions ([`JordanForm::conditions`], refreshed).
///
/// # Errors
/// As [`crate::jordan::jordan_qp`] and [`contributions_in`].
pub fn contributions_qp(
    ss: &StateSpace<crate::ratfunc::RatFuncField>,
) -> Result<Contributions<crate::ratfunc::RatFuncField>> {
    let jf = crate::jordan::jordan_qp(&ss.a)?;
    let k = jf.base().clone();
    let ss = in_field(ss, &k)?;
    let mut c = contributions_in(&ss, jf)?;
    c.jordan.conditions = k
        .conditions()?
        .into_iter()
        .map(|p| k.from_mpoly(p))
        .collect();
    Ok(c)
}

/// `ss` with its matrices carried by the field value `k` (over $\mathbb{Q}(p)$: another
/// condition log).
pub(crate) fn in_field<F: Field>(ss: &StateSpace<F>, k: &F) -> Result<StateSpace<F>> {
    let re =
        |m: &Matrix<F>| Matrix::from_vec(k.clone(), m.nrows(), m.ncols(), m.as_slice().to_vec());
    StateSpace::new(re(&ss.a), re(&ss.b), re(&ss.c), re(&ss.d))
}

/// The modes of a system over $F$ ranked by contribution, from the Jordan form `jf` of its
/// $A$ ([`crate::jordan::jordan_over`], or [`crate::jordan::jordan_qp`] over $\mathbb{Q}(p)$).
///
/// # Errors
/// `Invalid` when `jf` is not the Jordan form of `ss.a`; `Verification` for a component
/// without $G_0$; `Singular` from a Lyapunov solve (not for a stable part).
pub fn contributions_in<F: Field + 'static>(
    ss: &StateSpace<F>,
    jf: JordanForm<F>,
) -> Result<Contributions<F>> {
    if jf.a != ss.a {
        return Err(Error::Invalid(
            "contributions: the Jordan form is not of this system's A".into(),
        ));
    }
    let k = ss.field().clone();
    let fr = jf.free_response();
    let n = jf.n();
    let mut sum_p = Matrix::zeros(k.clone(), n, n);
    let mut verified = jf.verified;
    let mut modes = vec![];
    for (ci, comp) in jf.components.iter().enumerate() {
        let terms: Vec<_> = fr.terms.iter().filter(|t| t.component == ci).collect();
        let g0 = &terms
            .iter()
            .find(|t| t.power == 0)
            .ok_or_else(|| Error::Verification("a component without G_0".into()))?
            .coeff;
        let p = crate::jordan::response::trace_down(g0, &comp.factor, &k);
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
            Matrix::zeros(k.clone(), ss.c.nrows(), ss.b.ncols()),
        )?;
        let (cb, bb) = (comp.lift(&ss.c), comp.lift(&ss.b));
        let residues = terms.iter().map(|t| &(&cb * &t.coeff) * &bb).collect();
        let weight = if markov_zero(&part) {
            Weight::Zero
        } else {
            match hurwitz(&part.a)? {
                Some(false) => Weight::Infinite,
                stable => {
                    let (h, ok) = h2_squared(&part)?;
                    verified &= ok;
                    if stable.is_some() {
                        Weight::H2Squared(h)
                    } else {
                        Weight::H2SquaredWhereStable(h)
                    }
                }
            }
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
    let ranked = modes.iter().all(|a| {
        modes
            .iter()
            .all(|b| heavier(&k, &a.weight, &b.weight).is_some())
    });
    if ranked {
        modes.sort_by(|a, b| heavier(&k, &a.weight, &b.weight).unwrap_or(Ordering::Equal));
    }
    Ok(Contributions {
        jordan: jf,
        modes,
        d: ss.d.clone(),
        ranked,
        verified,
    })
}

/// The parts `idx` stacked block-diagonally (with `d`).
fn stack<F: Field>(
    modes: &[ModeContribution<F>],
    idx: &[usize],
    d: &Matrix<F>,
) -> Result<StateSpace<F>> {
    let k = d.field().clone();
    let parts: Vec<&StateSpace<F>> = idx.iter().map(|&i| &modes[i].part).collect();
    let a = Matrix::block_diag(
        k.clone(),
        &parts.iter().map(|p| p.a.clone()).collect::<Vec<_>>(),
    );
    let mut b = Matrix::zeros(k.clone(), 0, d.ncols());
    let mut c = Matrix::zeros(k, d.nrows(), 0);
    for p in &parts {
        b = b.vstack(&p.b)?;
        c = c.hstack(&p.c)?;
    }
    StateSpace::new(a, b, c, d.clone())
}

impl<F: Field> Contributions<F> {
    /// Keeps the `keep` heaviest modes (all when `keep` exceeds their number).
    ///
    /// # Errors
    /// `Unsupported` when the modes are not ranked (weights in symbols, module docs); shape
    /// errors (none expected); `Singular` from the error's Lyapunov solve.
    pub fn truncate(&self, keep: usize) -> Result<Truncation<F>> {
        if !self.ranked {
            return Err(Error::Unsupported(
                "--keep: the modes' H2 norms are rational functions of the parameters, whose order changes with their values (and each is the H2 norm only where its part is stable), so there is no \"K heaviest\" in symbols; give every symbol a value with --at".into(),
            ));
        }
        let k = self.d.field().clone();
        let keep = keep.min(self.modes.len());
        let kept: Vec<usize> = (0..keep).collect();
        // the dropped parts that reach y (a part of weight Zero has a zero transfer matrix)
        let dropped: Vec<usize> = (keep..self.modes.len())
            .filter(|&i| self.modes[i].weight != Weight::Zero)
            .collect();
        let system = stack(&self.modes, &kept, &self.d)?;
        let zero_d = Matrix::zeros(k, self.d.nrows(), self.d.ncols());
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
