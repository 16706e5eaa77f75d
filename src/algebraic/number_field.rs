//! General number fields $K = \mathbb{Q}\[t\]/(m(t))$ for an irreducible monic $m$.
//!
//! Elements are polynomials in $t$ of degree $< \deg m$ with rational coefficients
//! (canonical: reduced and without trailing zeros). Multiplication reduces modulo $m$;
//! the inverse comes from the extended Euclidean algorithm, $s a + u m = 1 \Rightarrow
//! a^{-1} = s$. A field carries a *marked embedding*: an approximation of the complex root
//! of $m$ that $t$ stands for, so elements can be approximated (and conjugated when the
//! field is closed under complex conjugation).
//!
//! | entry point | computes |
//! |---|---|
//! | [`NumberField::new`] | the field for a monic irreducible modulus and a root choice |
//! | [`NumberField::elem_from_poly`] | the class of a polynomial in $t$ |
//! | [`NumberField::generator`] | $t$ |

use super::AlgebraicNumber;
use crate::error::{Error, Result};
use crate::field::{Field, Q, Rational, lehmer, rational_to_f64};
use crate::poly::{Poly, fmt_poly};
use num_bigint::BigInt;
use num_traits::{One, Zero};
use std::fmt;
use std::sync::Arc;

/// Shared context of a number field.
#[derive(Debug)]
pub struct NumberFieldCtx {
    /// Monic irreducible modulus $m(t)$.
    pub modulus: Poly<Q>,
    /// Approximation `(re, im)` of the root $t$ stands for.
    pub root: (f64, f64),
    /// Variable name used in displays.
    pub var: String,
}

/// $\mathbb{Q}(\alpha)$ where $\alpha$ is a root of the monic irreducible `modulus`.
#[derive(Clone, Debug)]
pub struct NumberField(pub Arc<NumberFieldCtx>);

/// Exact equality: the same monic modulus and the same marked root. The marked root is the
/// root of the modulus nearest the stored approximation; when the two approximations differ,
/// the roots are isolated exactly ([`AlgebraicNumber::roots_of_irreducible`]) and compared
/// by index (no tolerance).
impl PartialEq for NumberField {
    fn eq(&self, other: &Self) -> bool {
        if Arc::ptr_eq(&self.0, &other.0) {
            return true;
        }
        if self.0.modulus != other.0.modulus {
            return false;
        }
        if self.0.root == other.0.root {
            return true;
        }
        match (self.marked_root_index(), other.marked_root_index()) {
            (Some(i), Some(j)) => i == j,
            _ => false,
        }
    }
}

/// An element of a [`NumberField`]: coefficients in $t$, low degree first.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct NfElem(pub Vec<Rational>);

