//! The damping table (python-control's `damp`): per pole $\lambda = \sigma + j\omega_d$ of
//! $A$ (each pole of a pair listed), $\omega_n = |\lambda|$ in rad/s and Hz,
//! $\zeta = -\sigma/\omega_n$, $\tau = -1/\sigma$.
//!
//! Exact where the pole's minimal polynomial over $\mathbb{Q}$ has degree at most 2 with
//! the pole non-real or rational: $\omega_n^2 = \lambda\bar\lambda$ and
//! $2\zeta\omega_n = -2\sigma$, i.e. $(a_0, a_1)$ of $s^2 + a_1 s + a_0$ for a complex pair,
//! $(\lambda^2, -2\lambda)$ for a rational pole, and $\tau = 2/a_1$ resp. $-1/\lambda$.

use crate::algebraic::{AlgebraicNumber, roots};
use crate::error::Result;
use crate::field::{Q, Rational};
use crate::matrix::Matrix;
use num_traits::Zero;
use std::f64::consts::PI;

/// One pole of the damping table.
#[derive(Clone, Debug)]
pub struct DampRow {
    /// The pole, exactly (its minimal polynomial and isolating region; displayed in
    /// `report/`).
    pub pole: AlgebraicNumber,
    pub approx: (f64, f64),
    pub multiplicity: usize,
    pub wn_rad_s: f64,
    pub wn_hz: f64,
    /// `None` for a pole at 0.
    pub zeta: Option<f64>,
    /// `None` on the imaginary axis (negative for a growing mode).
    pub time_constant_s: Option<f64>,
    /// Exact $\omega_n^2$, $2\zeta\omega_n$ and $\tau$ where they are rational.
    pub wn_squared: Option<Rational>,
    pub two_zeta_wn: Option<Rational>,
    pub time_constant_exact: Option<Rational>,
}

/// The damping table of a rational `a`, poles in the order of [`crate::algebraic::roots`]
/// (real ascending, then complex by real and imaginary part).
///
/// # Errors
/// `NotSquare`; root isolation failures.
pub fn damp(a: &Matrix<Q>) -> Result<Vec<DampRow>> {
    let cp = a.charpoly()?;
    Ok(roots(&cp)?
        .iter()
        .map(|(lam, mult)| row(lam, lam.approx(), *mult))
        .collect())
}

/// The damping table of `a` over any field with exact eigenvalues ($\mathbb{Q}$,
/// $\mathbb{Q}(i)$, $\mathbb{Q}(\sqrt d)$, ...): the roots of each irreducible factor of
/// det(sI - A) over the field, never those of the conjugate, in the order of [`damp`].
///
/// # Errors
/// `NotSquare`; as [`crate::jordan::EigenField::eigen_factors`].
pub fn damp_over<F: crate::jordan::EigenField>(a: &Matrix<F>) -> Result<Vec<DampRow>> {
    a.check_square("damp")?;
    let factors = F::eigen_factors(&a.charpoly()?)?;
    let mut out = vec![];
    for (_, mult, _, rs) in factors {
        for (lam, z) in rs {
            out.push(row(&lam, z, mult));
        }
    }
    // the order of [`damp`] over every field (real ascending, then complex)
    out.sort_by(|x, y| crate::algebraic::number::cmp_complex(&x.pole, &y.pole));
    Ok(out)
}

fn row(lam: &AlgebraicNumber, (re, im): (f64, f64), mult: usize) -> DampRow {
    let wn = re.hypot(im);
    let mp = lam.minpoly();
    let (mut wn2, mut tzw, mut tau) = (None, None, None);
    if let Some(l) = lam.to_rational() {
        wn2 = Some(&l * &l);
        tzw = Some(-(&l + &l));
        tau = (!l.is_zero()).then(|| -l.recip());
    } else if mp.deg() == 2 && !lam.is_real() {
        let a1 = mp.coeff(1);
        wn2 = Some(mp.coeff(0));
        tau = (!a1.is_zero()).then(|| Rational::from_integer(2.into()) / &a1);
        tzw = Some(a1);
    }
    DampRow {
        pole: lam.clone(),
        approx: (re, im),
        multiplicity: mult,
        wn_rad_s: wn,
        wn_hz: wn / (2.0 * PI),
        zeta: (wn > 0.0).then(|| -re / wn + 0.0),
        time_constant_s: (re != 0.0).then(|| -1.0 / re),
        wn_squared: wn2,
        two_zeta_wn: tzw,
        time_constant_exact: tau,
    }
}
