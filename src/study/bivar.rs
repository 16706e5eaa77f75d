//! The characteristic polynomial $P(x, v) = \sum_k p_k(v) x^k$ of a family over $F(v)$ and
//! the polynomials in $v$ that locate its critical values, by evaluation at integers and
//! interpolation over any field $F$ (written once: $F = \mathbb{Q}$ for [`ParamFamily`],
//! $F = K$ a quadratic field for [`super::critical::over_k`]).
//!
//! # Algorithm
//! With the rows of the pencil $\sum_j x^j P_j(v)$ scaled to polynomials in $v$ (each row
//! by the lcm of its denominators), $\det = c(v) P(x, v)$ has degree at most $d_x = \sum_i
//! \max\{j : \text{row } i \text{ of } P_j \ne 0\}$ in $x$ and $d_v = \sum_i \max
//! \deg_v(\text{row } i)$ in $v$; it is interpolated from the determinants at $(x_a, v_b) =
//! (a, b)$, $0 \le a \le d_x$, $0 \le b \le d_v$ ([`det_xv`]; each determinant by the
//! field's kernel). The conditions, at points $v_b$ where $p_n(v_b) \ne 0$:
//! * zero eigenvalue: $p_0(v)$;
//! * double eigenvalue: $\mathrm{Res}_x(P, \partial_x P)$, degree $\le (2 d_x - 1) d_v$
//!   ([`discriminant_over`]; over $\mathbb{Q}$ the shared subresultant resultant of
//!   $\mathbb{Z}[v][x]$, [`discriminant_v`]);
//! * over $\mathbb{Q}$ a pair $\lambda_i + \lambda_j = 0$ (which includes every imaginary
//!   pair): the Hurwitz determinant $\Delta_{n-1}(v)$ ([`hurwitz_delta_n1`]); over any $F$ an
//!   eigenvalue mirrored across the imaginary axis, $\lambda_i + \bar\lambda_j = 0$:
//!   $\mathrm{Res}_x(P(x, v), \bar P(-x, v))$, degree $\le 2 d_x d_v$ ([`mirror_resultant`]).
//!
//! The result over $\mathbb{Q}$ is checked: $P(x, v_0)/p_n(v_0) = \chi_{A(v_0)}$ at a
//! rational $v_0$, computed independently.

use super::family::ParamFamily;
use super::hurwitz::hurwitz_matrix;
use crate::algebraic::NumberField;
use crate::error::{Error, Result};
use crate::field::{Field, Q, Rational};
use crate::matrix::Matrix;
use crate::poly::Poly;
use num_traits::{One, Zero};

/// Largest accepted degree bound of $P$ in $v$ or in $x$ (bounds the grid).
pub const MAX_BIDEGREE: usize = 400;

/// Largest degree bound of a condition polynomial in $v$ (one resultant over $K$ per
/// interpolation point): beyond it `Limit`, not hours of work.
pub const MAX_CONDITION_DEGREE: usize = 20_000;

/// $P(x, v)$: `coeffs[j]` is $p_j(v)$.
#[derive(Clone, Debug, PartialEq)]
pub struct BiPolyOver<F: Field> {
    pub coeffs: Vec<Poly<F>>,
}

impl<F: Field> BiPolyOver<F> {
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
    /// $p_n(v)$.
    pub fn lead(&self) -> Poly<F> {
        self.coeffs.last().cloned().expect("nonzero")
    }
    /// The coefficient of the highest power of $v$ as a polynomial in $x$:
    /// $P(x, v) = v^{d} L(x) + O(v^{d-1})$, $d$ = [`Self::deg_v`]. As $|v| \to \infty$ the
    /// roots of $P(\cdot, v)$ that stay finite tend to the roots of $L$ (Hurwitz's theorem
    /// on $v^{-d} P$); for a gain sweep $\det(xI - A + vBC)$ they are the open-loop zeros.
    pub fn lead_in_v(&self) -> Poly<F> {
        let d = self.deg_v();
        let f = self.lead().field().clone();
        let cs = self
            .coeffs
            .iter()
            .map(|c| {
                if c.degree() == Some(d) {
                    c.coeffs()[d].clone()
                } else {
                    f.zero()
                }
            })
            .collect();
        Poly::new(f, cs)
    }
    /// $P(x, v_0) \in F[x]$.
    pub fn at(&self, v0: &F::Elem) -> Poly<F> {
        let f = self.lead().field().clone();
        Poly::new(f, self.coeffs.iter().map(|c| c.eval(v0)).collect())
    }
    /// $P(x, v_0)$ for $v_0$ in a field `e` that the coefficients map into by `lift`.
    pub fn at_in<E: Field>(
        &self,
        e: &E,
        v0: &E::Elem,
        lift: &dyn Fn(&F::Elem) -> E::Elem,
    ) -> Poly<E> {
        let c = self
            .coeffs
            .iter()
            .map(|p| {
                p.coeffs()
                    .iter()
                    .rev()
                    .fold(e.zero(), |acc, c| e.add(&e.mul(&acc, v0), &lift(c)))
            })
            .collect();
        Poly::new(e.clone(), c)
    }
}

