//! Gain and phase margins of a SISO system over $\mathbb{Q}$, $\mathbb{Q}(\sqrt d)$ and
//! $\mathbb{Q}(i)$, exactly (python-control's `margin` / `stability_margins`, its definitions
//! and choices). One computation for every field: the parts on the imaginary axis are
//! polynomials in $\omega$ over $\mathbb{Q}(\sqrt e)$ ([`axis`]; $\mathbb{Q}$ for
//! $\mathbb{Q}$ and $\mathbb{Q}(i)$), their real roots and signs decided exactly through
//! rational polynomials. For a system with complex coefficients ($\mathbb{Q}(i)$) the
//! frequencies are $\omega \ge 0$ as for a real one (its Nyquist curve is not symmetric, so
//! crossings at $\omega < 0$ are not reported), and $\omega = 0$ counts only where
//! $G(0)$ is real.
//!
//! With $G = N/D$ in lowest terms and $N(j\omega) = N_r + j N_i$, $D(j\omega) = D_r + j D_i$
//! (real polynomials in $\omega$, [`algebra::split_imaginary_axis`]):
//! $N \bar D = P + j I$ with $P = N_r D_r + N_i D_i$, $I = N_i D_r - N_r D_i$, and
//! $|D|^2 = D_r^2 + D_i^2$.
//!
//! - Phase crossovers: the real roots $\omega_{pc} \ge 0$ of $I$ (odd in $\omega$, so $0$ is
//!   one when $I \not\equiv 0$, as python-control counts it) with $P(\omega_{pc}) < 0$,
//!   decided exactly; there $G(j\omega) = P/|D|^2$ is real negative and
//!   the gain margin is $g = 1/|G| = -|D|^2/P$ at $\omega_{pc}$, an algebraic number.
//! - Gain crossovers: the positive real roots $\omega_{gc}$ of $|N|^2 - |D|^2$ (even in
//!   $\omega$); the phase margin is $\mathrm{PM} = (\arg G(j\omega_{gc}) \bmod 360^\circ) -
//!   180^\circ$, with the exact $\cos \mathrm{PM} = -P/|D|^2$ at $\omega_{gc}$.
//! - The margins reported are python-control's: the gain margin whose $|\log g|$ is least,
//!   the phase margin whose $|\mathrm{PM}|$ is least; none of a kind means infinite.
//!
//! `verified`: every crossing's minimal polynomial divides its defining polynomial ($I$ or
//! $|N|^2 - |D|^2$; over $\mathbb{Q}(\sqrt e)$ their norms), and every margin value's minimal
//! polynomial vanishes at the class of its rational expression in $\mathbb{Q}(\omega)$
//! (exact arithmetic in that field; over $\mathbb{Q}(\sqrt e)$: shares a root with it).

pub mod algebra;
pub mod axis;

use crate::algebraic::AlgebraicNumber;
use crate::error::{Error, Result};
use crate::field::{Field, Q, Rational};
use crate::poly::Poly;
use crate::system::StateSpace;
use axis::{AxisField, AxisPoly, axis_sign_at, axis_value_at, positive_roots};
use num_complex::Complex64;
use num_traits::Zero;
use std::cmp::Ordering;

/// A phase crossover: $G(j\omega)$ real and negative, $G(j\omega) = -1/g$.
#[derive(Clone, Debug)]
pub struct PhaseCrossing {
    pub w: AlgebraicNumber,
    /// The gain margin $g = 1/|G(j\omega)|$ at this crossing.
    pub gain_margin: AlgebraicNumber,
}

/// A gain crossover: $|G(j\omega)| = 1$.
#[derive(Clone, Debug)]
pub struct GainCrossing {
    pub w: AlgebraicNumber,
    /// $\cos \mathrm{PM} = -\mathrm{Re}\, G(j\omega)$, exact.
    pub cos_phase_margin: AlgebraicNumber,
    /// The phase margin in degrees, in $[-180, 180)$.
    pub phase_margin_deg: f64,
}

