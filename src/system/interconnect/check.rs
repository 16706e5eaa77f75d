//! Exact check of an interconnection: the identity of its transfer matrices
//! ($G_2 G_1$, $G_1 + G_2$, $(I - \sigma G K) G_{fb} = G$, $\mathrm{diag}(G_i)$) at enough
//! points $s_0$ to prove it.
//!
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
    let k = r.a.field().clone();
    let total: usize = parts.iter().map(|p| p.a.nrows()).sum::<usize>() + r.a.nrows();
    let need = total + 1;
    let mut agree = 0;
    for t in 0..(need + total) as i64 {
        if agree == need {
            break;
        }
        let s0 = k.from_rational(&Rational::new((2 * t + 1).into(), 7.into()));
        let Some(gr) = eval(&r, &s0) else {
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
