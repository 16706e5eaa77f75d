//! Float eigenvalues of $A(v)$ at many parameter values, computed in parallel (rayon).
//!
//! The entries of the family are compiled once to `f64` coefficient vectors; each point
//! then costs one $A(v)$ assembly ($M^{-1}$ by LU in the second-order form) and one
//! balanced Schur decomposition ([`crate::float::eigenvalues`]). Results are in the order
//! of the values; eigenvalues per value sorted by (real, imaginary) part, or matched to the
//! previous value by [`SweepResult::tracks`] for plotting continuous branches.

use super::family::{FamilyForm, ParamFamily, RatMatrix, second_order_state_matrix};
use super::qv::coeffs_f64;
use super::sweep_plan::{PointStatus, SweepPlan};
use crate::error::{Error, Result};
use nalgebra::DMatrix;
use num_complex::Complex;
use rayon::prelude::*;

/// Largest number of sweep points.
pub const MAX_POINTS: usize = 10_000_000;

/// Eigenvalues along the parameter.
#[derive(Clone, Debug, PartialEq)]
pub struct SweepResult {
    pub param: String,
    pub values: Vec<f64>,
    /// `eigenvalues[i]`: the (finite) eigenvalues at `values[i]`, sorted by (re, im).
    pub eigenvalues: Vec<Vec<Complex<f64>>>,
    /// `status[i]`: what `eigenvalues[i]` is (or why it is empty).
    pub status: Vec<PointStatus>,
}

/// `n` equally spaced values from `a` to `b` (both included; `n = 1` gives `a`).
pub fn sweep_values(a: f64, b: f64, n: usize) -> Vec<f64> {
    match n {
        0 => vec![],
        1 => vec![a],
        _ => (0..n)
            .map(|i| a + (b - a) * i as f64 / (n - 1) as f64)
            .collect(),
    }
}

struct FloatEntry {
    num: Vec<f64>,
    den: Vec<f64>,
}

impl FloatEntry {
    fn eval(&self, v: f64) -> f64 {
        let h = |c: &[f64]| c.iter().rev().fold(0.0, |acc, x| acc * v + x);
        if self.den.len() == 1 {
            h(&self.num) / self.den[0]
        } else {
            h(&self.num) / h(&self.den)
        }
    }
}

type FloatMatrix = Vec<Vec<FloatEntry>>;

fn compile(m: &RatMatrix) -> FloatMatrix {
    m.rows()
        .iter()
        .map(|r| {
            r.iter()
                .map(|f| FloatEntry {
                    num: coeffs_f64(f.num()),
                    den: coeffs_f64(f.den()),
                })
                .collect()
        })
        .collect()
}

fn at(m: &FloatMatrix, v: f64) -> DMatrix<f64> {
    let n = m.len();
    DMatrix::from_fn(n, n, |i, j| m[i][j].eval(v))
}

enum Compiled {
    First(FloatMatrix, Option<FloatMatrix>),
    Second(FloatMatrix, FloatMatrix, FloatMatrix),
}

impl Compiled {
    fn new(f: &ParamFamily) -> Self {
        match &f.form {
            FamilyForm::First { a, e } => Compiled::First(compile(a), e.as_ref().map(compile)),
            FamilyForm::Second { m, l, k } => Compiled::Second(compile(m), compile(l), compile(k)),
        }
    }
    fn state_matrix(&self, v: f64) -> Result<DMatrix<f64>> {
        match self {
            Compiled::First(a, None) => Ok(at(a, v)),
            Compiled::First(a, Some(e)) => at(e, v).lu().solve(&at(a, v)).ok_or(Error::Singular),
            Compiled::Second(m, l, k) => second_order_state_matrix(&at(m, v), &at(l, v), &at(k, v)),
        }
    }
    /// The pencil $(E(v), A(v))$; the second-order form linearized as in
    /// [`super::finite`] ($E = \mathrm{diag}(I, M)$, $A = [0, I; -K, -L]$).
    fn pencil(&self, v: f64) -> (DMatrix<f64>, DMatrix<f64>) {
        match self {
            Compiled::First(a, e) => {
                let a = at(a, v);
                let e = e
                    .as_ref()
                    .map_or_else(|| DMatrix::identity(a.nrows(), a.nrows()), |e| at(e, v));
                (e, a)
            }
            Compiled::Second(m, l, k) => {
                let (m, l, k) = (at(m, v), at(l, v), at(k, v));
                let n = m.nrows();
                let mut e = DMatrix::identity(2 * n, 2 * n);
                e.view_mut((n, n), (n, n)).copy_from(&m);
                let mut a = DMatrix::zeros(2 * n, 2 * n);
                a.view_mut((0, n), (n, n)).fill_with_identity();
                a.view_mut((n, 0), (n, n)).copy_from(&(-k));
                a.view_mut((n, n), (n, n)).copy_from(&(-l));
                (e, a)
            }
        }
    }
    /// The finite eigenvalues at `v` for the exact `status` (empty where there are none).
    fn eigenvalues(
        &self,
        v: f64,
        status: PointStatus,
        n: usize,
    ) -> (Vec<Complex<f64>>, PointStatus) {
        let finite = |x: &DMatrix<f64>| x.iter().all(|y| y.is_finite());
        let shift_invert = |r: usize| {
            let (e, a) = self.pencil(v);
            (finite(&e) && finite(&a))
                .then(|| crate::float::pencil_finite_eigenvalues(&e, &a, r).ok())
                .flatten()
        };
        let ev = match status {
            PointStatus::Regular => self
                .state_matrix(v)
                .ok()
                .filter(finite)
                .and_then(|a| crate::float::eigenvalues(&a).ok())
                .or_else(|| shift_invert(n)),
            PointStatus::Descriptor { infinite } => shift_invert(n - infinite),
            _ => return (vec![], status),
        };
        match ev {
            Some(ev) => (ev, status),
            None => (vec![], PointStatus::Failed),
        }
    }
}

