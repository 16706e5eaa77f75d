//! The base fields of the Jordan decomposition: what differs between $\mathbb{Q}$ and the
//! quadratic fields $\mathbb{Q}(\sqrt d)$, $\mathbb{Q}(i)$ ([`EigenField`], [`RealEmbed`]),
//! never a copy of an algorithm.
//!
//! * $\mathbb{Q}$: factorization over $\mathbb{Q}$ with certified roots; the field of an
//!   eigenvalue is $\mathbb{Q}$, $\mathbb{Q}(\sqrt f)$ (shown with its radical) or the
//!   component field; the real field of a pair from [`super::realfield`].
//! * $K = \mathbb{Q}(\sqrt d)$, $\mathbb{Q}(i)$: Trager's norm method over $K$, the exact choice
//!   of the roots of each factor that belong to $A$ (not to $\bar A$), the component field
//!   $E = K\[t\]/(g)$ marked at each root; the real field of a pair from a primitive element
//!   of $K(\theta)$ (the construction below).

use super::decompose::{CertifiedRoots, EigenField, FactorRoots, generic_component};
use super::pair_field::{
    EXPAND_MAX_DEGREE, EXPAND_MAX_EIGENVALUE_DEGREE, EXPAND_MAX_PRIMITIVE_DEGREE, PairField,
    RealEmbed, exact_parts, small_real_field,
};
use super::primary::{Component, named_field, rational_field};
use super::realfield::{RealParts, identify_real_root, real_parts_field, simplify, theta_powers};
use super::roots::{self, factor_q, quadratic_roots};
use super::{Embedding, JordanForm, quadratic_field};
use crate::algebraic::{
    NfElem, NumberField, factor_over_quadratic, rational_minpoly, roots_of_quadratic_factor,
};
use crate::error::{Error, Result};
use crate::field::{ComplexField, ComplexPair, Field, Q, Quadratic, QuadraticField, Rational};
use crate::matrix::Matrix;
use crate::poly::Poly;
use num_traits::{One, Zero};

impl RealEmbed for Q {
    fn is_real(&self) -> bool {
        true
    }
    fn into_real(&self, c: &Rational, f: &NumberField, _: &NfElem) -> NfElem {
        f.from_rational(c)
    }
    fn from_real(&self, f: &NumberField, x: &NfElem) -> Option<Rational> {
        f.to_rational(x)
    }
}

