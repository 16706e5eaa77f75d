//! [`AlgebraicNumber`]: a monic irreducible minimal polynomial over $\mathbb{Q}$ plus an
//! isolating region of one of its roots: the exact value (degree 1), an open interval with
//! rational endpoints (real, degree $\ge 2$), or a closed box with rational corners that
//! holds exactly one root, in its interior (non-real).
//!
//! Equality is exact: same minimal polynomial, and after refining one region until it lies
//! inside the other or misses it (a region holds exactly one root, so inclusion proves the
//! same root and disjointness a different one). Reals are ordered exactly the same way.
//! Real and imaginary parts come from composed polynomials: $\operatorname{Re} z$ is a root
//! of $\prod_{i,j} (x - (r_i + r_j)/2)$ and $\operatorname{Im} z$ of
//! $\prod_{i,j}(y - (r_i - r_j)/(2i))$ (built from Newton power sums, all rational), factored
//! over $\mathbb{Q}$; the right real root is the only candidate left in the shrinking
//! real (imaginary) range of the box.

use super::NumberField;
use super::digits::{round_sig, split_square};
use super::isolate_complex::{CBox, isolate_upper, refine_box};
use super::isolate_real::{RealRoot, bisect, isolate_real_roots, refine_real};
use crate::error::{Error, Result};
use crate::field::{Q, Rational, rational_to_f64};
use crate::poly::Poly;
use crate::poly::zslice as zp;
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

mod order;
pub(crate) use order::cmp_complex;

#[derive(Clone, Debug)]
pub(crate) enum Loc {
    Exact(Rational),
    Real(RealRoot),
    Complex { b: CBox, pure_imag: bool },
}

/// An algebraic number: minimal polynomial (monic, irreducible over $\mathbb{Q}$) and an
/// isolating interval or box of the root meant.
#[derive(Clone, Debug)]
pub struct AlgebraicNumber {
    minpoly: Poly<Q>,
    zp: Vec<BigInt>,
    loc: Loc,
}

fn pow2(k: i64) -> Rational {
    if k >= 0 {
        Rational::from_integer(BigInt::one() << k as usize)
    } else {
        Rational::new(BigInt::one(), BigInt::one() << (-k) as usize)
    }
}

/// `floor(log2 |q|)` roughly (exact enough for precision choices); very negative for 0.
fn log2_abs(q: &Rational) -> i64 {
    if q.is_zero() {
        return -(1 << 20);
    }
    q.numer().bits() as i64 - q.denom().bits() as i64
}

fn half() -> Rational {
    Rational::new(1.into(), 2.into())
}

impl AlgebraicNumber {
    /// The rational number `q`.
    pub fn from_rational(q: &Rational) -> Self {
        let minpoly = Poly::new(Q, vec![-q.clone(), Rational::one()]);
        AlgebraicNumber {
            zp: zp::from_poly_q(&minpoly),
            minpoly,
            loc: Loc::Exact(q.clone()),
        }
    }

    pub(crate) fn from_parts(minpoly: Poly<Q>, loc: Loc) -> Self {
        let minpoly = minpoly.monic();
        let loc = match loc {
            Loc::Real(r) if r.is_exact() => Loc::Exact(r.lo),
            l => l,
        };
        AlgebraicNumber {
            zp: zp::from_poly_q(&minpoly),
            minpoly,
            loc,
        }
    }

    /// All `deg p` roots of the irreducible `p`: the real ones ascending, then the non-real
    /// ones by (real part, imaginary part).
    ///
    /// # Errors
    /// `Invalid` for a constant `p`; `NotIrreducible` when `p` is reducible over Q;
    /// `Limit` when complex isolation needs more than the working-precision bound.
    pub fn roots_of_irreducible(p: &Poly<Q>) -> Result<Vec<AlgebraicNumber>> {
        if p.degree().unwrap_or(0) == 0 {
            return Err(Error::Invalid(
                "roots of a constant polynomial are undefined".into(),
            ));
        }
        if !super::is_irreducible_q(p) {
            return Err(Error::NotIrreducible(p.to_string()));
        }
        Self::roots_of_irreducible_unchecked(p)
    }

