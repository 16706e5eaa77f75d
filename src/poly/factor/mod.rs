//! Factorization of integer polynomials over $\mathbb{Q}$.
//!
//! Computes $f = c \prod_i f_i^{e_i}$ with $c \in \mathbb{Z}$ (carrying the sign) and
//! $f_i \in \mathbb{Z}\lbrack x\rbrack$ primitive, of positive leading coefficient, pairwise distinct and
//! irreducible over $\mathbb{Q}$ (equivalently over $\mathbb{Z}$, by Gauss's lemma).
//!
//! | entry point | computes | algorithm |
//! |---|---|---|
//! | [`factor_zpoly`] | $c$, $[(f_i, e_i)]$ | cyclotomic shortcut for $x^n \pm 1$, else [`factor_zpoly_zassenhaus`] |
//! | [`factor_zpoly_zassenhaus`] | same | Yun, then Zassenhaus on each square-free part |
//! | [`squarefree_decomposition`] | $\operatorname{pp}(f) = \prod_i a_i^i$ | Yun |
//! | [`is_irreducible`] | irreducibility over $\mathbb{Q}$ | degree sets mod $p$, then Zassenhaus |
//!
//! Zassenhaus pipeline for a square-free primitive $f$ of degree $n$: try several primes
//! $p \nmid \operatorname{lc}(f)$ with $f \bmod p$ square-free, keep the one with fewest
//! modular factors (distinct-degree counts) and intersect the possible factor degrees;
//! factor modulo $p$ (Cantor–Zassenhaus, `cantor_zassenhaus`); lift to $p^k$ past twice
//! $2^{\lfloor n/2 \rfloor} \|f\|_2$ (multifactor quadratic
//! Hensel lifting, `hensel`); recombine subsets (`zassenhaus`). Recombination is
//! exponential in the number of modular factors in the worst case (no LLL); Swinnerton-Dyer
//! polynomials of degree 16 (8 modular factors) take milliseconds.

pub(crate) mod cantor_zassenhaus;
pub(crate) mod hensel;
pub(crate) mod sqfree;
pub(crate) mod zassenhaus;

use crate::error::{Error, Result};
use crate::poly::fp::{PolyP, Zp, primes_from};
use crate::poly::zpoly::ZPoly;
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

/// How many usable primes are compared when choosing the factorization prime.
const PRIMES_TRIED: usize = 7;

/// Complete factorization over $\mathbb{Q}$: `f == content * prod(factor_i ^ mult_i)`.
///
/// The factors are primitive, have positive leading coefficient, are irreducible over
/// $\mathbb{Q}$ and are sorted by degree, then by coefficients from the leading one down;
/// `content` carries the sign. A constant `f` gives an empty list.
///
/// # Errors
/// [`Error::Invalid`] for the zero polynomial.
///
/// # Examples
/// ```
/// use exactlti::poly::{factor::factor_zpoly, zpoly::ZPoly};
/// let f = ZPoly::from_i64s(&[-2, 0, 0, 0, 2]); // 2x^4 - 2
/// let (c, fs) = factor_zpoly(&f).unwrap();
/// assert_eq!(c, 2.into());
/// let shown: Vec<String> = fs.iter().map(|(g, e)| format!("({g})^{e}")).collect();
/// assert_eq!(shown, ["(x - 1)^1", "(x + 1)^1", "(x^2 + 1)^1"]);
/// ```
pub fn factor_zpoly(f: &ZPoly) -> Result<(BigInt, Vec<(ZPoly, usize)>)> {
    factor_impl(f, true)
}

/// As [`factor_zpoly`], always through the general square-free + Zassenhaus path (no
/// special case for binomials $x^n \pm 1$).
///
/// # Errors
/// [`Error::Invalid`] for the zero polynomial.
pub fn factor_zpoly_zassenhaus(f: &ZPoly) -> Result<(BigInt, Vec<(ZPoly, usize)>)> {
    factor_impl(f, false)
}

