//! Kernels of $\mathbb{Q}\[t\]/(m)$ the generic [`super::Ext`] runs when its base is
//! $\mathbb{Q}$: the exact index of the marked root among the isolated roots of $m$, and the
//! product of two elements modulo an integral $m$ in integers (one division at the end).

use super::AlgebraicNumber;
use crate::field::{Q, Rational, lehmer};
use crate::poly::Poly;
use num_bigint::BigInt;
use num_traits::{One, Zero};

/// Index of the root of the irreducible `m` nearest `root` among its exactly isolated roots
/// ([`AlgebraicNumber::roots_of_irreducible`], canonical order). `None` when the isolation
/// fails (budget) or two roots are equally near.
pub(super) fn marked_root_index(m: &Poly<Q>, (xr, xi): (f64, f64)) -> Option<usize> {
    let roots = AlgebraicNumber::roots_of_irreducible(m).ok()?;
    let d: Vec<f64> = roots
        .iter()
        .map(|z| {
            let (a, b) = z.approx();
            (a - xr).hypot(b - xi)
        })
        .collect();
    let best = (0..d.len()).min_by(|&i, &j| d[i].total_cmp(&d[j]))?;
    let unique = (0..d.len()).all(|j| j == best || d[j] > d[best]);
    unique.then_some(best)
}

/// `a * b` modulo an integral monic `m` (coefficients low degree first): $(s_a a)(s_b b)$
/// with the lcms $s_a, s_b$ of the denominators is an integer polynomial, reduced modulo $m$
/// in integers, and each coefficient is divided by $s_a s_b$ once (one Lehmer gcd), instead
/// of normalising a rational after every multiply-add.
pub(super) fn mul_integral(m: &[Rational], a: &[Rational], b: &[Rational]) -> Vec<Rational> {
    let (sa, ia) = integer_scaled(a);
    let (sb, ib) = integer_scaled(b);
    let mut v = vec![BigInt::zero(); ia.len() + ib.len() - 1];
    for (i, x) in ia.iter().enumerate() {
        if x.is_zero() {
            continue;
        }
        for (j, y) in ib.iter().enumerate() {
            if !y.is_zero() {
                v[i + j] += x * y;
            }
        }
    }
    let d = m.len() - 1;
    while v.len() > d {
        let c = v.pop().expect("longer than d");
        if c.is_zero() {
            continue;
        }
        let off = v.len() - d;
        for (j, mj) in m.iter().enumerate().take(d) {
            if !mj.is_zero() {
                v[off + j] -= &c * mj.numer();
            }
        }
    }
    while v.last().is_some_and(|c| c.is_zero()) {
        v.pop();
    }
    let den = sa * sb;
    v.into_iter().map(|x| lehmer::fraction(x, &den)).collect()
}

/// The lcm $s$ of the denominators of `xs` and the integers $s x$.
fn integer_scaled(xs: &[Rational]) -> (BigInt, Vec<BigInt>) {
    let mut s = BigInt::one();
    for x in xs {
        if !x.denom().is_one() {
            let g = lehmer::gcd(&s, x.denom());
            s = &s / g * x.denom();
        }
    }
    let v = xs
        .iter()
        .map(|x| {
            if x.denom().is_one() {
                x.numer() * &s
            } else {
                x.numer() * (&s / x.denom())
            }
        })
        .collect();
    (s, v)
}