/// $P(x, v)$ over $\mathbb{Q}$.
pub type BiPoly = BiPolyOver<Q>;

impl BiPolyOver<Q> {
    /// $P(x, v_0)$ over $\mathbb{Q}(v_0) = \mathbb{Q}[t]/(f)$, $v_0 = t$.
    pub fn at_nf(&self, k: &NumberField) -> Poly<NumberField> {
        Poly::new(
            k.clone(),
            self.coeffs.iter().map(|c| k.from_poly(c)).collect(),
        )
    }
}

fn int<F: Field>(f: &F, i: usize) -> F::Elem {
    f.from_i64(i as i64)
}

/// Newton's divided differences: the polynomial of degree $< n$ through the $n$ points
/// $(x_i, y_i)$ (distinct $x_i$).
pub fn interpolate<F: Field>(f: &F, xs: &[F::Elem], ys: &[F::Elem]) -> Result<Poly<F>> {
    let n = xs.len();
    let mut c: Vec<F::Elem> = ys.to_vec();
    for j in 1..n {
        for i in (j..n).rev() {
            let den = f.sub(&xs[i], &xs[i - j]);
            let inv = f.inv(&den).ok_or(Error::DivisionByZero)?;
            c[i] = f.mul(&f.sub(&c[i], &c[i - 1]), &inv);
        }
    }
    let mut p = Poly::zero(f.clone());
    for i in (0..n).rev() {
        // p = p (x - x_i) + c_i
        let lin = Poly::new(f.clone(), vec![f.neg(&xs[i]), f.one()]);
        p = p.mul(&lin).add(&Poly::constant(f.clone(), c[i].clone()));
    }
    Ok(p)
}

/// $P(x, v)$ (lead $p_n$ monic in $v$) and the content $c(v)$ divided out (monic), from
/// the pencil's rows made polynomial: `rows[i][j][c]` is entry $(i, c)$ of $P_j$.
///
/// # Errors
/// `Singular` when the determinant vanishes identically; `Limit` beyond
/// [`MAX_BIDEGREE`].
pub fn det_xv<F: Field>(f: &F, rows: &[Vec<Vec<Poly<F>>>]) -> Result<(BiPolyOver<F>, Poly<F>)> {
    let n2 = rows.len();
    let (mut dx, mut dv) = (0usize, 0usize);
    for r in rows {
        let Some(jmax) = r.iter().rposition(|row| row.iter().any(|x| !x.is_zero())) else {
            return Err(Error::Singular);
        };
        dx += jmax;
        dv += r
            .iter()
            .flatten()
            .map(|x| x.degree().unwrap_or(0))
            .max()
            .unwrap_or(0);
    }
    if dx > MAX_BIDEGREE || dv > MAX_BIDEGREE {
        return Err(Error::Limit(format!(
            "characteristic polynomial of degree {dx} in x and {dv} in the parameter"
        )));
    }
    let xs: Vec<F::Elem> = (0..=dx).map(|i| int(f, i)).collect();
    let vs: Vec<F::Elem> = (0..=dv).map(|i| int(f, i)).collect();
    let mut table: Vec<Vec<F::Elem>> = vec![vec![]; dx + 1];
    for vb in &vs {
        let at_v: Vec<Vec<Vec<F::Elem>>> = rows
            .iter()
            .map(|r| {
                r.iter()
                    .map(|row| row.iter().map(|p| p.eval(vb)).collect())
                    .collect()
            })
            .collect();
        let mut dets = Vec::with_capacity(dx + 1);
        for xa in &xs {
            let m = Matrix::from_fn(f.clone(), n2, n2, |i, k| {
                let mut s = f.zero();
                let mut pw = f.one();
                for row in &at_v[i] {
                    s = f.add(&s, &f.mul(&row[k], &pw));
                    pw = f.mul(&pw, xa);
                }
                s
            });
            dets.push(if n2 == 0 { f.one() } else { m.det()? });
        }
        let px = interpolate(f, &xs, &dets)?;
        for (k, col) in table.iter_mut().enumerate() {
            col.push(px.coeff(k));
        }
    }
    let mut coeffs = table
        .iter()
        .map(|ys| interpolate(f, &vs, ys))
        .collect::<Result<Vec<_>>>()?;
    while coeffs.len() > 1 && coeffs.last().is_some_and(|c| c.is_zero()) {
        coeffs.pop();
    }
    if coeffs.iter().all(|c| c.is_zero()) {
        return Err(Error::Singular);
    }
    let content = coeffs
        .iter()
        .fold(Poly::zero(f.clone()), |g, c| {
            if c.is_zero() { g } else { g.gcd(c) }
        })
        .monic();
    let lc = coeffs.last().expect("nonzero").quo(&content).lc();
    let inv = f.inv(&lc).ok_or(Error::DivisionByZero)?;
    let coeffs = coeffs.iter().map(|c| c.quo(&content).scale(&inv)).collect();
    Ok((BiPolyOver { coeffs }, content))
}