/// Margins of a SISO loop transfer function over `K`.
#[derive(Clone, Debug)]
pub struct Margins<K: Field = Q> {
    pub num: Poly<K>,
    pub den: Poly<K>,
    /// $I(\omega) = \mathrm{Im}(N \bar D)$ at $s = j\omega$ (rational: over
    /// $\mathbb{Q}(\sqrt e)$ its norm $I \bar I$, whose real roots hold $I$'s).
    pub imag_poly: Poly<Q>,
    /// $|N(j\omega)|^2 - |D(j\omega)|^2$ (rational as `imag_poly`).
    pub magnitude_poly: Poly<Q>,
    /// Ascending in $\omega$.
    pub phase_crossings: Vec<PhaseCrossing>,
    /// Ascending in $\omega$.
    pub gain_crossings: Vec<GainCrossing>,
    /// $G(j\omega)$ is real for every $\omega$ ($I \equiv 0$): no phase crossover is counted.
    pub real_everywhere: bool,
    /// $|G(j\omega)| = 1$ for every $\omega$: no gain crossover is counted.
    pub unit_gain_everywhere: bool,
    /// The crossing whose gain margin is reported (`None`: infinite).
    pub gm_index: Option<usize>,
    /// The crossing whose phase margin is reported (`None`: infinite).
    pub pm_index: Option<usize>,
    pub verified: bool,
}

impl<K: Field> Margins<K> {
    /// The reported gain margin, `None` when infinite.
    pub fn gain_margin(&self) -> Option<&PhaseCrossing> {
        self.gm_index.map(|i| &self.phase_crossings[i])
    }
    /// The reported phase margin, `None` when infinite.
    pub fn phase_margin(&self) -> Option<&GainCrossing> {
        self.pm_index.map(|i| &self.gain_crossings[i])
    }
}

/// The margins of a SISO state-space system over $\mathbb{Q}$, $\mathbb{Q}(\sqrt d)$ or
/// $\mathbb{Q}(i)$ (from its transfer function in lowest terms).
///
/// # Errors
/// `Invalid` when the system is not SISO; `Limit` from root separation.
pub fn margins<K: AxisField>(s: &StateSpace<K>) -> Result<Margins<K>> {
    if s.ninputs() != 1 || s.noutputs() != 1 {
        return Err(Error::Invalid(format!(
            "margins need a SISO system (this one has {} outputs and {} inputs)",
            s.noutputs(),
            s.ninputs()
        )));
    }
    let g = s.transfer_matrix()?;
    let f = &g.entries[0][0];
    margins_tf(&f.num, &f.den)
}

/// A rational polynomial holding the real roots of `p`: `p` itself over $\mathbb{Q}$, else
/// its norm.
fn rational_hull(p: &AxisPoly) -> Poly<Q> {
    if p.is_rational() {
        p.q.clone()
    } else {
        p.norm()
    }
}

