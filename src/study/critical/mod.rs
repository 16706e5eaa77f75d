//! Exact critical values of one parameter $v$ on an interval $[a, b]$.
//!
//! With $P(x, v) = \sum_k p_k(v) x^k$ the characteristic polynomial of $A(v)$
//! ([`charpoly_xv`]), the eigenvalues change qualitatively only where
//! * an eigenvalue is zero: $p_0(v) = 0$;
//! * a pair is purely imaginary: $\Delta_{n-1}(v) = 0$ (Hurwitz determinant, which vanishes
//!   iff $\lambda_i + \lambda_j = 0$ for some pair), *confirmed* at the root $v_0$ by
//!   $g = \gcd(E, O) \ne 1$ over $\mathbb{Q}(v_0)$, where $P(x, v_0) = E(x^2) + x O(x^2)$,
//!   and a root $u = x^2 < 0$ of $g$ (real pairs $\pm a$ are rejected);
//! * two eigenvalues coincide: $\mathrm{Res}_x(P, \partial_x P)(v) = 0$, confirmed by
//!   $\gcd(P, \partial_x P) \ne 1$ over $\mathbb{Q}(v_0)$; the Jordan structure there comes
//!   from the ranks of $q(A(v_0))^k$ over $\mathbb{Q}(v_0)$ for each repeated irreducible
//!   factor $q$ of $P(x, v_0)$ over $\mathbb{Q}(v_0)$: $\#\{\text{blocks} \ge k\} =
//!   (\operatorname{rank} q(A)^{k-1} - \operatorname{rank} q(A)^k) / \deg q$.
//!
//! Each critical value is an [`AlgebraicNumber`] (minimal polynomial over $\mathbb{Q}$ and
//! an isolating interval). Between consecutive values the eigenvalue counts are constant;
//! they are computed exactly at a rational sample point (certified root isolation) and
//! cross-checked with the Routh–Hurwitz minors.

mod approx;
mod double;
mod imaginary;
mod intervals;
pub mod over_k;
mod roots;
mod structure;
pub mod value;

pub use roots::{rational_between, sign_at_root};
pub use structure::block_sizes;

use super::bivar::{BiPoly, charpoly_xv_content, discriminant_v, hurwitz_delta_n1};
use super::family::ParamFamily;
use super::hurwitz::{RootCounts, hurwitz_stable, root_counts};
use crate::algebraic::{AlgebraicNumber, NumberField};
use crate::error::{Error, Result};
use crate::field::{Field, Q, QuadraticField, Rational, rational_to_f64};
use crate::poly::Poly;
use imaginary::imaginary_pair_at;
use intervals::intervals_between;
use roots::real_roots_in;
use std::cmp::Ordering;
use structure::structure_at;

/// What happens at a critical value.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum CriticalKind {
    ZeroEigenvalue,
    ImaginaryPair,
    /// Over a non-real field ($\mathbb{Q}(i)$): one eigenvalue on the imaginary axis
    /// (the spectrum is not symmetric about the real axis).
    ImaginaryEigenvalue,
    DoubleEigenvalue,
}

impl CriticalKind {
    /// The contract's name.
    pub fn name(&self) -> &'static str {
        match self {
            CriticalKind::ZeroEigenvalue => "zero_eigenvalue",
            CriticalKind::ImaginaryPair => "imaginary_pair",
            CriticalKind::ImaginaryEigenvalue => "imaginary_eigenvalue",
            CriticalKind::DoubleEigenvalue => "double_eigenvalue",
        }
    }
}

/// Why the family is excluded at a point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SingularReason {
    /// An entry of the matrices has a pole.
    Pole,
    /// $\det(xE - A) = 0$ for every $x$ (resp. $\det(x^2M + xL + K)$).
    SingularPencil,
    /// The leading coefficient of $P(x, v)$ vanishes: an eigenvalue goes to infinity
    /// ($E(v)$ or $M(v)$ loses rank), fewer finite eigenvalues than elsewhere.
    OrderDrop,
}

impl SingularReason {
    /// Its name in reports.
    pub fn name(&self) -> &'static str {
        match self {
            SingularReason::Pole => "pole",
            SingularReason::SingularPencil => "singular_pencil",
            SingularReason::OrderDrop => "eigenvalue_at_infinity",
        }
    }
}

/// One eigenvalue of $A(v_0)$: the roots of one irreducible factor of $P(x, v_0)$ over
/// $\mathbb{Q}(v_0)$ (each root listed, same structure).
#[derive(Clone, Debug, PartialEq)]
pub struct EigenvalueAt {
    /// Approximate value.
    pub approx: (f64, f64),
    /// Algebraic multiplicity.
    pub multiplicity: usize,
    /// Jordan block sizes, non-increasing (sum = multiplicity).
    pub blocks: Vec<usize>,
    /// For a repeated eigenvalue: the irreducible factor of $P(x, v_0)$ over
    /// $\mathbb{Q}(v_0)$ (or $K(v_0)$) it is a root of, coefficients in $t = v_0$.
    pub factor: Option<FactorAt>,
    /// For a repeated eigenvalue whose factor is linear, $x - \lambda$: $\lambda$ exactly
    /// ([`value`]).
    pub value: Option<AlgebraicNumber>,
}

