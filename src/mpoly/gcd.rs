//! Greatest common divisors in $\mathbb{Z}\lbrack x_0, \dots, x_{k-1}\rbrack$.
//!
//! $\gcd(f, g)$ is the gcd of the integer contents times the gcd of the primitive parts, with a
//! positive leading coefficient. Staged as SymPy's `dmp_inner_gcd` (and, in spirit, FLINT's
//! `fmpz_mpoly_gcd`, which tries cheap algorithms before Brown/Zippel):
//!
//! 1. trivial cases (a zero, a constant, a monomial-free variable split);
//! 2. [`super::brown::gcd_brown`]: Brown's dense modular gcd (word primes, dense arrays of
//!    residues, evaluation and Newton interpolation per variable of the gcd *and* both
//!    cofactors, stopping as soon as one is stable and divides; the smallest of the three
//!    lifted over $\mathbb{Z}$ and proved by exact division). Measured fastest on all the
//!    bench's gcds (`benches/mpoly.rs` prints each stage alone): a small cofactor needs two or
//!    three points per variable and one prime;
//! 3. [`gcd_heuristic`]: evaluate the last variable at a large integer $\xi$, recurse, and
//!    read the gcd back from its $\xi$-adic expansion (Char, Geddes and Gonnet's GCDHEU as
//!    in SymPy's `dmp_zz_heu_gcd`); accepted only when it divides both inputs exactly, so it
//!    is never wrong, only sometimes unsuccessful. Its base case, one variable left, is the
//!    univariate integer gcd ([`crate::poly::zpoly::ZPoly::gcd`]). Used when Brown gives up
//!    (dense shape too large);
//! 4. [`gcd_subresultant`]: content and primitive part in a main variable, subresultant PRS
//!    with polynomial coefficients (always succeeds).

use super::MPoly;
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};

/// Evaluation points tried by the heuristic gcd per level.
const HEU_TRIES: usize = 6;
/// The heuristic gcd gives up when evaluated coefficients would exceed this many bits.
const HEU_MAX_BITS: u64 = 1 << 16;

/// $\gcd(f, g)$ with positive leading coefficient; $\gcd(0, 0) = 0$.
///
/// # Examples
/// ```
/// use exactlti::mpoly::{gcd, parse_mpoly_in};
/// let v = ["a", "b"];
/// let f = parse_mpoly_in("(a + b)^2*(a - b)", &v).unwrap().prim;
/// let g = parse_mpoly_in("(a + b)*(a + 2*b)", &v).unwrap().prim;
/// let vs: Vec<String> = v.iter().map(|s| s.to_string()).collect();
/// assert_eq!(gcd(&f, &g).display(&vs).to_string(), "a + b");
/// ```
pub fn gcd(f: &MPoly, g: &MPoly) -> MPoly {
    if f.is_zero() {
        return g.abs_lc();
    }
    if g.is_zero() {
        return f.abs_lc();
    }
    let (cf, pf) = f.content_primitive();
    let (cg, pg) = g.content_primitive();
    let c = cf.gcd(&cg);
    let h = primitive_gcd(&pf, &pg);
    if c.is_one() { h } else { h.scale(&c) }
}

/// gcd of primitive polynomials with positive leading coefficients.
fn primitive_gcd(f: &MPoly, g: &MPoly) -> MPoly {
    let n = f.nvars();
    if f.is_constant() || g.is_constant() {
        return MPoly::one(n);
    }
    if f == g {
        return f.clone();
    }
    // a variable in only one of them: the gcd is free of it; take coefficients' content
    let (df, dg) = (f.degrees(), g.degrees());
    for i in 0..n {
        if (df[i] > 0) != (dg[i] > 0) {
            let (with, without) = if df[i] > 0 { (f, g) } else { (g, f) };
            let mut acc = without.clone();
            for c in with.to_univariate(i).iter().rev() {
                if !c.is_zero() {
                    acc = gcd(&acc, c);
                    if acc.is_one() {
                        break;
                    }
                }
            }
            return acc;
        }
    }
    if let Some(h) = super::brown::gcd_brown(f, g) {
        return h;
    }
    if let Some(h) = gcd_heuristic(f, g) {
        return h;
    }
    gcd_subresultant(f, g)
}

