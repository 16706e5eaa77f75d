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

use super::bivar::{BiPoly, charpoly_xv, discriminant_v, hurwitz_delta_n1};
use super::family::ParamFamily;
use super::hurwitz::{RootCounts, hurwitz_stable, root_counts};
use crate::algebraic::{AlgebraicNumber, factor_over_number_field, factor_q};
use crate::algebraic::{NfElem, NumberField};
use crate::error::{Error, Result};
use crate::field::{Field, Q, Rational, rational_to_f64};
use crate::matrix::Matrix;
use crate::poly::Poly;
use num_complex::Complex;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;

/// What happens at a critical value.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum CriticalKind {
    ZeroEigenvalue,
    ImaginaryPair,
    DoubleEigenvalue,
}

impl CriticalKind {
    /// The contract's name.
    pub fn name(&self) -> &'static str {
        match self {
            CriticalKind::ZeroEigenvalue => "zero_eigenvalue",
            CriticalKind::ImaginaryPair => "imaginary_pair",
            CriticalKind::DoubleEigenvalue => "double_eigenvalue",
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
    /// $\mathbb{Q}(v_0)$ it is a root of, in `x` and `t` ($t = v_0$); empty otherwise.
    pub factor: String,
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
    /// Where $A(v)$ is undefined or the order drops (a denominator or $p_n$ vanishes).
    pub singular: Vec<AlgebraicNumber>,
    /// Kinds that hold for every $v$ (e.g. a rigid-body zero eigenvalue): not reported as
    /// critical values.
    pub persistent: Vec<CriticalKind>,
    pub intervals: Vec<StudyInterval>,
    /// Every confirmation exact and consistent; interval counts agree with Routh–Hurwitz.
    pub verified: bool,
}

/// Real roots of `p` in $[a, b]$, ascending, with their minimal polynomials.
fn real_roots_in(p: &Poly<Q>, a: &Rational, b: &Rational) -> Result<Vec<AlgebraicNumber>> {
    if p.degree().unwrap_or(0) == 0 {
        return Ok(vec![]);
    }
    let (lo, hi) = (
        AlgebraicNumber::from_rational(a),
        AlgebraicNumber::from_rational(b),
    );
    let mut out = vec![];
    for (f, _) in factor_q(p)?.1 {
        for r in real_roots_of_irreducible(&f) {
            if r >= lo && r <= hi {
                out.push(r);
            }
        }
    }
    out.sort_by(|x, y| x.partial_cmp(y).unwrap_or(Ordering::Equal));
    Ok(out)
}

/// The real roots of the irreducible `f`, as algebraic numbers (no complex isolation).
fn real_roots_of_irreducible(f: &Poly<Q>) -> Vec<AlgebraicNumber> {
    use crate::algebraic::number::Loc;
    let m = f.monic();
    if m.deg() == 1 {
        return vec![AlgebraicNumber::from_rational(&-m.coeff(0))];
    }
    let z = crate::algebraic::zp::from_poly_q(&m);
    crate::algebraic::isolate_real::isolate_real_roots(&z)
        .into_iter()
        .map(|r| AlgebraicNumber::from_parts(m.clone(), Loc::Real(r)))
        .collect()
}

/// Sign of the element `e` of $\mathbb{Q}(r) = \mathbb{Q}[t]/(f)$ at the real root `r`
/// (`e` nonzero), by interval Horner on refined isolating intervals.
pub fn sign_at_root(k: &NumberField, e: &NfElem, r: &AlgebraicNumber) -> Result<Ordering> {
    let p = k.elem_to_poly(e);
    if p.is_zero() {
        return Ok(Ordering::Equal);
    }
    if let Some(q) = r.to_rational() {
        return Ok(p.eval(&q).cmp(&Rational::zero()));
    }
    let mut r = r.clone();
    for _ in 0..80 {
        let (lo, hi) = r
            .interval()
            .ok_or_else(|| Error::Invalid("non-real root".into()))?;
        let (a, b) = interval_horner(&p, &lo, &hi);
        if a.is_positive() {
            return Ok(Ordering::Greater);
        }
        if b.is_negative() {
            return Ok(Ordering::Less);
        }
        let w = (&hi - &lo) / Rational::from_integer(256.into());
        r = r.refined(&w)?;
    }
    Err(Error::Limit(
        "sign of an algebraic number not decided".into(),
    ))
}

fn interval_horner(p: &Poly<Q>, lo: &Rational, hi: &Rational) -> (Rational, Rational) {
    let (mut a, mut b) = (Rational::zero(), Rational::zero());
    for c in p.coeffs().iter().rev() {
        let cands = [&a * lo, &a * hi, &b * lo, &b * hi];
        let mn = cands.iter().min().cloned().unwrap_or_default();
        let mx = cands.iter().max().cloned().unwrap_or_default();
        a = mn + c;
        b = mx + c;
    }
    (a, b)
}

/// $q(A)$ by Horner over the matrix field.
fn poly_of_matrix<K: Field>(q: &Poly<K>, a: &Matrix<K>) -> Result<Matrix<K>> {
    let k = a.field().clone();
    let n = a.nrows();
    let mut acc = Matrix::zeros(k.clone(), n, n);
    for c in q.coeffs().iter().rev() {
        acc = acc.try_mul(a)?;
        for i in 0..n {
            let v = k.add(acc.get(i, i), c);
            acc.set(i, i, v);
        }
    }
    Ok(acc)
}

/// Jordan block sizes (non-increasing) of each root of the irreducible `q` (multiplicity
/// `m` in the characteristic polynomial) for the matrix `a`.
pub fn block_sizes<K: Field>(a: &Matrix<K>, q: &Poly<K>, m: usize) -> Result<Vec<usize>> {
    if m == 1 {
        return Ok(vec![1]);
    }
    let d = q.deg();
    let qa = poly_of_matrix(q, a)?;
    let mut ranks = vec![a.nrows()];
    let mut pw = qa.clone();
    for k in 1..=m {
        ranks.push(pw.rank());
        if k < m {
            pw = pw.try_mul(&qa)?;
        }
    }
    // at_least[k] = number of blocks of size >= k (k = 1..=m)
    let at_least: Vec<usize> = (1..=m).map(|k| (ranks[k - 1] - ranks[k]) / d).collect();
    let mut blocks = vec![];
    for k in (1..=m).rev() {
        let exact = at_least[k - 1] - at_least.get(k).copied().unwrap_or(0);
        blocks.extend(std::iter::repeat_n(k, exact));
    }
    if blocks.iter().sum::<usize>() != m {
        return Err(Error::Verification(format!(
            "Jordan blocks {blocks:?} do not add up to the multiplicity {m}"
        )));
    }
    Ok(blocks)
}

/// $e(v_0)$ in `f64`, evaluated exactly at the rational `vq` near $v_0$.
fn approx_elem(k: &NumberField, e: &NfElem, vq: &Rational) -> f64 {
    rational_to_f64(&k.elem_to_poly(e).eval(vq))
}

/// Approximate roots of a polynomial over $\mathbb{Q}(v_0)$ (companion eigenvalues).
fn approx_roots(
    k: &NumberField,
    q: &Poly<NumberField>,
    v0: &Rational,
) -> Result<Vec<Complex<f64>>> {
    let c: Vec<f64> = q.coeffs().iter().map(|e| approx_elem(k, e, v0)).collect();
    let d = c.len() - 1;
    if d == 1 {
        return Ok(vec![Complex::new(-c[0] / c[1], 0.0)]);
    }
    let comp = nalgebra::DMatrix::from_fn(d, d, |i, j| {
        if i == 0 {
            -c[d - 1 - j] / c[d]
        } else if i == j + 1 {
            1.0
        } else {
            0.0
        }
    });
    crate::float::eigenvalues(&comp)
}

/// The general path of [`structure_at`]: square-free decomposition over $\mathbb{Q}(v_0)$ first; only repeated parts of degree
/// $> 1$ are factored (Trager), so the common case (one double eigenvalue in
/// $\mathbb{Q}(v_0)$) needs gcds and ranks only.
fn structure_general(
    fam: &ParamFamily,
    k: &NumberField,
    pk: &Poly<NumberField>,
    v0: &Rational,
) -> Result<Vec<EigenvalueAt>> {
    let mut a: Option<Matrix<NumberField>> = None;
    let mut out = vec![];
    for (s, m) in pk.squarefree() {
        let parts = if m > 1 && s.deg() > 1 {
            factor_over_number_field(&s)?
        } else {
            vec![(s, 1)]
        };
        for (q, e) in parts {
            let mult = m * e;
            let blocks = if mult > 1 {
                if a.is_none() {
                    a = Some(fam.state_matrix_nf(k)?);
                }
                block_sizes(a.as_ref().expect("set"), &q, mult)?
            } else {
                vec![1]
            };
            let factor = q.to_string();
            for z in approx_roots(k, &q, v0)? {
                out.push(EigenvalueAt {
                    approx: (z.re, z.im),
                    multiplicity: mult,
                    blocks: blocks.clone(),
                    factor: if mult > 1 {
                        factor.clone()
                    } else {
                        String::new()
                    },
                });
            }
        }
    }
    out.sort_by(|x, y| {
        x.approx
            .0
            .total_cmp(&y.approx.0)
            .then(x.approx.1.total_cmp(&y.approx.1))
    });
    Ok(out)
}

/// A rational within $2^{-80}$ of the real algebraic number `r`.
fn rational_near(r: &AlgebraicNumber) -> Result<Rational> {
    if let Some(q) = r.to_rational() {
        return Ok(q);
    }
    let w = Rational::new(1.into(), num_bigint::BigInt::one() << 80usize);
    let (lo, hi) = r.refined(&w)?.interval().unwrap_or_default();
    Ok((lo + hi) / Rational::from_integer(2.into()))
}

/// Numeric roots of a rational polynomial (companion eigenvalues).
fn approx_roots_q(p: &Poly<Q>) -> Result<Vec<Complex<f64>>> {
    let c: Vec<f64> = p.coeffs().iter().map(rational_to_f64).collect();
    let d = c.len().saturating_sub(1);
    if d == 0 {
        return Ok(vec![]);
    }
    let comp = nalgebra::DMatrix::from_fn(d, d, |i, j| {
        if i == 0 {
            -c[d - 1 - j] / c[d]
        } else if i == j + 1 {
            1.0
        } else {
            0.0
        }
    });
    crate::float::eigenvalues(&comp)
}

/// What is known about $P$ near the critical values: the discriminant and the first
/// subresultant of $P$, $\partial_x P$.
struct Known<'a> {
    fam: &'a ParamFamily,
    p: &'a BiPoly,
    disc: &'a Poly<Q>,
    s1: &'a (Poly<Q>, Poly<Q>),
}

