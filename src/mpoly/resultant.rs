//! Resultants and discriminants with respect to one variable.
//!
//! $\operatorname{Res}_{x}(f, g) = \operatorname{lc}(f)^{\deg g} \prod_{f(\alpha) = 0} g(\alpha)$,
//! computed by the subresultant algorithm over the coefficient ring
//! $\mathbb{Z}\lbrack \text{other variables}\rbrack$ (Cohen, *A Course in Computational
//! Algebraic Number Theory*, Alg. 3.3.7, without the content shortcut); all divisions are
//! exact. $\operatorname{Disc}_x(f) = (-1)^{n(n-1)/2} \operatorname{Res}_x(f, f') /
//! \operatorname{lc}(f)$ with $n = \deg_x f$. Both are polynomials free of $x$.
//!
//! With other variables present and $\deg f + \deg g \ge$ [`SYLVESTER_MIN`], the
//! subresultant remainders swell (the discriminant of the characteristic polynomial of a
//! dense 8 x 8 matrix in three parameters: > 40 s); there
//! $\operatorname{Res}_x(f, g) = \det \operatorname{Syl}(f, g)$ (the Sylvester matrix, free
//! of $x$) is interpolated modulo word primes ([`super::interp`], degrees probed and the
//! result checked at random points: [`super::probe`]).

use super::MPoly;
use super::gcd::{prem, subresultant_step, trim};
use super::interp::{Bounds, interpolate_zp};
use crate::qkernels::modular::det::det_mod_p;
use crate::qkernels::prime::Prime;

/// Sylvester matrices of at least this size (with other variables present) are
/// interpolated.
pub const SYLVESTER_MIN: usize = 6;

/// $\det \operatorname{Syl}(a, b)$ for coefficient lists `a`, `b` in $x_i$ (low degree first,
/// leading coefficients nonzero, degrees at least 1), by interpolation in the variables other
/// than $x_i$; `None` when the grid is too large (the caller runs the subresultants).
fn sylvester_det(a: &[MPoly], b: &[MPoly], i: usize) -> Option<MPoly> {
    let nv = a[0].nvars();
    let (da, db) = (a.len() - 1, b.len() - 1);
    let n = da + db;
    // the entries without x_i (of degree 0 in it): one variable fewer on the grid
    let down: Vec<usize> = (0..nv)
        .map(|j| match j.cmp(&i) {
            std::cmp::Ordering::Less => j,
            std::cmp::Ordering::Equal => 0,
            std::cmp::Ordering::Greater => j - 1,
        })
        .collect();
    let up: Vec<usize> = (0..nv - 1)
        .map(|j| if j >= i { j + 1 } else { j })
        .collect();
    let mut syl = vec![MPoly::zero(nv - 1); n * n];
    for (r, row_len, cs) in [(0, db, a), (db, da, b)] {
        for t in 0..row_len {
            for (k, c) in cs.iter().rev().enumerate() {
                syl[(r + t) * n + t + k] = c.remap(nv - 1, &down);
            }
        }
    }
    let map = |pr: &Prime, x: &mut [u64]| Some(vec![det_mod_p(pr, n, x)]);
    let bounds = Bounds::of_square(nv - 1, n, &syl).probe(&syl, &map);
    let det = interpolate_zp(nv - 1, &syl, &bounds, 1, false, map)
        .ok()??
        .pop()?;
    Some(det.remap(nv, &up))
}

/// $\operatorname{Res}_{x_i}(f, g)$ (zero when either is zero; $f^{0}$ conventions: the
/// resultant with a nonzero polynomial constant in $x_i$ is that constant to the other
/// degree).
///
/// # Examples
/// ```
/// use exactlti::mpoly::{parse_mpoly_in, resultant::resultant};
/// let v = ["x", "y"];
/// let f = parse_mpoly_in("x^2 + y^2 - 1", &v).unwrap().prim;
/// let g = parse_mpoly_in("x - y", &v).unwrap().prim;
/// let vs: Vec<String> = v.iter().map(|s| s.to_string()).collect();
/// assert_eq!(resultant(&f, &g, 0).display(&vs).to_string(), "2*y^2 - 1");
/// ```
pub fn resultant(f: &MPoly, g: &MPoly, i: usize) -> MPoly {
    let (da, db) = (f.deg(i) as usize, g.deg(i) as usize);
    if f.nvars() >= 2
        && da >= 1
        && db >= 1
        && da + db >= SYLVESTER_MIN
        && let Some(r) = sylvester_det(&f.to_univariate(i), &g.to_univariate(i), i)
    {
        return r;
    }
    resultant_prs(f, g, i)
}

