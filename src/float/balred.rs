//! Balanced truncation on the float path (python-control's `balred(sys, r)`, method
//! `truncate`; SLICOT AB09AD's square-root method).
//!
//! For a stable $(A, B, C, D)$: the Gramians $A W_c + W_c A^T + B B^T = 0$ and
//! $A^T W_o + W_o A + C^T C = 0$ (solved as Kronecker systems), symmetric square roots
//! $W_c = L_c L_c^T$, $W_o = L_o L_o^T$, the SVD $L_o^T L_c = U \Sigma V^T$ (the Hankel
//! singular values $\sigma_i$, the square roots of the eigenvalues of $W_c W_o$), and with
//! $T_r = L_c V_r \Sigma_r^{-1/2}$, $T_l = \Sigma_r^{-1/2} U_r^T L_o^T$ ($T_l T_r = I_r$):
//! $A_r = T_l A T_r$, $B_r = T_l B$, $C_r = C T_r$, $D_r = D$. The truncated system is
//! balanced (both of its Gramians are $\Sigma_r$) and
//! $\|G - G_r\|_\infty \le 2 \sum_{i > r} \sigma_i$.

use nalgebra::{DMatrix, SymmetricEigen};

use crate::error::{Error, Result};

/// Largest order solved (the Kronecker system has $n^2$ unknowns).
pub const MAX_BALRED_ORDER: usize = 40;

/// A balanced truncation.
#[derive(Clone, Debug, PartialEq)]
pub struct Balred {
    pub a: DMatrix<f64>,
    pub b: DMatrix<f64>,
    pub c: DMatrix<f64>,
    pub d: DMatrix<f64>,
    /// All Hankel singular values, decreasing.
    pub hankel_singular_values: Vec<f64>,
    /// $2 \sum_{i > r} \sigma_i$: the bound on $\|G - G_r\|_\infty$.
    pub error_bound: f64,
}

/// $X$ with $A X + X A^T + Q = 0$ (Kronecker: $(I \otimes A + A \otimes I) \mathrm{vec} X =
/// -\mathrm{vec} Q$), symmetrized.
fn lyap(a: &DMatrix<f64>, q: &DMatrix<f64>) -> Result<DMatrix<f64>> {
    let n = a.nrows();
    let mut k = DMatrix::<f64>::zeros(n * n, n * n);
    for i in 0..n {
        for j in 0..n {
            // vec index of X[i][j] (column-major): j * n + i
            let row = j * n + i;
            for l in 0..n {
                k[(row, j * n + l)] += a[(i, l)];
                k[(row, l * n + i)] += a[(j, l)];
            }
        }
    }
    let rhs = DMatrix::from_iterator(n * n, 1, q.iter().map(|x| -x));
    let x = k
        .lu()
        .solve(&rhs)
        .ok_or_else(|| Error::Invalid("the Lyapunov equation is singular".into()))?;
    let x = DMatrix::from_iterator(n, n, x.iter().copied());
    Ok((&x + x.transpose()) * 0.5)
}

/// A square root $L$ with $L L^T = W$ of a symmetric positive semidefinite $W$
/// (eigenvalues below zero from round-off clamped to 0).
fn sqrt_psd(w: &DMatrix<f64>) -> DMatrix<f64> {
    let e = SymmetricEigen::new(w.clone());
    let mut l = e.eigenvectors.clone();
    for (j, lam) in e.eigenvalues.iter().enumerate() {
        let s = lam.max(0.0).sqrt();
        l.column_mut(j).scale_mut(s);
    }
    l
}

