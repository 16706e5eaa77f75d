//! Where the rank of a matrix over $\mathbb{Q}(p)$ drops: the irreducible factors of the
//! **gcd of its maximal nonzero minors**, not the pivots of one elimination.
//!
//! For $M$ of rank $r$ over $\mathbb{Q}(p)$, a parameter value $p_0$ where $M$ is defined has
//! $\operatorname{rank} M(p_0) < r$ exactly when every $r \times r$ minor vanishes there. The
//! hypersurfaces where that happens are the zero sets of the irreducible $f$ dividing (the
//! numerator of) every minor. [`drop_factors`] finds them in two steps:
//!
//! 1. **candidates**: the irreducible factors of the numerator of **one** nonzero minor
//!    $\det M_{I,J}$ (rows and columns independent at a random point; a square $M$ has only
//!    $\det M$, and then step 2 is skipped: exact);
//! 2. **the test on the hypersurface**: a candidate $f$ linear in some parameter $x$
//!    ($f = a x + b$) gets two random rational points with $x = -b/a$, on $f = 0$; it is kept
//!    when the rank there (over $\mathbb{Q}$, of the caller's matrix evaluated at the point)
//!    is below $r$ at both. If $f$ divided every minor the rank drops at every point of
//!    $f = 0$; if a minor $m$ is not divisible by $f$, $m$ restricted to $f = 0$ is a nonzero
//!    polynomial and a random point gives $m \ne 0$ (Schwartz–Zippel: wrong with probability
//!    at most $\deg m / 2^{20}$ per point). A candidate linear in no parameter is kept (a
//!    superset, stated by [`Drop::untested`]).

use super::Matrix;
use crate::error::{Error, Result};
use crate::field::{Q, Rational};
use crate::mpoly::{MPoly, factor};
use crate::ratfunc::RatFuncField;
use crate::ratfunc::kernels::budget::det_budget;
use crate::rng::SplitMix64;
use num_traits::Zero;

/// `m` itself when the numerator of $\det m$ is within the determinant kernel's size budget
/// ([`crate::ratfunc::kernels::budget::det_budget`]: `Matrix::det` over $\mathbb{Q}(p)$
/// answers `Limit` beyond it): a check before any work, for a caller that expands smaller
/// minors first.
///
/// # Errors
/// `Limit` beyond (the caller falls back to its computation's log of conditions).
pub fn expandable(m: &Matrix<RatFuncField>) -> Result<&Matrix<RatFuncField>> {
    let nv = m.field().nvars();
    det_budget(nv, m.nrows(), m.ncols(), m.as_slice())?;
    Ok(m)
}

/// Half-width of the random integer coordinates of the test points.
const RANGE: i64 = 1 << 20;

/// The factors [`drop_factors`] found: `tested` (the rank drops on each, checked at points),
/// `untested` (linear in no parameter: kept unchecked).
#[derive(Clone, Debug, Default)]
pub struct Drop {
    pub tested: Vec<MPoly>,
    pub untested: Vec<MPoly>,
}

impl Drop {
    /// Every factor, tested first.
    pub fn all(self) -> Vec<MPoly> {
        let mut v = self.tested;
        v.extend(self.untested);
        v
    }
}

/// `m` at the rational `point`; `None` at a pole of an entry.
pub fn eval_at(m: &Matrix<RatFuncField>, point: &[Rational]) -> Option<Matrix<Q>> {
    let k = m.field();
    let mut xs = Vec::with_capacity(m.nrows() * m.ncols());
    for x in m.as_slice() {
        xs.push(k.eval(x, point)?);
    }
    Some(Matrix::from_vec(Q, m.nrows(), m.ncols(), xs))
}

/// A random rational point (integer coordinates).
pub fn random_point(nv: usize, rng: &mut SplitMix64) -> Vec<Rational> {
    (0..nv)
        .map(|_| Rational::from_integer(rng.int(-RANGE, RANGE).into()))
        .collect()
}

