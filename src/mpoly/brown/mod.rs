//! Brown's dense modular gcd in $\mathbb{Z}\lbrack x_0, \dots, x_{k-1}\rbrack$, with cofactors
//! and early termination.
//!
//! For primitive $f, g$ with lex leading coefficients $\operatorname{lc} f$,
//! $\operatorname{lc} g$ (integers), $G = \gcd(f, g)$, $f = G \bar f$, $g = G \bar g$ and
//! $\gamma = \gcd(\operatorname{lc} f, \operatorname{lc} g)$: for a word prime
//! $p \nmid \operatorname{lc} f \operatorname{lc} g$, [`rec::gcd_rec`] computes the monic
//! gcd $G_p$ of $f \bmod p$, $g \bmod p$ and the cofactors $f / G_p$, $g / G_p$ on dense
//! arrays of residues ([`dense`]), the recursion of Brown (Geddes–Czapor–Labahn Alg. 7.2)
//! interpolating gcd and cofactors together and stopping as soon as one of them is stable
//! and divides (as FLINT's `nmod_mpolyn_gcd_brown_smprime` does). Unless $p$ is unlucky
//! (then the leading monomial of $G_p$ is larger), $\gamma G_p \equiv
//! (\gamma / \operatorname{lc} G) G$ and $f / G_p \equiv \operatorname{lc}(G) \bar f$.
//!
//! Over $\mathbb{Z}$ the three images are lifted by the Chinese remainder theorem (symmetric
//! residues), smallest first; a lifted candidate is accepted only when **exact division over
//! $\mathbb{Z}$ proves it**: $\operatorname{pp}(H)$ divides $f$ and $g$, or
//! $G' = f / \operatorname{pp}(\bar f')$ is exact and divides $g$ (same for $\bar g'$). Since
//! the candidate's leading monomial is that of $G_p$, a common divisor with it is the gcd.
//! One prime usually suffices when a cofactor has small coefficients.
//!
//! Dense arrays limit the shape: `None` (the caller falls back) when the product of the
//! degrees is too large or no prime gave a verified result.

mod dense;
mod rec;

use super::{MPoly, pack};
use dense::{Dense, Zp};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::Signed;

/// Word primes below $2^{31}$ (products fit a `u64`).
const PRIME_START: u64 = (1 << 31) - 1;
/// Primes tried before giving up (the caller falls back to another method).
const MAX_PRIMES: usize = 400;
/// Largest dense array (entries) per input.
const MAX_DENSE: usize = 1 << 21;

/// The `i`-th prime below [`PRIME_START`] in decreasing order (cached process-wide; primality
/// by the deterministic Miller–Rabin test of [`crate::qkernels::prime::is_prime_u64`]).
fn nth_prime(i: usize) -> u64 {
    static PRIMES: std::sync::OnceLock<Vec<u64>> = std::sync::OnceLock::new();
    let table = PRIMES.get_or_init(|| {
        let mut v = Vec::with_capacity(MAX_PRIMES);
        let mut c = PRIME_START + 1;
        while v.len() < MAX_PRIMES {
            c -= 1;
            if crate::qkernels::prime::is_prime_u64(c) {
                v.push(c);
            }
        }
        v
    });
    table[i]
}

/// Lifting state of one of the three images: support (dense indices), residues in
/// $[0, m)$, modulus.
struct Lift {
    support: Vec<usize>,
    res: Vec<BigInt>,
    m: BigInt,
}

