//! Algebraic numbers: certified root isolation, exact real/imaginary parts, factorization
//! over $\mathbb{Q}$ (as monic polynomials) and over number fields, and the library side of
//! `exactlti poly factor|roots`.
//!
//! An algebraic number is its minimal polynomial $m \in \mathbb{Q}\[x\]$ (monic, irreducible)
//! together with a region holding exactly one root of $m$: an open interval with rational
//! endpoints for a real root (Descartes / VCA isolation, [`isolate_real`]) or a closed box
//! with rational corners for a non-real one (Newton inclusion discs certified in exact
//! arithmetic, [`isolate_complex`]). All certification is integer/rational arithmetic;
//! `f64` appears only in [`AlgebraicNumber::approx`] and as starting values of iterations
//! that are certified afterwards.
//!
//! | entry point | computes |
//! |---|---|
//! | [`factor_q`] | $p = c \prod_i f_i^{e_i}$, $f_i$ monic irreducible over $\mathbb{Q}$ |
//! | [`is_irreducible_q`] | irreducibility over $\mathbb{Q}$ |
//! | [`roots`] | every root of $p$ with its multiplicity |
//! | [`AlgebraicNumber::roots_of_irreducible`] | the $\deg p$ roots of an irreducible $p$ |
//! | [`factor_over_number_field`] | factorization over $\mathbb{Q}\[t\]/(m)$ (Trager) |
//! | [`factor_over_quadratic`] | factorization over $\mathbb{Q}(\sqrt d)$, $\mathbb{Q}(i)$ (through Trager) |
//! | [`roots_of_quadratic_factor`] | the roots of a factor over $\mathbb{Q}(\sqrt d)$, told exactly from its conjugate's |
//! | [`composed_half_sum`], [`composed_half_diff_imag`] | $\prod (x - \frac{r_i + r_j}{2})$, $\prod (x - \frac{r_i - r_j}{2i})$ |
//! | [`crate::report::sections::factor_report`], [`crate::report::sections::roots_report`] | the CLI's `poly factor` / `poly roots` reports |

pub(crate) mod digits;
pub(crate) mod ext;
mod ext_q;
pub mod isolate_complex;
pub(crate) mod isolate_real;
pub mod nf_factor;
pub(crate) mod number;
pub(crate) mod number_field;
pub(crate) mod quadratic_factor;
pub(crate) mod quadratic_roots;
pub(crate) mod zp; // re-export shim, see its docs

pub use ext::{Ext, ExtCtx, ExtElem};
pub use nf_factor::factor_over_number_field;
pub use number::AlgebraicNumber;
pub use number_field::{NfElem, NumberField, NumberFieldCtx};
pub use quadratic_factor::{factor_over_quadratic, norm_over_q, quadratic_as_number_field};
pub use quadratic_roots::{rational_minpoly, roots_of_quadratic_factor};

use crate::error::{Error, Result};
use crate::field::{Q, Rational};
use crate::poly::factor::factor_zpoly;
use crate::poly::zpoly::ZPoly;
use crate::poly::{Poly, monic_from_power_sums, newton_power_sums};
use num_bigint::BigInt;
use num_traits::{One, Zero};

/// Leading coefficient and monic irreducible factors with multiplicities.
pub type FactorizationQ = (Rational, Vec<(Poly<Q>, usize)>);

/// Monic irreducible factors over $\mathbb{Q}$ with multiplicities, sorted by degree, then
/// by coefficients from the leading one down: `p == lc * prod(f_i^e_i)`.
///
/// # Errors
/// `Invalid` for the zero polynomial.
///
/// # Examples
/// ```
/// use exactlti::algebraic::factor_q;
/// use exactlti::poly::parse_poly_q;
/// let (lc, fs) = factor_q(&parse_poly_q("2*x^3 - 2*x").unwrap()).unwrap();
/// assert_eq!(lc.to_string(), "2");
/// let shown: Vec<String> = fs.iter().map(|(f, e)| format!("{f}:{e}")).collect();
/// assert_eq!(shown, ["x - 1:1", "x:1", "x + 1:1"]);
/// ```
pub fn factor_q(p: &Poly<Q>) -> Result<FactorizationQ> {
    if p.is_zero() {
        return Err(Error::Invalid(
            "factorization of the zero polynomial".into(),
        ));
    }
    let lc = p.lc();
    if p.deg() == 0 {
        return Ok((lc, vec![]));
    }
    let z = ZPoly::from_poly_q(p);
    let (_, facs) = factor_zpoly(&z)?;
    let mut out: Vec<(Poly<Q>, usize)> =
        facs.into_iter().map(|(f, e)| (f.to_monic_q(), e)).collect();
    out.sort_by(|a, b| {
        a.0.deg().cmp(&b.0.deg()).then_with(|| {
            let ca: Vec<&Rational> = a.0.coeffs().iter().rev().collect();
            let cb: Vec<&Rational> = b.0.coeffs().iter().rev().collect();
            ca.cmp(&cb)
        })
    });
    Ok((lc, out))
}