fn simple(z: Complex<f64>) -> EigenvalueAt {
    EigenvalueAt {
        approx: (z.re, z.im),
        multiplicity: 1,
        blocks: vec![1],
        factor: String::new(),
    }
}

/// The eigenvalues of $A(v_0)$ with multiplicities and Jordan blocks; `true` when one is
/// repeated (checked exactly).
///
/// Exact decisions: $f \nmid \mathrm{disc}$ ($f$ the minimal polynomial of $v_0$) means
/// all eigenvalues are simple; else, when $s_{1,1}(v_0) \ne 0$, $\gcd(P, \partial_x P) =
/// x - \lambda$ with $\lambda = -s_{1,0}/s_{1,1} \in \mathbb{Q}(v_0)$: exactly one double
/// eigenvalue (checked: $P(\lambda) = P'(\lambda) = 0$), one Jordan block of size 2 iff
/// $\operatorname{rank}(A(v_0) - \lambda I) = n - 1$. Other cases take the general path
/// (square-free decomposition and factorization over $\mathbb{Q}(v_0)$).
fn structure_at(
    kn: &Known<'_>,
    k: &NumberField,
    r: &AlgebraicNumber,
) -> Result<(Vec<EigenvalueAt>, bool)> {
    let vq = rational_near(r)?;
    let mut ev = approx_roots_q(&kn.p.at(&vq))?;
    let f = r.minpoly();
    if !kn.disc.rem(f).is_zero() {
        let mut out: Vec<EigenvalueAt> = ev.into_iter().map(simple).collect();
        sort_eigs(&mut out);
        return Ok((out, false));
    }
    let s11 = k.elem_from_poly(&kn.s1.0);
    if k.is_zero(&s11) {
        let pk = kn.p.at_nf(k);
        let out = structure_general(kn.fam, k, &pk, &vq)?;
        let rep = out.iter().any(|e| e.multiplicity > 1);
        return Ok((out, rep));
    }
    // By the fundamental theorem of subresultants, f | disc and s11(v0) != 0 give
    // gcd(P, P') = s11 x + s10 at v0: exactly one double eigenvalue lambda = -s10/s11.
    // Its Jordan structure: rank(A - lambda I) = rank(s11 A + s10 I) = n - 1 iff one block.
    let blocks = match double_blocks_mod_p(kn, f)? {
        Some(b) => b,
        None => double_blocks_exact(kn, k)?,
    };
    let lq = -kn.s1.1.eval(&vq) / kn.s1.0.eval(&vq);
    let l = rational_to_f64(&lq);
    // the two numeric roots nearest to lambda are the double one
    for _ in 0..2 {
        if let Some(i) =
            (0..ev.len()).min_by(|&i, &j| (ev[i] - l).norm().total_cmp(&(ev[j] - l).norm()))
        {
            ev.remove(i);
        }
    }
    let mut out: Vec<EigenvalueAt> = ev.into_iter().map(simple).collect();
    let shown = format!(
        "-({})/({})",
        kn.s1.1.rem(f).to_string_var("t"),
        kn.s1.0.rem(f).to_string_var("t")
    );
    out.push(EigenvalueAt {
        approx: (l, 0.0),
        multiplicity: 2,
        blocks,
        factor: if shown.len() <= 400 {
            format!("x - {shown}")
        } else {
            String::new()
        },
    });
    sort_eigs(&mut out);
    Ok((out, true))
}