impl EigenField for Q {
    fn eigen_factors(chi: &Poly<Q>) -> Result<Vec<FactorRoots<Q>>> {
        let mut out = vec![];
        for (p, e) in roots::factor_q(chi)? {
            let rts = roots::certified_roots(&p)?;
            out.push((p.clone(), e, p, rts));
        }
        Ok(out)
    }
    /// Over $\mathbb{Q}$ a repeated factor goes through the rational restriction to its
    /// generalized eigenspace ([`super::PrimaryComponent::compute`]).
    fn component(
        a: &Matrix<Q>,
        chi: &Poly<Q>,
        (g, e, minpoly): (&Poly<Q>, usize, Poly<Q>),
        roots: Vec<(f64, f64)>,
    ) -> Result<Component<Q>> {
        if e == 1 && g.deg() >= 2 {
            generic_component(a, chi, (g, e, minpoly), roots)
        } else {
            Component::compute(a, g, e, Some(minpoly), roots, false)
        }
    }
    /// $\mathbb{Q}$ for a rational root, $\mathbb{Q}(\sqrt f)$ (displayed with its radical,
    /// one field for both roots) for a quadratic factor, else the component field marked at
    /// the root.
    fn root_field(jf: &JordanForm<Q>, ev: usize) -> (NumberField, Embedding<'_, Q>) {
        let e = &jf.eigenvalues[ev];
        let c = &jf.components[e.component];
        match c.degree() {
            1 => {
                let k = rational_field();
                let k2 = k.clone();
                (
                    k,
                    Box::new(move |x: &NfElem| {
                        k2.from_rational(&c.field.to_rational(x).expect("in Q"))
                    }),
                )
            }
            2 => {
                let (a0, s, fd) = quadratic_roots(&c.factor).expect("irreducible");
                let positive = if num_traits::Signed::is_negative(&fd) {
                    e.approx.1 > 0.0
                } else {
                    e.approx.0 > crate::field::rational_to_f64(&a0)
                };
                let s = if positive { s } else { -s };
                (
                    quadratic_field(&fd),
                    Box::new(move |x: &NfElem| super::quadratic_image(x, &a0, &s)),
                )
            }
            _ => (
                c.embedding(e.root, &e.symbol()),
                Box::new(|x: &NfElem| x.clone()),
            ),
        }
    }
    /// Built when it may be small ([`super::real::EXPAND_MAX_DEGREE`]) or on request, for
    /// eigenvalues of degree at most [`super::real::EXPAND_MAX_EIGENVALUE_DEGREE`].
    fn real_pair(jf: &JordanForm<Q>, ev: usize, expand: bool) -> Result<Option<PairField>> {
        let e = &jf.eigenvalues[ev];
        let small = matches!(exact_parts(e), (Some(a), Some(b))
            if a.degree() <= EXPAND_MAX_DEGREE && b.degree() <= EXPAND_MAX_DEGREE);
        if !expand && !small {
            return Ok(None);
        }
        let degree = e.minpoly.deg();
        if degree > EXPAND_MAX_EIGENVALUE_DEGREE {
            return Err(Error::Limit(format!(
                "eigenvalue {} has degree {degree}: its real field may have degree up to {} \
                 (`--expand` writes out pairs of degree at most {EXPAND_MAX_EIGENVALUE_DEGREE})",
                e.symbol(),
                degree * (degree - 1)
            )));
        }
        match pair_field_q(jf, ev) {
            Ok(pf) if expand || pf.field.degree() <= EXPAND_MAX_DEGREE => Ok(Some(pf)),
            Ok(_) => Ok(None),
            Err(err) if expand => Err(err),
            Err(_) => Ok(None),
        }
    }
}

impl RealEmbed for QuadraticField {
    fn is_real(&self) -> bool {
        QuadraticField::is_real(self)
    }
    fn into_real(&self, c: &Quadratic, f: &NumberField, alpha: &NfElem) -> NfElem {
        f.add(
            &f.from_rational(&c.a),
            &f.mul(&f.from_rational(&c.b), alpha),
        )
    }
    /// $\mathbb{Q}$ or $\mathbb{Q}(\sqrt d)$ itself (modulus $x^2 - d$).
    fn from_real(&self, f: &NumberField, x: &NfElem) -> Option<Quadratic> {
        let c = |i: usize| x.0.get(i).cloned().unwrap_or_default();
        let m = f.modulus();
        match f.degree() {
            1 => f
                .to_rational(x)
                .map(|q| Quadratic::new(q, Rational::default())),
            2 if m.coeff(1) == Rational::default()
                && -m.coeff(0) == Rational::from_integer(self.d().clone()) =>
            {
                Some(Quadratic::new(c(0), c(1)))
            }
            _ => None,
        }
    }
}

impl EigenField for QuadraticField {
    fn eigen_factors(chi: &Poly<QuadraticField>) -> Result<Vec<FactorRoots<QuadraticField>>> {
        let mut out = vec![];
        if chi.deg() == 0 {
            return Ok(out);
        }
        for (g, e) in factor_over_quadratic(chi)? {
            let (m, roots) = roots_of_quadratic(&g)?;
            out.push((g, e, m, roots));
        }
        Ok(out)
    }
    /// A pair of a rational quadratic factor keeps its radical form (`None`); else the real
    /// field of [`pair_field`].
    fn real_pair(
        jf: &JordanForm<QuadraticField>,
        ev: usize,
        expand: bool,
    ) -> Result<Option<PairField>> {
        let e = &jf.eigenvalues[ev];
        let c = &jf.components[e.component];
        if c.factor.deg() == 2 && c.minpoly.as_ref().is_some_and(|m| m.deg() == 2) {
            return Ok(None);
        }
        pair_field(&c.factor, e.approx, &format!("c{}", e.index), expand)
    }
}

