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

use super::{EigenField, JordanForm, RealEntries, RealJordanForm};
use crate::algebraic::{Ext, NumberField};
use crate::field::{Field, Q, Rational};
use crate::matrix::Matrix;
use crate::poly::{Poly, newton_power_sums};
use num_complex::Complex64;
use num_traits::{One, Zero};

/// $G_{\theta,k}$ of one component ($n \times n$ over the component field $E = F\[t\]/(p)$).
#[derive(Clone, Debug, PartialEq)]
pub struct ResponseTerm<E: Field = NumberField> {
    /// Index into the Jordan form's components.
    pub component: usize,
    /// The power $k$ of $t$.
    pub power: usize,
    pub coeff: Matrix<E>,
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

/// $e^{At}$ as a finite sum of exact terms, over the component fields $E = F\[t\]/(p)$.
#[derive(Clone, Debug, PartialEq)]
pub struct FreeResponse<E: Field = NumberField> {
    pub terms: Vec<ResponseTerm<E>>,
}

/// The chains of one component: its field, block sizes (largest first), $V$ and $W$.
pub(crate) type ComponentChains<'a, F> = (
    &'a Ext<F>,
    &'a [usize],
    &'a Matrix<Ext<F>>,
    &'a Matrix<Ext<F>>,
);

impl<F: Field> FreeResponse<Ext<F>> {
    /// The exact terms $G_{\theta,k} = \frac1{k!}\sum_{\text{chains}} \sum_j v_j w_{j+k}$,
    /// one set per component (in order), for an $n \times n$ matrix.
    pub(crate) fn from_chains<'a>(
        n: usize,
        components: impl Iterator<Item = ComponentChains<'a, F>>,
    ) -> Self
    where
        F: 'a,
    {
        let mut terms = vec![];
        for (ci, (e, blocks, chains, left)) in components.enumerate() {
            let smax = blocks.iter().copied().max().unwrap_or(0);
            let mut fact = Rational::one();
            for power in 0..smax {
                if power > 0 {
                    fact *= Rational::from_integer(power.into());
                }
                let mut g = Matrix::zeros(e.clone(), n, n);
                let mut off = 0;
                for &b in blocks {
                    for j in 0..b.saturating_sub(power) {
                        let v = chains.submatrix(0, n, off + j, off + j + 1);
                        let w = left.submatrix(off + j + power, off + j + power + 1, 0, n);
                        g = &g + &(&v * &w);
                    }
                    off += b;
                }
                let inv = e.from_rational(&fact.recip());
                terms.push(ResponseTerm {
                    component: ci,
                    power,
                    coeff: g.scale(&inv),
                });
            }
        }
        FreeResponse { terms }
    }
    /// Exact checks for $A$ over $F$: $A G_k = t G_k + (k+1) G_{k+1}$ in each component's
    /// $E = F\[t\]/(p)$ and $\sum_p \operatorname{Tr}_{E/F}(G_{p,0}) = I$, the trace from
    /// the Newton power sums of $p$. `component(i)` gives the field and the factor $p$.
    pub(crate) fn verify_over<'a>(
        &self,
        a: &Matrix<F>,
        component: impl Fn(usize) -> (&'a Ext<F>, &'a Poly<F>),
    ) -> bool
    where
        F: 'a,
    {
        let n = a.nrows();
        let k = a.field();
        let mut sum0 = Matrix::zeros(k.clone(), n, n);
        for term in &self.terms {
            let (e, p) = component(term.component);
            let ae = a.map(e, |x| e.from_base(x));
            let next = self
                .terms
                .iter()
                .find(|t| t.component == term.component && t.power == term.power + 1)
                .map(|t| t.coeff.scale(&e.from_i64(term.power as i64 + 1)))
                .unwrap_or_else(|| Matrix::zeros(e.clone(), n, n));
            let rhs = &term.coeff.scale(&e.generator()) + &next;
            if &ae * &term.coeff != rhs {
                return false;
            }
            if term.power == 0 {
                sum0 = &sum0 + &trace_down(&term.coeff, p, k);
            }
        }
        sum0.is_identity()
    }
}

