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
use crate::matrix::Matrix;

/// $G_{\theta,k}$ of one component ($n \times n$ over $E$).
pub type ResponseTermK = crate::jordan::ResponseTerm<RelField>;

/// $e^{At}$ over $K$ as a finite sum of exact terms.
pub type FreeResponseK = crate::jordan::FreeResponse<RelField>;

impl FreeResponseK {
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