/// Yun's square-free decomposition of the primitive part:
/// $\operatorname{pp}(f) = \prod_i a_i^{i}$ with $a_i$ square-free, pairwise coprime,
/// primitive with positive leading coefficient; only $a_i \ne 1$ are listed, by increasing
/// $i$. Empty for zero and for constants.
pub fn squarefree_decomposition(f: &ZPoly) -> Vec<(ZPoly, usize)> {
    if f.deg0() == 0 {
        return Vec::new();
    }
    sqfree::yun(&f.primitive_part())
}

/// True when `f` is irreducible over $\mathbb{Q}$: of degree $\ge 1$ and not a product of
/// two polynomials of lower degree (the content is irrelevant: $2x + 4$ is irreducible).
pub fn is_irreducible(f: &ZPoly) -> bool {
    let n = f.deg0();
    if n == 0 {
        return false;
    }
    let g = f.primitive_part();
    if n == 1 {
        return true;
    }
    if g.coeffs()[0].is_zero() {
        return false;
    }
    if g.gcd(&g.derivative()).deg0() > 0 {
        return false;
    }
    factor_squarefree(&g).len() == 1
}

fn factor_impl(f: &ZPoly, cyclotomic: bool) -> Result<(BigInt, Vec<(ZPoly, usize)>)> {
    if f.is_zero() {
        return Err(Error::Invalid(
            "factor_zpoly: the zero polynomial has no factorization".into(),
        ));
    }
    let content = f.content();
    let mut g = f.primitive_part();
    let mut out = Vec::new();
    if cyclotomic && let Some(fs) = cyclotomic_binomial(&g) {
        return Ok((content, fs.into_iter().map(|h| (h, 1)).collect()));
    }
    let zeros = g.coeffs().iter().take_while(|c| c.is_zero()).count();
    if zeros > 0 {
        out.push((ZPoly::x(), zeros));
        g = ZPoly::new(g.coeffs()[zeros..].to_vec());
    }
    if g.deg0() > 0 {
        for (a, i) in sqfree::yun(&g) {
            for h in factor_squarefree(&a) {
                out.push((h, i));
            }
        }
    }
    out.sort();
    Ok((content, out))
}

/// The result of comparing primes: the chosen one, its distinct-degree factorization, and
/// the possible degrees of factors over $\mathbb{Z}$.
struct PrimeChoice {
    zp: Zp,
    ddf: Ddf,
    allowed: Vec<bool>,
}

/// A distinct-degree factorization: (product of the degree-$d$ factors, $d$).
type Ddf = Vec<(PolyP, usize)>;

/// Subset sums of a multiset of degrees, as a bitmap over `0..=n`.
fn subset_sums(ddf: &[(PolyP, usize)], n: usize) -> Vec<bool> {
    let mut can = vec![false; n + 1];
    can[0] = true;
    for (g, d) in ddf {
        for _ in 0..(g.len() - 1) / d {
            for s in (*d..=n).rev() {
                if can[s - d] {
                    can[s] = true;
                }
            }
        }
    }
    can
}

/// Tries primes $p \ge 3$, $p \nmid \operatorname{lc}(f)$, with $f \bmod p$ square-free;
/// keeps the one with the fewest modular factors. Returns `None` when the degree sets
/// already prove `f` irreducible.
fn choose_prime(f: &ZPoly) -> Option<PrimeChoice> {
    let n = f.deg0();
    let mut allowed = vec![true; n + 1];
    let mut best: Option<(usize, Zp, Ddf)> = None;
    let mut usable = 0;
    for p in primes_from(3) {
        if usable == PRIMES_TRIED {
            break;
        }
        let zp = Zp::new(p);
        let fp = zp.reduce(f.coeffs());
        if fp.len() != n + 1 || !zp.is_squarefree(&fp) {
            continue;
        }
        usable += 1;
        let ddf = cantor_zassenhaus::distinct_degree(&zp, &zp.monic(&fp));
        let count: usize = ddf.iter().map(|(g, d)| (g.len() - 1) / d).sum();
        for (a, b) in allowed.iter_mut().zip(subset_sums(&ddf, n)) {
            *a &= b;
        }
        if count == 1 || allowed[1..n].iter().all(|&a| !a) {
            return None;
        }
        if best.as_ref().is_none_or(|(c, _, _)| count < *c) {
            best = Some((count, zp, ddf));
        }
    }
    let (_, zp, ddf) =
        best.expect("a square-free polynomial is square-free modulo almost all primes");
    Some(PrimeChoice { zp, ddf, allowed })
}

