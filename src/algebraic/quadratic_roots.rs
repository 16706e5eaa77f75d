//! The roots of a polynomial irreducible over a quadratic field $K = \mathbb{Q}(\alpha)$,
//! $\alpha = \sqrt d$ or $i\sqrt{-d}$, chosen exactly among those of its minimal polynomial
//! over $\mathbb{Q}$.
//!
//! For $g$ monic irreducible over $K$ write $g = g_0 + \alpha g_1$ ($g_0, g_1 \in
//! \mathbb{Q}\[x\]$) and $\bar g = g_0 - \alpha g_1$ (the Galois conjugate). The minimal
//! polynomial over $\mathbb{Q}$ of a root of $g$ is $m = g$ when $g_1 = 0$, else
//! $m = g \bar g$. In the second case half of the roots of $m$ are roots of $\bar g$ (for a
//! characteristic polynomial: eigenvalues of $\bar A$, **not** of $A$). At a root $\rho$ of
//! $m$, $g_1(\rho) \ne 0$ ($g$ and $\bar g$ have no common root) and
//! $$R(\rho) = -g_0(\rho)/g_1(\rho) = \pm\alpha, \qquad R = -g_0\, g_1^{-1} \bmod m,$$
//! with $+\alpha$ exactly for the roots of $g$. The sign is decided by evaluating $R$ in
//! exact rational interval arithmetic on the isolating box of $\rho$, refined until the
//! enclosure excludes the other candidate ($|2\alpha| \ge 2$ apart); no floating point is
//! involved in the decision.
//!
//! | entry point | computes |
//! |---|---|
//! | [`rational_minpoly`] | the minimal polynomial over $\mathbb{Q}$ of the roots of $g$ |
//! | [`roots_of_quadratic_factor`] | the roots of $g$ among the certified roots of $m$ |
//!
//! Used by the Jordan form over $K$ (eigenvalues of $A$) and by `tf` over $K$ (poles and
//! zeros).

use super::AlgebraicNumber;
use crate::error::{Error, Result};
use crate::field::{Q, QuadraticField, Rational, lehmer};
use crate::poly::Poly;
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

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
        Iv(lehmer::add(&self.0, &o.0), lehmer::add(&self.1, &o.1))
    }
    fn sub(&self, o: &Iv) -> Iv {
        Iv(lehmer::sub(&self.0, &o.1), lehmer::sub(&self.1, &o.0))
    }
    fn mul(&self, o: &Iv) -> Iv {
        let p = [
            lehmer::mul(&self.0, &o.0),
            lehmer::mul(&self.0, &o.1),
            lehmer::mul(&self.1, &o.0),
            lehmer::mul(&self.1, &o.1),
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

/// The entries of `all` (every root of [`rational_minpoly`]`(g)`, each with a payload) that
/// are roots of `g` under the embedding fixing $\alpha$, in their order. Exact: see the module
/// docs.
///
/// # Errors
/// `Limit` when 40 refinements do not decide (not expected); `Verification` when the count of
/// roots found differs from $\deg g$.
///
/// # Examples
/// ```
/// use exactlti::algebraic::{AlgebraicNumber, rational_minpoly, roots_of_quadratic_factor};
/// use exactlti::field::{Field, QuadraticField};
/// use exactlti::poly::Poly;
/// // g = x^2 - i over Q(i): its roots are (1 + i)/sqrt(2) and -(1 + i)/sqrt(2), not those of x^2 + i
/// let k = QuadraticField::gaussian();
/// let i = k.gen_elem();
/// let g = Poly::new(k.clone(), vec![k.neg(&i), k.zero(), k.one()]);
/// let m = rational_minpoly(&g);
/// let all: Vec<_> = AlgebraicNumber::roots_of_irreducible(&m)
///     .unwrap()
///     .into_iter()
///     .map(|z| (z, ()))
///     .collect();
/// let mine = roots_of_quadratic_factor(&g, all).unwrap();
/// assert_eq!(mine.len(), 2);
/// for (z, _) in mine {
///     let (re, im) = z.approx();
///     assert!(re * im > 0.0); // first or third quadrant
/// }
/// ```
pub fn roots_of_quadratic_factor<T>(
    g: &Poly<QuadraticField>,
    all: Vec<(AlgebraicNumber, T)>,
) -> Result<Vec<(AlgebraicNumber, T)>> {
    let m = rational_minpoly(g);
    let (g0, g1) = split(g);
    if g1.is_zero() {
        return Ok(all);
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
    Ok(out)
}