/// A polynomial in $v$ of degree $\le$ `bound` from its values at integers where
/// $p_n(v) \ne 0$.
pub(crate) fn interpolate_where_defined<F: Field>(
    f: &F,
    lead: &Poly<F>,
    bound: usize,
    val: &dyn Fn(&F::Elem) -> Result<F::Elem>,
) -> Result<Poly<F>> {
    if bound > MAX_CONDITION_DEGREE {
        return Err(Error::Limit(format!(
            "a condition polynomial of degree up to {bound} in the parameter (at most {MAX_CONDITION_DEGREE} over an extension field)"
        )));
    }
    let (mut xs, mut ys) = (vec![], vec![]);
    let mut i = 0usize;
    while xs.len() <= bound {
        let v = int(f, i);
        i += 1;
        if f.is_zero(&lead.eval(&v)) {
            continue;
        }
        ys.push(val(&v)?);
        xs.push(v);
    }
    interpolate(f, &xs, &ys)
}

/// $\mathrm{Res}_x(P, \partial_x P)(v)$.
///
/// # Errors
/// `Limit` beyond [`MAX_BIDEGREE`] squared.
pub fn discriminant_over<F: Field>(f: &F, p: &BiPolyOver<F>) -> Result<Poly<F>> {
    let dv = p.deg_v();
    let n = p.deg_x();
    if n < 2 {
        return Ok(Poly::one(f.clone()));
    }
    interpolate_where_defined(f, &p.lead(), (2 * n - 1) * dv, &|v| {
        let q = p.at(v);
        Ok(q.resultant(&q.derivative()))
    })
}

/// $\mathrm{Res}_x(P(x, v), \bar P(-x, v))$ with `conj` the complex conjugation of $F$
/// (the identity on a real field), after dividing out $x^z$ when $p_0 = \dots = p_{z-1} = 0$
/// identically (a persistent zero eigenvalue).
///
/// # Errors
/// As [`discriminant_over`].
pub fn mirror_resultant<F: Field>(
    f: &F,
    p: &BiPolyOver<F>,
    conj: &dyn Fn(&F::Elem) -> F::Elem,
) -> Result<Poly<F>> {
    // a zero eigenvalue for every v (p_0 = ... = p_{z-1} = 0) is no crossing: divide x^z out
    let z = p.coeffs.iter().take_while(|c| c.is_zero()).count();
    let p = &BiPolyOver {
        coeffs: p.coeffs[z.min(p.deg_x())..].to_vec(),
    };
    let dv = p.deg_v();
    let n = p.deg_x();
    interpolate_where_defined(f, &p.lead(), 2 * n * dv, &|v| {
        let q = p.at(v);
        let m: Vec<F::Elem> = q
            .coeffs()
            .iter()
            .enumerate()
            .map(|(j, c)| {
                let c = conj(c);
                if j % 2 == 1 { f.neg(&c) } else { c }
            })
            .collect();
        Ok(q.resultant(&Poly::new(f.clone(), m)))
    })
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
    let (p, content) = det_xv(&Q, &fam.poly_rows())?;
    // integer coefficients without common factor, leading coefficient of p_n positive
    let mut den = num_bigint::BigInt::one();
    let mut num_gcd = num_bigint::BigInt::zero();
    for c in p.coeffs.iter().flat_map(|c| c.coeffs().iter()) {
        den = num_integer::Integer::lcm(&den, c.denom());
        num_gcd = num_integer::Integer::gcd(&num_gcd, c.numer());
    }
    let mut scale = Rational::new(den, num_gcd.max(num_bigint::BigInt::one()));
    if p.lead().lc() < Rational::zero() {
        scale = -scale;
    }
    let p = BiPoly {
        coeffs: p.coeffs.iter().map(|c| c.scale(&scale)).collect(),
    };
    check_charpoly(&Q, &p, &fam.param, &|v0| fam.state_matrix_q(v0))?;
    Ok((p, content))
}

