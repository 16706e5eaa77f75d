//! Float responses through the Jordan blocks, after the exact decomposition.
//!
//! With $A = V J W$ ($W V = I$, $J = \operatorname{diag}(J_k)$, $J_k = \theta_k I + N$ of size
//! $m_k$) the minimal-realizations paper's eq. 56 splits by block:
//! $$G(s) = D + \sum_k C_k (sI - J_k)^{-1} B_k,\qquad
//! \big((sI - J_k)^{-1}\big)_{i,i+l} = (s - \theta_k)^{-(l+1)},$$
//! with $C_k = C V_k$, $B_k = W_k B$: $O(\sum_k m_k^2)$ work per frequency instead of a dense
//! LU of $sI - A$ ($O(n^3)$). The time step of the Jordan paper (sec. II) is the same
//! structure: $e^{Jh}$ is block diagonal with $(e^{J_k h})_{i,i+l} = e^{\theta_k h} h^l/l!$, so
//! $z_{j+1} = e^{Jh} z_j$ costs $O(\sum_k m_k^2)$ per step ($x_j = V z_j$, $z_0 = W x_0$)
//! against $O(n^2)$ for the dense $x_{j+1} = e^{Ah} x_j$.
//!
//! The decomposition ($\theta_k$, $V$, $W$) is exact ([`crate::jordan::JordanForm`]); only its
//! embedding into $\mathbb{C}$ (the certified root approximations) and the arithmetic here
//! are floating point.

use nalgebra::DMatrix;
use num_complex::Complex64 as C;
use num_traits::Zero;

use crate::error::{Error, Result};
use crate::field::Q;
use crate::jordan::JordanForm;
use crate::matrix::Matrix;

/// One Jordan block: eigenvalue, size, and first column of its chain in $V$.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ModalBlock {
    pub theta: C,
    pub size: usize,
    pub offset: usize,
}

/// $(J, WB, CV, D)$ in floating point with $V$ and $W = V^{-1}$ (to map states).
#[derive(Clone, Debug)]
pub struct ModalSystem {
    pub blocks: Vec<ModalBlock>,
    pub v: DMatrix<C>,
    pub w: DMatrix<C>,
    /// $W B$ ($n \times m$).
    pub bm: DMatrix<C>,
    /// $C V$ ($p \times n$).
    pub cm: DMatrix<C>,
    pub d: DMatrix<C>,
}

fn cplx(m: &DMatrix<f64>) -> DMatrix<C> {
    m.map(|x| C::new(x, 0.0))
}

impl ModalSystem {
    /// The float image of an exact Jordan form of $A$ (each component at each of its roots)
    /// with the system's $B$, $C$, $D$.
    ///
    /// # Errors
    /// `Invalid` for shapes that do not fit $A$; non-finite values.
    pub fn from_jordan(
        jf: &JordanForm,
        b: &Matrix<Q>,
        c: &Matrix<Q>,
        d: &Matrix<Q>,
    ) -> Result<Self> {
        let n = jf.n();
        let (mut v, mut w) = (DMatrix::zeros(n, n), DMatrix::zeros(n, n));
        let mut blocks = vec![];
        let mut col = 0;
        for comp in &jf.components {
            let m = comp.chains.ncols();
            for (j, &(re, im)) in comp.roots.iter().enumerate() {
                let emb = comp.embedding(j, "t");
                let z = |x| {
                    let (a, b) = emb.approx(x);
                    C::new(a, b)
                };
                for r in 0..n {
                    for q in 0..m {
                        v[(r, col + q)] = z(comp.chains.get(r, q));
                        w[(col + q, r)] = z(comp.left_chains.get(q, r));
                    }
                }
                let mut off = col;
                for &size in &comp.blocks {
                    blocks.push(ModalBlock {
                        theta: C::new(re, im),
                        size,
                        offset: off,
                    });
                    off += size;
                }
                col += m;
            }
        }
        let f = |m: &Matrix<Q>| crate::float::to_dmatrix(m);
        Self::from_parts(blocks, v, w, &f(b)?, &f(c)?, &f(d)?)
    }