    /// As [`Self::roots_of_irreducible`] for a `p` known to be irreducible.
    pub(crate) fn roots_of_irreducible_unchecked(p: &Poly<Q>) -> Result<Vec<AlgebraicNumber>> {
        let m = p.monic();
        if m.deg() == 1 {
            return Ok(vec![AlgebraicNumber::from_rational(&-m.coeff(0))]);
        }
        let z = zp::from_poly_q(&m);
        let reals = isolate_real_roots(&z);
        if reals.iter().any(|r| r.is_exact()) {
            return Err(Error::NotIrreducible(m.to_string()));
        }
        let upper = isolate_upper(&z, reals.len())?;
        let mk = |loc| AlgebraicNumber {
            minpoly: m.clone(),
            zp: z.clone(),
            loc,
        };
        let mut out: Vec<AlgebraicNumber> = reals.into_iter().map(|r| mk(Loc::Real(r))).collect();
        let mut cx = vec![];
        for (b, pure_imag) in upper {
            cx.push(mk(Loc::Complex {
                b: b.conj(),
                pure_imag,
            }));
            cx.push(mk(Loc::Complex { b, pure_imag }));
        }
        cx.sort_by(cmp_complex);
        out.extend(cx);
        Ok(out)
    }

    /// The monic irreducible minimal polynomial.
    pub fn minpoly(&self) -> &Poly<Q> {
        &self.minpoly
    }
    pub fn degree(&self) -> usize {
        self.minpoly.deg()
    }
    pub fn is_real(&self) -> bool {
        !matches!(self.loc, Loc::Complex { .. })
    }
    /// `Some(q)` for a rational number.
    pub fn to_rational(&self) -> Option<Rational> {
        match &self.loc {
            Loc::Exact(q) => Some(q.clone()),
            _ => None,
        }
    }
    /// Proven to have real part zero (a non-real root of an even or odd minimal polynomial
    /// whose box is symmetric about the imaginary axis).
    pub fn is_pure_imaginary(&self) -> bool {
        matches!(
            self.loc,
            Loc::Complex {
                pure_imag: true,
                ..
            }
        )
    }
    /// The isolating interval `(lo, hi)` of a real number (`lo == hi` for a rational).
    pub fn interval(&self) -> Option<(Rational, Rational)> {
        match &self.loc {
            Loc::Exact(q) => Some((q.clone(), q.clone())),
            Loc::Real(r) => Some((r.lo.clone(), r.hi.clone())),
            Loc::Complex { .. } => None,
        }
    }
    /// The isolating box `((re_lo, re_hi), (im_lo, im_hi))`; degenerate in the imaginary
    /// direction for reals.
    pub fn bounding_box(&self) -> ((Rational, Rational), (Rational, Rational)) {
        match &self.loc {
            Loc::Complex { b, .. } => (b.re.clone(), b.im.clone()),
            _ => {
                let (lo, hi) = self.interval().unwrap_or_default();
                ((lo, hi), (Rational::zero(), Rational::zero()))
            }
        }
    }

    /// A copy whose isolating region has width at most `width` (> 0).
    ///
    /// # Errors
    /// `Limit` when complex refinement exceeds its precision bound.
    pub fn refined(&self, width: &Rational) -> Result<Self> {
        let loc = match &self.loc {
            Loc::Exact(q) => Loc::Exact(q.clone()),
            Loc::Real(r) => Loc::Real(refine_real(&self.zp, r, width)),
            Loc::Complex { b, pure_imag } => Loc::Complex {
                b: refine_box(&self.zp, b, *pure_imag, width)?,
                pure_imag: *pure_imag,
            },
        };
        Ok(AlgebraicNumber {
            minpoly: self.minpoly.clone(),
            zp: self.zp.clone(),
            loc,
        })
    }

    fn width(&self) -> Rational {
        match &self.loc {
            Loc::Exact(_) => Rational::zero(),
            Loc::Real(r) => &r.hi - &r.lo,
            Loc::Complex { b, .. } => b.width(),
        }
    }

    /// Halves (at least) the isolating region.
    fn step(&self) -> Self {
        match &self.loc {
            Loc::Real(r) => AlgebraicNumber {
                minpoly: self.minpoly.clone(),
                zp: self.zp.clone(),
                loc: Loc::Real(bisect(&self.zp, r)),
            },
            Loc::Exact(_) => self.clone(),
            Loc::Complex { .. } => {
                let w = self.width() * half();
                self.refined(&w).unwrap_or_else(|_| self.clone())
            }
        }
    }

