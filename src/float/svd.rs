//! One-sided Jacobi SVD (Hestenes), the rank-revealing kernel of the float backend.
//!
//! Plane rotations $V = \prod J_{pq}$ make the columns of $W = GV$ mutually orthogonal; then
//! $\sigma_j = \lVert w_j \rVert$ and $G = W V^T$ with $W = U\Sigma$. $V$ is a product of
//! rotations, so it is orthogonal to working precision even where singular values vanish, and
//! small singular values come out with high relative accuracy.
//!
//! Why not nalgebra's SVD: in nalgebra 0.35 it returns inaccurate singular values and left
//! singular vectors for some rank-deficient inputs (e.g. a 3x3 upper triangular matrix whose
//! last two rows are $O(10^{-16})$: $\sigma_1$ off by $4\cdot 10^{-3}$), which breaks a
//! staircase silently. Jacobi is slower but these matrices are small or few.

use nalgebra::DMatrix;
use num_complex::Complex;

use super::FloatScalar;

/// The result of [`jacobi_svd`]: singular values descending, `v` orthogonal (unitary for
/// complex `T`), `w = G v`.
pub(crate) struct JacobiSvd<T: FloatScalar = f64> {
    pub sv: Vec<f64>,
    pub v: DMatrix<T>,
    pub w: DMatrix<T>,
}

/// One-sided Jacobi SVD of `g` (`m x n`): `n` singular values (zeros included when `m < n`).
///
/// Complex columns: with $\gamma = g_p^H g_q = |\gamma| e^{i\varphi}$, column `q` is first
/// multiplied by $e^{-i\varphi}$ (a unitary diagonal factor, applied to `v` as well), which
/// makes $\gamma$ real, then rotated as in the real case. Real input never takes that step.
pub(crate) fn jacobi_svd<T: FloatScalar>(mut g: DMatrix<T>) -> JacobiSvd<T> {
    let (m, n) = g.shape();
    let mut v = DMatrix::<T>::identity(n, n);
    let tol = f64::EPSILON * (m.max(1) as f64).sqrt();
    for _sweep in 0..80 {
        let mut rotated = false;
        for p in 0..n {
            for q in p + 1..n {
                let (alpha, beta, mut gamma) = {
                    let gp = g.column(p);
                    let gq = g.column(q);
                    (gp.norm_squared(), gq.norm_squared(), gp.dotc(&gq))
                };
                let modulus = gamma.modulus();
                if alpha == 0.0 || beta == 0.0 || modulus <= tol * (alpha * beta).sqrt() {
                    continue;
                }
                if gamma.imaginary() != 0.0 {
                    let phase = (gamma / T::from_real(modulus)).conjugate();
                    scale_column(&mut g, q, phase);
                    scale_column(&mut v, q, phase);
                    gamma = T::from_real(modulus);
                }
                let gamma = gamma.real();
                rotated = true;
                let zeta = (beta - alpha) / (2.0 * gamma);
                let t = zeta.signum() / (zeta.abs() + (1.0 + zeta * zeta).sqrt());
                let c = 1.0 / (1.0 + t * t).sqrt();
                let s = c * t;
                rotate(&mut g, p, q, c, s);
                rotate(&mut v, p, q, c, s);
            }
        }
        if !rotated {
            break;
        }
    }
    let norms: Vec<f64> = (0..n).map(|j| g.column(j).norm()).collect();
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by(|&x, &y| norms[y].total_cmp(&norms[x]).then(x.cmp(&y)));
    let sv = order.iter().map(|&j| norms[j]).collect();
    let v = DMatrix::from_fn(n, n, |i, j| v[(i, order[j])]);
    let w = DMatrix::from_fn(m, n, |i, j| g[(i, order[j])]);
    JacobiSvd { sv, v, w }
}

/// Column `q` of `x` <- `z x_q`.
fn scale_column<T: FloatScalar>(x: &mut DMatrix<T>, q: usize, z: T) {
    for e in x.column_mut(q).iter_mut() {
        *e *= z;
    }
}

