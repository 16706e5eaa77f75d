//! The real field of a complex pair of eigenvalues of a matrix over a real quadratic field
//! $K = \mathbb{Q}(\sqrt d)$, $d > 0$: the field $F$ in which the real and imaginary parts
//! of every element of $E = K(\theta)$ are exact (the rational machinery of
//! [`crate::jordan::realfield`], applied to a primitive element of $E$).
//!
//! # Construction
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

use super::RelElem;
use crate::algebraic::{AlgebraicNumber, NfElem, NumberField};
use crate::error::{Error, Result};
use crate::field::{ComplexField, ComplexPair, Field, Quadratic, QuadraticField, Rational};
use crate::poly::Poly;

/// Largest degree over $\mathbb{Q}$ of $E = K(\theta)$ whose real field is built, even on
/// request (`--expand`): the construction factors a polynomial of degree $[E:\mathbb{Q}]^2$
/// (64 at the bound: about 6 s for a quartic factor over $K$; 100 did not finish in 100 s).
pub const EXPAND_MAX_PRIMITIVE_DEGREE: usize = 8;

/// $F$ with the images of $\sqrt d$ and of the eigenvalue $\theta$ (module docs).
#[derive(Clone, Debug)]
pub struct PairField {
    /// The real field $F$.
    pub field: NumberField,
    /// $\sqrt d \in F$.
    pub sqrt_d: NfElem,
    /// $\theta = \operatorname{Re}\theta + i \operatorname{Im}\theta$ in $F(i)$.
    pub theta: ComplexPair<NfElem>,
}

/// Whether the real field of `z` may have degree at most
/// [`crate::jordan::real::EXPAND_MAX_DEGREE`] (the test of the rational realization).
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
    let (_, roots) = super::eigen::roots_of_factor(&h)?;
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
    Ok(Some(PairField {
        field: f,
        sqrt_d: s,
        theta,
    }))
}

impl PairField {
    /// The image in $F$ of an element of $K$.
    pub fn base(&self, c: &Quadratic) -> NfElem {
        let f = &self.field;
        f.add(
            &f.from_rational(&c.a),
            &f.mul(&f.from_rational(&c.b), &self.sqrt_d),
        )
    }
    /// $(\operatorname{Re} x, \operatorname{Im} x)$ in $F$ for $x \in E$ at $\theta$.
    pub fn re_im(&self, x: &RelElem) -> (NfElem, NfElem) {
        let cf = ComplexField::new(self.field.clone());
        let z = eval_k(&cf, &self.sqrt_d, &x.0, &self.theta);
        (z.re, z.im)
    }
    /// $A$ over $K$ as a matrix over $F$.
    pub fn matrix(
        &self,
        a: &crate::matrix::Matrix<QuadraticField>,
    ) -> crate::matrix::Matrix<NumberField> {
        a.map(&self.field, |x| self.base(x))
    }
    /// The definition line of $F$'s generator when $[F : \mathbb{Q}] \ge 3$ (shown as a
    /// symbol), else `None` ($\mathbb{Q}$ and $\mathbb{Q}(\sqrt f)$ show their radicals).
    pub fn symbol(&self) -> Option<String> {
        let f = &self.field;
        (f.degree() >= 3).then(|| {
            format!(
                "{} = {}",
                f.0.var,
                crate::jordan::value_display(f.modulus(), f.root_approx())
            )
        })
    }
}
