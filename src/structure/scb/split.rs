//! The states $x_s$ (sec. III-B): complement of $x_b, x_d$ whose derivative depends only on
//! $x_s$, $y_b$, $y_d$ and $u_c$; then the split of $x_s$ into $x_a$ and $x_c$ through the
//! controllability matrix (Kalman controllable form).
//!
//! Start from unit rows $T_s^0$ completing $T_{bd} = [T_b; T_d]$ (leading-one deletion rule)
//! and write $\tilde A = T_0 \hat A T_0^{-1}$ in the basis $T_0 = [T_s^0; T_b; T_d]$. The
//! sought rows are $T_s = T_s^0 + K T_{bd}$: $K$'s columns at the chain bottoms are
//! $-B_d^0$ (this removes $u_d$: $x_s^1 = x_s^0 - B_d^0 x_{d0}$), the derivative matrix is
//! then fixed, $X = \tilde A_{ss} + K_{\text{bot}} \tilde A_{\text{bot},s}$, and the other
//! columns follow upwards along each chain from
//! $K_{e_{l-1}} = X K_{e_l} - (\tilde A_{s,e_l} + K_{\text{bot}} \tilde A_{\text{bot},e_l})$
//! (columns of $x_b$ chain tops are zero): the elimination the paper cites from [1], done
//! as one triangular recursion.

use super::silverman::{Chains, align_b, leading_one_complement, silverman, unit_rows, vstack_all};
use super::steps::Rec;
use crate::error::{Error, Result};
use crate::field::Field;
use crate::matrix::Matrix;

/// The strictly proper SCB: transformations and structure.
#[derive(Clone, Debug)]
pub(crate) struct StrictScb<K: Field> {
    /// $\Gamma_1^{-1}$: rows $[T_a; T_b; T_c; T_d]$.
    pub t: Matrix<K>,
    /// $\Gamma_2^{-1}$: rows give $y = (y_d, y_b)$.
    pub g2inv: Matrix<K>,
    /// $\Gamma_3$: $\hat u = \Gamma_3 (u_d, u_c)$.
    pub g3: Matrix<K>,
    /// $(n_a, n_b, n_c, n_d)$.
    pub dims: [usize; 4],
    /// Lengths $q_i$ of the $x_d$ chains.
    pub chains: Vec<usize>,
}

/// Input transformation: $\Gamma_3 = [\bar D; W]^{-1}$ with $W$ unit rows completing $\bar D$,
/// so that $\bar D \Gamma_3 = [I, 0]$.
fn input_transform<K: Field>(dbar: &Matrix<K>) -> Result<Matrix<K>> {
    let k = dbar.field().clone();
    let m = dbar.ncols();
    let w = unit_rows(&k, m, &leading_one_complement(dbar));
    dbar.vstack(&w)?.inverse()
}

