//! Dense univariate polynomials over $\mathbb{Z}$.
//!
//! A [`ZPoly`] stores $f = \sum_i c_i x^i$ as `coeffs[i] = c_i`, low degree first, always
//! normalized (no trailing zero coefficients; the zero polynomial has no coefficients), so
//! `==` is equality of polynomials. It is the integer workhorse of factorization over
//! $\mathbb{Q}$ (see [`crate::poly::factor`]): by Gauss's lemma, factoring over $\mathbb{Q}$
//! reduces to factoring primitive integer polynomials.
//!
//! | entry point | computes |
//! |---|---|
//! | `+ - *` (by reference or value), [`ZPoly::scale`], [`ZPoly::pow`] | ring operations |
//! | [`ZPoly::content`], [`ZPoly::primitive_part`] | $f = \operatorname{cont}(f)\,\operatorname{pp}(f)$, $\operatorname{lc}(\operatorname{pp} f) > 0$ |
//! | [`ZPoly::derivative`], [`ZPoly::eval`] | $f'$, $f(a)$ |
//! | [`ZPoly::pseudo_divrem`] | $\operatorname{lc}(g)^{\deg f - \deg g + 1} f = q g + r$, $\deg r < \deg g$ |
//! | [`ZPoly::div_exact`] | $q$ with $f = q g$ over $\mathbb{Z}$, if it exists |
//! | [`ZPoly::gcd`] | $\gcd(f, g)$ over $\mathbb{Z}$ (subresultant PRS, modular coprimality shortcut) |
//!
//! `Display` writes `x^4 + 4*x^2 + 1`; [`ZPoly::display_with`] uses another variable name.

use super::Poly;
use crate::field::Q;
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;
use std::ops::{Add, Mul, Neg, Sub};

/// A dense integer polynomial, low degree first, without trailing zeros.
#[derive(Clone, Debug, PartialEq, Eq, Hash, Default)]
pub struct ZPoly {
    coeffs: Vec<BigInt>,
}

impl ZPoly {
    /// The polynomial $\sum_i c_i x^i$ from `coeffs` (low degree first); trailing zeros are
    /// dropped.
    pub fn new(mut coeffs: Vec<BigInt>) -> Self {
        while coeffs.last().is_some_and(|c| c.is_zero()) {
            coeffs.pop();
        }
        ZPoly { coeffs }
    }

    /// From machine integers, low degree first: `from_i64s(&[1, 0, 1])` is $x^2 + 1$.
    pub fn from_i64s(coeffs: &[i64]) -> Self {
        Self::new(coeffs.iter().map(|&c| BigInt::from(c)).collect())
    }

    /// The zero polynomial.
    pub fn zero() -> Self {
        ZPoly { coeffs: Vec::new() }
    }

    /// The constant polynomial 1.
    pub fn one() -> Self {
        Self::constant(BigInt::one())
    }

    /// The polynomial $x$.
    pub fn x() -> Self {
        Self::monomial(BigInt::one(), 1)
    }

    /// The constant polynomial `c`.
    pub fn constant(c: BigInt) -> Self {
        Self::new(vec![c])
    }

    /// $c x^k$.
    pub fn monomial(c: BigInt, k: usize) -> Self {
        let mut v = vec![BigInt::zero(); k + 1];
        v[k] = c;
        Self::new(v)
    }

    /// Coefficients, low degree first (empty for zero).
    pub fn coeffs(&self) -> &[BigInt] {
        &self.coeffs
    }

    /// Consumes `self`, returning the coefficients low degree first.
    pub fn into_coeffs(self) -> Vec<BigInt> {
        self.coeffs
    }

    /// The coefficient of $x^i$ (zero beyond the degree).
    pub fn coeff(&self, i: usize) -> BigInt {
        self.coeffs.get(i).cloned().unwrap_or_default()
    }

    /// True for the zero polynomial.
    pub fn is_zero(&self) -> bool {
        self.coeffs.is_empty()
    }

    /// True for the constant 1.
    pub fn is_one(&self) -> bool {
        self.coeffs.len() == 1 && self.coeffs[0].is_one()
    }

    /// The degree; `None` for the zero polynomial.
    pub fn degree(&self) -> Option<usize> {
        self.coeffs.len().checked_sub(1)
    }

    /// The degree, with the zero polynomial given degree 0 (convenient for constants).
    pub fn deg0(&self) -> usize {
        self.coeffs.len().saturating_sub(1)
    }

