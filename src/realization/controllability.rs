//! Controllability and observability matrices (paper eq. 7-8), the block Hankel matrix
//! (eq. 9) and the McMillan degree.

use crate::algebraic::Ext;
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
/// [`JordanField`]: one rank per irreducible factor $g$ of $\det(sI - A)$ over the field,
/// computed in $E = F\[t\]/(g)$ at $\lambda = t$ (the conjugate roots give the same rank).
///
/// # Errors
/// `NotSquare`/`Shape`; factorization failures.
pub fn pbh_controllable<F: JordanField>(a: &Matrix<F>, b: &Matrix<F>) -> Result<bool> {
    a.check_square("pbh")?;
    let n = a.nrows();
    b.check_shape("pbh B", (n, b.ncols()))?;
    for (g, _) in F::charpoly_factors(a)? {
        let e = Ext::with_var(&g, (0.0, 0.0), "t");
        let t = e.generator();
        let mut m = a.map(&e, |x| e.from_base(x));
        for i in 0..n {
            let v = e.sub(m.get(i, i), &t);
            m.set(i, i, v);
        }
        if m.hstack(&b.map(&e, |x| e.from_base(x)))?.rank() < n {
            return Ok(false);
        }
    }
    Ok(true)
}

/// PBH test for observability: the dual of [`pbh_controllable`].
///
/// # Errors
/// As [`pbh_controllable`].
pub fn pbh_observable<F: JordanField>(a: &Matrix<F>, c: &Matrix<F>) -> Result<bool> {
    pbh_controllable(&a.transpose(), &c.transpose())
}
