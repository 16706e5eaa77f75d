//! The modal table (minimal-realizations paper, Tab. 1 and Tab. 8): per mode the eigenvalue,
//! natural frequency, damping ratio, time constant and period, from the exact eigenvalues.
//!
//! For an eigenvalue $\lambda = \sigma + i\omega_d$: $\omega_n = |\lambda|$,
//! `frequency_hz` $= \omega_n / 2\pi$, `damping_ratio` $\zeta = -\sigma/\omega_n$,
//! `time_constant_s` $= -1/\sigma$ (negative for a growing mode; absent when $\sigma = 0$),
//! `period_s` $= 2\pi/|\omega_d|$ (absent for real modes). A complex pair is one mode, listed
//! with $\omega_d > 0$. The eigenvalues are exact algebraic numbers (certified roots of the
//! characteristic polynomial's irreducible factors); the derived figures are evaluated from
//! their certified approximations. Where the mode's factor has degree $\le 2$ the table also
//! gives exact closed forms: $\omega_n^2 = a_0$ and $\zeta = a_1/(2\sqrt{a_0})$ for
//! $s^2 + a_1 s + a_0$, and $\tau = -1/\lambda$ for a rational $\lambda$.

use crate::algebraic::AlgebraicNumber;
use crate::error::Result;
use crate::field::{Q, Rational};
use crate::jordan::EigenField;
use crate::matrix::Matrix;
use num_traits::{Signed, Zero};
use std::f64::consts::PI;

/// One row of the modal table.
#[derive(Clone, Debug)]
pub struct Mode {
    /// The eigenvalue, a certified algebraic number (its minimal polynomial and region).
    pub eigenvalue: AlgebraicNumber,
    pub approx: (f64, f64),
    pub multiplicity: usize,
    pub frequency_hz: f64,
    pub damping_ratio: Option<f64>,
    pub time_constant_s: Option<f64>,
    pub period_s: Option<f64>,
    /// Exact closed forms where the minimal polynomial has degree <= 2, by figure name.
    pub exact: Vec<(&'static str, ExactFigure)>,
    /// The row stands for a conjugate pair (a real matrix); `false` for a real eigenvalue and
    /// for each eigenvalue of a non-real matrix over $\mathbb{Q}(i)$ (listed one by one).
    pub paired: bool,
}

/// An exact figure of a mode: a rational number or $\pm\sqrt r$ for a rational $r \ge 0$.
#[derive(Clone, Debug, PartialEq)]
pub enum ExactFigure {
    Rational(Rational),
    Sqrt { radicand: Rational, negative: bool },
}

/// The modal table (one row per mode).
#[derive(Clone, Debug)]
pub struct ModalTable {
    pub modes: Vec<Mode>,
}

/// Computes the modal table of a rational matrix ([`modal_table_over`]).
///
/// # Errors
/// `NotSquare`; failures of the root isolation (none expected).
pub fn modal_table(a: &Matrix<Q>) -> Result<ModalTable> {
    modal_table_over(a)
}

/// The modal table of a matrix over any field with a Jordan decomposition (eigenvalues from
/// [`crate::jordan::eigenvalues_over`]). Over a real field ($A$ real) a complex pair is one
/// mode; over $\mathbb{Q}(i)$ the eigenvalues of a non-real $A$ do not come in conjugate
/// pairs, so each is listed (its damping ratio and time constant from its real part, its
/// period from $|\mathrm{Im}\,\lambda|$).
///
/// # Errors
/// `NotSquare`; those of the factorization and of root isolation.
pub fn modal_table_over<F: EigenField>(a: &Matrix<F>) -> Result<ModalTable> {
    let (_, factors) = crate::jordan::eigenvalues_over(a)?;
    // a real matrix (over a real field, or with every entry its own conjugate) has its
    // complex eigenvalues in conjugate pairs
    let k = a.field();
    let real = k.is_real() || a.as_slice().iter().all(|x| k.conj(x).as_ref() == Some(x));
    let mut modes = vec![];
    for (_, mult, _, roots) in factors {
        for (lam, z) in roots {
            if real && z.1 < 0.0 {
                continue; // the conjugate is listed
            }
            modes.push(mode(&lam, z, mult, real && z.1 > 0.0));
        }
    }
    Ok(ModalTable { modes })
}

/// One row: the figures of `lam` (approximation `(re, im)`, algebraic multiplicity `mult`;
/// `paired` when the row stands for `lam` and its conjugate).
fn mode(lam: &AlgebraicNumber, (re, im): (f64, f64), mult: usize, paired: bool) -> Mode {
    let wn = re.hypot(im);
    let mut exact = vec![];
    let mp = lam.minpoly();
    let q = ExactFigure::Rational;
    if mp.deg() == 1 {
        let l = -mp.coeff(0);
        if !l.is_zero() {
            exact.push(("time_constant_s", q(-l.recip())));
            exact.push(("natural_frequency_rad_s", q(l.abs())));
        }
    } else if mp.deg() == 2 && im != 0.0 {
        // mp = (x - lam)(x - conj lam): a0 = |lam|^2, a1 = -2 Re lam
        let (a0, a1) = (mp.coeff(0), mp.coeff(1));
        exact.push(("natural_frequency_squared", q(a0.clone())));
        let sqrt = |radicand: Rational, negative: bool| ExactFigure::Sqrt { radicand, negative };
        exact.push(("natural_frequency_rad_s", sqrt(a0.clone(), false)));
        // zeta = a1 / (2 sqrt(a0)) = sqrt(a1^2 / (4 a0)) with the sign of a1
        let z2 = &a1 * &a1 / (Rational::from_integer(4.into()) * &a0);
        exact.push(("damping_ratio", sqrt(z2, a1.is_negative())));
        if !a1.is_zero() {
            exact.push(("time_constant_s", q(Rational::from_integer(2.into()) / &a1)));
        }
    }
    Mode {
        eigenvalue: lam.clone(),
        approx: (re, im),
        multiplicity: mult,
        frequency_hz: wn / (2.0 * PI),
        damping_ratio: (wn > 0.0).then(|| -re / wn + 0.0),
        time_constant_s: (re != 0.0).then(|| -1.0 / re),
        period_s: (im != 0.0).then(|| 2.0 * PI / im.abs()),
        exact,
        paired,
    }
}