/// Does the singular matrix `b` over $\mathbb{Q}(v_0)$ have rank $n - 1$, i.e. a nonzero
/// $(n-1)$-minor? Minors are tried in the order of their float magnitude (guidance only)
/// and computed exactly and division-free (no inversions in $\mathbb{Q}(v_0)$); above
/// $n = 7$ the exact rank is used instead.
fn has_nonzero_minor(b: &Matrix<NumberField>) -> Result<bool> {
    let n = b.nrows();
    if n <= 1 {
        return Ok(n == 1 && b.rank() == 0);
    }
    if n > 7 {
        return Ok(b.rank() == n - 1);
    }
    let k = b.field().clone();
    let approx = b.to_approx_complex();
    let mut order: Vec<(usize, usize, f64)> = vec![];
    for i in 0..n {
        for j in 0..n {
            let m = nalgebra::DMatrix::from_fn(n - 1, n - 1, |r, c| {
                let rr = if r < i { r } else { r + 1 };
                let cc = if c < j { c } else { c + 1 };
                approx[rr][cc].0
            });
            order.push((i, j, m.determinant().abs()));
        }
    }
    order.sort_by(|x, y| y.2.total_cmp(&x.2));
    for (i, j, _) in order {
        let rows: Vec<usize> = (0..n).filter(|&r| r != i).collect();
        let cols: Vec<usize> = (0..n).filter(|&c| c != j).collect();
        let sub: Vec<Vec<NfElem>> = rows
            .iter()
            .map(|&r| cols.iter().map(|&c| b.get(r, c).clone()).collect())
            .collect();
        if !k.is_zero(&det_laplace(&k, &sub)) {
            return Ok(true);
        }
    }
    Ok(false)
}

