//! Eigenvalue bookkeeping for the Jordan module: factoring the characteristic polynomial
//! over $\mathbb{Q}$ ([`crate::algebraic::factor_q`]), certified roots (isolating
//! intervals and boxes from [`crate::algebraic`]) and exact displays (closed forms up to
//! degree 2, nested radicals for the biquadratic $x^4 + b x^2 + c$, e.g.
//! `i*sqrt(2 - sqrt(3))`).
//!
//! The split into real, purely imaginary and other complex roots is exact (it comes from
//! the isolation); the `f64` approximations are read off regions refined to relative width
//! about $2^{-60}$ and mark the embedding $t \mapsto \theta_j$ of each number field.

use crate::algebraic::AlgebraicNumber;
use crate::error::Result;
use crate::field::{Q, Rational, rational_to_f64};
use crate::poly::Poly;
use num_traits::Signed;
use std::cmp::Ordering;

/// Irreducible monic factors of `p` over $\mathbb{Q}$ with multiplicities (sorted by
/// degree, then coefficients).
///
/// # Errors
/// Those of the factorizer.
pub(crate) fn factor_q(p: &Poly<Q>) -> Result<Vec<(Poly<Q>, usize)>> {
    Ok(crate::algebraic::factor_q(p)?.1)
}

/// The roots of the irreducible monic `p` as certified algebraic numbers
/// ([`AlgebraicNumber::roots_of_irreducible`]: isolating intervals and boxes in exact
/// arithmetic) with their approximations, ordered by real part descending, then imaginary
/// part descending. Real roots have imaginary part exactly `0.0`, purely imaginary roots
/// real part exactly `0.0`, and each pair is exactly conjugate-symmetric in `f64`.
///
/// # Errors
/// `Limit` from complex isolation.
pub(crate) fn certified_roots(p: &Poly<Q>) -> Result<Vec<(AlgebraicNumber, (f64, f64))>> {
    let mut out = vec![];
    for z in AlgebraicNumber::roots_of_irreducible_unchecked(p)? {
        if z.is_real() {
            let (z, x) = real_approx(p, z);
            out.push((z, (x, 0.0)));
            continue;
        }
        let (_, (i0, i1)) = z.bounding_box();
        if (i0 + i1).is_negative() {
            continue; // added with its upper partner
        }
        let (re, im) = z.approx();
        let re = if z.is_pure_imaginary() { 0.0 } else { re };
        out.push((z.conj(), (re, -im)));
        out.push((z, (re, im)));
    }
    out.sort_by(|a, b| b.1.0.total_cmp(&a.1.0).then(b.1.1.total_cmp(&a.1.1)));
    Ok(out)
}

/// A certified `f64` approximation of a real root: Newton in `f64` from the isolating
/// interval, then certified by an exact sign change of `p` on a sub-interval of width a few
/// ulps (which then replaces the isolating interval); bisection to relative width $2^{-62}$
/// ([`AlgebraicNumber::approx`]) when that fails.
fn real_approx(p: &Poly<Q>, z: AlgebraicNumber) -> (AlgebraicNumber, f64) {
    use crate::algebraic::isolate_real::{RealRoot, sign_at};
    use crate::algebraic::number::Loc;
    let Some((lo, hi)) = z.interval() else {
        return (z.clone(), z.approx().0);
    };
    if lo == hi {
        return (z, rational_to_f64(&lo));
    }
    let zp = crate::poly::zslice::from_poly_q(p);
    let c: Vec<f64> = zp
        .iter()
        .map(|x| num_traits::ToPrimitive::to_f64(x).unwrap_or(f64::NAN))
        .collect();
    let (flo, fhi) = (rational_to_f64(&lo), rational_to_f64(&hi));
    let mut x = 0.5 * (flo + fhi);
    for _ in 0..60 {
        let (mut v, mut d) = (0.0f64, 0.0f64);
        for ck in c.iter().rev() {
            d = d * x + v;
            v = v * x + ck;
        }
        let step = v / d;
        if !step.is_finite() {
            break;
        }
        let nx = (x - step).clamp(flo, fhi);
        if nx == x {
            break;
        }
        x = nx;
    }
    let delta = (x.abs() * 2f64.powi(-50)).max(f64::MIN_POSITIVE);
    let q = |v: f64| Rational::from_float(v);
    if let (Some(a), Some(b)) = (q(x - delta), q(x + delta)) {
        let (sa, sb) = (sign_at(&zp, &a), sign_at(&zp, &b));
        if a > lo && b < hi && sa != Ordering::Equal && sb != Ordering::Equal && sa != sb {
            let tight =
                AlgebraicNumber::from_parts(p.clone(), Loc::Real(RealRoot { lo: a, hi: b }));
            return (tight, x);
        }
    }
    (z.clone(), z.approx().0)
}

pub(crate) use crate::algebraic::digits::quadratic_roots;
pub(crate) use crate::field::radical_text;

#[cfg(test)]
mod tests {
    use super::*;
    fn p(cs: &[i64]) -> Poly<Q> {
        Poly::from_i64s(cs)
    }
    #[test]
    fn certified_roots_displays() {
        let kinds = |q: &Poly<Q>| -> (usize, usize) {
            let rs = certified_roots(q).unwrap();
            (
                rs.iter().filter(|z| z.1.1 == 0.0).count(),
                rs.iter().filter(|z| z.1.0 == 0.0 && z.1.1 != 0.0).count(),
            )
        };
        assert_eq!(kinds(&p(&[1, 0, 4, 0, 1])), (0, 4));
        assert_eq!(kinds(&p(&[-2, 0, 0, 1])), (1, 0));
        assert_eq!(kinds(&p(&[1, 0, -4, 0, 1])), (4, 0));
        let rs = certified_roots(&p(&[1, 1, 0, 0, 1])).unwrap();
        assert_eq!(rs.len(), 4);
        for w in rs.chunks(2) {
            assert_eq!(w[0].1.0, w[1].1.0);
            assert_eq!(w[0].1.1, -w[1].1.1);
            assert!(w[0].1.1 > 0.0 && w[0].0 == w[1].0.conj());
        }
        let f = p(&[-1, 2])
            .pow(2)
            .mul(&p(&[1, 0, 1]))
            .mul(&p(&[3, 1]))
            .monic();
        let shown: Vec<String> = factor_q(&f)
            .unwrap()
            .iter()
            .map(|(g, e)| format!("({g})^{e}"))
            .collect();
        assert_eq!(shown.len(), 3, "{shown:?}");
        assert!(shown.contains(&"(x - 1/2)^2".to_string()));
    }
}
