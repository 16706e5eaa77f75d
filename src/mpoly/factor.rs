//! Factorization of multivariate polynomials over $\mathbb{Q}$ (equivalently over
//! $\mathbb{Z}$, by Gauss's lemma) into irreducibles with multiplicities.
//!
//! $f = c \prod_j f_j^{e_j}$ with $c \in \mathbb{Z}$ (carrying the sign) and $f_j$ primitive,
//! of positive (lex) leading coefficient, irreducible, pairwise distinct, sorted.
//!
//! Pipeline (Wang's EEZ in outline):
//! 1. integer content; then in a main variable $x$ (the one of smallest positive degree) the
//!    content in $x$, a polynomial in fewer variables, factored recursively;
//! 2. square-free decomposition in $x$ (Yun, with multivariate gcds);
//! 3. each square-free part: evaluate the other variables at small integer points that keep
//!    the degree and square-freeness (best of three points: fewest univariate factors);
//!    factor the image with Zassenhaus ([`crate::poly::factor::factor_zpoly`]); one factor
//!    means irreducible;
//! 4. multivariate Hensel lifting with imposed leading coefficients (module `hensel`); when
//!    the images have more factors than $f$ (extraneous factors), subsets are recombined by
//!    two-factor lifts, smallest first. A bounded number of lifts ([`MAX_LIFTS`]).
//!
//! Every answer is exact: lifted factors are checked by division, and a subset search that
//! finds nothing proves irreducibility (the lift of a true factor's image always succeeds).

use super::MPoly;
use super::gcd::{content_in, gcd};
use crate::error::{Error, Result};
use crate::field::Rational;
use crate::poly::factor::factor_zpoly;
use crate::poly::zpoly::ZPoly;
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

/// Most two-factor lifts tried in the recombination of one square-free part.
pub const MAX_LIFTS: usize = 4096;
/// Evaluation points tried before giving up on finding a good one.
const MAX_POINTS: usize = 200;

/// $f = c \prod_j f_j^{e_j}$.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Factorization {
    /// Integer content with the sign of $f$.
    pub content: BigInt,
    /// Irreducible, primitive factors with positive leading coefficient and multiplicities.
    pub factors: Vec<(MPoly, usize)>,
}

impl Factorization {
    /// $c \prod_j f_j^{e_j}$ (the check of a factorization).
    pub fn expand(&self, nvars: usize) -> MPoly {
        let mut acc = MPoly::constant(nvars, self.content.clone());
        for (f, e) in &self.factors {
            acc = acc.mul(&f.pow(*e as u32));
        }
        acc
    }
}

/// Irreducible factorization over $\mathbb{Q}$ of an integer polynomial.
///
/// # Errors
/// `Invalid` for the zero polynomial; `Limit` when the recombination budget
/// ([`MAX_LIFTS`]) or the search for an evaluation point is exhausted.
///
/// # Examples
/// ```
/// use exactlti::mpoly::{factor, parse_mpoly_in};
/// let v = ["a", "b", "c"];
/// let f = parse_mpoly_in("(a*b + c^2 + 1)^3*(a - b + 2*c)^2", &v).unwrap().prim;
/// let fz = factor(&f).unwrap();
/// assert_eq!(fz.factors.len(), 2);
/// assert_eq!(fz.expand(3), f);
/// ```
pub fn factor(f: &MPoly) -> Result<Factorization> {
    if f.is_zero() {
        return Err(Error::Invalid(
            "factorization of the zero polynomial".into(),
        ));
    }
    let (c, p) = f.content_primitive();
    let mut raw = Vec::new();
    factor_primitive(&p, 1, &mut raw)?;
    // merge equal factors, sort
    raw.sort_by(|a: &(MPoly, usize), b| cmp_poly(&a.0, &b.0));
    let mut factors: Vec<(MPoly, usize)> = Vec::new();
    for (g, e) in raw {
        match factors.last_mut() {
            Some((h, k)) if *h == g => *k += e,
            _ => factors.push((g, e)),
        }
    }
    Ok(Factorization {
        content: c,
        factors,
    })
}

/// Factorization of `content * prim` over $\mathbb{Q}$: the rational content and the
/// factors of `prim`.
pub fn factor_q(f: &super::QPoly) -> Result<(Rational, Vec<(MPoly, usize)>)> {
    let fz = factor(&f.prim)?;
    Ok((&f.content * Rational::from_integer(fz.content), fz.factors))
}

