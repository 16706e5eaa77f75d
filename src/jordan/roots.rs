//! Eigenvalue bookkeeping for the Jordan module: factoring the characteristic polynomial
//! over $\mathbb{Q}$ ([`crate::algebraic::factor_q`]), exact real-root counts (Sturm),
//! root approximations (Aberth–Ehrlich in `f64`, refined by Newton) and exact displays
//! (closed forms up to degree 2, nested radicals for the biquadratic $x^4 + b x^2 + c$,
//! e.g. `i*sqrt(2 - sqrt(3))`).
//!
//! The split into real and complex roots is exact (Sturm count); the approximations only
//! tell the roots apart and mark the embedding $t \mapsto \theta_j$ of each number field
//! (every identity that depends on them is verified exactly afterwards). Certified
//! isolating regions are available on demand through
//! [`super::Eigenvalue::algebraic_number`]; they are not on the hot path because complex
//! isolation of some cubics is slow at present.

use crate::error::Result;
use crate::field::quadratic::fmt_pair;
use crate::field::{Field, Q, QuadraticField, Rational, rational_to_f64};
use crate::poly::Poly;
use num_bigint::BigInt;
use num_complex::Complex64;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;

/// Irreducible monic factors of `p` over $\mathbb{Q}$ with multiplicities (sorted by
/// degree, then coefficients).
///
/// # Errors
/// Those of the factorizer.
pub(crate) fn factor_q(p: &Poly<Q>) -> Result<Vec<(Poly<Q>, usize)>> {
    Ok(crate::algebraic::factor_q(p)?.1)
}

/// Number of distinct real roots of a square-free `p` (Sturm's theorem).
pub(crate) fn real_root_count(p: &Poly<Q>) -> usize {
    if p.deg() == 0 {
        return 0;
    }
    let mut seq = vec![p.clone(), p.derivative()];
    while !seq.last().unwrap().is_zero() && seq.last().unwrap().deg() > 0 {
        let n = seq.len();
        let r = seq[n - 2].rem(&seq[n - 1]).neg();
        if r.is_zero() {
            break;
        }
        seq.push(r);
    }
    let variations = |signs: Vec<Ordering>| {
        let s: Vec<Ordering> = signs
            .into_iter()
            .filter(|o| *o != Ordering::Equal)
            .collect();
        s.windows(2).filter(|w| w[0] != w[1]).count()
    };
    let at_pos: Vec<Ordering> = seq.iter().map(|q| q.lc().cmp(&Rational::zero())).collect();
    let at_neg: Vec<Ordering> = seq
        .iter()
        .map(|q| {
            let s = q.lc().cmp(&Rational::zero());
            if q.deg() % 2 == 1 { s.reverse() } else { s }
        })
        .collect();
    variations(at_neg) - variations(at_pos)
}

/// Approximations of all complex roots of `p` (Aberth–Ehrlich iteration, then Newton).
pub(crate) fn approx_roots(p: &Poly<Q>) -> Vec<Complex64> {
    let n = p.deg();
    if n == 0 {
        return vec![];
    }
    let lc = rational_to_f64(&p.lc());
    let c: Vec<f64> = p.coeffs().iter().map(|x| rational_to_f64(x) / lc).collect();
    if n == 1 {
        return vec![Complex64::new(0.0 - c[0], 0.0)];
    }
    let eval = |z: Complex64| {
        let mut v = Complex64::new(0.0, 0.0);
        let mut d = Complex64::new(0.0, 0.0);
        for k in (0..=n).rev() {
            d = d * z + v;
            v = v * z + c[k];
        }
        (v, d)
    };
    let radius = 1.0 + c[..n].iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let r0 = radius.min(
        c[..n]
            .iter()
            .enumerate()
            .map(|(k, x)| x.abs().powf(1.0 / (n - k) as f64))
            .fold(0.0f64, f64::max)
            * 2.0
            + 1e-3,
    );
    let mut z: Vec<Complex64> = (0..n)
        .map(|k| Complex64::from_polar(r0, 0.4 + 2.0 * std::f64::consts::PI * k as f64 / n as f64))
        .collect();
    for _ in 0..800 {
        let mut moved = 0.0f64;
        for i in 0..n {
            let (v, d) = eval(z[i]);
            if v.norm() == 0.0 {
                continue;
            }
            let ratio = v / d;
            let s: Complex64 = (0..n)
                .filter(|&j| j != i)
                .map(|j| Complex64::new(1.0, 0.0) / (z[i] - z[j]))
                .sum();
            let w = ratio / (Complex64::new(1.0, 0.0) - ratio * s);
            if w.is_finite() {
                z[i] -= w;
                moved = moved.max(w.norm() / (1.0 + z[i].norm()));
            }
        }
        if moved < 1e-16 {
            break;
        }
    }
    for zi in z.iter_mut() {
        for _ in 0..3 {
            let (v, d) = eval(*zi);
            if d.norm() > 0.0 {
                let step = v / d;
                if step.is_finite() {
                    *zi -= step;
                }
            }
        }
    }
    z
}