/// The roots of the monic irreducible `g` over $K$ (under the embedding fixing $\alpha$),
/// as certified algebraic numbers with approximations, real part descending, with the
/// minimal polynomial over $\mathbb{Q}$ they share
/// ([`crate::algebraic::roots_of_quadratic_factor`]: the exact choice of the roots that
/// belong to $A$, not to $\bar A$).
///
/// # Errors
/// `Limit` from root isolation or from the exact choice of the roots of `g`.
pub fn roots_of_quadratic(g: &Poly<QuadraticField>) -> Result<(Poly<Q>, CertifiedRoots)> {
    let m = rational_minpoly(g);
    let all = roots::certified_roots(&m)?;
    Ok((m, roots_of_quadratic_factor(g, all)?))
}

/// The real field of the pair of eigenvalue `ev` of a rational matrix (module docs of
/// [`super::real`]).
///
/// # Errors
/// `Limit` or `Unsupported` when the field is not found (the pair then stays compact).
pub(crate) fn pair_field_q(jf: &JordanForm<Q>, ev: usize) -> Result<PairField> {
    let e = &jf.eigenvalues[ev];
    let p = &e.minpoly;
    let done = |field: NumberField, powers| PairField {
        alpha: field.zero(),
        field,
        powers,
    };
    if p.deg() == 2 {
        // theta = a0 + s sqrt(d), d < 0: Im = s sqrt(-d) (s > 0 for the upper root)
        let (a0, s, d) = quadratic_roots(p).expect("irreducible");
        let g = -d;
        let f = if g.is_one() {
            rational_field()
        } else {
            quadratic_field(&g)
        };
        let re = f.from_rational(&a0);
        let im = if g.is_one() {
            f.from_rational(&s)
        } else {
            f.from_poly(&Poly::new(Q, vec![Rational::zero(), s]))
        };
        let powers = theta_powers(p, &f, &re, &im)?;
        return Ok(done(f, powers));
    }
    if e.number.is_pure_imaginary() {
        // theta = i beta: beta is a real root of r(x) = p(i x) = sum c_k (-1)^(k/2) x^k
        let r = Poly::new(
            Q,
            p.coeffs()
                .iter()
                .enumerate()
                .map(|(k, c)| if (k / 2) % 2 == 0 { c.clone() } else { -c })
                .collect(),
        );
        let factors: Vec<Poly<Q>> = factor_q(&r)?.into_iter().map(|(g, _)| g).collect();
        let (g, beta) =
            identify_real_root(&factors, &e.number, &Rational::zero(), &Rational::one())?;
        let f = named_field(&g, (beta.approx().0, 0.0), &format!("b{}", ev + 1));
        let b = if g.deg() == 1 {
            f.from_rational(&-g.coeff(0))
        } else {
            f.generator()
        };
        let parts = simplify(RealParts {
            re: f.zero(),
            im: b,
            field: f,
            primitive: None,
            powers: vec![],
        });
        let powers = theta_powers(p, &parts.field, &parts.re, &parts.im)?;
        return Ok(done(parts.field, powers));
    }
    let parts = real_parts_field(&e.number, &format!("c{}", ev + 1))?;
    Ok(done(parts.field, parts.powers))
}

/// $p(x)$ for $p$ over $K$ at $x \in F(i)$, coefficients mapped by $\sqrt d \mapsto s$.
fn eval_k(
    cf: &ComplexField<NumberField>,
    s: &NfElem,
    p: &[Quadratic],
    x: &ComplexPair<NfElem>,
) -> ComplexPair<NfElem> {
    let f = &cf.base;
    let mut acc = cf.zero();
    for c in p.iter().rev() {
        let c = f.add(&f.from_rational(&c.a), &f.mul(&f.from_rational(&c.b), s));
        acc = cf.add(&cf.mul(&acc, x), &cf.from_base(&c));
    }
    acc
}

