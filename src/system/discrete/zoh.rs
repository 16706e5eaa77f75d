//! Exact zero-order-hold discretization where $e^{AT}$ is exact: $A$ nilpotent
//! (integrator chains, double integrators, any $A$ with every eigenvalue $0$).
//!
//! With $A^n = 0$ the series stop: $A_d = e^{AT} = \sum_{k<n} A^k T^k / k!$ and
//! $B_d = \int_0^T e^{A\tau} d\tau\, B = \sum_{k<n} A^k T^{k+1}/(k+1)!\, B$, exactly over any
//! field. Self-check: $A_d - I$ is nilpotent, so $\log A_d = \sum_{k \ge 1} (-1)^{k+1}
//! (A_d - I)^k / k$ is a finite sum, and it must equal $A T$; and $A_d - I = A \Gamma$
//! with $B_d = \Gamma B$.
//!
//! Where $A$ has an eigenvalue $\lambda \ne 0$, $e^{AT}$ has the entry $e^{\lambda T}$
//! (on its eigenvector), transcendental for algebraic $\lambda T \ne 0$
//! (Lindemann-Weierstrass): no exact result over a number field exists, and
//! [`zoh_exact`] answers `None` (the float path takes over and says so).

use super::super::StateSpace;
use crate::error::Result;
use crate::field::{Field, Rational};
use crate::matrix::Matrix;

/// The exact zoh discretization and its check, when $A$ is nilpotent.
#[derive(Clone, Debug)]
pub struct ZohExact<K: Field> {
    pub system: StateSpace<K>,
    /// $\log A_d = A T$ and $A_d - I = A \Gamma$, $B_d = \Gamma B$, exactly.
    pub verified: bool,
}

/// The zoh discretization of `s` with sample time `dt` when $A$ is nilpotent, else `None`.
///
/// # Errors
/// `Invalid` for `dt <= 0`.
pub fn zoh_exact<K: Field>(s: &StateSpace<K>, dt: &Rational) -> Result<Option<ZohExact<K>>> {
    if *dt <= Rational::from_integer(0.into()) {
        return Err(crate::error::Error::Invalid(format!(
            "the sample time must be positive, found {dt}"
        )));
    }
    let k = s.field().clone();
    let n = s.nstates();
    let i = Matrix::identity(k.clone(), n);
    let t = k.from_rational(dt);
    // powers A^k T^k / k! until zero (at most n of them for a nilpotent A)
    let mut term = i.clone();
    let mut ad = Matrix::zeros(k.clone(), n, n);
    let mut gamma = Matrix::zeros(k.clone(), n, n);
    let mut j = 0i64;
    while !term.is_zero() {
        if j as usize >= n.max(1) {
            return Ok(None); // A^n != 0: not nilpotent
        }
        ad = &ad + &term;
        // Gamma = sum A^j T^(j+1) / (j+1)!
        let g = term.scale(&k.div(&t, &k.from_i64(j + 1)).expect("j + 1 != 0"));
        gamma = &gamma + &g;
        term = (&s.a * &term).scale(&k.div(&t, &k.from_i64(j + 1)).expect("j + 1 != 0"));
        j += 1;
    }
    let bd = &gamma * &s.b;
    let system = StateSpace::new(ad.clone(), bd.clone(), s.c.clone(), s.d.clone())?;
    // log(A_d) = sum_{k>=1} (-1)^(k+1) X^k / k with X = A_d - I nilpotent
    let x = &ad - &i;
    let mut log = Matrix::zeros(k.clone(), n, n);
    let mut xk = x.clone();
    let mut kk = 1i64;
    while !xk.is_zero() && kk as usize <= n {
        let c = k.div(
            &k.from_i64(if kk % 2 == 1 { 1 } else { -1 }),
            &k.from_i64(kk),
        );
        log = &log + &xk.scale(&c.expect("k != 0"));
        xk = &xk * &x;
        kk += 1;
    }
    let verified = xk.is_zero() && log == s.a.scale(&t) && x == &s.a * &gamma;
    Ok(Some(ZohExact { system, verified }))
}