/// Heuristic gcd of two polynomials (Char–Geddes–Gonnet). `None` when it does not succeed;
/// a returned polynomial is the gcd (it is checked to divide both and is primitive times the
/// integer gcd).
pub fn gcd_heuristic(f: &MPoly, g: &MPoly) -> Option<MPoly> {
    heu(f, g).map(|h| h.abs_lc())
}

fn heu(f: &MPoly, g: &MPoly) -> Option<MPoly> {
    let n = f.nvars();
    let c = f.content().abs().gcd(&g.content().abs());
    let (f, g) = if c.is_one() {
        (f.clone(), g.clone())
    } else {
        (f.div_integer(&c), g.div_integer(&c))
    };
    let (df, dg) = (f.degrees(), g.degrees());
    let Some(v) = (0..n).rev().find(|&i| df[i] > 0 || dg[i] > 0) else {
        // both constants
        let a = f.to_constant().unwrap_or_default();
        let b = g.to_constant().unwrap_or_default();
        return Some(MPoly::constant(n, a.gcd(&b) * c));
    };
    // one variable left in both: the univariate integer gcd (modular coprimality test, then
    // the subresultant PRS) avoids one more level of evaluation
    if (0..n).all(|i| i == v || (df[i] == 0 && dg[i] == 0))
        && let (Some(fz), Some(gz)) = (f.to_zpoly(v), g.to_zpoly(v))
    {
        return Some(MPoly::from_zpoly(n, v, &fz.gcd(&gz)).scale(&c));
    }
    let (fnorm, gnorm) = (f.max_norm(), g.max_norm());
    let b: BigInt = BigInt::from(2) * fnorm.clone().min(gnorm.clone()) + 29;
    let lcf = f.lc().abs();
    let lcg = g.lc().abs();
    let b99: BigInt = BigInt::from(99) * b.sqrt();
    let lower: BigInt = BigInt::from(2) * (&fnorm / &lcf).min(&gnorm / &lcg) + 2;
    let mut x: BigInt = b.min(b99).max(lower);
    let maxdeg = df.iter().chain(dg.iter()).copied().max().unwrap_or(0) as u64 + 1;
    for _ in 0..HEU_TRIES {
        if x.bits().saturating_mul(maxdeg) + fnorm.bits().max(gnorm.bits()) > HEU_MAX_BITS {
            return None;
        }
        let ff = f.eval_var(v, &x);
        let gg = g.eval_var(v, &x);
        if !ff.is_zero() && !gg.is_zero() {
            let he = heu(&ff, &gg)?;
            let h = interpolate(&he, &x, v).primitive_part();
            if !h.is_zero()
                && let Some(_) = f.div_exact(&h)
                && let Some(_) = g.div_exact(&h)
            {
                return Some(h.scale(&c));
            }
            // cofactor route: cff = ff / he interpolated, h = f / cff
            if let Some(cffe) = ff.div_exact(&he) {
                let cff = interpolate(&cffe, &x, v);
                if !cff.is_zero()
                    && let Some(h) = f.div_exact(&cff)
                    // h = f / cff as it stands, NOT its primitive part: dividing out an
                    // integer content here can turn a proper divisor into one that
                    // divides both (gcd(961ab, a^2b^2) at xi = 31 gave a), and the
                    // correctness argument (Char, Geddes, Gonnet) covers only h itself
                    && g.div_exact(&h).is_some()
                {
                    return Some(h.abs_lc().scale(&c));
                }
            }
        }
        // next point: x * 73794 * x^(1/4) / 27011 (SymPy's sequence)
        x = &x * BigInt::from(73794) * x.sqrt().sqrt() / BigInt::from(27011);
    }
    None
}