impl NumberField {
    /// `Some(d)` when this is $\mathbb{Q}(\sqrt d)$ displayed with its radical: modulus
    /// $t^2 - d$ and variable [`crate::field::radical_text`]`(d)` (`sqrt(3)`, `sqrt(2)*i`,
    /// `i`). Its elements are then shown as every quadratic number is
    /// ([`crate::field::quadratic_display`]: `-6 + sqrt(1598)/10`, not
    /// `1/10*sqrt(1598) - 6`).
    pub fn radicand(&self) -> Option<num_bigint::BigInt> {
        let m = &self.0.modulus;
        if m.deg() != 2 || !m.coeff(1).is_zero() || !self.0.var.starts_with(['s', 'i']) {
            return None;
        }
        let d = -m.coeff(0);
        if !d.is_integer() {
            return None;
        }
        let d = d.to_integer();
        (crate::field::radical_text(&d) == self.0.var).then_some(d)
    }
    /// The field $\mathbb{Q}\[t\]/(m)$ with $t$ the root of $m$ near `root`.
    ///
    /// The modulus is made monic and checked irreducible over $\mathbb{Q}$
    /// ([`crate::algebraic::is_irreducible_q`]).
    ///
    /// # Errors
    /// `NotIrreducible` for a constant or reducible modulus.
    pub fn new(modulus: &Poly<Q>, root: (f64, f64)) -> Result<Self> {
        if !crate::algebraic::is_irreducible_q(modulus) {
            return Err(Error::NotIrreducible(modulus.monic().to_string()));
        }
        Ok(Self::new_unchecked(modulus, root))
    }
    /// As [`NumberField::new`] for a modulus the caller knows to be irreducible (e.g. a
    /// factor returned by [`crate::algebraic::factor_q`]); only made monic.
    pub fn new_unchecked(modulus: &Poly<Q>, root: (f64, f64)) -> Self {
        NumberField(Arc::new(NumberFieldCtx {
            modulus: modulus.monic(),
            root,
            var: "t".into(),
        }))
    }
    pub fn modulus(&self) -> &Poly<Q> {
        &self.0.modulus
    }
    pub fn degree(&self) -> usize {
        self.0.modulus.deg()
    }
    pub fn root_approx(&self) -> (f64, f64) {
        self.0.root
    }
    /// Index of the marked root among the exactly isolated roots of the modulus
    /// ([`AlgebraicNumber::roots_of_irreducible`], canonical order): the root nearest the
    /// stored approximation. `None` when the isolation fails (budget) or two roots are
    /// equally near.
    pub fn marked_root_index(&self) -> Option<usize> {
        let roots = AlgebraicNumber::roots_of_irreducible(&self.0.modulus).ok()?;
        let (xr, xi) = self.0.root;
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
    /// Invariants: the modulus is monic of degree at least 1 and the root approximation is
    /// finite. (Irreducibility is checked by [`NumberField::new`].)
    pub fn is_valid(&self) -> bool {
        let m = &self.0.modulus;
        m.deg() >= 1
            && m.coeff(m.deg()).is_one()
            && self.0.root.0.is_finite()
            && self.0.root.1.is_finite()
    }
    /// Is `a` a canonical element: fewer coefficients than the degree, no trailing zero?
    pub fn is_valid_elem(&self, a: &NfElem) -> bool {
        a.0.len() <= self.degree() && a.0.last().is_none_or(|c| !c.is_zero())
    }
    /// The element with coefficients `c` (low degree first) in the basis
    /// $1, t, \dots, t^{d-1}$, reduced modulo the modulus: the checked constructor.
    pub fn elem_from_coeffs(&self, c: Vec<Rational>) -> NfElem {
        self.reduce(c)
    }
    /// Coefficients of `a` in the basis $1, t, \dots, t^{d-1}$ (low degree first, trailing
    /// zeros dropped).
    pub fn elem_coeffs<'a>(&self, a: &'a NfElem) -> &'a [Rational] {
        &a.0
    }
    /// Display name of the generator (`t` unless set by the caller).
    pub fn var(&self) -> &str {
        &self.0.var
    }
    /// The generator $t$.
    pub fn generator(&self) -> NfElem {
        self.elem_from_poly(&Poly::x(Q))
    }
    /// The class of `p(t)`.
    pub fn elem_from_poly(&self, p: &Poly<Q>) -> NfElem {
        let r = if p.deg() >= self.degree() {
            p.rem(&self.0.modulus)
        } else {
            p.clone()
        };
        NfElem(r.into_coeffs())
    }
    /// The element as a polynomial in $t$.
    pub fn elem_to_poly(&self, a: &NfElem) -> Poly<Q> {
        Poly::new(Q, a.0.clone())
    }
    /// `a * b` for an integral modulus: $(s_a a)(s_b b)$ with the lcms $s_a, s_b$ of the
    /// denominators is an integer polynomial, reduced modulo the monic integral $m$ in
    /// integers, and each coefficient is divided by $s_a s_b$ once (one Lehmer gcd), instead
    /// of normalising a rational after every multiply-add.
    fn mul_integral(&self, a: &NfElem, b: &NfElem) -> NfElem {
        let (sa, ia) = integer_scaled(&a.0);
        let (sb, ib) = integer_scaled(&b.0);
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
        let m = self.0.modulus.coeffs();
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
        NfElem(v.into_iter().map(|x| lehmer::fraction(x, &den)).collect())
    }
    fn reduce(&self, mut v: Vec<Rational>) -> NfElem {
        let m = self.0.modulus.coeffs();
        let d = m.len() - 1;
        while v.len() > d {
            let c = v.pop().unwrap();
            if c.is_zero() {
                continue;
            }
            let off = v.len() - d;
            for j in 0..d {
                if !m[j].is_zero() {
                    v[off + j] = lehmer::sub(&v[off + j], &lehmer::mul(&c, &m[j]));
                }
            }
        }
        while v.last().is_some_and(|c| c.is_zero()) {
            v.pop();
        }
        NfElem(v)
    }
    /// Evaluates the element at the marked complex root, in f64 (always defined; the field
    /// trait's [`Field::approx`] wraps it in `Some`).
    pub fn approx(&self, a: &NfElem) -> (f64, f64) {
        let (xr, xi) = self.0.root;
        let (mut re, mut im) = (0.0, 0.0);
        for c in a.0.iter().rev() {
            let nr = re * xr - im * xi + rational_to_f64(c);
            let ni = re * xi + im * xr;
            re = nr;
            im = ni;
        }
        (re, im)
    }
}

