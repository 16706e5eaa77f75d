//! Certified real root isolation: Descartes' rule of signs with bisection (the
//! Vincent–Collins–Akritas method) on integer polynomials, with exact Taylor shifts.
//!
//! For a square-free $p \in \mathbb{Z}\[x\]$ the roots in $(0, 1)$ of $q$ correspond to the
//! positive roots of $(x+1)^n q(1/(x+1))$, and the number $v$ of sign variations of its
//! coefficients exceeds that count by an even number (Descartes). $v = 0$ proves no root,
//! $v = 1$ proves exactly one; otherwise $(0, 1)$ is bisected with $2^n q(x/2)$ and its Taylor
//! shift by one. Every step is integer arithmetic. Roots met exactly at a bisection point are
//! returned as exact points; such a point may also be the endpoint of a neighbouring open
//! interval (which still holds exactly one root in its interior).
//!
//! | entry point | computes |
//! |---|---|
//! | [`isolate_real_roots`] | disjoint isolating intervals of all real roots, ascending |
//! | [`sign_at`] | exact sign of $p(q)$ at a rational $q$ |
//! | [`refine_real`] | bisection of an isolating interval to a requested width |

use crate::field::Rational;
use crate::poly::zslice as zp;
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;

/// An isolated real root: an exact point (`lo == hi`) or an open interval `(lo, hi)` which
/// holds exactly one root (for an irreducible polynomial of degree >= 2 the rational
/// endpoints are never roots).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RealRoot {
    pub lo: Rational,
    pub hi: Rational,
}

impl RealRoot {
    pub fn is_exact(&self) -> bool {
        self.lo == self.hi
    }
}

/// Number of sign variations of a coefficient sequence (zeros skipped).
fn variations(a: &[BigInt]) -> usize {
    let mut last = 0i8;
    let mut v = 0;
    for c in a {
        let s = match c.sign() {
            num_bigint::Sign::Plus => 1,
            num_bigint::Sign::Minus => -1,
            num_bigint::Sign::NoSign => 0,
        };
        if s != 0 {
            if last != 0 && s != last {
                v += 1;
            }
            last = s;
        }
    }
    v
}

/// In place: `a(x) -> a(x + 1)` (classical $O(n^2)$ additions).
pub(crate) fn taylor_shift_one(a: &mut [BigInt]) {
    let n = a.len();
    if n < 2 {
        return;
    }
    for i in 0..n - 1 {
        for j in (i..n - 1).rev() {
            let t = a[j + 1].clone();
            a[j] += t;
        }
    }
}

/// Descartes bound for the roots of `q` in $(0, 1)$, stopping early at 2.
fn descartes_01(q: &[BigInt]) -> usize {
    let mut b: Vec<BigInt> = q.iter().rev().cloned().collect();
    taylor_shift_one(&mut b);
    variations(&b).min(2)
}

/// `log2` bound `k` with every positive root of `p` below $2^k$ (Fujiwara's bound).
fn positive_root_bound_bits(p: &[BigInt]) -> u64 {
    let n = p.len() - 1;
    let bn = p[n].bits() as i64;
    let mut k: i64 = 0;
    for i in 1..=n {
        let c = &p[n - i];
        if c.is_zero() {
            continue;
        }
        let num = c.bits() as i64 - bn + 1;
        let e = if num <= 0 {
            num / i as i64
        } else {
            (num + i as i64 - 1) / i as i64
        };
        k = k.max(e + 1);
    }
    k.max(0) as u64
}

/// Roots of the square-free `p` (with `p(0) != 0`) in $(0, \infty)$, ascending.
fn isolate_positive(p: &[BigInt], out: &mut Vec<RealRoot>) {
    let n = p.len() - 1;
    if n == 0 {
        return;
    }
    let k = positive_root_bound_bits(p);
    // q(x) = p(2^k x)
    let q: Vec<BigInt> = p
        .iter()
        .enumerate()
        .map(|(i, c)| c << (k as usize * i))
        .collect();
    let q = zp::primitive(&q);
    let scale = Rational::from_integer(BigInt::one() << k as usize);
    // stack of (poly, c, j): interval (c / 2^j, (c + 1) / 2^j) in units of 2^k
    let mut stack: Vec<(Vec<BigInt>, BigInt, u64)> = vec![(q, BigInt::zero(), 0)];
    let mut found: Vec<RealRoot> = vec![];
    while let Some((q, c, j)) = stack.pop() {
        let v = descartes_01(&q);
        if v == 0 {
            continue;
        }
        let den = Rational::from_integer(BigInt::one() << j as usize);
        if v == 1 {
            let lo = Rational::from_integer(c.clone()) / &den * &scale;
            let hi = Rational::from_integer(&c + 1) / &den * &scale;
            found.push(RealRoot { lo, hi });
            continue;
        }
        let d = q.len() - 1;
        // q1(x) = 2^d q(x / 2) on (0, 1/2); q2 = q1(x + 1) on (1/2, 1)
        let q1: Vec<BigInt> = q.iter().enumerate().map(|(i, a)| a << (d - i)).collect();
        let mut q2 = q1.clone();
        taylor_shift_one(&mut q2);
        let c2 = &c << 1usize;
        if q2[0].is_zero() {
            // exact root at the midpoint
            let mid = Rational::from_integer(&c2 + 1)
                / Rational::from_integer(BigInt::one() << (j + 1) as usize)
                * &scale;
            found.push(RealRoot {
                lo: mid.clone(),
                hi: mid,
            });
            q2.remove(0);
        }
        stack.push((zp::primitive(&q2), &c2 + 1, j + 1));
        stack.push((zp::primitive(&q1), c2, j + 1));
    }
    found.sort_by(|a, b| a.lo.cmp(&b.lo));
    out.extend(found);
}