/// Reads a polynomial in $x_v$ back from its value at $x_v = \xi$: symmetric remainders of
/// the coefficients modulo $\xi$ are the coefficients of $x_v^0, x_v^1, \dots$.
fn interpolate(h: &MPoly, xi: &BigInt, v: usize) -> MPoly {
    let n = h.nvars();
    let half = xi / 2;
    let mut h = h.clone();
    let mut out: Vec<MPoly> = Vec::new();
    while !h.is_zero() {
        let g = MPoly::from_terms(
            n,
            h.terms()
                .iter()
                .map(|(m, c)| {
                    let mut r = c.mod_floor(xi);
                    if r > half {
                        r -= xi;
                    }
                    (*m, r)
                })
                .collect(),
        );
        h = h.sub(&g).div_integer(xi);
        out.push(g);
        if out.len() > 1 << 16 {
            break;
        }
    }
    MPoly::from_univariate(n, v, &out)
}

/// Content of $f$ as a polynomial in $x_i$: the gcd of its coefficients (positive lc).
pub fn content_in(f: &MPoly, i: usize) -> MPoly {
    let cs = f.to_univariate(i);
    let mut acc = MPoly::zero(f.nvars());
    // smallest coefficients first: the gcd shrinks fast
    let mut order: Vec<&MPoly> = cs.iter().filter(|c| !c.is_zero()).collect();
    order.sort_by_key(|c| c.len());
    for c in order {
        acc = gcd(&acc, c);
        if acc.is_one() {
            break;
        }
    }
    acc
}

/// Primitive part of $f$ in $x_i$ (divided by [`content_in`], positive leading coefficient).
pub fn primitive_in(f: &MPoly, i: usize) -> MPoly {
    let c = content_in(f, i);
    if c.is_zero() {
        return f.clone();
    }
    f.div_exact(&c).expect("content divides").abs_lc()
}

/// Pseudo-remainder of `a` by `b` as polynomials in one variable with polynomial
/// coefficients (low degree first): $\operatorname{lc}(b)^{\deg a - \deg b + 1} a = q b + r$.
pub(crate) fn prem(a: &[MPoly], b: &[MPoly]) -> Vec<MPoly> {
    let db = b.len() - 1;
    let lcb = &b[db];
    let mut r: Vec<MPoly> = a.to_vec();
    trim(&mut r);
    if r.len() < b.len() {
        return r;
    }
    let mut e = (r.len() - b.len() + 1) as u32;
    while r.len() >= b.len() {
        let d = r.len() - 1;
        let t = r[d].clone();
        for rk in r.iter_mut().take(d) {
            *rk = rk.mul(lcb);
        }
        for (j, bj) in b.iter().enumerate().take(db) {
            let k = j + d - db;
            r[k] = r[k].sub(&t.mul(bj));
        }
        r.pop();
        trim(&mut r);
        e -= 1;
    }
    if e > 0 {
        let f = lcb.pow(e);
        for rk in r.iter_mut() {
            *rk = rk.mul(&f);
        }
    }
    r
}

pub(crate) fn trim(r: &mut Vec<MPoly>) {
    while r.last().is_some_and(|c| c.is_zero()) {
        r.pop();
    }
}

/// gcd by content/primitive part in a main variable and the subresultant PRS (Collins,
/// Brown–Traub) over the coefficient ring. Always succeeds; used as the exact fallback and as
/// the oracle in tests.
pub fn gcd_subresultant(f: &MPoly, g: &MPoly) -> MPoly {
    if f.is_zero() {
        return g.abs_lc();
    }
    if g.is_zero() {
        return f.abs_lc();
    }
    let n = f.nvars();
    let (cf, f) = f.content_primitive();
    let (cg, g) = g.content_primitive();
    let c = cf.abs().gcd(&cg.abs());
    let (df, dg) = (f.degrees(), g.degrees());
    let Some(x) = (0..n).find(|&i| df[i] > 0 || dg[i] > 0) else {
        return MPoly::constant(n, c);
    };
    let conf = content_in(&f, x);
    let cong = content_in(&g, x);
    let cont = gcd_subresultant(&conf, &cong);
    let pf = f.div_exact(&conf).expect("content divides");
    let pg = g.div_exact(&cong).expect("content divides");
    let h = if pf.deg(x) == 0 || pg.deg(x) == 0 {
        MPoly::one(n)
    } else {
        let (a, b) = if pf.deg(x) >= pg.deg(x) {
            (pf, pg)
        } else {
            (pg, pf)
        };
        let r = subresultant_last(a.to_univariate(x), b.to_univariate(x));
        if r.len() <= 1 {
            MPoly::one(n)
        } else {
            primitive_in(&MPoly::from_univariate(n, x, &r), x)
        }
    };
    h.mul(&cont).scale(&c).abs_lc()
}