impl fmt::Display for NumberField {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "QQ[t]/({})", self.0.modulus.to_string_var("t"))
    }
}

impl Field for NumberField {
    type Elem = NfElem;
    fn zero(&self) -> NfElem {
        NfElem(vec![])
    }
    fn one(&self) -> NfElem {
        NfElem(vec![Rational::one()])
    }
    fn is_zero(&self, a: &NfElem) -> bool {
        a.0.is_empty()
    }
    fn is_one(&self, a: &NfElem) -> bool {
        a.0.len() == 1 && a.0[0].is_one()
    }
    fn add(&self, a: &NfElem, b: &NfElem) -> NfElem {
        let n = a.0.len().max(b.0.len());
        let mut v: Vec<Rational> = (0..n)
            .map(|i| match (a.0.get(i), b.0.get(i)) {
                (Some(x), Some(y)) => lehmer::add(x, y),
                (Some(x), None) => x.clone(),
                (None, Some(y)) => y.clone(),
                _ => Rational::zero(),
            })
            .collect();
        while v.last().is_some_and(|c| c.is_zero()) {
            v.pop();
        }
        NfElem(v)
    }
    fn sub(&self, a: &NfElem, b: &NfElem) -> NfElem {
        self.add(a, &self.neg(b))
    }
    fn mul(&self, a: &NfElem, b: &NfElem) -> NfElem {
        if a.0.is_empty() || b.0.is_empty() {
            return NfElem(vec![]);
        }
        if a.0.len() == 1 {
            return NfElem(b.0.iter().map(|y| lehmer::mul(&a.0[0], y)).collect());
        }
        if b.0.len() == 1 {
            return NfElem(a.0.iter().map(|x| lehmer::mul(x, &b.0[0])).collect());
        }
        if self.0.modulus.coeffs().iter().all(|c| c.denom().is_one()) {
            return self.mul_integral(a, b);
        }
        let mut v = vec![Rational::zero(); a.0.len() + b.0.len() - 1];
        for (i, x) in a.0.iter().enumerate() {
            if x.is_zero() {
                continue;
            }
            for (j, y) in b.0.iter().enumerate() {
                if !y.is_zero() {
                    v[i + j] = lehmer::add(&v[i + j], &lehmer::mul(x, y));
                }
            }
        }
        self.reduce(v)
    }
    fn neg(&self, a: &NfElem) -> NfElem {
        NfElem(a.0.iter().map(|x| -x).collect())
    }
    fn inv(&self, a: &NfElem) -> Option<NfElem> {
        if a.0.is_empty() {
            return None;
        }
        if a.0.len() == 1 {
            return Some(NfElem(vec![a.0[0].recip()]));
        }
        let (g, s, _) = self.elem_to_poly(a).xgcd(&self.0.modulus);
        debug_assert!(g.is_one(), "modulus not irreducible");
        Some(self.elem_from_poly(&s))
    }
    fn from_rational(&self, q: &Rational) -> NfElem {
        if q.is_zero() {
            NfElem(vec![])
        } else {
            NfElem(vec![q.clone()])
        }
    }
    fn to_rational(&self, a: &NfElem) -> Option<Rational> {
        match a.0.len() {
            0 => Some(Rational::zero()),
            1 => Some(a.0[0].clone()),
            _ => None,
        }
    }
    fn fmt_elem(&self, a: &NfElem) -> String {
        match self.radicand() {
            Some(d) => {
                let c = |i: usize| a.0.get(i).cloned().unwrap_or_else(Rational::zero);
                crate::field::quadratic_display(&c(0), &c(1), &d)
            }
            None => fmt_poly(&Q, &a.0, &self.0.var),
        }
    }
    fn latex_elem(&self, a: &NfElem) -> String {
        match self.radicand() {
            Some(d) => {
                let c = |i: usize| a.0.get(i).cloned().unwrap_or_else(Rational::zero);
                crate::field::quadratic_latex(&c(0), &c(1), &d)
            }
            None => self.fmt_elem(a),
        }
    }
    fn approx(&self, a: &NfElem) -> Option<(f64, f64)> {
        Some(NumberField::approx(self, a))
    }
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

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn arithmetic() {
        // Q(cbrt 2)
        let k = NumberField::new(&Poly::from_i64s(&[-2, 0, 0, 1]), (1.2599, 0.0)).unwrap();
        let t = k.generator();
        let t3 = k.mul(&k.mul(&t, &t), &t);
        assert_eq!(t3, k.from_i64(2));
        let a = k.add(&t, &k.one());
        let ai = k.inv(&a).unwrap();
        assert!(k.is_one(&k.mul(&a, &ai)));
        assert_eq!(k.fmt_elem(&a), "t + 1");
        let (re, _) = k.approx(&a);
        assert!((re - 2.2599).abs() < 1e-3);
        assert!(NumberField::new(&Poly::from_i64s(&[1, 2, 1]), (0.0, 0.0)).is_err());
        assert!(NumberField::new(&Poly::from_i64s(&[1, 0, 4, 0, 1]), (0.0, 0.5)).is_ok());
        assert!(NumberField::new(&Poly::from_i64s(&[1, 0, 2, 0, 1]), (0.0, 1.0)).is_err());
    }

