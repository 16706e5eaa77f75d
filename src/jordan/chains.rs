//! Jordan chains (generalized eigenvectors) of one eigenvalue, over any field `K`.
//!
//! Input: $N = A - \theta I$ over $K \ni \theta$ and the algebraic multiplicity $m$ of
//! $\theta$. Output: block sizes $k_1 \ge k_2 \ge \dots$ ($\sum k_i = m$), right chains
//! $V$ ($n \times m$) with $A V = V J_\theta$ and left chains $W$ ($m \times n$) with
//! $W A = J_\theta W$ and $W V = I_m$, where $J_\theta$ is the Jordan matrix with those
//! blocks (ones on the superdiagonal: $N v_1 = 0$, $N v_j = v_{j-1}$).
//!
//! # Algorithm
//! One Gauss–Jordan elimination of $[N \mid I]$ gives $R = P N$ in RREF with $P$
//! invertible. With it:
//! * $N x = y$ is solvable iff $(P y)_{r..n} = 0$, and then $x_{\text{piv}(i)} = (P y)_i$;
//!   so $\ker N^k = N^{-1}(\ker N^{k-1})$ is built level by level in $O(n^2 m)$ per level.
//! * $y N = z$ is solvable iff $z = z_{\text{piv}} R_{0..r}$, and then $y = z_{\text{piv}}
//!   P_{0..r}$; the rows $P_{r..n}$ span the left kernel. The left generalized eigenspace
//!   is built the same way.
//! * The right generalized eigenspace basis $B$ (adapted to the flag $\ker N \subset
//!   \ker N^2 \subset \dots$) gives the nilpotent restriction $M$ ($N B = B M$, $m \times
//!   m$); chains are chosen top-down in coordinates, then $V = B C$.
//! * With $L$ any basis of the left generalized eigenspace, $W = (L V)^{-1} L$.
//!
//! Cost: one $n \times 2n$ elimination over $K$ plus $O(n^2 m s)$, $s$ the largest block.
//! Block sizes follow from $\dim \ker N^k$: the number of blocks of size $\ge k$ is
//! $\dim\ker N^k - \dim\ker N^{k-1}$.

use crate::error::{Error, Result};
use crate::field::Field;
use crate::matrix::Matrix;

/// Chains of one eigenvalue (see the module docs).
#[derive(Clone, Debug, PartialEq)]
pub struct Chains<K: Field> {
    /// Jordan block sizes, largest first.
    pub blocks: Vec<usize>,
    /// $\dim \ker N^k$ for $k = 1, 2, \dots, s$.
    pub kernel_dims: Vec<usize>,
    /// Right chains as columns, block by block ($n \times m$).
    pub v: Matrix<K>,
    /// Left chains as rows ($m \times n$), $W V = I$.
    pub w: Matrix<K>,
}

/// The Jordan matrix of one eigenvalue `theta` with the given block sizes.
pub fn jordan_block_matrix<K: Field>(k: &K, theta: &K::Elem, blocks: &[usize]) -> Matrix<K> {
    let m: usize = blocks.iter().sum();
    let mut j = Matrix::zeros(k.clone(), m, m);
    let mut off = 0;
    for &b in blocks {
        for i in 0..b {
            j.set(off + i, off + i, theta.clone());
            if i + 1 < b {
                j.set(off + i, off + i + 1, k.one());
            }
        }
        off += b;
    }
    j
}

/// `a * b` (over $\mathbb{Q}$ the product dispatches to the integer kernel of
/// `qkernels::intmul` through `Matrix::try_mul`).
pub(crate) fn mul<K: Field>(a: &Matrix<K>, b: &Matrix<K>) -> Matrix<K> {
    a * b
}

/// Elimination data of $[N \mid I]$: $R = P N$.
struct Elim<K: Field> {
    r: Matrix<K>,
    p: Matrix<K>,
    piv: Vec<usize>,
}

impl<K: Field + 'static> Elim<K> {
    fn new(nm: &Matrix<K>) -> Self {
        let n = nm.nrows();
        let k = nm.field().clone();
        let aug = nm.hstack(&Matrix::identity(k, n)).expect("same rows");
        let (ra, piv_all) = aug.rref();
        let piv: Vec<usize> = piv_all.into_iter().filter(|&c| c < n).collect();
        Elim {
            r: ra.submatrix(0, n, 0, n),
            p: ra.submatrix(0, n, n, 2 * n),
            piv,
        }
    }
    fn rank(&self) -> usize {
        self.piv.len()
    }
}

/// Canonical null-space basis (columns) read off an RREF `r` with pivot columns `piv`.
pub(crate) fn nullspace_of_rref<K: Field>(r: &Matrix<K>, piv: &[usize]) -> Matrix<K> {
    crate::matrix::nullspace_from_rref(r, piv)
}

