//! Sparse multivariate polynomials over $\mathbb{Z}$ (and over $\mathbb{Q}$ as content times a
//! primitive integer polynomial): arithmetic, gcd, resultants, factorization.
//!
//! An [`MPoly`] in $k \le$ [`MAX_VARS`] variables $x_0, \dots, x_{k-1}$ stores its terms as
//! `(monomial, coefficient)` pairs with nonzero [`BigInt`] coefficients, sorted by the
//! **lexicographic** order $x_0 > x_1 > \dots$, largest first. A monomial packs the exponent
//! vector into one `u128` (variable 0 in the most significant field, [`width`] bits per
//! variable), so comparing monomials is comparing integers and multiplying them is adding.
//! Lex order serves the recursive algorithms (gcd, resultant, factorization view $f$ as a
//! polynomial in a main variable with polynomial coefficients). The representation is
//! canonical, so `==` is equality of polynomials. Variable *names* live outside the polynomial
//! (`&[String]`, as in SymPy's `ring` / FLINT's `mpoly_ctx`).
//!
//! | entry point | computes |
//! |---|---|
//! | [`MPoly::add`], [`MPoly::sub`], [`MPoly::mul`], [`MPoly::pow`] | ring operations (an `i128` accumulator when the coefficients are small) |
//! | [`MPoly::div_exact`] | $q$ with $f = q g$ in $\mathbb{Z}\lbrack x\rbrack$, if it exists |
//! | [`MPoly::eval_var`], [`MPoly::eval_all`], [`MPoly::shift_var`] | $f\vert_{x_i = a}$, $f(a)$, $f\vert_{x_i = x_i + a}$ |
//! | [`MPoly::derivative`], [`MPoly::content`], [`MPoly::primitive_part`] | $\partial f / \partial x_i$, $f = \operatorname{cont}(f) \operatorname{pp}(f)$ |
//! | [`gcd::gcd`] | $\gcd(f, g)$: Brown's modular gcd with cofactors ([`brown`]), else heuristic gcd (SymPy `heugcd`), else subresultant PRS in a main variable |
//! | [`resultant::resultant`], [`resultant::discriminant`] | $\operatorname{Res}_{x_i}(f, g)$, $\operatorname{Disc}_{x_i}(f)$ |
//! | [`factor::factor`] | $f = c \prod f_j^{e_j}$, $f_j$ irreducible over $\mathbb{Q}$ |
//! | [`parse::parse_mpoly`] | `m*u^2 - 3*cr` into a [`QPoly`] and its variables |
//!
//! **Why hand-written.** `feanor-math` (the one maintained Rust crate with multivariate
//! polynomials) has its own ring framework and integer type and no multivariate factorization
//! over $\mathbb{Z}$; we need exact gcd/factorization on `num-bigint` integers that plugs into
//! our [`crate::field::Field`] trait, so the kernels here are our own (staged as in FLINT's
//! `fmpz_mpoly_gcd` / SymPy's `euclidtools`: cheap heuristic first, exact fallback; Wang-style
//! evaluation, univariate Zassenhaus ([`crate::poly::factor`]) and Hensel lifting).

pub(crate) mod arith;
pub(crate) mod bounds;
pub mod brown;
pub(crate) mod display;
pub mod factor;
pub mod gcd;
mod hensel;
pub mod interp;
pub(crate) mod modp;
pub(crate) mod monomap;
pub(crate) mod parse;
pub mod probe;
pub mod resultant;

pub use factor::{Factorization, factor};
pub use gcd::gcd;
pub use parse::{parse_mpoly, parse_mpoly_in};

use crate::field::Rational;
use crate::poly::zpoly::ZPoly;
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};

/// Most variables a polynomial may have (each exponent then has 8 bits).
pub const MAX_VARS: usize = 16;

/// Bits per exponent for `nvars` variables: $\min(32, \lfloor 128 / k \rfloor)$.
pub fn width(nvars: usize) -> u32 {
    if nvars == 0 {
        32
    } else {
        (128 / nvars as u32).min(32)
    }
}

/// Largest exponent representable with `nvars` variables.
pub fn max_exponent(nvars: usize) -> u32 {
    let w = width(nvars);
    if w >= 32 { u32::MAX } else { (1u32 << w) - 1 }
}

/// A sparse polynomial in $\mathbb{Z}\lbrack x_0, \dots, x_{k-1}\rbrack$, lex order, canonical.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct MPoly {
    nvars: usize,
    /// Nonzero terms, monomials strictly decreasing.
    terms: Vec<(u128, BigInt)>,
}