impl Lift {
    fn new(img: &Dense, p: u64) -> Lift {
        let (support, res) = img
            .c
            .iter()
            .enumerate()
            .filter(|t| *t.1 != 0)
            .map(|(i, &c)| (i, BigInt::from(c)))
            .unzip();
        Lift {
            support,
            res,
            m: BigInt::from(p),
        }
    }
    /// Adds an image; returns whether the symmetric lift was already right mod `p`
    /// (stable), `None` when the support differs (restart).
    fn combine(&mut self, zp: Zp, img: &Dense) -> Option<bool> {
        let nz = img.c.iter().filter(|&&c| c != 0).count();
        if nz != self.support.len() || self.support.iter().any(|&i| img.c[i] == 0) {
            return None;
        }
        let half: BigInt = &self.m >> 1;
        let stable = self.support.iter().zip(&self.res).all(|(&i, c)| {
            let s = if c > &half { c - &self.m } else { c.clone() };
            zp.reduce(&s) == img.c[i]
        });
        if !stable {
            let minv = zp.inv(zp.reduce(&self.m));
            for (&i, c) in self.support.iter().zip(self.res.iter_mut()) {
                let t = zp.mul(zp.sub(img.c[i], zp.reduce(c)), minv);
                if t != 0 {
                    *c += &self.m * BigInt::from(t);
                }
            }
            self.m *= zp.p;
        }
        Some(stable)
    }
    /// Symmetric lift as a polynomial (dense shape `dims` over the variables `used`).
    fn poly(&self, n: usize, used: &[usize], dims: &[usize]) -> MPoly {
        let half: BigInt = &self.m >> 1;
        let mut e = vec![0u32; n];
        let t = self
            .support
            .iter()
            .zip(&self.res)
            .map(|(&i, c)| {
                let mut r = i;
                for j in (0..used.len()).rev() {
                    e[used[j]] = (r % dims[j]) as u32;
                    r /= dims[j];
                }
                let c = if c > &half { c - &self.m } else { c.clone() };
                (pack(n, &e), c)
            })
            .collect();
        MPoly::from_terms(n, t)
    }
}

/// Dense shape and flat index of every term of `f` over the variables `used`.
fn layout(f: &MPoly, used: &[usize]) -> (Vec<usize>, Vec<usize>) {
    let d = f.degrees();
    let dims: Vec<usize> = used.iter().map(|&i| d[i] as usize + 1).collect();
    let idx = f
        .terms()
        .iter()
        .map(|(m, _)| {
            used.iter()
                .zip(&dims)
                .fold(0, |s, (&i, &n)| s * n + f.exp(*m, i) as usize)
        })
        .collect();
    (dims, idx)
}

fn to_dense(zp: Zp, f: &MPoly, dims: &[usize], idx: &[usize]) -> Dense {
    let mut d = Dense::zeros(dims.to_vec());
    for ((_, c), &i) in f.terms().iter().zip(idx) {
        d.c[i] = zp.reduce(c);
    }
    d
}