    /// The leading coefficient; zero for the zero polynomial.
    pub fn leading_coeff(&self) -> BigInt {
        self.coeffs.last().cloned().unwrap_or_default()
    }

    /// $\max_i |c_i|$ (zero for the zero polynomial).
    pub fn max_norm(&self) -> BigInt {
        self.coeffs
            .iter()
            .map(|c| c.abs())
            .max()
            .unwrap_or_default()
    }

    /// $\sum_i c_i^2 = \|f\|_2^2$.
    pub fn norm2_squared(&self) -> BigInt {
        self.coeffs.iter().map(|c| c * c).sum()
    }

    /// $c f$.
    pub fn scale(&self, c: &BigInt) -> Self {
        if c.is_zero() {
            return Self::zero();
        }
        ZPoly {
            coeffs: self.coeffs.iter().map(|a| a * c).collect(),
        }
    }

    /// The signed content: $\gcd$ of the coefficients with the sign of the leading
    /// coefficient, so that `f == f.primitive_part().scale(&f.content())`; zero for zero.
    pub fn content(&self) -> BigInt {
        let mut g = BigInt::zero();
        for c in self.coeffs.iter().rev() {
            g = g.gcd(c);
            if g.is_one() {
                break;
            }
        }
        if self.leading_coeff().is_negative() {
            -g
        } else {
            g
        }
    }

    /// The primitive part with positive leading coefficient (zero for zero).
    pub fn primitive_part(&self) -> Self {
        let c = self.content();
        if c.is_zero() || c.is_one() {
            return self.clone();
        }
        ZPoly {
            coeffs: self.coeffs.iter().map(|a| a / &c).collect(),
        }
    }

    /// $f'$.
    pub fn derivative(&self) -> Self {
        Self::new(super::zslice::derivative(&self.coeffs))
    }

    /// $f(a)$ by Horner's rule.
    pub fn eval(&self, a: &BigInt) -> BigInt {
        let mut acc = BigInt::zero();
        for c in self.coeffs.iter().rev() {
            acc = acc * a + c;
        }
        acc
    }

    /// $f^e$ by repeated squaring ($f^0 = 1$).
    pub fn pow(&self, e: u32) -> Self {
        crate::field::pow_by_squaring(self, e, Self::one(), |a, b| a * b)
    }

    /// Pseudo-division: $(q, r)$ with $\operatorname{lc}(g)^{\delta} f = q g + r$,
    /// $\delta = \max(\deg f - \deg g + 1, 0)$ and $\deg r < \deg g$.
    ///
    /// # Panics
    /// If `g` is zero (a caller bug in this low-level kernel).
    pub fn pseudo_divrem(&self, g: &ZPoly) -> (ZPoly, ZPoly) {
        let dg = g
            .degree()
            .expect("pseudo_divrem: division by the zero polynomial");
        let lc = g.leading_coeff();
        let Some(df) = self.degree().filter(|&d| d >= dg) else {
            return (Self::zero(), self.clone());
        };
        let mut r = self.coeffs.clone();
        let mut q = vec![BigInt::zero(); df - dg + 1];
        for k in (0..=df - dg).rev() {
            let t = r[k + dg].clone();
            for c in q.iter_mut() {
                *c *= &lc;
            }
            q[k] = t.clone();
            for c in r.iter_mut().take(k + dg) {
                *c *= &lc;
            }
            r[k + dg] = BigInt::zero();
            if !t.is_zero() {
                for (j, gj) in g.coeffs.iter().enumerate().take(dg) {
                    r[k + j] -= &t * gj;
                }
            }
        }
        r.truncate(dg);
        (Self::new(q), Self::new(r))
    }

    /// The exact quotient $f / g$ over $\mathbb{Z}$, or `None` when $g \nmid f$ in
    /// $\mathbb{Z}\lbrack x\rbrack$ (also when `g` is zero).
    pub fn div_exact(&self, g: &ZPoly) -> Option<ZPoly> {
        let dg = g.degree()?;
        if self.is_zero() {
            return Some(Self::zero());
        }
        let df = self.degree()?;
        if df < dg {
            return None;
        }
        let lc = g.leading_coeff();
        // cheap necessary conditions: leading and (first nonzero) trailing coefficients
        if !self.leading_coeff().is_multiple_of(&lc) {
            return None;
        }
        let mut r = self.coeffs.clone();
        let mut q = vec![BigInt::zero(); df - dg + 1];
        for k in (0..=df - dg).rev() {
            let top = std::mem::take(&mut r[k + dg]);
            if top.is_zero() {
                continue;
            }
            let (t, rem) = top.div_rem(&lc);
            if !rem.is_zero() {
                return None;
            }
            for (j, gj) in g.coeffs.iter().enumerate().take(dg) {
                r[k + j] -= &t * gj;
            }
            q[k] = t;
        }
        if r.iter().any(|c| !c.is_zero()) {
            return None;
        }
        Some(Self::new(q))
    }

