//! The product kernel of $\mathbb{Q}(p)$: $AB$ with one reduction per entry.
//!
//! Row $i$ of $A$ is $P_i / d_i$ ($d_i$ the lcm of its denominators, $P_i$ over
//! $\mathbb{Z}\lbrack p\rbrack$) and column $j$ of $B$ is $Q_j / e_j$; then
//! $$(AB)_{ij} = \frac{P_i \cdot Q_j}{d_i e_j},$$
//! a dot product of polynomials and one reduction to lowest terms. The generic loop adds
//! $l$ fractions with different denominators, a gcd at every addition, and the entries
//! in between grow (the inverse of a Vandermonde matrix, rows with denominators
//! $\prod_{j \ne i} (p_i - p_j)$, times a Krylov matrix: the companion matrix, whose
//! entries are polynomials). The kernel runs when some entry of $A$ or $B$ has a
//! non-constant denominator and the inner dimension is at least 2.
//!
//! A row of $A$ whose denominators are many different polynomials has an lcm far larger
//! than any of them (the rows of that inverse Vandermonde matrix: every difference
//! $p_i - p_j$); when the lcm of a row has more than [`LCM_GROWTH`] times the terms of its
//! largest denominator, that row's entries are summed fraction by fraction instead (the
//! reduced sums stay small there).

use super::clear_rows;
use crate::field::Field;
use crate::mpoly::MPoly;
use crate::mpoly::gcd::lcm;
use crate::ratfunc::{RatFunc, RatFuncField};

/// Largest ratio of a row's lcm to its largest denominator (in terms) for which the row is
/// cleared to one denominator.
const LCM_GROWTH: usize = 8;

/// $AB$ for row-major `a` (`m x l`) and `b` (`l x n`); `None` when the generic loop is as
/// good (all denominators constant, or `l < 2`).
pub fn mul_qp(
    k: &RatFuncField,
    (m, l, n): (usize, usize, usize),
    a: &[RatFunc],
    b: &[RatFunc],
) -> Option<Vec<RatFunc>> {
    let fractional = |x: &[RatFunc]| x.iter().any(|e| !e.den().is_constant());
    if l < 2 || m * n == 0 || !(fractional(a) || fractional(b)) {
        return None;
    }
    let nv = k.nvars();
    let bt: Vec<RatFunc> = (0..n * l).map(|t| b[(t % l) * n + t / l].clone()).collect();
    let (qb, eb) = clear_rows(nv, n, l, &bt);
    let mut out = Vec::with_capacity(m * n);
    for i in 0..m {
        let Some((row, di)) = clear_row_bounded(nv, &a[i * l..(i + 1) * l]) else {
            // fraction by fraction (see the module docs)
            for j in 0..n {
                let mut acc = k.zero();
                for t in 0..l {
                    let (x, y) = (&a[i * l + t], &b[t * n + j]);
                    if !k.is_zero(x) && !k.is_zero(y) {
                        k.mul_add_assign(&mut acc, x, y);
                    }
                }
                out.push(acc);
            }
            continue;
        };
        for j in 0..n {
            let col = &qb[j * l..(j + 1) * l];
            let mut acc = MPoly::zero(nv);
            for (x, y) in row.iter().zip(col) {
                if !x.is_zero() && !y.is_zero() {
                    acc = acc.add(&x.mul(y));
                }
            }
            out.push(if acc.is_zero() {
                k.zero()
            } else {
                reduce(k, acc, &di, &eb[j])
            });
        }
    }
    Some(out)
}

/// The row times the lcm of its denominators, and that lcm; `None` when the lcm grows
/// past [`LCM_GROWTH`] times the terms of the row's largest denominator.
fn clear_row_bounded(nv: usize, row: &[RatFunc]) -> Option<(Vec<MPoly>, MPoly)> {
    let largest = row.iter().map(|e| e.den().len()).max().unwrap_or(1);
    let mut d = MPoly::one(nv);
    for e in row {
        if !e.den().is_one() && !e.num().is_zero() {
            d = lcm(&d, e.den());
            if d.len() > LCM_GROWTH * largest {
                return None;
            }
        }
    }
    let cleared = row
        .iter()
        .map(|e| {
            if e.num().is_zero() {
                MPoly::zero(nv)
            } else {
                e.num().mul(&d.div_exact(e.den()).expect("lcm"))
            }
        })
        .collect();
    Some((cleared, d))
}

/// `num / (d e)` in lowest terms: the two denominators divided out one at a time (exact
/// division first: the common case of a polynomial result costs no gcd).
fn reduce(k: &RatFuncField, num: MPoly, d: &MPoly, e: &MPoly) -> RatFunc {
    let mut num = num;
    let mut den = MPoly::one(k.nvars());
    for f in [d, e] {
        if f.is_one() {
            continue;
        }
        match num.div_exact(f) {
            Some(q) => num = q,
            None => den = den.mul(f),
        }
    }
    k.frac(num, den).expect("nonzero denominator")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::matrix::Matrix;

    /// The kernel equals the generic loop (fractions with different denominators, zeros,
    /// a polynomial result).
    #[test]
    fn mul_matches_generic_loop() {
        let k = RatFuncField::new(&["a", "b"]).unwrap();
        let e = |s: &str| k.parse(s).unwrap();
        let x = Matrix::from_vec(
            k.clone(),
            2,
            3,
            vec![
                e("1/(a-b)"),
                e("a/(a+b)"),
                e("0"),
                e("b"),
                e("1/a"),
                e("a^2/(b+1)"),
            ],
        );
        let y = Matrix::from_vec(
            k.clone(),
            3,
            2,
            vec![
                e("a-b"),
                e("1"),
                e("0"),
                e("(a+b)/a"),
                e("b+1"),
                e("7/(a*b)"),
            ],
        );
        let got = mul_qp(&k, (2, 3, 2), x.as_slice(), y.as_slice()).unwrap();
        for i in 0..2 {
            for j in 0..2 {
                let mut want = k.zero();
                for t in 0..3 {
                    want = k.add(&want, &k.mul(x.get(i, t), y.get(t, j)));
                }
                assert_eq!(got[i * 2 + j], want, "entry {i},{j}");
            }
        }
        assert_eq!(got[0], k.one());
    }
}
