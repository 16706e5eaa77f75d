//! Closed-form free response $x(t) = e^{At} x_0$ over a quadratic field $K$, from the Jordan
//! form over $K$ (the rational [`crate::jordan::FreeResponse`] on the components of
//! [`super::JordanFormK`]).
//!
//! With the chains $V$, $W$ of a component ($A V = V J_t$, $W V = I$ in $E = K\[t\]/(g)$),
//! $$e^{At} = \sum_\theta \sum_{k \ge 0} t^k e^{\theta t} G_{\theta,k}, \qquad
//! G_{\theta,k} = \frac{(A - \theta I)^k V W}{k!} = \frac1{k!} \sum_{\text{chains}}
//! \sum_j v_j\, w_{j+k},$$
//! computed once per factor in $E$ (the roots of $g$, the eigenvalues of $A$, by the marked
//! embeddings). [`FreeResponseK::verify`] checks exactly $A G_k = t G_k + (k+1) G_{k+1}$ in
//! $E$ (so $x' = A x$) and $\sum_g \operatorname{Tr}_{E/K} G_{g,0} = I$ (so $x(0) = x_0$),
//! the trace from the Newton power sums of $g$ over $K$.

use super::{JordanFormK, RelField};
use crate::field::{Field, Quadratic, QuadraticField, Rational};
use crate::matrix::Matrix;
use crate::poly::Poly;

/// $G_{\theta,k}$ of one component ($n \times n$ over $E$).
#[derive(Clone, Debug, PartialEq)]
pub struct ResponseTermK {
    /// Index into [`JordanFormK::components`].
    pub component: usize,
    /// The power $k$ of $t$.
    pub power: usize,
    pub coeff: Matrix<RelField>,
}

/// $e^{At}$ over $K$ as a finite sum of exact terms.
#[derive(Clone, Debug, PartialEq)]
pub struct FreeResponseK {
    pub terms: Vec<ResponseTermK>,
}

/// Newton power sums $s_0, \dots, s_{u-1}$ of the roots of the monic `g` over $K$.
pub(crate) fn power_sums(g: &Poly<QuadraticField>, u: usize) -> Vec<Quadratic> {
    let k = g.field();
    let d = g.deg();
    let a = |i: usize| g.coeff(i); // x^d + a_{d-1} x^{d-1} + ... + a_0
    let mut s = vec![k.from_i64(d as i64)];
    for j in 1..u {
        // s_j = -(j a_{d-j} [j <= d] + sum_{i=1}^{min(j-1, d)} a_{d-i} s_{j-i})
        let mut v = if j <= d {
            k.mul(&k.from_i64(j as i64), &a(d - j))
        } else {
            k.zero()
        };
        for i in 1..j.min(d + 1) {
            v = k.add(&v, &k.mul(&a(d - i), &s[j - i]));
        }
        s.push(k.neg(&v));
    }
    s
}

impl JordanFormK {
    /// The exact terms $G_{\theta,k}$ of $e^{At}$, one set per component.
    pub fn free_response(&self) -> FreeResponseK {
        let n = self.n();
        let mut terms = vec![];
        for (ci, c) in self.components.iter().enumerate() {
            let e = &c.field;
            let smax = c.blocks.iter().copied().max().unwrap_or(0);
            let mut fact = Rational::from_integer(1.into());
            for power in 0..smax {
                if power > 0 {
                    fact *= Rational::from_integer(power.into());
                }
                let mut g = Matrix::zeros(e.clone(), n, n);
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
                let inv = e.from_rational(&num_traits::Inv::inv(fact.clone()));
                terms.push(ResponseTermK {
                    component: ci,
                    power,
                    coeff: g.scale(&inv),
                });
            }
        }
        FreeResponseK { terms }
    }
}

impl FreeResponseK {
    /// Exact checks: $A G_k = t G_k + (k+1) G_{k+1}$ in each component's $E$ and
    /// $\sum_g \operatorname{Tr}_{E/K}(G_{g,0}) = I$ over $K$.
    pub fn verify(&self, jf: &JordanFormK) -> bool {
        let n = jf.n();
        let k = jf.base().clone();
        let mut sum0 = Matrix::zeros(k.clone(), n, n);
        for term in &self.terms {
            let c = &jf.components[term.component];
            let e = &c.field;
            let ae = super::lift(&jf.a, e);
            let next = self
                .terms
                .iter()
                .find(|t| t.component == term.component && t.power == term.power + 1)
                .map(|t| t.coeff.scale(&e.from_i64(term.power as i64 + 1)))
                .unwrap_or_else(|| Matrix::zeros(e.clone(), n, n));
            if &ae * &term.coeff != &term.coeff.scale(&c.root_elem()) + &next {
                return false;
            }
            if term.power == 0 {
                let s = power_sums(&c.factor, c.factor.deg());
                let tr = term.coeff.map(&k, |x| {
                    x.0.iter()
                        .zip(&s)
                        .fold(k.zero(), |acc, (a, b)| k.add(&acc, &k.mul(a, b)))
                });
                sum0 = &sum0 + &tr;
            }
        }
        sum0.is_identity()
    }
    /// $G_{\theta,k}$ of eigenvalue `ev` of `jf` in that eigenvalue's field
    /// ([`JordanFormK::root_field`]): `(power, G)` pairs.
    pub fn terms_of(&self, jf: &JordanFormK, ev: usize) -> Vec<(usize, Matrix<RelField>)> {
        let e = &jf.eigenvalues[ev];
        let f = jf.root_field(ev);
        self.terms
            .iter()
            .filter(|t| t.component == e.component)
            .map(|t| (t.power, t.coeff.map(&f, |x| x.clone())))
            .collect()
    }
}
