//! Simple algebraic extensions $E = F\[t\]/(g)$ of any exact field $F$ by a monic irreducible
//! $g \in F\[x\]$, as a [`Field`]: one type for the number fields $\mathbb{Q}\[t\]/(m)$
//! ([`crate::algebraic::NumberField`] $=$ `Ext<Q>`) and the relative extensions
//! $K\[t\]/(g)$ of a quadratic field $K$ (`Ext<QuadraticField>`).
//!
//! Elements are polynomials $\sum_{i < \deg g} c_i t^i$ with $c_i \in F$ (canonical: reduced
//! modulo $g$, no trailing zeros). Multiplication reduces modulo $g$; the inverse comes from
//! the extended Euclidean algorithm over $F$, $s a + u g = 1 \Rightarrow a^{-1} = s$; the
//! norm is $N_{E/F}(a) = \operatorname{res}(g, a)$ (monic $g$). The field carries a *marked
//! embedding* (the isolating data of the root $\theta$ that $t$ stands for): $F$ keeps its own
//! embedding and $t \mapsto \theta$ (its approximation `root`), so elements have
//! approximations; over $\mathbb{Q}$ the marked root is told from its conjugates exactly
//! ([`Ext::marked_root_index`]). Over $\mathbb{Q}$ with an integral modulus the product runs
//! in integers (`ext_q`).
//!
//! Displays use the variable (`t`, a root symbol `r<k>`), the radical when the field is
//! $\mathbb{Q}(\sqrt d)$ named by its radical ([`Ext::radicand`]), or, when
//! $\theta = a_0 + s\sqrt f$ with rational $a_0, s$, `u + v*sqrt(f)` with $u, v \in F$.

use crate::field::{Field, Rational};
use crate::poly::Poly;
use num_bigint::BigInt;
use num_traits::Zero;
use std::sync::Arc;

/// $t = a_0 + s\sqrt f$ with rational $a_0, s$ and square-free $f$.
pub type Radical = (Rational, Rational, BigInt);

/// Shared context of an extension.
#[derive(Debug)]
pub struct ExtCtx<F: Field> {
    /// The base field $F$.
    pub base: F,
    /// Monic irreducible modulus $g \in F\[x\]$.
    pub modulus: Poly<F>,
    /// Approximation `(re, im)` of the root $t$ stands for.
    pub root: (f64, f64),
    /// Display name of $t$.
    pub var: String,
    /// The radical form of $t$, when known: elements display as `u + v*sqrt(f)`.
    pub radical: Option<Radical>,
}

/// $E = F\[t\]/(g)$ marked at one root of $g$ (see the module docs).
#[derive(Clone, Debug)]
pub struct Ext<F: Field>(pub Arc<ExtCtx<F>>);

/// An element of an [`Ext`]: coefficients in $t$ over $F$, low degree first.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct ExtElem<E>(pub Vec<E>);