/// True when `p` has degree >= 1 and is irreducible over $\mathbb{Q}$.
pub fn is_irreducible_q(p: &Poly<Q>) -> bool {
    p.deg() >= 1 && crate::poly::factor::is_irreducible(&ZPoly::from_poly_q(p))
}

fn binomials(n: usize) -> Vec<Vec<Rational>> {
    let mut rows = vec![vec![Rational::one()]];
    for k in 1..=n {
        let prev = &rows[k - 1];
        let mut r = vec![Rational::one(); k + 1];
        for j in 1..k {
            r[j] = &prev[j - 1] + &prev[j];
        }
        rows.push(r);
    }
    rows
}

/// $\prod_{i,j} (x - (r_i + r_j)/2)$ over the roots $r_i$ of `p` (degree $n^2$).
pub fn composed_half_sum(p: &Poly<Q>) -> Poly<Q> {
    pair_power_sum_poly(p, false, |k| {
        Rational::new(BigInt::one(), BigInt::one() << k)
    })
}

/// $\prod_{i,j} (y - (r_i - r_j)/(2i))$ over the roots of `p`: real coefficients, the
/// imaginary parts of the roots are among its real roots.
pub fn composed_half_diff_imag(p: &Poly<Q>) -> Poly<Q> {
    // (2i)^-k = (-1)^(k/2) / 2^k for even k; odd power sums of differences vanish
    pair_power_sum_poly(p, true, |k| {
        if k % 2 == 1 {
            Rational::zero()
        } else {
            let sign = if (k / 2) % 2 == 1 {
                -BigInt::one()
            } else {
                BigInt::one()
            };
            Rational::new(sign, BigInt::one() << k)
        }
    })
}

/// The monic polynomial of degree $n^2$ whose power sums are
/// $t_k = w_k \sum_{i,j} (r_i \pm r_j)^k = w_k \sum_m \binom{k}{m} (\pm 1)^{k-m} s_m s_{k-m}$
/// ($s_m$ the power sums of the roots of `p`, `-` when `diff`, $w_k$ = `scale(k)`): with
/// $w_k = w^k$ its roots are $w (r_i \pm r_j)$.
fn pair_power_sum_poly(p: &Poly<Q>, diff: bool, scale: impl Fn(usize) -> Rational) -> Poly<Q> {
    let p = p.monic();
    let n = p.deg();
    let big = n * n;
    let s = newton_power_sums(&p, big);
    let c = binomials(big);
    let mut t = vec![Rational::from_integer(big.into())];
    for k in 1..=big {
        let w = scale(k);
        if w.is_zero() {
            t.push(w);
            continue;
        }
        let mut v = Rational::zero();
        for m in 0..=k {
            let term = &c[k][m] * &s[m] * &s[k - m];
            if diff && (k - m) % 2 == 1 {
                v -= term
            } else {
                v += term
            }
        }
        t.push(v * w);
    }
    monic_from_power_sums(&t, big)
}

/// All roots of `p` with multiplicities: real ones ascending, then non-real ones by (real
/// part, imaginary part); the multiplicities add up to `deg p`.
///
/// # Errors
/// `Invalid` for the zero polynomial; `Limit` from complex isolation.
pub fn roots(p: &Poly<Q>) -> Result<Vec<(AlgebraicNumber, usize)>> {
    let (_, facs) = factor_q(p)?;
    let mut out = vec![];
    for (f, e) in facs {
        for r in AlgebraicNumber::roots_of_irreducible_unchecked(&f)? {
            out.push((r, e));
        }
    }
    out.sort_by(|a, b| number::cmp_complex(&a.0, &b.0));
    Ok(out)
}