/// Checks $P(x, v_0) = p_n(v_0) \chi_{A(v_0)}(x)$ at a rational $v_0$ (in `f`) where both
/// sides are defined, `state` giving $A(v_0)$.
///
/// # Errors
/// `Verification` when they differ or no point is found.
pub fn check_charpoly<F: Field>(
    f: &F,
    p: &BiPolyOver<F>,
    param: &str,
    state: &dyn Fn(&F::Elem) -> Result<Matrix<F>>,
) -> Result<()> {
    for t in 0..64i64 {
        let v0 = f.from_rational(&Rational::new((7919 + 31 * t).into(), 1009.into()));
        if f.is_zero(&p.lead().eval(&v0)) {
            continue;
        }
        let Ok(a) = state(&v0) else {
            continue;
        };
        let lhs = p.at(&v0);
        if lhs.deg() != a.nrows() || lhs.monic() != a.charpoly()? {
            return Err(Error::Verification(format!(
                "characteristic polynomial in (x, {param}) over {f} disagrees with charpoly(A({}))",
                f.fmt_elem(&v0)
            )));
        }
        return Ok(());
    }
    Err(Error::Verification(
        "no rational check point for the characteristic polynomial".into(),
    ))
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
    interpolate_where_defined(&Q, &Poly::one(Q), bound, &|v| {
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
        interpolate_where_defined(&Q, &Poly::one(Q), bound, &|v| {
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
        assert_eq!(-s10 / s11, int(&Q, 2));
        // j = 0 is the resultant (zero here)
        assert!(subresultant_coeff(&fc, 3, &gc, 2, 0, 0).unwrap().is_zero());
        let h = Poly::<Q>::from_i64s(&[-1, 0, 1]);
        let hc: Vec<Rational> = (0..3).map(|k| h.coeff(k)).collect();
        let hd: Vec<Rational> = vec![int(&Q, 0), int(&Q, 2)];
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
        let int = |i: usize| int(&Q, i);
        let f = Poly::<Q>::from_i64s(&[3, -1, 0, 2]);
        let xs: Vec<Rational> = (0..4).map(int).collect();
        let ys: Vec<Rational> = xs.iter().map(|x| f.eval(x)).collect();
        assert_eq!(interpolate(&Q, &xs, &ys).unwrap(), f);
        let g = Poly::<Q>::from_i64s(&[0, 1, 1]).scale(&Rational::new(1.into(), 2.into()));
        let xs: Vec<Rational> = (0..5).map(int).collect();
        let ys: Vec<Rational> = xs.iter().map(|x| g.eval(x)).collect();
        assert_eq!(interpolate(&Q, &xs, &ys).unwrap(), g);
        let xs: Vec<_> = [0, 2, 5, 7].iter().map(|&i| Q.from_i64(i)).collect();
        let ys: Vec<_> = xs.iter().map(|x| f.eval(x)).collect();
        assert_eq!(interpolate(&Q, &xs, &ys).unwrap(), f);
    }

    #[test]
    fn determinant_of_a_companion_family() {
        // A(v) = [[0, 1], [-v, -1]]: det(xI - A) = x^2 + x + v; pencil [-A, I]
        let c = |i: i64| Poly::<Q>::from_i64s(&[i]);
        let v = Poly::<Q>::from_i64s(&[0, 1]);
        let rows = vec![
            vec![vec![c(0), c(-1)], vec![c(1), c(0)]],
            vec![vec![v.clone(), c(1)], vec![c(0), c(1)]],
        ];
        let (p, content) = det_xv(&Q, &rows).unwrap();
        assert!(content.is_one());
        assert_eq!(p.coeffs, vec![v.clone(), c(1), c(1)]);
        // disc = 1 - 4v up to sign
        let d = discriminant_over(&Q, &p).unwrap();
        assert_eq!(d.monic(), Poly::<Q>::from_i64s(&[-1, 4]).monic());
        // Res(P(x), P(-x)) = prod P(-l) = prod (-2 l) = 4 v: a zero eigenvalue at v = 0 only
        let r = mirror_resultant(&Q, &p, &|c| c.clone()).unwrap();
        assert_eq!(r.monic(), Poly::<Q>::from_i64s(&[0, 1]));
    }
}
