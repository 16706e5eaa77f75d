//! Exact critical values of a family whose entries lie in $K(v)$, $K = \mathbb{Q}(\sqrt d)$
//! or $\mathbb{Q}(i)$, for a real parameter $v$ on $[a, b]$: the same questions as over
//! $\mathbb{Q}$ ([`super::critical_values`]), computed over $K$.
//!
//! * $P(x, v) \in K[x, v]$ and the conditions (zero eigenvalue $p_0$, double eigenvalue
//!   $\mathrm{Res}_x(P, P_x)$, an eigenvalue mirrored across the imaginary axis
//!   $\mathrm{Res}_x(P(x), \bar P(-x))$) by evaluation and interpolation over $K$
//!   ([`crate::study::bivar`], generic over the field).
//! * Their real roots with minimal polynomials over $\mathbb{Q}$ *and* over $K$ (a critical
//!   value may lie in $K$ and not in $\mathbb{Q}$, e.g. $3/\sqrt 2$): roots of the norm, the
//!   factor over $K$ that vanishes decided exactly ([`roots_k`]).
//! * At each root $r$: everything in $E = K(r) = K[t]/(h)$ ([`at_root`]): $A(r)$, $P(x, r)$,
//!   square-free decomposition, Jordan blocks from ranks, the imaginary-axis confirmation by
//!   Sturm sequences with exact signs.
//! * Between critical values, at a rational sample $s$: over a real $K$ the Hurwitz minors of
//!   $P(x, s)$ (exact signs in $K$) give the roots in the right half-plane, Sturm sequences
//!   the real roots; over $\mathbb{Q}(i)$ the counts are those of $P \bar P \in
//!   \mathbb{Q}[x]$, the spectrum of $A(s)$ and of its conjugate (the same real parts), and
//!   `doubled` says so.
//!
//! Kinds: over a real $K$ as over $\mathbb{Q}$ (`imaginary_pair`); over $\mathbb{Q}(i)$ the
//! spectrum is not symmetric, and a crossing is one eigenvalue on the imaginary axis
//! (`imaginary_eigenvalue`).

mod at_root;
pub use at_root::RootField;
pub(crate) mod roots_k;
pub(crate) mod scalar;

pub use scalar::{KRat, KReader};

use super::intervals::intervals_between;
use super::{CriticalKind, CriticalValue, CriticalValues, FieldCharpoly, SingularReason};
use crate::algebraic::AlgebraicNumber;
use crate::error::{Error, Result};
use crate::field::{Field, Q, Quadratic, QuadraticField, Rational};
use crate::matrix::Matrix;
use crate::poly::Poly;
use crate::ratfunc::RatFuncField;
use crate::study::bivar::{
    BiPoly, BiPolyOver, check_charpoly, det_xv, discriminant_over, mirror_resultant,
};
use crate::study::family::{state_first, state_second};
use crate::study::family_read::read_file_matrices;
use crate::study::hurwitz::{RootCounts, hurwitz_matrix, hurwitz_stable, root_counts};
use crate::study::qv::parts_q;
use num_traits::Zero;
use roots_k::{real_roots_k, sign_k};
use std::cmp::Ordering;
use std::path::Path;

/// A family $\sum_j x^j P_j(v)$ over $K(v)$: `[-A, E]` (first order, $E = I$ when not
/// given) or `[K, L, M]` (second order).
#[derive(Clone, Debug)]
pub struct KFamily {
    pub k: QuadraticField,
    /// $\mathbb{Q}(v)$, the field of the parts of the entries.
    pub q: RatFuncField,
    pub param: String,
    pub name: Option<String>,
    pub pencil: Vec<Vec<Vec<KRat>>>,
    pub second_order: bool,
}