/// The real field of the pair of the root near `approx` of the irreducible `g` over a real
/// $K$ (module docs); `None` when `expand` is false and the field may have degree above
/// [`EXPAND_MAX_DEGREE`]. `var` names a primitive element of degree
/// $\ge 3$ in displays.
///
/// # Errors
/// `Invalid` for a non-real $K$ or a real root; `Limit` when $[E : \mathbb{Q}] >$
/// [`EXPAND_MAX_PRIMITIVE_DEGREE`]; those of root isolation and of
/// [`crate::jordan::realfield`]; `Verification` if a check fails.
pub fn pair_field(
    g: &Poly<QuadraticField>,
    approx: (f64, f64),
    var: &str,
    expand: bool,
) -> Result<Option<PairField>> {
    let k = g.field().clone();
    if !k.is_real() || approx.1 == 0.0 {
        return Err(Error::Invalid(format!(
            "the real field of a pair needs a real K and a non-real root (K = {k})"
        )));
    }
    let shift = if g.coeffs().iter().all(|c| k.to_rational(c).is_some()) {
        1
    } else {
        0
    };
    let alpha = k.gen_elem();
    let sq = crate::field::rational_to_f64(&Rational::from_integer(k.d().clone())).sqrt();
    // h(x) = g(x - shift sqrt d)
    let lin = Poly::new(
        k.clone(),
        vec![k.neg(&k.mul(&k.from_i64(shift), &alpha)), k.one()],
    );
    let h = if shift == 0 {
        g.clone()
    } else {
        g.compose(&lin)
    };
    let (_, roots) = roots_of_quadratic(&h)?;
    let want = (approx.0 + shift as f64 * sq, approx.1);
    let dist = |z: &(f64, f64)| (z.0 - want.0).hypot(z.1 - want.1);
    let gamma = roots
        .into_iter()
        .min_by(|x, y| dist(&x.1).total_cmp(&dist(&y.1)))
        .map(|x| x.0)
        .ok_or_else(|| Error::Verification(format!("no root of {h}")))?;
    if !expand && !small_real_field(&gamma) {
        return Ok(None);
    }
    if gamma.degree() > EXPAND_MAX_PRIMITIVE_DEGREE {
        return Err(Error::Limit(format!(
            "K(theta) has degree {} over QQ (at most {EXPAND_MAX_PRIMITIVE_DEGREE} is expanded: \
             its real field has degree up to {})",
            gamma.degree(),
            gamma.degree() * (gamma.degree() - 1)
        )));
    }
    let parts = real_parts_field(&gamma, var)?;
    let f = parts.field;
    if !expand && f.degree() > EXPAND_MAX_DEGREE {
        return Ok(None);
    }
    let cf = ComplexField::new(f.clone());
    let gam = ComplexPair {
        re: parts.re,
        im: parts.im,
    };
    let part = |b: bool| -> Vec<Quadratic> {
        h.coeffs()
            .iter()
            .map(|c| {
                let q = if b { c.b.clone() } else { c.a.clone() };
                Quadratic::new(q, Rational::default())
            })
            .collect()
    };
    let zero = f.zero();
    let (h0, h1) = (
        eval_k(&cf, &zero, &part(false), &gam),
        eval_k(&cf, &zero, &part(true), &gam),
    );
    let bad = |what: &str| Error::Verification(format!("the real field of a root of {g}: {what}"));
    let inv = cf.inv(&h1).ok_or_else(|| bad("h1(gamma) = 0"))?;
    let s = cf.neg(&cf.mul(&h0, &inv));
    let d = f.from_rational(&Rational::from_integer(k.d().clone()));
    if !f.is_zero(&s.im) || f.mul(&s.re, &s.re) != d || f.approx(&s.re).0 <= 0.0 {
        return Err(bad("no positive square root of d"));
    }
    let s = s.re;
    let ks = f.mul(&f.from_i64(shift), &s);
    let theta = ComplexPair {
        re: f.sub(&gam.re, &ks),
        im: gam.im,
    };
    if !cf.is_zero(&eval_k(&cf, &s, g.coeffs(), &theta)) || f.is_zero(&theta.im) {
        return Err(bad("g(theta) != 0"));
    }
    let mut powers = vec![cf.one()];
    while powers.len() < g.deg() {
        let next = cf.mul(powers.last().expect("one"), &theta);
        powers.push(next);
    }
    Ok(Some(PairField {
        field: f,
        alpha: s,
        powers,
    }))
}
