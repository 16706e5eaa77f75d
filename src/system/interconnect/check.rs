//! Exact check of an interconnection: the identity of its transfer matrices
//! ($G_2 G_1$, $G_1 + G_2$, $(I - \sigma G K) G_{fb} = G$, $\mathrm{diag}(G_i)$), proved
//! from finitely many coefficients or values.
//!
//! **Standard systems** (no `E`): on the Laurent series at infinity,
//! $G = \sum_k h_k s^{-k}$ with $h_0 = D$, $h_k = C A^{k-1} B$, the identities become Cauchy
//! products of the Markov sequences. The difference of the two sides is
//! $P(s)/\prod_i d_i(s)$ with $\deg P \le \sum_i n_i = \deg \prod_i d_i$; in $t = 1/s$ its
//! numerator is a polynomial of degree at most $\sum_i n_i$ and its denominator is 1 at
//! $t = 0$, so the first $\sum_i n_i + 1$ series coefficients vanish iff it is zero. Only
//! products $A (A^{k-1} B)$: no inversion (cheap over $\mathbb{Q}(p)$).
//!
//! **Descriptor parts** (improper transfer matrices): by values at points $s_0$.
//! Every transfer matrix $G_i = C_i (sE_i - A_i)^{-1} B_i + D_i$ has entries $N/d_i$ with
//! $d_i = \det(sE_i - A_i)$ of degree at most $n_i$ and $\deg N \le n_i$. Over the common
//! denominator $\prod_i d_i$ (the parts and the result), each identity above is a matrix of
//! polynomials of degree at most $\sum_i n_i$; it vanishes identically iff it vanishes at
//! $\sum_i n_i + 1$ points where no $d_i$ vanishes. At most $\sum_i n_i$ points are skipped
//! as roots of some $d_i$, so the search is bounded; a singular pencil ($d_i \equiv 0$)
//! fails the check.

use super::{Blocks, BlocksRef, Sign};
use crate::field::{Field, Rational};
use crate::matrix::Matrix;

/// Which interconnection a result came from (the parts by reference).
#[derive(Clone, Copy, Debug)]
pub enum Interconnection<'a, S> {
    /// [`super::series`]`(g1, g2)`: $G = G_2 G_1$.
    Series(&'a S, &'a S),
    /// [`super::parallel`]`(g1, g2)`: $G = G_1 + G_2$.
    Parallel(&'a S, &'a S),
    /// [`super::feedback`]`(g, k, sign)`: $(I - \sigma G K) G_{fb} = G$.
    Feedback(&'a S, &'a S, Sign),
    /// [`super::append`]`(systems)`: $G = \mathrm{diag}(G_1, \dots)$.
    Append(&'a [S]),
}

/// $G(s_0) = C (s_0 E - A)^{-1} B + D$, `None` at a root of $\det(s_0E - A)$.
fn eval<K: Field>(p: &BlocksRef<'_, K>, s0: &K::Elem) -> Option<Matrix<K>> {
    let n = p.a.nrows();
    let k = p.a.field();
    let se = match p.e {
        Some(e) => e.scale(s0),
        None => Matrix::identity(k.clone(), n).scale(s0),
    };
    let x = (&se - p.a).inverse().ok()?;
    Some(&(&(p.c * &x) * p.b) + p.d)
}

/// Is `result` the interconnection `op` of its parts? Exact (see the module docs).
pub fn verify<K: Field, S: Blocks<K>>(op: &Interconnection<'_, S>, result: &S) -> bool {
    let parts: Vec<BlocksRef<'_, K>> = match op {
        Interconnection::Series(a, b)
        | Interconnection::Parallel(a, b)
        | Interconnection::Feedback(a, b, _) => vec![a.blocks(), b.blocks()],
        Interconnection::Append(list) => list.iter().map(Blocks::blocks).collect(),
    };
    let r = result.blocks();
    if r.e.is_none() && parts.iter().all(|p| p.e.is_none()) {
        return verify_markov(op, &parts, &r);
    }
    verify_points(op, &parts, &r)
}

/// $h_0 = D$, $h_k = C A^{k-1} B$ for $k < len$.
fn markov<K: Field>(p: &BlocksRef<'_, K>, len: usize) -> Vec<Matrix<K>> {
    let mut out = vec![p.d.clone()];
    let mut w = p.b.clone();
    for k in 1..len {
        if k > 1 {
            w = p.a * &w;
        }
        out.push(p.c * &w);
    }
    out
}