    /// $\gcd(f, g)$ in $\mathbb{Z}\lbrack x\rbrack$: the gcd of the contents times the primitive gcd,
    /// with positive leading coefficient; $\gcd(0, 0) = 0$.
    ///
    /// # Algorithm
    /// If the images modulo a prime not dividing both leading coefficients are coprime, the
    /// primitive gcd is 1; otherwise the subresultant PRS (Collins; Brown–Traub) followed by
    /// the primitive part.
    pub fn gcd(&self, g: &ZPoly) -> ZPoly {
        if self.is_zero() {
            return g.abs_lc();
        }
        if g.is_zero() {
            return self.abs_lc();
        }
        let c = self.content().gcd(&g.content());
        let (mut a, mut b) = (self.primitive_part(), g.primitive_part());
        if a.deg0() < b.deg0() {
            std::mem::swap(&mut a, &mut b);
        }
        if b.deg0() == 0 || coprime_mod_some_prime(&a, &b) {
            return Self::constant(c);
        }
        subresultant_gcd(a, b).primitive_part().scale(&c)
    }

    /// `self` or `-self`, whichever has a nonnegative leading coefficient.
    fn abs_lc(&self) -> ZPoly {
        if self.leading_coeff().is_negative() {
            -self
        } else {
            self.clone()
        }
    }
}

/// Subresultant PRS for primitive `a`, `b` with $\deg a \ge \deg b \ge 1$; returns the last
/// nonzero remainder (an associate of the gcd over $\mathbb{Q}$).
fn subresultant_gcd(mut a: ZPoly, mut b: ZPoly) -> ZPoly {
    let mut g = BigInt::one();
    let mut h = BigInt::one();
    loop {
        let delta = (a.deg0() - b.deg0()) as u32;
        let (_, r) = a.pseudo_divrem(&b);
        if r.is_zero() {
            return b;
        }
        if r.deg0() == 0 {
            return ZPoly::one();
        }
        let den = &g * num_traits::pow(h.clone(), delta as usize);
        a = b;
        b = ZPoly::new(r.coeffs.iter().map(|c| c / &den).collect());
        g = a.leading_coeff();
        // h = g^delta / h^(delta - 1)
        h = if delta == 0 {
            h
        } else {
            num_traits::pow(g.clone(), delta as usize)
                / num_traits::pow(h.clone(), delta as usize - 1)
        };
    }
}

impl Ord for ZPoly {
    /// By degree, then coefficients from the leading one down.
    fn cmp(&self, other: &Self) -> Ordering {
        self.coeffs
            .len()
            .cmp(&other.coeffs.len())
            .then_with(|| self.coeffs.iter().rev().cmp(other.coeffs.iter().rev()))
    }
}