/// A polynomial over $\mathbb{Q}$: `content * prim` with `prim` primitive of positive leading
/// coefficient (or zero, with content 0).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct QPoly {
    pub content: Rational,
    pub prim: MPoly,
}

impl QPoly {
    /// Splits an integer polynomial times a rational.
    pub fn new(c: Rational, f: MPoly) -> Self {
        if c.is_zero() || f.is_zero() {
            return QPoly {
                content: Rational::zero(),
                prim: MPoly::zero(f.nvars),
            };
        }
        let (fc, fp) = f.content_primitive();
        QPoly {
            content: c * Rational::from_integer(fc),
            prim: fp,
        }
    }
    pub fn is_zero(&self) -> bool {
        self.prim.is_zero()
    }
    /// `content * prim` when the content is an integer.
    pub fn to_integer_poly(&self) -> Option<MPoly> {
        self.content
            .is_integer()
            .then(|| self.prim.scale(self.content.numer()))
    }
}

impl MPoly {
    /// Builds a polynomial from arbitrary terms (combined, zeros dropped, sorted).
    ///
    /// # Panics
    /// If `nvars > MAX_VARS` (a caller bug; parsers check first).
    pub fn from_terms(nvars: usize, mut terms: Vec<(u128, BigInt)>) -> Self {
        assert!(nvars <= MAX_VARS, "too many variables");
        terms.sort_by_key(|a| std::cmp::Reverse(a.0));
        let mut out: Vec<(u128, BigInt)> = Vec::with_capacity(terms.len());
        for (m, c) in terms {
            match out.last_mut() {
                Some((lm, lc)) if *lm == m => *lc += c,
                _ => out.push((m, c)),
            }
        }
        out.retain(|(_, c)| !c.is_zero());
        MPoly { nvars, terms: out }
    }
    /// From already sorted (strictly decreasing), nonzero terms.
    pub(crate) fn from_sorted(nvars: usize, terms: Vec<(u128, BigInt)>) -> Self {
        debug_assert!(terms.windows(2).all(|w| w[0].0 > w[1].0));
        debug_assert!(terms.iter().all(|t| !t.1.is_zero()));
        MPoly { nvars, terms }
    }
    /// From exponent vectors.
    pub fn from_exps(nvars: usize, terms: &[(&[u32], i64)]) -> Self {
        let t = terms
            .iter()
            .map(|(e, c)| (pack(nvars, e), BigInt::from(*c)))
            .collect();
        Self::from_terms(nvars, t)
    }
    pub fn zero(nvars: usize) -> Self {
        MPoly {
            nvars,
            terms: Vec::new(),
        }
    }
    pub fn one(nvars: usize) -> Self {
        Self::constant(nvars, BigInt::one())
    }
    pub fn constant(nvars: usize, c: BigInt) -> Self {
        if c.is_zero() {
            return Self::zero(nvars);
        }
        MPoly {
            nvars,
            terms: vec![(0, c)],
        }
    }
    /// The variable $x_i$.
    pub fn var(nvars: usize, i: usize) -> Self {
        MPoly {
            nvars,
            terms: vec![(1u128 << shift(nvars, i), BigInt::one())],
        }
    }
    pub fn nvars(&self) -> usize {
        self.nvars
    }
    pub fn terms(&self) -> &[(u128, BigInt)] {
        &self.terms
    }
    pub fn len(&self) -> usize {
        self.terms.len()
    }
    pub fn is_empty(&self) -> bool {
        self.terms.is_empty()
    }
    pub fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }
    pub fn is_one(&self) -> bool {
        self.terms.len() == 1 && self.terms[0].0 == 0 && self.terms[0].1.is_one()
    }
    /// Constant (including zero)?
    pub fn is_constant(&self) -> bool {
        self.terms.is_empty() || (self.terms.len() == 1 && self.terms[0].0 == 0)
    }
    /// The constant value when [`MPoly::is_constant`].
    pub fn to_constant(&self) -> Option<BigInt> {
        match self.terms.as_slice() {
            [] => Some(BigInt::zero()),
            [(0, c)] => Some(c.clone()),
            _ => None,
        }
    }
    /// Leading coefficient (lex); zero for the zero polynomial.
    pub fn lc(&self) -> BigInt {
        self.terms
            .first()
            .map_or_else(BigInt::zero, |t| t.1.clone())
    }
    /// Leading monomial (lex).
    pub fn lm(&self) -> Option<u128> {
        self.terms.first().map(|t| t.0)
    }
    /// Exponent of $x_i$ in a packed monomial.
    pub fn exp(&self, m: u128, i: usize) -> u32 {
        exp(self.nvars, m, i)
    }
    /// Exponent vector of a packed monomial.
    pub fn exps(&self, m: u128) -> Vec<u32> {
        (0..self.nvars).map(|i| exp(self.nvars, m, i)).collect()
    }
    /// $\deg_{x_i} f$ (`None` for zero).
    pub fn degree(&self, i: usize) -> Option<u32> {
        self.terms.iter().map(|(m, _)| self.exp(*m, i)).max()
    }
    /// $\deg_{x_i} f$, 0 for the zero polynomial.
    pub fn deg(&self, i: usize) -> u32 {
        self.degree(i).unwrap_or(0)
    }
    /// Degrees in every variable, into a fixed array (no allocation; entries past `nvars`
    /// are 0).
    pub fn degrees_array(&self) -> [u32; MAX_VARS] {
        let mut d = [0; MAX_VARS];
        for (m, _) in &self.terms {
            for (i, di) in d.iter_mut().enumerate().take(self.nvars) {
                *di = (*di).max(self.exp(*m, i));
            }
        }
        d
    }
    /// Degrees in every variable.
    pub fn degrees(&self) -> Vec<u32> {
        let mut d = vec![0; self.nvars];
        for (m, _) in &self.terms {
            for (i, di) in d.iter_mut().enumerate() {
                *di = (*di).max(self.exp(*m, i));
            }
        }
        d
    }
    /// Total degree (0 for zero).
    pub fn total_degree(&self) -> u32 {
        self.terms
            .iter()
            .map(|(m, _)| (0..self.nvars).map(|i| self.exp(*m, i)).sum::<u32>())
            .max()
            .unwrap_or(0)
    }
    /// Variables that occur.
    pub fn vars_used(&self) -> Vec<usize> {
        let d = self.degrees();
        (0..self.nvars).filter(|&i| d[i] > 0).collect()
    }
    /// Largest absolute value of a coefficient.
    pub fn max_norm(&self) -> BigInt {
        self.terms
            .iter()
            .map(|t| t.1.abs())
            .max()
            .unwrap_or_else(BigInt::zero)
    }
    /// Integer content with the sign of the leading coefficient ($0$ for zero).
    pub fn content(&self) -> BigInt {
        let mut g = BigInt::zero();
        for (_, c) in &self.terms {
            g = g.gcd(c);
            if g.is_one() {
                break;
            }
        }
        if self.lc().is_negative() { -g } else { g }
    }
    /// `(content, primitive part)`; the primitive part has a positive leading coefficient.
    pub fn content_primitive(&self) -> (BigInt, MPoly) {
        let c = self.content();
        if c.is_zero() || c.is_one() {
            return (c, self.clone());
        }
        (c.clone(), self.div_integer(&c))
    }
    /// Primitive part (positive leading coefficient).
    pub fn primitive_part(&self) -> MPoly {
        self.content_primitive().1
    }
    /// Exact division by an integer (every coefficient must be a multiple).
    pub fn div_integer(&self, c: &BigInt) -> MPoly {
        MPoly {
            nvars: self.nvars,
            terms: self.terms.iter().map(|(m, a)| (*m, a / c)).collect(),
        }
    }
    /// Multiplication by an integer.
    pub fn scale(&self, c: &BigInt) -> MPoly {
        if c.is_zero() {
            return Self::zero(self.nvars);
        }
        MPoly {
            nvars: self.nvars,
            terms: self.terms.iter().map(|(m, a)| (*m, a * c)).collect(),
        }
    }
    /// `-f`.
    pub fn neg(&self) -> MPoly {
        MPoly {
            nvars: self.nvars,
            terms: self.terms.iter().map(|(m, a)| (*m, -a)).collect(),
        }
    }
    /// `f` with positive leading coefficient.
    pub fn abs_lc(&self) -> MPoly {
        if self.lc().is_negative() {
            self.neg()
        } else {
            self.clone()
        }
    }
    /// The same polynomial in `n >= nvars` variables (new variables appended, unused).
    pub fn extend_vars(&self, n: usize) -> MPoly {
        assert!(n >= self.nvars && n <= MAX_VARS);
        if n == self.nvars {
            return self.clone();
        }
        let t = self
            .terms
            .iter()
            .map(|(m, c)| (pack(n, &self.exps(*m)), c.clone()))
            .collect();
        Self::from_sorted(n, t)
    }
    /// Renames variables: variable `i` becomes variable `map[i]` of an `n`-variable ring.
    pub fn remap(&self, n: usize, map: &[usize]) -> MPoly {
        let t = self
            .terms
            .iter()
            .map(|(m, c)| {
                let mut e = vec![0; n];
                for (i, &j) in map.iter().enumerate() {
                    e[j] += self.exp(*m, i);
                }
                (pack(n, &e), c.clone())
            })
            .collect();
        Self::from_terms(n, t)
    }
    /// As a polynomial in $x_i$: coefficients (polynomials free of $x_i$), low degree first.
    pub fn to_univariate(&self, i: usize) -> Vec<MPoly> {
        let d = self.deg(i) as usize;
        let sh = shift(self.nvars, i);
        let mask = !(((1u128 << width(self.nvars)) - 1) << sh);
        let mut out: Vec<Vec<(u128, BigInt)>> = vec![Vec::new(); d + 1];
        for (m, c) in &self.terms {
            out[self.exp(*m, i) as usize].push((m & mask, c.clone()));
        }
        out.into_iter()
            .map(|t| Self::from_terms(self.nvars, t))
            .collect()
    }
    /// Inverse of [`MPoly::to_univariate`].
    pub fn from_univariate(nvars: usize, i: usize, cs: &[MPoly]) -> MPoly {
        let sh = shift(nvars, i);
        let mut t = Vec::new();
        for (k, c) in cs.iter().enumerate() {
            for (m, a) in &c.terms {
                t.push((m + ((k as u128) << sh), a.clone()));
            }
        }
        Self::from_terms(nvars, t)
    }
    /// Leading coefficient in $x_i$ (a polynomial free of $x_i$).
    pub fn lc_in(&self, i: usize) -> MPoly {
        self.to_univariate(i)
            .pop()
            .unwrap_or_else(|| Self::zero(self.nvars))
    }
    /// The dense univariate polynomial in $x_i$ when no other variable occurs.
    pub fn to_zpoly(&self, i: usize) -> Option<ZPoly> {
        let d = self.deg(i) as usize;
        let mut cs = vec![BigInt::zero(); d + 1];
        for (m, c) in &self.terms {
            let e = self.exp(*m, i);
            if *m != (e as u128) << shift(self.nvars, i) {
                return None;
            }
            cs[e as usize] = c.clone();
        }
        Some(ZPoly::new(cs))
    }
    /// A univariate polynomial placed in variable $x_i$.
    pub fn from_zpoly(nvars: usize, i: usize, f: &ZPoly) -> MPoly {
        let sh = shift(nvars, i);
        let t = f
            .coeffs()
            .iter()
            .enumerate()
            .rev()
            .filter(|(_, c)| !c.is_zero())
            .map(|(k, c)| ((k as u128) << sh, c.clone()))
            .collect();
        Self::from_sorted(nvars, t)
    }
}

