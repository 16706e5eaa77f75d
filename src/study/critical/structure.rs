//! The eigenvalues of $A(v_0)$ at a critical value $v_0$, with multiplicities and Jordan
//! block sizes decided exactly over $\mathbb{Q}(v_0)$.

use super::approx::{approx_roots, approx_roots_q};
use super::double::{double_blocks_exact, double_blocks_mod_p};
use super::roots::rational_near;
use super::value::value_over_q;
use super::{EigenvalueAt, FactorAt, Known};
use crate::algebraic::{AlgebraicNumber, NumberField, factor_over_number_field};
use crate::error::{Error, Result};
use crate::field::{Field, Rational, rational_to_f64};
use crate::matrix::Matrix;
use crate::poly::Poly;
use crate::study::family::ParamFamily;
use num_complex::Complex;

fn simple(z: Complex<f64>) -> EigenvalueAt {
    EigenvalueAt {
        approx: (z.re, z.im),
        multiplicity: 1,
        blocks: vec![1],
        factor: None,
        value: None,
    }
}

/// The eigenvalues of $A(v_0)$ with multiplicities and Jordan blocks; `true` when one is
/// repeated (checked exactly).
///
/// Exact decisions: $f \nmid \mathrm{disc}$ ($f$ the minimal polynomial of $v_0$) means
/// all eigenvalues are simple; else, when $s_{1,1}(v_0) \ne 0$, $\gcd(P, \partial_x P) =
/// x - \lambda$ with $\lambda = -s_{1,0}/s_{1,1} \in \mathbb{Q}(v_0)$: exactly one double
/// eigenvalue (checked: $P(\lambda) = P'(\lambda) = 0$), one Jordan block of size 2 iff
/// $\operatorname{rank}(A(v_0) - \lambda I) = n - 1$. Other cases take the general path
/// (square-free decomposition and factorization over $\mathbb{Q}(v_0)$).
pub(super) fn structure_at(
    kn: &Known<'_>,
    k: &NumberField,
    r: &AlgebraicNumber,
) -> Result<(Vec<EigenvalueAt>, bool)> {
    let vq = rational_near(r)?;
    let mut ev = approx_roots_q(&kn.p.at(&vq))?;
    let f = r.minpoly();
    if !kn.disc.rem(f).is_zero() {
        let mut out: Vec<EigenvalueAt> = ev.into_iter().map(simple).collect();
        sort_eigs(&mut out);
        return Ok((out, false));
    }
    let s11 = k.from_poly(&kn.s1.0);
    if k.is_zero(&s11) {
        let pk = kn.p.at_nf(k);
        let out = structure_general(kn.fam, k, &pk, &vq, r)?;
        let rep = out.iter().any(|e| e.multiplicity > 1);
        return Ok((out, rep));
    }
    // By the fundamental theorem of subresultants, f | disc and s11(v0) != 0 give
    // gcd(P, P') = s11 x + s10 at v0: exactly one double eigenvalue lambda = -s10/s11.
    // Its Jordan structure: rank(A - lambda I) = rank(s11 A + s10 I) = n - 1 iff one block.
    let blocks = match double_blocks_mod_p(kn, f)? {
        Some(b) => b,
        None => double_blocks_exact(kn, k)?,
    };
    let lq = -kn.s1.1.eval(&vq) / kn.s1.0.eval(&vq);
    let l = rational_to_f64(&lq);
    // the two numeric roots nearest to lambda are the double one
    for _ in 0..2 {
        if let Some(i) =
            (0..ev.len()).min_by(|&i, &j| (ev[i] - l).norm().total_cmp(&(ev[j] - l).norm()))
        {
            ev.remove(i);
        }
    }
    let mut out: Vec<EigenvalueAt> = ev.into_iter().map(simple).collect();
    // lambda = -s10(v0)/s11(v0) in Q(v0): the factor x - lambda and its exact value
    let lambda = k.neg(
        &k.div(&k.from_poly(&kn.s1.1), &s11)
            .ok_or(Error::DivisionByZero)?,
    );
    let factor = Poly::new(k.clone(), vec![k.neg(&lambda), k.one()]);
    out.push(EigenvalueAt {
        approx: (l, 0.0),
        multiplicity: 2,
        blocks,
        value: Some(value_over_q(k, &lambda, r)?),
        factor: Some(FactorAt::Q(factor)),
    });
    sort_eigs(&mut out);
    Ok((out, true))
}

/// The general path of [`structure_at`]: square-free decomposition over $\mathbb{Q}(v_0)$ first; only repeated parts of degree
/// $> 1$ are factored (Trager), so the common case (one double eigenvalue in
/// $\mathbb{Q}(v_0)$) needs gcds and ranks only.
fn structure_general(
    fam: &ParamFamily,
    k: &NumberField,
    pk: &Poly<NumberField>,
    v0: &Rational,
    r: &AlgebraicNumber,
) -> Result<Vec<EigenvalueAt>> {
    let mut a: Option<Matrix<NumberField>> = None;
    let mut out = vec![];
    for (s, m) in pk.squarefree() {
        let parts = if m > 1 && s.deg() > 1 {
            factor_over_number_field(&s)?
        } else {
            vec![(s, 1)]
        };
        for (q, e) in parts {
            let mult = m * e;
            let blocks = if mult > 1 {
                if a.is_none() {
                    a = Some(fam.state_matrix_nf(k)?);
                }
                block_sizes(a.as_ref().expect("set"), &q, mult)?
            } else {
                vec![1]
            };
            let value = if mult > 1 && q.deg() == 1 {
                Some(value_over_q(k, &k.neg(&q.monic().coeff(0)), r)?)
            } else {
                None
            };
            let factor = (mult > 1).then(|| FactorAt::Q(q.clone()));
            for z in approx_roots(k, &q, v0)? {
                out.push(EigenvalueAt {
                    approx: (z.re, z.im),
                    multiplicity: mult,
                    blocks: blocks.clone(),
                    factor: factor.clone(),
                    value: value.clone(),
                });
            }
        }
    }
    sort_eigs(&mut out);
    Ok(out)
}

fn sort_eigs(out: &mut [EigenvalueAt]) {
    out.sort_by(|x, y| {
        x.approx
            .0
            .total_cmp(&y.approx.0)
            .then(x.approx.1.total_cmp(&y.approx.1))
    });
}

/// Jordan block sizes (non-increasing) of each root of the irreducible `q` (multiplicity
/// `m` in the characteristic polynomial) for the matrix `a`.
pub fn block_sizes<K: Field>(a: &Matrix<K>, q: &Poly<K>, m: usize) -> Result<Vec<usize>> {
    if m == 1 {
        return Ok(vec![1]);
    }
    let d = q.deg();
    let qa = a.eval_poly(q)?;
    let mut ranks = vec![a.nrows()];
    let mut pw = qa.clone();
    for k in 1..=m {
        ranks.push(pw.rank());
        if k < m {
            pw = pw.try_mul(&qa)?;
        }
    }
    // at_least[k] = number of blocks of size >= k (k = 1..=m)
    let at_least: Vec<usize> = (1..=m).map(|k| (ranks[k - 1] - ranks[k]) / d).collect();
    let mut blocks = vec![];
    for k in (1..=m).rev() {
        let exact = at_least[k - 1] - at_least.get(k).copied().unwrap_or(0);
        blocks.extend(std::iter::repeat_n(k, exact));
    }
    if blocks.iter().sum::<usize>() != m {
        return Err(Error::Verification(format!(
            "Jordan blocks {blocks:?} do not add up to the multiplicity {m}"
        )));
    }
    Ok(blocks)
}
