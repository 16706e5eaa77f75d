//! The exact real field $F = \mathbb{Q}(\operatorname{Re}\theta, \operatorname{Im}\theta)$
//! of a non-real algebraic number $\theta = a + b i$, with $a$ and $b$ as elements of $F$.
//!
//! # Construction (primitive element)
//! Let $p$ be the minimal polynomial of $\theta$ (roots $\theta_1, \dots, \theta_d$) and
//! $w = (1 - k i)/2$ for a small integer $k \ne 0$. Then
//! $$c = w\theta + \bar w \bar\theta = a + k b \in \mathbb{R}$$
//! is a root of
//! $$P_k(x) = \prod_{j, l} \big(x - w\theta_j - \bar w \theta_l\big) \in \mathbb{Q}[x],$$
//! (the set of roots is closed under conjugation since $\{\theta_j\}$ is), computed from
//! Newton power sums: $\sum_{j,l} (w\theta_j + \bar w\theta_l)^n = \sum_m \binom nm
//! \operatorname{Re}(w^m \bar w^{n-m}) s_m s_{n-m}$. The diagonal $j = l$ gives back
//! $\theta_j$ ($w + \bar w = 1$), so $p \mid P_k$. $k$ runs over $1, -1, 2, -2, \dots$ until
//! $P_k$ is square-free; then $c$ *separates*: $c = w\theta_j + \bar w\theta_l$ only for
//! $\theta_j = \theta$, $\theta_l = \bar\theta$.
//!
//! The minimal polynomial $g$ of $c$ is the irreducible factor of $P_k$ having $c$ as a
//! real root, identified with certified intervals (the box of $\theta$ maps to an interval
//! of $a + k b$; candidate roots are refined until one is left). With $F = \mathbb{Q}[c]/(g)$
//! (real embedding at $c$) and $\bar\theta = (c - w\theta)/\bar w$:
//! $$\gcd_{F(i)[y]}\big(p(y),\ p((c - w y)/\bar w)\big) = y - \theta,$$
//! linear by separation. This writes $\theta = a(c) + b(c)\, i$ exactly, and
//! $\mathbb{Q}(c) = \mathbb{Q}(a, b)$ since $c = a + k b$. The result is checked:
//! $p(a + b i) = 0$ in $F(i)$ and $b \ne 0$.
//!
//! A field of degree 2 is shown with its radical ($\mathbb{Q}(\sqrt f)$), degree 1 as
//! $\mathbb{Q}$.
//!
//! | entry point | computes |
//! |---|---|
//! | [`real_parts_field`] | $(F, a, b)$ for a non-real algebraic $\theta$ |
//! | [`identify_real_root`] | the real root of one of several polynomials equal to a linear form in $\operatorname{Re}, \operatorname{Im}$ of $\theta$ |

use super::primary::{named_field, rational_field};
use super::roots::quadratic_roots;
use super::{quadratic_field, quadratic_image};
use crate::algebraic::AlgebraicNumber;
use crate::algebraic::isolate_real::isolate_real_roots;
use crate::algebraic::number::Loc;
use crate::algebraic::zp;
use crate::error::{Error, Result};
use crate::field::{ComplexField, ComplexPair, Field, NfElem, NumberField, Q, Rational};
use crate::poly::Poly;
use num_traits::{One, Zero};

/// A real field with the real and imaginary parts of one root.
#[derive(Clone, Debug)]
pub(crate) struct RealParts {
    pub field: NumberField,
    pub re: NfElem,
    pub im: NfElem,
    /// The primitive element's minimal polynomial and $k$ ($c = a + k b$); `None` when the
    /// field is given by another construction.
    pub primitive: Option<(Poly<Q>, i64)>,
}

/// Power sums $s_0, \dots, s_N$ of the roots of a monic `p` (Newton's identities).
fn power_sums(p: &Poly<Q>, upto: usize) -> Vec<Rational> {
    let d = p.deg();
    let a = |i: usize| p.coeff(i);
    let mut s = vec![Rational::from_integer(d.into())];
    for n in 1..=upto {
        let mut v = if n <= d {
            a(d - n) * Rational::from_integer(n.into())
        } else {
            Rational::zero()
        };
        for i in 1..n.min(d + 1) {
            v += a(d - i) * &s[n - i];
        }
        s.push(-v);
    }
    s
}

/// The monic polynomial of degree `n` with power sums `s[1..=n]`.
fn from_power_sums(s: &[Rational], n: usize) -> Poly<Q> {
    let mut e = vec![Rational::one()];
    for k in 1..=n {
        let mut v = Rational::zero();
        for i in 1..=k {
            let t = &e[k - i] * &s[i];
            if i % 2 == 1 { v += t } else { v -= t }
        }
        e.push(v / Rational::from_integer(k.into()));
    }
    let mut c = vec![Rational::zero(); n + 1];
    for k in 0..=n {
        c[n - k] = if k % 2 == 0 { e[k].clone() } else { -&e[k] };
    }
    Poly::new(Q, c)
}