/// The margins of $G = N/D$ (`den` nonzero; the fraction need not be reduced, but a factor
/// common to both that vanishes on the imaginary axis hides a crossing there).
///
/// # Errors
/// `DivisionByZero` for a zero `den`; `Limit` from root separation.
pub fn margins_tf<K: AxisField>(num: &Poly<K>, den: &Poly<K>) -> Result<Margins<K>> {
    if den.is_zero() {
        return Err(Error::DivisionByZero);
    }
    let k = den.field().clone();
    let (nr, ni) = k.split_axis(num);
    let (dr, di) = k.split_axis(den);
    let p = nr.mul(&dr).add(&ni.mul(&di));
    let im = ni.mul(&dr).sub(&nr.mul(&di));
    let d2 = dr.mul(&dr).add(&di.mul(&di));
    let n2 = nr.mul(&nr).add(&ni.mul(&ni));
    let mag = n2.sub(&d2);
    let (im_q, mag_q) = (rational_hull(&im), rational_hull(&mag));
    let mut verified = true;
    let mut phase_crossings = vec![];
    // python-control counts w = 0 (a root of the odd I) when G(0) is finite and negative:
    // the Nyquist curve starts on the negative real axis, gain margin 1/|G(0)|
    let zero = AlgebraicNumber::from_rational(&Rational::zero());
    let real_at_0 =
        im.q.eval(&Rational::zero()).is_zero() && im.r.eval(&Rational::zero()).is_zero();
    if !im.is_zero() && real_at_0 && axis_sign_at(&p, &zero)? == Ordering::Less {
        let (gm, ok) = axis_value_at(&d2.neg(), &p, &zero)?;
        verified &= ok;
        phase_crossings.push(PhaseCrossing {
            w: zero,
            gain_margin: gm,
        });
    }
    if !im.is_zero() {
        for w in positive_roots(&im)? {
            verified &= im_q.rem(w.minpoly()).is_zero();
            if axis_sign_at(&p, &w)? != Ordering::Less {
                continue; // the positive real axis, a zero or a pole on the axis
            }
            let (gm, ok) = axis_value_at(&d2.neg(), &p, &w)?;
            verified &= ok;
            phase_crossings.push(PhaseCrossing { w, gain_margin: gm });
        }
    }
    let mut gain_crossings = vec![];
    if !mag.is_zero() {
        for w in positive_roots(&mag)? {
            verified &= mag_q.rem(w.minpoly()).is_zero();
            let (c, ok) = axis_value_at(&p.neg(), &d2, &w)?;
            verified &= ok;
            let pm = phase_margin_deg(&[&nr, &ni, &dr, &di], w.approx().0);
            gain_crossings.push(GainCrossing {
                w,
                cos_phase_margin: c,
                phase_margin_deg: pm,
            });
        }
    }
    let gm_index = argmin(
        phase_crossings
            .iter()
            .map(|c| c.gain_margin.approx().0.ln().abs()),
    );
    let pm_index = argmin(gain_crossings.iter().map(|c| c.phase_margin_deg.abs()));
    Ok(Margins {
        num: num.clone(),
        den: den.clone(),
        imag_poly: im_q,
        magnitude_poly: mag_q,
        phase_crossings,
        gain_crossings,
        real_everywhere: im.is_zero(),
        unit_gain_everywhere: mag.is_zero(),
        gm_index,
        pm_index,
        verified,
    })
}

/// The first index of the least value (`None` for none).
fn argmin(xs: impl Iterator<Item = f64>) -> Option<usize> {
    let mut best: Option<(usize, f64)> = None;
    for (i, x) in xs.enumerate() {
        if best.is_none_or(|(_, b)| x < b) {
            best = Some((i, x));
        }
    }
    best.map(|(i, _)| i)
}

/// $G(j\omega)$ in floats.
pub fn eval_jw(num: &Poly<Q>, den: &Poly<Q>, w: f64) -> Complex64 {
    let ev = |p: &Poly<Q>| {
        p.coeffs()
            .iter()
            .rev()
            .fold(Complex64::new(0.0, 0.0), |acc, c| {
                acc * Complex64::new(0.0, w) + crate::field::rational_to_f64(c)
            })
    };
    ev(num) / ev(den)
}

/// python-control's phase margin at a gain crossover: `remainder(angle(G, deg), 360) - 180`,
/// from the axis parts `[Nr, Ni, Dr, Di]` in floats.
fn phase_margin_deg(parts: &[&AxisPoly; 4], w: f64) -> f64 {
    let v: Vec<f64> = parts.iter().map(|p| p.eval_f64(w)).collect();
    let g = Complex64::new(v[0], v[1]) / Complex64::new(v[2], v[3]);
    g.arg().to_degrees().rem_euclid(360.0) - 180.0
}

/// `20 log10(g)`.
pub fn to_db(g: f64) -> f64 {
    20.0 * g.log10()
}
