//! An element $\lambda$ of $E = K(r) = K[t]/(h)$, $K = \mathbb{Q}$ or $\mathbb{Q}(\sqrt d)$,
//! $r$ a real algebraic number marked as the root of $h$, as an [`AlgebraicNumber`]: the
//! exact eigenvalue of a linear factor $x - \lambda$ at a critical value.
//!
//! * Minimal polynomial: $\lambda$ is a root of the characteristic polynomial $\chi$ of the
//!   multiplication map $y \mapsto \lambda y$ on $E$ over $K$ (and so of its norm
//!   $\chi \bar\chi \in \mathbb{Q}[x]$ over $\mathbb{Q}(\sqrt d)$); its minimal polynomial is
//!   one of the irreducible factors over $\mathbb{Q}$.
//! * Which root: writing $\lambda = A(t) + \sqrt d\, B(t)$ with $A, B \in \mathbb{Q}[t]$, an
//!   isolating interval $[l, u] \ni r$ gives a rational enclosure of $A(r)$, $B(r)$ (interval
//!   Horner) and of $\sqrt d$ (an isolating interval of $x^2 - d$); the candidate roots whose
//!   isolating regions meet the enclosure are kept, and both are refined until one is left
//!   (an enclosure holds $\lambda$, a region holds exactly one root: the survivor is
//!   $\lambda$).

use crate::algebraic::{AlgebraicNumber, Ext, ExtElem, factor_q, norm_over_q};
use crate::error::{Error, Result};
use crate::field::{Field, Q, Quadratic, QuadraticField, Rational};
use crate::matrix::Matrix;
use crate::poly::Poly;
use num_traits::{Signed, Zero};

/// A closed rational interval.
type Iv = (Rational, Rational);

/// $\lambda \in \mathbb{Q}(r)$ (`e` marked at `r`) as an algebraic number.
///
/// # Errors
/// `Verification` when no single root is left after refinement (not expected); the errors
/// of factoring and root isolation.
pub fn value_over_q(
    e: &Ext<Q>,
    lambda: &ExtElem<Rational>,
    r: &AlgebraicNumber,
) -> Result<AlgebraicNumber> {
    let chi = mult_charpoly(e, lambda)?;
    let a = Poly::new(Q, e.coeffs(lambda).to_vec());
    identify(&chi, r, &a, &Poly::zero(Q), &Rational::zero())
}

/// $\lambda \in K(r)$, $K = \mathbb{Q}(\sqrt d)$ (`e` marked at `r`), as an algebraic number.
///
/// # Errors
/// As [`value_over_q`].
pub fn value_over_k(
    e: &Ext<QuadraticField>,
    lambda: &ExtElem<Quadratic>,
    r: &AlgebraicNumber,
) -> Result<AlgebraicNumber> {
    let chi = norm_over_q(&mult_charpoly(e, lambda)?);
    let cs = e.coeffs(lambda);
    let a = Poly::new(Q, cs.iter().map(|c| c.a.clone()).collect());
    let b = Poly::new(Q, cs.iter().map(|c| c.b.clone()).collect());
    let d = Rational::from_integer(e.base().d().clone());
    identify(&chi, r, &a, &b, &d)
}

/// The characteristic polynomial over the base of multiplication by `lambda` on `e`.
fn mult_charpoly<F: Field>(e: &Ext<F>, lambda: &ExtElem<F::Elem>) -> Result<Poly<F>> {
    let base = e.base().clone();
    let n = e.degree();
    let t = e.generator();
    let mut cols = Vec::with_capacity(n);
    let mut y = lambda.clone();
    for _ in 0..n {
        cols.push(e.coeffs(&y).to_vec());
        y = e.mul(&y, &t);
    }
    Matrix::from_fn(base.clone(), n, n, |i, j| {
        cols[j].get(i).cloned().unwrap_or_else(|| base.zero())
    })
    .charpoly()
}

/// The root of `chi` equal to $A(r) + \sqrt d B(r)$ (see the module docs).
fn identify(
    chi: &Poly<Q>,
    r: &AlgebraicNumber,
    a: &Poly<Q>,
    b: &Poly<Q>,
    d: &Rational,
) -> Result<AlgebraicNumber> {
    let (_, facs) = factor_q(chi)?;
    let mut cands = vec![];
    for (f, _) in facs {
        cands.extend(AlgebraicNumber::roots_of_irreducible(&f)?);
    }
    let sqrt_d = (!b.is_zero()).then(|| sqrt_of(d)).transpose()?;
    let mut w = Rational::new(1.into(), 1024.into());
    for _ in 0..200 {
        if cands.len() == 1 {
            return Ok(cands.remove(0));
        }
        let (re, im) = enclosure(r, a, b, d, sqrt_d.as_ref(), &w)?;
        let mut keep = vec![];
        for c in cands {
            let c = c.refined(&w)?;
            let (cr, ci) = c.bounding_box();
            if meets(&cr, &re) && meets(&ci, &im) {
                keep.push(c);
            }
        }
        cands = keep;
        w = &w / Rational::from_integer(16.into());
    }
    Err(Error::Verification(format!(
        "{} roots of {chi} left in the enclosure of an eigenvalue",
        cands.len()
    )))
}

