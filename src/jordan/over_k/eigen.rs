//! Eigenvalues of a matrix over $K = \mathbb{Q}(\alpha)$: the factorization of $\chi_A$ over
//! $K$, the minimal polynomial over $\mathbb{Q}$ of the roots of each factor, and the exact
//! choice of the roots that belong to $A$.
//!
//! For $g$ monic irreducible over $K$ write $g = g_0 + \alpha g_1$ ($g_0, g_1 \in
//! \mathbb{Q}\[x\]$) and $\bar g = g_0 - \alpha g_1$ (the Galois conjugate). The minimal
//! polynomial over $\mathbb{Q}$ of a root of $g$ is $m = g$ when $g_1 = 0$, else
//! $m = g \bar g$ (it lies in $\mathbb{Q}\[x\]$, is divisible by the two distinct irreducible
//! $g, \bar g$ and divides their product). In the second case half of the roots of $m$ are
//! roots of $\bar g$: eigenvalues of $\bar A$, **not** of $A$. At a root $\rho$ of $m$,
//! $g_1(\rho) \ne 0$ ($g$ and $\bar g$ have no common root) and
//! $$R(\rho) = -g_0(\rho)/g_1(\rho) = \pm\alpha, \qquad R = -g_0\, g_1^{-1} \bmod m,$$
//! with $+\alpha$ exactly for the roots of $g$. The sign is decided by evaluating $R$ in
//! exact rational interval arithmetic on the isolating box of $\rho$, refined until the
//! enclosure excludes the other candidate ($|2\alpha| \ge 2$ apart); no floating point is
//! involved in the decision.

use crate::algebraic::{AlgebraicNumber, NfElem, NumberField, factor_over_number_field};
use crate::error::{Error, Result};
use crate::field::{Q, Quadratic, QuadraticField, Rational};
use crate::poly::Poly;
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

/// $K$ as the number field $\mathbb{Q}\[t\]/(t^2 - d)$ marked at $\alpha$.
fn as_number_field(k: &QuadraticField) -> NumberField {
    let d = Rational::from_integer(k.d().clone());
    let m = Poly::new(Q, vec![-d, Rational::zero(), Rational::one()]);
    let r = num_traits::ToPrimitive::to_f64(&k.d().abs())
        .unwrap_or(f64::MAX)
        .sqrt();
    let root = if k.is_real() { (r, 0.0) } else { (0.0, r) };
    NumberField::new_unchecked(&m, root)
}

fn to_nf(x: &Quadratic) -> NfElem {
    let mut v = vec![x.a.clone(), x.b.clone()];
    while v.last().is_some_and(|c| c.is_zero()) {
        v.pop();
    }
    NfElem(v)
}

fn from_nf(x: &NfElem) -> Quadratic {
    let c = |i: usize| x.0.get(i).cloned().unwrap_or_else(Rational::zero);
    Quadratic::new(c(0), c(1))
}

/// Monic irreducible factors of `f` over $K$ with multiplicities (Trager's norm method,
/// [`factor_over_number_field`]), sorted by degree then display.
///
/// # Errors
/// Those of [`factor_over_number_field`].
pub fn factor_over_k(f: &Poly<QuadraticField>) -> Result<Vec<(Poly<QuadraticField>, usize)>> {
    let k = f.field().clone();
    let nf = as_number_field(&k);
    let fk = Poly::new(nf.clone(), f.coeffs().iter().map(to_nf).collect());
    Ok(factor_over_number_field(&fk)?
        .into_iter()
        .map(|(g, e)| {
            (
                Poly::new(k.clone(), g.coeffs().iter().map(from_nf).collect()),
                e,
            )
        })
        .collect())
}

/// $(g_0, g_1)$ with $g = g_0 + \alpha g_1$.
fn split(g: &Poly<QuadraticField>) -> (Poly<Q>, Poly<Q>) {
    let g0 = Poly::new(Q, g.coeffs().iter().map(|c| c.a.clone()).collect());
    let g1 = Poly::new(Q, g.coeffs().iter().map(|c| c.b.clone()).collect());
    (g0, g1)
}

/// The minimal polynomial over $\mathbb{Q}$ of the roots of the monic irreducible `g`.
pub fn rational_minpoly(g: &Poly<QuadraticField>) -> Poly<Q> {
    let (g0, g1) = split(g);
    if g1.is_zero() {
        return g0;
    }
    let gb = Poly::new(
        g.field().clone(),
        g.coeffs().iter().map(|c| g.field().galois(c)).collect(),
    );
    let (n0, n1) = split(&g.mul(&gb));
    debug_assert!(n1.is_zero());
    n0.monic()
}

