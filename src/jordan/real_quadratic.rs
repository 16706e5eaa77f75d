//! The real Jordan form of the roots of a quadratic factor $g = x^2 + bx + c$ over any field
//! $F$ (over $\mathbb{Q}(p)$ the real form of `jordan --real`), with its sign condition.
//!
//! The roots are $\theta = \alpha \pm i\omega$ with $\alpha = -b/2$ and $\omega = \sqrt{c -
//! b^2/4}$, a complex pair exactly where the discriminant $b^2 - 4c < 0$ (then $\omega$ is
//! real). $\omega$ is kept as a symbol: $R = F\[w\]/(w^2 - (c - b^2/4))$. From the chains of
//! the component ($A v_j = t v_j + v_{j-1}$ over $E = F\[t\]/(g)$, $v_j = p_j + q_j t$) the real
//! columns are $x_j = p_j + \alpha q_j$, $y_j = w q_j$ (real and imaginary part of
//! $v_j(\alpha + i\omega)$), and
//! $$A\,[\dots, x_j, y_j, \dots] = [\dots, x_j, y_j, \dots]\,J_{\mathbb R},$$
//! $J_{\mathbb R}$ with blocks $[[\alpha, w], [-w, \alpha]]$ on the diagonal and $I_2$ above,
//! holds exactly in $R$ (checked: only ring operations, so it holds for either square root).

use super::primary::Component;
use crate::algebraic::{Ext, ExtElem};
use crate::field::Field;
use crate::matrix::Matrix;
use crate::poly::Poly;

/// The real form of one quadratic component (module docs).
#[derive(Clone, Debug)]
pub struct QuadraticReal<F: Field> {
    /// $\alpha = -b/2$, the real part of the pair.
    pub re: F::Elem,
    /// $\omega^2 = c - b^2/4$.
    pub im_squared: F::Elem,
    /// $b^2 - 4c$: the roots are a complex pair exactly where it is $< 0$.
    pub discriminant: F::Elem,
    /// $R = F\[w\]/(w^2 - \omega^2)$, `w` standing for $\omega$.
    pub field: Ext<F>,
    /// The real columns $[x_1, y_1, x_2, y_2, \dots]$ ($n \times 2m$) over $R$.
    pub t: Matrix<Ext<F>>,
    /// $J_{\mathbb R}$ ($2m \times 2m$) over $R$.
    pub j: Matrix<Ext<F>>,
    /// $A T = T J_{\mathbb R}$ holds exactly in $R$.
    pub verified: bool,
}

/// The real form of the component of a monic quadratic factor (module docs), `w` displayed
/// as `var`; `None` for a factor of another degree.
pub fn quadratic_real<F: Field>(
    a: &Matrix<F>,
    comp: &Component<F>,
    var: &str,
) -> Option<QuadraticReal<F>> {
    let g = comp.factor.monic();
    if g.deg() != 2 {
        return None;
    }
    let k = a.field().clone();
    let (b, c) = (g.coeff(1), g.coeff(0));
    let four = k.from_i64(4);
    let re = k.neg(&k.div(&b, &k.from_i64(2))?);
    let b2 = k.mul(&b, &b);
    let discriminant = k.sub(&b2, &k.mul(&four, &c));
    let im_squared = k.neg(&k.div(&discriminant, &four)?);
    let modulus = Poly::new(k.clone(), vec![k.neg(&im_squared), k.zero(), k.one()]);
    let field = Ext::with_var(&modulus, (0.0, 0.0), var);
    let w = field.generator();
    let v = &comp.chains;
    let (n, m) = (v.nrows(), v.ncols());
    let part = |x: &ExtElem<F::Elem>, i: usize| x.0.get(i).cloned().unwrap_or_else(|| k.zero());
    let mut t = Matrix::zeros(field.clone(), n, 2 * m);
    for col in 0..m {
        for row in 0..n {
            let x = v.get(row, col);
            let (p, q) = (part(x, 0), part(x, 1));
            let xr = k.add(&p, &k.mul(&re, &q));
            t.set(row, 2 * col, field.from_base(&xr));
            t.set(row, 2 * col + 1, field.mul(&w, &field.from_base(&q)));
        }
    }
    let alpha = field.from_base(&re);
    let mut j = Matrix::zeros(field.clone(), 2 * m, 2 * m);
    let mut off = 0;
    for &s in &comp.blocks {
        for i in 0..s {
            let r = off + 2 * i;
            j.set(r, r, alpha.clone());
            j.set(r + 1, r + 1, alpha.clone());
            j.set(r, r + 1, w.clone());
            j.set(r + 1, r, field.neg(&w));
            if i + 1 < s {
                j.set(r, r + 2, field.one());
                j.set(r + 1, r + 3, field.one());
            }
        }
        off += 2 * s;
    }
    let ar = a.map(&field, |x| field.from_base(x));
    let verified = match (ar.try_mul(&t), t.try_mul(&j)) {
        (Ok(l), Ok(r)) => l == r,
        _ => false,
    };
    Some(QuadraticReal {
        re,
        im_squared,
        discriminant,
        field,
        t,
        j,
        verified,
    })
}
