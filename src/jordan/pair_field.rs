//! The real field of a complex pair of eigenvalues: the number field $F$ in which the real
//! and imaginary parts of every element of $E = F_0\[t\]/(g)$ at the root $\theta$ are exact
//! ([`PairField`], one type for every base field $F_0$; the base field builds it through
//! [`super::EigenField::real_pair`]).
//!
//! An element $x = \sum_k c_k t^k$ ($c_k \in F_0$) maps to $\operatorname{Re} x + i
//! \operatorname{Im} x = \sum_k \iota(c_k)\,\theta^k$ in $F(i)$, with $\iota: F_0 \to F$ the
//! embedding of the base field ([`RealEmbed::into_real`]; over $\mathbb{Q}$ the
//! identity, over $\mathbb{Q}(\sqrt d)$ given by the image of $\sqrt d$) and the table of
//! $\theta^0, \dots, \theta^{\deg g - 1}$.
//!
//! The constructions are methods of the base field (`super::fields`):
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
//!
//! The size bounds of the real forms (when a pair is expanded, when the parts of $\theta$ are
//! computed) are here too.

use crate::algebraic::{AlgebraicNumber, ExtElem, NfElem, NumberField};
use crate::field::{ComplexPair, Field, Q};
use crate::matrix::Matrix;
use crate::poly::Poly;

/// How a base field sits in the real number fields of the real forms.
pub trait RealEmbed: Field {
    /// Whether the field is real (its matrices have a real Jordan form).
    fn is_real(&self) -> bool;
    /// The image of `c` in the real number field `f`, given the image `alpha` of the field's
    /// generator.
    fn into_real(&self, c: &Self::Elem, f: &NumberField, alpha: &NfElem) -> NfElem;
    /// `x` of the real field `f` as an element of this field, when it lies in it.
    fn from_real(&self, f: &NumberField, x: &NfElem) -> Option<Self::Elem>;
}

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
    pub fn re_im<F: RealEmbed>(&self, k: &F, x: &ExtElem<F::Elem>) -> (NfElem, NfElem) {
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
    pub fn matrix<F: RealEmbed>(&self, a: &Matrix<F>) -> Matrix<NumberField> {
        let k = a.field();
        a.map(&self.field, |x| k.into_real(x, &self.field, &self.alpha))
    }
}

/// Whether the real field of `z` may have degree at most
/// [`crate::jordan::real::EXPAND_MAX_DEGREE`].
pub(crate) fn small_real_field(z: &AlgebraicNumber) -> bool {
    if !parts_affordable(z.minpoly()) {
        return false;
    }
    match (z.try_re(), z.try_im()) {
        (Ok(a), Ok(b)) => a.degree() <= EXPAND_MAX_DEGREE && b.degree() <= EXPAND_MAX_DEGREE,
        _ => false,
    }
}

/// Largest eigenvalue degree for which the minimal polynomials of $\operatorname{Re}\theta$
/// (degree up to $d(d-1)/2$) and $\operatorname{Im}\theta$ (up to $d(d-1)$) are computed.
pub const PARTS_MAX_DEGREE: usize = 4;

/// Largest real-field degree that [`JordanForm::real_form`] expands into by default.
pub const EXPAND_MAX_DEGREE: usize = 4;

/// Largest eigenvalue degree whose pair is expanded into its real field even on request
/// (`--expand`): the real field of a generic factor of degree $d$ has degree $d(d-1)$, found by
/// factoring a polynomial of that degree (degree 5, field 20: 0.6 s; degree 6, field 30: 16 s
/// for the companion matrix of $x^6 - x + 1$, and more than 60 s for a dense random 6x6).
pub const EXPAND_MAX_EIGENVALUE_DEGREE: usize = 5;

/// Bit size (numerator plus denominator) above which the parts of a root of degree 3 or 4
/// are not computed: the composed polynomials of degree up to 12 and their factorization
/// then cost seconds (a mutant with an entry `-1e-300` has 300-digit coefficients), and the
/// compact form is exact anyway.
pub const PARTS_MAX_BITS: u64 = 256;

/// Whether [`exact_parts`] computes $\operatorname{Re}\theta$ and $\operatorname{Im}\theta$
/// for a root of `p`: degree at most [`PARTS_MAX_DEGREE`], and for degree 3 or 4
/// coefficients of at most [`PARTS_MAX_BITS`] bits.
pub fn parts_affordable(p: &Poly<Q>) -> bool {
    p.deg() <= 2
        || (p.deg() <= PARTS_MAX_DEGREE
            && p.coeffs()
                .iter()
                .all(|c| c.numer().bits() + c.denom().bits() <= PARTS_MAX_BITS))
}

/// $\operatorname{Re}\theta$ and $\operatorname{Im}\theta$ as certified algebraic numbers
/// when [`parts_affordable`] (composed polynomials of degree $d(d-1)/2$ and
/// $d(d-1)$, factored), else `None`.
pub(crate) fn exact_parts(
    e: &super::Certified,
) -> (Option<AlgebraicNumber>, Option<AlgebraicNumber>) {
    if parts_affordable(&e.minpoly) {
        (e.number.try_re().ok(), e.number.try_im().ok())
    } else {
        (None, None)
    }
}