/// [`resultant`] by the subresultant algorithm alone (the oracle of the interpolated path).
pub fn resultant_prs(f: &MPoly, g: &MPoly, i: usize) -> MPoly {
    let n = f.nvars();
    if f.is_zero() || g.is_zero() {
        return MPoly::zero(n);
    }
    let (mut a, mut b) = (f.to_univariate(i), g.to_univariate(i));
    trim(&mut a);
    trim(&mut b);
    let (da, db) = (a.len() - 1, b.len() - 1);
    if db == 0 {
        return b[0].pow(da as u32);
    }
    if da == 0 {
        return a[0].pow(db as u32);
    }
    let mut s = false; // sign flip
    if da < db {
        std::mem::swap(&mut a, &mut b);
        if da % 2 == 1 && db % 2 == 1 {
            s = !s;
        }
    }
    let mut g_ = MPoly::one(n);
    let mut h = MPoly::one(n);
    loop {
        let (dega, degb) = (a.len() - 1, b.len() - 1);
        let delta = (dega - degb) as u32;
        if dega % 2 == 1 && degb % 2 == 1 {
            s = !s;
        }
        let r = prem(&a, &b);
        if r.is_empty() {
            return MPoly::zero(n);
        }
        subresultant_step([&mut a, &mut b], &r, [&mut g_, &mut h], delta);
        if b.len() == 1 {
            let dega = (a.len() - 1) as u32;
            let num = b[0].pow(dega);
            let res = if dega == 0 {
                num
            } else {
                num.div_exact(&h.pow(dega - 1))
                    .expect("exact subresultant step")
            };
            return if s { res.neg() } else { res };
        }
    }
}

/// $\operatorname{Disc}_{x_i}(f)$; zero for $\deg_{x_i} f < 1$... by convention 1 for degree
/// one and 0 for a polynomial free of $x_i$.
pub fn discriminant(f: &MPoly, i: usize) -> MPoly {
    let n = f.nvars();
    let d = f.deg(i);
    if f.is_zero() || d == 0 {
        return MPoly::zero(n);
    }
    if d == 1 {
        return MPoly::one(n);
    }
    let r = resultant(f, &f.derivative(i), i);
    let q = r.div_exact(&f.lc_in(i)).expect("lc divides the resultant");
    if (d as u64 * (d as u64 - 1) / 2) % 2 == 1 {
        q.neg()
    } else {
        q
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    fn p(s: &str) -> MPoly {
        let f = crate::mpoly::parse_mpoly_in(s, &["x", "a", "b", "c"]).unwrap();
        f.prim.scale(&f.content.to_integer())
    }
    #[test]
    fn examples() {
        assert_eq!(discriminant(&p("a*x^2 + b*x + c"), 0), p("b^2 - 4*a*c"));
        assert_eq!(discriminant(&p("x^3 + a*x + b"), 0), p("-4*a^3 - 27*b^2"));
        // Res(x - a, g) = g(a)
        let g = p("x^3 - b*x + 2");
        assert_eq!(resultant(&p("x - a"), &g, 0), p("a^3 - b*a + 2"));
        // Res(g, f) = (-1)^(deg f deg g) Res(f, g)
        assert_eq!(resultant(&g, &p("x - a"), 0), p("a^3 - b*a + 2").neg());
        // common root => zero
        assert!(resultant(&p("(x - a)*(x + b)"), &p("(x - a)*(x + 1)"), 0).is_zero());
    }
}