/// Columns `p, q` of `x` <- `(c x_p - s x_q, s x_p + c x_q)`.
fn rotate<T: FloatScalar>(x: &mut DMatrix<T>, p: usize, q: usize, c: f64, s: f64) {
    let nr = x.nrows();
    let data = x.as_mut_slice();
    let (lo, hi) = data.split_at_mut(q * nr);
    let xp = &mut lo[p * nr..(p + 1) * nr];
    let xq = &mut hi[..nr];
    for (a, b) in xp.iter_mut().zip(xq.iter_mut()) {
        let (u, w) = (*a, *b);
        *a = u.scale(c) - w.scale(s);
        *b = u.scale(s) + w.scale(c);
    }
}

/// Singular values of `m` (`min(rows, cols)` of them, descending) and a full orthogonal `U`
/// (`rows x rows`) with `U^T m` having rows of norms `σ_1, σ_2, ...` followed by zero rows.
pub(crate) fn left_basis(m: &DMatrix<f64>) -> (Vec<f64>, DMatrix<f64>) {
    let k = m.nrows().min(m.ncols());
    let j = jacobi_svd(m.transpose());
    (j.sv[..k].to_vec(), j.v)
}

/// Singular values of `m` (`min(rows, cols)`, descending) and a full orthogonal `V`
/// (`cols x cols`) with `m V` having columns of norms `σ_1, σ_2, ...` then zero columns.
pub(crate) fn right_basis(m: &DMatrix<f64>) -> (Vec<f64>, DMatrix<f64>) {
    let k = m.nrows().min(m.ncols());
    let j = jacobi_svd(m.clone());
    (j.sv[..k].to_vec(), j.v)
}

/// Singular values of a complex matrix, through the real embedding
/// $\begin{bmatrix} \Re M & -\Im M \\ \Im M & \Re M \end{bmatrix}$ (each value twice).
pub(crate) fn complex_singular_values(m: &DMatrix<Complex<f64>>) -> Vec<f64> {
    let (r, c) = m.shape();
    let real = DMatrix::from_fn(2 * r, 2 * c, |i, j| {
        let z = m[(i % r, j % c)];
        match (i < r, j < c) {
            (true, true) | (false, false) => z.re,
            (true, false) => -z.im,
            (false, true) => z.im,
        }
    });
    let sv = jacobi_svd(real).sv;
    sv.iter().step_by(2).take(r.min(c)).copied().collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn jacobi_rank_deficient_triangle() {
        // The case where nalgebra 0.35's SVD is off by 4e-3.
        let r = DMatrix::from_row_slice(
            3,
            3,
            &[
                -0.286894844536796,
                -0.18976084760429482,
                -0.19589067563148568,
                0.0,
                -4.0892403624808086e-16,
                -2.0316683689780122e-16,
                0.0,
                0.0,
                -2.0571979251763968e-16,
            ],
        );
        let (sv, u) = left_basis(&r);
        assert!((sv[0] - 0.395842125).abs() < 1e-9, "{sv:?}");
        assert!(sv[1] < 1e-15 && sv[2] < 1e-15);
        assert!((u[(0, 0)].abs() - 1.0).abs() < 1e-14, "{u}");
        let o = u.transpose() * &u - DMatrix::<f64>::identity(3, 3);
        assert!(o.norm() < 1e-14);
    }

    #[test]
    fn jacobi_reconstructs() {
        let g = DMatrix::from_fn(5, 3, |i, j| {
            ((i * 7 + j * 3) % 5) as f64 - 2.0 + 0.1 * j as f64
        });
        let s = jacobi_svd(g.clone());
        let back = &s.w * s.v.transpose();
        assert!((back - &g).norm() < 1e-13);
        assert!(s.sv.windows(2).all(|w| w[0] >= w[1]));
        let (sv, v) = right_basis(&g);
        assert_eq!(sv.len(), 3);
        assert!((v.transpose() * &v - DMatrix::<f64>::identity(3, 3)).norm() < 1e-14);
        let z = DMatrix::from_fn(2, 2, |i, j| {
            Complex::new((i + j) as f64, i as f64 - j as f64)
        });
        let cs = complex_singular_values(&z);
        assert_eq!(cs.len(), 2);
        // |det| = product of singular values.
        let det = z[(0, 0)] * z[(1, 1)] - z[(0, 1)] * z[(1, 0)];
        assert!((cs[0] * cs[1] - det.norm()).abs() < 1e-12);
    }
}
