//! The `Poly<K>` type and its arithmetic.

use crate::error::{Error, Result};
use crate::field::{Field, Q, Rational};

/// A dense univariate polynomial over the field `K`, coefficients low degree first.
///
/// Invariant: the last coefficient is non-zero (the zero polynomial has no coefficients),
/// so `==` is mathematical equality.
#[derive(Clone, Debug, PartialEq)]
pub struct Poly<K: Field> {
    field: K,
    coeffs: Vec<K::Elem>,
}

impl<K: Field> Poly<K> {
    /// From coefficients, low degree first (trailing zeros are removed).
    pub fn new(field: K, mut coeffs: Vec<K::Elem>) -> Self {
        while coeffs.last().is_some_and(|c| field.is_zero(c)) {
            coeffs.pop();
        }
        Poly { field, coeffs }
    }
    pub fn zero(field: K) -> Self {
        Poly {
            field,
            coeffs: vec![],
        }
    }
    pub fn one(field: K) -> Self {
        let one = field.one();
        Poly {
            field,
            coeffs: vec![one],
        }
    }
    pub fn constant(field: K, c: K::Elem) -> Self {
        Self::new(field, vec![c])
    }
    /// The monomial $c x^k$.
    pub fn monomial(field: K, c: K::Elem, k: usize) -> Self {
        let mut v = vec![field.zero(); k + 1];
        v[k] = c;
        Self::new(field, v)
    }
    /// The variable $x$.
    pub fn x(field: K) -> Self {
        let one = field.one();
        Self::monomial(field, one, 1)
    }
    pub fn field(&self) -> &K {
        &self.field
    }
    pub fn coeffs(&self) -> &[K::Elem] {
        &self.coeffs
    }
    pub fn into_coeffs(self) -> Vec<K::Elem> {
        self.coeffs
    }
    /// Coefficient of $x^i$ (zero beyond the degree).
    pub fn coeff(&self, i: usize) -> K::Elem {
        self.coeffs
            .get(i)
            .cloned()
            .unwrap_or_else(|| self.field.zero())
    }
    /// Degree; `None` for the zero polynomial.
    pub fn degree(&self) -> Option<usize> {
        self.coeffs.len().checked_sub(1)
    }
    /// Degree with `deg 0 = 0` (use only when zero is excluded or irrelevant).
    pub fn deg(&self) -> usize {
        self.coeffs.len().saturating_sub(1)
    }
    pub fn is_zero(&self) -> bool {
        self.coeffs.is_empty()
    }
    pub fn is_one(&self) -> bool {
        self.coeffs.len() == 1 && self.field.is_one(&self.coeffs[0])
    }
    pub fn is_constant(&self) -> bool {
        self.coeffs.len() <= 1
    }
    /// Leading coefficient (zero for the zero polynomial).
    pub fn lc(&self) -> K::Elem {
        self.coeffs
            .last()
            .cloned()
            .unwrap_or_else(|| self.field.zero())
    }
    pub fn is_monic(&self) -> bool {
        self.coeffs.last().is_some_and(|c| self.field.is_one(c))
    }
    pub fn add(&self, g: &Self) -> Self {
        let k = &self.field;
        let n = self.coeffs.len().max(g.coeffs.len());
        let v = (0..n)
            .map(|i| match (self.coeffs.get(i), g.coeffs.get(i)) {
                (Some(a), Some(b)) => k.add(a, b),
                (Some(a), None) => a.clone(),
                (None, Some(b)) => b.clone(),
                (None, None) => k.zero(),
            })
            .collect();
        Self::new(k.clone(), v)
    }
    pub fn neg(&self) -> Self {
        let k = &self.field;
        Poly {
            field: k.clone(),
            coeffs: self.coeffs.iter().map(|c| k.neg(c)).collect(),
        }
    }
    pub fn sub(&self, g: &Self) -> Self {
        self.add(&g.neg())
    }
    pub fn mul(&self, g: &Self) -> Self {
        let k = &self.field;
        if self.is_zero() || g.is_zero() {
            return Self::zero(k.clone());
        }
        let mut v = vec![k.zero(); self.coeffs.len() + g.coeffs.len() - 1];
        for (i, a) in self.coeffs.iter().enumerate() {
            if k.is_zero(a) {
                continue;
            }
            for (j, b) in g.coeffs.iter().enumerate() {
                k.mul_add_assign(&mut v[i + j], a, b);
            }
        }
        Self::new(k.clone(), v)
    }
    /// $c f$.
    pub fn scale(&self, c: &K::Elem) -> Self {
        let k = &self.field;
        Self::new(k.clone(), self.coeffs.iter().map(|a| k.mul(a, c)).collect())
    }
    /// $f^e$ by repeated squaring.
    pub fn pow(&self, e: u32) -> Self {
        crate::field::pow_by_squaring(self, e, Self::one(self.field.clone()), Self::mul)
    }
    /// The same polynomial over $\mathbb{Q}$ when every coefficient is rational.
    pub fn to_rational_poly(&self) -> Option<Poly<Q>> {
        let cs: Option<Vec<Rational>> = self
            .coeffs
            .iter()
            .map(|c| self.field.to_rational(c))
            .collect();
        Some(Poly::new(Q, cs?))
    }
    /// $x^k f$.
    pub fn shift(&self, k: usize) -> Self {
        if self.is_zero() {
            return self.clone();
        }
        let mut v = vec![self.field.zero(); k];
        v.extend(self.coeffs.iter().cloned());
        Poly {
            field: self.field.clone(),
            coeffs: v,
        }
    }
    /// Monic associate (zero stays zero).
    pub fn monic(&self) -> Self {
        match self.coeffs.last() {
            None => self.clone(),
            Some(l) => {
                let li = self.field.inv(l).expect("non-zero leading coefficient");
                self.scale(&li)
            }
        }
    }
    /// Division with remainder: $f = q g + r$, $\deg r < \deg g$.
    ///
    /// # Errors
    /// `DivisionByZero` when `g` is zero.
    pub fn divrem(&self, g: &Self) -> Result<(Self, Self)> {
        let k = &self.field;
        let dg = g.degree().ok_or(Error::DivisionByZero)?;
        let lci = k.inv(&g.lc()).ok_or(Error::DivisionByZero)?;
        let mut r = self.coeffs.clone();
        if r.len() <= dg {
            return Ok((Self::zero(k.clone()), self.clone()));
        }
        let mut q = vec![k.zero(); r.len() - dg];
        for i in (dg..r.len()).rev() {
            if k.is_zero(&r[i]) {
                continue;
            }
            let c = k.mul(&r[i], &lci);
            for (j, gj) in g.coeffs.iter().enumerate() {
                k.mul_sub_assign(&mut r[i - dg + j], &c, gj);
            }
            q[i - dg] = c;
        }
        r.truncate(dg);
        Ok((Self::new(k.clone(), q), Self::new(k.clone(), r)))
    }
    /// Remainder of division by a non-zero `g` (panics on zero `g`).
    pub fn rem(&self, g: &Self) -> Self {
        self.divrem(g).expect("division by zero polynomial").1
    }
    /// Quotient of division by a non-zero `g` (panics on zero `g`).
    pub fn quo(&self, g: &Self) -> Self {
        self.divrem(g).expect("division by zero polynomial").0
    }
    /// Exact quotient `f / g`; `None` when `g` does not divide `f` (or is zero).
    pub fn div_exact(&self, g: &Self) -> Option<Self> {
        let (q, r) = self.divrem(g).ok()?;
        r.is_zero().then_some(q)
    }
    /// Monic greatest common divisor (zero when both are zero).
    pub fn gcd(&self, g: &Self) -> Self {
        if let crate::field::Kernels::Table(t) = self.field.kernels()
            && !self.is_zero()
            && !g.is_zero()
            && let Some(c) = t.poly_gcd(&self.field, self.coeffs(), g.coeffs())
        {
            return Self::new(self.field.clone(), c);
        }
        let (mut a, mut b) = (self.clone(), g.clone());
        while !b.is_zero() {
            let r = a.rem(&b);
            a = b;
            b = r;
        }
        a.monic()
    }
    /// Extended gcd: `(g, s, t)` with monic `g = s f + t h`.
    pub fn xgcd(&self, h: &Self) -> (Self, Self, Self) {
        let k = self.field.clone();
        let (mut r0, mut r1) = (self.clone(), h.clone());
        let (mut s0, mut s1) = (Self::one(k.clone()), Self::zero(k.clone()));
        let (mut t0, mut t1) = (Self::zero(k.clone()), Self::one(k.clone()));
        while !r1.is_zero() {
            let (q, r) = r0.divrem(&r1).expect("non-zero divisor");
            r0 = std::mem::replace(&mut r1, r);
            let s2 = s0.sub(&q.mul(&s1));
            s0 = std::mem::replace(&mut s1, s2);
            let t2 = t0.sub(&q.mul(&t1));
            t0 = std::mem::replace(&mut t1, t2);
        }
        if r0.is_zero() {
            return (r0, s0, t0);
        }
        let li = k.inv(&r0.lc()).expect("non-zero");
        (r0.scale(&li), s0.scale(&li), t0.scale(&li))
    }
    /// Formal derivative.
    pub fn derivative(&self) -> Self {
        let k = &self.field;
        let v = self
            .coeffs
            .iter()
            .enumerate()
            .skip(1)
            .map(|(i, c)| k.mul(c, &k.from_i64(i as i64)))
            .collect();
        Self::new(k.clone(), v)
    }
    /// $f(a)$ by Horner's rule.
    pub fn eval(&self, a: &K::Elem) -> K::Elem {
        let k = &self.field;
        let mut acc = k.zero();
        for c in self.coeffs.iter().rev() {
            acc = k.add(&k.mul(&acc, a), c);
        }
        acc
    }
    /// Composition $f(g(x))$.
    pub fn compose(&self, g: &Self) -> Self {
        let mut acc = Self::zero(self.field.clone());
        for c in self.coeffs.iter().rev() {
            acc = acc
                .mul(g)
                .add(&Self::constant(self.field.clone(), c.clone()));
        }
        acc
    }
    /// Square-free factorization (Yun, characteristic zero): `f = lc * prod f_i^i` with
    /// monic, square-free, pairwise coprime `f_i`; returns the non-constant `(f_i, i)`.
    pub fn squarefree(&self) -> Vec<(Self, usize)> {
        let mut out = vec![];
        if self.degree().unwrap_or(0) == 0 {
            return out;
        }
        let f = self.monic();
        let df = f.derivative();
        let a = f.gcd(&df);
        // Yun: b_1 = f/a, d_1 = f'/a - b_1'; g_i = gcd(b_i, d_i) is the part of multiplicity i
        let mut b = f.quo(&a);
        let mut d = df.quo(&a).sub(&b.derivative());
        let mut i = 1;
        while b.deg() > 0 {
            let g = b.gcd(&d);
            if !g.is_one() {
                out.push((g.clone(), i));
            }
            let nb = b.quo(&g);
            d = d.quo(&g).sub(&nb.derivative());
            b = nb;
            i += 1;
        }
        out
    }
    /// Resultant $\mathrm{Res}(f, g)$ by the Euclidean remainder sequence over the field.
    pub fn resultant(&self, g: &Self) -> K::Elem {
        let k = self.field.clone();
        let (mut a, mut b) = (self.clone(), g.clone());
        if a.is_zero() || b.is_zero() {
            return k.zero();
        }
        let mut res = k.one();
        loop {
            let da = a.deg();
            let db = b.deg();
            if db == 0 {
                let lb = b.lc();
                let mut p = k.one();
                for _ in 0..da {
                    p = k.mul(&p, &lb);
                }
                return k.mul(&res, &p);
            }
            let r = a.rem(&b);
            if r.is_zero() {
                return k.zero();
            }
            let dr = r.deg();
            // Res(a,b) = (-1)^(da db) lc(b)^(da - dr) Res(b, r)
            let lb = b.lc();
            for _ in 0..(da - dr) {
                res = k.mul(&res, &lb);
            }
            if da % 2 == 1 && db % 2 == 1 {
                res = k.neg(&res);
            }
            a = b;
            b = r;
        }
    }
    /// Maps coefficients into another field.
    pub fn map<L: Field>(&self, to: &L, f: impl Fn(&K::Elem) -> L::Elem) -> Poly<L> {
        Poly::new(to.clone(), self.coeffs.iter().map(f).collect())
    }
}

