//! The characteristic polynomial $P(x, v) = \sum_k p_k(v) x^k \in \mathbb{Q}[v][x]$ of a
//! [`ParamFamily`], and the polynomials in $v$ that locate its critical values:
//! $p_0(v)$ (zero eigenvalue), the Hurwitz determinant $\Delta_{n-1}(v)$ (a pair
//! $\lambda_i + \lambda_j = 0$, which includes every imaginary pair) and the discriminant
//! $\mathrm{Res}_x(P, \partial_x P)(v)$ (a repeated eigenvalue).
//!
//! # Algorithm
//! Evaluation and interpolation: every entry of the pencil $\sum_j x^j P_j(v)$ is made
//! polynomial by scaling each row with the lcm of its denominators; the determinant is then
//! a polynomial whose degrees in $x$ and $v$ are bounded by row sums of entry degrees, so
//! $\det$ over $\mathbb{Q}$ at a grid of integer points followed by Newton interpolation
//! (first in $x$, then in $v$) gives $P$ exactly. The same holds for $\Delta_{n-1}$
//! (degree $\le (n-1) d_v$) and the discriminant (degree $\le (2n-1) d_v$), evaluated at
//! points where $p_n \ne 0$. The result is checked: $P(x, v_0)/p_n(v_0) = \chi_{A(v_0)}$ at
//! a rational $v_0$, computed independently.

use super::family::ParamFamily;
use super::hurwitz::hurwitz_matrix;
use crate::algebraic::NumberField;
use crate::error::{Error, Result};
use crate::field::{Q, Rational};
use crate::matrix::Matrix;
use crate::poly::Poly;
use num_traits::{One, Zero};

/// Largest accepted degree bound of $P$ in $v$ or in $x$ (bounds the grid).
pub const MAX_BIDEGREE: usize = 400;

/// $P(x, v)$: `coeffs[k]` $= p_k(v)$, the coefficient of $x^k$.
#[derive(Clone, Debug, PartialEq)]
pub struct BiPoly {
    pub coeffs: Vec<Poly<Q>>,
}

impl BiPoly {
    /// Degree in $x$.
    pub fn deg_x(&self) -> usize {
        self.coeffs.len().saturating_sub(1)
    }
    /// Largest degree in $v$ of a coefficient.
    pub fn deg_v(&self) -> usize {
        self.coeffs
            .iter()
            .map(|c| c.degree().unwrap_or(0))
            .max()
            .unwrap_or(0)
    }
    /// $P(x, v_0) \in \mathbb{Q}[x]$.
    pub fn at(&self, v0: &Rational) -> Poly<Q> {
        Poly::new(Q, self.coeffs.iter().map(|c| c.eval(v0)).collect())
    }
    /// $P(x, v_0)$ over $\mathbb{Q}(v_0) = \mathbb{Q}[t]/(f)$, $v_0 = t$.
    pub fn at_nf(&self, k: &NumberField) -> Poly<NumberField> {
        Poly::new(
            k.clone(),
            self.coeffs.iter().map(|c| k.from_poly(c)).collect(),
        )
    }
    /// The leading coefficient $p_n(v)$.
    pub fn lead(&self) -> Poly<Q> {
        self.coeffs.last().cloned().unwrap_or_else(|| Poly::zero(Q))
    }
}

/// Interpolation at the points $0, 1, \dots, m$ through integer values: forward
/// differences $\Delta^j y_0$ (integers) and $p(x) = \sum_j \Delta^j y_0 \binom{x}{j}$,
/// accumulated as $m!\,p(x)$ in integer arithmetic (no gcds) and divided once. Falls back to
/// [`interpolate`] for non-integer values.
pub fn interpolate_consecutive(ys: &[Rational]) -> Poly<Q> {
    use num_bigint::BigInt;
    let m1 = ys.len();
    if m1 == 0 {
        return Poly::zero(Q);
    }
    if !ys.iter().all(|y| y.is_integer()) {
        let xs: Vec<Rational> = (0..m1).map(int).collect();
        return interpolate(&xs, ys);
    }
    let mut d: Vec<BigInt> = ys.iter().map(|y| y.to_integer()).collect();
    let mut diffs = Vec::with_capacity(m1);
    for j in 0..m1 {
        diffs.push(d[0].clone());
        for i in 0..m1 - 1 - j {
            d[i] = &d[i + 1] - &d[i];
        }
    }
    let m = m1 - 1;
    // falling factorial x(x-1)...(x-j+1) and the weights m!/j!
    let mut ff: Vec<BigInt> = vec![BigInt::one()];
    let mut weight: Vec<BigInt> = vec![BigInt::one(); m1];
    for j in (0..m).rev() {
        weight[j] = &weight[j + 1] * BigInt::from(j as u64 + 1);
    }
    let mut acc: Vec<BigInt> = vec![BigInt::zero(); m1];
    for (j, dj) in diffs.iter().enumerate() {
        if !dj.is_zero() {
            let w = dj * &weight[j];
            for (k, c) in ff.iter().enumerate() {
                acc[k] += &w * c;
            }
        }
        // ff *= (x - j)
        let mut next = vec![BigInt::zero(); ff.len() + 1];
        for (k, c) in ff.iter().enumerate() {
            next[k + 1] += c;
            next[k] -= c * BigInt::from(j as u64);
        }
        ff = next;
    }
    let fact = weight[0].clone();
    Poly::new(
        Q,
        acc.into_iter()
            .map(|c| Rational::new(c, fact.clone()))
            .collect(),
    )
}