/// Total order used for sorting factors: total degree, then number of terms, then terms.
pub fn cmp_poly(a: &MPoly, b: &MPoly) -> std::cmp::Ordering {
    a.total_degree()
        .cmp(&b.total_degree())
        .then(a.len().cmp(&b.len()))
        .then_with(|| {
            for (x, y) in a.terms().iter().zip(b.terms()) {
                let o = y.0.cmp(&x.0).then(x.1.cmp(&y.1));
                if o != std::cmp::Ordering::Equal {
                    return o;
                }
            }
            std::cmp::Ordering::Equal
        })
}

/// Factors a primitive polynomial with positive leading coefficient; pushes `(factor,
/// e * mult)`.
fn factor_primitive(p: &MPoly, e: usize, out: &mut Vec<(MPoly, usize)>) -> Result<()> {
    let used = p.vars_used();
    if used.is_empty() {
        return Ok(());
    }
    let degs = p.degrees();
    let x = *used.iter().min_by_key(|&&i| (degs[i], i)).unwrap();
    let cont = content_in(p, x);
    let p1 = if cont.is_one() {
        p.clone()
    } else {
        factor_primitive(&cont, e, out)?;
        p.div_exact(&cont).expect("content divides")
    };
    for (a, k) in squarefree_in(&p1, x) {
        for g in factor_squarefree(&a, x)? {
            out.push((g, e * k));
        }
    }
    Ok(())
}

/// Square-free decomposition in $x$ of a polynomial primitive in $x$ (Yun):
/// $f = \prod_i a_i^i$, $a_i$ square-free, pairwise coprime; only non-constant $a_i$ are listed.
pub fn squarefree_in(f: &MPoly, x: usize) -> Vec<(MPoly, usize)> {
    let mut out = Vec::new();
    if f.deg(x) == 0 {
        return out;
    }
    // shortcut: a square-free image of the same degree proves f square-free (gcd(f, f_x) has
    // degree 0 in x then, and f is primitive in x)
    let lc = f.lc_in(x);
    let mut rng = Rng(0xC0FFEE ^ f.len() as u64);
    for attempt in 0..3 {
        let a: Vec<BigInt> = (0..f.nvars())
            .map(|j| {
                if j == x || attempt == 0 {
                    BigInt::zero()
                } else {
                    rng.small(3 + attempt)
                }
            })
            .collect();
        if lc.eval_all(&a).is_zero() {
            continue;
        }
        let fa = f.eval_except(x, &a);
        if fa.gcd(&fa.derivative()).deg0() == 0 {
            out.push((f.abs_lc(), 1));
            return out;
        }
    }
    let fp = f.derivative(x);
    let a0 = gcd(f, &fp);
    let mut b = f.div_exact(&a0).expect("gcd divides");
    let mut c = fp.div_exact(&a0).expect("gcd divides");
    let mut d = c.sub(&b.derivative(x));
    let mut i = 1;
    while b.deg(x) > 0 {
        let a = gcd(&b, &d);
        if a.deg(x) > 0 {
            out.push((a.abs_lc(), i));
        }
        b = b.div_exact(&a).expect("gcd divides");
        c = d.div_exact(&a).expect("gcd divides");
        d = c.sub(&b.derivative(x));
        i += 1;
    }
    out
}

/// Small deterministic generator for evaluation points.
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    fn small(&mut self, r: i64) -> BigInt {
        BigInt::from((self.next() % (2 * r as u64 + 1)) as i64 - r)
    }
}