/// Determinant by Laplace expansion along the first row (division-free; small sizes).
fn det_laplace<K: Field>(k: &K, m: &[Vec<K::Elem>]) -> K::Elem {
    let n = m.len();
    match n {
        0 => k.one(),
        1 => m[0][0].clone(),
        2 => k.sub(&k.mul(&m[0][0], &m[1][1]), &k.mul(&m[0][1], &m[1][0])),
        _ => {
            let mut acc = k.zero();
            for j in 0..n {
                if k.is_zero(&m[0][j]) {
                    continue;
                }
                let minor: Vec<Vec<K::Elem>> = m[1..]
                    .iter()
                    .map(|r| {
                        r.iter()
                            .enumerate()
                            .filter(|(c, _)| *c != j)
                            .map(|(_, x)| x.clone())
                            .collect()
                    })
                    .collect();
                let t = k.mul(&m[0][j], &det_laplace(k, &minor));
                acc = if j % 2 == 0 {
                    k.add(&acc, &t)
                } else {
                    k.sub(&acc, &t)
                };
            }
            acc
        }
    }
}

/// Jordan blocks of the double eigenvalue from a reduction modulo a prime: `Some([2])` when
/// $s_{1,1} A + s_{1,0} I$ has rank $n - 1$ modulo $p$ (hence over $\mathbb{Q}(v_0)$),
/// after checking $P(\lambda) \equiv P'(\lambda) \equiv 0$; `None` when undecided.
fn double_blocks_mod_p(kn: &Known<'_>, f: &Poly<Q>) -> Result<Option<Vec<usize>>> {
    use super::modp::{poly_at, rank_mod, root_mod_p, state_matrix_mod};
    for skip in 0..3 {
        let Some((p, t0)) = root_mod_p(f, skip) else {
            return Ok(None);
        };
        let (Some(s11), Some(s10)) = (poly_at(&kn.s1.0, t0, p), poly_at(&kn.s1.1, t0, p)) else {
            continue;
        };
        let Some(a) = state_matrix_mod(kn.fam, t0, p) else {
            continue;
        };
        if s11 == 0 {
            continue;
        }
        // P(lambda) = P'(lambda) = 0 mod p (a necessary condition, checked)
        let lam = (p - s10)
            * super::modp::rational_mod(&Rational::new(1.into(), s11.into()), p).unwrap_or(0)
            % p;
        let pc: Option<Vec<u64>> = kn.p.coeffs.iter().map(|c| poly_at(c, t0, p)).collect();
        let Some(pc) = pc else { continue };
        let ev = |cs: &[u64]| cs.iter().rev().fold(0u64, |acc, c| (acc * lam + c) % p);
        let dc: Vec<u64> = pc
            .iter()
            .enumerate()
            .skip(1)
            .map(|(i, c)| c * (i as u64) % p)
            .collect();
        if ev(&pc) != 0 || ev(&dc) != 0 {
            return Err(Error::Verification(
                "the repeated eigenvalue from the subresultant is not a double root mod p".into(),
            ));
        }
        let n = a.len();
        let b: Vec<Vec<u64>> = (0..n)
            .map(|i| {
                (0..n)
                    .map(|j| (a[i][j] * s11 + if i == j { s10 } else { 0 }) % p)
                    .collect()
            })
            .collect();
        if rank_mod(b, p) == n - 1 {
            return Ok(Some(vec![2]));
        }
    }
    Ok(None)
}

