//! Exact verification of an SCB: the identities of sec. II-C and the zero/identity pattern of
//! eq. (4)–(6), observability of $(A_{bb}, C_b)$, controllability of $(A_{cc}, B_c)$.

use super::Scb;
use crate::error::{Error, Result};
use crate::field::Field;
use crate::matrix::Matrix;

/// The block structure an SCB must have.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Pattern {
    /// $(n_a, n_b, n_c, n_d)$.
    pub dims: [usize; 4],
    /// Integrator chain lengths $q_i$ (their sum is $n_d$).
    pub chains: Vec<usize>,
    /// Size of the feedthrough block $I_{m_0}$.
    pub m0: usize,
}

fn fail(msg: impl Into<String>) -> Error {
    Error::Verification(msg.into())
}

fn zero_block<K: Field>(m: &Matrix<K>, rows: &std::ops::Range<usize>, cols: &[usize]) -> bool {
    rows.clone()
        .all(|i| cols.iter().all(|&j| m.field().is_zero(m.get(i, j))))
}

fn range_vec(r: &std::ops::Range<usize>) -> Vec<usize> {
    r.clone().collect()
}

/// Rows of `x` lie in the row space of `c`.
fn in_row_space<K: Field>(x: &Matrix<K>, c: &Matrix<K>) -> bool {
    if x.nrows() == 0 || x.is_zero() {
        return true;
    }
    c.vstack(x).map(|s| s.rank() == c.rank()).unwrap_or(false)
}

/// Is $(A, C)$ observable? (rank of the observability matrix.)
pub(crate) fn observable<K: Field>(a: &Matrix<K>, c: &Matrix<K>) -> bool {
    let n = a.nrows();
    let mut o = c.clone();
    let mut blk = c.clone();
    for _ in 1..n.max(1) {
        blk = &blk * a;
        o = o.vstack(&blk).expect("same cols");
    }
    o.rank() == n
}

/// Checks that $(A, B, C, D)$ has the compact SCB form of eq. (6) for `pat`.
///
/// # Errors
/// `Verification` naming the first violated condition.
pub fn check_pattern<K: Field>(
    a: &Matrix<K>,
    b: &Matrix<K>,
    c: &Matrix<K>,
    d: &Matrix<K>,
    pat: &Pattern,
) -> Result<()> {
    let [na, nb, nc, nd] = pat.dims;
    let n = na + nb + nc + nd;
    let md = pat.chains.len();
    let m0 = pat.m0;
    if a.shape() != (n, n) || b.nrows() != n || c.ncols() != n {
        return Err(fail("dims do not add up to the number of states"));
    }
    if pat.chains.iter().sum::<usize>() != nd || pat.chains.contains(&0) {
        return Err(fail("chain lengths do not add up to dim x_d"));
    }
    let (m, p) = (b.ncols(), c.nrows());
    if m < m0 + md || p < m0 + md || d.shape() != (p, m) {
        return Err(fail("input/output dimensions do not fit the pattern"));
    }
    let ra = 0..na;
    let rb = na..na + nb;
    let rc = na + nb..na + nb + nc;
    let rd = na + nb + nc..n;
    let (u0, ud, uc) = (0..m0, m0..m0 + md, m0 + md..m);
    let (y0, yd, yb) = (0..m0, m0..m0 + md, m0 + md..p);
    // chain bookkeeping: first and bottom state of each chain
    let mut firsts = Vec::with_capacity(md);
    let mut bottoms = Vec::with_capacity(md);
    let mut off = rd.start;
    for &q in &pat.chains {
        firsts.push(off);
        bottoms.push(off + q - 1);
        off += q;
    }
    let non_first_d: Vec<usize> = rd.clone().filter(|j| !firsts.contains(j)).collect();
    let k = a.field();
    // D = diag(I, 0)
    let mut dd = Matrix::zeros(k.clone(), p, m);
    for i in 0..m0 {
        dd.set(i, i, k.one());
    }
    if *d != dd {
        return Err(fail("D is not diag(I_m0, 0)"));
    }
    // B
    let not_u0: Vec<usize> = ud.clone().chain(uc.clone()).collect();
    if !zero_block(b, &ra, &not_u0) || !zero_block(b, &rb, &not_u0) {
        return Err(fail("x_a or x_b is driven by u_d or u_c"));
    }
    if !zero_block(b, &rc, &range_vec(&ud)) || !zero_block(b, &rd, &range_vec(&uc)) {
        return Err(fail("x_c driven by u_d or x_d driven by u_c"));
    }
    for (i, &bot) in bottoms.iter().enumerate() {
        for r in rd.clone() {
            let want = if r == bot { k.one() } else { k.zero() };
            if *b.get(r, ud.start + i) != want {
                return Err(fail(format!(
                    "B_d is not the chain input pattern at chain {}",
                    i + 1
                )));
            }
        }
    }
    let _ = u0;
    // C
    let not_d: Vec<usize> = (0..rd.start).collect();
    if !zero_block(c, &yd, &not_d) {
        return Err(fail("y_d depends on states outside x_d"));
    }
    for (i, &f) in firsts.iter().enumerate() {
        for j in rd.clone() {
            let want = if j == f { k.one() } else { k.zero() };
            if *c.get(yd.start + i, j) != want {
                return Err(fail(format!(
                    "C_d is not the chain output pattern at chain {}",
                    i + 1
                )));
            }
        }
    }
    let not_b: Vec<usize> = (0..n).filter(|j| !rb.contains(j)).collect();
    if !zero_block(c, &yb, &not_b) {
        return Err(fail("y_b depends on states outside x_b"));
    }
    let _ = y0;
    let cb = c.submatrix(yb.start, yb.end, rb.start, rb.end);
    // A
    let ac_cols = range_vec(&rc);
    if !zero_block(a, &ra, &ac_cols) || !zero_block(a, &rb, &ac_cols) {
        return Err(fail("x_a or x_b depends on x_c"));
    }
    if !zero_block(a, &rb, &range_vec(&ra)) {
        return Err(fail("x_b depends on x_a"));
    }
    for rows in [&ra, &rb, &rc] {
        if !zero_block(a, rows, &non_first_d) {
            return Err(fail(
                "x_a, x_b or x_c depends on x_d other than through y_d",
            ));
        }
    }
    for rows in [&ra, &rc] {
        let blk = a.submatrix(rows.start, rows.end, rb.start, rb.end);
        if !in_row_space(&blk, &cb) {
            return Err(fail("x_a or x_c depends on x_b other than through y_b"));
        }
    }
    for (i, &q) in pat.chains.iter().enumerate() {
        for lvl in 0..q.saturating_sub(1) {
            let r = firsts[i] + lvl;
            for j in 0..n {
                let v = a.get(r, j);
                if j == r + 1 {
                    if !k.is_one(v) {
                        return Err(fail(format!(
                            "chain {} lacks its integrator at level {}",
                            i + 1,
                            lvl + 1
                        )));
                    }
                } else if !firsts.contains(&j) && !k.is_zero(v) {
                    return Err(fail(format!(
                        "chain {} level {} has a term outside y_d",
                        i + 1,
                        lvl + 1
                    )));
                }
            }
        }
    }
    let abb = a.submatrix(rb.start, rb.end, rb.start, rb.end);
    if !observable(&abb, &cb) {
        return Err(fail("(A_bb, C_b) is not observable"));
    }
    let acc = a.submatrix(rc.start, rc.end, rc.start, rc.end);
    let bc = b.submatrix(rc.start, rc.end, uc.start, uc.end);
    if !observable(&acc.transpose(), &bc.transpose()) {
        return Err(fail("(A_cc, B_c) is not controllable"));
    }
    Ok(())
}

