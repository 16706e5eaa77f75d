//! Compression of $E$ and elimination of algebraic states of a descriptor system, exactly.
//!
//! With $r = \mathrm{rank}\,E$, $U = [Y; W]$ and $V = [Z, K]$, where $Y$ selects $r$
//! independent rows of $E$, $W E = 0$ (a basis of the left kernel), $Z$ selects $r$
//! independent columns and $EK = 0$:
//! $$UEV = \begin{bmatrix}E_{11} & 0\\ 0 & 0\end{bmatrix},\qquad E_{11} = YEZ
//! \text{ invertible},\qquad x = Vz .$$
//! When $E$ is block diagonal up to a permutation ($E_{11}$ beside zero rows and columns),
//! $U$ and $V$ are permutations and $z$ are the file's own states.
//!
//! Eliminating the states $J$ with the (algebraic) rows $I$, $X = \hat A_{IJ}$ invertible,
//! $R$, $S$ the remaining rows and states:
//! $$A' = \hat A_{RS} - \hat A_{RJ}X^{-1}\hat A_{IS},\quad B' = \hat B_R - \hat A_{RJ}X^{-1}\hat B_I,
//! \quad C' = \hat C_S - \hat C_JX^{-1}\hat A_{IS},\quad D' = D - \hat C_JX^{-1}\hat B_I,$$
//! $E' = \hat E_{RS}$. The rows $I$ read $0 = \hat A_{IJ}z_J + \hat A_{IS}z_S + \hat B_Iu$, so
//! the transfer matrix is unchanged ($\det(sE' - A') = \det(s\hat E - \hat A)/\det(-X)$).
//! With $J$, $I$ a maximal invertible block of $\hat A_{22}$ the result has
//! $A'\ker E' \subseteq \mathrm{im}\,E'$: no non-dynamic modes (its $\hat A_{22}$ is a Schur
//! complement of a rank-$k$ matrix in a $k \times k$ invertible block, hence zero). When
//! $k = n - r$ (index at most 1) nothing algebraic is left: $E' = E_{11}$.

use crate::error::Result;
use crate::field::Field;
use crate::matrix::Matrix;
use crate::system::Descriptor;

/// A descriptor system in the coordinates $x = Vz$, equations multiplied by $U$, with
/// $UEV = \mathrm{diag}(E_{11}, 0)$.
#[derive(Clone, Debug)]
pub(crate) struct CompressedE<K: Field> {
    /// $(UEV, UAV, UB, CV, D)$.
    pub system: Descriptor<K>,
    /// $r = \mathrm{rank}\,E$.
    pub rank: usize,
    /// $x = Vz$.
    pub v: Matrix<K>,
    /// The row operations $U$.
    pub u: Matrix<K>,
}

/// Unit vectors $e_i$, $i \in$ `idx`, as the columns of an $n \times |idx|$ matrix.
fn units<K: Field>(fld: &K, n: usize, idx: &[usize]) -> Matrix<K> {
    Matrix::from_fn(fld.clone(), n, idx.len(), |i, j| {
        if idx[j] == i { fld.one() } else { fld.zero() }
    })
}

/// The compression of the module docs.
///
/// # Errors
/// Only internal shape errors.
pub(crate) fn compress_e<K: Field>(sys: &Descriptor<K>) -> Result<CompressedE<K>> {
    let fld = sys.a.field().clone();
    let n = sys.nstates();
    let (_, col_piv) = sys.e.rref();
    let (_, row_piv) = sys.e.transpose().rref();
    let r = col_piv.len();
    let u = units(&fld, n, &row_piv)
        .transpose()
        .vstack(&sys.e.transpose().nullspace().transpose())?;
    let v = units(&fld, n, &col_piv).hstack(&sys.e.nullspace())?;
    let system = Descriptor {
        e: &(&u * &sys.e) * &v,
        a: &(&u * &sys.a) * &v,
        b: &u * &sys.b,
        c: &sys.c * &v,
        d: sys.d.clone(),
    };
    Ok(CompressedE {
        system,
        rank: r,
        v,
        u,
    })
}

/// The complement of `idx` in `0..n`, ascending.
fn complement(n: usize, idx: &[usize]) -> Vec<usize> {
    (0..n).filter(|i| !idx.contains(i)).collect()
}

/// Eliminates the states `cols` with the equations `rows` ($X = A_{rows, cols}$ invertible,
/// rows and columns of $E$ there zero): the formulas of the module docs. Also returns
/// $-X^{-1}A_{IS}$ and $-X^{-1}B_I$: the eliminated states are
/// $z_J = -X^{-1}A_{IS}z_S - X^{-1}B_Iu$.
///
/// # Errors
/// `Singular` when $X$ is not invertible.
pub(crate) fn eliminate<K: Field>(
    sys: &Descriptor<K>,
    rows: &[usize],
    cols: &[usize],
) -> Result<(Descriptor<K>, Matrix<K>, Matrix<K>)> {
    let n = sys.nstates();
    let (rr, ss) = (complement(n, rows), complement(n, cols));
    let a_r = sys.a.select_rows(&rr);
    let a_i = sys.a.select_rows(rows);
    let xi = a_i.select_cols(cols).inverse()?;
    let a_rj = a_r.select_cols(cols);
    let c_j = sys.c.select_cols(cols);
    let xa = &xi * &a_i.select_cols(&ss);
    let xb = &xi * &sys.b.select_rows(rows);
    let out = Descriptor {
        e: sys.e.select_rows(&rr).select_cols(&ss),
        a: &a_r.select_cols(&ss) - &(&a_rj * &xa),
        b: &sys.b.select_rows(&rr) - &(&a_rj * &xb),
        c: &sys.c.select_cols(&ss) - &(&c_j * &xa),
        d: &sys.d - &(&c_j * &xb),
    };
    Ok((out, -&xa, -&xb))
}

/// The elimination of the module docs on a compressed system: the rows and states of a
/// maximal invertible block of $\hat A_{22}$ (indices into the whole state vector).
pub(crate) fn algebraic_block<K: Field>(c: &CompressedE<K>) -> (Vec<usize>, Vec<usize>) {
    let n = c.system.nstates();
    let a22 = c.system.a.submatrix(c.rank, n, c.rank, n);
    let (_, cols) = a22.rref();
    let (_, rows) = a22.transpose().rref();
    let shift = |v: Vec<usize>| v.into_iter().map(|i| i + c.rank).collect();
    (shift(rows), shift(cols))
}

/// An input-output equivalent descriptor system without non-dynamic modes (module docs),
/// with $E = \mathrm{diag}(E_{11}, 0)$; the number of states removed.
///
/// # Errors
/// Only internal errors.
pub(crate) fn remove_nondynamic<K: Field>(sys: &Descriptor<K>) -> Result<(Descriptor<K>, usize)> {
    let c = compress_e(sys)?;
    let (rows, cols) = algebraic_block(&c);
    if rows.is_empty() {
        return Ok((sys.clone(), 0));
    }
    let (out, _, _) = eliminate(&c.system, &rows, &cols)?;
    Ok((out, rows.len()))
}
