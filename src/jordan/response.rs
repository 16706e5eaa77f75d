//! Closed-form free response $x(t) = e^{At} x_0$ from the Jordan form.
//!
//! With the chains $V$, $W$ of a component ($A V = V J$, $W V = I$), the spectral
//! projector is $P_\theta = V W$ and
//! $$e^{At} = \sum_\theta \sum_{k \ge 0} t^k e^{\theta t} G_{\theta,k}, \qquad
//! G_{\theta,k} = \frac{(A - \theta I)^k P_\theta}{k!} = \frac1{k!} \sum_{\text{chains}}
//! \sum_j v_j\, w_{j+k},$$
//! exact in $K = \mathbb{Q}(\theta)$ and computed once per factor (conjugate roots by
//! embedding). The identities $A G_k = \theta G_k + (k+1) G_{k+1}$ (the derivative) and
//! $\sum_p \operatorname{Tr}_{K_p/\mathbb{Q}} G_{p,0} = I$ (the value at $t = 0$) are
//! checked exactly by [`FreeResponse::verify`].
//!
//! In the real form a complex pair $a \pm b i$ contributes
//! $t^k e^{a t} (\cos(bt)\, C_k + \sin(bt)\, S_k)$ with $C_k = 2\operatorname{Re} G_k$,
//! $S_k = -2 \operatorname{Im} G_k$ (exact in the block's real field), as in eq. 36–37 of
//! the vehicle-dynamics paper.

use super::{JordanForm, RealJordanForm};
use crate::algebraic::{NfElem, NumberField};
use crate::field::{Field, Q, Rational};
use crate::matrix::Matrix;
use crate::poly::newton_power_sums;
use num_complex::Complex64;
use num_traits::{One, Zero};

/// $G_{\theta,k}$ of one component ($n \times n$ over the component field).
#[derive(Clone, Debug, PartialEq)]
pub struct ResponseTerm {
    /// Index into [`JordanForm::components`].
    pub component: usize,
    /// The power $k$ of $t$.
    pub power: usize,
    pub coeff: Matrix<NumberField>,
}

/// A real-form term $t^k e^{a t}(\cos(bt) C + \sin(bt) S)$ ($b = 0$, $S = 0$ for a real
/// eigenvalue).
#[derive(Clone, Debug, PartialEq)]
pub struct RealResponseTerm {
    /// Index into [`JordanForm::eigenvalues`].
    pub eigenvalue: usize,
    pub power: usize,
    pub cos: Matrix<NumberField>,
    pub sin: Option<Matrix<NumberField>>,
}

/// $e^{At}$ as a finite sum of exact terms.
#[derive(Clone, Debug, PartialEq)]
pub struct FreeResponse {
    pub terms: Vec<ResponseTerm>,
}

fn factorial(k: usize) -> Rational {
    (1..=k).fold(Rational::one(), |acc, i| {
        acc * Rational::from_integer(i.into())
    })
}

impl JordanForm {
    /// The exact terms $G_{\theta,k}$ of $e^{At}$, one set per component.
    pub fn free_response(&self) -> FreeResponse {
        let mut terms = vec![];
        for (ci, c) in self.components.iter().enumerate() {
            let k = &c.field;
            let n = self.n();
            let smax = c.blocks.first().copied().unwrap_or(0);
            for power in 0..smax {
                let mut g = Matrix::zeros(k.clone(), n, n);
                let mut off = 0;
                for &b in &c.blocks {
                    for j in 0..b.saturating_sub(power) {
                        let v = c.chains.submatrix(0, n, off + j, off + j + 1);
                        let w = c
                            .left_chains
                            .submatrix(off + j + power, off + j + power + 1, 0, n);
                        g = &g + &(&v * &w);
                    }
                    off += b;
                }
                let inv = k.from_rational(&factorial(power).recip());
                terms.push(ResponseTerm {
                    component: ci,
                    power,
                    coeff: g.scale(&inv),
                });
            }
        }
        FreeResponse { terms }
    }
}

