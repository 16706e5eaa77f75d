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
//!
//! # Certificate of a step
//! Each step is checked on its outputs, without trusting the eliminations that produced
//! them: $E N_i = 0$ exactly, the rows of $N_i$ outside the pivots form the identity (so
//! $[X, N_i]$ is invertible and $N_i$ has full column rank), $\mathrm{rank}\,E \ge
//! \#\text{pivots}$; hence $\ker E = \mathrm{span}\,N_i$ exactly. Then $Y (A N_i) = 0$
//! exactly, $\mathrm{rank}\,Y = $ its number of rows and $\mathrm{rank}(A N_i) \ge \rho_i$;
//! hence $\mathrm{rank}(A N_i) = \rho_i$ and the rows of $Y$ span the left null space of
//! $A N_i$ (so $[Z; Y]$ is invertible for a complement $Z$). The last step checks
//! $\mathrm{rank}\,E = $ its number of columns. Every lower bound on a rank is exact
//! ([`crate::matrix::Matrix::rank_at_least`]: over $\mathbb{Q}$ one elimination modulo a
//! prime), every upper bound comes from an exhibited exact null space. These are the
//! hypotheses of Van Dooren's Thm. 3.2, so the indices read off the steps are exact.

use crate::field::Field;
use crate::matrix::Matrix;

/// Dimensions $(n_i, \rho_i)$ of the staircase steps and the deflated pencil.
#[derive(Clone, Debug)]
pub(crate) struct Deflation<K: Field> {
    pub steps: Vec<(usize, usize)>,
    pub a: Matrix<K>,
    pub e: Matrix<K>,
    /// Every step's certificate (module docs) held.
    pub certified: bool,
}

/// Do the rows of `ker` outside `piv` form the identity (in increasing order)?
fn identity_off_pivots<K: Field>(ker: &Matrix<K>, piv: &[usize]) -> bool {
    let free: Vec<usize> = (0..ker.nrows()).filter(|i| !piv.contains(i)).collect();
    ker.is_identity_on_rows(&free)
}

/// Runs the staircase until $E$ has full column rank.
pub(crate) fn deflate_right<K: Field>(a: &Matrix<K>, e: &Matrix<K>) -> Deflation<K> {
    let mut a = a.clone();
    let mut e = e.clone();
    let mut steps = Vec::new();
    let mut certified = true;
    loop {
        let n = e.ncols();
        let (r, piv) = e.rref();
        certified = certified && e.rank_at_least(piv.len());
        if piv.len() == n {
            break;
        }
        let ker = crate::matrix::nullspace_from_rref(&r, &piv);
        certified = certified && identity_off_pivots(&ker, &piv) && (&e * &ker).is_zero();
        let an = &a * &ker;
        let y = an.left_nullspace();
        let rho = a.nrows() - y.nrows();
        certified = certified
            && (&y * &an).is_zero()
            && y.rank_at_least(y.nrows())
            && an.rank_at_least(rho);
        steps.push((ker.ncols(), rho));
        let ax = a.select_cols(&piv);
        let ex = e.select_cols(&piv);
        a = &y * &ax;
        e = &y * &ex;
    }
    Deflation {
        steps,
        a,
        e,
        certified,
    }
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