/// Isolates all real roots of a square-free integer polynomial (coefficients low first).
///
/// Returns disjoint [`RealRoot`]s in ascending order; an empty list for constants.
pub fn isolate_real_roots(p: &[BigInt]) -> Vec<RealRoot> {
    let p = zp::trim(p);
    if p.len() <= 1 {
        return vec![];
    }
    let mut p = p.to_vec();
    let mut zero_root = false;
    while p[0].is_zero() {
        p.remove(0);
        zero_root = true;
    }
    let mut neg = vec![];
    let pm: Vec<BigInt> = p
        .iter()
        .enumerate()
        .map(|(i, c)| if i % 2 == 1 { -c } else { c.clone() })
        .collect();
    isolate_positive(&pm, &mut neg);
    let mut out: Vec<RealRoot> = neg
        .into_iter()
        .rev()
        .map(|r| RealRoot {
            lo: -r.hi,
            hi: -r.lo,
        })
        .collect();
    if zero_root {
        out.push(RealRoot {
            lo: Rational::zero(),
            hi: Rational::zero(),
        });
    }
    isolate_positive(&p, &mut out);
    out
}

/// Exact sign of `p(x)` for a rational `x`.
pub fn sign_at(p: &[BigInt], x: &Rational) -> Ordering {
    zp::eval_hom(p, x.numer(), x.denom()).sign_ordering()
}

trait SignOrd {
    fn sign_ordering(&self) -> Ordering;
}
impl SignOrd for BigInt {
    fn sign_ordering(&self) -> Ordering {
        if self.is_positive() {
            Ordering::Greater
        } else if self.is_negative() {
            Ordering::Less
        } else {
            Ordering::Equal
        }
    }
}

/// One bisection step of an open isolating interval of a square-free `p`; returns the new
/// root (possibly an exact point when the midpoint is a root).
pub fn bisect(p: &[BigInt], r: &RealRoot) -> RealRoot {
    if r.is_exact() {
        return r.clone();
    }
    let two = Rational::from_integer(2.into());
    let mid = (&r.lo + &r.hi) / two;
    let sm = sign_at(p, &mid);
    if sm == Ordering::Equal {
        return RealRoot {
            lo: mid.clone(),
            hi: mid,
        };
    }
    // sign of p just right of lo: p(lo), or p'(lo) when lo is a (simple) root listed apart
    let mut sl = sign_at(p, &r.lo);
    if sl == Ordering::Equal {
        sl = sign_at(&zp::derivative(p), &r.lo);
    }
    if sl == sm {
        RealRoot {
            lo: mid,
            hi: r.hi.clone(),
        }
    } else {
        RealRoot {
            lo: r.lo.clone(),
            hi: mid,
        }
    }
}

/// Bisects until the width is at most `width` (a positive rational).
pub fn refine_real(p: &[BigInt], r: &RealRoot, width: &Rational) -> RealRoot {
    let mut r = r.clone();
    while !r.is_exact() && &(&r.hi - &r.lo) > width {
        r = bisect(p, &r);
    }
    r
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::poly::zslice::from_i64s as z;
    #[test]
    fn isolates() {
        // (x^2 - 2)(x - 1/2)(x + 3) x -> times 2
        let p = zp::mul(
            &zp::mul(&z(&[-2, 0, 1]), &z(&[-1, 2])),
            &zp::mul(&z(&[3, 1]), &z(&[0, 1])),
        );
        let rs = isolate_real_roots(&p);
        assert_eq!(rs.len(), 5);
        for w in rs.windows(2) {
            assert!(w[0].hi <= w[1].lo);
        }
        let half = Rational::new(1.into(), 2.into());
        assert!(rs.iter().any(|r| r.lo <= half && half <= r.hi));
        assert!(rs.iter().any(|r| r.is_exact() && r.lo.is_zero()));
        // roots met at a bisection point are exact: x^2 - x = x (x - 1) with bound 2
        assert_eq!(isolate_real_roots(&z(&[0, -1, 1])).len(), 2);
        let t = refine_real(&p, &rs[4], &Rational::new(1.into(), 1000.into()));
        assert!(t.lo < Rational::new(1415.into(), 1000.into()));
        assert!(t.hi > Rational::new(1414.into(), 1000.into()));
        assert!(isolate_real_roots(&z(&[1, 0, 1])).is_empty());
    }
}
