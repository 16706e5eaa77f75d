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
//! (real embedding at $c$), $\theta$ is a rational function of $c$ (Lagrange
//! interpolation over the roots of $P_k$):
//! $$\theta = \frac{H_k(c)}{P_k'(c)}, \qquad H_k(x) = \sum_{j,l} \theta_j
//! \frac{P_k(x)}{x - c_{jl}} \in \mathbb{Q}(i)[x],$$
//! where $P_k - \varepsilon H_k = \prod (x - c_{jl} - \varepsilon\theta_j)$ comes from the
//! same power sums over the dual numbers $\mathbb{Q}(i)[\varepsilon]/(\varepsilon^2)$
//! (the weight $w$ becomes $w + \varepsilon$). Splitting $H_k = H_r + i H_i$ gives
//! $a = H_r(c)/P_k'(c)$, $b = H_i(c)/P_k'(c)$ in $F$, and $\mathbb{Q}(c) =
//! \mathbb{Q}(a, b)$ since $c = a + k b$. The result is checked exactly: $p(a + b i) = 0$
//! in $F(i)$ and $b \ne 0$ (and the marked embedding of $F$ sends $a + b i$ to $\theta$).
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
use crate::algebraic::{NfElem, NumberField};
use crate::error::{Error, Result};
use crate::field::{ComplexField, ComplexPair, Field, Q, Rational};
use crate::poly::Poly;
use num_traits::{One, Signed, Zero};

/// A real field with the real and imaginary parts of one root.
#[derive(Clone, Debug)]
pub(crate) struct RealParts {
    pub field: NumberField,
    pub re: NfElem,
    pub im: NfElem,
    /// The primitive element's minimal polynomial and $k$ ($c = a + k b$); `None` when the
    /// field is given by another construction.
    pub primitive: Option<(Poly<Q>, i64)>,
    /// $\theta^0, \dots, \theta^{d-1}$ in $F(i)$ once checked ([`theta_powers`]).
    pub powers: Vec<ComplexPair<NfElem>>,
}

/// A Gaussian rational $x + y i$.
type G = (Rational, Rational);

fn gmul(x: &G, y: &G) -> G {
    (&x.0 * &y.0 - &x.1 * &y.1, &x.0 * &y.1 + &x.1 * &y.0)
}
fn gadd(x: &G, y: &G) -> G {
    (&x.0 + &y.0, &x.1 + &y.1)
}
fn gscale(x: &G, q: &Rational) -> G {
    (&x.0 * q, &x.1 * q)
}

/// A dual number $u + \varepsilon v$ ($\varepsilon^2 = 0$) over the Gaussian rationals.
#[derive(Clone)]
struct Dual(G, G);

impl Dual {
    fn mul(&self, o: &Dual) -> Dual {
        Dual(
            gmul(&self.0, &o.0),
            gadd(&gmul(&self.0, &o.1), &gmul(&self.1, &o.0)),
        )
    }
    fn add(&self, o: &Dual) -> Dual {
        Dual(gadd(&self.0, &o.0), gadd(&self.1, &o.1))
    }
    fn scale(&self, q: &Rational) -> Dual {
        Dual(gscale(&self.0, q), gscale(&self.1, q))
    }
}

