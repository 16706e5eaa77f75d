//! Step and impulse responses in closed form, from the Jordan form of $A$.
//!
//! With $e^{At} = \sum_\theta \sum_k t^k e^{\theta t} G_{\theta,k}$
//! ([`crate::jordan::FreeResponse`]) and $H_{\theta,k} = C G_{\theta,k} B$ (exact in
//! $\mathbb{Q}(\theta)$):
//! $$h(t) = C e^{At} B = \sum_\theta \sum_k t^k e^{\theta t} H_{\theta,k} \quad (t > 0,
//! \text{ plus } D\,\delta(t)), \qquad
//! s(t) = D + \sum_\theta \sum_k H_{\theta,k}\, I_k(\theta, t),\quad
//! I_k(\theta, t) = \int_0^t \tau^k e^{\theta\tau}\, d\tau .$$
//! The coefficients are exact; only the evaluation at a time $t$ (for tables and plots) is in
//! floating point. Two identities are checked exactly, over $\mathbb{Q}$, by summing the
//! traces $\operatorname{Tr}_{\mathbb{Q}(\theta)/\mathbb{Q}}$ over the components:
//! $\sum_\theta \operatorname{Tr} H_{\theta,0} = C B$ (the impulse response at $t = 0^+$) and,
//! when $A$ is invertible,
//! $D + \sum_{\theta,k} \operatorname{Tr}\big(k!\,(-\theta)^{-(k+1)} H_{\theta,k}\big)
//! = D - C A^{-1} B$ (the DC gain, the step response's final value when $A$ is Hurwitz),
//! which is $(\theta + N)^{-1} = \sum_k (-N)^k \theta^{-(k+1)}$ on each generalized
//! eigenspace.

use crate::algebraic::Ext;
use crate::error::Result;
use crate::field::{Field, Q, Rational};
use crate::jordan::{EigenField, JordanForm, jordan_over};
use crate::matrix::Matrix;
use crate::poly::newton_power_sums;
use crate::system::StateSpace;
use num_complex::Complex64;
use num_traits::{One, Zero};

/// One exact output term $H_{\theta,k} = C G_{\theta,k} B$ ($p \times m$ over the component
/// field) and its float values at each conjugate root.
#[derive(Clone, Debug)]
pub struct OutputTerm<F: Field = Q> {
    /// Index into [`JordanForm::components`].
    pub component: usize,
    /// The power $k$ of $t$.
    pub power: usize,
    pub coeff: Matrix<Ext<F>>,
    /// `(theta_j, H` at `theta_j)` for every root of the component.
    values: Vec<(Complex64, Vec<Complex64>)>,
}

/// The closed-form step and impulse responses of a system over $F$ ($\mathbb{Q}$,
/// $\mathbb{Q}(\sqrt d)$, $\mathbb{Q}(i)$: written once; the traces are
/// $\operatorname{Tr}_{F(\theta)/F}$).
#[derive(Clone, Debug)]
pub struct ClosedFormResponse<F: Field = Q> {
    pub jordan: JordanForm<F>,
    pub terms: Vec<OutputTerm<F>>,
    /// $D$.
    pub d: Matrix<F>,
    /// $C B$ as computed by the sum of traces of $H_{\theta,0}$ (exact).
    pub impulse_at_zero: Matrix<F>,
    /// $D - C A^{-1} B$ from the sum of the traces (exact; `None` when $A$ is singular).
    pub dc_gain: Option<Matrix<F>>,
    /// The identities of the module docs held exactly (and the Jordan form verified).
    pub verified: bool,
    noutputs: usize,
    ninputs: usize,
}

fn factorial(k: usize) -> Rational {
    (1..=k).fold(Rational::one(), |acc, i| {
        acc * Rational::from_integer(i.into())
    })
}

/// $\int_0^t \tau^k e^{\theta\tau} d\tau$ in floating point (series for small $|\theta t|$).
pub fn integral_power_exp(k: usize, theta: Complex64, t: f64) -> Complex64 {
    let z = theta * t;
    if z.norm() < 1.0 {
        // sum_j theta^j t^(k+j+1) / (j! (k+j+1))
        let mut term = Complex64::new(t.powi(k as i32 + 1), 0.0); // theta^j t^(k+j+1) / j!
        let mut sum = Complex64::zero();
        for j in 0..60 {
            let add = term / (k + j + 1) as f64;
            sum += add;
            if add.norm() <= 1e-17 * sum.norm() {
                break;
            }
            term = term * z / (j + 1) as f64;
        }
        return sum;
    }
    // k!/(-theta)^(k+1) (1 - e^(theta t) sum_{j<=k} (-theta t)^j / j!)
    let mut partial = Complex64::zero();
    let mut pw = Complex64::one();
    for j in 0..=k {
        if j > 0 {
            pw = pw * (-z) / j as f64;
        }
        partial += pw;
    }
    let fact: f64 = (1..=k).map(|i| i as f64).product();
    fact / (-theta).powi(k as i32 + 1) * (Complex64::one() - z.exp() * partial)
}

