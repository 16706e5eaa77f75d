//! The modified Silverman iterations (Grip–Saberi sec. III-A): integrator chains of $x_d$
//! and the raw chains of $x_b$, as rows (linear functionals of $\hat x$).
//!
//! Step $i$ works on the level-$i$ rows $C_i$ of the active chains. With $\bar D_{i-1}$ the
//! input coefficients of the bottoms of the chains that already ended, the canonical (RREF)
//! left null space of $[\bar D_{i-1}; C_i \hat B]$ gives $[S_{ib}, S_{i2}]$; $S_{i1}$ keeps the
//! rows of $I_{p_i}$ whose index is not a leading one of $\mathrm{rref}(S_{i2})$ (the paper's
//! deletion rule). The chains picked by $S_{i1}$ end with length $i$; each row of
//! $[S_{ib}, S_{i2}]$ gives a continuing chain $\sum S_{i2} (\text{chain}) + \sum S_{ib}
//! (\text{ended chain shifted so that the bottoms align})$, whose level-$i$ row has zero input
//! coefficient and whose levels still satisfy $r_l \hat A = r_{l+1} + (\text{combination of } y_d)$.
//! Then $\bar\phi_i$ does the same with the candidate rows $\bar C_i = C_i \hat A$ against all
//! rows found so far: dependent combinations end as $x_b$ chains of length $i$.

use super::steps::Rec;
use crate::error::{Error, Result};
use crate::field::Field;
use crate::matrix::Matrix;

/// The chains found by the iterations.
#[derive(Clone, Debug)]
pub(crate) struct Chains<K: Field> {
    /// $x_d$ chains in the order they ended (non-decreasing length); row $l$ = level $l+1$.
    pub d: Vec<Matrix<K>>,
    /// Raw $x_b$ chains (rows: levels), before [`align_b`].
    pub b: Vec<Matrix<K>>,
    /// Input coefficients of the $x_d$ bottoms, $\bar D$ ($m_d \times m$), row $e$ for chain $e$.
    pub dbar: Matrix<K>,
}

/// Indices of the rows of $I_p$ kept by the leading-one deletion rule for `s2` (rows of
/// `s2` independent, `p = s2.ncols()`): the columns that are not pivots of `rref(s2)`.
pub(crate) fn leading_one_complement<K: Field>(s2: &Matrix<K>) -> Vec<usize> {
    let (_, piv) = s2.rref();
    (0..s2.ncols()).filter(|c| !piv.contains(c)).collect()
}

/// Rows of the identity (`p x p`) selected by `idx`.
pub(crate) fn unit_rows<K: Field>(k: &K, p: usize, idx: &[usize]) -> Matrix<K> {
    Matrix::identity(k.clone(), p).select_rows(idx)
}

/// Stacks matrices vertically (all with `ncols` columns).
pub(crate) fn vstack_all<K: Field>(k: &K, ncols: usize, ms: &[&Matrix<K>]) -> Matrix<K> {
    let mut out = Matrix::zeros(k.clone(), 0, ncols);
    for m in ms {
        out = out.vstack(m).expect("same column count");
    }
    out
}

/// Row `level` of every chain, stacked.
fn level_rows<K: Field>(k: &K, n: usize, chains: &[Matrix<K>], level: usize) -> Matrix<K> {
    let rows: Vec<Matrix<K>> = chains.iter().map(|ch| ch.select_rows(&[level])).collect();
    vstack_all(k, n, &rows.iter().collect::<Vec<_>>())
}

/// `acc += c * m` entry-wise.
fn add_scaled<K: Field>(acc: &mut Matrix<K>, c: &K::Elem, m: &Matrix<K>, row_offset: usize) {
    let k = acc.field().clone();
    if k.is_zero(c) {
        return;
    }
    for i in 0..m.nrows() {
        for j in 0..m.ncols() {
            let v = m.get(i, j);
            if !k.is_zero(v) {
                k.mul_add_assign(acc.get_mut(i + row_offset, j), c, v);
            }
        }
    }
}

