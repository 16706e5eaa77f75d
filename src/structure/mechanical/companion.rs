//! The mechanical normal form of a controllable single-input pair, built without the search
//! of eq. 15: the interleaved controller form.
//!
//! For $(A, b)$ controllable with one input and $n = 2h$ states let $w$ be the row with
//! $w A^j b = \delta_{j, n-1}$ ($j < n$), i.e. $w \mathcal{C} = e_n^T$ for the Krylov matrix
//! $\mathcal{C} = [b, Ab, \dots, A^{n-1} b]$. The rows $w A^j$ ($j < n$) form the controller
//! form's transformation $T_c$, and with $\chi(s) = \det(sI - A) = \sum_l a_l s^l$
//! ($a_n = 1$)
//! $$T_c^{-1} = S, \qquad S_{:,k} = \sum_{l = k+1}^{n} a_l A^{l-k-1} b,
//! \quad S_{:,n-1} = b,\ S_{:,k} = A S_{:,k+1} + a_{k+1} b$$
//! (Faddeev–LeVerrier: $S_{:,k} = B_k b$ with $\operatorname{adj}(sI - A) = \sum_k s^k B_k$;
//! $T_c S$ is the Hankel matrix of the $w A^{i+j} b$ times the Hankel matrix of the $a_l$,
//! which is $I$ by Cayley–Hamilton). Interleaving the rows,
//! $$t_i = w A^{2i}, \qquad t_{h+i} = w A^{2i+1} \qquad (i = 0, \dots, h-1),$$
//! gives $t_i A = t_{h+i}$ (the upper half of $\tilde A = [[0, I], [\cdot, \cdot]]$) and
//! $T b = e_n$ ($w A^j b = 0$ for $j < n - 1$): $T$ solves eq. 15, it is a row permutation of
//! $T_c$ (so invertible) and $T^{-1}$ is the same permutation of the columns of $S$, which
//! needs no inverse. The lower half of $\tilde A$ is read off the rows:
//! $t_{h+i} A = w A^{2i+2} = t_{i+1}$ for $i < h - 1$ and
//! $t_{n-1} A = w A^n = -\sum_{l<n} a_l\, w A^l$ (Cayley–Hamilton).
//!
//! Only $w$ costs a solve (one right-hand side); the columns of $S$, $\tilde A$ and
//! $\tilde C = C S$ are polynomial in $A$, $b$, $C$ and the $a_l$. For a diagonal
//! $A = \operatorname{diag}(p_0, \dots, p_{n-1})$ the column $l$ of $T$ has the single
//! denominator $b_l \prod_{j \ne l} (p_l - p_j)$ while $T^{-1}$ is polynomial; every check of
//! [`super::MechanicalNormalForm::verify`] is then a product with one denominator per column.

use crate::error::Result;
use crate::field::Field;
use crate::matrix::Matrix;
use crate::realization::controllability_matrix;

/// $(T, T^{-1}, \tilde A)$.
pub type Interleaved<K> = (Matrix<K>, Matrix<K>, Matrix<K>);

/// $(T, T^{-1}, \tilde A)$ of the interleaved controller form for a controllable pair with one
/// input and an even number of states (see the module docs); `None` when the pair does not
/// qualify (more inputs, odd `n`, `n = 0`) or the Krylov matrix is singular.
///
/// # Errors
/// `Limit` from the characteristic polynomial.
pub fn interleaved_controller_form<K: Field>(
    a: &Matrix<K>,
    b: &Matrix<K>,
) -> Result<Option<Interleaved<K>>> {
    let n = a.nrows();
    if b.ncols() != 1 || n == 0 || !n.is_multiple_of(2) {
        return Ok(None);
    }
    let k = a.field().clone();
    let krylov = controllability_matrix(a, b);
    let mut e_last = Matrix::zeros(k.clone(), n, 1);
    e_last.set(n - 1, 0, k.one());
    // w^T solves C^T w^T = e_n (a unique solution exactly when (A, b) is controllable)
    let w = match krylov.transpose().solve(&e_last)? {
        Some((x, null)) if null.ncols() == 0 => x.transpose(),
        _ => return Ok(None),
    };
    let chi = a.charpoly()?;
    let coeff = |l: usize| -> K::Elem { chi.coeff(l) };
    // rows w A^j, j < n
    let mut powers = vec![w.row(0).to_vec()];
    let mut wa = w.clone();
    for _ in 1..n {
        wa = wa.try_mul(a)?;
        powers.push(wa.row(0).to_vec());
    }
    // columns S_{:,k}: S_{:,n-1} = b, S_{:,k} = A S_{:,k+1} + a_{k+1} b
    let mut s_cols = vec![b.clone(); n];
    for kk in (0..n - 1).rev() {
        s_cols[kk] = &a.try_mul(&s_cols[kk + 1])? + &b.scale(&coeff(kk + 1));
    }
    let h = n / 2;
    // state r of the form is w A^{order[r]}
    let order: Vec<usize> = (0..h)
        .map(|i| 2 * i)
        .chain((0..h).map(|i| 2 * i + 1))
        .collect();
    let mut pos = vec![0; n];
    for (r, &j) in order.iter().enumerate() {
        pos[j] = r;
    }
    let t = Matrix::from_fn(k.clone(), n, n, |r, c| powers[order[r]][c].clone());
    let t_inv = Matrix::from_fn(k.clone(), n, n, |i, r| s_cols[order[r]].get(i, 0).clone());
    // row r of A~: t_r A = w A^{order[r] + 1}, a row of T, or -sum_l a_l w A^l
    let mut a_tilde = Matrix::zeros(k.clone(), n, n);
    for r in 0..n {
        let j = order[r] + 1;
        if j < n {
            a_tilde.set(r, pos[j], k.one());
        } else {
            for l in 0..n {
                a_tilde.set(r, pos[l], k.neg(&coeff(l)));
            }
        }
    }
    Ok(Some((t, t_inv, a_tilde)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::qmat;

    /// On a controllable pair: $T T^{-1} = I$, $T A = \tilde A T$, $T b = e_n$ and the upper
    /// half of $\tilde A$ is $[0\ I]$.
    #[test]
    fn interleaved_form_identities() {
        let a = qmat![[1, 2, 0, -1], [0, -3, 1, 2], [4, 0, 2, 1], [-1, 1, 0, 5]];
        let b = qmat![[1], [0], [2], [-1]];
        let (t, t_inv, at) = interleaved_controller_form(&a, &b).unwrap().unwrap();
        assert!((&t * &t_inv).is_identity());
        assert_eq!(&at * &t, &t * &a);
        assert_eq!(&t * &b, qmat![[0], [0], [0], [1]]);
        assert_eq!(at.submatrix(0, 2, 0, 4), qmat![[0, 0, 1, 0], [0, 0, 0, 1]]);
        // an uncontrollable pair does not qualify
        let a = qmat![[1, 0], [0, 1]];
        assert!(
            interleaved_controller_form(&a, &qmat![[1], [1]])
                .unwrap()
                .is_none()
        );
    }
}
