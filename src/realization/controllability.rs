//! Controllability and observability matrices (paper eq. 7-8), the block Hankel matrix
//! (eq. 9) and the McMillan degree.

use crate::error::Result;
use crate::field::Field;
use crate::jordan::JordanField;
use crate::matrix::Matrix;
use crate::system::StateSpace;

/// $\mathcal C = [B, AB, \dots, A^{n-1}B]$.
pub fn controllability_matrix<K: Field>(a: &Matrix<K>, b: &Matrix<K>) -> Matrix<K> {
    let n = a.nrows();
    let mut out = Matrix::zeros(a.field().clone(), n, n * b.ncols());
    let mut ab = b.clone();
    for k in 0..n {
        out.set_block(0, k * b.ncols(), &ab);
        if k + 1 < n {
            ab = a * &ab;
        }
    }
    out
}

/// $\mathcal O = [C; CA; \dots; CA^{n-1}]$.
pub fn observability_matrix<K: Field>(a: &Matrix<K>, c: &Matrix<K>) -> Matrix<K> {
    controllability_matrix(&a.transpose(), &c.transpose()).transpose()
}

/// Is $(A, B)$ controllable ($\mathrm{rank}\,\mathcal C = n$)?
pub fn is_controllable<K: Field>(a: &Matrix<K>, b: &Matrix<K>) -> bool {
    controllability_matrix(a, b).rank() == a.nrows()
}

/// Is $(A, C)$ observable ($\mathrm{rank}\,\mathcal O = n$)?
pub fn is_observable<K: Field>(a: &Matrix<K>, c: &Matrix<K>) -> bool {
    observability_matrix(a, c).rank() == a.nrows()
}

/// Block Hankel matrix with `rows` x `cols` blocks: block $(i, j)$ is $C A^{i+j+shift} B$.
pub fn hankel_matrix<K: Field>(
    sys: &StateSpace<K>,
    rows: usize,
    cols: usize,
    shift: usize,
) -> Matrix<K> {
    let (p, m) = (sys.noutputs(), sys.ninputs());
    let mk = sys.markov(rows + cols + shift);
    let mut h = Matrix::zeros(sys.field().clone(), rows * p, cols * m);
    for i in 0..rows {
        for j in 0..cols {
            h.set_block(i * p, j * m, &mk[i + j + shift]);
        }
    }
    h
}

/// McMillan degree: the rank of the $n \times n$-block Hankel matrix $\mathcal O \mathcal C$.
pub fn mcmillan_degree<K: Field>(sys: &StateSpace<K>) -> usize {
    let n = sys.nstates();
    if n == 0 || sys.ninputs() == 0 || sys.noutputs() == 0 {
        return 0;
    }
    hankel_matrix(sys, n, n, 0).rank()
}

/// An invertible `T` with $T X = [0; Y]$, `Y` of full row rank: the left null space of `X`
/// on top, completed by unit rows. Returns `(T, rank X)`.
pub fn row_compression<K: Field>(x: &Matrix<K>) -> (Matrix<K>, usize) {
    let l = x.left_nullspace();
    let comp = l.transpose().complete_basis().transpose();
    let r = comp.nrows();
    (l.vstack(&comp).expect("same width"), r)
}

/// PBH test (Popov–Belevitch–Hautus): $(A, B)$ is controllable iff
/// $\mathrm{rank}\,[A - \lambda I, B] = n$ for every eigenvalue $\lambda$. Exact over every
/// [`JordanField`] ($\mathbb{Q}(p)$ too), all over the base field $F$ (no arithmetic in an
/// extension $F\[t\]/(g)$, whose inverses swell over $\mathbb{Q}(p)$):
///
/// * a left eigenvector $w$ with $w B = 0$ exists for some eigenvalue iff the Kalman matrix
///   $\mathcal C$ has rank $< n$ (Hautus $\Leftrightarrow$ Kalman), so full rank decides every
///   eigenvalue at once;
/// * otherwise the test runs per irreducible factor $g$ of $\det(sI - A)$ over $F$: the left
///   kernel $W$ of $g(A)$ holds every left eigenvector of every root of $g$ and is
///   $A$-invariant, so PBH fails at the roots of $g$ iff $(W A^j B)_{j < k}$ has rank
///   $< k = \dim W$ (the $g$-primary part's controllability; for $g = s - \theta$ this is
///   $\mathrm{rank}\,[A - \theta I, B] < n$). Some factor must fail: if none does, the two
///   tests disagree and `Verification` is returned.
///
/// # Errors
/// `NotSquare`/`Shape`; factorization failures; `Verification` as above.
pub fn pbh_controllable<F: JordanField>(a: &Matrix<F>, b: &Matrix<F>) -> Result<bool> {
    a.check_square("pbh")?;
    let n = a.nrows();
    b.check_shape("pbh B", (n, b.ncols()))?;
    if controllability_matrix(a, b).rank() == n {
        return Ok(true);
    }
    for (g, _) in F::charpoly_factors(a)? {
        let w = a.eval_poly(&g)?.left_nullspace();
        let k = w.nrows();
        let mut r = w;
        let mut kry = Matrix::zeros(a.field().clone(), k, 0);
        for _ in 0..k {
            kry = kry.hstack(&(&r * b))?;
            r = &r * a;
        }
        if kry.rank() < k {
            return Ok(false);
        }
    }
    Err(crate::error::Error::Verification(
        "PBH: the Kalman matrix is rank deficient but no eigenvalue fails the PBH test".into(),
    ))
}

/// PBH test for observability: the dual of [`pbh_controllable`].
///
/// # Errors
/// As [`pbh_controllable`].
pub fn pbh_observable<F: JordanField>(a: &Matrix<F>, c: &Matrix<F>) -> Result<bool> {
    pbh_controllable(&a.transpose(), &c.transpose())
}