/// $\sqrt{|d|}$ as the positive root of $x^2 - |d|$ ($d$ square-free; $1$ for $d = -1$).
fn sqrt_of(d: &Rational) -> Result<AlgebraicNumber> {
    if d.abs() == Rational::from_integer(1.into()) {
        return Ok(AlgebraicNumber::from_rational(&d.abs()));
    }
    let p = Poly::new(
        Q,
        vec![-d.abs(), Rational::zero(), Rational::from_integer(1.into())],
    );
    AlgebraicNumber::roots_of_irreducible(&p)?
        .pop()
        .ok_or_else(|| Error::Verification("sqrt of the field's radicand".into()))
}

/// Real and imaginary enclosures of $A(r) + \sqrt d B(r)$ at isolating width `w`.
fn enclosure(
    r: &AlgebraicNumber,
    a: &Poly<Q>,
    b: &Poly<Q>,
    d: &Rational,
    sqrt_d: Option<&AlgebraicNumber>,
    w: &Rational,
) -> Result<(Iv, Iv)> {
    let rr = r.refined(w)?.bounding_box().0;
    let re = horner(a, &rr);
    let zero = (Rational::zero(), Rational::zero());
    let Some(s) = sqrt_d else {
        return Ok((re, zero));
    };
    let s = s.refined(w)?.bounding_box().0;
    let part = mul(&horner(b, &rr), &s);
    if d.is_negative() {
        Ok((re, part))
    } else {
        Ok(((&re.0 + &part.0, &re.1 + &part.1), zero))
    }
}

/// $p(x)$ over the interval `x` (interval Horner).
fn horner(p: &Poly<Q>, x: &Iv) -> Iv {
    let mut acc = (Rational::zero(), Rational::zero());
    for c in p.coeffs().iter().rev() {
        let m = mul(&acc, x);
        acc = (&m.0 + c, &m.1 + c);
    }
    acc
}

fn mul(x: &Iv, y: &Iv) -> Iv {
    let ps = [&x.0 * &y.0, &x.0 * &y.1, &x.1 * &y.0, &x.1 * &y.1];
    let lo = ps.iter().min().cloned().unwrap_or_default();
    let hi = ps.iter().max().cloned().unwrap_or_default();
    (lo, hi)
}

fn meets(x: &Iv, y: &Iv) -> bool {
    x.0 <= y.1 && y.0 <= x.1
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> Rational {
        Rational::new(n.into(), d.into())
    }

    #[test]
    fn an_element_of_a_quadratic_field_is_its_closed_form() {
        // r = sqrt(2) (root of t^2 - 2 near 1.41); lambda = 3 - r/2 = 3 - sqrt(2)/2
        let f = Poly::new(Q, vec![q(-2, 1), q(0, 1), q(1, 1)]);
        let r = AlgebraicNumber::roots_of_irreducible(&f)
            .unwrap()
            .pop()
            .unwrap();
        let e = r.to_number_field();
        let lambda = e.from_poly(&Poly::new(Q, vec![q(3, 1), q(-1, 2)]));
        let v = value_over_q(&e, &lambda, &r).unwrap();
        assert_eq!(v.value_string(), "3 - sqrt(2)/2");
        // the other root of its minimal polynomial is 3 + sqrt(2)/2: the enclosure chose
        let f2 = v.minpoly().clone();
        assert_eq!(f2, Poly::new(Q, vec![q(17, 2), q(-6, 1), q(1, 1)]));
    }

    #[test]
    fn a_rational_element_and_a_cubic_field() {
        // r the real root of t^3 - 2; lambda = r^2 has minimal polynomial x^3 - 4
        let f = Poly::new(Q, vec![q(-2, 1), q(0, 1), q(0, 1), q(1, 1)]);
        let r = AlgebraicNumber::roots_of_irreducible(&f).unwrap().remove(0);
        let e = r.to_number_field();
        let l2 = e.from_poly(&Poly::new(Q, vec![q(0, 1), q(0, 1), q(1, 1)]));
        let v = value_over_q(&e, &l2, &r).unwrap();
        assert_eq!(
            v.minpoly(),
            &Poly::new(Q, vec![q(-4, 1), q(0, 1), q(0, 1), q(1, 1)])
        );
        assert!((v.approx().0 - 4f64.cbrt()).abs() < 1e-12);
        let c = e.from_rational(&q(-7, 3));
        assert_eq!(value_over_q(&e, &c, &r).unwrap().value_string(), "-7/3");
    }

    #[test]
    fn an_element_over_q_sqrt_3_and_over_q_i() {
        // K = Q(sqrt 3), r = sqrt(2): lambda = sqrt(3) + r = sqrt 3 + sqrt 2
        let h = Poly::new(Q, vec![q(-2, 1), q(0, 1), q(1, 1)]);
        let r = AlgebraicNumber::roots_of_irreducible(&h)
            .unwrap()
            .pop()
            .unwrap();
        for (d, want) in [
            (3, (3f64.sqrt() + 2f64.sqrt(), 0.0)),
            (-1, (2f64.sqrt(), 1.0)),
        ] {
            let k = QuadraticField::new(d).unwrap();
            let hk = h.map(&k, |c| k.from_rational(c));
            let e = Ext::with_var(&hk, r.approx(), "t");
            let theta = e.from_base(&Quadratic::new(q(0, 1), q(1, 1)));
            let lambda = e.add(&theta, &e.generator());
            let v = value_over_k(&e, &lambda, &r).unwrap();
            let z = v.approx();
            assert!((z.0 - want.0).abs() < 1e-12 && (z.1 - want.1).abs() < 1e-12);
            assert_eq!(v.minpoly().deg(), 4);
        }
    }
}