/// Irreducible factors of a square-free polynomial, primitive in $x$ with $\deg_x \ge 1$.
fn factor_squarefree(f: &MPoly, x: usize) -> Result<Vec<MPoly>> {
    let f = f.abs_lc();
    let n = f.nvars();
    let used = f.vars_used();
    if used.len() == 1 {
        let z = f.to_zpoly(x).expect("univariate");
        let (_, fs) = factor_zpoly(&z)?;
        return Ok(fs.iter().map(|(g, _)| MPoly::from_zpoly(n, x, g)).collect());
    }
    if f.deg(x) == 1 {
        return Ok(vec![f]);
    }
    let dx = f.deg(x);
    let lc = f.lc_in(x);
    let mut rng = Rng(0x5EED ^ f.len() as u64);
    let mut best: Option<(Vec<BigInt>, Vec<ZPoly>)> = None;
    let mut good = 0;
    for attempt in 0..MAX_POINTS {
        let range = 1 + (attempt as i64) / 4;
        let a: Vec<BigInt> = (0..n)
            .map(|j| {
                if j == x || !used.contains(&j) || attempt == 0 {
                    BigInt::zero()
                } else {
                    rng.small(range)
                }
            })
            .collect();
        if lc.eval_all(&a).is_zero() {
            continue;
        }
        let fa = f.eval_except(x, &a);
        if fa.deg0() != dx as usize {
            continue;
        }
        if fa.gcd(&fa.derivative()).deg0() != 0 {
            continue;
        }
        let (_, fs) = factor_zpoly(&fa)?;
        let us: Vec<ZPoly> = fs.into_iter().map(|(g, _)| g).collect();
        if us.len() == 1 {
            return Ok(vec![f]);
        }
        if best.as_ref().is_none_or(|(_, b)| us.len() < b.len()) {
            best = Some((a, us));
        }
        good += 1;
        if good >= 3 {
            break;
        }
    }
    let Some((a, us)) = best else {
        return Err(Error::Limit(
            "multivariate factorization: no good evaluation point found".into(),
        ));
    };
    if let Some(hs) = super::hensel::lift(&f, x, &a, &us) {
        return Ok(hs);
    }
    // extraneous factors: recombine subsets by two-factor lifts
    let r = us.len();
    let mut lifts = 0;
    for size in 1..=r / 2 {
        let mut subset: Vec<usize> = (0..size).collect();
        loop {
            // avoid trying S and its complement twice when size = r/2
            if !(2 * size == r && subset[0] != 0) {
                lifts += 1;
                if lifts > MAX_LIFTS {
                    return Err(Error::Limit(
                        "multivariate factorization: recombination budget exhausted".into(),
                    ));
                }
                let mut us_s = ZPoly::one();
                let mut us_c = ZPoly::one();
                for (i, u) in us.iter().enumerate() {
                    if subset.contains(&i) {
                        us_s = &us_s * u;
                    } else {
                        us_c = &us_c * u;
                    }
                }
                if let Some(hs) = super::hensel::lift(&f, x, &a, &[us_s, us_c]) {
                    let g = hs[0].clone();
                    let rest = f.div_exact(&g).expect("lifted factor divides");
                    let mut out = vec![g];
                    out.extend(factor_squarefree(&rest, x)?);
                    return Ok(out);
                }
            }
            if !next_subset(&mut subset, r) {
                break;
            }
        }
    }
    Ok(vec![f])
}

/// Next `k`-subset of `0..r` in lexicographic order.
fn next_subset(s: &mut [usize], r: usize) -> bool {
    let k = s.len();
    let mut i = k;
    while i > 0 {
        i -= 1;
        if s[i] < r - k + i {
            s[i] += 1;
            for j in i + 1..k {
                s[j] = s[j - 1] + 1;
            }
            return true;
        }
    }
    false
}

/// Is `f` irreducible over $\mathbb{Q}$ (non-constant, primitive up to a unit)?
pub fn is_irreducible(f: &MPoly) -> Result<bool> {
    let fz = factor(f)?;
    Ok(fz.factors.len() == 1 && fz.factors[0].1 == 1)
}

/// Is `c` plus or minus one?
pub fn is_unit(c: &BigInt) -> bool {
    c.abs().is_one()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mpoly::parse::abc as p;
    #[test]
    fn examples() {
        let f = p("(a*b + c^2 + 1)^3*(a - b + 2*c)^2");
        let fz = factor(&f).unwrap();
        assert_eq!(fz.expand(3), f);
        assert_eq!(
            fz.factors,
            vec![(p("a - b + 2*c"), 2), (p("a*b + c^2 + 1"), 3)]
        );
        // needs lifting: two factors with the same square-free part
        let g = p("(a^2*b + c + 3)*(a*c^2 - b + 1)*(a + b*c)");
        let gz = factor(&g).unwrap();
        assert_eq!(gz.expand(3), g);
        assert_eq!(gz.factors.len(), 3);
        let h = p("-6*a^2*b^2 + 6*c^4");
        let hz = factor(&h).unwrap();
        assert_eq!(hz.content, BigInt::from(-6));
        assert_eq!(hz.expand(3), h);
        assert_eq!(hz.factors.len(), 2);
        assert!(is_irreducible(&p("a^2 + b^2 + c^2 - 1")).unwrap());
    }
}