/// Exact equality: the same monic modulus and the same marked root. Over $\mathbb{Q}$, when
/// the two approximations differ, the roots are isolated exactly and compared by index (no
/// tolerance); over other bases the approximations must agree (fields are built once per
/// component and root, so this is identity in practice).
impl<F: Field> PartialEq for Ext<F> {
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

impl<F: Field> Ext<F> {
    /// $F\[t\]/(g)$ for a `g` the caller knows to be irreducible (only made monic), marked at
    /// the root near `root` and displayed with variable `var`.
    pub fn with_var(g: &Poly<F>, root: (f64, f64), var: &str) -> Self {
        Ext(Arc::new(ExtCtx {
            base: g.field().clone(),
            modulus: g.monic(),
            root,
            var: var.into(),
            radical: None,
        }))
    }
    /// The same field marked at another root, with a display variable and radical form.
    pub fn marked(&self, root: (f64, f64), var: &str, radical: Option<Radical>) -> Self {
        Ext(Arc::new(ExtCtx {
            base: self.0.base.clone(),
            modulus: self.0.modulus.clone(),
            root,
            var: var.into(),
            radical,
        }))
    }
    /// The base field $F$.
    pub fn base(&self) -> &F {
        &self.0.base
    }
    /// The modulus $g$.
    pub fn modulus(&self) -> &Poly<F> {
        &self.0.modulus
    }
    /// $[E : F] = \deg g$.
    pub fn degree(&self) -> usize {
        self.0.modulus.deg()
    }
    /// Approximation of the marked root.
    pub fn root_approx(&self) -> (f64, f64) {
        self.0.root
    }
    /// Display name of the generator (`t` unless set by the caller).
    pub fn var(&self) -> &str {
        &self.0.var
    }
    /// The generator $t$ (for $\deg g = 1$ the root itself, an element of $F$).
    pub fn generator(&self) -> ExtElem<F::Elem> {
        self.from_poly(&Poly::x(self.0.base.clone()))
    }
    /// The image of an element of $F$.
    pub fn from_base(&self, c: &F::Elem) -> ExtElem<F::Elem> {
        if self.0.base.is_zero(c) {
            ExtElem(vec![])
        } else {
            ExtElem(vec![c.clone()])
        }
    }
    /// `Some(c)` when `a` lies in $F$.
    pub fn to_base(&self, a: &ExtElem<F::Elem>) -> Option<F::Elem> {
        match a.0.len() {
            0 => Some(self.0.base.zero()),
            1 => Some(a.0[0].clone()),
            _ => None,
        }
    }
    /// The class of `p(t)`.
    pub fn from_poly(&self, p: &Poly<F>) -> ExtElem<F::Elem> {
        self.reduce(p.coeffs().to_vec())
    }
    /// The element with coefficients `c` (low degree first) in the basis
    /// $1, t, \dots, t^{d-1}$, reduced modulo the modulus: the checked constructor.
    pub fn from_coeffs(&self, c: Vec<F::Elem>) -> ExtElem<F::Elem> {
        self.reduce(c)
    }
    /// Coefficients of `a` in the basis $1, t, \dots, t^{d-1}$ (low degree first, trailing
    /// zeros dropped).
    pub fn coeffs<'a>(&self, a: &'a ExtElem<F::Elem>) -> &'a [F::Elem] {
        &a.0
    }
    /// The element as a polynomial in $t$ over $F$.
    pub fn to_poly(&self, a: &ExtElem<F::Elem>) -> Poly<F> {
        Poly::new(self.0.base.clone(), a.0.clone())
    }
    /// `c * a` for `c` in $F$.
    pub fn scale(&self, c: &F::Elem, a: &ExtElem<F::Elem>) -> ExtElem<F::Elem> {
        let k = &self.0.base;
        if k.is_zero(c) {
            return ExtElem(vec![]);
        }
        ExtElem(a.0.iter().map(|x| k.mul(c, x)).collect())
    }
    /// The norm $N_{E/F}(a) = \prod_j \sigma_j(a) = \operatorname{res}(g, a)$ ($g$ monic).
    pub fn norm(&self, a: &ExtElem<F::Elem>) -> F::Elem {
        let k = &self.0.base;
        match a.0.len() {
            0 => k.zero(),
            1 => crate::field::pow_by_squaring(&a.0[0], self.degree() as u32, k.one(), |x, y| {
                k.mul(x, y)
            }),
            _ => self.0.modulus.resultant(&self.to_poly(a)),
        }
    }
    /// Is `a` a canonical element: fewer coefficients than the degree, no trailing zero?
    pub fn is_valid_elem(&self, a: &ExtElem<F::Elem>) -> bool {
        a.0.len() <= self.degree() && a.0.last().is_none_or(|c| !self.0.base.is_zero(c))
    }
    /// Index of the marked root among the exactly isolated roots of a rational modulus
    /// ([`super::AlgebraicNumber::roots_of_irreducible`], canonical order): the root nearest
    /// the stored approximation. `None` when the modulus has a coefficient outside $\mathbb{Q}$, when the
    /// isolation fails (budget) or two roots are equally near.
    pub fn marked_root_index(&self) -> Option<usize> {
        let k = &self.0.base;
        let m: Option<Vec<Rational>> = self
            .0
            .modulus
            .coeffs()
            .iter()
            .map(|c| k.to_rational(c))
            .collect();
        let m = Poly::new(crate::field::Q, m?);
        super::ext_q::marked_root_index(&m, self.0.root)
    }
    /// `Some(d)` when this is $\mathbb{Q}(\sqrt d)$ displayed with its radical: modulus
    /// $t^2 - d$ with rational $d$ and variable [`crate::field::radical_text`]`(d)`
    /// (`sqrt(3)`, `sqrt(2)*i`, `i`). Its elements are then shown as every quadratic number
    /// is ([`crate::report::display::quadratic_display`]: `-6 + sqrt(1598)/10`, not
    /// `1/10*sqrt(1598) - 6`).
    pub fn radicand(&self) -> Option<BigInt> {
        let m = &self.0.modulus;
        let k = &self.0.base;
        if m.deg() != 2 || !k.is_zero(&m.coeff(1)) || !self.0.var.starts_with(['s', 'i']) {
            return None;
        }
        let d = -k.to_rational(&m.coeff(0))?;
        if !d.is_integer() {
            return None;
        }
        let d = d.to_integer();
        (crate::field::radical_text(&d) == self.0.var).then_some(d)
    }
    /// Coefficients reduced modulo the monic $g$ (top down, skipping zero coefficients of
    /// $g$), without trailing zeros.
    fn reduce(&self, mut v: Vec<F::Elem>) -> ExtElem<F::Elem> {
        let k = &self.0.base;
        let g = self.0.modulus.coeffs();
        let d = g.len() - 1;
        while v.len() > d {
            let c = v.pop().expect("longer than d");
            if k.is_zero(&c) {
                continue;
            }
            let off = v.len() - d;
            for (j, gj) in g.iter().enumerate().take(d) {
                if !k.is_zero(gj) {
                    k.mul_sub_assign(&mut v[off + j], &c, gj);
                }
            }
        }
        while v.last().is_some_and(|c| k.is_zero(c)) {
            v.pop();
        }
        ExtElem(v)
    }
    /// Approximation under the marked embedding (Horner at the marked root); `NaN` parts
    /// when the base has no embedding.
    pub fn approx(&self, a: &ExtElem<F::Elem>) -> (f64, f64) {
        let (xr, xi) = self.0.root;
        let (mut re, mut im) = (0.0, 0.0);
        for c in a.0.iter().rev() {
            let (cr, ci) = self.0.base.approx(c).unwrap_or((f64::NAN, f64::NAN));
            let nr = re * xr - im * xi + cr;
            let ni = re * xi + im * xr + ci;
            re = nr;
            im = ni;
        }
        (re, im)
    }
    /// `(c0, c1, d)` for $a = c_0 + c_1 \sqrt d$ with rational $c_0, c_1$ in a field named
    /// by its radical ([`Ext::radicand`]).
    pub(crate) fn radical_pair(
        &self,
        a: &ExtElem<F::Elem>,
    ) -> Option<(Rational, Rational, BigInt)> {
        let d = self.radicand()?;
        let k = &self.0.base;
        let c = |i: usize| match a.0.get(i) {
            Some(x) => k.to_rational(x),
            None => Some(Rational::zero()),
        };
        Some((c(0)?, c(1)?, d))
    }
}