/// Gaussian rational product.
fn gmul(x: &(Rational, Rational), y: &(Rational, Rational)) -> (Rational, Rational) {
    (&x.0 * &y.0 - &x.1 * &y.1, &x.0 * &y.1 + &x.1 * &y.0)
}

/// $P_k(x) = \prod_{j,l} (x - w\theta_j - \bar w\theta_l)$, $w = (1 - k i)/2$ (degree $d^2$).
pub(crate) fn composed_primitive(p: &Poly<Q>, k: i64) -> Poly<Q> {
    let p = p.monic();
    let big = p.deg() * p.deg();
    let s = power_sums(&p, big);
    let half = Rational::new(1.into(), 2.into());
    let w = (half.clone(), Rational::from_integer((-k).into()) * &half);
    // powers w^m
    let mut wp = vec![(Rational::one(), Rational::zero())];
    for m in 1..=big {
        let next = gmul(&wp[m - 1], &w);
        wp.push(next);
    }
    let mut t = vec![Rational::from_integer(big.into())];
    let mut binom = vec![Rational::one()];
    for n in 1..=big {
        // binomial row n
        let mut row = vec![Rational::one(); n + 1];
        for j in 1..n {
            row[j] = &binom[j - 1] + &binom[j];
        }
        binom = row;
        let mut v = Rational::zero();
        for m in 0..=n {
            // Re(w^m conj(w)^(n-m)) = Re(w^m) Re(w^(n-m)) + Im(w^m) Im(w^(n-m))
            let (a, b) = (&wp[m], &wp[n - m]);
            let re = &a.0 * &b.0 + &a.1 * &b.1;
            if re.is_zero() || s[m].is_zero() || s[n - m].is_zero() {
                continue;
            }
            v += &binom[m] * re * &s[m] * &s[n - m];
        }
        t.push(v);
    }
    from_power_sums(&t, big)
}

/// Among the real roots of the irreducible `factors`, the one equal to
/// $x = \alpha \operatorname{Re}\theta + \beta \operatorname{Im}\theta$ (which must be a
/// root of one of them): candidates are isolated exactly and refined together with the box
/// of $\theta$ until one candidate interval meets the image of the box.
///
/// # Errors
/// `Verification` when no candidate is left (the value is not a root of the factors);
/// `Limit` from complex refinement.
pub(crate) fn identify_real_root(
    factors: &[Poly<Q>],
    theta: &AlgebraicNumber,
    alpha: &Rational,
    beta: &Rational,
) -> Result<(Poly<Q>, AlgebraicNumber)> {
    let mut cands: Vec<(Poly<Q>, AlgebraicNumber)> = vec![];
    for f in factors {
        if f.deg() == 1 {
            cands.push((f.clone(), AlgebraicNumber::from_rational(&-f.coeff(0))));
            continue;
        }
        for r in isolate_real_roots(&zp::from_poly_q(f)) {
            cands.push((
                f.clone(),
                AlgebraicNumber::from_parts(f.clone(), Loc::Real(r)),
            ));
        }
    }
    let half = Rational::new(1.into(), 2.into());
    let mut th = theta.clone();
    for _ in 0..4000 {
        let ((r0, r1), (i0, i1)) = th.bounding_box();
        let lin = |re: &Rational, im: &Rational| alpha * re + beta * im;
        let xs = [lin(&r0, &i0), lin(&r0, &i1), lin(&r1, &i0), lin(&r1, &i1)];
        let lo = xs.iter().min().cloned().unwrap_or_default();
        let hi = xs.iter().max().cloned().unwrap_or_default();
        let w = &hi - &lo;
        let mut keep = vec![];
        for (f, c) in cands {
            let c = match c.interval() {
                Some((a, b)) if &b - &a > &w * &half && !w.is_zero() => c.refined(&(&w * &half))?,
                _ => c,
            };
            let (cl, ch) = c.interval().unwrap_or_default();
            if !(ch < lo || cl > hi) {
                keep.push((f, c));
            }
        }
        cands = keep;
        match cands.len() {
            0 => break,
            1 => return Ok(cands.pop().expect("one candidate")),
            _ => {}
        }
        let bw = (&r1 - &r0).max(&i1 - &i0);
        th = th.refined(&(bw * Rational::new(1.into(), 16.into())))?;
    }
    Err(Error::Verification(format!(
        "linear form of the parts of a root of {} not found among the candidate roots",
        theta.minpoly()
    )))
}

