//! Hurwitz matrices and exact stability counts of a polynomial with rational coefficients.
//!
//! For $a(x) = a_0 x^n + a_1 x^{n-1} + \dots + a_n$ the Hurwitz matrix is
//! $H_{ij} = a_{2j - i}$ ($1$-based, $a_k = 0$ outside $0..n$); with $a_0 > 0$ all roots lie
//! in the open left half-plane iff every leading principal minor $\Delta_k$ is positive
//! (Routh–Hurwitz). [`root_counts`] counts roots by the sign of their real part from the
//! certified roots of [`crate::algebraic::roots`], and [`hurwitz_stable`] decides
//! stability from the minors; the two are independent and checked against each other.

use crate::algebraic::roots;
use crate::error::Result;
use crate::field::{Field, Q, Rational};
use crate::matrix::Matrix;
use crate::poly::Poly;
use num_traits::{Signed, Zero};
use std::cmp::Ordering;

/// The $n \times n$ Hurwitz matrix of the polynomial with coefficients `c` (`c[k]` of
/// $x^k$, degree $n$).
pub fn hurwitz_matrix<K: Field>(k: &K, c: &[K::Elem], n: usize) -> Matrix<K> {
    // a_j = c[n - j]
    let a = |j: i64| -> K::Elem {
        if j < 0 || j > n as i64 {
            k.zero()
        } else {
            c.get(n - j as usize).cloned().unwrap_or_else(|| k.zero())
        }
    };
    Matrix::from_fn(k.clone(), n, n, |i, j| {
        a(2 * (j as i64 + 1) - (i as i64 + 1))
    })
}

/// Routh–Hurwitz: are all roots of `p` (degree $\ge 1$) in the open left half-plane?
///
/// # Errors
/// From the determinants.
pub fn hurwitz_stable(p: &Poly<Q>) -> Result<bool> {
    let n = p.deg();
    let p = if p.lc().is_negative() {
        p.neg()
    } else {
        p.clone()
    };
    let h = hurwitz_matrix(&Q, p.coeffs(), n);
    for k in 1..=n {
        if h.submatrix(0, k, 0, k).det()? <= Rational::zero() {
            return Ok(false);
        }
    }
    Ok(true)
}

/// Counts of the roots of a polynomial by kind (with multiplicity).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RootCounts {
    pub real_negative: usize,
    pub zero: usize,
    pub real_positive: usize,
    /// Complex conjugate pairs with negative real part.
    pub complex_pairs_stable: usize,
    /// Purely imaginary pairs $\pm i\omega$, $\omega > 0$.
    pub imaginary_pairs: usize,
    /// Complex conjugate pairs with positive real part.
    pub complex_pairs_unstable: usize,
}

impl RootCounts {
    /// Number of roots with positive real part.
    pub fn unstable(&self) -> usize {
        self.real_positive + 2 * self.complex_pairs_unstable
    }
    /// All roots in the open left half-plane.
    pub fn is_stable(&self) -> bool {
        self.unstable() == 0 && self.zero == 0 && self.imaginary_pairs == 0
    }
}

/// Exact counts of the roots of `p` by the sign of their real part.
///
/// # Algorithm
/// Real roots: square-free decomposition and Descartes isolation (intervals bisected away
/// from 0). Roots with positive real part: the Routh array (exact over $\mathbb{Q}$); when
/// a first-column entry vanishes (roots on or symmetric about the imaginary axis), all
/// roots are isolated instead ([`crate::algebraic::roots`], certified boxes).
///
/// # Errors
/// From [`crate::algebraic::roots`].
pub fn root_counts(p: &Poly<Q>) -> Result<RootCounts> {
    if let Some(c) = root_counts_routh(p) {
        return Ok(c);
    }
    root_counts_isolated(p)
}

/// Number of roots with positive real part by the Routh array; `None` when a first-column
/// entry vanishes.
pub fn routh_rhp(p: &Poly<Q>) -> Option<usize> {
    let n = p.deg();
    let a: Vec<Rational> = (0..=n).rev().map(|k| p.coeff(k)).collect(); // a0 x^n + ...
    let mut r0: Vec<Rational> = a.iter().step_by(2).cloned().collect();
    let mut r1: Vec<Rational> = a.iter().skip(1).step_by(2).cloned().collect();
    let mut first = vec![r0[0].clone()];
    for _ in 0..n {
        if r1.is_empty() || r1[0].is_zero() {
            return None;
        }
        first.push(r1[0].clone());
        let next: Vec<Rational> = (0..r0.len().saturating_sub(1))
            .map(|j| {
                let b = r1.get(j + 1).cloned().unwrap_or_default();
                (&r1[0] * &r0[j + 1] - &r0[0] * &b) / &r1[0]
            })
            .collect();
        r0 = r1;
        r1 = next;
    }
    let changes = first
        .windows(2)
        .filter(|w| w[0].is_negative() != w[1].is_negative())
        .count();
    Some(changes)
}

