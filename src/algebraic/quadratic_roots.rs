//! The roots of a polynomial irreducible over a quadratic field $K = \mathbb{Q}(\alpha)$,
//! $\alpha = \sqrt d$ or $i\sqrt{-d}$, chosen exactly among those of its minimal polynomial
//! over $\mathbb{Q}$.
//!
//! For $g$ monic irreducible over $K$ write $g = g_0 + \alpha g_1$ ($g_0, g_1 \in
//! \mathbb{Q}\[x\]$) and $\bar g = g_0 - \alpha g_1$ (the Galois conjugate). The minimal
//! polynomial over $\mathbb{Q}$ of a root of $g$ is $m = g$ when $g_1 = 0$, else
//! $m = g \bar g$. In the second case half of the roots of $m$ are roots of $\bar g$ (for a
//! characteristic polynomial: eigenvalues of $\bar A$, **not** of $A$); $g$ and $\bar g$
//! are distinct monic irreducibles, so no root is shared. A root $\rho$ of $m$ is a root
//! of $g$ exactly when $g(\rho) = g_0(\rho) + \alpha g_1(\rho) = 0$. This is decided by
//! exact rational interval arithmetic: $g_0$ and $g_1$ (real coefficients, degree
//! $\deg g$) are evaluated on the isolating box of $\rho$, $\alpha$ enters as a rational
//! enclosure of $\sqrt{|d|}$ (exact for $\mathbb{Q}(i)$), and the box is refined until
//! the enclosure of one of $g(\rho)$, $\bar g(\rho)$ excludes 0; the other one is then
//! the polynomial that vanishes. No floating point is involved in the decision, and the
//! count of the roots found is checked against $\deg g$.
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
    fn neg(&self) -> Iv {
        Iv(-&self.1, -&self.0)
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

/// A rational interval of width at most $2^{-\text{bits}}$ around $\sqrt{|d|}$ (a point
/// when $|d|$ is a square, e.g. $d = -1$).
fn sqrt_enclosure(d: &BigInt, bits: u32) -> Iv {
    let n = d.abs() << (2 * bits);
    let r = n.sqrt();
    let den = BigInt::one() << bits;
    if &r * &r == n {
        Iv::point(Rational::new(r, den))
    } else {
        Iv(
            Rational::new(r.clone(), den.clone()),
            Rational::new(r + 1, den),
        )
    }
}

/// Is the root `z` of $m = g \bar g$ a root of $g = g_0 + \alpha g_1$ (see the module
/// docs)? Decided exactly by interval evaluation on refined isolating regions.
///
/// # Errors
/// `Limit` when 40 refinements (down to width $2^{-400}$) do not decide (not expected:
/// exactly one of $g(z)$, $\bar g(z)$ is zero); `Verification` when both enclosures
/// exclude 0 (`z` is then no root of $m$).
fn is_root_of_g(g0: &Poly<Q>, g1: &Poly<Q>, d: &BigInt, z: &AlgebraicNumber) -> Result<bool> {
    let real_k = d.is_positive();
    let nonzero = |re: &Iv, im: &Iv| re.sign().is_some() || im.sign().is_some();
    let mut z = z.clone();
    for step in 0..40u32 {
        let ((r0, r1), (i0, i1)) = z.bounding_box();
        let (re, im) = (Iv(r0, r1), Iv(i0, i1));
        let (a_re, a_im) = eval_box(g0, &re, &im);
        let (b_re, b_im) = eval_box(g1, &re, &im);
        let s = sqrt_enclosure(d, 10 * (step + 1) + 20);
        // alpha g1(z): sqrt(d) (b_re + i b_im), or i sqrt(-d) (b_re + i b_im)
        let (t_re, t_im) = if real_k {
            (s.mul(&b_re), s.mul(&b_im))
        } else {
            (s.mul(&b_im).neg(), s.mul(&b_re))
        };
        let g_nonzero = nonzero(&a_re.add(&t_re), &a_im.add(&t_im));
        let gbar_nonzero = nonzero(&a_re.sub(&t_re), &a_im.sub(&t_im));
        match (g_nonzero, gbar_nonzero) {
            (false, true) => return Ok(true),
            (true, false) => return Ok(false),
            (true, true) => {
                return Err(Error::Verification(
                    "a root of the minimal polynomial is a root of neither g nor its conjugate"
                        .into(),
                ));
            }
            (false, false) => {
                let w = Rational::new(BigInt::one(), BigInt::one() << (10 * (step + 1)));
                z = z.refined(&w)?;
            }
        }
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
    let d = g.field().d();
    let mut out = vec![];
    for (z, a) in all {
        if is_root_of_g(&g0, &g1, d, &z)? {
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