/// $(F, a, b)$ with $F$ real, $\theta = a + b i$, for a non-real algebraic `theta` (see the
/// module docs); `var` names the primitive element in displays.
///
/// # Errors
/// `Invalid` for a real `theta`; `Limit` when no separating $k$ is found in $|k| \le 64$ or
/// refinement fails; `Verification` if a checked identity fails.
pub(crate) fn real_parts_field(theta: &AlgebraicNumber, var: &str) -> Result<RealParts> {
    if theta.is_real() {
        return Err(Error::Invalid(format!(
            "real parts field of a real number (root of {})",
            theta.minpoly()
        )));
    }
    let p = theta.minpoly().clone();
    for step in 0..128i64 {
        let k = if step % 2 == 0 {
            step / 2 + 1
        } else {
            -(step / 2 + 1)
        };
        let pk = composed_primitive(&p, k);
        if !pk.gcd(&pk.derivative()).is_one() {
            continue;
        }
        let (_, facs) = crate::algebraic::factor_q(&pk)?;
        let facs: Vec<Poly<Q>> = facs
            .into_iter()
            .map(|(f, _)| f)
            .filter(|f| *f != p)
            .collect();
        let (g, c) = identify_real_root(
            &facs,
            theta,
            &Rational::one(),
            &Rational::from_integer(k.into()),
        )?;
        let croot = c.approx().0;
        let f = named_field(&g, (croot, 0.0), var);
        let Some((re, im)) = parts_by_gcd(&p, &f, k) else {
            continue;
        };
        let parts = simplify(RealParts {
            field: f,
            re,
            im,
            primitive: Some((g, k)),
        });
        check_parts(&p, &parts)?;
        // the marked embedding carries (a, b) to the parts of this root
        let (ta, tb) = theta.approx();
        let (fa, _) = parts.field.approx(&parts.re);
        let (fb, _) = parts.field.approx(&parts.im);
        let tol = 1e-6 * (1.0 + ta.abs() + tb.abs());
        if (fa - ta).abs() > tol || (fb - tb).abs() > tol {
            return Err(Error::Verification(format!(
                "the real field of a root of {p} is marked at another root"
            )));
        }
        return Ok(parts);
    }
    Err(Error::Limit(format!(
        "no separating primitive element a + k b found for a root of {p}"
    )))
}

/// $\theta$ from the linear $\gcd_{F(i)}(p(y), p((c - w y)/\bar w))$.
fn parts_by_gcd(p: &Poly<Q>, f: &NumberField, k: i64) -> Option<(NfElem, NfElem)> {
    let cf = ComplexField::new(f.clone());
    let q = |x: &Rational| f.from_rational(x);
    let half = Rational::new(1.into(), 2.into());
    let w = ComplexPair {
        re: q(&half),
        im: q(&(Rational::from_integer((-k).into()) * &half)),
    };
    let wbar = cf.conj(&w).expect("conjugation");
    let wbar_inv = cf.inv(&wbar)?;
    let c = cf.from_base(&f.generator());
    // L(y) = c / wbar - (w / wbar) y
    let lin = Poly::new(
        cf.clone(),
        vec![cf.mul(&c, &wbar_inv), cf.neg(&cf.mul(&w, &wbar_inv))],
    );
    let pc = p.map(&cf, |x| cf.from_rational(x));
    let h = pc.gcd(&pc.compose(&lin));
    if h.deg() != 1 {
        return None;
    }
    let theta = cf.neg(&cf.mul(&h.coeff(0), &cf.inv(&h.coeff(1))?));
    Some((theta.re, theta.im))
}

/// Degree 1 and 2 fields in their usual presentation ($\mathbb{Q}$, $\mathbb{Q}(\sqrt f)$).
pub(crate) fn simplify(parts: RealParts) -> RealParts {
    let f = &parts.field;
    match f.degree() {
        1 => {
            let k = rational_field();
            let to = |x: &NfElem| k.from_rational(&f.to_rational(x).unwrap_or_default());
            RealParts {
                re: to(&parts.re),
                im: to(&parts.im),
                field: k.clone(),
                primitive: parts.primitive,
            }
        }
        2 => {
            let Some((a0, s, fd)) = quadratic_roots(f.modulus()) else {
                return parts;
            };
            // the marked root is a0 + s sqrt(fd) or a0 - s sqrt(fd)
            let positive = f.root_approx().0 > crate::field::rational_to_f64(&a0);
            let s = if positive { s } else { -s };
            let k = quadratic_field(&fd);
            RealParts {
                re: quadratic_image(&parts.re, &a0, &s),
                im: quadratic_image(&parts.im, &a0, &s),
                field: k,
                primitive: parts.primitive,
            }
        }
        _ => parts,
    }
}

/// $p(a + b i) = 0$ in $F(i)$ and $b \ne 0$.
fn check_parts(p: &Poly<Q>, parts: &RealParts) -> Result<()> {
    let f = &parts.field;
    let cf = ComplexField::new(f.clone());
    let theta = ComplexPair {
        re: parts.re.clone(),
        im: parts.im.clone(),
    };
    let mut acc = cf.zero();
    for c in p.coeffs().iter().rev() {
        acc = cf.add(&cf.mul(&acc, &theta), &cf.from_rational(c));
    }
    if !cf.is_zero(&acc) || f.is_zero(&parts.im) {
        return Err(Error::Verification(format!(
            "real and imaginary parts of a root of {p} do not satisfy it"
        )));
    }
    Ok(())
}