impl PartialOrd for ZPoly {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

fn add_coeffs(a: &[BigInt], b: &[BigInt], sub: bool) -> ZPoly {
    let n = a.len().max(b.len());
    let mut v = Vec::with_capacity(n);
    for i in 0..n {
        let x = a.get(i);
        let y = b.get(i);
        v.push(match (x, y, sub) {
            (Some(x), Some(y), false) => x + y,
            (Some(x), Some(y), true) => x - y,
            (Some(x), None, _) => x.clone(),
            (None, Some(y), false) => y.clone(),
            (None, Some(y), true) => -y,
            (None, None, _) => BigInt::zero(),
        });
    }
    ZPoly::new(v)
}

fn mul_coeffs(a: &[BigInt], b: &[BigInt]) -> ZPoly {
    ZPoly::new(super::zslice::mul(a, b))
}

macro_rules! binop {
    ($tr:ident, $m:ident, $body:expr) => {
        impl $tr<&ZPoly> for &ZPoly {
            type Output = ZPoly;
            fn $m(self, rhs: &ZPoly) -> ZPoly {
                $body(&self.coeffs, &rhs.coeffs)
            }
        }
        impl $tr<ZPoly> for ZPoly {
            type Output = ZPoly;
            fn $m(self, rhs: ZPoly) -> ZPoly {
                $body(&self.coeffs, &rhs.coeffs)
            }
        }
        impl $tr<&ZPoly> for ZPoly {
            type Output = ZPoly;
            fn $m(self, rhs: &ZPoly) -> ZPoly {
                $body(&self.coeffs, &rhs.coeffs)
            }
        }
    };
}

binop!(Add, add, |a, b| add_coeffs(a, b, false));
binop!(Sub, sub, |a, b| add_coeffs(a, b, true));
binop!(Mul, mul, mul_coeffs);

impl Neg for &ZPoly {
    type Output = ZPoly;
    fn neg(self) -> ZPoly {
        ZPoly {
            coeffs: self.coeffs.iter().map(|c| -c).collect(),
        }
    }
}

impl Neg for ZPoly {
    type Output = ZPoly;
    fn neg(self) -> ZPoly {
        -&self
    }
}

/// True when some prime $p$ not dividing both leading coefficients gives coprime images
/// modulo $p$, which proves $\gcd(f, g) = 1$ over $\mathbb{Q}$. `false` means "unknown".
pub(crate) fn coprime_mod_some_prime(f: &ZPoly, g: &ZPoly) -> bool {
    let (df, dg) = (f.deg0(), g.deg0());
    // three primes just above 10^6
    for p in [1_000_003, 1_000_033, 1_000_037] {
        let k = crate::poly::fp::Zp::new(p);
        let (a, b) = (k.reduce(f.coeffs()), k.reduce(g.coeffs()));
        // the degree of one image must be kept, so that gcd mod p is an image of a multiple of
        // the gcd over Z of at least its degree
        if a.len() != df + 1 && b.len() != dg + 1 {
            continue;
        }
        if k.gcd(&a, &b).len() == 1 {
            return true;
        }
    }
    false
}

impl ZPoly {
    /// The primitive integer polynomial with positive leading coefficient proportional to
    /// `p` (zero for zero).
    pub fn from_poly_q(p: &Poly<Q>) -> ZPoly {
        ZPoly::new(super::zslice::from_poly_q(p))
    }
    /// $f / \operatorname{lc}(f)$ over $\mathbb{Q}$ (zero stays zero).
    pub fn to_monic_q(&self) -> Poly<Q> {
        super::zslice::to_monic_q(self.coeffs())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(c: &[i64]) -> ZPoly {
        ZPoly::from_i64s(c)
    }

    #[test]
    fn display_examples() {
        assert_eq!(p(&[1, 0, 4, 0, 1]).to_string(), "x^4 + 4*x^2 + 1");
        assert_eq!(p(&[1, -3, -1]).to_string(), "-x^2 - 3*x + 1");
        assert_eq!(p(&[0, 2]).to_string(), "2*x");
        assert_eq!(p(&[-1]).to_string(), "-1");
        assert_eq!(p(&[]).to_string(), "0");
        assert_eq!(p(&[1, 0, 1]).display_with("s").to_string(), "s^2 + 1");
    }

    #[test]
    fn divisions_and_gcd() {
        let f = p(&[1, 0, 1]);
        let g = p(&[-2, 1]);
        let fg = &f * &g;
        assert_eq!(fg.div_exact(&g), Some(f.clone()));
        assert_eq!(fg.div_exact(&p(&[1, 1])), None);
        let (q, r) = p(&[1, 2, 3, 4]).pseudo_divrem(&p(&[1, 2]));
        let lhs = p(&[1, 2, 3, 4]).scale(&BigInt::from(8));
        assert_eq!(lhs, &q * &p(&[1, 2]) + r);
        let a = &(&f * &g) * &p(&[3, 5]);
        let b = &(&f * &g) * &p(&[7, 1, 1]);
        assert_eq!(a.gcd(&b), fg);
        assert_eq!(
            a.scale(&BigInt::from(6)).gcd(&b.scale(&BigInt::from(4))),
            fg.scale(&BigInt::from(2))
        );
        assert_eq!(p(&[2, 4]).content(), BigInt::from(2));
        assert_eq!(p(&[2, -4]).content(), BigInt::from(-2));
        assert_eq!(p(&[2, -4]).primitive_part(), p(&[-1, 2]));
    }
}