/// The irreducible factor of $P(x, v_0)$ a repeated eigenvalue is a root of.
#[derive(Clone, Debug, PartialEq)]
pub enum FactorAt {
    /// Over $\mathbb{Q}(v_0) = \mathbb{Q}[t]/(f)$, $f$ the minimal polynomial of $v_0$.
    Q(Poly<NumberField>),
    /// Over $K(v_0) = K[t]/(h)$, $K = \mathbb{Q}(\sqrt d)$ or $\mathbb{Q}(i)$.
    K(Poly<over_k::RootField>),
}

impl FactorAt {
    /// The degree of the factor in $x$.
    pub fn deg(&self) -> usize {
        match self {
            FactorAt::Q(p) => p.deg(),
            FactorAt::K(p) => p.deg(),
        }
    }
}

/// A critical value of the parameter.
#[derive(Clone, Debug)]
pub struct CriticalValue {
    pub value: AlgebraicNumber,
    pub kind: CriticalKind,
    /// The eigenvalues of $A(v_0)$ with their Jordan structure.
    pub eigenvalues_at: Vec<EigenvalueAt>,
    /// For `ImaginaryPair`: the crossing frequency $\omega$ (approximate).
    pub omega: Option<f64>,
    /// The confirmation was decided in exact arithmetic (always, except for an imaginary
    /// pair whose $g$ has degree $\ge 2$, decided from approximations).
    pub certified: bool,
    /// Over a field $K \ne \mathbb{Q}$: the minimal polynomial of the value over $K$ (a
    /// factor of `value.minpoly()`; of degree 1 when the value lies in $K$).
    pub minpoly_over_field: Option<Poly<QuadraticField>>,
}

/// The characteristic polynomial and the conditions of a family over $K(v)$,
/// $K = \mathbb{Q}(\sqrt d)$ or $\mathbb{Q}(i)$ ([`over_k`]).
#[derive(Clone, Debug)]
pub struct FieldCharpoly {
    pub field: QuadraticField,
    /// $p_j(v) \in K[v]$, $P = \sum_j p_j x^j$ ($p_n$ monic).
    pub charpoly: Vec<Poly<QuadraticField>>,
    /// The polynomials in $v$ whose roots were examined, by kind.
    pub conditions: Vec<(CriticalKind, Poly<QuadraticField>)>,
    /// The interval counts are those of $A(v)$ and its complex conjugate together (a
    /// non-real field: each count is twice that of $A(v)$ in the same half-plane).
    pub doubled: bool,
}

/// An open interval between consecutive critical values.
#[derive(Clone, Debug)]
pub struct StudyInterval {
    pub from: AlgebraicNumber,
    pub to: AlgebraicNumber,
    /// The rational point where the counts were computed.
    pub sample: Rational,
    pub counts: RootCounts,
    /// Routh–Hurwitz at `sample` (agrees with `counts.is_stable()` when verified).
    pub stable: bool,
}

/// The result of [`critical_values`].
#[derive(Clone, Debug)]
pub struct CriticalValues {
    pub param: String,
    pub from: Rational,
    pub to: Rational,
    /// $P(x, v)$.
    pub charpoly: BiPoly,
    /// The three polynomials in $v$ whose roots were examined, by kind.
    pub conditions: Vec<(CriticalKind, Poly<Q>)>,
    /// Sorted by value, then kind.
    pub critical: Vec<CriticalValue>,
    /// Roots of $\Delta_{n-1}$ that are not imaginary pairs (a real pair $\pm a$ or a
    /// double zero), with the reason.
    pub rejected: Vec<(AlgebraicNumber, String)>,
    /// Where $A(v)$ is undefined or the order drops (a denominator, the content of the
    /// determinant or $p_n$ vanishes), ascending.
    pub singular: Vec<AlgebraicNumber>,
    /// Why, for each entry of `singular`.
    pub singular_reasons: Vec<SingularReason>,
    /// Kinds that hold for every $v$ (e.g. a rigid-body zero eigenvalue): not reported as
    /// critical values.
    pub persistent: Vec<CriticalKind>,
    pub intervals: Vec<StudyInterval>,
    /// Every confirmation exact and consistent; interval counts agree with Routh–Hurwitz.
    pub verified: bool,
    /// For a family over $K(v)$, $K \ne \mathbb{Q}$: its $P$ and conditions over $K$
    /// (`charpoly` and `conditions` are then empty).
    pub over_field: Option<FieldCharpoly>,
}

