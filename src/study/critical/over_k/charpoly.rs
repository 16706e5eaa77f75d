//! The characteristic polynomial $P(x, v) = \sum_j p_j(v) x^j$ of a family over $F(v)$ and
//! the polynomials in $v$ whose roots are the critical values, all by evaluation at
//! integers and interpolation over any field $F$ (written once for every ground field).
//!
//! With the rows of the pencil $\sum_j x^j P_j(v)$ scaled to polynomials in $v$,
//! $\det = c(v) P(x, v)$ has degree at most $d_x = \sum_i \max\{j : \text{row } i \text{ of }
//! P_j \ne 0\}$ in $x$ and $d_v = \sum_i \max \deg_v(\text{row } i)$ in $v$; it is
//! interpolated from the determinants at $(x_a, v_b) = (a, b)$, $0 \le a \le d_x$,
//! $0 \le b \le d_v$. The conditions, at points $v_b$ where $p_n(v_b) \ne 0$ (so that
//! resultants specialize):
//! * zero eigenvalue: $p_0(v)$;
//! * double eigenvalue: $\mathrm{Res}_x(P, \partial_x P)$, degree $\le (2 d_x - 1) d_v$;
//! * an eigenvalue mirrored by another across the imaginary axis, $\lambda_i + \bar\lambda_j
//!   = 0$ (for $i = j$: on the axis): $\mathrm{Res}_x(P(x, v), \bar P(-x, v))$, degree $\le
//!   2 d_x d_v$, where $\bar P$ conjugates the coefficients ($\bar P = P$ over a real field).

use crate::error::{Error, Result};
use crate::field::Field;
use crate::matrix::Matrix;
use crate::poly::Poly;

/// Largest degree bound in $x$ or $v$ accepted (as over $\mathbb{Q}$).
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
    /// $p_n(v)$.
    pub fn lead(&self) -> Poly<F> {
        self.coeffs.last().cloned().expect("nonzero")
    }
    /// $P(x, v_0)$ for $v_0$ in a field `e` that the coefficients map into by `lift`.
    pub fn at<E: Field>(&self, e: &E, v0: &E::Elem, lift: &dyn Fn(&F::Elem) -> E::Elem) -> Poly<E> {
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
fn interpolate_where_defined<F: Field>(
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

/// $P(x, v_0)$ for $v_0 \in F$.
fn at_point<F: Field>(f: &F, p: &BiPolyOver<F>, v0: &F::Elem) -> Poly<F> {
    Poly::new(f.clone(), p.coeffs.iter().map(|c| c.eval(v0)).collect())
}

/// $\mathrm{Res}_x(P, \partial_x P)(v)$.
///
/// # Errors
/// `Limit` beyond [`MAX_BIDEGREE`] squared.
pub fn discriminant_over<F: Field>(f: &F, p: &BiPolyOver<F>) -> Result<Poly<F>> {
    let dv = p
        .coeffs
        .iter()
        .map(|c| c.degree().unwrap_or(0))
        .max()
        .unwrap_or(0);
    let n = p.deg_x();
    if n < 2 {
        return Ok(Poly::one(f.clone()));
    }
    interpolate_where_defined(f, &p.lead(), (2 * n - 1) * dv, &|v| {
        let q = at_point(f, p, v);
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
    let dv = p
        .coeffs
        .iter()
        .map(|c| c.degree().unwrap_or(0))
        .max()
        .unwrap_or(0);
    let n = p.deg_x();
    interpolate_where_defined(f, &p.lead(), 2 * n * dv, &|v| {
        let q = at_point(f, p, v);
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::Q;

    #[test]
    fn interpolation_recovers_a_polynomial() {
        let p = Poly::<Q>::from_i64s(&[3, -1, 0, 2]);
        let xs: Vec<_> = [0, 2, 5, 7].iter().map(|&i| Q.from_i64(i)).collect();
        let ys: Vec<_> = xs.iter().map(|x| p.eval(x)).collect();
        assert_eq!(interpolate(&Q, &xs, &ys).unwrap(), p);
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