/// Jordan blocks of the double eigenvalue over $\mathbb{Q}(v_0)$ exactly (slow path).
fn double_blocks_exact(kn: &Known<'_>, k: &NumberField) -> Result<Vec<usize>> {
    let s11 = k.elem_from_poly(&kn.s1.0);
    let s10 = k.elem_from_poly(&kn.s1.1);
    let a = kn.fam.state_matrix_nf(k)?;
    let n = a.nrows();
    let mut shifted = a.scale(&s11);
    for i in 0..n {
        let d = k.add(shifted.get(i, i), &s10);
        shifted.set(i, i, d);
    }
    Ok(if has_nonzero_minor(&shifted)? {
        vec![2]
    } else {
        vec![1, 1]
    })
}

fn sort_eigs(out: &mut [EigenvalueAt]) {
    out.sort_by(|x, y| {
        x.approx
            .0
            .total_cmp(&y.approx.0)
            .then(x.approx.1.total_cmp(&y.approx.1))
    });
}

/// Is there a purely imaginary pair at $v_0$? `Some((omega, certified))` or `None` with the
/// reason.
fn imaginary_pair_at(
    k: &NumberField,
    pk: &Poly<NumberField>,
    r: &AlgebraicNumber,
) -> Result<std::result::Result<(f64, bool), String>> {
    let cs = pk.coeffs();
    let even: Vec<NfElem> = cs.iter().step_by(2).cloned().collect();
    let odd: Vec<NfElem> = cs.iter().skip(1).step_by(2).cloned().collect();
    let e = Poly::new(k.clone(), even);
    let o = Poly::new(k.clone(), odd);
    let g = e.gcd(&o);
    let v0 = &rational_near(r)?;
    match g.degree() {
        None | Some(0) => Ok(Err("no pair adds up to zero".into())),
        Some(1) => {
            // u = x^2 = -g0/g1
            let g = g.monic();
            let u = k.neg(&g.coeff(0));
            match sign_at_root(k, &u, r)? {
                Ordering::Less => Ok(Ok(((-approx_elem(k, &u, v0)).sqrt(), true))),
                Ordering::Equal => Ok(Err("a double zero eigenvalue".into())),
                Ordering::Greater => Ok(Err(format!(
                    "a real pair +-{:.6}",
                    approx_elem(k, &u, v0).sqrt()
                ))),
            }
        }
        Some(_) => {
            let us = approx_roots(k, &g, v0)?;
            let scale = us.iter().map(|u| u.norm()).fold(1e-300, f64::max);
            match us
                .iter()
                .find(|u| u.re < -1e-9 * scale && u.im.abs() <= 1e-9 * scale)
            {
                Some(u) => Ok(Ok(((-u.re).sqrt(), false))),
                None => Ok(Err("pairs adding up to zero are not imaginary".into())),
            }
        }
    }
}