/// Roots of an irreducible `p` ordered (real part descending, then imaginary part
/// descending), with the exactly known number of real roots made exactly real and the
/// complex ones made exactly conjugate-symmetric.
pub(crate) fn ordered_roots(p: &Poly<Q>) -> Vec<(f64, f64)> {
    let nreal = real_root_count(p);
    let mut z = approx_roots(p);
    z.sort_by(|a, b| a.im.abs().total_cmp(&b.im.abs()));
    let mut out: Vec<(f64, f64)> = vec![];
    for (i, w) in z.iter().enumerate() {
        if i < nreal {
            out.push((w.re, 0.0));
        }
    }
    let mut cx: Vec<Complex64> = z[nreal..].to_vec();
    cx.sort_by(|a, b| b.im.total_cmp(&a.im));
    let half = cx.len() / 2;
    let (up, down) = cx.split_at(half);
    let mut down: Vec<Complex64> = down.to_vec();
    for u in up {
        // partner: nearest to the conjugate
        let (k, _) = down
            .iter()
            .enumerate()
            .map(|(k, d)| (k, (d - u.conj()).norm()))
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .expect("conjugate partner");
        let d = down.remove(k);
        let re = 0.5 * (u.re + d.re);
        let im = 0.5 * (u.im - d.im).abs();
        out.push((re, im));
        out.push((re, -im));
    }
    // all roots on the imaginary axis (exactly: p even and p(ix) has only real roots)
    let even = p
        .coeffs()
        .iter()
        .enumerate()
        .all(|(k, c)| k % 2 == 0 || c.is_zero());
    if even && nreal == 0 {
        let r = Poly::new(
            Q,
            p.coeffs()
                .iter()
                .enumerate()
                .map(|(k, c)| if (k / 2) % 2 == 0 { c.clone() } else { -c })
                .collect(),
        );
        if real_root_count(&r) == p.deg() {
            for z in out.iter_mut() {
                z.0 = 0.0;
            }
        }
    }
    out.sort_by(|a, b| b.0.total_cmp(&a.0).then(b.1.total_cmp(&a.1)));
    out
}

/// Radical text for $\sqrt f$ (`i` for $f = -1$).
pub(crate) fn radical_text(f: &BigInt) -> String {
    if *f == BigInt::from(-1) {
        "i".into()
    } else if f.is_negative() {
        format!("sqrt({})*i", -f)
    } else {
        format!("sqrt({f})")
    }
}

/// For a monic quadratic $x^2 + b x + c$: roots $a_0 \pm s\sqrt f$ as `(a0, s, f)` with
/// `s > 0` and `f` square-free (`None` when the roots are rational).
pub(crate) fn quadratic_roots(p: &Poly<Q>) -> Option<(Rational, Rational, BigInt)> {
    let b = p.coeff(1);
    let c = p.coeff(0);
    let half = Rational::new(1.into(), 2.into());
    let a0 = -&b * &half;
    let disc4 = &a0 * &a0 - c; // (b^2 - 4c)/4
    let (field, _, s) = QuadraticField::sqrt_of_rational(&disc4);
    field.map(|k| (a0, s, k.d().clone()))
}