impl KFamily {
    /// Reads the file at `path` over $K(v)$ (`param` symbolic, `at` values first), `k` the
    /// field of the system file.
    ///
    /// # Errors
    /// As [`crate::study::ParamFamily::from_file_at`] (with $\sqrt d$ / $i$ of `k` allowed).
    pub fn from_file_at(
        path: &Path,
        param: &str,
        at: &[(String, String)],
        k: &QuadraticField,
    ) -> Result<Self> {
        if !crate::io::expr::is_parameter_name(param) {
            return Err(Error::Invalid(format!("'{param}' cannot name a parameter")));
        }
        let q = crate::study::qv::field(param)?;
        let m = read_file_matrices(
            &KReader {
                k: k.clone(),
                q: q.clone(),
            },
            path,
            param,
            at,
        )?;
        let one = || KRat::real(&q, q.one());
        let zero = || KRat::real(&q, q.zero());
        let square = |x: &Vec<Vec<KRat>>, n: usize| -> Result<()> {
            if x.len() != n || x.iter().any(|r| r.len() != n) {
                return Err(Error::Shape {
                    op: "parameter family",
                    expected: (n, n),
                    found: (x.len(), x.first().map_or(0, Vec::len)),
                });
            }
            Ok(())
        };
        let eye = |n: usize| -> Vec<Vec<KRat>> {
            (0..n)
                .map(|i| {
                    (0..n)
                        .map(|j| if i == j { one() } else { zero() })
                        .collect()
                })
                .collect()
        };
        let zeros = |n: usize| vec![vec![zero(); n]; n];
        let (pencil, second_order) = if let Some(mm) = m.m {
            let n = mm.len();
            let l = m.l.unwrap_or_else(|| zeros(n));
            let kk = m.k.unwrap_or_else(|| zeros(n));
            for x in [&mm, &l, &kk] {
                square(x, n)?;
            }
            (vec![kk, l, mm], true)
        } else if let Some(a) = m.a {
            let n = a.len();
            let e = m.e.unwrap_or_else(|| eye(n));
            square(&a, n)?;
            square(&e, n)?;
            let neg: Vec<Vec<KRat>> = a
                .iter()
                .map(|r| r.iter().map(|x| x.neg(&q)).collect())
                .collect();
            (vec![neg, e], false)
        } else {
            return Err(Error::Invalid(format!(
                "{}: no system: give A (first-order form) or M (second-order form)",
                m.file
            )));
        };
        Ok(KFamily {
            k: k.clone(),
            q,
            param: param.into(),
            name: m.name,
            pencil,
            second_order,
        })
    }

    /// $A(v_0)$ over a field `e` holding $\theta$ (`theta`) and $v_0$.
    ///
    /// # Errors
    /// `DivisionByZero` at a pole; `Singular` for a singular pencil.
    pub fn state_matrix_in<E: Field>(
        &self,
        e: &E,
        theta: &E::Elem,
        v0: &E::Elem,
    ) -> Result<Matrix<E>> {
        let ev = |m: &Vec<Vec<KRat>>| -> Result<Matrix<E>> {
            let rows = m
                .iter()
                .map(|r| r.iter().map(|x| x.eval_in(e, theta, v0)).collect())
                .collect::<Result<Vec<Vec<E::Elem>>>>()?;
            if rows.is_empty() {
                return Ok(Matrix::zeros(e.clone(), 0, 0));
            }
            Matrix::from_rows(e.clone(), rows)
        };
        if self.second_order {
            state_second(
                ev(&self.pencil[2])?,
                ev(&self.pencil[1])?,
                ev(&self.pencil[0])?,
            )
        } else {
            let a = ev(&self.pencil[0])?.scale(&e.neg(&e.one()));
            state_first(a, Some(ev(&self.pencil[1])?))
        }
    }

    /// Every denominator of every entry (in $\mathbb{Q}[v]$, monic).
    pub fn denominators(&self) -> Vec<Poly<Q>> {
        let mut out: Vec<Poly<Q>> = vec![];
        for x in self.pencil.iter().flatten().flatten() {
            let d = x.den();
            if !d.is_one() && !out.contains(&d) {
                out.push(d);
            }
        }
        out
    }

    /// The pencil's rows scaled by the lcm of their denominators: `rows[i][j][c]` in $K[v]$.
    fn poly_rows(&self) -> Vec<Vec<Vec<Poly<QuadraticField>>>> {
        let k = &self.k;
        let n = self.pencil[0].len();
        (0..n)
            .map(|i| {
                let l = self
                    .pencil
                    .iter()
                    .flat_map(|p| p[i].iter())
                    .fold(Poly::one(Q), |l, x| {
                        let d = x.den();
                        l.mul(&d).quo(&l.gcd(&d))
                    });
                self.pencil
                    .iter()
                    .map(|p| {
                        p[i].iter()
                            .map(|x| {
                                let ((an, ad), (bn, bd)) = (parts_q(&x.a), parts_q(&x.b));
                                let a = an.mul(&l.quo(&ad));
                                let b = bn.mul(&l.quo(&bd));
                                let m = a.coeffs().len().max(b.coeffs().len());
                                Poly::new(
                                    k.clone(),
                                    (0..m)
                                        .map(|j| Quadratic::new(a.coeff(j), b.coeff(j)))
                                        .collect(),
                                )
                            })
                            .collect()
                    })
                    .collect()
            })
            .collect()
    }
}