fn root_counts_routh(p: &Poly<Q>) -> Option<RootCounts> {
    use crate::algebraic::isolate_real::{bisect, isolate_real_roots};
    let n = p.deg();
    let zero = (0..=n).take_while(|&k| p.coeff(k).is_zero()).count();
    let q = Poly::new(Q, p.coeffs()[zero..].to_vec());
    let rhp = routh_rhp(&q)?;
    let mut c = RootCounts {
        zero,
        ..RootCounts::default()
    };
    for (s, m) in q.squarefree() {
        let z = crate::algebraic::zp::from_poly_q(&s);
        for mut r in isolate_real_roots(&z) {
            while r.lo.is_negative() && r.hi.is_positive() {
                r = bisect(&z, &r);
            }
            if r.hi.is_positive() || (r.hi.is_zero() && r.lo.is_positive()) {
                c.real_positive += m;
            } else {
                c.real_negative += m;
            }
        }
    }
    let complex = n - zero - c.real_positive - c.real_negative;
    c.complex_pairs_unstable = rhp.checked_sub(c.real_positive)? / 2;
    c.complex_pairs_stable = (complex / 2).checked_sub(c.complex_pairs_unstable)?;
    Some(c)
}

/// As [`root_counts`], always from certified isolation of every root.
///
/// # Errors
/// From [`crate::algebraic::roots`].
pub fn root_counts_isolated(p: &Poly<Q>) -> Result<RootCounts> {
    let mut c = RootCounts::default();
    for (z, m) in roots(p)? {
        if z.is_real() {
            let s = z
                .partial_cmp(&crate::algebraic::AlgebraicNumber::from_rational(
                    &Rational::zero(),
                ))
                .unwrap_or(Ordering::Equal);
            match s {
                Ordering::Less => c.real_negative += m,
                Ordering::Equal => c.zero += m,
                Ordering::Greater => c.real_positive += m,
            }
        } else {
            // count each pair once: the root in the upper half-plane
            let (_, im) = z.approx();
            if im < 0.0 {
                continue;
            }
            if z.is_pure_imaginary() {
                c.imaginary_pairs += m;
                continue;
            }
            let re = z.try_re()?;
            let zero = crate::algebraic::AlgebraicNumber::from_rational(&Rational::zero());
            match re.partial_cmp(&zero).unwrap_or(Ordering::Equal) {
                Ordering::Less => c.complex_pairs_stable += m,
                Ordering::Equal => c.imaginary_pairs += m,
                Ordering::Greater => c.complex_pairs_unstable += m,
            }
        }
    }
    Ok(c)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn routh_hurwitz_examples() {
        // (x+1)(x+2)(x+3) stable; x^3 + x^2 + x + 1 = (x+1)(x^2+1) not; (x-1)(x+2) not
        assert!(hurwitz_stable(&Poly::from_i64s(&[6, 11, 6, 1])).unwrap());
        assert!(!hurwitz_stable(&Poly::from_i64s(&[1, 1, 1, 1])).unwrap());
        assert!(!hurwitz_stable(&Poly::from_i64s(&[-2, 1, 1])).unwrap());
        let c = root_counts(&Poly::from_i64s(&[1, 1, 1, 1])).unwrap();
        assert_eq!((c.real_negative, c.imaginary_pairs), (1, 1));
        // (x^2 - 2x + 5)(x - 3) x^2
        let p = Poly::from_i64s(&[5, -2, 1]).mul(&Poly::from_i64s(&[-3, 1]));
        let c = root_counts(&p.shift(2)).unwrap();
        assert_eq!(
            (c.zero, c.real_positive, c.complex_pairs_unstable),
            (2, 1, 1)
        );
        assert_eq!(c.unstable(), 3);
        // the Routh path and the isolation path agree
        for cs in [
            [6i64, 11, 6, 1, 0],
            [5, -2, 1, 3, 1],
            [-3, 1, 4, 1, 2],
            [7, 0, 2, -1, 1],
        ] {
            let p = Poly::from_i64s(&cs);
            assert_eq!(
                root_counts(&p).unwrap(),
                root_counts_isolated(&p).unwrap(),
                "{p}"
            );
        }
    }
}
