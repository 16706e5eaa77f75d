//! Factorization of a polynomial in $s$ with coefficients in $\mathbb{Q}(p_1, \dots, p_k)$
//! (a zero polynomial, a characteristic polynomial over symbolic parameters).
//!
//! $f(s) \in \mathbb{Q}(p)[s]$ is made primitive in $\mathbb{Z}[p, s]$ (multiplied by the
//! common denominator of its coefficients), factored there ([`crate::mpoly::factor()`]), and
//! the factors that involve $s$ are returned monic in $s$. By Gauss's lemma these are the
//! irreducible factors of $f$ over $\mathbb{Q}(p)$; the identity checked is
//! $f = \mathrm{lc}(f) \prod_i g_i^{e_i}$ as polynomials over $\mathbb{Q}(p)$.

use crate::error::{Error, Result};
use crate::mpoly::gcd::lcm;
use crate::mpoly::{MAX_VARS, MPoly};
use crate::poly::Poly;
use crate::ratfunc::RatFuncField;

/// The monic irreducible factors of `f` over $\mathbb{Q}(p)$ with multiplicities (empty for
/// a constant), verified by multiplying back.
///
/// # Errors
/// `Limit` with more than `MAX_VARS - 1` parameters or from the factorization;
/// `Verification` if the product differs from `f` (an internal error).
pub fn factor_over_qp(f: &Poly<RatFuncField>) -> Result<Vec<(Poly<RatFuncField>, usize)>> {
    let k = f.field().clone();
    if f.deg() == 0 || f.is_zero() {
        return Ok(vec![]);
    }
    let n = k.nvars();
    if n + 1 > MAX_VARS {
        return Err(Error::Limit(format!(
            "factoring over Q(p) with {n} parameters (at most {})",
            MAX_VARS - 1
        )));
    }
    // common denominator; then F(p, s) = sum_j (c_j * den) s^j with s the last variable
    let mut den = MPoly::one(n);
    for c in f.coeffs() {
        den = lcm(&den, c.den());
    }
    let s = n;
    let mut cs = Vec::with_capacity(f.deg() + 1);
    for c in f.coeffs() {
        let scaled = c.num().mul(&den.div_exact(c.den()).expect("lcm divisible"));
        cs.push(scaled.extend_vars(n + 1));
    }
    let big = MPoly::from_univariate(n + 1, s, &cs);
    let fz = crate::mpoly::factor(&big)?;
    let mut out = Vec::new();
    for (g, e) in fz.factors {
        if g.deg(s) == 0 {
            continue;
        }
        let gc: Vec<_> = g
            .to_univariate(s)
            .iter()
            .map(|c| k.from_mpoly(c.remap(n, &identity_map(n + 1))))
            .collect();
        out.push((Poly::new(k.clone(), gc).monic(), e));
    }
    // the identity f = lc(f) prod g^e
    let mut prod = Poly::new(k.clone(), vec![f.lc()]);
    for (g, e) in &out {
        for _ in 0..*e {
            prod = prod.mul(g);
        }
    }
    if prod != *f {
        return Err(Error::Verification(
            "factorization over Q(p): the product of the factors differs".into(),
        ));
    }
    Ok(out)
}

/// `map[i] = i` for the first `n - 1` variables (the last, `s`, is absent in coefficients).
fn identity_map(n: usize) -> Vec<usize> {
    (0..n).map(|i| i.min(n - 2)).collect()
}

/// All roots of `f` in the open left half plane for every parameter value? Decided per
/// irreducible factor over $\mathbb{Q}(p)$ by [`crate::structure::scb::hurwitz`] (which
/// knows the signs of constants): `Some(false)` when one factor is not Hurwitz (e.g. `s`, a
/// zero at the origin for every parameter value), `Some(true)` when every factor is,
/// `None` when the answer depends on the parameters.
///
/// # Errors
/// As [`factor_over_qp`].
pub fn hurwitz_over_qp(f: &Poly<RatFuncField>) -> Result<Option<bool>> {
    let mut all = Some(true);
    for (g, _) in factor_over_qp(f)? {
        match crate::structure::scb::hurwitz(&g) {
            Some(false) => return Ok(Some(false)),
            Some(true) => {}
            None => all = None,
        }
    }
    Ok(all)
}