/// A random point on $f = 0$ for `f` linear in some parameter; `None` when it is linear in
/// none (or the leading coefficient vanished at every try).
fn point_on(k: &RatFuncField, f: &MPoly, rng: &mut SplitMix64) -> Option<Vec<Rational>> {
    let nv = f.nvars();
    let x = (0..nv).find(|&i| f.deg(i) == 1)?;
    let cs = f.to_univariate(x);
    for _ in 0..8 {
        let mut p = random_point(nv, rng);
        let ev = |g: &MPoly, p: &[Rational]| k.eval(&k.from_mpoly(g.clone()), p);
        let a = ev(&cs[1], &p)?;
        if a.is_zero() {
            continue;
        }
        p[x] = -ev(&cs[0], &p)? / a;
        return Some(p);
    }
    None
}

/// The irreducible factors of `candidates` on whose zero set `rank_at` (the rank of the
/// caller's matrix at a rational point, `None` where it is undefined) drops below `r`
/// (module docs, step 2); `exact`: every factor is known to divide every minor (kept
/// without a test).
///
/// # Errors
/// As [`crate::mpoly::factor()`] (`Limit`).
pub fn drop_factors(
    k: &RatFuncField,
    candidates: &MPoly,
    r: usize,
    exact: bool,
    rank_at: &dyn Fn(&[Rational]) -> Option<usize>,
) -> Result<Drop> {
    if candidates.is_constant() || r == 0 {
        return Ok(Drop::default());
    }
    let fs: Vec<MPoly> = factor(&candidates.primitive_part())?
        .factors
        .into_iter()
        .map(|(f, _)| f)
        .collect();
    Ok(test_factors(k, fs, r, exact, rank_at))
}

/// [`drop_factors`] on candidates already factored (irreducible).
pub fn test_factors(
    k: &RatFuncField,
    fs: Vec<MPoly>,
    r: usize,
    exact: bool,
    rank_at: &dyn Fn(&[Rational]) -> Option<usize>,
) -> Drop {
    let mut out = Drop::default();
    let mut rng = SplitMix64(0x25c0_4d17);
    for f in fs {
        if f.is_constant() {
            continue;
        }
        if exact {
            out.tested.push(f);
            continue;
        }
        let mut verdicts = vec![];
        for _ in 0..16 {
            if verdicts.len() == 2 {
                break;
            }
            let Some(p) = point_on(k, &f, &mut rng) else {
                break;
            };
            if let Some(q) = rank_at(&p) {
                verdicts.push(q < r);
            }
        }
        match verdicts.as_slice() {
            [] => out.untested.push(f),
            v if v.iter().all(|&d| d) => out.tested.push(f),
            _ => {}
        }
    }
    out
}

/// Rows of `m` (a matrix over $\mathbb{Q}$) independent and spanning its row space.
pub fn independent_rows(m: &Matrix<Q>) -> Vec<usize> {
    let (_, piv) = m.transpose().rref();
    piv
}

impl Matrix<RatFuncField> {
    /// The irreducible factors on which the rank `r` of `self` drops (module docs): the
    /// candidates of one nonzero `r x r` minor, tested on their zero sets.
    ///
    /// # Errors
    /// Those of the determinant kernel (`Limit` beyond its size budget) and of factoring.
    pub fn rank_drop(&self, r: usize) -> Result<Drop> {
        if r == 0 {
            return Ok(Drop::default());
        }
        let nv = self.field().nvars();
        let mut rng = SplitMix64(0x25c0_4d18);
        let Some((rows, cols)) = (0..16).find_map(|_| {
            let m = eval_at(self, &random_point(nv, &mut rng))?;
            let rows = independent_rows(&m);
            let cols = independent_rows(&m.select_rows(&rows).transpose());
            (rows.len() == r).then_some((rows, cols))
        }) else {
            return Err(Error::Invalid(format!(
                "rank {r} not met at 16 random points (a rank drop everywhere?)"
            )));
        };
        let minor = self.select_rows(&rows).select_cols(&cols).det()?;
        let exact = self.nrows() == r && self.ncols() == r;
        drop_factors(self.field(), minor.num(), r, exact, &|p| {
            eval_at(self, p).map(|m| m.rank())
        })
    }
}
