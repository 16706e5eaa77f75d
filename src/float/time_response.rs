//! Float step and impulse responses on an even time grid.
//!
//! With $\Phi = \exp\left(\begin{bmatrix} A & B \\ 0 & 0 \end{bmatrix} \Delta t\right)
//! = \begin{bmatrix} \Phi_{11} & \Phi_{12} \\ 0 & I \end{bmatrix}$ (nalgebra's Padé
//! `exp`), the step response is $x_{k+1} = \Phi_{11} x_k + \Phi_{12} u$, $x_0 = 0$, exact for
//! a constant input up to rounding (zero-order hold); the impulse response is
//! $x_0 = B$, $x_{k+1} = \Phi_{11} x_k$, $y = C x$ (the $D\,\delta(t)$ part left out).
//!
//! | entry point | returns |
//! |---|---|
//! | [`time_response`] with [`Input::Step`] | $s(t_k)$, one $p \times m$ matrix per time |
//! | [`time_response`] with [`Input::Impulse`] | $h(t_k) = C e^{A t_k} B$ |
//!
//! Both are written once for real and complex matrices ([`FloatScalar`]): a system with
//! complex coefficients (over $\mathbb{Q}(i)$) has a complex response, as in python-control
//! and MATLAB.

use nalgebra::DMatrix;

use super::{FloatScalar, check_system};
use crate::error::{Error, Result};

fn propagators<T: FloatScalar>(
    a: &DMatrix<T>,
    b: &DMatrix<T>,
    dt: f64,
) -> Result<(DMatrix<T>, DMatrix<T>)> {
    if !(dt.is_finite() && dt > 0.0) {
        return Err(Error::Invalid("time response: need a time step > 0".into()));
    }
    let (n, m) = (a.nrows(), b.ncols());
    let mut big = DMatrix::zeros(n + m, n + m);
    big.view_mut((0, 0), (n, n))
        .copy_from(&(a * T::from_real(dt)));
    big.view_mut((0, n), (n, m))
        .copy_from(&(b * T::from_real(dt)));
    let phi = big.exp();
    if phi.iter().any(|x| !x.is_finite()) {
        return Err(Error::Invalid(
            "time response: the matrix exponential overflows on this horizon".into(),
        ));
    }
    Ok((
        phi.view((0, 0), (n, n)).into_owned(),
        phi.view((0, n), (n, m)).into_owned(),
    ))
}

/// Zero-order-hold discretization with sample time `dt`: $A_d = e^{A T}$,
/// $B_d = \int_0^T e^{A \tau} d\tau\, B$, both read off $\exp([[A, B], [0, 0]]\, T)$
/// (python-control's and scipy's `zoh`).
///
/// # Errors
/// `Invalid` for `dt` not finite and positive, or an overflowing exponential.
pub fn zoh(a: &DMatrix<f64>, b: &DMatrix<f64>, dt: f64) -> Result<(DMatrix<f64>, DMatrix<f64>)> {
    propagators(a, b, dt)
}

fn step_of(times: &[f64]) -> Result<f64> {
    match times {
        [] | [_] => Ok(1.0),
        [t0, t1, ..] => {
            if *t0 != 0.0 {
                return Err(Error::Invalid(
                    "time response: the grid starts at t = 0".into(),
                ));
            }
            Ok(t1 - t0)
        }
    }
}

/// The input of [`time_response`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Input {
    /// Every input a unit step at $t = 0$: the step response $s(t_k)$.
    Step,
    /// Every input a unit impulse at $t = 0$: $h(t_k) = C e^{A t_k} B$ (the $D\,\delta(t)$
    /// part left out).
    Impulse,
}

/// The step or impulse response of $(A, B, C, D)$ at the even grid `times` (starting at 0),
/// one $p \times m$ matrix per time, by one recursion
/// $x_{k+1} = \Phi_{11} x_k + \Phi_{12} u$, $y_k = C x_k + D u$: the step has $x_0 = 0$,
/// $u = 1$; the impulse $x_0 = B$, $u = 0$.
///
/// # Errors
/// Shape errors as [`super::freqresp`]; a grid that is not even from 0; overflow.
pub fn time_response<T: FloatScalar>(
    input: Input,
    [a, b, c, d]: [&DMatrix<T>; 4],
    times: &[f64],
) -> Result<Vec<DMatrix<T>>> {
    let (what, step) = match input {
        Input::Step => ("step response", true),
        Input::Impulse => ("impulse response", false),
    };
    let (n, m, _) = check_system(what, a, b, c, d)?;
    let dt = step_of(times)?;
    let feed = if step {
        d.clone()
    } else {
        DMatrix::zeros(d.nrows(), m)
    };
    if n == 0 {
        return Ok(vec![feed; times.len()]);
    }
    let (p11, p12) = propagators(a, b, dt)?;
    let mut x = if step {
        DMatrix::zeros(n, m)
    } else {
        b.clone()
    };
    let mut out = Vec::with_capacity(times.len());
    for _ in times {
        out.push(c * &x + &feed);
        x = &p11 * &x;
        if step {
            x += &p12;
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn first_order_lag() {
        // 1/(s + 2): step 1/2 (1 - e^{-2t}), impulse e^{-2t}
        let a = DMatrix::from_element(1, 1, -2.0);
        let one = DMatrix::from_element(1, 1, 1.0);
        let z = DMatrix::zeros(1, 1);
        let ts: Vec<f64> = (0..11).map(|k| k as f64 * 0.3).collect();
        let s = time_response(Input::Step, [&a, &one, &one, &z], &ts).unwrap();
        let h = time_response(Input::Impulse, [&a, &one, &one, &z], &ts).unwrap();
        for (k, t) in ts.iter().enumerate() {
            assert!((s[k][(0, 0)] - 0.5 * (1.0 - (-2.0 * t).exp())).abs() < 1e-12);
            assert!((h[k][(0, 0)] - (-2.0 * t).exp()).abs() < 1e-12);
        }
    }

    #[test]
    fn complex_rotation() {
        // x' = (i - 1/2) x + u: impulse e^{(i - 1/2) t}, step (e^{(i - 1/2) t} - 1)/(i - 1/2)
        use num_complex::Complex;
        let lam = Complex::new(-0.5, 1.0);
        let a = DMatrix::from_element(1, 1, lam);
        let one = DMatrix::from_element(1, 1, Complex::new(1.0, 0.0));
        let z = DMatrix::from_element(1, 1, Complex::new(0.0, 0.0));
        let ts: Vec<f64> = (0..21).map(|k| k as f64 * 0.25).collect();
        let s = time_response(Input::Step, [&a, &one, &one, &z], &ts).unwrap();
        let h = time_response(Input::Impulse, [&a, &one, &one, &z], &ts).unwrap();
        for (k, t) in ts.iter().enumerate() {
            let e = (lam * t).exp();
            assert!((h[k][(0, 0)] - e).norm() < 1e-12);
            assert!((s[k][(0, 0)] - (e - 1.0) / lam).norm() < 1e-12);
        }
    }
}