/// $\gcd(f, g)$ of primitive, non-constant $f, g$ by Brown's modular algorithm, positive
/// leading coefficient, proved by exact division; `None` if the dense shape is too large or
/// no verified result came within `MAX_PRIMES` (400) primes (then the caller uses another
/// method).
///
/// # Examples
/// ```
/// use exactlti::mpoly::{brown::gcd_brown, parse_mpoly_in};
/// let v = ["a", "b", "c"];
/// let p = |s: &str| parse_mpoly_in(s, &v).unwrap().prim;
/// let h = p("a*b + c^2 + 1");
/// let g = gcd_brown(&h.pow(3).mul(&p("a - b + 2*c")), &h.pow(2).mul(&p("a + b + c"))).unwrap();
/// assert_eq!(g, h.pow(2));
/// ```
pub fn gcd_brown(f: &MPoly, g: &MPoly) -> Option<MPoly> {
    if f.is_zero() || g.is_zero() || f.nvars() != g.nvars() {
        return None;
    }
    let n = f.nvars();
    let (df, dg) = (f.degrees(), g.degrees());
    // dense variable order: the largest degree first (the main variable of the univariate
    // gcds), the smallest last (evaluated first, fewest points)
    let mut used: Vec<usize> = (0..n).filter(|&i| df[i] > 0 || dg[i] > 0).collect();
    if used.is_empty() {
        return None;
    }
    used.sort_by_key(|&i| std::cmp::Reverse(df[i].max(dg[i])));
    let (fdims, fidx) = layout(f, &used);
    let (gdims, gidx) = layout(g, &used);
    if fdims.iter().product::<usize>() > MAX_DENSE || gdims.iter().product::<usize>() > MAX_DENSE {
        return None;
    }
    let hdims: Vec<usize> = fdims.iter().zip(&gdims).map(|(a, b)| *a.min(b)).collect();
    // leading coefficients in the dense (lex) order
    let lead_coeff = |p: &MPoly, idx: &[usize]| {
        let k = (0..idx.len()).max_by_key(|&k| idx[k]).unwrap_or(0);
        p.terms()[k].1.clone()
    };
    let (lf, lg) = (lead_coeff(f, &fidx), lead_coeff(g, &gidx));
    let gamma = lf.abs().gcd(&lg.abs());
    // the trials: 0 = gcd, 1 = cofactor of f, 2 = cofactor of g
    let trial = |which: usize, cand: MPoly| -> Option<MPoly> {
        let cand = cand.primitive_part();
        match which {
            0 => (f.div_exact(&cand).is_some() && g.div_exact(&cand).is_some()).then_some(cand),
            1 => {
                let h = f.div_exact(&cand)?.primitive_part();
                g.div_exact(&h).map(|_| h)
            }
            _ => {
                let h = g.div_exact(&cand)?.primitive_part();
                f.div_exact(&h).map(|_| h)
            }
        }
    };
    let mut lifts: [Option<Lift>; 3] = [None, None, None];
    let mut lead: Option<usize> = None;
    let mut rng = 0x5EED_u64;
    for i in 0..MAX_PRIMES {
        let zp = Zp { p: nth_prime(i) };
        if zp.reduce(&lf) == 0 || zp.reduce(&lg) == 0 {
            continue;
        }
        let (fp, gp) = (
            to_dense(zp, f, &fdims, &fidx),
            to_dense(zp, g, &gdims, &gidx),
        );
        let Some((mut h, x, y)) = rec::gcd_rec(zp, &fp, &gp, &mut rng) else {
            continue;
        };
        let li = h.lead()?;
        if li == 0 {
            return Some(MPoly::one(n));
        }
        match lead {
            Some(l) if li > l => continue,
            Some(l) if li == l => {}
            _ => {
                lead = Some(li);
                lifts = [None, None, None];
            }
        }
        h.scale(zp, zp.reduce(&gamma));
        let imgs = [(&h, &hdims), (&x, &fdims), (&y, &gdims)];
        let mut order: Vec<(usize, usize)> = imgs
            .iter()
            .enumerate()
            .map(|(w, (d, _))| (d.c.iter().filter(|&&c| c != 0).count(), w))
            .collect();
        order.sort();
        for (_, w) in order {
            let (img, dims) = imgs[w];
            let try_now = match &mut lifts[w] {
                Some(l) => match l.combine(zp, img) {
                    Some(stable) => stable,
                    None => {
                        lifts[w] = Some(Lift::new(img, zp.p));
                        true
                    }
                },
                None => {
                    lifts[w] = Some(Lift::new(img, zp.p));
                    true
                }
            };
            if try_now
                && let Some(l) = &lifts[w]
                && let Some(r) = trial(w, l.poly(n, &used, dims))
            {
                return Some(r.abs_lc());
            }
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    fn p(s: &str) -> MPoly {
        crate::mpoly::parse_mpoly_in(s, &["x", "a", "b", "c"])
            .unwrap()
            .prim
    }
    #[test]
    fn textbook() {
        let f = p("a*b + c^2 + 1");
        let g = p("a - b + 2*c");
        let h = p("x^2 + a*x - 3");
        assert_eq!(
            gcd_brown(&f.pow(3).mul(&g.pow(2)), &f.pow(2).mul(&h)),
            Some(f.pow(2))
        );
        assert_eq!(gcd_brown(&f, &g), Some(MPoly::one(4)));
        // non-monic leading coefficients that vanish at small points
        let u = p("3*a*x^2 - b*c + 7");
        let w = p("2*b*x + a - 1");
        assert_eq!(
            gcd_brown(&u.mul(&w), &u.mul(&p("x*c + 5"))),
            Some(u.clone())
        );
        assert_eq!(gcd_brown(&u.mul(&w).mul(&w), &w.pow(3)), Some(w.pow(2)));
    }
}