/// Runs the iterations on a strictly proper $(\hat A, \hat B, \hat C)$ with $\hat B$ of full
/// column rank and $\hat C$ of full row rank.
/// With a recorder, each $\bar S_i$ and $\bar\phi_i$ is recorded as a step.
pub(crate) fn silverman<K: Field>(
    a: &Matrix<K>,
    b: &Matrix<K>,
    c: &Matrix<K>,
    mut rec: Rec<'_, '_, K>,
) -> Chains<K> {
    let k = a.field().clone();
    let (n, m) = (a.nrows(), b.ncols());
    let mut active: Vec<Matrix<K>> = (0..c.nrows()).map(|i| c.select_rows(&[i])).collect();
    let mut ended: Vec<Matrix<K>> = Vec::new();
    let mut dbar = Matrix::zeros(k.clone(), 0, m);
    let mut bch: Vec<Matrix<K>> = Vec::new();
    while !active.is_empty() {
        let i = active[0].nrows();
        // ---- S-bar_i: split the level-i rows by their input coefficients ----
        let ci = level_rows(&k, n, &active, i - 1);
        let cib = &ci * b;
        let qbar = dbar.nrows();
        let stacked = dbar.vstack(&cib).expect("same cols");
        let nl = stacked.left_nullspace();
        let s_ib = nl.submatrix(0, nl.nrows(), 0, qbar);
        let s_i2 = nl.submatrix(0, nl.nrows(), qbar, qbar + active.len());
        let ending = leading_one_complement(&s_i2);
        if let Some(r) = rec.as_deref_mut() {
            super::steps::silverman_s(r, (i, &ended), &ci, &stacked, &nl, &ending);
        }
        let mut continuing = Vec::with_capacity(nl.nrows());
        for r in 0..nl.nrows() {
            let mut ch = Matrix::zeros(k.clone(), i, n);
            for (cidx, chain) in active.iter().enumerate() {
                add_scaled(&mut ch, s_i2.get(r, cidx), chain, 0);
            }
            for (e, chain) in ended.iter().enumerate() {
                // ended chain of length j < i, bottoms aligned: level l gets e_{l-(i-j)}
                let j = chain.nrows();
                add_scaled(&mut ch, s_ib.get(r, e), chain, i - j);
            }
            continuing.push(ch);
        }
        for &cidx in &ending {
            let chain = active[cidx].clone();
            let bottom = &chain.select_rows(&[i - 1]) * b;
            dbar = dbar.vstack(&bottom).expect("same cols");
            ended.push(chain);
        }
        if continuing.is_empty() {
            break;
        }
        // ---- phi-bar_i: candidates C-bar = C_i A against every row found so far ----
        let mut found: Vec<&Matrix<K>> = ended.iter().collect();
        found.extend(bch.iter());
        found.extend(continuing.iter());
        let existing = vstack_all(&k, n, &found);
        let tops = level_rows(&k, n, &continuing, i - 1);
        let cbar = &tops * a;
        let ne = existing.nrows();
        let nl = existing.vstack(&cbar).expect("same cols").left_nullspace();
        let phi_2 = nl.submatrix(0, nl.nrows(), ne, ne + continuing.len());
        let going_on = leading_one_complement(&phi_2);
        if let Some(r) = rec.as_deref_mut() {
            super::steps::silverman_phi(r, i, &existing, &cbar, &nl, &going_on);
        }
        for r in 0..nl.nrows() {
            let mut ch = Matrix::zeros(k.clone(), i, n);
            for (cidx, chain) in continuing.iter().enumerate() {
                add_scaled(&mut ch, phi_2.get(r, cidx), chain, 0);
            }
            bch.push(ch);
        }
        active = going_on
            .iter()
            .map(|&cidx| {
                continuing[cidx]
                    .vstack(&cbar.select_rows(&[cidx]))
                    .expect("same cols")
            })
            .collect();
    }
    Chains {
        d: ended,
        b: bch,
        dbar,
    }
}

/// Removes from the $x_b$ rows their dependence on the non-output rows of $x_d$: returns
/// $T_b' = T_b + K T_d$ with $T_b' \hat A \in \operatorname{rowspan}(T_b') + Y_d$ ($Y_d$ the
/// chains' first rows). Column $e_{l-1}$ of $K$ is $F_{bb} K_{e_l} - F_{bd,e_l}$, from each
/// chain's bottom upwards ($K_{\text{bottom}} = 0$), where $T_b \hat A = F_{bb} T_b + F_{bd} T_d$.
pub(crate) fn align_b<K: Field>(
    a: &Matrix<K>,
    tb: &Matrix<K>,
    d: &[Matrix<K>],
) -> Result<Matrix<K>> {
    let k = a.field().clone();
    let n = a.nrows();
    let nb = tb.nrows();
    if nb == 0 || d.is_empty() {
        return Ok(tb.clone());
    }
    let td = vstack_all(&k, n, &d.iter().collect::<Vec<_>>());
    let nd = td.nrows();
    let r = tb.vstack(&td).expect("same cols");
    let rhs = (tb * a).transpose();
    let (ft, _) = r.transpose().solve(&rhs)?.ok_or_else(|| {
        Error::Verification("scb: an x_b derivative left the span of the rows found".into())
    })?;
    let f = ft.transpose(); // nb x (nb + nd)
    let fbb = f.submatrix(0, nb, 0, nb);
    let mut kk = Matrix::zeros(k.clone(), nb, nd);
    let mut off = 0;
    for ch in d {
        let q = ch.nrows();
        for l in (1..q).rev() {
            // column (off + l - 1) from column (off + l)
            let col = Matrix::column(k.clone(), kk.col(off + l));
            let prod = &fbb * &col;
            for row in 0..nb {
                let v = k.sub(prod.get(row, 0), f.get(row, nb + off + l));
                kk.set(row, off + l - 1, v);
            }
        }
        off += q;
    }
    Ok(tb + &(&kk * &td))
}