    /// `(re, im)` in f64, from a region refined to relative width about $2^{-60}$.
    pub fn approx(&self) -> (f64, f64) {
        match &self.loc {
            Loc::Exact(q) => (rational_to_f64(q), 0.0),
            Loc::Real(_) => {
                let mut a = self.clone();
                loop {
                    let (lo, hi) = a.interval().unwrap_or_default();
                    let m = log2_abs(&lo).min(log2_abs(&hi));
                    let zero_in = lo.is_negative() != hi.is_negative() || lo.is_zero();
                    if !zero_in && a.width() <= pow2(m - 62) {
                        return (rational_to_f64(&((lo + hi) * half())), 0.0);
                    }
                    let target = if zero_in {
                        a.width() * half()
                    } else {
                        pow2(m - 62)
                    };
                    a = a.refined(&target).unwrap_or_else(|_| a.step());
                }
            }
            Loc::Complex { .. } => {
                let mut a = self.clone();
                for _ in 0..64 {
                    let ((r0, r1), (i0, i1)) = a.bounding_box();
                    let cr = (&r0 + &r1) * half();
                    let ci = (&i0 + &i1) * half();
                    let m = log2_abs(&cr).max(log2_abs(&ci));
                    let w = a.width();
                    let big = pow2(m - 2) > w;
                    if big && w <= pow2(m - 62) {
                        break;
                    }
                    let target = if big { pow2(m - 62) } else { &w * pow2(-8) };
                    match a.refined(&target) {
                        Ok(b) => a = b,
                        Err(_) => break,
                    }
                }
                let ((r0, r1), (i0, i1)) = a.bounding_box();
                let re = if a.is_pure_imaginary() {
                    0.0
                } else {
                    rational_to_f64(&((r0 + r1) * half()))
                };
                (re, rational_to_f64(&((i0 + i1) * half())))
            }
        }
    }

    /// `(re, im)` rounded to `n` significant digits, each correct (the region is refined
    /// until its whole range rounds to the same string). Exact parts (rational numbers, real
    /// parts of quadratic and of purely imaginary numbers) are rounded exactly.
    pub fn digits(&self, n: usize) -> (String, String) {
        let n = n.max(1);
        if let Loc::Exact(q) = &self.loc {
            return (round_sig(q, n), "0".into());
        }
        if self.degree() == 2
            && let Some((a, b, d)) = self.quadratic_parts()
            && d.is_negative()
        {
            let re = round_sig(&a, n);
            if d == BigInt::from(-1) {
                return (re, round_sig(&b, n));
            }
            // im = b sqrt(-d): refine only the imaginary range
            let (_, im) = self.digits_generic(n);
            return (re, im);
        }
        self.digits_generic(n)
    }

    fn digits_generic(&self, n: usize) -> (String, String) {
        let mut a = self.clone();
        let pure = a.is_pure_imaginary();
        let real = a.is_real();
        for _ in 0..4 * n + 400 {
            let ((r0, r1), (i0, i1)) = a.bounding_box();
            let (re0, re1) = (round_sig(&r0, n), round_sig(&r1, n));
            let (im0, im1) = (round_sig(&i0, n), round_sig(&i1, n));
            let re_ok = pure || re0 == re1;
            let im_ok = real || im0 == im1;
            if re_ok && im_ok {
                return (
                    if pure { "0".into() } else { re0 },
                    if real { "0".into() } else { im0 },
                );
            }
            let w = a.width() * pow2(-4);
            a = a.refined(&w).unwrap_or_else(|_| a.step());
        }
        // a rational part sitting on a rounding boundary: round the centre
        let ((r0, r1), (i0, i1)) = a.bounding_box();
        let re = if pure {
            "0".into()
        } else {
            round_sig(&((r0 + r1) * half()), n)
        };
        let im = if real {
            "0".into()
        } else {
            round_sig(&((i0 + i1) * half()), n)
        };
        (re, im)
    }

    /// Complex conjugate (exact: same minimal polynomial, mirrored box).
    pub fn conj(&self) -> Self {
        match &self.loc {
            Loc::Complex { b, pure_imag } => AlgebraicNumber {
                minpoly: self.minpoly.clone(),
                zp: self.zp.clone(),
                loc: Loc::Complex {
                    b: b.conj(),
                    pure_imag: *pure_imag,
                },
            },
            _ => self.clone(),
        }
    }

    /// `-self` (minimal polynomial $(-1)^n m(-x)$, mirrored region).
    pub fn neg(&self) -> Self {
        let cs: Vec<Rational> = self
            .minpoly
            .coeffs()
            .iter()
            .enumerate()
            .map(|(i, c)| if i % 2 == 1 { -c } else { c.clone() })
            .collect();
        let mp = Poly::new(Q, cs).monic();
        let loc = match &self.loc {
            Loc::Exact(q) => Loc::Exact(-q),
            Loc::Real(r) => Loc::Real(RealRoot {
                lo: -&r.hi,
                hi: -&r.lo,
            }),
            Loc::Complex { b, pure_imag } => Loc::Complex {
                b: CBox {
                    re: (-&b.re.1, -&b.re.0),
                    im: (-&b.im.1, -&b.im.0),
                },
                pure_imag: *pure_imag,
            },
        };
        AlgebraicNumber {
            zp: zp::from_poly_q(&mp),
            minpoly: mp,
            loc,
        }
    }

