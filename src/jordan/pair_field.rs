//! The real field of a complex pair of eigenvalues: the number field $F$ in which the real
//! and imaginary parts of every element of $E = F_0\[t\]/(g)$ at the root $\theta$ are exact
//! ([`PairField`], one type for every base field $F_0$; the base field builds it through
//! [`super::EigenField::real_pair`]).
//!
//! An element $x = \sum_k c_k t^k$ ($c_k \in F_0$) maps to $\operatorname{Re} x + i
//! \operatorname{Im} x = \sum_k \iota(c_k)\,\theta^k$ in $F(i)$, with $\iota: F_0 \to F$ the
//! embedding of the base field ([`super::EigenField::into_real`]; over $\mathbb{Q}$ the
//! identity, over $\mathbb{Q}(\sqrt d)$ given by the image of $\sqrt d$) and the table of
//! $\theta^0, \dots, \theta^{\deg g - 1}$.
//!
//! # Over $\mathbb{Q}$
//! See [`super::real`]: $\mathbb{Q}$ or $\mathbb{Q}(\sqrt{|f|})$ for a quadratic factor,
//! $\mathbb{Q}(\beta)$ for a purely imaginary root $i\beta$, else
//! $\mathbb{Q}(\operatorname{Re}\theta, \operatorname{Im}\theta)$ from a primitive element.
//!
//! # Over a real quadratic field $K = \mathbb{Q}(\sqrt d)$
//! Let $g \in K\[x\]$ be the irreducible factor with root $\theta$ and $h(x) = g(x -
//! k\sqrt d)$, $k = 0$ when $g \notin \mathbb{Q}\[x\]$, else $k = 1$. Then $h \notin
//! \mathbb{Q}\[x\]$, so its roots have degree $2 \deg g = [E : \mathbb{Q}]$ over
//! $\mathbb{Q}$ and $\gamma = \theta + k\sqrt d$ generates $E$ over $\mathbb{Q}$. With
//! $F = \mathbb{Q}(\operatorname{Re}\gamma, \operatorname{Im}\gamma)$ (from
//! [`crate::jordan::realfield`]), $F(i) \supseteq \mathbb{Q}(\gamma) = E$, and the real
//! elements of $F(i)$ lie in $F$: so $\sqrt d \in F$ and $\operatorname{Re} x,
//! \operatorname{Im} x \in F$ for every $x \in E$. Writing $h = h_0 + \sqrt d\, h_1$ with
//! $h_0, h_1 \in \mathbb{Q}\[x\]$ ($h_1 \ne 0$ of degree below $2\deg g$, so $h_1(\gamma)
//! \ne 0$): $\sqrt d = -h_0(\gamma)/h_1(\gamma)$ and $\theta = \gamma - k\sqrt d$ in $F(i)$.
//!
//! # Checks (exact)
//! $s = \sqrt d$ is real, $s^2 = d$, $s > 0$ under the marked embedding, and $g(\theta) = 0$
//! in $F(i)$ with the coefficients of $g$ mapped by $\sqrt d \mapsto s$: then $t \mapsto
//! \theta$, $\sqrt d \mapsto s$ is a field embedding $E \to F(i)$ sending $t$ to the
//! eigenvalue (the marked root of $F$ is checked by the rational construction), so the real
//! blocks built from it are exact images of the verified complex ones.

use super::primary::{named_field, rational_field};
use super::realfield::{RealParts, identify_real_root, real_parts_field, simplify, theta_powers};
use super::roots::{factor_q, quadratic_roots};
use super::{EigenField, JordanForm, quadratic_field};
use crate::algebraic::{AlgebraicNumber, ExtElem, NfElem, NumberField};
use crate::error::{Error, Result};
use crate::field::{ComplexField, ComplexPair, Field, Q, Quadratic, QuadraticField, Rational};
use crate::matrix::Matrix;
use crate::poly::Poly;
use num_traits::{One, Zero};

/// Largest degree over $\mathbb{Q}$ of $E = K(\theta)$ whose real field is built, even on
/// request (`--expand`): the construction factors a polynomial of degree $[E:\mathbb{Q}]^2$
/// (64 at the bound: about 6 s for a quartic factor over $K$; 100 did not finish in 100 s).
pub const EXPAND_MAX_PRIMITIVE_DEGREE: usize = 8;

/// The real field $F$ of a complex pair with the image of the base field's generator and
/// the powers of $\theta$ in $F(i)$ (module docs).
#[derive(Clone, Debug, PartialEq)]
pub struct PairField {
    /// The real field $F$.
    pub field: NumberField,
    /// The image in $F$ of the base field's generator ($\sqrt d$ over $\mathbb{Q}(\sqrt d)$;
    /// zero over $\mathbb{Q}$).
    pub alpha: NfElem,
    /// $\theta^0, \dots, \theta^{\deg g - 1}$ in $F(i)$, checked: $g(\theta) = 0$.
    pub powers: Vec<ComplexPair<NfElem>>,
}

impl PairField {
    /// $(\operatorname{Re} x, \operatorname{Im} x)$ in $F$ for $x \in E$ at $\theta$.
    pub fn re_im<F: EigenField>(&self, k: &F, x: &ExtElem<F::Elem>) -> (NfElem, NfElem) {
        let f = &self.field;
        let (mut re, mut im) = (f.zero(), f.zero());
        for (c, pw) in x.0.iter().zip(&self.powers) {
            if k.is_zero(c) {
                continue;
            }
            let c = k.into_real(c, f, &self.alpha);
            re = f.add(&re, &f.mul(&c, &pw.re));
            im = f.add(&im, &f.mul(&c, &pw.im));
        }
        (re, im)
    }
    /// $\theta = \operatorname{Re}\theta + i \operatorname{Im}\theta$ in $F(i)$.
    pub fn theta(&self) -> ComplexPair<NfElem> {
        self.powers.get(1).cloned().unwrap_or_else(|| ComplexPair {
            re: self.field.zero(),
            im: self.field.zero(),
        })
    }
    /// A matrix over the base field as a matrix over $F$.
    pub fn matrix<F: EigenField>(&self, a: &Matrix<F>) -> Matrix<NumberField> {
        let k = a.field();
        a.map(&self.field, |x| k.into_real(x, &self.field, &self.alpha))
    }
}

/// Whether the real field of `z` may have degree at most
/// [`crate::jordan::real::EXPAND_MAX_DEGREE`].
pub(crate) fn small_real_field(z: &AlgebraicNumber) -> bool {
    use crate::jordan::real::{EXPAND_MAX_DEGREE, parts_affordable};
    if !parts_affordable(z.minpoly()) {
        return false;
    }
    match (z.try_re(), z.try_im()) {
        (Ok(a), Ok(b)) => a.degree() <= EXPAND_MAX_DEGREE && b.degree() <= EXPAND_MAX_DEGREE,
        _ => false,
    }
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
/// [`crate::jordan::real::EXPAND_MAX_DEGREE`]. `var` names a primitive element of degree
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
    let (_, roots) = super::decompose::roots_of_quadratic(&h)?;
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
    let parts = crate::jordan::realfield::real_parts_field(&gamma, var)?;
    let f = parts.field;
    if !expand && f.degree() > crate::jordan::real::EXPAND_MAX_DEGREE {
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