impl FreeResponse {
    /// Exact checks: $A G_k = t G_k + (k+1) G_{k+1}$ in each component field and
    /// $\sum_p \operatorname{Tr}_{K_p/\mathbb{Q}}(G_{p,0}) = I$.
    pub fn verify(&self, jf: &JordanForm) -> bool {
        let n = jf.n();
        let mut sum0 = Matrix::zeros(Q, n, n);
        for term in &self.terms {
            let c = &jf.components[term.component];
            let k = &c.field;
            let ak = jf.a.convert_to(k);
            let next = self
                .terms
                .iter()
                .find(|t| t.component == term.component && t.power == term.power + 1)
                .map(|t| t.coeff.scale(&k.from_i64(term.power as i64 + 1)))
                .unwrap_or_else(|| Matrix::zeros(k.clone(), n, n));
            let rhs = &term.coeff.scale(&c.root_elem()) + &next;
            if &ak * &term.coeff != rhs {
                return false;
            }
            if term.power == 0 {
                let ps = newton_power_sums(&c.factor, c.factor.deg().saturating_sub(1));
                let tr = term.coeff.map(&Q, |x: &NfElem| {
                    x.0.iter()
                        .zip(&ps)
                        .fold(Rational::zero(), |acc, (a, b)| acc + a * b)
                });
                sum0 = &sum0 + &tr;
            }
        }
        sum0.is_identity()
    }
    /// The exact term vectors $G_{\theta,k} x_0$ for eigenvalue `ev` of `jf`, in that
    /// eigenvalue's field (see [`JordanForm::root_map`]): `(power, vector)` pairs.
    pub fn term_vectors(
        &self,
        jf: &JordanForm,
        ev: usize,
        x0: &Matrix<Q>,
    ) -> Vec<(usize, Matrix<NumberField>)> {
        let e = &jf.eigenvalues[ev];
        let (field, f) = jf.root_map(ev);
        self.terms
            .iter()
            .filter(|t| t.component == e.component)
            .map(|t| {
                let g = t.coeff.map(&field, &f);
                (t.power, &g * &x0.convert_to(&field))
            })
            .collect()
    }
    /// Floating-point evaluation of $x(t) = e^{At} x_0$ (sum over all roots).
    pub fn evaluate(&self, jf: &JordanForm, x0: &[f64], t: f64) -> Vec<f64> {
        let n = jf.n();
        let mut x = vec![Complex64::zero(); n];
        for term in &self.terms {
            let c = &jf.components[term.component];
            for (j, &(re, im)) in c.roots.iter().enumerate() {
                let emb = c.embedding(j, "t");
                let theta = Complex64::new(re, im);
                let scal = (theta * t).exp() * t.powi(term.power as i32);
                for r in 0..n {
                    for q in 0..n {
                        let (gr, gi) = emb.approx(term.coeff.get(r, q));
                        x[r] += scal * Complex64::new(gr, gi) * x0[q];
                    }
                }
            }
        }
        x.into_iter().map(|z| z.re).collect()
    }
    /// The real-form terms: a real eigenvalue keeps $G_k$; a pair $a \pm bi$ gives
    /// $C_k = 2\operatorname{Re} G_k$, $S_k = -2\operatorname{Im} G_k$ in the block's real
    /// field. Blocks that are not exact are skipped (see [`RealJordanForm::notes`]).
    pub fn real_terms(&self, jf: &JordanForm, rf: &RealJordanForm) -> Vec<RealResponseTerm> {
        let mut out = vec![];
        for b in &rf.blocks {
            let Some(field) = &b.field else { continue };
            if b.t.is_none() {
                continue;
            }
            let e = &jf.eigenvalues[b.eigenvalue];
            for term in self.terms.iter().filter(|t| t.component == e.component) {
                if !b.pair {
                    let (_, f) = jf.root_map(b.eigenvalue);
                    out.push(RealResponseTerm {
                        eigenvalue: b.eigenvalue,
                        power: term.power,
                        cos: term.coeff.map(field, &f),
                        sin: None,
                    });
                    continue;
                }
                let n = jf.n();
                let two = field.from_i64(2);
                let mut cm = Matrix::zeros(field.clone(), n, n);
                let mut sm = Matrix::zeros(field.clone(), n, n);
                for r in 0..n {
                    for q in 0..n {
                        let (re, im) = b.re_im(term.coeff.get(r, q)).expect("exact block");
                        cm.set(r, q, field.mul(&two, &re));
                        sm.set(r, q, field.neg(&field.mul(&two, &im)));
                    }
                }
                out.push(RealResponseTerm {
                    eigenvalue: b.eigenvalue,
                    power: term.power,
                    cos: cm,
                    sin: Some(sm),
                });
            }
        }
        out
    }
}