impl<F: EigenField> ClosedFormResponse<F> {
    /// Builds the exact terms from the Jordan form of `ss.a` and checks the identities.
    ///
    /// # Errors
    /// As [`jordan_over`] (a characteristic polynomial that cannot be factored, limits).
    pub fn new(ss: &StateSpace<F>) -> Result<Self> {
        let jf = jordan_over(&ss.a)?;
        let fr = jf.free_response();
        let (p, m) = (ss.noutputs(), ss.ninputs());
        let base = ss.field().clone();
        let mut terms = vec![];
        let mut h0 = Matrix::zeros(base.clone(), p, m);
        let mut dc = Matrix::zeros(base.clone(), p, m);
        let mut singular = false;
        for g in &fr.terms {
            let c = &jf.components[g.component];
            let k = &c.field;
            let h = &(&c.lift(&ss.c) * &g.coeff) * &c.lift(&ss.b);
            let ps = newton_power_sums(&c.factor, c.factor.deg().saturating_sub(1));
            let trace = |x: &Matrix<Ext<F>>| {
                x.map(&base, |e: &crate::algebraic::ExtElem<F::Elem>| {
                    e.0.iter()
                        .zip(&ps)
                        .fold(base.zero(), |acc, (a, b)| base.add(&acc, &base.mul(a, b)))
                })
            };
            if g.power == 0 {
                h0 = &h0 + &trace(&h);
            }
            let theta = c.root_elem();
            match k.inv(&k.neg(&theta)) {
                Some(minv) => {
                    let mut s = k.from_rational(&factorial(g.power));
                    for _ in 0..=g.power {
                        s = k.mul(&s, &minv);
                    }
                    dc = &dc + &trace(&h.scale(&s));
                }
                None => singular = true,
            }
            let values = c
                .roots
                .iter()
                .enumerate()
                .map(|(j, &(re, im))| {
                    let emb = c.embedding(j, "t");
                    let v = (0..p)
                        .flat_map(|r| (0..m).map(move |q| (r, q)))
                        .map(|(r, q)| {
                            let (a, b) = emb.approx(h.get(r, q));
                            Complex64::new(a, b)
                        })
                        .collect();
                    (Complex64::new(re, im), v)
                })
                .collect();
            terms.push(OutputTerm {
                component: g.component,
                power: g.power,
                coeff: h,
                values,
            });
        }
        let cb = &ss.c * &ss.b;
        let mut verified = jf.verified && h0 == cb;
        let dc_gain = if singular {
            None
        } else {
            let dc = &ss.d + &dc;
            // the identity against the direct solve D - C A^{-1} B
            match ss.a.inverse() {
                Ok(ai) => verified &= dc == &ss.d - &(&(&ss.c * &ai) * &ss.b),
                Err(_) => verified = false,
            }
            Some(dc)
        };
        Ok(ClosedFormResponse {
            jordan: jf,
            terms,
            d: ss.d.clone(),
            impulse_at_zero: h0,
            dc_gain,
            verified,
            noutputs: p,
            ninputs: m,
        })
    }

    fn eval(&self, f: impl Fn(usize, Complex64) -> Complex64) -> Vec<Vec<Complex64>> {
        let (p, m) = (self.noutputs, self.ninputs);
        let mut out = vec![Complex64::zero(); p * m];
        for term in &self.terms {
            for (theta, v) in &term.values {
                let w = f(term.power, *theta);
                for (o, x) in out.iter_mut().zip(v) {
                    *o += w * x;
                }
            }
        }
        (0..p)
            .map(|i| (0..m).map(|j| out[i * m + j]).collect())
            .collect()
    }