/// A rational strictly between the reals `a < b`.
pub fn rational_between(a: &AlgebraicNumber, b: &AlgebraicNumber) -> Result<Rational> {
    let (mut a, mut b) = (a.clone(), b.clone());
    for _ in 0..200 {
        let (_, ahi) = a
            .interval()
            .ok_or_else(|| Error::Invalid("non-real".into()))?;
        let (blo, _) = b
            .interval()
            .ok_or_else(|| Error::Invalid("non-real".into()))?;
        if ahi < blo {
            return Ok(simplest_between(&ahi, &blo));
        }
        let half = |x: &AlgebraicNumber| -> Result<AlgebraicNumber> {
            let (lo, hi) = x.interval().unwrap_or_default();
            if lo == hi {
                return Ok(x.clone());
            }
            x.refined(&((hi - lo) / Rational::from_integer(2.into())))
        };
        a = half(&a)?;
        b = half(&b)?;
    }
    Err(Error::Limit(
        "could not separate two critical values".into(),
    ))
}

/// A short rational in the open interval $(a, b)$: the continued-fraction simplest one.
fn simplest_between(a: &Rational, b: &Rational) -> Rational {
    let fl = a.floor();
    if &(&fl + Rational::one()) < b {
        return fl + Rational::one();
    }
    // a, b in [fl, fl + 1]; recurse on reciprocals of the fractional parts
    let (fa, fb) = (a - &fl, b - &fl);
    if fa.is_zero() {
        // (fl, b): choose fl + 1/m with 1/m < fb
        let m = (Rational::one() / &fb).floor() + Rational::one();
        return fl + Rational::one() / m;
    }
    fl + Rational::one() / simplest_between(&(Rational::one() / &fb), &(Rational::one() / &fa))
}