/// Last nonzero remainder of the subresultant PRS of `a`, `b` ($\deg a \ge \deg b \ge 1$).
fn subresultant_last(mut a: Vec<MPoly>, mut b: Vec<MPoly>) -> Vec<MPoly> {
    let n = a[0].nvars();
    let mut g = MPoly::one(n);
    let mut h = MPoly::one(n);
    loop {
        let delta = (a.len() - b.len()) as u32;
        let r = prem(&a, &b);
        if r.is_empty() {
            return b;
        }
        if r.len() == 1 {
            return r;
        }
        subresultant_step([&mut a, &mut b], &r, [&mut g, &mut h], delta);
    }
}

/// One step of the subresultant PRS (Cohen, Alg. 3.3.1), shared by [`subresultant_last`] and
/// [`super::resultant::resultant`]: with `r = prem(a, b)` nonzero and `delta = deg a - deg
/// b`, `a <- b`, `b <- r / (g h^delta)`, `g <- lc(a)`, `h <- g^delta / h^(delta - 1)`; every
/// division is exact.
pub(crate) fn subresultant_step(
    [a, b]: [&mut Vec<MPoly>; 2],
    r: &[MPoly],
    [g, h]: [&mut MPoly; 2],
    delta: u32,
) {
    let den = g.mul(&h.pow(delta));
    let next = r
        .iter()
        .map(|c| c.div_exact(&den).expect("exact subresultant step"))
        .collect();
    *a = std::mem::replace(b, next);
    *g = a.last().unwrap().clone();
    if delta != 0 {
        *h = g
            .pow(delta)
            .div_exact(&h.pow(delta - 1))
            .expect("exact subresultant step");
    }
}

/// $\operatorname{lcm}(f, g)$ with positive leading coefficient.
pub fn lcm(f: &MPoly, g: &MPoly) -> MPoly {
    if f.is_zero() || g.is_zero() {
        return MPoly::zero(f.nvars());
    }
    let h = gcd(f, g);
    f.div_exact(&h).expect("gcd divides").mul(g).abs_lc()
}

/// Integer gcd helper for callers.
pub fn integer_gcd(a: &BigInt, b: &BigInt) -> BigInt {
    if a.is_zero() && b.is_zero() {
        BigInt::zero()
    } else {
        a.gcd(b)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mpoly::parse::abc as p;
    #[test]
    fn examples() {
        let f = p("a*b + c^2 + 1");
        let g = p("a - b + 2*c");
        let h = p("a^2 + 3*b - 7");
        let fg = f.pow(3).mul(&g.pow(2));
        let fh = f.pow(2).mul(&h);
        assert_eq!(gcd(&fg, &fh), f.pow(2));
        assert_eq!(gcd_subresultant(&fg, &fh), f.pow(2));
        assert_eq!(
            gcd(&g.scale(&6.into()), &g.scale(&(-4).into())),
            g.scale(&2.into())
        );
        assert_eq!(gcd(&f, &g), MPoly::one(3));
        assert_eq!(gcd(&p("a*b"), &p("b*c")), p("b"));
        assert_eq!(content_in(&p("a*b + a*c"), 1), p("a"));
        assert_eq!(lcm(&p("a*b"), &p("b*c")), p("a*b*c"));
    }
}