/// A closed rational interval.
#[derive(Clone, Debug)]
struct Iv(Rational, Rational);

impl Iv {
    fn point(x: Rational) -> Iv {
        Iv(x.clone(), x)
    }
    fn add(&self, o: &Iv) -> Iv {
        Iv(&self.0 + &o.0, &self.1 + &o.1)
    }
    fn sub(&self, o: &Iv) -> Iv {
        Iv(&self.0 - &o.1, &self.1 - &o.0)
    }
    fn mul(&self, o: &Iv) -> Iv {
        let p = [
            &self.0 * &o.0,
            &self.0 * &o.1,
            &self.1 * &o.0,
            &self.1 * &o.1,
        ];
        let lo = p.iter().min().cloned().unwrap_or_default();
        let hi = p.iter().max().cloned().unwrap_or_default();
        Iv(lo, hi)
    }
    /// `Some(true)` if every point is positive, `Some(false)` if every point is negative.
    fn sign(&self) -> Option<bool> {
        if self.0.is_positive() {
            Some(true)
        } else if self.1.is_negative() {
            Some(false)
        } else {
            None
        }
    }
}

/// An enclosure of `p(z)` for every `z` in the box `(re, im)` (rectangular interval Horner).
fn eval_box(p: &Poly<Q>, re: &Iv, im: &Iv) -> (Iv, Iv) {
    let zero = || Iv::point(Rational::zero());
    let (mut ar, mut ai) = (zero(), zero());
    for c in p.coeffs().iter().rev() {
        let nr = ar.mul(re).sub(&ai.mul(im)).add(&Iv::point(c.clone()));
        let ni = ar.mul(im).add(&ai.mul(re));
        ar = nr;
        ai = ni;
    }
    (ar, ai)
}

/// Does the root `z` of $m$ satisfy $R(z) = +\alpha$ (see the module docs)? Decided exactly
/// by interval evaluation on refined isolating regions.
///
/// # Errors
/// `Limit` when 40 refinements (down to width $2^{-400}$) do not decide (not expected:
/// the two candidates are at least 2 apart).
fn fixes_alpha(r: &Poly<Q>, z: &AlgebraicNumber, real_k: bool) -> Result<bool> {
    let mut z = z.clone();
    for step in 0..40 {
        let ((r0, r1), (i0, i1)) = z.bounding_box();
        let (vr, vi) = eval_box(r, &Iv(r0, r1), &Iv(i0, i1));
        // alpha = +sqrt(d) (real K) or +i sqrt(-d): the relevant part's sign
        if let Some(s) = if real_k { vr.sign() } else { vi.sign() } {
            return Ok(s);
        }
        let w = Rational::new(BigInt::one(), BigInt::one() << (10 * (step + 1)));
        z = z.refined(&w)?;
    }
    Err(Error::Limit(
        "could not separate the eigenvalues of A from those of its conjugate".into(),
    ))
}

/// Certified roots with their approximations.
pub type CertifiedRoots = Vec<(AlgebraicNumber, (f64, f64))>;

/// The roots of the monic irreducible `g` over $K$ (under the embedding fixing $\alpha$),
/// as certified algebraic numbers with approximations, real part descending.
///
/// # Errors
/// `Limit` from root isolation or from [`fixes_alpha`].
pub fn roots_of_factor(g: &Poly<QuadraticField>) -> Result<(Poly<Q>, CertifiedRoots)> {
    let m = rational_minpoly(g);
    let all = super::super::roots::certified_roots(&m)?;
    let (g0, g1) = split(g);
    if g1.is_zero() {
        return Ok((m, all));
    }
    // R = -g0 / g1 mod m
    let (one, s, _) = g1.rem(&m).xgcd(&m);
    if !one.is_one() {
        return Err(Error::Verification(format!(
            "g1 and the minimal polynomial {m} have a common factor"
        )));
    }
    let r = g0.mul(&s).neg().rem(&m);
    let real_k = g.field().is_real();
    let mut out = vec![];
    for (z, a) in all {
        if fixes_alpha(&r, &z, real_k)? {
            out.push((z, a));
        }
    }
    if out.len() != g.deg() {
        return Err(Error::Verification(format!(
            "{} of the roots of {m} are roots of {g} (expected {})",
            out.len(),
            g.deg()
        )));
    }
    Ok((m, out))
}