/// Critical values of `fam`'s parameter on $[a, b]$ over its field (see the module docs).
///
/// # Errors
/// `Invalid` for $a > b$; the errors of the steps.
pub fn critical_values_over_k(fam: &KFamily, a: &Rational, b: &Rational) -> Result<CriticalValues> {
    if a > b {
        return Err(Error::Invalid(format!("empty range: from {a} > to {b}")));
    }
    let k = &fam.k;
    let (p, content) = det_xv(k, &fam.poly_rows())?;
    let theta = Quadratic::new(Rational::zero(), Rational::from_integer(1.into()));
    check_charpoly(k, &p, &fam.param, &|v0| fam.state_matrix_in(k, &theta, v0))?;
    let imag_kind = if k.is_real() {
        CriticalKind::ImaginaryPair
    } else {
        CriticalKind::ImaginaryEigenvalue
    };
    // complex conjugation of K (the identity on a real field)
    let conj = |c: &Quadratic| if k.is_real() { c.clone() } else { k.galois(c) };
    let conditions = vec![
        (CriticalKind::ZeroEigenvalue, p.coeffs[0].clone()),
        (imag_kind, mirror_resultant(k, &p, &conj)?),
        (CriticalKind::DoubleEigenvalue, discriminant_over(k, &p)?),
    ];
    let (singular, singular_reasons) = singular_points(fam, &p, &content, a, b)?;
    let mut out = Found::default();
    for (kind, cond) in &conditions {
        if cond.is_zero() {
            if p.deg_x() > 1 || *kind == CriticalKind::ZeroEigenvalue {
                out.persistent.push(*kind);
            }
            continue;
        }
        for (r, h) in real_roots_k(cond, a, b)? {
            if !singular.contains(&r) {
                confirm(fam, &p, *kind, r, h, &mut out)?;
            }
        }
    }
    let mut verified = out.verified;
    let mut critical = out.critical;
    critical.sort_by(|x, y| {
        x.value
            .partial_cmp(&y.value)
            .unwrap_or(Ordering::Equal)
            .then(x.kind.cmp(&y.kind))
    });
    let count = |s: &Rational| counts_at(k, &p.at(&k.from_rational(s)));
    let intervals = intervals_between(a, b, &critical, &singular, &mut verified, &count)?;
    Ok(CriticalValues {
        param: fam.param.clone(),
        from: a.clone(),
        to: b.clone(),
        charpoly: BiPoly { coeffs: vec![] },
        conditions: vec![],
        critical,
        rejected: out.rejected,
        singular,
        singular_reasons,
        persistent: out.persistent,
        intervals,
        verified,
        over_field: Some(FieldCharpoly {
            field: k.clone(),
            charpoly: p.coeffs.clone(),
            conditions,
            doubled: !k.is_real(),
        }),
    })
}

/// What the confirmations found.
struct Found {
    critical: Vec<CriticalValue>,
    rejected: Vec<(AlgebraicNumber, String)>,
    persistent: Vec<CriticalKind>,
    verified: bool,
}

impl Default for Found {
    fn default() -> Self {
        Found {
            critical: vec![],
            rejected: vec![],
            persistent: vec![],
            verified: true,
        }
    }
}

/// Confirms the root `r` (minimal polynomial `h` over $K$) of the condition of `kind`.
fn confirm(
    fam: &KFamily,
    p: &BiPolyOver<QuadraticField>,
    kind: CriticalKind,
    r: AlgebraicNumber,
    h: Poly<QuadraticField>,
    out: &mut Found,
) -> Result<()> {
    let k = &fam.k;
    let at = at_root::at_root(fam, p, &r, &h)?;
    let zero_here = at.e.is_zero(&at.p.coeff(0));
    let (ok, omega) = match kind {
        CriticalKind::ZeroEigenvalue => (zero_here, None),
        CriticalKind::DoubleEigenvalue => (at.repeated, None),
        CriticalKind::ImaginaryPair | CriticalKind::ImaginaryEigenvalue => {
            let found = if k.is_real() {
                at_root::imaginary_pair_k(&at, k, &r)?
            } else {
                at_root::imaginary_eigenvalue_i(&at, &r)?
            };
            match found {
                Ok(w) => (true, Some(w)),
                Err(why) => {
                    // a root of the mirror resultant that is only a zero eigenvalue is
                    // reported as that, not as a rejected crossing
                    if !zero_here {
                        out.rejected.push((r, why));
                    }
                    return Ok(());
                }
            }
        }
    };
    out.verified &= ok;
    out.critical.push(CriticalValue {
        value: r,
        kind,
        eigenvalues_at: at.eigenvalues,
        omega,
        certified: true,
        minpoly_over_field: Some(h),
    });
    Ok(())
}