/// Eigenvalues of $A(v)$ for every `v` in `values`, in parallel; `progress(k)` is called
/// with the number of points finished so far (from worker threads, unordered).
///
/// Where $E(v)$ (or $M(v)$) is singular the list holds the finite eigenvalues of the
/// pencil ($\det(xE - A) = 0$; their number decided exactly by [`SweepPlan`], their values
/// by [`crate::float::pencil_finite_eigenvalues`]). A value where the family is undefined
/// (a pole, a singular pencil) gives an empty list and says so in `status`, so one bad
/// point does not spoil a sweep.
///
/// # Errors
/// `Limit` for more than [`MAX_POINTS`] values; errors of [`SweepPlan::new`].
pub fn sweep(
    fam: &ParamFamily,
    values: &[f64],
    progress: Option<&(dyn Fn(usize) + Sync)>,
) -> Result<SweepResult> {
    if values.len() > MAX_POINTS {
        return Err(Error::Limit(format!("more than {MAX_POINTS} sweep points")));
    }
    let plan = SweepPlan::new(fam)?;
    let c = Compiled::new(fam);
    let done = std::sync::atomic::AtomicUsize::new(0);
    let (eigenvalues, status): (Vec<Vec<Complex<f64>>>, Vec<PointStatus>) = values
        .par_iter()
        .with_min_len(16)
        .map(|&v| {
            let out = c.eigenvalues(v, plan.status(v), plan.nstates);
            if let Some(p) = progress {
                p(done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1);
            }
            out
        })
        .unzip();
    Ok(SweepResult {
        param: fam.param.clone(),
        values: values.to_vec(),
        eigenvalues,
        status,
    })
}

impl SweepResult {
    /// The eigenvalues re-ordered into continuous branches: entry `k` of each list
    /// continues entry `k` of the previous list (greedy nearest match). Points with no
    /// eigenvalues are skipped in the matching.
    pub fn tracks(&self) -> Vec<Vec<Complex<f64>>> {
        let mut out: Vec<Vec<Complex<f64>>> = Vec::with_capacity(self.eigenvalues.len());
        let mut prev: Option<Vec<Complex<f64>>> = None;
        for ev in &self.eigenvalues {
            let Some(p) = prev.as_ref().filter(|p| p.len() == ev.len()) else {
                out.push(ev.clone());
                if !ev.is_empty() {
                    prev = Some(ev.clone());
                }
                continue;
            };
            let mut used = vec![false; ev.len()];
            let mut next = vec![Complex::new(0.0, 0.0); ev.len()];
            for (k, z) in p.iter().enumerate() {
                let j = (0..ev.len())
                    .filter(|&j| !used[j])
                    .min_by(|&i, &j| (ev[i] - z).norm().total_cmp(&(ev[j] - z).norm()))
                    .expect("as many eigenvalues as before");
                used[j] = true;
                next[k] = ev[j];
            }
            out.push(next.clone());
            prev = Some(next);
        }
        out
    }

    /// CSV: `param, re1, im1, re2, im2, ...` (sorted eigenvalues per row).
    pub fn to_csv(&self) -> String {
        use std::fmt::Write;
        let n = self.eigenvalues.iter().map(Vec::len).max().unwrap_or(0);
        let mut s = self.param.clone();
        for k in 1..=n {
            let _ = write!(s, ",re{k},im{k}");
        }
        s.push('\n');
        for (v, ev) in self.values.iter().zip(&self.eigenvalues) {
            let _ = write!(s, "{v}");
            for z in ev {
                let _ = write!(s, ",{},{}", z.re, z.im);
            }
            s.push('\n');
        }
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::matrix::Matrix;

    #[test]
    fn damped_oscillator_sweep() {
        // q'' + c q' + q = 0: eigenvalues (-c +- sqrt(c^2 - 4))/2
        let k = crate::study::qv::field("c").unwrap();
        let rf =
            |s: &str| Matrix::from_rows(k.clone(), vec![vec![k.parse(s).expect("valid")]]).unwrap();
        let fam = ParamFamily::second_order("c", rf("1"), rf("c"), rf("1")).unwrap();
        let vals = sweep_values(0.0, 4.0, 5);
        let r = sweep(&fam, &vals, None).unwrap();
        for (c, ev) in vals.iter().zip(&r.eigenvalues) {
            let sum = ev[0] + ev[1];
            let prod = ev[0] * ev[1];
            assert!(
                (sum.re + c).abs() < 1e-6 && (prod.re - 1.0).abs() < 1e-6,
                "c = {c}: {ev:?}"
            );
        }
        assert_eq!(r.tracks().len(), 5);
    }
}
