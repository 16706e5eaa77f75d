//! Approximate values near a critical value (guidance and display only; every decision
//! that matters is exact): elements of $\mathbb{Q}(v_0)$ and polynomial roots in `f64`.

use crate::algebraic::{NfElem, NumberField};
use crate::error::Result;
use crate::field::{Q, Rational, rational_to_f64};
use crate::poly::Poly;
use num_complex::Complex;

/// $e(v_0)$ in `f64`, evaluated exactly at the rational `vq` near $v_0$.
pub(super) fn approx_elem(k: &NumberField, e: &NfElem, vq: &Rational) -> f64 {
    rational_to_f64(&k.elem_to_poly(e).eval(vq))
}

/// Roots of $\sum_i c_i x^i$ (`c` low degree first, leading `c` nonzero) as the
/// eigenvalues of its companion matrix; none for a constant.
fn companion_roots(c: &[f64]) -> Result<Vec<Complex<f64>>> {
    let d = c.len().saturating_sub(1);
    match d {
        0 => return Ok(vec![]),
        1 => return Ok(vec![Complex::new(-c[0] / c[1], 0.0)]),
        _ => {}
    }
    let comp = nalgebra::DMatrix::from_fn(d, d, |i, j| {
        if i == 0 {
            -c[d - 1 - j] / c[d]
        } else if i == j + 1 {
            1.0
        } else {
            0.0
        }
    });
    crate::float::eigenvalues(&comp)
}

/// Approximate roots of a polynomial over $\mathbb{Q}(v_0)$ (companion eigenvalues).
pub(super) fn approx_roots(
    k: &NumberField,
    q: &Poly<NumberField>,
    v0: &Rational,
) -> Result<Vec<Complex<f64>>> {
    let c: Vec<f64> = q.coeffs().iter().map(|e| approx_elem(k, e, v0)).collect();
    companion_roots(&c)
}

/// Numeric roots of a rational polynomial (companion eigenvalues).
pub(super) fn approx_roots_q(p: &Poly<Q>) -> Result<Vec<Complex<f64>>> {
    let c: Vec<f64> = p.coeffs().iter().map(rational_to_f64).collect();
    companion_roots(&c)
}