/// The free response from one initial state: $x(t) = e^{At} x_0 = \sum_\theta \sum_k t^k
/// e^{\theta t} g_{\theta,k}$ with $g_{\theta,k} = G_{\theta,k} x_0$ exact in the component
/// field (conjugate roots by embedding).
#[derive(Clone, Debug, PartialEq)]
pub struct StateResponse<E: Field = NumberField> {
    /// `(component, power k, g)` with `g` an $n \times 1$ column over the component field.
    pub terms: Vec<(usize, usize, Matrix<E>)>,
}

impl<F: Field> FreeResponse<Ext<F>> {
    /// $g_{\theta,k} = G_{\theta,k} x_0$ for an initial state `x0` ($n \times 1$ over $F$).
    pub fn from_state(&self, x0: &Matrix<F>) -> StateResponse<Ext<F>> {
        let terms = self
            .terms
            .iter()
            .map(|t| {
                let e = t.coeff.field();
                let x = x0.map(e, |v| e.from_base(v));
                (t.component, t.power, &t.coeff * &x)
            })
            .collect();
        StateResponse { terms }
    }
}

/// $\operatorname{Tr}_{E/F}$ of each entry, $E = F\[t\]/(p)$, from the Newton power sums of $p$.
pub(crate) fn trace_down<F: Field>(m: &Matrix<Ext<F>>, p: &Poly<F>, k: &F) -> Matrix<F> {
    let ps = newton_power_sums(p, p.deg().saturating_sub(1));
    m.map(k, |x| {
        x.0.iter().zip(&ps).fold(k.zero(), |mut acc, (a, b)| {
            k.mul_add_assign(&mut acc, a, b);
            acc
        })
    })
}

impl<F: Field> StateResponse<Ext<F>> {
    /// The closed form checked exactly, on the vectors themselves: $\dot x = A x$ term by term,
    /// $A g_k = \theta g_k + (k+1) g_{k+1}$ in each component field (the derivative of
    /// $t^k e^{\theta t}$ is $\theta t^k e^{\theta t} + k t^{k-1} e^{\theta t}$), and $x(0) = x_0$:
    /// $\sum_p \operatorname{Tr}_{E_p/F} g_{p,0} = x_0$. `component(i)` gives the field and the
    /// factor $p$ of component `i`.
    pub fn verify_over<'a>(
        &self,
        a: &Matrix<F>,
        x0: &Matrix<F>,
        component: impl Fn(usize) -> (&'a Ext<F>, &'a Poly<F>),
    ) -> bool
    where
        F: 'a,
    {
        let k = a.field();
        let mut sum0 = Matrix::zeros(k.clone(), a.nrows(), 1);
        for (ci, power, g) in &self.terms {
            let (e, p) = component(*ci);
            let ae = a.map(e, |x| e.from_base(x));
            let next = self
                .terms
                .iter()
                .find(|(c, q, _)| c == ci && *q == power + 1)
                .map(|(_, _, h)| h.scale(&e.from_i64(*power as i64 + 1)))
                .unwrap_or_else(|| Matrix::zeros(e.clone(), a.nrows(), 1));
            if &ae * g != &g.scale(&e.generator()) + &next {
                return false;
            }
            if *power == 0 {
                sum0 = &sum0 + &trace_down(g, p, k);
            }
        }
        &sum0 == x0
    }
    /// [`StateResponse::verify_over`] with the components of `jf`.
    pub fn verify(&self, jf: &JordanForm<F>, x0: &Matrix<F>) -> bool {
        self.verify_over(&jf.a, x0, |i| {
            let c = &jf.components[i];
            (&c.field, &c.factor)
        })
    }
}

impl<F: Field> FreeResponse<Ext<F>> {
    /// Exact checks: $A G_k = t G_k + (k+1) G_{k+1}$ in each component field $E$ and
    /// $\sum_p \operatorname{Tr}_{E/F}(G_{p,0}) = I$.
    pub fn verify(&self, jf: &JordanForm<F>) -> bool {
        self.verify_over(&jf.a, |i| {
            let c = &jf.components[i];
            (&c.field, &c.factor)
        })
    }
}

