//! Gramians of stable systems by exact Lyapunov solves (paper eq. 6).
//!
//! $A W_c + W_c A^T = -BB^T$ and $A^T W_o + W_o A = -C^TC$ are solved as the linear systems
//! $(I \otimes A + A \otimes I)\,\mathrm{vec}(W) = -\mathrm{vec}(Q)$, uniquely solvable when no
//! two eigenvalues of $A$ sum to zero. Stability is decided exactly over $\mathbb Q$ by the
//! Routh–Hurwitz test on $\det(sI - A)$ ([`is_hurwitz`]), over any field by Lyapunov's
//! theorem ([`hurwitz`]). [`gramian`] is written once over the field: conjugate transposes
//! ($A W + W A^H + B B^H = 0$), which are transposes over a real field.

use crate::error::{Error, Result};
use crate::field::{Field, Q, Rational};
use crate::matrix::Matrix;
use crate::poly::Poly;
use crate::system::StateSpace;
use num_traits::{Signed, Zero};
use std::cmp::Ordering;

/// Controllability and observability Gramians.
#[derive(Clone, Debug)]
pub struct Gramians {
    pub wc: Matrix<Q>,
    pub wo: Matrix<Q>,
}

/// Exact Routh–Hurwitz test: are all roots of `p` in the open left half-plane?
pub fn is_hurwitz(p: &Poly<Q>) -> bool {
    let n = match p.degree() {
        None => return false,
        Some(n) => n,
    };
    if n == 0 {
        return true;
    }
    let c: Vec<Rational> = p.coeffs().iter().rev().cloned().collect(); // c[0] s^n + c[1] s^{n-1} + ...
    let sign = c[0].is_positive();
    if c.iter().any(|x| x.is_zero() || x.is_positive() != sign) {
        return false;
    }
    // Routh array
    let mut r0: Vec<Rational> = c.iter().step_by(2).cloned().collect();
    let mut r1: Vec<Rational> = c.iter().skip(1).step_by(2).cloned().collect();
    for _ in 0..n {
        if r1.is_empty() {
            break;
        }
        if r1[0].is_zero() || r1[0].is_positive() != r0[0].is_positive() {
            return false;
        }
        let mut r2 = vec![];
        for j in 0..r0.len().saturating_sub(1) {
            let a = r0.get(j + 1).cloned().unwrap_or_default();
            let b = r1.get(j + 1).cloned().unwrap_or_default();
            r2.push((&r1[0] * &a - &r0[0] * &b) / &r1[0]);
        }
        while r2.last().is_some_and(|x| x.is_zero()) && r2.len() > 1 {
            r2.pop();
        }
        if r2.iter().all(|x| x.is_zero()) {
            r2.clear();
        }
        r0 = r1;
        r1 = r2;
    }
    true
}

/// Solves $A W + W A^T = -Q$ exactly.
///
/// # Errors
/// `Singular` when the Lyapunov operator is singular (two eigenvalues sum to zero).
pub fn lyapunov<K: Field>(a: &Matrix<K>, q: &Matrix<K>) -> Result<Matrix<K>> {
    let n = a.nrows();
    let i = Matrix::identity(a.field().clone(), n);
    let op = &i.kron(a) + &a.kron(&i);
    let rhs = -&q.vec();
    match op.solve(&rhs)? {
        Some((x, nul)) if nul.ncols() == 0 => x.unvec(n, n),
        _ => Err(Error::Singular),
    }
}

/// Which Gramian (python-control's `gram(sys, 'c' | 'o')`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GramType {
    /// $A W + W A^T + B B^T = 0$.
    Controllability,
    /// $A^T W + W A + C^T C = 0$.
    Observability,
}

/// One Gramian with its exact check (`F`: the field of the system).
#[derive(Clone, Debug)]
pub struct Gramian<F: Field = Q> {
    pub kind: GramType,
    pub w: Matrix<F>,
    /// Whether the equation is written with conjugate transposes ($A^H$, $B^H$): some entry of
    /// the system is not real (over $\mathbb{Q}(i)$, $\mathbb{Q}(\sqrt d)$ with $d < 0$).
    pub hermitian: bool,
    /// The Lyapunov residual is exactly zero and $W = W^H$.
    pub verified: bool,
}

