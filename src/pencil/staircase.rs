//! Exact staircase deflation of a pencil $A - sE$ (Van Dooren 1979), one step per kernel.
//!
//! Step $i$: $N_i$ = basis of $\ker E$ (dimension $n_i$), $\rho_i = \mathrm{rank}(A N_i)$.
//! With column coordinates $[X, N_i]$ ($X$ = unit vectors at the pivot columns of
//! $\mathrm{rref}(E)$) and row coordinates $[Z; Y]$ ($Y$ = canonical left null space of
//! $A N_i$), the pencil becomes
//! $$\begin{bmatrix} Z(A - sE)X & Z A N_i \\ Y(A - sE)X & 0 \end{bmatrix},$$
//! $Z A N_i$ of full row rank $\rho_i$, and the step continues on $Y A X - s\,Y E X$.
//! It stops when $E$ has full column rank. Then (Van Dooren, Thm. 3.2) the number of right
//! minimal indices equal to $i - 1$ is $n_i - \rho_i$, and the number of infinite Jordan
//! blocks of size $i$ is $\rho_i - n_{i+1}$. All ranks and null spaces are exact.

use crate::field::Field;
use crate::matrix::Matrix;

/// Dimensions $(n_i, \rho_i)$ of the staircase steps and the deflated pencil.
#[derive(Clone, Debug)]
pub(crate) struct Deflation<K: Field> {
    pub steps: Vec<(usize, usize)>,
    pub a: Matrix<K>,
    pub e: Matrix<K>,
}

/// Runs the staircase until $E$ has full column rank.
pub(crate) fn deflate_right<K: Field>(a: &Matrix<K>, e: &Matrix<K>) -> Deflation<K> {
    let mut a = a.clone();
    let mut e = e.clone();
    let mut steps = Vec::new();
    loop {
        let n = e.ncols();
        let (r, piv) = e.rref();
        if piv.len() == n {
            break;
        }
        let ker = crate::matrix::nullspace_from_rref(&r, &piv);
        let an = &a * &ker;
        let y = an.left_nullspace();
        let rho = a.nrows() - y.nrows();
        steps.push((ker.ncols(), rho));
        let ax = a.select_cols(&piv);
        let ex = e.select_cols(&piv);
        a = &y * &ax;
        e = &y * &ex;
    }
    Deflation { steps, a, e }
}

/// Right minimal indices (ascending) and infinite block sizes (ascending) from the steps.
pub(crate) fn indices_from_steps(steps: &[(usize, usize)]) -> (Vec<usize>, Vec<usize>) {
    let mut eps = Vec::new();
    let mut inf = Vec::new();
    for (i, &(ni, rho)) in steps.iter().enumerate() {
        let next = steps.get(i + 1).map_or(0, |s| s.0);
        eps.extend(std::iter::repeat_n(i, ni.saturating_sub(rho)));
        inf.extend(std::iter::repeat_n(i + 1, rho.saturating_sub(next)));
    }
    (eps, inf)
}
