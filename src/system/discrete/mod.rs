//! Discrete-time systems $x_{k+1} = A x_k + B u_k$, $y_k = C x_k + D u_k$ with sample time
//! $T$ (the file key `dt`), exactly over any field $K$.
//!
//! | entry point | computes |
//! |---|---|
//! | [`tustin`] | c2d by the bilinear map $s = \frac{2}{T}\frac{z - 1}{z + 1}$: with $M = I - \frac{T}{2} A$, $A_d = M^{-1}(I + \frac{T}{2} A)$, $B_d = T M^{-1} B$, $C_d = C M^{-1}$, $D_d = D + \frac12 C B_d$ (scipy's `cont2discrete` `bilinear`, python-control's `c2d(..., 'tustin')`); $G_d(z) = G(\frac{2}{T}\frac{z-1}{z+1})$ |
//! | [`tustin_inverse`] | d2c, its exact inverse: $N = (A_d + I)^{-1}$, $A = \frac{2}{T}(A_d - I) N$, $B = \frac{2}{T} N B_d$, $C = 2 C_d N$, $D = D_d - C_d N B_d$ |
//! | [`step_sequence`] | $y_k = D + \sum_{i<k} C A^i B$ (unit step on each input, $x_0 = 0$) |
//! | [`impulse_sequence`] | the response to a unit-area pulse $u_0 = 1/T$: $y_0 = D/T$, $y_k = C A^{k-1} B / T$ (python-control, MATLAB) |
//! | [`zoh_exact`] | zero-order hold where $e^{AT}$ is exact ($A$ nilpotent: the series stop), checked by $\log A_d = A T$ |
//! | [`stability`] | $|z| < 1$ decided exactly over $\mathbb{Q}$ (Schur-Cohn, Sturm on the circle) |

pub mod stability;
mod zoh;

pub use zoh::{ZohExact, zoh_exact};

use super::StateSpace;
use crate::error::{Error, Result};
use crate::field::{Field, Rational};
use crate::matrix::Matrix;

/// `T / 2` in the field, refusing $T \le 0$.
fn half(k: &impl Field, dt: &Rational) -> Result<Rational> {
    if *dt <= Rational::from_integer(0.into()) {
        return Err(Error::Invalid(format!(
            "the sample time must be positive, found {dt}"
        )));
    }
    let _ = k;
    Ok(dt / Rational::from_integer(2.into()))
}

/// The Tustin (bilinear) discretization of `s` with sample time `dt`.
///
/// # Errors
/// `Invalid` for `dt <= 0`; `Singular` when $2/T$ is an eigenvalue of $A$ (the map has a
/// pole there).
pub fn tustin<K: Field>(s: &StateSpace<K>, dt: &Rational) -> Result<StateSpace<K>> {
    let k = s.field().clone();
    let h = k.from_rational(&half(&k, dt)?);
    let n = s.nstates();
    let i = Matrix::identity(k.clone(), n);
    let ah = s.a.scale(&h);
    let mi = (&i - &ah).inverse()?;
    let ad = &mi * &(&i + &ah);
    let bd = (&mi * &s.b).scale(&k.from_rational(dt));
    let cd = &s.c * &mi;
    let dd = &s.d + &(&s.c * &bd).scale(&k.from_rational(&Rational::new(1.into(), 2.into())));
    StateSpace::new(ad, bd, cd, dd)
}

/// The continuous system whose Tustin discretization with sample time `dt` is `s`.
///
/// # Errors
/// `Invalid` for `dt <= 0`; `Singular` when $-1$ is an eigenvalue of $A_d$ (it maps to
/// $s = \infty$).
pub fn tustin_inverse<K: Field>(s: &StateSpace<K>, dt: &Rational) -> Result<StateSpace<K>> {
    let k = s.field().clone();
    let h = half(&k, dt)?;
    let two_over_t = k.from_rational(&(Rational::from_integer(1.into()) / h));
    let i = Matrix::identity(k.clone(), s.nstates());
    let nm = (&s.a + &i).inverse()?;
    let a = (&(&s.a - &i) * &nm).scale(&two_over_t);
    let b = (&nm * &s.b).scale(&two_over_t);
    let c = (&s.c * &nm).scale(&k.from_i64(2));
    let d = &s.d - &(&(&s.c * &nm) * &s.b);
    StateSpace::new(a, b, c, d)
}

/// The unit-step responses $y_0, \dots, y_{N-1}$ ($p \times m$ each: column $j$ is the
/// response to a unit step on input $j$ from $x_0 = 0$).
pub fn step_sequence<K: Field>(s: &StateSpace<K>, samples: usize) -> Vec<Matrix<K>> {
    let mut out = Vec::with_capacity(samples);
    let mut y = s.d.clone();
    let mut ab = s.b.clone();
    for _ in 0..samples {
        out.push(y.clone());
        y = &y + &(&s.c * &ab);
        ab = &s.a * &ab;
    }
    out
}

/// The responses to a unit-area pulse $u_0 = 1/T$ on each input: $y_0 = D / T$,
/// $y_k = C A^{k-1} B / T$.
pub fn impulse_sequence<K: Field>(
    s: &StateSpace<K>,
    samples: usize,
    dt: &Rational,
) -> Vec<Matrix<K>> {
    let k = s.field();
    let inv_t = k.from_rational(&(Rational::from_integer(1.into()) / dt));
    let mut out = Vec::with_capacity(samples);
    if samples == 0 {
        return out;
    }
    out.push(s.d.scale(&inv_t));
    out.extend(s.markov(samples - 1).into_iter().map(|m| m.scale(&inv_t)));
    out
}