/// Bit offset of variable `i`.
pub(crate) fn shift(nvars: usize, i: usize) -> u32 {
    width(nvars) * (nvars - 1 - i) as u32
}

/// Exponent of variable `i` in `m`.
pub(crate) fn exp(nvars: usize, m: u128, i: usize) -> u32 {
    let w = width(nvars);
    ((m >> shift(nvars, i)) & ((1u128 << w) - 1)) as u32
}

/// Packs an exponent vector.
///
/// # Panics
/// If an exponent exceeds [`max_exponent`].
pub fn pack(nvars: usize, e: &[u32]) -> u128 {
    let mut m = 0u128;
    for (i, &ei) in e.iter().enumerate().take(nvars) {
        assert!(ei <= max_exponent(nvars), "exponent too large");
        m |= (ei as u128) << shift(nvars, i);
    }
    m
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn packing() {
        let f = MPoly::from_exps(3, &[(&[1, 0, 2], 3), (&[0, 5, 0], -1), (&[1, 0, 2], 1)]);
        assert_eq!(f.len(), 2);
        assert_eq!(f.lc(), BigInt::from(4));
        assert_eq!(f.degrees(), vec![1, 5, 2]);
        assert_eq!(f.total_degree(), 5);
        let u = f.to_univariate(1);
        assert_eq!(u.len(), 6);
        assert_eq!(MPoly::from_univariate(3, 1, &u), f);
    }
}