/// Newton interpolation: the polynomial of degree $< $ `xs.len()` through `(xs, ys)`.
pub fn interpolate(xs: &[Rational], ys: &[Rational]) -> Poly<Q> {
    let n = xs.len();
    let mut dd: Vec<Rational> = ys.to_vec();
    for j in 1..n {
        for i in (j..n).rev() {
            dd[i] = (&dd[i] - &dd[i - 1]) / (&xs[i] - &xs[i - j]);
        }
    }
    let mut p = Poly::zero(Q);
    for i in (0..n).rev() {
        p = p
            .mul(&Poly::new(Q, vec![-xs[i].clone(), Rational::one()]))
            .add(&Poly::constant(Q, dd[i].clone()));
    }
    p
}

fn int(i: usize) -> Rational {
    Rational::from_integer((i as i64).into())
}

/// The characteristic polynomial $P(x, v)$ of the family, primitive over $\mathbb{Q}[v]$
/// (no factor free of $x$), with the identity $P(x, v_0) = p_n(v_0)\,\chi_{A(v_0)}(x)$
/// checked at one rational point.
///
/// # Errors
/// `Singular` when the pencil is singular (its determinant vanishes identically);
/// `Limit` for degree bounds above [`MAX_BIDEGREE`]; `Verification` if the check fails.
pub fn charpoly_xv(fam: &ParamFamily) -> Result<BiPoly> {
    Ok(charpoly_xv_content(fam)?.0)
}

/// [`charpoly_xv`] and the content $c(v)$ it divided out (monic): with the rows of the
/// pencil made polynomial, $\det = c(v) P(x, v)$, so at a root of $c$ that is no pole of an
/// entry the pencil is singular ($\det(xE(v_0) - A(v_0)) = 0$ for every $x$).
///
/// # Errors
/// As [`charpoly_xv`].
pub fn charpoly_xv_content(fam: &ParamFamily) -> Result<(BiPoly, Poly<Q>)> {
    let pencil = fam.pencil();
    let n2 = pencil[0].len();
    // scale each row by the lcm of its denominators: entries in Q[v]
    let mut rows: Vec<Vec<Vec<Poly<Q>>>> = vec![]; // rows[i][j][k]
    let (mut dx, mut dv) = (0usize, 0usize);
    for i in 0..n2 {
        let mut l = Poly::one(Q);
        for p in &pencil {
            for f in &p[i] {
                l = l.mul(&f.den).quo(&l.gcd(&f.den));
            }
        }
        let r: Vec<Vec<Poly<Q>>> = pencil
            .iter()
            .map(|p| p[i].iter().map(|f| f.num.mul(&l.quo(&f.den))).collect())
            .collect();
        let jmax = r.iter().rposition(|row| row.iter().any(|x| !x.is_zero()));
        let Some(jmax) = jmax else {
            return Err(Error::Singular);
        };
        dx += jmax;
        dv += r
            .iter()
            .flatten()
            .map(|x| x.degree().unwrap_or(0))
            .max()
            .unwrap_or(0);
        rows.push(r);
    }
    if dx > MAX_BIDEGREE || dv > MAX_BIDEGREE {
        return Err(Error::Limit(format!(
            "characteristic polynomial of degree {dx} in x and {dv} in the parameter"
        )));
    }
    let xs: Vec<Rational> = (0..=dx).map(int).collect();
    let vs: Vec<Rational> = (0..=dv).map(int).collect();
    // per v point: the polynomial in x
    let mut table: Vec<Vec<Rational>> = vec![vec![]; dx + 1]; // table[k][b]
    for vb in &vs {
        let at_v: Vec<Vec<Vec<Rational>>> = rows
            .iter()
            .map(|r| {
                r.iter()
                    .map(|row| row.iter().map(|p| p.eval(vb)).collect())
                    .collect()
            })
            .collect();
        let mut dets = Vec::with_capacity(dx + 1);
        for xa in &xs {
            let m = Matrix::from_fn(Q, n2, n2, |i, k| {
                let mut s = Rational::zero();
                let mut pw = Rational::one();
                for row in &at_v[i] {
                    s += &row[k] * &pw;
                    pw *= xa;
                }
                s
            });
            dets.push(if n2 == 0 { Rational::one() } else { m.det()? });
        }
        let px = interpolate_consecutive(&dets);
        for (k, col) in table.iter_mut().enumerate() {
            col.push(px.coeff(k));
        }
    }
    let mut coeffs: Vec<Poly<Q>> = table.iter().map(|ys| interpolate_consecutive(ys)).collect();
    while coeffs.len() > 1 && coeffs.last().is_some_and(|c| c.is_zero()) {
        coeffs.pop();
    }
    if coeffs.iter().all(|c| c.is_zero()) {
        return Err(Error::Singular);
    }
    let content = coeffs
        .iter()
        .fold(Poly::zero(Q), |g, c| if c.is_zero() { g } else { g.gcd(c) });
    let mut coeffs: Vec<Poly<Q>> = coeffs.iter().map(|c| c.quo(&content)).collect();
    // integer coefficients without common factor, leading coefficient of p_n positive
    let mut den = num_bigint::BigInt::one();
    let mut num_gcd = num_bigint::BigInt::zero();
    for c in coeffs.iter().flat_map(|c| c.coeffs().iter()) {
        den = num_integer::Integer::lcm(&den, c.denom());
        num_gcd = num_integer::Integer::gcd(&num_gcd, c.numer());
    }
    let mut scale = Rational::new(den, num_gcd.max(num_bigint::BigInt::one()));
    if coeffs.last().is_some_and(|c| c.lc() < Rational::zero()) {
        scale = -scale;
    }
    coeffs = coeffs.iter().map(|c| c.scale(&scale)).collect();
    let p = BiPoly { coeffs };
    check_charpoly(fam, &p)?;
    Ok((p, content.monic()))
}

