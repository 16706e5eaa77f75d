//! The RREF of a rank-deficient rational matrix from one nonsingular block (issue 29): one
//! certified solve, by Dixon's lifting ([`super::dixon`], output-sensitive), or the CRT
//! solve of [`super::direct`] should that find no invertible image.
//!
//! One image $\bar A = A \bmod p$ ([`super::qimage`]) gives pivot columns $P$ (its RREF) and
//! rows $S$ ($|S| = |P| = r$, the first independent rows of $\bar A_{:,P}$), so the block
//! $B = A_{S,P}$ is nonsingular modulo $p$, hence over $\mathbb{Q}$. With the free columns
//! $F$, [`super::dixon::solve_dixon_int`] gives $N, \delta \ne 0$ with
//! $B N = \delta A_{S,F}$, certified there. The candidate $X$ ($r \times n$) has
//! $X_{:,P} = I$ and $X_{:,F} = N / \delta$, so $A_{S,:} = B X$.
//!
//! **Identities checked exactly** (integers, each row $i \notin S$ scaled by the lcm $e_i$
//! of its denominators): $\delta\, e_i a_{i,f} = \sum_k e_i a_{i,P_k} N_{k,f}$ for every
//! $f \in F$, i.e. $A_{i,:} = A_{i,P} X$; and $X_{k,f} = 0$ for $f < P_k$. Then the row
//! space of $A$ lies in that of $X$, which has rank $r \le \operatorname{rank} A$ ($B$ is
//! nonsingular): both row spaces are equal, and $X$, in reduced echelon form, is *the*
//! RREF of $A$. A failed check (an unlucky prime: later pivots than over $\mathbb{Q}$)
//! returns `None` and the caller takes the reconstruction path of [`super::rref`].
//!
//! The lifting runs as long as the output needs (twice $\log_2 \max(|N|, \delta)$ bits),
//! not to the determinant bound of the block, and the solve has only $|F|$ right-hand sides.

use super::direct::solve_direct_int;
use super::dixon::solve_dixon_int;
use super::qimage::RatMat;
use super::rref::{IntRref, rref_mod_p};
use crate::field::Rational;
use crate::qkernels::prime::primes;
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};

/// The certified RREF of the `m x n` row-major `a` as `num / den` (see the module docs);
/// `None` when the first usable prime is unlucky or `a` is zero modulo it.
///
/// # Panics
/// When `a.len() != m * n`.
pub fn rref_pivot_solve(m: usize, n: usize, a: &[Rational]) -> Option<IntRref> {
    let rm = RatMat::new(m, n, a);
    let (pr, img) = primes(0).find_map(|pr| rm.image(&pr).map(|img| (pr, img)))?;
    let mut red = img.clone();
    let piv = rref_mod_p(&pr, m, n, &mut red);
    let r = piv.len();
    if r == 0 {
        return None;
    }
    // the first independent rows of A_{:,P} modulo p: pivots of its transpose
    let mut t: Vec<u64> = (0..r)
        .flat_map(|k| (0..m).map(move |i| (k, i)))
        .map(|(k, i)| img[i * n + piv[k]])
        .collect();
    let rows = rref_mod_p(&pr, r, m, &mut t);
    if rows.len() != r {
        return None;
    }
    let mut is_piv = vec![false; n];
    piv.iter().for_each(|&c| is_piv[c] = true);
    let free: Vec<usize> = (0..n).filter(|&c| !is_piv[c]).collect();
    let block: Vec<Rational> = rows
        .iter()
        .flat_map(|&i| piv.iter().map(move |&c| a[i * n + c].clone()))
        .collect();
    let rhs: Vec<Rational> = rows
        .iter()
        .flat_map(|&i| free.iter().map(move |&c| a[i * n + c].clone()))
        .collect();
    let (mut den, mut x) = solve_dixon_int(r, free.len(), &block, &rhs)
        .or_else(|| solve_direct_int(r, free.len(), &block, &rhs))?;
    if den.is_negative() {
        den = -den;
        x.iter_mut().for_each(|v| *v = -std::mem::take(v));
    }
    let nf = free.len();
    // reduced echelon form: nothing left of a pivot
    for (k, &p) in piv.iter().enumerate() {
        if free
            .iter()
            .zip(&x[k * nf..])
            .any(|(&f, v)| f < p && !v.is_zero())
        {
            return None;
        }
    }
    let mut in_s = vec![false; m];
    rows.iter().for_each(|&i| in_s[i] = true);
    let other_rows_ok = (0..m)
        .filter(|&i| !in_s[i])
        .all(|i| row_in_span(&a[i * n..(i + 1) * n], &piv, &free, &den, &x));
    if !other_rows_ok {
        return None;
    }
    let mut num = vec![BigInt::zero(); r * n];
    for (k, &p) in piv.iter().enumerate() {
        num[k * n + p] = den.clone();
        for (fi, &f) in free.iter().enumerate() {
            num[k * n + f] = std::mem::take(&mut x[k * nf + fi]);
        }
    }
    Some(IntRref {
        pivots: piv,
        den,
        num,
    })
}

