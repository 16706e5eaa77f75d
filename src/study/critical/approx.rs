//! Approximate values near a critical value (guidance and display only; every decision
//! that matters is exact): elements of $\mathbb{Q}(v_0)$ and polynomial roots in `f64`.

use crate::algebraic::{NfElem, NumberField};
use crate::error::Result;
use crate::field::{Q, Rational, rational_to_f64};
use crate::poly::Poly;
use num_complex::Complex;

/// $e(v_0)$ in `f64`, evaluated exactly at the rational `vq` near $v_0$.
pub(super) fn approx_elem(k: &NumberField, e: &NfElem, vq: &Rational) -> f64 {
    rational_to_f64(&k.to_poly(e).eval(vq))
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
    match crate::float::eigenvalues(&comp) {
        Ok(ev) => Ok(ev),
        // the Schur iteration can stall on symmetric spectra (x^4 + 1): these values are
        // guidance only, so fall back to simultaneous iteration on the polynomial itself
        Err(_) => Ok(aberth_roots(c)),
    }
}

/// Roots of $\sum_i c_i x^i$ (degree $d \ge 1$) by the Aberth-Ehrlich iteration from $d$
/// points on a circle of the Cauchy radius; nearly real roots snapped to the real axis,
/// sorted by (real, imaginary) part.
fn aberth_roots(c: &[f64]) -> Vec<Complex<f64>> {
    let d = c.len() - 1;
    let lead = c[d];
    let radius = 1.0 + c[..d].iter().map(|x| (x / lead).abs()).fold(0.0, f64::max);
    let mut z: Vec<Complex<f64>> = (0..d)
        .map(|k| Complex::from_polar(radius, 0.4 + std::f64::consts::TAU * k as f64 / d as f64))
        .collect();
    let eval = |x: Complex<f64>| {
        let (mut p, mut dp) = (Complex::new(0.0, 0.0), Complex::new(0.0, 0.0));
        for a in c.iter().rev() {
            dp = dp * x + p;
            p = p * x + a;
        }
        (p, dp)
    };
    for _ in 0..1000 {
        let mut moved = 0.0f64;
        for k in 0..d {
            let (p, dp) = eval(z[k]);
            if p.norm() == 0.0 {
                continue;
            }
            let ratio = p / dp;
            let repulsion: Complex<f64> = (0..d)
                .filter(|&j| j != k)
                .map(|j| (z[k] - z[j]).inv())
                .sum();
            let w = ratio / (Complex::new(1.0, 0.0) - ratio * repulsion);
            if w.is_finite() {
                z[k] -= w;
                moved = moved.max(w.norm() / (1.0 + z[k].norm()));
            }
        }
        if moved < 1e-15 {
            break;
        }
    }
    for x in &mut z {
        if x.im.abs() <= 1e-10 * (1.0 + x.norm()) {
            x.im = 0.0;
        }
    }
    z.sort_by(|x, y| x.re.total_cmp(&y.re).then(x.im.total_cmp(&y.im)));
    z
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

#[cfg(test)]
mod tests {
    #[test]
    fn aberth_finds_the_roots_of_symmetric_polynomials() {
        // x^4 + 1 and x^4 - 5x^2 + 4 = (x^2 - 1)(x^2 - 4)
        let r = super::aberth_roots(&[1.0, 0.0, 0.0, 0.0, 1.0]);
        assert!(
            r.iter()
                .all(|z| (z.norm() - 1.0).abs() < 1e-12
                    && (z.re.abs() - 0.5f64.sqrt()).abs() < 1e-12)
        );
        let r = super::aberth_roots(&[4.0, 0.0, -5.0, 0.0, 1.0]);
        let re: Vec<f64> = r.iter().map(|z| z.re).collect();
        for (got, want) in re.iter().zip([-2.0, -1.0, 1.0, 2.0]) {
            assert!((got - want).abs() < 1e-12, "{r:?}");
        }
        assert!(r.iter().all(|z| z.im == 0.0));
    }
}
