//! The relative extension $E = K\[t\]/(g)$ of a quadratic field $K = \mathbb{Q}(\alpha)$
//! ($\alpha = i$ or $\sqrt d$) by a monic irreducible $g \in K\[x\]$, as a [`Field`].
//!
//! Elements are polynomials $\sum_{i < \deg g} c_i t^i$ with $c_i \in K$ (canonical: reduced
//! modulo $g$, no trailing zeros). Multiplication reduces modulo $g$; the inverse comes from
//! the extended Euclidean algorithm over $K$. The field carries a *marked embedding*: $\alpha$
//! keeps its value in $K$ ($i$, or $\sqrt d > 0$) and $t$ goes to one root $\theta$ of $g$
//! (its approximation `root`), so elements have approximations; displays use the root's
//! symbol (`r<k>`) or, when $\theta = a_0 + s\sqrt f$ with rational $a_0, s$ (a rational
//! quadratic $g$), the radical: `u + v*sqrt(f)` with $u, v \in K$.

use crate::field::quadratic::fmt_pair;
use crate::field::{Field, Quadratic, QuadraticField, Rational};
use crate::poly::{Poly, fmt_poly};
use std::fmt;
use std::sync::Arc;

/// Shared context of a relative extension.
#[derive(Debug)]
pub struct RelCtx {
    /// The base field $K$.
    pub k: QuadraticField,
    /// Monic irreducible modulus $g \in K\[x\]$.
    pub modulus: Poly<QuadraticField>,
    /// Approximation `(re, im)` of the root $t$ stands for.
    pub root: (f64, f64),
    /// Display name of $t$.
    pub var: String,
    /// $t = a_0 + s\sqrt f$ with rational $a_0, s$ and square-free $f$, when known: elements
    /// display as `u + v*sqrt(f)`.
    pub radical: Option<(Rational, Rational, num_bigint::BigInt)>,
}

/// $E = K\[t\]/(g)$ marked at one root of $g$ (see the module docs).
#[derive(Clone, Debug)]
pub struct RelField(pub Arc<RelCtx>);

/// An element of a [`RelField`]: coefficients in $t$ over $K$, low degree first.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct RelElem(pub Vec<Quadratic>);

/// Same modulus and the same marked root approximation (fields are built once per
/// component and root, so this is identity in practice).
impl PartialEq for RelField {
    fn eq(&self, other: &Self) -> bool {
        Arc::ptr_eq(&self.0, &other.0)
            || (self.0.modulus == other.0.modulus && self.0.root == other.0.root)
    }
}

impl RelField {
    /// $K\[t\]/(g)$ for a monic irreducible `g` marked at the root near `root`.
    pub fn new(g: &Poly<QuadraticField>, root: (f64, f64), var: &str) -> Self {
        RelField(Arc::new(RelCtx {
            k: g.field().clone(),
            modulus: g.monic(),
            root,
            var: var.into(),
            radical: None,
        }))
    }
    /// The same field marked at another root, with a display variable and radical form.
    pub fn marked(
        &self,
        root: (f64, f64),
        var: &str,
        radical: Option<(Rational, Rational, num_bigint::BigInt)>,
    ) -> Self {
        RelField(Arc::new(RelCtx {
            k: self.0.k.clone(),
            modulus: self.0.modulus.clone(),
            root,
            var: var.into(),
            radical,
        }))
    }
    /// The base field $K$.
    pub fn base(&self) -> &QuadraticField {
        &self.0.k
    }
    /// The modulus $g$.
    pub fn modulus(&self) -> &Poly<QuadraticField> {
        &self.0.modulus
    }
    /// $[E : K] = \deg g$.
    pub fn degree(&self) -> usize {
        self.0.modulus.deg()
    }
    /// The generator $t$ (for $\deg g = 1$ the root itself, an element of $K$).
    pub fn generator(&self) -> RelElem {
        self.from_poly(&Poly::x(self.0.k.clone()))
    }
    /// The image of an element of $K$.
    pub fn from_base(&self, c: &Quadratic) -> RelElem {
        if self.0.k.is_zero(c) {
            RelElem(vec![])
        } else {
            RelElem(vec![c.clone()])
        }
    }
    /// The class of `p(t)`.
    pub fn from_poly(&self, p: &Poly<QuadraticField>) -> RelElem {
        self.reduce(p.coeffs().to_vec())
    }
    /// Coefficients reduced modulo the monic $g$ (top down, skipping zero coefficients of
    /// $g$), without trailing zeros.
    fn reduce(&self, mut v: Vec<Quadratic>) -> RelElem {
        let k = &self.0.k;
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
        RelElem(v)
    }
    /// The element as a polynomial in $t$ over $K$.
    pub fn to_poly(&self, a: &RelElem) -> Poly<QuadraticField> {
        Poly::new(self.0.k.clone(), a.0.clone())
    }
    /// `c * a` for `c` in $K$.
    pub fn scale(&self, c: &Quadratic, a: &RelElem) -> RelElem {
        let k = &self.0.k;
        if k.is_zero(c) {
            return RelElem(vec![]);
        }
        RelElem(a.0.iter().map(|x| k.mul(c, x)).collect())
    }
    /// `Some(c)` when `a` lies in $K$.
    pub fn to_base(&self, a: &RelElem) -> Option<Quadratic> {
        match a.0.len() {
            0 => Some(self.0.k.zero()),
            1 => Some(a.0[0].clone()),
            _ => None,
        }
    }
    /// Approximation under the marked embedding.
    pub fn approx(&self, a: &RelElem) -> (f64, f64) {
        let (xr, xi) = self.0.root;
        let (mut re, mut im) = (0.0, 0.0);
        for c in a.0.iter().rev() {
            let (cr, ci) = self.0.k.approx(c);
            let nr = re * xr - im * xi + cr;
            let ni = re * xi + im * xr + ci;
            re = nr;
            im = ni;
        }
        (re, im)
    }
}