/// All identities of an [`Scb`] against its original system.
pub(crate) fn check<K: Field>(s: &Scb<K>) -> Result<()> {
    let [a0, b0, c0, d0] = &s.orig;
    let k = a0.field().clone();
    let n = a0.nrows();
    let m0 = s.m0;
    for (name, g) in [
        ("Gamma1", &s.gamma1),
        ("Gamma2", &s.gamma2),
        ("Gamma3", &s.gamma3),
        ("U", &s.u_pre),
        ("Y", &s.y_pre),
    ] {
        if !g.is_square() || g.rank() != g.nrows() {
            return Err(fail(format!("{name} is not invertible")));
        }
    }
    let yinv = s.y_pre.inverse()?;
    let bh = b0 * &s.u_pre;
    let ch = &yinv * c0;
    let dh = &(&yinv * d0) * &s.u_pre;
    let ah = a0 - &(&bh.submatrix(0, n, 0, m0) * &ch.submatrix(0, m0, 0, n));
    if &s.gamma1 * &s.a != &ah * &s.gamma1 {
        return Err(fail("A != Gamma1^-1 (A-hat - B0 C0) Gamma1"));
    }
    if &s.gamma1 * &s.b != &bh * &s.gamma3 {
        return Err(fail("B != Gamma1^-1 B-hat Gamma3"));
    }
    if &s.gamma2 * &s.c != &ch * &s.gamma1 {
        return Err(fail("C != Gamma2^-1 C-hat Gamma1"));
    }
    if &s.gamma2 * &s.d != &dh * &s.gamma3 {
        return Err(fail("D != Gamma2^-1 D-hat Gamma3"));
    }
    // Gamma2 = diag(I, .), Gamma3 = diag(I, .)
    for (name, g) in [("Gamma2", &s.gamma2), ("Gamma3", &s.gamma3)] {
        for i in 0..g.nrows() {
            for j in 0..g.ncols() {
                if i < m0 || j < m0 {
                    let want = if i == j { k.one() } else { k.zero() };
                    if *g.get(i, j) != want {
                        return Err(fail(format!("{name} is not diag(I_m0, .)")));
                    }
                }
            }
        }
    }
    check_pattern(
        &s.a,
        &s.b,
        &s.c,
        &s.d,
        &Pattern {
            dims: s.dims,
            chains: s.chains.clone(),
            m0,
        },
    )?;
    if s.left_invertible != (s.dims[2] == 0) || s.right_invertible != (s.dims[1] == 0) {
        return Err(fail("invertibility flags disagree with the dims"));
    }
    Ok(())
}
