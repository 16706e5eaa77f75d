//! The unifying transformation of sec. 2.2.
//!
//! A transformation $\hat T$ with $[I\ 0]\hat T A = [0\ I]\hat T F$ and
//! $\hat T B = [0; \hat B_2]$ ($\hat B_2$ of size $n/2 \times p$, rank $p$) is followed by
//! $W = \mathrm{blkdiag}(W_1, W_1)$ with $W_1 \hat B_2 = [0; I_p]$ (eq. 13–14). $W$ keeps the
//! upper block row $[0\ I]$ of the state matrix because it acts identically on both halves.
//! Here $W_1 = [E, \hat B_2]^{-1}$ where $E$ completes the columns of $\hat B_2$ to a basis
//! with unit vectors, so $W_1 \hat B_2$ is the last $p$ columns of $I$.
//!
//! | entry point | computes |
//! |---|---|
//! | [`unifying_transformation`] | $W$ for a given $\hat T$ and $B$ |

use crate::error::{Error, Result};
use crate::field::Field;
use crate::matrix::Matrix;

/// $W = \mathrm{blkdiag}(W_1, W_1)$ with $W \hat T B = [0; I_p]$ (so `z = W T x`).
///
/// # Errors
/// `Shape` when `t_hat` is not `n x n` with `n = b.nrows()` even; `Invalid` when the upper half
/// of $\hat T B$ is not zero or its lower half $\hat B_2$ does not have rank $p$.
pub fn unifying_transformation<K: Field>(t_hat: &Matrix<K>, b: &Matrix<K>) -> Result<Matrix<K>> {
    let n = b.nrows();
    if t_hat.shape() != (n, n) || !n.is_multiple_of(2) {
        return Err(Error::Shape {
            op: "unifying_transformation",
            expected: (n, n),
            found: t_hat.shape(),
        });
    }
    let h = n / 2;
    let p = b.ncols();
    let bh = t_hat.try_mul(b)?;
    if !bh.submatrix(0, h, 0, p).is_zero() {
        return Err(Error::Invalid(
            "the upper half of T B is not zero: T is not of the form [X^T; X^T A]".into(),
        ));
    }
    let b2 = bh.submatrix(h, n, 0, p);
    if b2.rank() != p {
        return Err(Error::Invalid(format!(
            "the lower half of T B has rank {} < p = {p}",
            b2.rank()
        )));
    }
    let w1 = b2.complete_basis().hstack(&b2)?.inverse()?;
    Ok(Matrix::block_diag(b.field().clone(), &[w1.clone(), w1]))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::qmat;

    #[test]
    fn unify_examples() {
        // T_hat B = [0; 0; 2; 3] -> W T_hat B = [0; 0; 0; 1]
        let b = qmat![[0], [0], [2], [3]];
        let w = unifying_transformation(&Matrix::identity(crate::field::Q, 4), &b).unwrap();
        assert_eq!(&w * &b, qmat![[0], [0], [0], [1]]);
        assert!(
            unifying_transformation(
                &Matrix::identity(crate::field::Q, 4),
                &qmat![[1], [0], [0], [0]]
            )
            .is_err()
        );
    }
}