/// Checks $P(x, v_0) = p_n(v_0) \chi_{A(v_0)}(x)$ at a rational $v_0$ where both sides
/// are defined.
fn check_charpoly(fam: &ParamFamily, p: &BiPoly) -> Result<()> {
    for t in 0..64i64 {
        let v0 = Rational::new((7919 + 31 * t).into(), 1009.into());
        if p.lead().eval(&v0).is_zero() {
            continue;
        }
        let Ok(a) = fam.state_matrix_q(&v0) else {
            continue;
        };
        let chi = a.charpoly()?;
        let lhs = p.at(&v0);
        if lhs.monic() != chi || lhs.deg() != a.nrows() {
            return Err(Error::Verification(format!(
                "characteristic polynomial in (x, {}) disagrees with charpoly(A({v0}))",
                fam.param
            )));
        }
        return Ok(());
    }
    Err(Error::Verification(
        "no rational check point for the characteristic polynomial".into(),
    ))
}

/// Interpolates `f(v)` (a polynomial of degree $\le$ `bound`) from its values at integer
/// points where `p_n` does not vanish.
fn interpolate_at_good_points(
    lead: &Poly<Q>,
    bound: usize,
    f: impl Fn(&Rational) -> Result<Rational>,
) -> Result<Poly<Q>> {
    let mut xs = vec![];
    let mut ys = vec![];
    let mut i = 0usize;
    while xs.len() <= bound {
        let v = int(i);
        i += 1;
        if lead.eval(&v).is_zero() {
            continue;
        }
        ys.push(f(&v)?);
        xs.push(v);
    }
    if i == xs.len() {
        return Ok(interpolate_consecutive(&ys));
    }
    Ok(interpolate(&xs, &ys))
}

/// The Hurwitz determinant $\Delta_{n-1}(v)$ of $P(\cdot, v)$ (zero polynomial for $n \le 1$).
///
/// $\Delta_{n-1} = (-1)^{n(n-1)/2} p_n^{n-1} \prod_{i<j} (\lambda_i + \lambda_j)$, so it
/// vanishes exactly where two eigenvalues add up to zero.
///
/// # Errors
/// From the determinants.
pub fn hurwitz_delta_n1(p: &BiPoly) -> Result<Poly<Q>> {
    let n = p.deg_x();
    if n <= 1 {
        return Ok(Poly::zero(Q));
    }
    let bound = (n - 1) * p.deg_v();
    interpolate_at_good_points(&Poly::one(Q), bound, |v| {
        let h = hurwitz_matrix(&Q, p.at(v).coeffs(), n);
        det_small(h.submatrix(0, n - 1, 0, n - 1).rows())
    })
}