    /// Real part, exactly.
    ///
    /// # Errors
    /// From the factorization over Q of the composed polynomial, or `Limit`.
    pub fn try_re(&self) -> Result<Self> {
        match &self.loc {
            Loc::Complex {
                pure_imag: true, ..
            } => Ok(Self::from_rational(&Rational::zero())),
            Loc::Complex { .. } => {
                if let Some((a, _, _)) = self.quadratic_parts() {
                    return Ok(Self::from_rational(&a));
                }
                let q = super::composed_half_sum(&self.minpoly);
                identify_real(&q, self, |b| b.re.clone())
            }
            _ => Ok(self.clone()),
        }
    }

    /// Imaginary part, exactly.
    ///
    /// # Errors
    /// As [`Self::try_re`].
    pub fn try_im(&self) -> Result<Self> {
        match &self.loc {
            Loc::Complex { .. } => {
                let q = super::composed_half_diff_imag(&self.minpoly);
                identify_real(&q, self, |b| b.im.clone())
            }
            _ => Ok(Self::from_rational(&Rational::zero())),
        }
    }

    /// Real part (exact); the same as [`Self::try_re`].
    ///
    /// # Errors
    /// As [`Self::try_re`].
    pub fn re(&self) -> Result<Self> {
        self.try_re()
    }
    /// Imaginary part (exact); the same as [`Self::try_im`].
    ///
    /// # Errors
    /// As [`Self::try_im`].
    pub fn im(&self) -> Result<Self> {
        self.try_im()
    }

    /// For degree <= 2: `(a, b, d)` with value `a + b*sqrt(d)`, `d` square-free (up to the
    /// square factors of primes >= 2^16), `d = -1` meaning `i`; rationals give `(q, 0, 1)`.
    pub fn quadratic_parts(&self) -> Option<(Rational, Rational, BigInt)> {
        match self.degree() {
            1 => Some((-self.minpoly.coeff(0), Rational::zero(), BigInt::one())),
            2 => {
                let bq = self.minpoly.coeff(1);
                let cq = self.minpoly.coeff(0);
                let a = -&bq * half();
                let disc = &a * &a - &cq; // value = a +- sqrt(disc)
                let (s, d) = split_square(&(disc.numer() * disc.denom()));
                let mag = Rational::new(s, disc.denom().clone());
                let positive = match &self.loc {
                    Loc::Complex { b, .. } => b.im.0.is_positive(),
                    Loc::Real(r) => {
                        let mut r = r.clone();
                        while r.lo <= a && a <= r.hi {
                            r = bisect(&self.zp, &r);
                        }
                        r.lo > a
                    }
                    Loc::Exact(_) => return None,
                };
                Some((a, if positive { mag } else { -mag }, d))
            }
            _ => None,
        }
    }

    /// $\mathbb{Q}\[t\]/(m)$ with $t$ marked as this root.
    pub fn to_number_field(&self) -> NumberField {
        NumberField::new_unchecked(&self.minpoly, self.approx())
    }
}

/// Finds the real root of `q` equal to the real (or imaginary) part of `z`, where `range`
/// extracts from `z`'s box an interval containing that part.
fn identify_real(
    q: &Poly<Q>,
    z: &AlgebraicNumber,
    range: impl Fn(&CBox) -> (Rational, Rational),
) -> Result<AlgebraicNumber> {
    let (_, facs) = super::factor_q(q)?;
    let mut cands: Vec<AlgebraicNumber> = vec![];
    for (f, _) in facs {
        let zf = zp::from_poly_q(&f);
        if f.deg() == 1 {
            cands.push(AlgebraicNumber::from_rational(&-f.coeff(0)));
            continue;
        }
        for r in isolate_real_roots(&zf) {
            cands.push(AlgebraicNumber::from_parts(f.clone(), Loc::Real(r)));
        }
    }
    let mut z = z.clone();
    for _ in 0..10_000 {
        let Loc::Complex { b, .. } = &z.loc else {
            break;
        };
        let (lo, hi) = range(b);
        let w = &hi - &lo;
        let mut keep = vec![];
        for c in cands {
            let c = if c.width() > &w * half() {
                c.refined(&(&w * half()))?
            } else {
                c
            };
            let (cl, ch) = c.interval().unwrap_or_default();
            if !(ch < lo || cl > hi) {
                keep.push(c);
            }
        }
        cands = keep;
        if cands.len() == 1 {
            return Ok(cands.pop().unwrap_or_else(|| z.clone()));
        }
        if cands.is_empty() {
            break;
        }
        z = z.refined(&(z.width() * pow2(-4)))?;
    }
    Err(Error::Verification(
        "real or imaginary part not found among the composed roots".into(),
    ))
}
