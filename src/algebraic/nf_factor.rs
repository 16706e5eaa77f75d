//! Factorization over a number field $K = \mathbb{Q}\[t\]/(m)$ by Trager's norm method.
//!
//! For square-free monic $f \in K\[x\]$ choose $s = 0, 1, -1, 2, -2, \dots$ until the norm
//! $N(x) = \mathrm{Res}_t\big(m(t), f(x - s t, t)\big) \in \mathbb{Q}\[x\]$ is square-free.
//! Then $N = \prod_i N_i$ over $\mathbb{Q}$ gives $f(x - s t) = \prod_i \gcd_K(f(x - s t),
//! N_i)$ with each gcd irreducible over $K$ (Trager 1976), and substituting back
//! $x \mapsto x + s t$ gives the factors of $f$. The norm is computed by evaluation at
//! $\deg N + 1$ integers (univariate resultants over $\mathbb{Q}$) and Newton interpolation.
//! A general $f$ is first split by Yun's square-free decomposition over $K$.
//!
//! | entry point | computes |
//! |---|---|
//! | [`factor_over_number_field`] | monic irreducible factors over $K$ with multiplicities |
//! | [`norm`] | $\mathrm{Res}_t(m(t), f(x, t))$ |

use super::{NfElem, NumberField};
use crate::error::{Error, Result};
use crate::field::{Field, Q, Rational};
use crate::poly::Poly;

/// The norm $N_{K(x)/\mathbb{Q}(x)}(f) = \mathrm{Res}_t(m(t), f(x, t))$ of `f` in $K\[x\]$
/// (monic in $x$ of degree $[K:\mathbb{Q}] \deg f$ when `f` is monic).
pub fn norm(f: &Poly<NumberField>) -> Poly<Q> {
    let k = f.field();
    let m = k.modulus();
    let d = k.degree() * f.deg();
    // values at x = 0..=d
    let xs: Vec<Rational> = (0..=d as i64)
        .map(|i| Rational::from_integer(i.into()))
        .collect();
    let ys: Vec<Rational> = xs
        .iter()
        .map(|x0| {
            // F(t) = sum_k c_k(t) x0^k
            let mut acc = Poly::zero(Q);
            let mut pw = Rational::from_integer(1.into());
            for c in f.coeffs() {
                let ct = k.to_poly(c);
                acc = acc.add(&ct.scale(&pw));
                pw *= x0;
            }
            m.resultant(&acc)
        })
        .collect();
    interpolate(&xs, &ys)
}

/// Newton interpolation through `(xs[i], ys[i])`.
fn interpolate(xs: &[Rational], ys: &[Rational]) -> Poly<Q> {
    let n = xs.len();
    let mut c = ys.to_vec();
    for j in 1..n {
        for i in (j..n).rev() {
            c[i] = (&c[i] - &c[i - 1]) / (&xs[i] - &xs[i - j]);
        }
    }
    let mut p = Poly::constant(Q, c[n - 1].clone());
    for i in (0..n - 1).rev() {
        p = p
            .mul(&Poly::new(
                Q,
                vec![-xs[i].clone(), Rational::from_integer(1.into())],
            ))
            .add(&Poly::constant(Q, c[i].clone()));
    }
    p
}

/// $x + c$ in $K[x]$.
fn x_plus(k: &NumberField, c: &NfElem) -> Poly<NumberField> {
    Poly::new(k.clone(), vec![c.clone(), k.one()])
}

/// Irreducible monic factors over $K$ of a square-free monic `f`.
fn trager_squarefree(f: &Poly<NumberField>) -> Result<Vec<Poly<NumberField>>> {
    let k = f.field().clone();
    if f.deg() <= 1 {
        return Ok(vec![f.monic()]);
    }
    let t = k.generator();
    for i in 0..64i64 {
        let s = if i % 2 == 1 { (i + 1) / 2 } else { -(i / 2) };
        let st = k.mul(&k.from_i64(s), &t);
        // g(x) = f(x - s t)
        let g = f.compose(&x_plus(&k, &k.neg(&st)));
        let nrm = norm(&g);
        if !nrm.gcd(&nrm.derivative()).is_one() {
            continue;
        }
        let (_, facs) = super::factor_q(&nrm)?;
        if facs.len() == 1 {
            return Ok(vec![f.monic()]);
        }
        let back = x_plus(&k, &st);
        let mut out = vec![];
        for (ni, _) in facs {
            let nk = ni.map(&k, |c| k.from_rational(c));
            let h = g.gcd(&nk);
            if h.deg() >= 1 {
                out.push(h.compose(&back).monic());
            }
        }
        let total: usize = out.iter().map(|h| h.deg()).sum();
        if total != f.deg() {
            return Err(Error::Verification(format!(
                "Trager factors of degree {total} for a polynomial of degree {}",
                f.deg()
            )));
        }
        return Ok(out);
    }
    Err(Error::Limit(
        "no shift s with a square-free norm among 64 tries".into(),
    ))
}

/// Factorization of `f` over its number field $K$: monic irreducible factors with
/// multiplicities, sorted by degree then by the display of their coefficients; the product
/// of `g^e` is the monic associate of `f`.
///
/// # Errors
/// `Invalid` for the zero polynomial; `Limit` / `Verification` from the norm method.
///
/// # Examples
/// ```
/// use exactlti::algebraic::factor_over_number_field;
/// use exactlti::algebraic::NumberField;
/// use exactlti::field::{Field, Q};
/// use exactlti::poly::Poly;
/// // x^2 + 1 over Q(i) = Q[t]/(t^2 + 1) splits as (x - t)(x + t)
/// let k = NumberField::new(&Poly::from_i64s(&[1, 0, 1]), (0.0, 1.0)).unwrap();
/// let f = Poly::from_i64s(&[1, 0, 1]).map(&k, |c| k.from_rational(c));
/// let fs = factor_over_number_field(&f).unwrap();
/// let shown: Vec<String> = fs.iter().map(|(g, _)| g.to_string()).collect();
/// assert_eq!(shown, ["x + t", "x - t"]);
/// ```
pub fn factor_over_number_field(f: &Poly<NumberField>) -> Result<Vec<(Poly<NumberField>, usize)>> {
    if f.is_zero() {
        return Err(Error::Invalid(
            "factorization of the zero polynomial".into(),
        ));
    }
    let mut out = vec![];
    for (g, e) in f.squarefree() {
        for h in trager_squarefree(&g)? {
            out.push((h, e));
        }
    }
    let key = |h: &Poly<NumberField>| (h.deg(), h.to_string());
    out.sort_by(|a, b| key(&a.0).cmp(&key(&b.0)).then(a.1.cmp(&b.1)));
    Ok(out)
}