/// $P_k(x) = \prod_{j,l} (x - c_{jl})$, $c_{jl} = w\theta_j + \bar w\theta_l$,
/// $w = (1 - k i)/2$ (degree $d^2$, rational), and $H_k(x) = \sum_{j,l} \theta_j
/// P_k(x)/(x - c_{jl})$ as real and imaginary parts $(H_r, H_i)$, so that
/// $\theta_j = H_k(c_{jl}) / P_k'(c_{jl})$ when $P_k$ is square-free.
///
/// Both come from one Newton recurrence over dual numbers: $Q_\varepsilon(x) = \prod (x -
/// c_{jl} - \varepsilon\theta_j) = P_k - \varepsilon H_k$ has power sums
/// $\sum_m \binom nm (w + \varepsilon)^m \bar w^{n-m} s_m s_{n-m}$.
pub(crate) fn composed_primitive(p: &Poly<Q>, k: i64) -> (Poly<Q>, Poly<Q>, Poly<Q>) {
    let p = p.monic();
    let big = p.deg() * p.deg();
    let s = crate::poly::newton_power_sums(&p, big);
    let zero = || (Rational::zero(), Rational::zero());
    let half = Rational::new(1.into(), 2.into());
    let w: G = (half.clone(), Rational::from_integer((-k).into()) * &half);
    let mut wp: Vec<G> = vec![(Rational::one(), Rational::zero())];
    for m in 1..=big {
        let next = gmul(&wp[m - 1], &w);
        wp.push(next);
    }
    let conj = |x: &G| (x.0.clone(), -&x.1);
    // power sums T_n(eps)
    let mut t: Vec<Dual> = vec![Dual(
        (Rational::from_integer(big.into()), Rational::zero()),
        zero(),
    )];
    let mut binom = vec![Rational::one()];
    for n in 1..=big {
        let mut row = vec![Rational::one(); n + 1];
        for j in 1..n {
            row[j] = &binom[j - 1] + &binom[j];
        }
        binom = row;
        let mut acc = Dual(zero(), zero());
        for m in 0..=n {
            if s[m].is_zero() || s[n - m].is_zero() {
                continue;
            }
            let c = &binom[m] * &s[m] * &s[n - m];
            let wb = conj(&wp[n - m]);
            let u = gmul(&wp[m], &wb);
            let v = if m == 0 {
                zero()
            } else {
                gscale(&gmul(&wp[m - 1], &wb), &Rational::from_integer(m.into()))
            };
            acc = acc.add(&Dual(u, v).scale(&c));
        }
        t.push(acc);
    }
    // elementary symmetric functions (Newton's identities over the dual numbers)
    let mut e = vec![Dual((Rational::one(), Rational::zero()), zero())];
    for kk in 1..=big {
        let mut v = Dual(zero(), zero());
        for i in 1..=kk {
            let term = e[kk - i].mul(&t[i]);
            v = if i % 2 == 1 {
                v.add(&term)
            } else {
                v.add(&term.scale(&-Rational::one()))
            };
        }
        e.push(v.scale(&Rational::new(1.into(), kk.into())));
    }
    let mut pc = vec![Rational::zero(); big + 1];
    let mut hr = vec![Rational::zero(); big + 1];
    let mut hi = vec![Rational::zero(); big + 1];
    for kk in 0..=big {
        let sign = if kk % 2 == 0 {
            Rational::one()
        } else {
            -Rational::one()
        };
        debug_assert!(e[kk].0.1.is_zero(), "P_k has rational coefficients");
        pc[big - kk] = &e[kk].0.0 * &sign;
        // Q_eps = P - eps H
        hr[big - kk] = -(&e[kk].1.0 * &sign);
        hi[big - kk] = -(&e[kk].1.1 * &sign);
    }
    (Poly::new(Q, pc), Poly::new(Q, hr), Poly::new(Q, hi))
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
        let (pk, hr, hi) = composed_primitive(&p, k);
        let dpk = pk.derivative();
        if !is_squarefree(&pk) {
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
        // theta = H(c) / P'(c)
        let Some(den) = f.inv(&f.from_poly(&dpk)) else {
            continue;
        };
        let re = f.mul(&f.from_poly(&hr), &den);
        let im = f.mul(&f.from_poly(&hi), &den);
        // the marked embedding carries (a, b) to the parts of this root: evaluated exactly
        // at a rational point within 2^-128 of c (a float evaluation of a high-degree
        // polynomial with large coefficients loses every digit and used to report a
        // correct field as "marked at another root")
        if !marked_at(&f, &c, &re, &im, theta)? {
            return Err(Error::Verification(format!(
                "the real field of a root of {p} is marked at another root"
            )));
        }
        let mut parts = simplify(RealParts {
            field: f,
            re,
            im,
            primitive: Some((g, k)),
            powers: vec![],
        });
        parts.powers = theta_powers(&p, &parts.field, &parts.re, &parts.im)?;
        return Ok(parts);
    }
    Err(Error::Limit(format!(
        "no separating primitive element a + k b found for a root of {p}"
    )))
}

/// Whether $a(c) + b(c)\,i$ is $\theta$ (not another root): $a$, $b$ are evaluated exactly
/// at the midpoint of an interval of width $2^{-128}(1 + |c|)$ around $c$ and compared
/// with the certified approximation of $\theta$.
fn marked_at(
    f: &NumberField,
    c: &AlgebraicNumber,
    re: &NfElem,
    im: &NfElem,
    theta: &AlgebraicNumber,
) -> Result<bool> {
    let (lo, hi) = match c.interval() {
        Some(iv) => iv,
        None => return Ok(true),
    };
    let scale = Rational::one() + lo.abs().max(hi.abs());
    let width = scale * Rational::new(1.into(), num_bigint::BigInt::one() << 128u32);
    let c = if &hi - &lo > width {
        c.refined(&width)?
    } else {
        c.clone()
    };
    let (lo, hi) = c.interval().unwrap_or((lo, hi));
    let mid = (&lo + &hi) * Rational::new(1.into(), 2.into());
    let at = |x: &NfElem| crate::field::rational_to_f64(&f.to_poly(x).eval(&mid));
    let (ta, tb) = theta.approx();
    let tol = 1e-6 * (1.0 + ta.abs() + tb.abs());
    Ok((at(re) - ta).abs() <= tol && (at(im) - tb).abs() <= tol)
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
                powers: parts.powers,
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
                powers: parts.powers,
            }
        }
        _ => parts,
    }
}