impl Poly<Q> {
    /// From integer coefficients, low degree first.
    pub fn from_i64s(cs: &[i64]) -> Self {
        Poly::new(
            Q,
            cs.iter()
                .map(|&c| Rational::from_integer(c.into()))
                .collect(),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    fn p(cs: &[i64]) -> Poly<Q> {
        Poly::from_i64s(cs)
    }
    #[test]
    fn basics() {
        let f = p(&[1, 0, 4, 0, 1]);
        let g = p(&[2, 1]);
        let (q, r) = f.divrem(&g).unwrap();
        assert_eq!(q.mul(&g).add(&r), f);
        let (d, s, t) = f.xgcd(&g);
        assert!(d.is_one());
        assert_eq!(s.mul(&f).add(&t.mul(&g)), d);
        // (x-1)^2 (x+2)^3
        let h = p(&[-1, 1]).pow(2).mul(&p(&[2, 1]).pow(3));
        let sf = h.squarefree();
        assert_eq!(sf, vec![(p(&[-1, 1]), 2), (p(&[2, 1]), 3)]);
        // Res(x^2 - 2, x^2 - 3) = 1 ; Res(x - a, g) = g(a)
        assert_eq!(
            p(&[-2, 0, 1]).resultant(&p(&[-3, 0, 1])),
            Rational::from_integer(1.into())
        );
        assert_eq!(
            p(&[-2, 1]).resultant(&f),
            -f.eval(&Rational::from_integer(2.into())) * Rational::from_integer((-1).into())
        );
        assert_eq!(p(&[1, 1]).compose(&p(&[0, 0, 1])), p(&[1, 0, 1]));
    }
}
