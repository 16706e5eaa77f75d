//! The Jordan structure of a double eigenvalue $\lambda = -s_{1,0}/s_{1,1}$ at $v_0$: one
//! block of size 2 iff $s_{1,1} A(v_0) + s_{1,0} I$ has rank $n - 1$, decided modulo a
//! prime when possible, else exactly over $\mathbb{Q}(v_0)$.

use super::Known;
use crate::algebraic::{NfElem, NumberField};
use crate::error::{Error, Result};
use crate::field::{Field, Q, Rational};
use crate::matrix::Matrix;
use crate::poly::Poly;

/// Does the singular matrix `b` over $\mathbb{Q}(v_0)$ have rank $n - 1$, i.e. a nonzero
/// $(n-1)$-minor? Minors are tried in the order of their float magnitude (guidance only)
/// and computed exactly and division-free (no inversions in $\mathbb{Q}(v_0)$); above
/// $n = 7$ the exact rank is used instead.
fn has_nonzero_minor(b: &Matrix<NumberField>) -> Result<bool> {
    let n = b.nrows();
    if n <= 1 {
        return Ok(n == 1 && b.rank() == 0);
    }
    if n > 7 {
        return Ok(b.rank() == n - 1);
    }
    let k = b.field().clone();
    let approx = b.to_approx_complex();
    let mut order: Vec<(usize, usize, f64)> = vec![];
    for i in 0..n {
        for j in 0..n {
            let m = nalgebra::DMatrix::from_fn(n - 1, n - 1, |r, c| {
                let rr = if r < i { r } else { r + 1 };
                let cc = if c < j { c } else { c + 1 };
                approx[rr][cc].0
            });
            order.push((i, j, m.determinant().abs()));
        }
    }
    order.sort_by(|x, y| y.2.total_cmp(&x.2));
    for (i, j, _) in order {
        let rows: Vec<usize> = (0..n).filter(|&r| r != i).collect();
        let cols: Vec<usize> = (0..n).filter(|&c| c != j).collect();
        let sub: Vec<Vec<NfElem>> = rows
            .iter()
            .map(|&r| cols.iter().map(|&c| b.get(r, c).clone()).collect())
            .collect();
        if !k.is_zero(&det_laplace(&k, &sub)) {
            return Ok(true);
        }
    }
    Ok(false)
}

/// Determinant by Laplace expansion along the first row (division-free; small sizes).
fn det_laplace<K: Field>(k: &K, m: &[Vec<K::Elem>]) -> K::Elem {
    let n = m.len();
    match n {
        0 => k.one(),
        1 => m[0][0].clone(),
        2 => k.sub(&k.mul(&m[0][0], &m[1][1]), &k.mul(&m[0][1], &m[1][0])),
        _ => {
            let mut acc = k.zero();
            for j in 0..n {
                if k.is_zero(&m[0][j]) {
                    continue;
                }
                let minor: Vec<Vec<K::Elem>> = m[1..]
                    .iter()
                    .map(|r| {
                        r.iter()
                            .enumerate()
                            .filter(|(c, _)| *c != j)
                            .map(|(_, x)| x.clone())
                            .collect()
                    })
                    .collect();
                let t = k.mul(&m[0][j], &det_laplace(k, &minor));
                acc = if j % 2 == 0 {
                    k.add(&acc, &t)
                } else {
                    k.sub(&acc, &t)
                };
            }
            acc
        }
    }
}

/// Jordan blocks of the double eigenvalue from a reduction modulo a prime: `Some([2])` when
/// $s_{1,1} A + s_{1,0} I$ has rank $n - 1$ modulo $p$ (hence over $\mathbb{Q}(v_0)$),
/// after checking $P(\lambda) \equiv P'(\lambda) \equiv 0$; `None` when undecided.
pub(super) fn double_blocks_mod_p(kn: &Known<'_>, f: &Poly<Q>) -> Result<Option<Vec<usize>>> {
    use crate::study::modp::{poly_at, rank_mod, root_mod_p, state_matrix_mod};
    for skip in 0..3 {
        let Some((p, t0)) = root_mod_p(f, skip) else {
            return Ok(None);
        };
        let (Some(s11), Some(s10)) = (poly_at(&kn.s1.0, t0, p), poly_at(&kn.s1.1, t0, p)) else {
            continue;
        };
        let Some(a) = state_matrix_mod(kn.fam, t0, p) else {
            continue;
        };
        if s11 == 0 {
            continue;
        }
        // P(lambda) = P'(lambda) = 0 mod p (a necessary condition, checked)
        let lam = (p - s10)
            * crate::study::modp::rational_mod(&Rational::new(1.into(), s11.into()), p)
                .unwrap_or(0)
            % p;
        let pc: Option<Vec<u64>> = kn.p.coeffs.iter().map(|c| poly_at(c, t0, p)).collect();
        let Some(pc) = pc else { continue };
        let ev = |cs: &[u64]| cs.iter().rev().fold(0u64, |acc, c| (acc * lam + c) % p);
        let dc: Vec<u64> = pc
            .iter()
            .enumerate()
            .skip(1)
            .map(|(i, c)| c * (i as u64) % p)
            .collect();
        if ev(&pc) != 0 || ev(&dc) != 0 {
            return Err(Error::Verification(
                "the repeated eigenvalue from the subresultant is not a double root mod p".into(),
            ));
        }
        let n = a.len();
        let b: Vec<Vec<u64>> = (0..n)
            .map(|i| {
                (0..n)
                    .map(|j| (a[i][j] * s11 + if i == j { s10 } else { 0 }) % p)
                    .collect()
            })
            .collect();
        if rank_mod(b, p) == n - 1 {
            return Ok(Some(vec![2]));
        }
    }
    Ok(None)
}

/// Jordan blocks of the double eigenvalue over $\mathbb{Q}(v_0)$ exactly (slow path).
pub(super) fn double_blocks_exact(kn: &Known<'_>, k: &NumberField) -> Result<Vec<usize>> {
    let s11 = k.from_poly(&kn.s1.0);
    let s10 = k.from_poly(&kn.s1.1);
    let a = kn.fam.state_matrix_nf(k)?;
    let n = a.nrows();
    let mut shifted = a.scale(&s11);
    for i in 0..n {
        let d = k.add(shifted.get(i, i), &s10);
        shifted.set(i, i, d);
    }
    Ok(if has_nonzero_minor(&shifted)? {
        vec![2]
    } else {
        vec![1, 1]
    })
}
