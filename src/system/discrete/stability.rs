//! Exact stability over $\mathbb{Q}$, $\mathbb{Q}(\sqrt d)$, $\mathbb{Q}(i)$: where the roots
//! of a polynomial lie with respect to the unit circle (discrete time) or the imaginary axis
//! (continuous time), decided with exact arithmetic only, written once over the field: the
//! field's complex conjugation ([`Field::conj`]) and the sign of a real element
//! ([`Field::sign`]) are all it asks (over $\mathbb{Q}(p)$ signs are undecided: refused).
//! With non-real coefficients $p^*$ below is $z^n \bar p(1/z)$ and $|a|$ is compared as
//! $a \bar a$; a factor is judged on the circle through $f \bar f$ (real coefficients).
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
use crate::field::{Field, Q, Rational};
use crate::matrix::Matrix;
use crate::poly::{Poly, sign_variations};
use std::cmp::Ordering;

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
/// multiplicity in the minimal polynomial (`F`: the field of $A$; the factors are
/// irreducible over $F$).
#[derive(Clone, Debug)]
pub struct Stability<F: Field = Q> {
    pub domain: Domain,
    pub charpoly: Poly<F>,
    /// Monic irreducible factor, multiplicity in $\chi$, multiplicity in the minimal
    /// polynomial, place.
    pub factors: Vec<(Poly<F>, usize, usize, Place)>,
    pub verdict: Verdict,
}

/// $p^*(z) = z^n \bar p(1/z)$: the coefficients reversed and conjugated (reversed over a real
/// field). A root $\zeta$ of $p$ gives the root $1/\bar\zeta$ of $p^*$.
fn reversed<F: Field>(p: &Poly<F>) -> Option<Poly<F>> {
    let k = p.field();
    let mut cs = p
        .coeffs()
        .iter()
        .map(|c| k.conj(c))
        .collect::<Option<Vec<_>>>()?;
    cs.reverse();
    Some(Poly::new(k.clone(), cs))
}

/// Every root of `p` strictly inside the unit circle, over any field with conjugation and the
/// order of the reals (Schur-Cohn: $|p(0)| < |\mathrm{lc}\, p|$, compared as $a \bar a$,
/// and $(\overline{\mathrm{lc}\, p}\, p - p(0)\, p^*)/z$ stable). `None` when a sign or a
/// conjugate is undecided in the field.
pub fn schur_stable_in<F: Field>(p: &Poly<F>) -> Option<bool> {
    if p.is_zero() {
        return Some(false);
    }
    let k = p.field().clone();
    let mut p = p.clone();
    while p.deg() > 0 {
        let (a0, an) = (p.coeff(0), p.lc());
        let (c0, cn) = (k.conj(&a0)?, k.conj(&an)?);
        let gap = k.sub(&k.mul(&an, &cn), &k.mul(&a0, &c0));
        if k.sign(&gap)? != Ordering::Greater {
            return Some(false);
        }
        let t = p.scale(&cn).sub(&reversed(&p)?.scale(&a0));
        // the constant term cancels: divide by z
        p = Poly::new(k.clone(), t.coeffs()[1..].to_vec());
    }
    Some(true)
}

/// Every root of `p` strictly inside the unit circle (Schur-Cohn / Jury). A nonzero
/// constant has no roots and is stable; the zero polynomial is not.
pub fn schur_stable(p: &Poly<Q>) -> bool {
    schur_stable_in(p).unwrap_or(false)
}

/// Number of sign changes of the Sturm sequence `seq` at `x`.
fn sign_changes<F: Field>(seq: &[Poly<F>], x: &F::Elem) -> Option<usize> {
    let k = seq.first()?.field();
    let signs = seq
        .iter()
        .map(|s| k.sign(&s.eval(x)))
        .collect::<Option<Vec<_>>>()?;
    Some(sign_variations(&signs))
}

/// Distinct real roots of the real polynomial `h` in $(lo, hi]$.
fn real_roots_in<F: Field>(h: &Poly<F>, lo: &F::Elem, hi: &F::Elem) -> Option<usize> {
    let seq = h.sturm_sequence();
    Some(sign_changes(&seq, lo)?.saturating_sub(sign_changes(&seq, hi)?))
}

/// $h$ with $f(z) = z^m h(z + 1/z)$ for a palindromic $f$ of degree $2m$:
/// $z^k + z^{-k} = P_k(x)$, $P_0 = 2$, $P_1 = x$, $P_{k+1} = x P_k - P_{k-1}$.
fn palindromic_reduce<F: Field>(f: &Poly<F>) -> Poly<F> {
    let k = f.field().clone();
    let m = f.deg() / 2;
    let x = Poly::x(k.clone());
    let mut h = Poly::constant(k.clone(), f.coeff(m));
    let two = k.from_rational(&Rational::from_integer(2.into()));
    let (mut prev, mut cur) = (Poly::constant(k.clone(), two), x.clone());
    for j in 1..=m {
        h = h.add(&cur.scale(&f.coeff(m + j)));
        let next = x.mul(&cur).sub(&prev);
        prev = cur;
        cur = next;
    }
    h
}