/// The smallest $k$ with $p^k > 2 \cdot 2^{\lfloor n/2 \rfloor} \|f\|_2$.
///
/// For $h \mid f$ of degree $d$, Mahler's measure gives
/// $\|h\|_1 \le 2^d M(h) \le 2^d |\operatorname{lc} h / \operatorname{lc} f| \, \|f\|_2$, so
/// the candidate $(\operatorname{lc} f / \operatorname{lc} h)\, h$ has coefficients at most
/// $2^d \|f\|_2$ in absolute value: the leading coefficient does not enter the bound.
fn lifting_exponent(f: &ZPoly, p: u64) -> u32 {
    let n = f.deg0();
    // compare squares: p^(2k) > 4 * 4^(n/2) * |f|_2^2
    let rhs = (f.norm2_squared() << (2 * (n / 2))) * 4u32;
    let p2 = BigInt::from(p) * BigInt::from(p);
    let mut acc = p2.clone();
    let mut k = 1;
    while acc <= rhs {
        acc *= &p2;
        k += 1;
    }
    k
}

/// Irreducible factors of a square-free primitive `f` with positive leading coefficient
/// and $f(0) \ne 0$ (or of degree 1), sorted.
fn factor_squarefree(f: &ZPoly) -> Vec<ZPoly> {
    if f.deg0() <= 1 {
        return vec![f.clone()];
    }
    let Some(choice) = choose_prime(f) else {
        return vec![f.clone()];
    };
    let zp = choice.zp;
    let modular = cantor_zassenhaus::factor_from_ddf(&zp, choice.ddf, 0x5EED);
    if modular.len() == 1 {
        return vec![f.clone()];
    }
    let k = lifting_exponent(f, zp.p);
    let m = num_traits::pow(BigInt::from(zp.p), k as usize);
    let fm = hensel::reduce_coeffs(f.coeffs(), &m);
    let lifted = hensel::lift(&zp, &fm, &modular, k);
    let mut fs = zassenhaus::recombine(f, lifted, &m, &choice.allowed);
    fs.sort();
    fs
}

/// If `g` (primitive, positive leading coefficient) is $x^n - 1$ or $x^n + 1$, its
/// factorization into cyclotomic polynomials: $x^n - 1 = \prod_{d \mid n} \Phi_d$ and
/// $x^n + 1 = \prod_{d \mid 2n,\ d \nmid n} \Phi_d$, each $\Phi_d$ computed as
/// $(x^d - 1) / \prod_{e \mid d, e < d} \Phi_e$ (exact division).
fn cyclotomic_binomial(g: &ZPoly) -> Option<Vec<ZPoly>> {
    let c = g.coeffs();
    let n = c.len().checked_sub(1)?;
    if n == 0
        || !c[1..n].iter().all(|a| a.is_zero())
        || !c[n].is_one()
        || c[0].abs() != BigInt::one()
    {
        return None;
    }
    let plus = c[0].is_one();
    let big = if plus { 2 * n } else { n };
    let divisors: Vec<usize> = (1..=big).filter(|d| big % d == 0).collect();
    let mut phi: Vec<(usize, ZPoly)> = Vec::new();
    for &d in &divisors {
        let mut q = ZPoly::monomial(BigInt::one(), d) - ZPoly::one();
        for (e, pe) in &phi {
            if d % e == 0 {
                q = q.div_exact(pe)?;
            }
        }
        phi.push((d, q));
    }
    let mut fs: Vec<ZPoly> = phi
        .into_iter()
        .filter(|(d, _)| !plus || n % d != 0)
        .map(|(_, p)| p)
        .collect();
    fs.sort();
    Some(fs)
}