    /// $h(t) = C e^{At} B$ ($p \times m$, floats; the $D\,\delta(t)$ part left out): its real
    /// part (the whole value over a real field).
    pub fn impulse_at(&self, t: f64) -> Vec<Vec<f64>> {
        real_part(self.impulse_at_complex(t))
    }

    /// $h(t)$ as complex numbers (over a field that is not real, e.g. $\mathbb{Q}(i)$).
    pub fn impulse_at_complex(&self, t: f64) -> Vec<Vec<Complex64>> {
        self.eval(|k, theta| (theta * t).exp() * t.powi(k as i32))
    }

    /// $s(t) = D + \int_0^t C e^{A\tau} B\, d\tau$ ($p \times m$, floats): its real part.
    pub fn step_at(&self, t: f64) -> Vec<Vec<f64>> {
        real_part(self.step_at_complex(t))
    }

    /// $s(t)$ as complex numbers.
    pub fn step_at_complex(&self, t: f64) -> Vec<Vec<Complex64>> {
        let k = self.d.field();
        let mut s = self.eval(|j, theta| integral_power_exp(j, theta, t));
        for (i, row) in s.iter_mut().enumerate() {
            for (j, x) in row.iter_mut().enumerate() {
                let (re, im) = k.approx(self.d.get(i, j)).unwrap_or((f64::NAN, f64::NAN));
                *x += Complex64::new(re, im);
            }
        }
        s
    }
}

fn real_part(v: Vec<Vec<Complex64>>) -> Vec<Vec<f64>> {
    v.into_iter()
        .map(|r| r.into_iter().map(|z| z.re).collect())
        .collect()
}

/// A time horizon showing the response settle: 7 time constants of the slowest stable pole,
/// at least 3 periods of the slowest oscillation; 10 s when every pole is at 0.
pub fn default_horizon(poles: &[(f64, f64)]) -> f64 {
    let mut t: f64 = 0.0;
    for &(re, im) in poles {
        let r = (re * re + im * im).sqrt();
        if r < 1e-12 {
            continue;
        }
        if re < -1e-9 * r {
            t = t.max(7.0 / -re);
        } else {
            t = t.max(5.0 / r);
        }
        if im.abs() > 1e-9 * r {
            t = t.max(3.0 * 2.0 * std::f64::consts::PI / im.abs());
        }
    }
    if t == 0.0 {
        return 10.0;
    }
    // rounded up to 1, 2, 5 x 10^k for a readable time axis
    let t = t.min(1e6);
    let mag = 10f64.powf(t.log10().floor());
    [1.0, 2.0, 5.0, 10.0]
        .iter()
        .map(|s| s * mag)
        .find(|s| *s >= t * (1.0 - 1e-12))
        .unwrap_or(10.0 * mag)
}

/// Enough points on `[0, t_end]` for 20 per period of the fastest oscillation (and 20 per
/// time constant of the fastest decay), between 500 and 5000.
pub fn default_points(t_end: f64, poles: &[(f64, f64)]) -> usize {
    let fastest = poles
        .iter()
        .map(|&(re, im)| (re.abs(), im.abs() / (2.0 * std::f64::consts::PI)))
        .map(|(rate, freq)| rate.max(freq))
        .fold(0.0, f64::max);
    let want = (t_end * fastest * 20.0).ceil();
    if want.is_finite() {
        (want as usize).clamp(500, 5000)
    } else {
        5000
    }
}

/// `points` evenly spaced times from 0 to `t_end`.
pub fn time_grid(t_end: f64, points: usize) -> Vec<f64> {
    let n = points.max(2);
    (0..n).map(|k| t_end * k as f64 / (n - 1) as f64).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integral_matches_both_branches() {
        for &(k, re, im) in &[
            (0usize, -1.0, 0.0),
            (2, -0.3, 2.0),
            (1, 0.0, 0.0),
            (3, 0.5, -1.0),
        ] {
            let th = Complex64::new(re, im);
            for &t in &[0.2, 0.99, 1.01, 3.0] {
                // trapezoid reference
                let n = 20000;
                let h = t / n as f64;
                let f = |s: f64| (th * s).exp() * s.powi(k as i32);
                let mut acc = (f(0.0) + f(t)) / 2.0;
                for i in 1..n {
                    acc += f(i as f64 * h);
                }
                let r = acc * h;
                let v = integral_power_exp(k, th, t);
                assert!(
                    (v - r).norm() < 1e-6 * (1.0 + r.norm()),
                    "{k} {th} {t}: {v} {r}"
                );
            }
        }
    }
}