/// The controllability or observability Gramian of a stable system over any field with
/// complex conjugation (the identity over a real field), written once:
/// $A W + W A^H + B B^H = 0$ or $A^H W + W A + C^H C = 0$, solved exactly and verified by
/// substituting $W$ back (and $W = W^H$). Stability is decided exactly in the field by
/// Lyapunov's theorem ([`hurwitz`]).
///
/// # Errors
/// `Unstable` when $A$ is not Hurwitz; `Unsupported` when its stability is undecided in the
/// field (over $\mathbb{Q}(p)$: signs of rational functions of the parameters).
pub fn gramian<F: Field>(sys: &StateSpace<F>, kind: GramType) -> Result<Gramian<F>> {
    match hurwitz(&sys.a)? {
        Some(true) => {}
        Some(false) => {
            return Err(Error::Unstable(
                "A has an eigenvalue with non-negative real part; the Gramian integral diverges"
                    .into(),
            ));
        }
        None => {
            return Err(Error::Unsupported(format!(
                "the Gramian needs A Hurwitz, which is not decided over {} (a sign of a rational function of the parameters); give the symbols values with --at",
                sys.field()
            )));
        }
    }
    let (a, q) = match kind {
        GramType::Controllability => (sys.a.clone(), &sys.b * &adjoint(&sys.b)),
        GramType::Observability => (adjoint(&sys.a), &adjoint(&sys.c) * &sys.c),
    };
    let w = lyapunov_h(&a, &q)?;
    let residual = &(&(&a * &w) + &(&w * &adjoint(&a))) + &q;
    let verified = residual.is_zero() && w == adjoint(&w);
    let hermitian = [&sys.a, &sys.b, &sys.c]
        .iter()
        .any(|m| adjoint(m) != m.transpose());
    Ok(Gramian {
        kind,
        w,
        hermitian,
        verified,
    })
}

/// The complex conjugate of every entry (the identity in a real field, also in
/// $\mathbb{Q}(p)$ with real parameters).
fn conjugate<F: Field>(m: &Matrix<F>) -> Matrix<F> {
    let k = m.field().clone();
    m.map(&k, |x| k.conj(x).unwrap_or_else(|| x.clone()))
}

/// $M^H$.
pub(crate) fn adjoint<F: Field>(m: &Matrix<F>) -> Matrix<F> {
    conjugate(&m.transpose())
}

/// Solves $A W + W A^H = -Q$ exactly ($\operatorname{vec}$: $(I \otimes A + \bar A \otimes I)
/// \operatorname{vec} W = -\operatorname{vec} Q$).
///
/// # Errors
/// `Singular` when the operator is singular ($\lambda_i + \bar\lambda_j = 0$).
pub(crate) fn lyapunov_h<F: Field>(a: &Matrix<F>, q: &Matrix<F>) -> Result<Matrix<F>> {
    let n = a.nrows();
    let i = Matrix::identity(a.field().clone(), n);
    let op = &i.kron(a) + &conjugate(a).kron(&i);
    match op.solve(&-&q.vec())? {
        Some((x, nul)) if nul.ncols() == 0 => x.unvec(n, n),
        _ => Err(Error::Singular),
    }
}

/// Is $A$ Hurwitz? Lyapunov's theorem: $A X + X A^H = -I$ has a positive definite solution
/// (every leading principal minor $> 0$, a sign in $F$; a singular operator,
/// $\lambda_i + \bar\lambda_j = 0$, means not Hurwitz). `None` when a sign is undecided
/// (over $\mathbb{Q}(p)$: a sign of a rational function of the parameters).
pub(crate) fn hurwitz<F: Field>(a: &Matrix<F>) -> Result<Option<bool>> {
    let n = a.nrows();
    let k = a.field();
    let x = match lyapunov_h(a, &Matrix::identity(k.clone(), n)) {
        Ok(x) => x,
        Err(Error::Singular) => return Ok(Some(false)),
        Err(e) => return Err(e),
    };
    let mut decided = true;
    for m in 1..=n {
        match k.sign(&x.submatrix(0, m, 0, m).det()?) {
            Some(Ordering::Greater) => {}
            Some(_) => return Ok(Some(false)),
            None => decided = false,
        }
    }
    Ok(decided.then_some(true))
}

/// Gramians of a stable rational system.
///
/// # Errors
/// `Unstable` when $A$ is not Hurwitz (the Gramian integrals diverge).
pub fn gramians(sys: &StateSpace<Q>) -> Result<Gramians> {
    if !is_hurwitz(&sys.a.charpoly()?) {
        return Err(Error::Unstable("A has an eigenvalue with non-negative real part; the Gramian integrals (eq. 5) diverge".into()));
    }
    let wc = lyapunov(&sys.a, &(&sys.b * &sys.b.transpose()))?;
    let wo = lyapunov(&sys.a.transpose(), &(&sys.c.transpose() * &sys.c))?;
    Ok(Gramians { wc, wo })
}