/// Columns of `extra` that are independent modulo the (independent) columns of `base`.
fn independent_extra<K: Field + 'static>(base: &Matrix<K>, extra: &Matrix<K>) -> Matrix<K> {
    let both = base.hstack(extra).expect("same rows");
    let (_, piv) = both.rref();
    let keep: Vec<usize> = piv
        .into_iter()
        .filter(|&c| c >= base.ncols())
        .map(|c| c - base.ncols())
        .collect();
    extra.select_cols(&keep)
}

/// Right generalized eigenspace basis adapted to the kernel flag, and the flag dimensions.
fn right_flag<K: Field + 'static>(e: &Elim<K>, m: usize) -> Result<(Matrix<K>, Vec<usize>)> {
    let n = e.p.nrows();
    let r = e.rank();
    let k = e.p.field().clone();
    let mut basis = nullspace_of_rref(&e.r, &e.piv);
    let mut dims = vec![basis.ncols()];
    let p_bot = e.p.submatrix(r, n, 0, n);
    while basis.ncols() < m {
        // preimages of the whole current space (a combination of levels may lie in the
        // range of N when no single level does)
        let cur = &basis;
        let cs = mul(&p_bot, cur).nullspace();
        let ys = mul(cur, &cs);
        let pys = mul(&e.p.submatrix(0, r, 0, n), &ys);
        let mut xs = Matrix::zeros(k.clone(), n, ys.ncols());
        for (i, &pc) in e.piv.iter().enumerate() {
            for j in 0..ys.ncols() {
                xs.set(pc, j, pys.get(i, j).clone());
            }
        }
        let new = independent_extra(&basis, &xs);
        if new.ncols() == 0 {
            return Err(Error::Verification(format!(
                "generalized eigenspace has dimension {} but the multiplicity is {m}",
                basis.ncols()
            )));
        }
        basis = basis.hstack(&new)?;
        dims.push(basis.ncols());
    }
    if basis.ncols() != m {
        return Err(Error::Verification(format!(
            "generalized eigenspace has dimension {} but the multiplicity is {m}",
            basis.ncols()
        )));
    }
    Ok((basis, dims))
}

/// Rows spanning the left generalized eigenspace ($m \times n$).
fn left_space<K: Field + 'static>(e: &Elim<K>, m: usize) -> Result<Matrix<K>> {
    let n = e.p.nrows();
    let r = e.rank();
    let mut basis = e.p.submatrix(r, n, 0, n); // left kernel rows
    let r_top = e.r.submatrix(0, r, 0, n);
    let p_top = e.p.submatrix(0, r, 0, n);
    while basis.nrows() < m {
        let cur = basis.clone();
        let cur_piv = cur.select_cols(&e.piv);
        // z = c cur solvable iff z = z_piv R_top: c (cur - cur_piv R_top) = 0
        let d = cur.try_sub(&mul(&cur_piv, &r_top))?;
        let cs = d.transpose().nullspace().transpose(); // rows c
        let zp = mul(&cs, &cur_piv);
        let ys = mul(&zp, &p_top);
        let new = independent_extra(&basis.transpose(), &ys.transpose()).transpose();
        if new.nrows() == 0 {
            return Err(Error::Verification(format!(
                "left generalized eigenspace has dimension {} but the multiplicity is {m}",
                basis.nrows()
            )));
        }
        basis = basis.vstack(&new)?;
    }
    if basis.nrows() != m {
        return Err(Error::Verification(format!(
            "left generalized eigenspace has dimension {} but the multiplicity is {m}",
            basis.nrows()
        )));
    }
    Ok(basis)
}

/// Chooses chains top-down for the nilpotent `mm` ($m \times m$) whose kernel flag is the
/// coordinate flag with dimensions `dims`; returns block sizes and the chain matrix `C`.
fn chains_in_coordinates<K: Field + 'static>(
    mm: &Matrix<K>,
    dims: &[usize],
) -> (Vec<usize>, Matrix<K>) {
    let k = mm.field().clone();
    let m = mm.nrows();
    let s = dims.len();
    // tops: (length, vector)
    let mut tops: Vec<(usize, Matrix<K>)> = vec![];
    for level in (1..=s).rev() {
        let lo = if level >= 2 { dims[level - 2] } else { 0 };
        let hi = dims[level - 1];
        // vectors already at this level: M^(len-level) top for longer chains
        let mut have: Vec<Matrix<K>> = vec![];
        for (len, top) in &tops {
            let mut v = top.clone();
            for _ in 0..(len - level) {
                v = mm * &v;
            }
            have.push(v.submatrix(lo, hi, 0, 1));
        }
        let width = hi - lo;
        let mut s_mat = Matrix::zeros(k.clone(), width, have.len() + width);
        for (j, h) in have.iter().enumerate() {
            for i in 0..width {
                s_mat.set(i, j, h.get(i, 0).clone());
            }
        }
        for i in 0..width {
            s_mat.set(i, have.len() + i, k.one());
        }
        let (_, piv) = s_mat.rref();
        for c in piv.into_iter().filter(|&c| c >= have.len()) {
            let mut e = Matrix::zeros(k.clone(), m, 1);
            e.set(lo + c - have.len(), 0, k.one());
            tops.push((level, e));
        }
    }
    let blocks: Vec<usize> = tops.iter().map(|(l, _)| *l).collect();
    let mut c = Matrix::zeros(k.clone(), m, m);
    let mut col = 0;
    for (len, top) in &tops {
        // v_len = top, v_{j-1} = M v_j
        let mut v = top.clone();
        for j in (0..*len).rev() {
            for i in 0..m {
                c.set(i, col + j, v.get(i, 0).clone());
            }
            v = mm * &v;
        }
        col += len;
    }
    (blocks, c)
}