/// $\delta\, e a_f = \sum_k e a_{P_k} N_{k,f}$ for every free column $f$ ($e$ the lcm of the
/// row's denominators): the row is $a_P X$.
fn row_in_span(
    row: &[Rational],
    piv: &[usize],
    free: &[usize],
    den: &BigInt,
    x: &[BigInt],
) -> bool {
    let e = row.iter().fold(BigInt::one(), |l, v| {
        if v.denom().is_one() {
            l
        } else {
            l.lcm(v.denom())
        }
    });
    let int = |v: &Rational| v.numer() * (&e / v.denom());
    let lhs: Vec<BigInt> = piv.iter().map(|&c| int(&row[c])).collect();
    let nf = free.len();
    free.iter().enumerate().all(|(fi, &f)| {
        let s: BigInt = lhs
            .iter()
            .enumerate()
            .filter(|(_, c)| !c.is_zero())
            .map(|(k, c)| c * &x[k * nf + fi])
            .sum();
        s == den * int(&row[f])
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(a: i64, b: i64) -> Rational {
        Rational::new(a.into(), b.into())
    }

    #[test]
    fn rank_deficient_rref_is_certified() {
        // rows: r0, r1, r0 + r1 (rank 2), pivots 0, 1
        let r0 = [q(1, 2), q(1, 3), q(2, 7)];
        let r1 = [q(-3, 5), q(4, 1), q(1, 9)];
        let mut a: Vec<Rational> = r0.iter().chain(&r1).cloned().collect();
        a.extend(r0.iter().zip(&r1).map(|(x, y)| x + y));
        let res = rref_pivot_solve(3, 3, &a).expect("lucky prime");
        assert_eq!(res.pivots, vec![0, 1]);
        // R = [[1, 0, c0], [0, 1, c1]] with r0 = a0 R, reassembled exactly
        let c: Vec<Rational> = (0..2)
            .map(|k| Rational::new(res.num[k * 3 + 2].clone(), res.den.clone()))
            .collect();
        for row in [&r0, &r1] {
            assert_eq!(&row[0] * &c[0] + &row[1] * &c[1], row[2]);
        }
    }

    #[test]
    fn zero_pivot_block_row_order() {
        // the first row is zero: S must skip it; column 0 is zero: no pivot there
        let a = vec![
            q(0, 1),
            q(0, 1),
            q(0, 1),
            q(0, 1),
            q(2, 3),
            q(1, 1),
            q(0, 1),
            q(4, 3),
            q(2, 1),
        ];
        let res = rref_pivot_solve(3, 3, &a).expect("lucky prime");
        assert_eq!(res.pivots, vec![1]);
        assert_eq!(Rational::new(res.num[2].clone(), res.den.clone()), q(3, 2));
    }
}