/// What is known about $P$ near the critical values: the discriminant and the first
/// subresultant of $P$, $\partial_x P$.
struct Known<'a> {
    fam: &'a ParamFamily,
    p: &'a BiPoly,
    disc: &'a Poly<Q>,
    s1: &'a (Poly<Q>, Poly<Q>),
}

/// Critical values of the family's parameter on $[a, b]$ and the intervals between them.
///
/// # Errors
/// `Invalid` for $a > b$; errors of [`charpoly_xv`], factoring and root isolation.
pub fn critical_values(fam: &ParamFamily, a: &Rational, b: &Rational) -> Result<CriticalValues> {
    if a > b {
        return Err(Error::Invalid(format!("empty range: from {a} > to {b}")));
    }
    let (p, content) = charpoly_xv_content(fam)?;
    let conditions = vec![
        (CriticalKind::ZeroEigenvalue, p.coeffs[0].clone()),
        (CriticalKind::ImaginaryPair, hurwitz_delta_n1(&p)?),
        (CriticalKind::DoubleEigenvalue, discriminant_v(&p)?),
    ];
    let s1 = super::bivar::first_subresultant(&p)?;
    let kn = Known {
        fam,
        p: &p,
        disc: &conditions[2].1,
        s1: &s1,
    };
    let (singular, singular_reasons) = singular_points(fam, &p, &content, a, b)?;
    let mut critical = vec![];
    let mut rejected = vec![];
    let mut persistent = vec![];
    let mut verified = true;
    for (kind, cond) in &conditions {
        if cond.is_zero() {
            if p.deg_x() > 1 || *kind == CriticalKind::ZeroEigenvalue {
                persistent.push(*kind);
            }
            continue;
        }
        let rts = real_roots_in(cond, a, b)?;
        for r in rts {
            if singular.contains(&r) {
                continue;
            }
            let k = r.to_number_field();
            let pk = p.at_nf(&k);
            let (eigenvalues_at, repeated) = structure_at(&kn, &k, &r)?;
            let (ok, omega, certified) = match kind {
                CriticalKind::ZeroEigenvalue => (pk.coeff(0) == k.zero(), None, true),
                CriticalKind::DoubleEigenvalue => (repeated, None, true),
                CriticalKind::ImaginaryPair | CriticalKind::ImaginaryEigenvalue => {
                    match imaginary_pair_at(&k, &pk, &r)? {
                        Ok((w, cert)) => (true, Some(w), cert),
                        Err(why) => {
                            rejected.push((r.clone(), why));
                            continue;
                        }
                    }
                }
            };
            verified &= ok && certified;
            critical.push(CriticalValue {
                eigenvalues_at,
                value: r,
                kind: *kind,
                omega,
                certified,
                minpoly_over_field: None,
            });
        }
    }
    critical.sort_by(|x, y| {
        x.value
            .partial_cmp(&y.value)
            .unwrap_or(Ordering::Equal)
            .then(x.kind.cmp(&y.kind))
    });
    let count = |s: &Rational| -> Result<intervals::Counts> {
        let ps = p.at(s);
        Ok(Some((root_counts(&ps)?, hurwitz_stable(&ps)?, true)))
    };
    let intervals = intervals_between(a, b, &critical, &singular, &mut verified, &count)?;
    Ok(CriticalValues {
        param: fam.param.clone(),
        from: a.clone(),
        to: b.clone(),
        charpoly: p,
        conditions,
        critical,
        rejected,
        singular,
        singular_reasons,
        persistent,
        intervals,
        verified,
        over_field: None,
    })
}

/// The points of $[a, b]$ where the family is undefined or its finite spectrum changes
/// size, each with its first reason: a pole of an entry, a singular pencil (a root of the
/// content $c$ of the determinant), the leading coefficient $p_r$ vanishing (an
/// eigenvalue goes to infinity: fewer finite eigenvalues).
fn singular_points(
    fam: &ParamFamily,
    p: &BiPoly,
    content: &Poly<Q>,
    a: &Rational,
    b: &Rational,
) -> Result<(Vec<AlgebraicNumber>, Vec<SingularReason>)> {
    let mut out: Vec<(AlgebraicNumber, SingularReason)> = vec![];
    let dens = fam.denominators();
    let lead = p.lead();
    let parts = dens
        .iter()
        .map(|d| (d, SingularReason::Pole))
        .chain([
            (content, SingularReason::SingularPencil),
            (&lead, SingularReason::OrderDrop),
        ])
        .collect::<Vec<_>>();
    for (poly, why) in parts {
        for r in real_roots_in(poly, a, b)? {
            out.push((r, why));
        }
    }
    Ok(intervals::singular_sorted(out))
}

/// `f64` of a rational (re-export for reports).
pub fn approx_q(q: &Rational) -> f64 {
    rational_to_f64(q)
}