/// The resultant $\mathrm{Res}_x(P, \partial_x P)(v)$ (the discriminant times $\pm p_n$):
/// the shared subresultant resultant ([`crate::mpoly::resultant::resultant`]) of $L P$ and
/// $L \partial_x P$ in $\mathbb{Z}[v][x]$, divided by $L^{2n-1}$ ($L$ the common
/// denominator of $P$'s coefficients). It equals the Sylvester determinant of formal degrees
/// $n$, $n - 1$, since $p_n \ne 0$.
///
/// # Errors
/// None at present (the signature is that of the other locators).
pub fn discriminant_v(p: &BiPoly) -> Result<Poly<Q>> {
    use crate::mpoly::MPoly;
    use num_bigint::BigInt;
    let n = p.deg_x();
    if n <= 1 {
        return Ok(Poly::zero(Q));
    }
    let l = p
        .coeffs
        .iter()
        .flat_map(|c| c.coeffs())
        .fold(BigInt::one(), |l, c| {
            num_integer::Integer::lcm(&l, c.denom())
        });
    let lq = Rational::from_integer(l);
    let in_v = |c: &Poly<Q>| {
        let cs: Vec<MPoly> = c
            .coeffs()
            .iter()
            .map(|q| MPoly::constant(2, (q * &lq).to_integer()))
            .collect();
        MPoly::from_univariate(2, 1, &cs)
    };
    let f = MPoly::from_univariate(2, 0, &p.coeffs.iter().map(in_v).collect::<Vec<_>>());
    let r = crate::mpoly::resultant::resultant(&f, &f.derivative(0), 0);
    let scale = num_traits::pow(lq, 2 * n - 1);
    let cs = r
        .to_univariate(1)
        .iter()
        .map(|c| Rational::from_integer(c.to_constant().unwrap_or_default()) / &scale)
        .collect();
    Ok(Poly::new(Q, cs))
}

/// Coefficient $s_{j,i}$ of the $j$-th subresultant of `f` (formal degree `n`) and `g`
/// (formal degree `m`): the determinant of the $(n + m - 2j)$-square matrix whose rows are
/// $x^{m-j-1} f, \dots, f, x^{n-j-1} g, \dots, g$ restricted to the columns of
/// $x^{n+m-j-1}, \dots, x^{j+1}$ and $x^i$.
pub fn subresultant_coeff(
    f: &[Rational],
    n: usize,
    g: &[Rational],
    m: usize,
    j: usize,
    i: usize,
) -> Result<Rational> {
    let size = n + m - 2 * j;
    let top = n + m - j - 1; // highest power
    let mut cols: Vec<usize> = (j + 1..=top).rev().collect(); // powers
    cols.push(i);
    let coef = |c: &[Rational], k: i64| -> Rational {
        if k < 0 {
            Rational::zero()
        } else {
            c.get(k as usize).cloned().unwrap_or_default()
        }
    };
    let mut rows: Vec<Vec<Rational>> = vec![];
    for s in (0..m - j).rev() {
        rows.push(
            cols.iter()
                .map(|&pw| coef(f, pw as i64 - s as i64))
                .collect(),
        );
    }
    for s in (0..n - j).rev() {
        rows.push(
            cols.iter()
                .map(|&pw| coef(g, pw as i64 - s as i64))
                .collect(),
        );
    }
    debug_assert_eq!(rows.len(), size);
    det_small(rows)
}

/// Determinant of a small rational matrix (the shared fraction-free kernel
/// [`crate::qkernels::fraction_free::det_bareiss`]).
pub fn det_small(rows: Vec<Vec<Rational>>) -> Result<Rational> {
    let n = rows.len();
    if rows.iter().any(|r| r.len() != n) {
        return Err(Error::Invalid(format!(
            "det_small: a {n}-row matrix that is not square"
        )));
    }
    let flat: Vec<Rational> = rows.into_iter().flatten().collect();
    Ok(crate::qkernels::fraction_free::det_bareiss(n, &flat))
}