/// The coefficient `k` of the Cauchy product of two Markov sequences.
fn cauchy<K: Field>(f: &[Matrix<K>], g: &[Matrix<K>], k: usize) -> Option<Matrix<K>> {
    let mut acc = f[0].try_mul(&g[k]).ok()?;
    for i in 1..=k {
        acc = acc.try_add(&f[i].try_mul(&g[k - i]).ok()?).ok()?;
    }
    Some(acc)
}

/// The check on Markov sequences (standard systems).
fn verify_markov<K: Field, S>(
    op: &Interconnection<'_, S>,
    parts: &[BlocksRef<'_, K>],
    r: &BlocksRef<'_, K>,
) -> bool {
    let len = parts.iter().map(|p| p.a.nrows()).sum::<usize>() + r.a.nrows() + 1;
    let hs: Vec<Vec<Matrix<K>>> = parts.iter().map(|p| markov(p, len)).collect();
    let hr = markov(r, len);
    let k = r.a.field().clone();
    match op {
        Interconnection::Series(..) => {
            (0..len).all(|i| cauchy(&hs[1], &hs[0], i) == Some(hr[i].clone()))
        }
        Interconnection::Parallel(..) => {
            (0..len).all(|i| hs[0][i].try_add(&hs[1][i]).ok() == Some(hr[i].clone()))
        }
        Interconnection::Append(_) => (0..len).all(|i| {
            let blocks: Vec<Matrix<K>> = hs.iter().map(|h| h[i].clone()).collect();
            Matrix::block_diag(k.clone(), &blocks) == hr[i]
        }),
        Interconnection::Feedback(_, _, sign) => {
            // R - sign (G K) R = G, coefficient by coefficient
            let s = sign.value(&k);
            let gk: Option<Vec<Matrix<K>>> = (0..len).map(|i| cauchy(&hs[0], &hs[1], i)).collect();
            let Some(gk) = gk else { return false };
            (0..len).all(|i| {
                cauchy(&gk, &hr, i)
                    .and_then(|m| hr[i].try_sub(&m.scale(&s)).ok())
                    .is_some_and(|lhs| lhs == hs[0][i])
            })
        }
    }
}

/// The check by values at points (descriptor parts).
fn verify_points<K: Field, S>(
    op: &Interconnection<'_, S>,
    parts: &[BlocksRef<'_, K>],
    r: &BlocksRef<'_, K>,
) -> bool {
    let k = r.a.field().clone();
    let total: usize = parts.iter().map(|p| p.a.nrows()).sum::<usize>() + r.a.nrows();
    let need = total + 1;
    let mut agree = 0;
    for t in 0..(need + total) as i64 {
        if agree == need {
            break;
        }
        let s0 = k.from_rational(&Rational::new((2 * t + 1).into(), 7.into()));
        let Some(gr) = eval(r, &s0) else {
            continue;
        };
        let Some(gs) = parts
            .iter()
            .map(|p| eval(p, &s0))
            .collect::<Option<Vec<_>>>()
        else {
            continue;
        };
        if !identity_holds(op, &gs, &gr) {
            return false;
        }
        agree += 1;
    }
    agree == need
}

/// The identity of `op` at one point, given the parts' values `gs` and the result's `gr`.
fn identity_holds<K: Field, S>(
    op: &Interconnection<'_, S>,
    gs: &[Matrix<K>],
    gr: &Matrix<K>,
) -> bool {
    let k = gr.field().clone();
    let expect = match op {
        Interconnection::Series(..) => gs[1].try_mul(&gs[0]).ok(),
        Interconnection::Parallel(..) => gs[0].try_add(&gs[1]).ok(),
        Interconnection::Append(_) => Some(Matrix::block_diag(k.clone(), gs)),
        Interconnection::Feedback(_, _, sign) => {
            // (I - sign G K) G_fb = G
            let gk = gs[0].try_mul(&gs[1]).ok();
            let lhs = gk.and_then(|gk| {
                let m = &Matrix::identity(k.clone(), gk.nrows()) - &gk.scale(&sign.value(&k));
                m.try_mul(gr).ok()
            });
            return lhs.as_ref() == Some(&gs[0]);
        }
    };
    expect.as_ref() == Some(gr)
}