    #[test]
    fn products_match_the_polynomial_remainder() {
        // integral modulus (integer kernel) and a non-integral one (rational path): a b is
        // the remainder of the polynomial product, for fractions with unrelated denominators
        let r = |n: i64, d: i64| Rational::new(n.into(), d.into());
        let x5 = Poly::from_i64s(&[-3, 1, 0, 0, 0, 1]);
        let half = Poly::new(Q, vec![r(-1, 2), r(0, 1), r(1, 3), r(1, 1)]);
        for m in [x5, half] {
            let k = NumberField::new(&m, (1.0, 0.0)).unwrap();
            let mut seed = 7u64;
            let mut next = |lo: i64, hi: i64| {
                seed = seed
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                lo + ((seed >> 33) % (hi - lo + 1) as u64) as i64
            };
            for _ in 0..40 {
                let mut el = || {
                    let c: Vec<Rational> = (0..m.deg())
                        .map(|_| r(next(-50, 50) * next(0, 1), next(1, 12)))
                        .collect();
                    Poly::new(Q, c)
                };
                let (pa, pb) = (el(), el());
                let (a, b) = (k.elem_from_poly(&pa), k.elem_from_poly(&pb));
                assert_eq!(k.mul(&a, &b), k.elem_from_poly(&pa.mul(&pb)), "{pa} * {pb}");
            }
            // the zero product and a product with a one-coefficient element
            assert!(k.is_zero(&k.mul(&k.zero(), &k.generator())));
            assert_eq!(
                k.mul(&k.from_i64(3), &k.generator()).0,
                vec![r(0, 1), r(3, 1)]
            );
        }
    }
}
