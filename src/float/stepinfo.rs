//! Step-response characteristics of one channel from its samples (python-control's
//! `step_info`, same definitions), given the final value $y_\infty$.
//!
//! With $\sigma = \operatorname{sign} y_\infty$ and samples $y_k$ at times $t_k$:
//! - rise time: $t_{hi} - t_{lo}$, the first times with $\sigma (y_k - 0.1 y_\infty) \ge 0$
//!   and $\sigma (y_k - 0.9 y_\infty) \ge 0$;
//! - settling time: the time after the last sample with $|y_k / y_\infty - 1| \ge 0.02$
//!   (`None` when the last sample is still outside the band);
//! - settling min / max: over the samples from the 90 % time on, $y_\infty$ included;
//! - overshoot: $100\,(\max_k \sigma y_k - |y_\infty|)/|y_\infty|$ when positive, else 0;
//! - undershoot: $-100\, y_u / y_\infty$ for $y_u = y_{\arg\min \sigma y_k}$ when
//!   $\sigma y_u < 0$, else 0;
//! - peak: $\max_k |y_k|$ and its (first) time.
//!
//! Not for $y_\infty = 0$ (no relative band) or a response that never reaches 90 %: those
//! are `None` with the reason.

/// The characteristics of one step response.
#[derive(Clone, Debug, PartialEq)]
pub struct StepInfo {
    pub rise_time: f64,
    /// `None`: still outside the 2 % band at the last sample (horizon too short).
    pub settling_time: Option<f64>,
    pub settling_min: f64,
    pub settling_max: f64,
    /// Percent.
    pub overshoot: f64,
    /// Percent.
    pub undershoot: f64,
    pub peak: f64,
    pub peak_time: f64,
    pub steady_state_value: f64,
}

/// Why a channel has no step characteristics.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NoStepInfo {
    /// $y_\infty = 0$: rise and settling are relative to a final value that is zero.
    ZeroFinalValue,
    /// The samples never reach 10 % or 90 % of $y_\infty$ (horizon too short).
    NotReached,
    /// Fewer than two samples, or a non-finite sample or final value.
    BadSamples,
}

/// Default thresholds: 2 % settling band, 10 %-90 % rise.
pub const SETTLING_THRESHOLD: f64 = 0.02;
pub const RISE_LIMITS: (f64, f64) = (0.1, 0.9);

/// The characteristics of samples `y` at `times` with final value `y_inf`.
///
/// # Errors
/// [`NoStepInfo`] as documented.
pub fn step_info(times: &[f64], y: &[f64], y_inf: f64) -> Result<StepInfo, NoStepInfo> {
    if times.len() != y.len()
        || times.len() < 2
        || !y_inf.is_finite()
        || y.iter().chain(times).any(|v| !v.is_finite())
    {
        return Err(NoStepInfo::BadSamples);
    }
    if y_inf == 0.0 {
        return Err(NoStepInfo::ZeroFinalValue);
    }
    let sg = y_inf.signum();
    let first = |lim: f64| y.iter().position(|v| sg * (v - lim * y_inf) >= 0.0);
    let (Some(lo), Some(hi)) = (first(RISE_LIMITS.0), first(RISE_LIMITS.1)) else {
        return Err(NoStepInfo::NotReached);
    };
    let outside = y
        .iter()
        .rposition(|v| (v / y_inf - 1.0).abs() >= SETTLING_THRESHOLD);
    let settled = outside.map_or(0, |k| k + 1);
    let tail = &y[hi..];
    let settling_min = tail.iter().copied().fold(y_inf, f64::min);
    let settling_max = tail.iter().copied().fold(y_inf, f64::max);
    let y_os = y.iter().map(|v| sg * v).fold(f64::NEG_INFINITY, f64::max);
    let dy = y_os.abs() - y_inf.abs();
    let overshoot = if dy > 0.0 {
        (100.0 * dy / y_inf).abs()
    } else {
        0.0
    };
    let mut us = 0;
    for (k, v) in y.iter().enumerate() {
        if sg * v < sg * y[us] {
            us = k;
        }
    }
    let undershoot = if sg * y[us] < 0.0 {
        -100.0 * y[us] / y_inf
    } else {
        0.0
    };
    let mut pk = 0;
    for (k, v) in y.iter().enumerate() {
        if v.abs() > y[pk].abs() {
            pk = k;
        }
    }
    Ok(StepInfo {
        rise_time: times[hi] - times[lo],
        settling_time: times.get(settled).copied(),
        settling_min,
        settling_max,
        overshoot,
        undershoot,
        peak: y[pk].abs(),
        peak_time: times[pk],
        steady_state_value: y_inf,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn first_order_by_hand() {
        // y = 1 - e^{-t}: rise ln 9 = 2.197, settling ln 50 = 3.912, no overshoot
        let t: Vec<f64> = (0..=100_000).map(|k| k as f64 * 1e-4).collect();
        let y: Vec<f64> = t.iter().map(|t| 1.0 - (-t).exp()).collect();
        let s = step_info(&t, &y, 1.0).unwrap();
        assert!((s.rise_time - 9f64.ln()).abs() < 2e-4);
        assert!((s.settling_time.unwrap() - 50f64.ln()).abs() < 2e-4);
        assert_eq!(s.overshoot, 0.0);
        assert_eq!(s.undershoot, 0.0);
        assert!((s.peak - y[100_000]).abs() < 1e-15);
        assert_eq!(step_info(&t, &y, 0.0), Err(NoStepInfo::ZeroFinalValue));
        assert_eq!(step_info(&t, &y, 3.0), Err(NoStepInfo::NotReached));
        assert_eq!(
            step_info(&t[..1], &y[..1], 1.0),
            Err(NoStepInfo::BadSamples)
        );
    }
}