/// Where the roots of the monic irreducible `f` over $F$ lie with respect to the unit circle
/// (`None`: a sign undecided in the field). A factor with a non-real coefficient is
/// judged on the circle through $f \bar f$, which has real coefficients, the roots of $f$
/// and their conjugates (the same moduli).
pub fn classify_factor_in<F: Field>(f: &Poly<F>) -> Option<Place> {
    if schur_stable_in(f)? {
        return Some(Place::Inside);
    }
    let k = f.field();
    let fbar = Poly::new(
        k.clone(),
        f.coeffs()
            .iter()
            .map(|c| k.conj(c))
            .collect::<Option<Vec<_>>>()?,
    );
    let f = if fbar == *f { f.clone() } else { f.mul(&fbar) };
    let r = reversed(&f)?;
    let self_reciprocal = r.deg() == f.deg() && (r.monic() == f);
    if !self_reciprocal {
        return Some(Place::Outside);
    }
    if f.deg() == 1 {
        return Some(Place::Boundary); // z - 1 or z + 1
    }
    if f.deg() % 2 == 1 {
        // odd palindromic polynomials have the root -1: not irreducible beyond degree 1
        return Some(Place::Outside);
    }
    let h = palindromic_reduce(&f);
    let two = k.from_rational(&Rational::from_integer(2.into()));
    if real_roots_in(&h, &k.neg(&two), &two)? == h.deg() {
        Some(Place::Boundary)
    } else {
        Some(Place::Outside)
    }
}

/// Where the roots of the monic irreducible `f` over $\mathbb{Q}$ lie with respect to the
/// unit circle.
pub fn classify_factor(f: &Poly<Q>) -> Place {
    classify_factor_in(f).unwrap_or(Place::Outside)
}

/// $(z + 1)^d f((z - 1)/(z + 1))$: the image of $f(s)$ under $s = (z - 1)/(z + 1)$
/// ($\mathrm{Re}\, s < 0 \iff |z| < 1$); `None` when the degree drops ($f(1) = 0$, a root
/// at $s = 1$).
fn to_disk<F: Field>(f: &Poly<F>) -> Option<Poly<F>> {
    let k = f.field().clone();
    let d = f.deg();
    let zm = Poly::new(k.clone(), vec![k.neg(&k.one()), k.one()]);
    let zp = Poly::new(k.clone(), vec![k.one(), k.one()]);
    let mut g = Poly::zero(k);
    for (j, c) in f.coeffs().iter().enumerate() {
        g = g.add(&zm.pow(j as u32).mul(&zp.pow((d - j) as u32)).scale(c));
    }
    (g.deg() == d).then(|| g.monic())
}

/// Where the roots of an irreducible factor over $F$ lie for `domain` (`None`: undecided).
pub fn place_in<F: Field>(f: &Poly<F>, domain: Domain) -> Option<Place> {
    match domain {
        Domain::Discrete => classify_factor_in(f),
        Domain::Continuous => match to_disk(f) {
            None => Some(Place::Outside),
            Some(g) => classify_factor_in(&g),
        },
    }
}

/// Where the roots of an irreducible factor lie for `domain`.
pub fn place_of(f: &Poly<Q>, domain: Domain) -> Place {
    place_in(f, domain).unwrap_or(Place::Outside)
}

/// How often `f` divides `p`.
fn multiplicity<F: Field>(p: &Poly<F>, f: &Poly<F>) -> usize {
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
    stability_with(a, domain, |chi| Ok(factor_q(chi)?.1))
}

/// The exact stability of $A$ over its field $F$ for `domain`, written once: `factor` gives
/// the monic irreducible factors of $\chi_A$ over $F$ with their multiplicities
/// ([`factor_q`] over $\mathbb{Q}$; the tower's factorization over $\mathbb{Q}(\sqrt d)$,
/// $\mathbb{Q}(i)$); each is placed by [`place_in`] (Schur-Cohn with conjugates, a Sturm
/// count on the circle), and the minimal polynomial decides the boundary's Jordan blocks.
///
/// # Errors
/// `NotSquare` for a non-square `A`; `Unsupported` when a place is undecided in the field
/// (signs of rational functions of parameters); those of `factor`.
pub fn stability_with<F: Field>(
    a: &Matrix<F>,
    domain: Domain,
    factor: impl Fn(&Poly<F>) -> Result<Vec<(Poly<F>, usize)>>,
) -> Result<Stability<F>> {
    a.check_square("stability A")?;
    let chi = a.charpoly()?;
    let mu = a.minpoly()?;
    let mut factors = vec![];
    for (f, e) in factor(&chi)? {
        let place = place_in(&f, domain).ok_or_else(|| {
            crate::error::Error::Unsupported(format!(
                "stability: where the roots of a factor lie is not decided over {}",
                a.field()
            ))
        })?;
        let in_mu = multiplicity(&mu, &f);
        factors.push((f, e, in_mu, place));
    }
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