/// Strictly proper SCB of $(\hat A, \hat B, \hat C)$ ($\hat B$ full column rank, $\hat C$ full
/// row rank).
pub(crate) fn strictly_proper<K: Field>(
    a: &Matrix<K>,
    b: &Matrix<K>,
    c: &Matrix<K>,
    mut rec: Rec<'_, '_, K>,
) -> Result<StrictScb<K>> {
    let k = a.field().clone();
    let n = a.nrows();
    let Chains { d, b: braw, dbar } = silverman(a, b, c, rec.as_deref_mut());
    let md = d.len();
    let tb_raw = vstack_all(&k, n, &braw.iter().collect::<Vec<_>>());
    let tb = align_b(a, &tb_raw, &d)?;
    let td = vstack_all(&k, n, &d.iter().collect::<Vec<_>>());
    let (nb, nd) = (tb.nrows(), td.nrows());
    let g3 = input_transform(&dbar)?;
    // ---- x_s ----
    let tbd = tb.vstack(&td)?;
    let ts0 = unit_rows(&k, n, &leading_one_complement(&tbd));
    let ns = ts0.nrows();
    let t0 = ts0.vstack(&tbd)?;
    let at = &(&t0 * a) * &t0.inverse()?;
    let bt = &(&t0 * b) * &g3;
    // positions (in T0 coordinates) of chain levels
    let mut bottoms = Vec::with_capacity(md);
    let mut d_levels: Vec<Vec<usize>> = Vec::new();
    let mut off = ns + nb;
    for ch in &d {
        d_levels.push((off..off + ch.nrows()).collect());
        bottoms.push(off + ch.nrows() - 1);
        off += ch.nrows();
    }
    let mut b_levels: Vec<Vec<usize>> = Vec::new();
    let mut off = ns;
    for ch in &braw {
        b_levels.push((off..off + ch.nrows()).collect());
        off += ch.nrows();
    }
    let mut kk = Matrix::zeros(k.clone(), ns, n); // columns indexed by T0 coordinates
    for (e, &bot) in bottoms.iter().enumerate() {
        for r in 0..ns {
            kk.set(r, bot, k.neg(bt.get(r, e)));
        }
    }
    // rhs_j = A~_{s,j} + sum_bot K_bot A~_{bot,j}; X = rhs restricted to the s columns
    let mut rhs = at.submatrix(0, ns, 0, n);
    for &bot in &bottoms {
        let kb = Matrix::column(k.clone(), kk.col(bot));
        let contrib = &kb * &at.select_rows(&[bot]);
        rhs = &rhs + &contrib;
    }
    let x = rhs.submatrix(0, ns, 0, ns);
    for levels in d_levels.iter().chain(b_levels.iter()) {
        for l in (1..levels.len()).rev() {
            let (lo, hi) = (levels[l - 1], levels[l]);
            let kh = Matrix::column(k.clone(), kk.col(hi));
            let v = &(&x * &kh) - &Matrix::column(k.clone(), rhs.col(hi));
            for r in 0..ns {
                kk.set(r, lo, v.get(r, 0).clone());
            }
        }
    }
    let ks = kk.submatrix(0, ns, ns, n);
    let ts = &ts0 + &(&ks * &tbd);
    // ---- x_a, x_c: Kalman controllable form of (X, B_sc) ----
    let bsc = (&(&ts * b) * &g3).submatrix(0, ns, md, b.ncols());
    if let Some(r) = rec.as_deref_mut() {
        super::steps::states(r, [a, b, c], [&ts0, &ts], &x, &g3, md);
    }
    let (p, na) = controllable_split(&x, &bsc, rec)?;
    let ac = &p.inverse()? * &ts;
    let t = vstack_all(
        &k,
        n,
        &[
            &ac.submatrix(0, na, 0, n),
            &tb,
            &ac.submatrix(na, ns, 0, n),
            &td,
        ],
    );
    // ---- outputs: y = (y_d, y_b) ----
    let mut firsts: Vec<Matrix<K>> = d.iter().map(|ch| ch.select_rows(&[0])).collect();
    let mut off = 0;
    for ch in &braw {
        firsts.push(tb.select_rows(&[off]));
        off += ch.nrows();
    }
    let ys = vstack_all(&k, n, &firsts.iter().collect::<Vec<_>>());
    let (g2t, _) = c
        .transpose()
        .solve(&ys.transpose())?
        .ok_or_else(|| Error::Verification("scb: an output row left the output space".into()))?;
    Ok(StrictScb {
        t,
        g2inv: g2t.transpose(),
        g3,
        dims: [na, nb, ns - na, nd],
        chains: d.iter().map(|ch| ch.nrows()).collect(),
    })
}

/// $P = [T_2, T_1]$ with the columns of $T_1$ the canonical basis of the column space of
/// $[B, XB, \dots, X^{n-1}B]$ (transposed RREF) and $T_2$ the left null space of that matrix
/// (transposed), or unit columns when the two are not complementary (possible over non-real
/// fields); returns $(P, n_a)$ with $n_a$ = number of columns of $T_2$.
pub(crate) fn controllable_split<K: Field>(
    x: &Matrix<K>,
    bsc: &Matrix<K>,
    rec: Rec<'_, '_, K>,
) -> Result<(Matrix<K>, usize)> {
    let ns = x.nrows();
    let mut ctr = bsc.clone();
    let mut blk = bsc.clone();
    for _ in 1..ns.max(1) {
        blk = x * &blk;
        ctr = ctr.hstack(&blk)?;
    }
    let t1 = ctr.transpose().row_space().transpose();
    let mut t2 = ctr.left_nullspace().transpose();
    let mut p = t2.hstack(&t1)?;
    if p.rank() < ns {
        t2 = t1.complete_basis();
        p = t2.hstack(&t1)?;
    }
    if let Some(r) = rec {
        super::steps::kalman_split(r, x, bsc, &ctr, &p, t2.ncols());
    }
    Ok((p, t2.ncols()))
}
