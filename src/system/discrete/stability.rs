//! Exact stability over $\mathbb{Q}$: where the roots of a polynomial lie with respect to
//! the unit circle (discrete time) or the imaginary axis (continuous time), decided with
//! rational arithmetic only.
//!
//! * [`schur_stable`]: every root in $|z| < 1$, by the Schur-Cohn (Jury) reduction: with
//!   $p^*(z) = z^n p(1/z)$, $p$ is Schur stable iff $|p(0)| < |\mathrm{lc}\,p|$ and
//!   $(\mathrm{lc}(p)\, p - p(0)\, p^*) / z$ (degree $n - 1$) is Schur stable (Rouché on
//!   $|z| = 1$, where $|p^*| = |p|$).
//! * [`classify_factor`]: an irreducible $f$ has every root inside, every root on the
//!   circle, or a root outside. A root $\zeta$ on the circle makes $1/\zeta = \bar\zeta$ a
//!   root, so $f$ is self-reciprocal ($f^* = \pm f$); such an $f$ of degree $2m$ is
//!   $z^m h(z + 1/z)$, and its roots are all on the circle iff $h$ has $m$ real roots in
//!   $[-2, 2]$ (counted by a Sturm sequence). A factor that is not Schur stable and not on
//!   the circle has a root outside.
//! * [`stability_of`]: a matrix is asymptotically stable when every factor of
//!   $\det(zI - A)$ is inside, marginally stable when the others are on the circle and
//!   simple in the minimal polynomial (no Jordan block larger than 1 there), else unstable.
//!   Continuous time is the same question after $s = (z - 1)/(z + 1)$, which maps
//!   $\mathrm{Re}\, s < 0$ onto $|z| < 1$ and the imaginary axis onto the circle.

use crate::algebraic::factor_q;
use crate::error::Result;
use crate::field::{Q, Rational};
use crate::matrix::Matrix;
use crate::poly::Poly;
use num_traits::{Signed, Zero};

/// Time domain of a stability question.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Domain {
    /// $\dot x = A x$: stable region $\mathrm{Re}\, s < 0$.
    Continuous,
    /// $x_{k+1} = A x_k$: stable region $|z| < 1$.
    Discrete,
}

impl Domain {
    /// The time domain of a system with sample time `dt` (`None`: continuous time).
    pub fn of(dt: Option<&crate::field::Rational>) -> Self {
        if dt.is_some() {
            Domain::Discrete
        } else {
            Domain::Continuous
        }
    }

    /// The transform variable of transfer functions and characteristic polynomials:
    /// `s` (Laplace) in continuous time, `z` in discrete time.
    pub fn var(self) -> &'static str {
        match self {
            Domain::Continuous => "s",
            Domain::Discrete => "z",
        }
    }
}

/// Where the roots of an irreducible factor lie.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Place {
    /// Every root in the stable region.
    Inside,
    /// Every root on its boundary (unit circle, imaginary axis).
    Boundary,
    /// At least one root outside the closed stable region.
    Outside,
}

/// The verdict for a matrix.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    AsymptoticallyStable,
    /// Roots on the boundary, all semisimple.
    MarginallyStable,
    /// A root outside.
    Unstable,
    /// A boundary root with a Jordan block larger than 1.
    UnstableJordan,
}

/// The stability of $A$: its characteristic polynomial's factors, where each lies and its
/// multiplicity in the minimal polynomial.
#[derive(Clone, Debug)]
pub struct Stability {
    pub domain: Domain,
    pub charpoly: Poly<Q>,
    /// Monic irreducible factor, multiplicity in $\chi$, multiplicity in the minimal
    /// polynomial, place.
    pub factors: Vec<(Poly<Q>, usize, usize, Place)>,
    pub verdict: Verdict,
}

/// $p^*(z) = z^n p(1/z)$: the coefficients reversed.
fn reversed(p: &Poly<Q>) -> Poly<Q> {
    let mut cs = p.coeffs().to_vec();
    cs.reverse();
    Poly::new(Q, cs)
}

/// Every root of `p` strictly inside the unit circle (Schur-Cohn / Jury). A nonzero
/// constant has no roots and is stable; the zero polynomial is not.
pub fn schur_stable(p: &Poly<Q>) -> bool {
    if p.is_zero() {
        return false;
    }
    let mut p = p.clone();
    while p.deg() > 0 {
        let (a0, an) = (p.coeff(0), p.lc());
        if a0.abs() >= an.abs() {
            return false;
        }
        let t = p.scale(&an).sub(&reversed(&p).scale(&a0));
        // the constant term cancels: divide by z
        p = Poly::new(Q, t.coeffs()[1..].to_vec());
    }
    true
}

/// Number of sign changes of the Sturm sequence `seq` at `x`.
fn sign_changes(seq: &[Poly<Q>], x: &Rational) -> usize {
    let signs: Vec<bool> = seq
        .iter()
        .map(|s| s.eval(x))
        .filter(|v| !v.is_zero())
        .map(|v| v.is_positive())
        .collect();
    signs.windows(2).filter(|w| w[0] != w[1]).count()
}