impl<F: EigenField> FreeResponse<Ext<F>> {
    /// $G_{\theta,k}$ of eigenvalue `ev` of `jf` in that eigenvalue's field
    /// ([`JordanForm::root_map`]): `(power, G)` pairs.
    pub fn terms_of(&self, jf: &JordanForm<F>, ev: usize) -> Vec<(usize, Matrix<Ext<F>>)> {
        terms_at(
            jf,
            ev,
            self.terms.iter().map(|t| (t.component, t.power, &t.coeff)),
        )
    }
}

impl<F: EigenField> StateResponse<Ext<F>> {
    /// $g_{\theta,k}$ of eigenvalue `ev` of `jf` in that eigenvalue's field
    /// ([`JordanForm::root_map`]): `(power, g)` pairs.
    pub fn terms_of(&self, jf: &JordanForm<F>, ev: usize) -> Vec<(usize, Matrix<Ext<F>>)> {
        terms_at(jf, ev, self.terms.iter().map(|(c, k, g)| (*c, *k, g)))
    }
}

/// The terms `(component, power, matrix)` of eigenvalue `ev`'s component, each mapped into
/// that eigenvalue's field ([`JordanForm::root_map`]): `(power, matrix)` pairs.
fn terms_at<'a, F: EigenField + 'a>(
    jf: &JordanForm<F>,
    ev: usize,
    terms: impl Iterator<Item = (usize, usize, &'a Matrix<Ext<F>>)>,
) -> Vec<(usize, Matrix<Ext<F>>)> {
    let e = &jf.eigenvalues[ev];
    let (field, f) = jf.root_map(ev);
    terms
        .filter(|(c, _, _)| *c == e.component)
        .map(|(_, k, g)| (k, g.map(&field, &f)))
        .collect()
}

impl<F: Field + 'static> StateResponse<Ext<F>> {
    /// Floating-point value of $x(t)$ (the sum over every root of every component), complex:
    /// each exact $g$ embedded at its root by the field's [`Field::approx`].
    pub fn evaluate_complex(&self, jf: &JordanForm<F>, t: f64) -> Vec<Complex64> {
        let n = jf.n();
        let mut x = vec![Complex64::zero(); n];
        for (ci, power, g) in &self.terms {
            let c = &jf.components[*ci];
            for (j, &(re, im)) in c.roots.iter().enumerate() {
                let emb = c.embedding(j, "t");
                let scal = (Complex64::new(re, im) * t).exp() * t.powi(*power as i32);
                for (r, xr) in x.iter_mut().enumerate() {
                    let (gr, gi) = emb.approx(g.get(r, 0));
                    *xr += scal * Complex64::new(gr, gi);
                }
            }
        }
        x
    }
    /// Floating-point value of $x(t)$ for a real system (the real parts of
    /// [`Self::evaluate_complex`]).
    pub fn evaluate(&self, jf: &JordanForm<F>, t: f64) -> Vec<f64> {
        self.evaluate_complex(jf, t)
            .into_iter()
            .map(|z| z.re)
            .collect()
    }
}

impl FreeResponse {
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
    /// field. Blocks in the compact form are skipped.
    pub fn real_terms(&self, jf: &JordanForm, rf: &RealJordanForm) -> Vec<RealResponseTerm> {
        let mut out = vec![];
        for b in &rf.blocks {
            let e = &jf.eigenvalues[b.eigenvalue];
            for term in self.terms.iter().filter(|t| t.component == e.component) {
                match &b.entries {
                    RealEntries::Root { field, .. } => {
                        let (_, f) = jf.root_map(b.eigenvalue);
                        out.push(RealResponseTerm {
                            eigenvalue: b.eigenvalue,
                            power: term.power,
                            cos: term.coeff.map(field, &f),
                            sin: None,
                        });
                    }
                    RealEntries::Expanded { pair, .. } => {
                        let field = &pair.field;
                        let n = jf.n();
                        let two = field.from_i64(2);
                        let mut cm = Matrix::zeros(field.clone(), n, n);
                        let mut sm = Matrix::zeros(field.clone(), n, n);
                        for r in 0..n {
                            for q in 0..n {
                                let (re, im) = pair.re_im(&Q, term.coeff.get(r, q));
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
                    _ => {}
                }
            }
        }
        out
    }
}