/// Jordan chains of the eigenvalue $\theta$ where `nm` $= A - \theta I$ and `m` is the
/// algebraic multiplicity.
///
/// # Errors
/// `NotSquare`; `Verification` when the generalized eigenspace does not have dimension `m`
/// (a wrong multiplicity).
pub fn jordan_chains<K: Field + 'static>(nm: &Matrix<K>, m: usize) -> Result<Chains<K>> {
    nm.check_square("jordan_chains")?;
    let e = Elim::new(nm);
    let (b, dims) = right_flag(&e, m)?;
    // restriction M: N B = B M, through m independent rows of B
    let (_, rows) = b.transpose().rref();
    let b_sub = b.select_rows(&rows);
    let nb = mul(nm, &b);
    let mm = mul(&b_sub.inverse()?, &nb.select_rows(&rows));
    let (blocks, c) = chains_in_coordinates(&mm, &dims);
    let v = mul(&b, &c);
    let l = left_space(&e, m)?;
    let lv = mul(&l, &v);
    let w = mul(&lv.inverse()?, &l);
    Ok(Chains {
        blocks,
        kernel_dims: dims,
        v,
        w,
    })
}

/// Whether the columns of `v` form a chain of `nm`: $N v_1 = 0$, $v_1 \ne 0$, $N v_j =
/// v_{j-1}$.
pub fn is_chain<K: Field>(nm: &Matrix<K>, v: &Matrix<K>) -> bool {
    if v.ncols() == 0 || v.col(0).iter().all(|x| v.field().is_zero(x)) {
        return false;
    }
    let nv = nm * v;
    let n = v.nrows();
    (0..v.ncols()).all(|j| {
        if j == 0 {
            nv.submatrix(0, n, 0, 1).is_zero()
        } else {
            nv.submatrix(0, n, j, j + 1) == v.submatrix(0, n, j - 1, j)
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::{Q, Rational};
    use crate::qmat;

    fn check(a: &Matrix<Q>, theta: i64, m: usize, want: &[usize]) {
        let t = Rational::from_integer(theta.into());
        let n = a.nrows();
        let nm = a.try_sub(&Matrix::identity(Q, n).scale(&t)).unwrap();
        let ch = jordan_chains(&nm, m).unwrap();
        assert_eq!(ch.blocks, want);
        let j = jordan_block_matrix(&Q, &t, &ch.blocks);
        assert_eq!(a * &ch.v, &ch.v * &j);
        assert_eq!(&ch.w * a, &j * &ch.w);
        assert!((&ch.w * &ch.v).is_identity());
    }

    #[test]
    fn small_structures() {
        // single-wheel yaw plane with m = 1, u = 1, cr = 1: three zeros in one block
        let a = qmat![[0, 1, -1, 0], [0, 0, 0, -1], [0, 0, -1, -1], [0, 0, 0, 0]];
        check(&a, 0, 3, &[3]);
        check(&a, -1, 1, &[1]);
        let a2 = qmat![[0, 0, 1, 0], [0, 0, 0, 1], [-1, 0, -2, 0], [0, 0, 0, 0]];
        check(&a2, 0, 2, &[2]);
        check(&a2, -1, 2, &[2]);
        let a1 = qmat![[0, 0, 1, 0], [0, 0, 0, 1], [0, 0, -1, 0], [0, 0, 0, -1]];
        check(&a1, 0, 2, &[1, 1]);
        check(&a1, -1, 2, &[1, 1]);
        // nilpotent with blocks 3, 2, 1 shuffled by a similarity
        let j = jordan_block_matrix(&Q, &Rational::from_integer(0.into()), &[3, 2, 1]);
        let p = qmat![
            [1, 2, 0, 0, 1, 0],
            [0, 1, 0, 1, 0, 0],
            [1, 0, 1, 0, 0, 1],
            [0, 0, 1, 1, 0, 0],
            [0, 1, 0, 0, 1, 1],
            [1, 0, 0, 0, 0, 1]
        ];
        let a = &(&p * &j) * &p.inverse().unwrap();
        check(&a, 0, 6, &[3, 2, 1]);
    }

    #[test]
    fn wrong_multiplicity_is_an_error() {
        let a = qmat![[1, 1], [0, 1]];
        let nm = a.try_sub(&Matrix::identity(Q, 2)).unwrap();
        assert!(jordan_chains(&nm, 3).is_err());
    }
}