    /// From given blocks and chains ($A = V J W$, $W = V^{-1}$) and real $B$, $C$, $D$.
    ///
    /// # Errors
    /// `Invalid` when the shapes do not fit or a value is not finite.
    pub fn from_parts(
        blocks: Vec<ModalBlock>,
        v: DMatrix<C>,
        w: DMatrix<C>,
        b: &DMatrix<f64>,
        c: &DMatrix<f64>,
        d: &DMatrix<f64>,
    ) -> Result<Self> {
        let n = v.nrows();
        let covered: usize = blocks.iter().map(|k| k.size).sum();
        let fits = v.ncols() == n
            && w.shape() == (n, n)
            && b.nrows() == n
            && c.ncols() == n
            && d.shape() == (c.nrows(), b.ncols())
            && covered == n
            && blocks.iter().all(|k| k.offset + k.size <= n);
        if !fits {
            return Err(Error::Invalid(
                "modal system: shapes of V, W, B, C, D and the blocks do not fit".into(),
            ));
        }
        let finite = v.iter().chain(w.iter()).all(|z| z.is_finite())
            && blocks.iter().all(|k| k.theta.is_finite());
        if !finite {
            return Err(Error::Invalid("modal system: a value is not finite".into()));
        }
        Ok(ModalSystem {
            bm: &w * cplx(b),
            cm: cplx(c) * &v,
            blocks,
            v,
            w,
            d: cplx(d),
        })
    }

    /// Size of the state.
    pub fn n(&self) -> usize {
        self.v.nrows()
    }

    /// $G(s)$ through the blocks (eq. 56); `None` at an eigenvalue.
    pub fn at(&self, s: C) -> Option<DMatrix<C>> {
        let mut g = self.d.clone();
        let m = self.bm.ncols();
        let mut u = vec![C::zero(); m];
        let mut powers = vec![];
        for k in &self.blocks {
            let diff = s - k.theta;
            if diff.is_zero() {
                return None;
            }
            let r = diff.inv();
            powers.clear();
            let mut p = r;
            for _ in 0..k.size {
                powers.push(p);
                p *= r;
            }
            for i in 0..k.size {
                // u = sum_l r^(l+1) (W B)[i + l, :], then G += (C V)[:, i] u
                u.iter_mut().for_each(|x| *x = C::zero());
                for (l, pw) in powers.iter().enumerate().take(k.size - i) {
                    let row = k.offset + i + l;
                    for (q, x) in u.iter_mut().enumerate() {
                        *x += pw * self.bm[(row, q)];
                    }
                }
                let colk = k.offset + i;
                for q in 0..m {
                    for o in 0..g.nrows() {
                        g[(o, q)] += self.cm[(o, colk)] * u[q];
                    }
                }
            }
        }
        Some(g)
    }

    /// $G(j 2\pi f)$ at each frequency `freqs_hz` (hertz).
    ///
    /// # Errors
    /// `Singular` when $j\omega$ is an eigenvalue; `Invalid` for a non-finite frequency.
    pub fn freqresp(&self, freqs_hz: &[f64]) -> Result<Vec<DMatrix<C>>> {
        freqs_hz
            .iter()
            .map(|&f| {
                if !f.is_finite() {
                    return Err(Error::Invalid(format!("frequency {f} is not finite")));
                }
                let s = C::new(0.0, 2.0 * std::f64::consts::PI * f);
                self.at(s).ok_or(Error::Singular)
            })
            .collect()
    }

    /// The transition $e^{Jh}$ over one step `h` (per block, its Toeplitz coefficients).
    pub fn transition(&self, h: f64) -> ModalTransition {
        let blocks = self
            .blocks
            .iter()
            .map(|k| {
                let e = (k.theta * h).exp();
                let mut coeffs = Vec::with_capacity(k.size);
                let mut c = e;
                for l in 0..k.size {
                    if l > 0 {
                        c *= h / l as f64;
                    }
                    coeffs.push(c);
                }
                (k.offset, coeffs)
            })
            .collect();
        ModalTransition { blocks }
    }

    /// $z_0 = W x_0$.
    pub fn to_modal(&self, x0: &[f64]) -> Vec<C> {
        let n = self.n();
        (0..n)
            .map(|i| (0..n).map(|j| self.w[(i, j)] * x0[j]).sum())
            .collect()
    }

    /// $x = \operatorname{Re}(V z)$ (real for a real $A$ and real $x_0$).
    pub fn to_state(&self, z: &[C]) -> Vec<f64> {
        let n = self.n();
        (0..n)
            .map(|i| (0..n).map(|j| self.v[(i, j)] * z[j]).sum::<C>().re)
            .collect()
    }