/// Critical values of the family's parameter on $[a, b]$ and the intervals between them.
///
/// # Errors
/// `Invalid` for $a > b$; errors of [`charpoly_xv`], factoring and root isolation.
pub fn critical_values(fam: &ParamFamily, a: &Rational, b: &Rational) -> Result<CriticalValues> {
    if a > b {
        return Err(Error::Invalid(format!("empty range: from {a} > to {b}")));
    }
    let p = charpoly_xv(fam)?;
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
    let mut sing_poly = p.lead();
    for d in fam.denominators() {
        sing_poly = sing_poly.mul(&d);
    }
    let singular = real_roots_in(&sing_poly, a, b)?;
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
                CriticalKind::ImaginaryPair => match imaginary_pair_at(&k, &pk, &r)? {
                    Ok((w, cert)) => (true, Some(w), cert),
                    Err(why) => {
                        rejected.push((r.clone(), why));
                        continue;
                    }
                },
            };
            verified &= ok && certified;
            critical.push(CriticalValue {
                eigenvalues_at,
                value: r,
                kind: *kind,
                omega,
                certified,
            });
        }
    }
    critical.sort_by(|x, y| {
        x.value
            .partial_cmp(&y.value)
            .unwrap_or(Ordering::Equal)
            .then(x.kind.cmp(&y.kind))
    });
    let intervals = intervals_between(&p, a, b, &critical, &singular, &mut verified)?;
    Ok(CriticalValues {
        param: fam.param.clone(),
        from: a.clone(),
        to: b.clone(),
        charpoly: p,
        conditions,
        critical,
        rejected,
        singular,
        persistent,
        intervals,
        verified,
    })
}

fn intervals_between(
    p: &BiPoly,
    a: &Rational,
    b: &Rational,
    critical: &[CriticalValue],
    singular: &[AlgebraicNumber],
    verified: &mut bool,
) -> Result<Vec<StudyInterval>> {
    let mut pts: Vec<AlgebraicNumber> = vec![AlgebraicNumber::from_rational(a)];
    let mut inner: Vec<AlgebraicNumber> = critical
        .iter()
        .map(|c| c.value.clone())
        .chain(singular.iter().cloned())
        .collect();
    inner.sort_by(|x, y| x.partial_cmp(y).unwrap_or(Ordering::Equal));
    for x in inner {
        if pts.last() != Some(&x) {
            pts.push(x);
        }
    }
    let last = AlgebraicNumber::from_rational(b);
    if pts.last() != Some(&last) {
        pts.push(last);
    }
    let mut out = vec![];
    for w in pts.windows(2) {
        let s = rational_between(&w[0], &w[1])?;
        let ps = p.at(&s);
        let counts = root_counts(&ps)?;
        let stable = hurwitz_stable(&ps)?;
        *verified &= stable == counts.is_stable();
        out.push(StudyInterval {
            from: w[0].clone(),
            to: w[1].clone(),
            sample: s,
            counts,
            stable,
        });
    }
    Ok(out)
}

/// `f64` of a rational (re-export for reports).
pub fn approx_q(q: &Rational) -> f64 {
    rational_to_f64(q)
}
