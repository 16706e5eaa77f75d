//! Integer product kernel over $\mathbb{Q}$.
//!
//! $C = AB$ with $A = D_r^{-1}\hat A$ (row $i$ scaled by the lcm $d_i$ of its denominators)
//! and $B = \hat B D_c^{-1}$ (column $j$ by $e_j$): $c_{ij} = (\hat A \hat B)_{ij} / (d_i e_j)$.
//! The dot products are exact integer sums and each entry is reduced once (with a Lehmer
//! gcd), instead of normalising a rational after every multiply-add.

use super::gcd::{fraction, gcd};
use crate::field::Rational;
use num_bigint::BigInt;
use num_traits::{One, Zero};

fn scale<'a>(xs: impl Iterator<Item = &'a Rational> + Clone) -> (BigInt, Vec<BigInt>) {
    let mut d = BigInt::one();
    for x in xs.clone() {
        if !x.denom().is_one() {
            let g = gcd(&d, x.denom());
            d = &d / g * x.denom();
        }
    }
    let v = xs
        .map(|x| {
            if x.is_zero() {
                BigInt::zero()
            } else if x.denom().is_one() {
                x.numer() * &d
            } else {
                x.numer() * (&d / x.denom())
            }
        })
        .collect();
    (d, v)
}

/// Row-major product of an `m x k` and a `k x n` rational matrix.
pub fn mul_q(m: usize, k: usize, n: usize, a: &[Rational], b: &[Rational]) -> Vec<Rational> {
    let rows: Vec<(BigInt, Vec<BigInt>)> = (0..m)
        .map(|i| scale(a[i * k..(i + 1) * k].iter()))
        .collect();
    let cols: Vec<(BigInt, Vec<BigInt>)> = (0..n)
        .map(|j| scale((0..k).map(|l| &b[l * n + j])))
        .collect();
    let mut out = Vec::with_capacity(m * n);
    for (di, ri) in &rows {
        for (ej, cj) in &cols {
            let mut acc = BigInt::zero();
            for (x, y) in ri.iter().zip(cj) {
                if !x.is_zero() && !y.is_zero() {
                    acc += x * y;
                }
            }
            out.push(if acc.is_zero() {
                Rational::zero()
            } else if di.is_one() && ej.is_one() {
                Rational::from_integer(acc)
            } else {
                fraction(acc, &(di * ej))
            });
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn matches_naive() {
        let r = |n: i64, d: i64| Rational::new(n.into(), d.into());
        let a = vec![r(1, 2), r(-3, 4), r(0, 1), r(5, 6), r(7, 1), r(-1, 3)];
        let b = vec![r(2, 3), r(1, 1), r(-1, 5), r(0, 1), r(3, 7), r(9, 2)];
        let c = mul_q(2, 3, 2, &a, &b);
        for i in 0..2 {
            for j in 0..2 {
                let want: Rational = (0..3).map(|l| &a[i * 3 + l] * &b[l * 2 + j]).sum();
                assert_eq!(c[i * 2 + j], want);
            }
        }
    }
}