/// The balanced truncation of order `r` of a stable system.
///
/// # Errors
/// `Invalid` for an unstable $A$ (an eigenvalue with real part $\ge 0$), an order above
/// [`MAX_BALRED_ORDER`], `r` above the number of nonzero Hankel singular values.
pub fn balred([a, b, c, d]: [&DMatrix<f64>; 4], r: usize) -> Result<Balred> {
    let n = a.nrows();
    if n > MAX_BALRED_ORDER {
        return Err(Error::Invalid(format!(
            "balanced truncation: order {n} above {MAX_BALRED_ORDER} on the float path"
        )));
    }
    if n > 0 && super::eigenvalues(a)?.iter().any(|z| z.re >= 0.0) {
        return Err(Error::Invalid(
            "balanced truncation needs a stable A (every eigenvalue with Re < 0)".into(),
        ));
    }
    let wc = lyap(a, &(b * b.transpose()))?;
    let wo = lyap(&a.transpose(), &(c.transpose() * c))?;
    let (lc, lo) = (sqrt_psd(&wc), sqrt_psd(&wo));
    let svd = (lo.transpose() * &lc).svd(true, true);
    let (u, vt) = (
        svd.u.ok_or_else(|| Error::Invalid("SVD failed".into()))?,
        svd.v_t.ok_or_else(|| Error::Invalid("SVD failed".into()))?,
    );
    // nalgebra's singular values are not sorted: order them decreasing
    let mut idx: Vec<usize> = (0..svd.singular_values.len()).collect();
    idx.sort_by(|&i, &j| svd.singular_values[j].total_cmp(&svd.singular_values[i]));
    let hsv: Vec<f64> = idx.iter().map(|&i| svd.singular_values[i]).collect();
    let tol = hsv.first().copied().unwrap_or(0.0) * 1e-13 * (n.max(1) as f64);
    let nonzero = hsv.iter().filter(|s| **s > tol).count();
    if r > nonzero {
        return Err(Error::Invalid(format!(
            "balanced truncation: order {r} above the {nonzero} nonzero Hankel singular values"
        )));
    }
    let mut tr = DMatrix::<f64>::zeros(n, r);
    let mut tl = DMatrix::<f64>::zeros(r, n);
    for (k, &i) in idx.iter().take(r).enumerate() {
        let s = hsv[k].sqrt();
        tr.set_column(k, &(&lc * vt.row(i).transpose() / s));
        tl.set_row(k, &((lo.clone() * u.column(i)).transpose() / s));
    }
    Ok(Balred {
        a: &tl * a * &tr,
        b: &tl * b,
        c: c * &tr,
        d: d.clone(),
        error_bound: 2.0 * hsv[r..].iter().sum::<f64>(),
        hankel_singular_values: hsv,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lyapunov_residual_and_balanced_gramians() {
        let a = DMatrix::from_row_slice(3, 3, &[-1.0, 2.0, 0.0, 0.0, -3.0, 1.0, 0.5, 0.0, -2.0]);
        let b = DMatrix::from_row_slice(3, 1, &[1.0, 0.0, 1.0]);
        let c = DMatrix::from_row_slice(1, 3, &[1.0, 1.0, 0.0]);
        let d = DMatrix::zeros(1, 1);
        let q = &b * b.transpose();
        let x = lyap(&a, &q).unwrap();
        assert!((&a * &x + &x * a.transpose() + &q).amax() < 1e-12);
        let full = balred([&a, &b, &c, &d], 3).unwrap();
        // the full-order balanced realization has both Gramians diag(sigma)
        let wc = lyap(&full.a, &(&full.b * full.b.transpose())).unwrap();
        let wo = lyap(&full.a.transpose(), &(full.c.transpose() * &full.c)).unwrap();
        let sig = DMatrix::from_diagonal(&nalgebra::DVector::from_vec(
            full.hankel_singular_values.clone(),
        ));
        assert!((&wc - &sig).amax() < 1e-10, "{wc}");
        assert!((&wo - &sig).amax() < 1e-10, "{wo}");
        assert!(full.error_bound.abs() < 1e-12);
        let r1 = balred([&a, &b, &c, &d], 1).unwrap();
        assert_eq!((r1.a.nrows(), r1.b.ncols(), r1.c.nrows()), (1, 1, 1));
        assert!(balred([&a, &b, &c, &d], 4).is_err());
        let unstable = DMatrix::from_row_slice(1, 1, &[1.0]);
        let one = DMatrix::from_row_slice(1, 1, &[1.0]);
        assert!(balred([&unstable, &one, &one, &d], 1).is_err());
    }
}