impl fmt::Display for RelField {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}[t]/({})",
            self.0.k,
            fmt_poly(&self.0.k, self.0.modulus.coeffs(), "t")
        )
    }
}

/// `x` in parentheses when it is a sum or difference (for a coefficient before a product).
fn paren(x: String) -> String {
    if x[1..].contains([' ', '+']) || x[1..].contains('-') {
        format!("({x})")
    } else {
        x
    }
}

impl Field for RelField {
    type Elem = RelElem;
    fn zero(&self) -> RelElem {
        RelElem(vec![])
    }
    fn one(&self) -> RelElem {
        RelElem(vec![self.0.k.one()])
    }
    fn is_zero(&self, a: &RelElem) -> bool {
        a.0.is_empty()
    }
    fn is_one(&self, a: &RelElem) -> bool {
        a.0.len() == 1 && self.0.k.is_one(&a.0[0])
    }
    fn add(&self, a: &RelElem, b: &RelElem) -> RelElem {
        let k = &self.0.k;
        let n = a.0.len().max(b.0.len());
        let mut v: Vec<Quadratic> = (0..n)
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
        RelElem(v)
    }
    fn sub(&self, a: &RelElem, b: &RelElem) -> RelElem {
        self.add(a, &self.neg(b))
    }
    fn mul(&self, a: &RelElem, b: &RelElem) -> RelElem {
        if a.0.is_empty() || b.0.is_empty() {
            return RelElem(vec![]);
        }
        if a.0.len() == 1 {
            return self.scale(&a.0[0], b);
        }
        if b.0.len() == 1 {
            return self.scale(&b.0[0], a);
        }
        let k = &self.0.k;
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
    fn neg(&self, a: &RelElem) -> RelElem {
        RelElem(a.0.iter().map(|x| self.0.k.neg(x)).collect())
    }
    fn inv(&self, a: &RelElem) -> Option<RelElem> {
        if a.0.is_empty() {
            return None;
        }
        if a.0.len() == 1 {
            return self.0.k.inv(&a.0[0]).map(|c| RelElem(vec![c]));
        }
        let (g, s, _) = self.to_poly(a).xgcd(&self.0.modulus);
        debug_assert!(g.is_one(), "modulus not irreducible over K");
        Some(self.from_poly(&s))
    }
    fn from_rational(&self, q: &Rational) -> RelElem {
        self.from_base(&self.0.k.from_rational(q))
    }
    fn to_rational(&self, a: &RelElem) -> Option<Rational> {
        self.to_base(a).and_then(|c| self.0.k.to_rational(&c))
    }
    fn fmt_elem(&self, a: &RelElem) -> String {
        let k = &self.0.k;
        if let Some((a0, s, f)) = &self.0.radical {
            // c0 + c1 (a0 + s sqrt f) = (c0 + a0 c1) + (s c1) sqrt f
            let c0 = a.0.first().cloned().unwrap_or_else(|| k.zero());
            let c1 = a.0.get(1).cloned().unwrap_or_else(|| k.zero());
            let u = k.add(&c0, &k.mul(&k.from_rational(a0), &c1));
            let v = k.mul(&k.from_rational(s), &c1);
            let rad = super::super::roots::radical_text(f);
            return match (k.to_rational(&u), k.to_rational(&v)) {
                (Some(u), Some(v)) => fmt_pair(&u, &v, &rad),
                _ if k.is_zero(&v) => k.fmt_elem(&u),
                _ => {
                    // u + v sqrt f, written "u - w sqrt f" when v = -w displays with a sign
                    let neg = k.fmt_elem(&v).starts_with('-');
                    let w = if neg { k.neg(&v) } else { v };
                    let wt = match k.to_rational(&w) {
                        Some(q) if q == Rational::from_integer(1.into()) => rad,
                        _ => format!("{}*{rad}", paren(k.fmt_elem(&w))),
                    };
                    let op = if neg { "-" } else { "+" };
                    if k.is_zero(&u) {
                        if neg { format!("-{wt}") } else { wt }
                    } else {
                        format!("{} {op} {wt}", k.fmt_elem(&u))
                    }
                }
            };
        }
        fmt_poly(k, &a.0, &self.0.var)
    }
    fn approx(&self, a: &RelElem) -> Option<(f64, f64)> {
        Some(RelField::approx(self, a))
    }
}