/// Exact display of the root of the irreducible `p` nearest `approx`.
pub(crate) fn value_string(p: &Poly<Q>, approx: (f64, f64)) -> String {
    match p.deg() {
        1 => Q.fmt_elem(&-p.coeff(0)),
        2 => {
            let (a0, s, f) = quadratic_roots(p).expect("irreducible quadratic");
            let positive = if f.is_negative() {
                approx.1 > 0.0
            } else {
                approx.0 > rational_to_f64(&a0)
            };
            let coef = if positive { s } else { -s };
            fmt_pair(&a0, &coef, &radical_text(&f))
        }
        4 if p.coeff(1).is_zero() && p.coeff(3).is_zero() => {
            // theta^2 = u with u a root of y^2 + b y + c
            let q = Poly::new(Q, vec![p.coeff(0), p.coeff(2), Rational::one()]);
            match quadratic_roots(&q) {
                Some((a0, s, f)) if f.is_positive() => {
                    let z = Complex64::new(approx.0, approx.1);
                    let u = z * z;
                    let coef = if u.re > rational_to_f64(&a0) { s } else { -s };
                    let u_pos = u.re > 0.0;
                    let sign_neg = if u_pos {
                        approx.0 < 0.0
                    } else {
                        approx.1 < 0.0
                    };
                    let (ua, ub) = if u_pos { (a0, coef) } else { (-a0, -coef) };
                    let inner = fmt_pair(&ua, &ub, &radical_text(&f));
                    let body = if u_pos {
                        format!("sqrt({inner})")
                    } else {
                        format!("i*sqrt({inner})")
                    };
                    if sign_neg { format!("-{body}") } else { body }
                }
                _ => root_of(p, approx),
            }
        }
        _ => root_of(p, approx),
    }
}

fn root_of(p: &Poly<Q>, approx: (f64, f64)) -> String {
    format!("root of {p} near {}", fmt_approx(approx))
}

/// `1.2345678901` or `-1.2 + 0.5*i`.
pub(crate) fn fmt_approx((re, im): (f64, f64)) -> String {
    if im == 0.0 {
        format!("{re:.10}")
    } else if im > 0.0 {
        format!("{re:.10} + {im:.10}*i")
    } else {
        format!("{re:.10} - {:.10}*i", -im)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    fn p(cs: &[i64]) -> Poly<Q> {
        Poly::from_i64s(cs)
    }
    #[test]
    fn sturm_roots_displays() {
        assert_eq!(real_root_count(&p(&[1, 0, 4, 0, 1])), 0);
        assert_eq!(real_root_count(&p(&[-2, 0, 0, 1])), 1);
        assert_eq!(real_root_count(&p(&[1, 0, -4, 0, 1])), 4);
        let vs = |q: &Poly<Q>| -> Vec<String> {
            ordered_roots(q)
                .iter()
                .map(|z| value_string(q, *z))
                .collect()
        };
        assert_eq!(vs(&p(&[2, 2, 1])), ["-1 + i", "-1 - i"]);
        let v = vs(&p(&[1, 0, 4, 0, 1]));
        assert!(v.contains(&"i*sqrt(2 - sqrt(3))".to_string()), "{v:?}");
        assert!(v.contains(&"-i*sqrt(2 + sqrt(3))".to_string()), "{v:?}");
        let v = vs(&p(&[1, 0, -4, 0, 1]));
        assert!(v.contains(&"-sqrt(2 + sqrt(3))".to_string()), "{v:?}");
        assert_eq!(vs(&p(&[-1, -1, 1])), ["1/2 + sqrt(5)/2", "1/2 - sqrt(5)/2"]);
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