/// Poles, singular pencils (roots of the content) and order drops (roots of $p_n$) in
/// $[a, b]$, ascending, each with its first reason.
fn singular_points(
    fam: &KFamily,
    p: &BiPolyOver<QuadraticField>,
    content: &Poly<QuadraticField>,
    a: &Rational,
    b: &Rational,
) -> Result<(Vec<AlgebraicNumber>, Vec<SingularReason>)> {
    let mut out: Vec<(AlgebraicNumber, SingularReason)> = vec![];
    for d in fam.denominators() {
        for r in super::roots::real_roots_in(&d, a, b)? {
            out.push((r, SingularReason::Pole));
        }
    }
    for (c, why) in [
        (content, SingularReason::SingularPencil),
        (&p.lead(), SingularReason::OrderDrop),
    ] {
        for (r, _) in real_roots_k(c, a, b)? {
            out.push((r, why));
        }
    }
    Ok(super::intervals::singular_sorted(out))
}

/// Root counts of $P(x, s)$ over $K$, Routh–Hurwitz stability, and whether the counts are
/// consistent; `None` at a degenerate sample (a Hurwitz minor vanishes, over a real $K$).
fn counts_at(
    k: &QuadraticField,
    ps: &Poly<QuadraticField>,
) -> Result<Option<(RootCounts, bool, bool)>> {
    if !k.is_real() {
        // the spectrum of A(s) and of its conjugate: P times its conjugate, over Q
        let n = crate::algebraic::norm_over_q(ps);
        return Ok(Some((root_counts(&n)?, hurwitz_stable(&n)?, true)));
    }
    // zero eigenvalues (a persistent one: p_0 = 0 for every v) counted and divided out
    let zero = ps.coeffs().iter().take_while(|c| k.is_zero(c)).count();
    let ps = Poly::new(k.clone(), ps.coeffs()[zero..].to_vec());
    let ps = if sign_k(k, &ps.lc()) == Ordering::Less {
        ps.neg()
    } else {
        ps
    };
    let n = ps.deg();
    let h = hurwitz_matrix(k, ps.coeffs(), n);
    let mut first_col = vec![Ordering::Greater];
    let mut prev = Ordering::Greater;
    for j in 1..=n {
        let dj = sign_k(k, &h.submatrix(0, j, 0, j).det()?);
        if dj == Ordering::Equal {
            return Ok(None);
        }
        first_col.push(if dj == prev {
            Ordering::Greater
        } else {
            Ordering::Less
        });
        prev = dj;
    }
    let rhp = first_col.windows(2).filter(|w| w[0] != w[1]).count();
    let stable = rhp == 0 && zero == 0;
    let (mut neg, mut pos) = (0, 0);
    for (s, m) in ps.squarefree() {
        let (ns, np) = super::imaginary::real_roots_by_sign(&s, &|x| Ok(sign_k(k, x)))?;
        neg += m * ns;
        pos += m * np;
    }
    let consistent =
        rhp >= pos && n >= rhp + neg && (n - rhp - neg) % 2 == 0 && (rhp - pos.min(rhp)) % 2 == 0;
    let counts = RootCounts {
        real_negative: neg,
        zero,
        real_positive: pos,
        complex_pairs_stable: n.saturating_sub(rhp + neg) / 2,
        imaginary_pairs: 0,
        complex_pairs_unstable: rhp.saturating_sub(pos) / 2,
    };
    Ok(Some((counts, stable, consistent)))
}

/// Reads `path` over its field `k` and computes [`critical_values_over_k`].
///
/// # Errors
/// As [`KFamily::from_file_at`] and [`critical_values_over_k`].
pub fn critical_values_of_file(
    path: &Path,
    param: &str,
    at: &[(String, String)],
    k: &QuadraticField,
    a: &Rational,
    b: &Rational,
) -> Result<CriticalValues> {
    critical_values_over_k(&KFamily::from_file_at(path, param, at, k)?, a, b)
}