impl<F: Field> Field for Ext<F> {
    type Elem = ExtElem<F::Elem>;
    fn zero(&self) -> Self::Elem {
        ExtElem(vec![])
    }
    fn one(&self) -> Self::Elem {
        ExtElem(vec![self.0.base.one()])
    }
    fn is_zero(&self, a: &Self::Elem) -> bool {
        a.0.is_empty()
    }
    fn is_one(&self, a: &Self::Elem) -> bool {
        a.0.len() == 1 && self.0.base.is_one(&a.0[0])
    }
    fn add(&self, a: &Self::Elem, b: &Self::Elem) -> Self::Elem {
        let k = &self.0.base;
        let n = a.0.len().max(b.0.len());
        let mut v: Vec<F::Elem> = (0..n)
            .map(|i| match (a.0.get(i), b.0.get(i)) {
                (Some(x), Some(y)) => k.add(x, y),
                (Some(x), None) => x.clone(),
                (None, Some(y)) => y.clone(),
                _ => k.zero(),
            })
            .collect();
        while v.last().is_some_and(|c| k.is_zero(c)) {
            v.pop();
        }
        ExtElem(v)
    }
    fn sub(&self, a: &Self::Elem, b: &Self::Elem) -> Self::Elem {
        self.add(a, &self.neg(b))
    }
    fn mul(&self, a: &Self::Elem, b: &Self::Elem) -> Self::Elem {
        if a.0.is_empty() || b.0.is_empty() {
            return ExtElem(vec![]);
        }
        if a.0.len() == 1 {
            return self.scale(&a.0[0], b);
        }
        if b.0.len() == 1 {
            return self.scale(&b.0[0], a);
        }
        let k = &self.0.base;
        if let Some(p) = k.mul_mod_poly(self.0.modulus.coeffs(), &a.0, &b.0) {
            return ExtElem(p);
        }
        let mut v = vec![k.zero(); a.0.len() + b.0.len() - 1];
        for (i, x) in a.0.iter().enumerate() {
            if k.is_zero(x) {
                continue;
            }
            for (j, y) in b.0.iter().enumerate() {
                if !k.is_zero(y) {
                    k.mul_add_assign(&mut v[i + j], x, y);
                }
            }
        }
        self.reduce(v)
    }
    fn neg(&self, a: &Self::Elem) -> Self::Elem {
        ExtElem(a.0.iter().map(|x| self.0.base.neg(x)).collect())
    }
    fn inv(&self, a: &Self::Elem) -> Option<Self::Elem> {
        if a.0.is_empty() {
            return None;
        }
        if a.0.len() == 1 {
            return self.0.base.inv(&a.0[0]).map(|c| ExtElem(vec![c]));
        }
        let (g, s, _) = self.to_poly(a).xgcd(&self.0.modulus);
        debug_assert!(g.is_one(), "modulus not irreducible over the base");
        Some(self.from_poly(&s))
    }
    fn from_rational(&self, q: &Rational) -> Self::Elem {
        self.from_base(&self.0.base.from_rational(q))
    }
    fn to_rational(&self, a: &Self::Elem) -> Option<Rational> {
        self.to_base(a).and_then(|c| self.0.base.to_rational(&c))
    }
    fn elem_value(&self, a: &Self::Elem) -> Option<crate::field::ElemValue> {
        let k = &self.0.base;
        let vals = |c: &[F::Elem]| {
            c.iter()
                .map(|x| k.elem_value(x))
                .collect::<Option<Vec<_>>>()
        };
        Some(crate::field::ElemValue::Ext {
            coeffs: vals(&a.0)?,
            generator: Box::new(crate::field::Generator {
                modulus: vals(self.0.modulus.coeffs())?,
                root: self.0.root,
                name: self.0.var.clone(),
                radical: self.0.radical.clone(),
            }),
        })
    }
    fn approx(&self, a: &Self::Elem) -> Option<(f64, f64)> {
        let z = Ext::approx(self, a);
        (!z.0.is_nan()).then_some(z)
    }
}