/// The first subresultant $S_1(x, v) = s_{1,1}(v) x + s_{1,0}(v)$ of $P$ and
/// $\partial_x P$ (formal degrees $n$, $n-1$): where the discriminant vanishes and
/// $s_{1,1} \ne 0$, $\gcd_x(P, \partial_x P) = S_1$, so the repeated eigenvalue is
/// $-s_{1,0}/s_{1,1}$.
///
/// # Errors
/// From the determinants.
pub fn first_subresultant(p: &BiPoly) -> Result<(Poly<Q>, Poly<Q>)> {
    let n = p.deg_x();
    if n < 2 {
        return Ok((Poly::zero(Q), Poly::zero(Q)));
    }
    let bound = (2 * n - 3) * p.deg_v();
    let at = |i: usize| {
        interpolate_at_good_points(&Poly::one(Q), bound, |v| {
            let f = p.at(v);
            let fc: Vec<Rational> = (0..=n).map(|k| f.coeff(k)).collect();
            let g = f.derivative();
            let gc: Vec<Rational> = (0..n).map(|k| g.coeff(k)).collect();
            subresultant_coeff(&fc, n, &gc, n - 1, 1, i)
        })
    };
    Ok((at(1)?, at(0)?))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn subresultant_of_a_double_root() {
        // f = (x - 2)^2 (x + 1) = x^3 - 3x^2 + 4; gcd(f, f') = x - 2
        let f = Poly::<Q>::from_i64s(&[4, 0, -3, 1]);
        let g = f.derivative();
        let fc: Vec<Rational> = (0..4).map(|k| f.coeff(k)).collect();
        let gc: Vec<Rational> = (0..3).map(|k| g.coeff(k)).collect();
        let s11 = subresultant_coeff(&fc, 3, &gc, 2, 1, 1).unwrap();
        let s10 = subresultant_coeff(&fc, 3, &gc, 2, 1, 0).unwrap();
        assert!(!s11.is_zero());
        assert_eq!(-s10 / s11, int(2));
        // j = 0 is the resultant (zero here)
        assert!(subresultant_coeff(&fc, 3, &gc, 2, 0, 0).unwrap().is_zero());
        let h = Poly::<Q>::from_i64s(&[-1, 0, 1]);
        let hc: Vec<Rational> = (0..3).map(|k| h.coeff(k)).collect();
        let hd: Vec<Rational> = vec![int(0), int(2)];
        assert_eq!(
            subresultant_coeff(&hc, 2, &hd, 1, 0, 0).unwrap(),
            h.resultant(&h.derivative())
        );
    }

    /// The resultant of the shared kernel equals the Sylvester determinant of formal
    /// degrees n, n - 1 at every point, on random P(x, v) with rational coefficients.
    #[test]
    fn discriminant_is_the_sylvester_determinant() {
        let mut g = crate::rng::SplitMix64(0xd15c);
        let mut small = |m: u64| (g.next_u64() % (2 * m + 1)) as i64 - m as i64;
        for _ in 0..12 {
            let n = 2 + (small(2).unsigned_abs() as usize);
            let coeffs: Vec<Poly<Q>> = (0..=n)
                .map(|k| {
                    let cs: Vec<i64> = (0..3).map(|_| small(5)).collect();
                    let c = Poly::<Q>::from_i64s(&cs);
                    let c = if k == n && c.is_zero() {
                        Poly::one(Q)
                    } else {
                        c
                    };
                    c.scale(&Rational::new(1.into(), (1 + small(3).abs()).into()))
                })
                .collect();
            let p = BiPoly { coeffs };
            let d = discriminant_v(&p).unwrap();
            for v in -3i64..4 {
                let v = Rational::from_integer(v.into());
                let f = p.at(&v);
                if f.deg() < n {
                    continue;
                }
                let fc: Vec<Rational> = (0..=n).map(|k| f.coeff(k)).collect();
                let fd = f.derivative();
                let gc: Vec<Rational> = (0..n).map(|k| fd.coeff(k)).collect();
                let sylvester = subresultant_coeff(&fc, n, &gc, n - 1, 0, 0).unwrap();
                assert_eq!(d.eval(&v), sylvester, "{p:?} at {v}");
                assert_eq!(sylvester, f.resultant(&fd), "{p:?} at {v}");
            }
        }
    }

    #[test]
    fn interpolation_reproduces() {
        let f = Poly::<Q>::from_i64s(&[3, -1, 0, 2]);
        let xs: Vec<Rational> = (0..4).map(int).collect();
        let ys: Vec<Rational> = xs.iter().map(|x| f.eval(x)).collect();
        assert_eq!(interpolate(&xs, &ys), f);
        assert_eq!(interpolate_consecutive(&ys), f);
        let g = Poly::<Q>::from_i64s(&[0, 1, 1]).scale(&Rational::new(1.into(), 2.into()));
        let ys: Vec<Rational> = (0..5).map(|i| g.eval(&int(i))).collect();
        assert_eq!(interpolate_consecutive(&ys), g);
    }
}