/// The powers $\theta^0, \dots, \theta^{d-1}$ of $\theta = a + b i$ in $F(i)$
/// ($d = \deg p$), after checking exactly that $p(\theta) = 0$ and $b \ne 0$: then
/// $t \mapsto \theta$ is a field embedding of $\mathbb{Q}[t]/(p)$ into $F(i)$.
///
/// # Errors
/// `Verification` when the check fails.
pub(crate) fn theta_powers(
    p: &Poly<Q>,
    f: &NumberField,
    re: &NfElem,
    im: &NfElem,
) -> Result<Vec<ComplexPair<NfElem>>> {
    let cf = ComplexField::new(f.clone());
    let theta = ComplexPair {
        re: re.clone(),
        im: im.clone(),
    };
    let p = p.monic();
    let d = p.deg();
    let mut powers = vec![cf.one()];
    for k in 1..=d {
        let next = cf.mul(&powers[k - 1], &theta);
        powers.push(next);
    }
    // p(theta) = sum_k p_k theta^k
    let mut acc = cf.zero();
    for (c, pw) in p.coeffs().iter().zip(&powers) {
        if !c.is_zero() {
            let c = cf.from_rational(c);
            acc = cf.add(&acc, &cf.mul(&c, pw));
        }
    }
    if !cf.is_zero(&acc) || f.is_zero(im) {
        return Err(Error::Verification(format!(
            "real and imaginary parts of a root of {p} do not satisfy it"
        )));
    }
    powers.pop();
    Ok(powers)
}

/// Square-freeness of `p` over $\mathbb{Q}$: proven by a square-free image modulo a prime
/// not dividing the leading coefficient ([`crate::poly::fp::Zp::is_squarefree`]; a
/// square-free image of the same degree implies $\gcd(p, p') = 1$); the exact gcd over
/// $\mathbb{Q}$ decides when a few primes do not.
pub(crate) fn is_squarefree(p: &Poly<Q>) -> bool {
    let z = zp::from_poly_q(p);
    for q in [
        2_147_483_647u64,
        2_147_483_629,
        2_147_483_587,
        2_147_483_579,
    ] {
        let f = crate::poly::fp::Zp::new(q);
        let red = f.reduce(&z);
        if red.len() != z.len() {
            continue;
        }
        if f.is_squarefree(&red) {
            return true;
        }
    }
    p.gcd(&p.derivative()).is_one()
}

#[cfg(test)]
mod tests {
    use super::*;
    fn p(cs: &[i64]) -> Poly<Q> {
        Poly::from_i64s(cs)
    }

    #[test]
    fn composed_primitive_examples() {
        // theta = +-i, w = (1 - i)/2: c in {1, -1, i, -i}
        let (pk, hr, hi) = composed_primitive(&p(&[1, 0, 1]), 1);
        assert_eq!(pk, p(&[-1, 0, 0, 0, 1]));
        // theta = H(c)/P'(c): at c = 1 the root i, at c = -1 the root -i
        let one = Rational::one();
        let d1 = pk.derivative().eval(&one);
        assert_eq!(
            (hr.eval(&one) / &d1, hi.eval(&one) / &d1),
            (Rational::zero(), one.clone())
        );
        let m1 = -one.clone();
        let d2 = pk.derivative().eval(&m1);
        assert_eq!(
            (hr.eval(&m1) / &d2, hi.eval(&m1) / &d2),
            (Rational::zero(), -one)
        );
        // p divides P_k
        let q = p(&[-2, 0, 0, 1]);
        let (pk, _, _) = composed_primitive(&q, 2);
        assert_eq!(pk.deg(), 9);
        assert!(pk.rem(&q).is_zero());
    }

    #[test]
    fn real_parts_of_cube_root_pair() {
        let q = p(&[-2, 0, 0, 1]);
        let up = AlgebraicNumber::roots_of_irreducible(&q)
            .unwrap()
            .into_iter()
            .find(|z| z.approx().1 > 0.0)
            .unwrap();
        let parts = real_parts_field(&up, "c").unwrap();
        assert_eq!(parts.field.degree(), 6);
        let (a, _) = parts.field.approx(&parts.re);
        let (b, _) = parts.field.approx(&parts.im);
        assert!((a + 2f64.cbrt() / 2.0).abs() < 1e-12);
        assert!((b - 2f64.cbrt() * 3f64.sqrt() / 2.0).abs() < 1e-12);
        // a^3 = -1/4 exactly
        let f = &parts.field;
        let a3 = f.mul(&f.mul(&parts.re, &parts.re), &parts.re);
        assert_eq!(
            f.to_rational(&a3),
            Some(Rational::new((-1).into(), 4.into()))
        );
        // a real root is refused
        let real = AlgebraicNumber::roots_of_irreducible(&q).unwrap()[0].clone();
        assert!(real_parts_field(&real, "c").is_err());
    }

    #[test]
    fn squarefree_and_inverse() {
        assert!(is_squarefree(&p(&[-2, 0, 0, 1])));
        assert!(!is_squarefree(&p(&[-1, 1]).pow(2).mul(&p(&[2, 1]))));
        let f = named_field(
            &p(&[-2, 0, 0, 0, 0, 0, 0, 0, 0, 1]),
            (2f64.powf(1.0 / 9.0), 0.0),
            "t",
        );
        for x in [p(&[1, 1]), p(&[3, 0, -1, 0, 0, 2, 0, 0, 1])] {
            let x = f.from_poly(&x);
            let y = f.inv(&x).unwrap();
            assert!(f.is_one(&f.mul(&x, &y)));
        }
    }
}