/// Distinct real roots of the square-free `h` in $(lo, hi]$.
fn real_roots_in(h: &Poly<Q>, lo: &Rational, hi: &Rational) -> usize {
    let mut seq = vec![h.clone(), h.derivative()];
    while !seq[seq.len() - 1].is_zero() && seq[seq.len() - 1].deg() > 0 {
        let n = seq.len();
        let r = seq[n - 2].rem(&seq[n - 1]).neg();
        if r.is_zero() {
            break;
        }
        seq.push(r);
    }
    sign_changes(&seq, lo).saturating_sub(sign_changes(&seq, hi))
}

/// $h$ with $f(z) = z^m h(z + 1/z)$ for a palindromic $f$ of degree $2m$:
/// $z^k + z^{-k} = P_k(x)$, $P_0 = 2$, $P_1 = x$, $P_{k+1} = x P_k - P_{k-1}$.
fn palindromic_reduce(f: &Poly<Q>) -> Poly<Q> {
    let m = f.deg() / 2;
    let x = Poly::x(Q);
    let mut h = Poly::constant(Q, f.coeff(m));
    let (mut prev, mut cur) = (
        Poly::constant(Q, Rational::from_integer(2.into())),
        x.clone(),
    );
    for k in 1..=m {
        h = h.add(&cur.scale(&f.coeff(m + k)));
        let next = x.mul(&cur).sub(&prev);
        prev = cur;
        cur = next;
    }
    h
}

/// Where the roots of the monic irreducible `f` lie with respect to the unit circle.
pub fn classify_factor(f: &Poly<Q>) -> Place {
    if schur_stable(f) {
        return Place::Inside;
    }
    let r = reversed(f);
    let self_reciprocal = r.deg() == f.deg() && (r.monic() == *f);
    if !self_reciprocal {
        return Place::Outside;
    }
    if f.deg() == 1 {
        return Place::Boundary; // z - 1 or z + 1
    }
    if f.deg() % 2 == 1 {
        // odd palindromic polynomials have the root -1: not irreducible beyond degree 1
        return Place::Outside;
    }
    let h = palindromic_reduce(f);
    let two = Rational::from_integer(2.into());
    if real_roots_in(&h, &-two.clone(), &two) == h.deg() {
        Place::Boundary
    } else {
        Place::Outside
    }
}

/// $(z + 1)^d f((z - 1)/(z + 1))$: the image of $f(s)$ under $s = (z - 1)/(z + 1)$
/// ($\mathrm{Re}\, s < 0 \iff |z| < 1$); `None` when the degree drops ($f(1) = 0$, a root
/// at $s = 1$).
fn to_disk(f: &Poly<Q>) -> Option<Poly<Q>> {
    let d = f.deg();
    let zm = Poly::new(
        Q,
        vec![
            -Rational::from_integer(1.into()),
            Rational::from_integer(1.into()),
        ],
    );
    let zp = Poly::new(
        Q,
        vec![
            Rational::from_integer(1.into()),
            Rational::from_integer(1.into()),
        ],
    );
    let mut g = Poly::zero(Q);
    for (k, c) in f.coeffs().iter().enumerate() {
        g = g.add(&zm.pow(k as u32).mul(&zp.pow((d - k) as u32)).scale(c));
    }
    (g.deg() == d).then(|| g.monic())
}

/// Where the roots of an irreducible factor lie for `domain`.
pub fn place_of(f: &Poly<Q>, domain: Domain) -> Place {
    match domain {
        Domain::Discrete => classify_factor(f),
        Domain::Continuous => to_disk(f).map_or(Place::Outside, |g| classify_factor(&g)),
    }
}

/// How often `f` divides `p`.
fn multiplicity(p: &Poly<Q>, f: &Poly<Q>) -> usize {
    let (mut p, mut k) = (p.clone(), 0);
    while let Some(q) = p.div_exact(f) {
        p = q;
        k += 1;
    }
    k
}

/// The exact stability of $A$ over $\mathbb{Q}$ for `domain`.
///
/// # Errors
/// `NotSquare` for a non-square `A`.
pub fn stability_of(a: &Matrix<Q>, domain: Domain) -> Result<Stability> {
    a.check_square("stability A")?;
    let chi = a.charpoly()?;
    let mu = a.minpoly()?;
    let (_, fs) = factor_q(&chi)?;
    let factors: Vec<_> = fs
        .into_iter()
        .map(|(f, e)| {
            let place = place_of(&f, domain);
            let in_mu = multiplicity(&mu, &f);
            (f, e, in_mu, place)
        })
        .collect();
    let verdict = if factors.iter().any(|x| x.3 == Place::Outside) {
        Verdict::Unstable
    } else if factors.iter().all(|x| x.3 == Place::Inside) {
        Verdict::AsymptoticallyStable
    } else if factors.iter().any(|x| x.3 == Place::Boundary && x.2 > 1) {
        Verdict::UnstableJordan
    } else {
        Verdict::MarginallyStable
    };
    Ok(Stability {
        domain,
        charpoly: chi,
        factors,
        verdict,
    })
}
