//! Gramians of stable systems by exact Lyapunov solves (paper eq. 6).
//!
//! $A W_c + W_c A^T = -BB^T$ and $A^T W_o + W_o A = -C^TC$ are solved as the linear systems
//! $(I \otimes A + A \otimes I)\,\mathrm{vec}(W) = -\mathrm{vec}(Q)$, uniquely solvable when no
//! two eigenvalues of $A$ sum to zero. Stability is decided exactly over $\mathbb Q$ by the
//! Routh–Hurwitz test on $\det(sI - A)$.

use crate::error::{Error, Result};
use crate::field::{Field, Q, Rational};
use crate::matrix::Matrix;
use crate::poly::Poly;
use crate::system::StateSpace;
use num_traits::{Signed, Zero};

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

/// One Gramian with its exact check.
#[derive(Clone, Debug)]
pub struct Gramian {
    pub kind: GramType,
    pub w: Matrix<Q>,
    /// The Lyapunov residual is exactly zero and $W = W^T$.
    pub verified: bool,
}

/// The controllability or observability Gramian of a stable rational system, verified by
/// substituting it back into its Lyapunov equation (exact arithmetic).
///
/// # Errors
/// `Unstable` when $A$ is not Hurwitz (decided exactly, Routh–Hurwitz on $\det(sI - A)$).
pub fn gramian(sys: &StateSpace<Q>, kind: GramType) -> Result<Gramian> {
    if !is_hurwitz(&sys.a.charpoly()?) {
        return Err(Error::Unstable(
            "A has an eigenvalue with non-negative real part; the Gramian integral diverges".into(),
        ));
    }
    let (a, q) = match kind {
        GramType::Controllability => (sys.a.clone(), &sys.b * &sys.b.transpose()),
        GramType::Observability => (sys.a.transpose(), &sys.c.transpose() * &sys.c),
    };
    let w = lyapunov(&a, &q)?;
    let residual = &(&(&a * &w) + &(&w * &a.transpose())) + &q;
    let zero = Matrix::zeros(Q, w.nrows(), w.ncols());
    let verified = residual == zero && w == w.transpose();
    Ok(Gramian { kind, w, verified })
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