    /// $y = \operatorname{Re}(C V z)$.
    pub fn output(&self, z: &[C]) -> Vec<f64> {
        (0..self.cm.nrows())
            .map(|o| (0..self.n()).map(|j| self.cm[(o, j)] * z[j]).sum::<C>().re)
            .collect()
    }
}

/// $e^{Jh}$ block by block: `(offset, [e^{θh} h^l / l!])`.
#[derive(Clone, Debug)]
pub struct ModalTransition {
    pub blocks: Vec<(usize, Vec<C>)>,
}

impl ModalTransition {
    /// Nonzero entries of $e^{Jh}$ ($\sum_k m_k (m_k + 1)/2$).
    pub fn nonzeros(&self) -> usize {
        self.blocks
            .iter()
            .map(|(_, c)| c.len() * (c.len() + 1) / 2)
            .sum()
    }

    /// One step $z \leftarrow e^{Jh} z$ in place (the upper-triangular Toeplitz block times
    /// the chain coordinates, top row first so each entry is read before it is written).
    pub fn step(&self, z: &mut [C]) {
        for (off, coeffs) in &self.blocks {
            let m = coeffs.len();
            for i in 0..m {
                let mut acc = C::zero();
                for (l, c) in coeffs.iter().enumerate().take(m - i) {
                    acc += c * z[off + i + l];
                }
                z[off + i] = acc;
            }
        }
    }
}

/// The states $x_0, \dots, x_{\text{steps}}$ by the modal transition.
pub fn simulate_modal(sys: &ModalSystem, h: f64, steps: usize, x0: &[f64]) -> Vec<Vec<f64>> {
    let phi = sys.transition(h);
    let mut z = sys.to_modal(x0);
    let mut out = vec![sys.to_state(&z)];
    for _ in 0..steps {
        phi.step(&mut z);
        out.push(sys.to_state(&z));
    }
    out
}

/// The states $x_0, \dots, x_{\text{steps}}$ by the dense transition `phi` $= e^{Ah}$.
pub fn simulate_dense(phi: &DMatrix<f64>, steps: usize, x0: &[f64]) -> Vec<Vec<f64>> {
    let n = phi.nrows();
    let mut x = x0.to_vec();
    let mut out = vec![x.clone()];
    let mut next = vec![0.0; n];
    for _ in 0..steps {
        for (i, y) in next.iter_mut().enumerate() {
            *y = (0..n).map(|j| phi[(i, j)] * x[j]).sum();
        }
        std::mem::swap(&mut x, &mut next);
        out.push(x.clone());
    }
    out
}

/// $e^{Ah}$ (dense, float; the zero-order hold's $A_d$).
///
/// # Errors
/// As [`crate::float::time_response::zoh`].
pub fn dense_transition(a: &DMatrix<f64>, h: f64) -> Result<DMatrix<f64>> {
    let b = DMatrix::zeros(a.nrows(), 1);
    Ok(crate::float::time_response::zoh(a, &b, h)?.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::qmat;

    #[test]
    fn a_single_jordan_block_responds_as_its_closed_form() {
        // A = [[-1, 1], [0, -1]], B = [0; 1], C = [1, 0]: G(s) = 1/(s+1)^2
        let a = qmat![[-1, 1], [0, -1]];
        let jf = crate::jordan::jordan(&a).unwrap();
        let sys =
            ModalSystem::from_jordan(&jf, &qmat![[0], [1]], &qmat![[1, 0]], &qmat![[0]]).unwrap();
        let s = C::new(0.3, 2.0);
        let want = ((s + 1.0) * (s + 1.0)).inv();
        assert!((sys.at(s).unwrap()[(0, 0)] - want).norm() < 1e-14);
        assert!(sys.at(C::new(-1.0, 0.0)).is_none());
        // e^{At} x0 with x0 = [0, 1]: x = [t e^-t, e^-t]
        let xs = simulate_modal(&sys, 0.5, 4, &[0.0, 1.0]);
        let t = 2.0f64;
        assert!((xs[4][0] - t * (-t).exp()).abs() < 1e-14);
        assert!((xs[4][1] - (-t).exp()).abs() < 1e-14);
        assert_eq!(sys.transition(0.5).nonzeros(), 3);
    }
}
