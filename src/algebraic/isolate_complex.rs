//! Certified complex root isolation by Newton inclusion discs.
//!
//! **Inclusion lemma.** For a polynomial $p$ of degree $n$ and any $z$ with $p'(z) \ne 0$,
//! the closed disc $|w - z| \le n\,|p(z)/p'(z)|$ holds a root of $p$: from
//! $p'(z)/p(z) = \sum_k 1/(z - r_k)$, if every $|z - r_k| > \rho$ then $|p'/p| < n/\rho$.
//!
//! Approximations $z_1, \dots, z_n$ come from the Aberth–Ehrlich iteration in a small
//! software floating point (`Fx`, a `BigInt` mantissa and a binary exponent, precision
//! doubled on failure). Each $z_j$ is then rounded to a dyadic Gaussian rational and its
//! inclusion radius is computed **exactly** (Gaussian-integer Horner, integer square root
//! rounded up). The axis-parallel bounding boxes are enlarged strictly beyond the discs. If
//! the $n$ closed boxes are pairwise disjoint, each holds at least one root and $p$ has $n$
//! roots, so **each box holds exactly one root**, in its interior. A box whose imaginary
//! range excludes 0 holds a non-real root; a box meeting the real axis whose mirror image
//! meets no other box holds a real root (its conjugate must lie in the same box). For
//! $p(-x) = \pm p(x)$ the same argument with the reflection $z \mapsto -\bar z$ proves a
//! root purely imaginary; such boxes are made symmetric about the imaginary axis.
//!
//! | entry point | computes |
//! |---|---|
//! | [`isolate_upper`] | isolating boxes of the roots with positive imaginary part |
//! | [`refine_box`] | a sub-box of an isolating box of at most a given width |

use crate::error::{Error, Result};
use crate::field::Rational;
use crate::poly::zslice as zp;
use num_bigint::BigInt;
use num_traits::{One, Zero};

// ----------------------------------------------------------------------------------------
// Fx: a tiny binary floating point (value m * 2^e), used only to produce approximations.

#[derive(Clone, Debug)]
pub(crate) struct Fx {
    m: BigInt,
    e: i64,
}

impl Fx {
    fn zero() -> Self {
        Fx {
            m: BigInt::zero(),
            e: 0,
        }
    }
    fn from_int(m: &BigInt, prec: u64) -> Self {
        Fx { m: m.clone(), e: 0 }.norm(prec)
    }
    fn from_f64(x: f64) -> Self {
        if x == 0.0 || !x.is_finite() {
            return Fx::zero();
        }
        let bits = x.to_bits();
        let sign = if bits >> 63 == 1 { -1 } else { 1 };
        let exp = ((bits >> 52) & 0x7ff) as i64;
        let frac = bits & ((1u64 << 52) - 1);
        let (m, e) = if exp == 0 {
            (frac, -1074)
        } else {
            (frac | (1u64 << 52), exp - 1075)
        };
        Fx {
            m: BigInt::from(m) * sign,
            e,
        }
    }
    fn norm(mut self, prec: u64) -> Self {
        let b = self.m.bits();
        if b > prec {
            let sh = b - prec;
            self.m >>= sh as usize;
            self.e += sh as i64;
        }
        if self.m.is_zero() {
            self.e = 0;
        }
        self
    }
    fn is_zero(&self) -> bool {
        self.m.is_zero()
    }
    /// `floor(log2 |x|)`-ish magnitude; very negative for zero.
    fn mag(&self) -> i64 {
        if self.m.is_zero() {
            i64::MIN / 4
        } else {
            self.e + self.m.bits() as i64
        }
    }
    fn neg(&self) -> Self {
        Fx {
            m: -&self.m,
            e: self.e,
        }
    }
    fn add(&self, o: &Fx, prec: u64) -> Fx {
        if self.is_zero() {
            return o.clone();
        }
        if o.is_zero() {
            return self.clone();
        }
        // drop a term far below the precision of the other
        if self.mag() > o.mag() + prec as i64 + 4 {
            return self.clone();
        }
        if o.mag() > self.mag() + prec as i64 + 4 {
            return o.clone();
        }
        let e = self.e.min(o.e);
        let a = &self.m << (self.e - e) as usize;
        let b = &o.m << (o.e - e) as usize;
        Fx { m: a + b, e }.norm(prec)
    }
    fn sub(&self, o: &Fx, prec: u64) -> Fx {
        self.add(&o.neg(), prec)
    }
    fn mul(&self, o: &Fx, prec: u64) -> Fx {
        Fx {
            m: &self.m * &o.m,
            e: self.e + o.e,
        }
        .norm(prec)
    }
    fn div(&self, o: &Fx, prec: u64) -> Option<Fx> {
        if o.is_zero() {
            return None;
        }
        let sh = prec + o.m.bits() + 2;
        let sh2 = sh.saturating_sub(self.m.bits());
        let m = (&self.m << sh2 as usize) / &o.m;
        Some(
            Fx {
                m,
                e: self.e - o.e - sh2 as i64,
            }
            .norm(prec),
        )
    }
    fn from_rational(q: &Rational, prec: u64) -> Fx {
        let n = Fx::from_int(q.numer(), prec + 8);
        let d = Fx::from_int(q.denom(), prec + 8);
        n.div(&d, prec).unwrap_or_else(Fx::zero)
    }
}

#[derive(Clone, Debug)]
pub(crate) struct Cx {
    re: Fx,
    im: Fx,
}

impl Cx {
    fn add(&self, o: &Cx, p: u64) -> Cx {
        Cx {
            re: self.re.add(&o.re, p),
            im: self.im.add(&o.im, p),
        }
    }
    fn sub(&self, o: &Cx, p: u64) -> Cx {
        Cx {
            re: self.re.sub(&o.re, p),
            im: self.im.sub(&o.im, p),
        }
    }
    fn mul(&self, o: &Cx, p: u64) -> Cx {
        Cx {
            re: self.re.mul(&o.re, p).sub(&self.im.mul(&o.im, p), p),
            im: self.re.mul(&o.im, p).add(&self.im.mul(&o.re, p), p),
        }
    }
    fn div(&self, o: &Cx, p: u64) -> Option<Cx> {
        let d = o.re.mul(&o.re, p).add(&o.im.mul(&o.im, p), p);
        let re = self.re.mul(&o.re, p).add(&self.im.mul(&o.im, p), p);
        let im = self.im.mul(&o.re, p).sub(&self.re.mul(&o.im, p), p);
        Some(Cx {
            re: re.div(&d, p)?,
            im: im.div(&d, p)?,
        })
    }
    fn mag(&self) -> i64 {
        self.re.mag().max(self.im.mag())
    }
    fn is_zero(&self) -> bool {
        self.re.is_zero() && self.im.is_zero()
    }
}

/// `(p(z), p'(z))` by Horner in `Fx`.
fn horner(a: &[Fx], z: &Cx, prec: u64) -> (Cx, Cx) {
    let n = a.len() - 1;
    let mut b = Cx {
        re: a[n].clone(),
        im: Fx::zero(),
    };
    let mut d = Cx {
        re: Fx::zero(),
        im: Fx::zero(),
    };
    for k in (0..n).rev() {
        d = d.mul(z, prec).add(&b, prec);
        b = b.mul(z, prec);
        b.re = b.re.add(&a[k], prec);
    }
    (b, d)
}

/// Aberth–Ehrlich iterations (Gauss–Seidel order) until every correction is below
/// `2^-(prec - 8)` relative, or `max_iter`.
fn aberth(a: &[Fx], z: &mut [Cx], prec: u64, max_iter: usize) {
    let n = z.len();
    let tol = prec as i64 - 8;
    for _ in 0..max_iter {
        let mut done = true;
        for i in 0..n {
            let (pv, dv) = horner(a, &z[i], prec);
            if pv.is_zero() {
                continue;
            }
            let Some(w) = pv.div(&dv, prec) else {
                // p'(z) = 0: nudge
                let eps = Fx {
                    m: BigInt::one(),
                    e: z[i].mag().max(-(prec as i64)) - 20,
                };
                z[i].re = z[i].re.add(&eps, prec);
                done = false;
                continue;
            };
            let mut s = Cx {
                re: Fx::zero(),
                im: Fx::zero(),
            };
            for j in 0..n {
                if j != i {
                    let d = z[i].sub(&z[j], prec);
                    if let Some(inv) = (Cx {
                        re: Fx::from_int(&BigInt::one(), prec),
                        im: Fx::zero(),
                    })
                    .div(&d, prec)
                    {
                        s = s.add(&inv, prec);
                    }
                }
            }
            let one = Cx {
                re: Fx::from_int(&BigInt::one(), prec),
                im: Fx::zero(),
            };
            let den = one.sub(&w.mul(&s, prec), prec);
            let delta = w.div(&den, prec).unwrap_or(w);
            if !delta.is_zero() && delta.mag() > z[i].mag().max(-(prec as i64) / 2) - tol {
                done = false;
            }
            z[i] = z[i].sub(&delta, prec);
        }
        if done {
            break;
        }
    }
}

// ----------------------------------------------------------------------------------------
// exact certification

/// A closed axis-parallel box with rational corners.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CBox {
    pub re: (Rational, Rational),
    pub im: (Rational, Rational),
}

impl CBox {
    pub fn intersects(&self, o: &CBox) -> bool {
        self.re.0 <= o.re.1 && o.re.0 <= self.re.1 && self.im.0 <= o.im.1 && o.im.0 <= self.im.1
    }
    pub fn contains_box(&self, o: &CBox) -> bool {
        self.re.0 <= o.re.0 && o.re.1 <= self.re.1 && self.im.0 <= o.im.0 && o.im.1 <= self.im.1
    }
    /// Complex conjugate image.
    pub fn conj(&self) -> CBox {
        CBox {
            re: self.re.clone(),
            im: (-&self.im.1, -&self.im.0),
        }
    }
    /// Image under $z \mapsto -\bar z$.
    pub fn mirror_imag_axis(&self) -> CBox {
        CBox {
            re: (-&self.re.1, -&self.re.0),
            im: self.im.clone(),
        }
    }
    pub fn width(&self) -> Rational {
        let a = &self.re.1 - &self.re.0;
        let b = &self.im.1 - &self.im.0;
        if a > b { a } else { b }
    }
    pub fn center(&self) -> (Rational, Rational) {
        let two = Rational::from_integer(2.into());
        (
            (&self.re.0 + &self.re.1) / &two,
            (&self.im.0 + &self.im.1) / two,
        )
    }
    /// Symmetric about the imaginary axis: `[-R, R]` with `R = max(|lo|, |hi|)`.
    pub fn symmetrized(&self) -> CBox {
        let r = if -&self.re.0 > self.re.1 {
            -&self.re.0
        } else {
            self.re.1.clone()
        };
        CBox {
            re: (-&r, r),
            im: self.im.clone(),
        }
    }
    pub fn is_symmetric(&self) -> bool {
        self.re.0 == -&self.re.1
    }
}

/// Gaussian-integer Horner: `sum c_k w^k d^(n-k)` for `w = a + b i`.
fn horner_gauss(c: &[BigInt], a: &BigInt, b: &BigInt, d: &BigInt) -> (BigInt, BigInt) {
    let (mut xr, mut xi) = (BigInt::zero(), BigInt::zero());
    let mut dp = BigInt::one();
    for ck in c.iter().rev() {
        let nr = &xr * a - &xi * b + ck * &dp;
        let ni = &xr * b + &xi * a;
        xr = nr;
        xi = ni;
        dp *= d;
    }
    (xr, xi)
}

/// The strictly enlarged bounding box of the Newton inclusion disc at `z = (a + b i) / 2^s`;
/// `None` when `p'(z) = 0`.
fn newton_box(p: &[BigInt], dp: &[BigInt], a: &BigInt, b: &BigInt, s: u64) -> Option<CBox> {
    let n = p.len() - 1;
    let d = BigInt::one() << s as usize;
    let (pr, pi) = horner_gauss(p, a, b, &d);
    let (qr, qi) = horner_gauss(dp, a, b, &d);
    let q2 = &qr * &qr + &qi * &qi;
    if q2.is_zero() {
        return None;
    }
    // rho^2 = n^2 |P|^2 / (|P'|^2 4^s) = N / M
    let nn = BigInt::from(n * n) * (&pr * &pr + &pi * &pi);
    let mm = q2 << (2 * s) as usize;
    let t = ((mm.bits() as i64 - nn.bits() as i64) / 2 + 8).max(0) as usize;
    // R = (isqrt(ceil(N 4^t / M)) + 1) / 2^t > rho
    let num = &nn << (2 * t);
    let (qq, rr) = (&num / &mm, &num % &mm);
    let c = if rr.is_zero() { qq } else { qq + 1 };
    let r = Rational::new(c.sqrt() + 1, BigInt::one() << t);
    let den = Rational::from_integer(d);
    let cr = Rational::from_integer(a.clone()) / &den;
    let ci = Rational::from_integer(b.clone()) / &den;
    Some(CBox {
        re: (&cr - &r, &cr + &r),
        im: (&ci - &r, &ci + &r),
    })
}

/// Dyadic exact form `(a, b, s)` with `z = (a + b i) / 2^s`.
fn dyadic(z: &Cx) -> (BigInt, BigInt, u64) {
    let e = z.re.e.min(z.im.e);
    let e = if z.re.is_zero() {
        z.im.e
    } else if z.im.is_zero() {
        z.re.e
    } else {
        e
    };
    if e >= 0 {
        (
            &z.re.m << (z.re.e.max(0)) as usize,
            &z.im.m << (z.im.e.max(0)) as usize,
            0,
        )
    } else {
        let s = (-e) as u64;
        let a = &z.re.m << (z.re.e + s as i64).max(0) as usize;
        let b = &z.im.m << (z.im.e + s as i64).max(0) as usize;
        (a, b, s)
    }
}

/// Result of a certification attempt.
struct Cert {
    boxes: Vec<CBox>,
    /// 1 upper half plane, -1 lower, 0 real.
    kind: Vec<i8>,
    pure_imag: Vec<bool>,
}

fn certify(p: &[BigInt], z: &[Cx]) -> Option<Cert> {
    let dp = zp::derivative(p);
    let mut boxes = Vec::with_capacity(z.len());
    for zi in z {
        let (a, b, s) = dyadic(zi);
        boxes.push(newton_box(p, &dp, &a, &b, s)?);
    }
    let n = boxes.len();
    for i in 0..n {
        for j in i + 1..n {
            if boxes[i].intersects(&boxes[j]) {
                return None;
            }
        }
    }
    let zero = Rational::zero();
    let mut kind = vec![0i8; n];
    for i in 0..n {
        if boxes[i].im.0 > zero {
            kind[i] = 1;
        } else if boxes[i].im.1 < zero {
            kind[i] = -1;
        } else {
            let c = boxes[i].conj();
            if (0..n).any(|j| j != i && boxes[j].intersects(&c)) {
                return None;
            }
        }
    }
    let par = zp::parity(p);
    let mut pure_imag = vec![false; n];
    if par != 0 {
        for i in 0..n {
            if kind[i] != 0 && boxes[i].re.0 <= zero && boxes[i].re.1 >= zero {
                let m = boxes[i].mirror_imag_axis();
                if (0..n).any(|j| j != i && boxes[j].intersects(&m)) {
                    return None;
                }
                pure_imag[i] = true;
                boxes[i] = boxes[i].symmetrized();
            }
        }
    }
    Some(Cert {
        boxes,
        kind,
        pure_imag,
    })
}

const MAX_PREC: u64 = 1 << 15;

/// Initial approximations on a circle of radius about $|a_0/a_n|^{1/n}$.
fn initial(p: &[BigInt], prec: u64) -> Vec<Cx> {
    let n = p.len() - 1;
    let lead = p[n].bits() as f64;
    let low = p
        .iter()
        .find(|c| !c.is_zero())
        .map_or(0.0, |c| c.bits() as f64);
    let r = 2f64.powf(((low - lead) / n as f64).clamp(-900.0, 900.0));
    (0..n)
        .map(|k| {
            let th = 2.0 * std::f64::consts::PI * k as f64 / n as f64 + 0.4;
            Cx {
                re: Fx::from_f64(r * th.cos()).norm(prec),
                im: Fx::from_f64(r * th.sin()).norm(prec),
            }
        })
        .collect()
}

/// All `n` approximations, certified: `(boxes, kind, pure_imag)`, at increasing precision.
fn certified_all(p: &[BigInt], start_prec: u64) -> Result<Cert> {
    let n = p.len() - 1;
    let mut prec = start_prec.max(64);
    let mut z = initial(p, prec);
    let mut iters = 100 + 10 * n;
    loop {
        let a: Vec<Fx> = p.iter().map(|c| Fx::from_int(c, prec)).collect();
        aberth(&a, &mut z, prec, iters);
        if let Some(c) = certify(p, &z) {
            return Ok(c);
        }
        prec *= 2;
        iters = 40 + 2 * n;
        if prec > MAX_PREC {
            return Err(Error::Limit(format!(
                "complex root isolation did not certify below {MAX_PREC} bits"
            )));
        }
        for zi in z.iter_mut() {
            zi.re = zi.re.clone().norm(prec);
            zi.im = zi.im.clone().norm(prec);
        }
    }
}

/// Isolating boxes of the roots of the square-free integer polynomial `p` (degree >= 1)
/// with positive imaginary part, each with a flag "purely imaginary (proved)"; the roots
/// with negative imaginary part are their conjugates. `n_real` is the number of real roots
/// (from the real isolation), checked against the boxes.
///
/// # Errors
/// `Limit` when certification fails below 32768 bits of working precision; `Verification`
/// when the box count disagrees with `n_real` (an internal error).
pub fn isolate_upper(p: &[BigInt], n_real: usize) -> Result<Vec<(CBox, bool)>> {
    let p = zp::trim(p);
    let n = p.len().saturating_sub(1);
    if n <= 1 || n_real == n {
        return Ok(vec![]);
    }
    let c = certified_all(p, 64)?;
    let reals = c.kind.iter().filter(|&&k| k == 0).count();
    let upper = c.kind.iter().filter(|&&k| k == 1).count();
    if reals != n_real || 2 * upper != n - n_real {
        return Err(Error::Verification(format!(
            "complex isolation found {reals} real and {upper} upper roots, expected {n_real} real"
        )));
    }
    Ok((0..n)
        .filter(|&i| c.kind[i] == 1)
        .map(|i| (c.boxes[i].clone(), c.pure_imag[i]))
        .collect())
}

/// A sub-box of the isolating box `b` (of the square-free `p`) of width at most `width`,
/// again isolating (symmetric about the imaginary axis when `pure_imag`).
///
/// Newton steps from the centre, certified by the inclusion lemma (the inclusion box must
/// lie inside `b`, which holds only one root); on failure the whole polynomial is
/// re-isolated at higher precision and the new box inside `b` is taken.
///
/// # Errors
/// `Limit` when the working precision bound is reached.
pub fn refine_box(p: &[BigInt], b: &CBox, pure_imag: bool, width: &Rational) -> Result<CBox> {
    let mut b = b.clone();
    let dp = zp::derivative(p);
    let mut fails = 0;
    while &b.width() > width {
        // bits needed: log2(|center| / width) + margin
        let wbits = (width.denom().bits() as i64 - width.numer().bits() as i64).max(0) as u64;
        let (cr, ci) = b.center();
        let mag = (cr.numer().bits() as i64 - cr.denom().bits() as i64)
            .max(ci.numer().bits() as i64 - ci.denom().bits() as i64)
            .max(0) as u64;
        let prec = (wbits + mag + 64) << fails.min(6);
        if prec > MAX_PREC * 4 {
            return Err(Error::Limit("root refinement precision".into()));
        }
        let a: Vec<Fx> = p.iter().map(|c| Fx::from_int(c, prec)).collect();
        let mut z = Cx {
            re: Fx::from_rational(&cr, prec),
            im: Fx::from_rational(&ci, prec),
        };
        for _ in 0..(2 * (64 - (prec.leading_zeros() as usize)) + 8) {
            let (pv, dv) = horner(&a, &z, prec);
            match pv.div(&dv, prec) {
                Some(w) => {
                    let stop =
                        w.is_zero() || w.mag() < z.mag().max(-(prec as i64)) - prec as i64 + 4;
                    z = z.sub(&w, prec);
                    if stop {
                        break;
                    }
                }
                None => break,
            }
        }
        let (za, zb, s) = dyadic(&z);
        let nb = newton_box(p, &dp, &za, &zb, s);
        match nb {
            Some(nb) if b.contains_box(&nb) && nb.width() < b.width() => {
                b = if pure_imag { nb.symmetrized() } else { nb };
                fails = 0;
            }
            _ => {
                fails += 1;
                if fails >= 3 {
                    // robust fallback: re-isolate everything, take the box inside b
                    let c = certified_all(p, prec)?;
                    if let Some(nb) = c.boxes.iter().find(|x| b.contains_box(x))
                        && nb.width() < b.width()
                    {
                        b = if pure_imag {
                            nb.symmetrized()
                        } else {
                            nb.clone()
                        };
                        continue;
                    }
                    if fails > 8 {
                        return Err(Error::Limit("complex root refinement stalled".into()));
                    }
                }
            }
        }
    }
    Ok(b)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::poly::zslice::from_i64s as z;
    #[test]
    fn boxes_of_quartic() {
        // x^4 + 4x^2 + 1: four purely imaginary roots
        let p = z(&[1, 0, 4, 0, 1]);
        let u = isolate_upper(&p, 0).unwrap();
        assert_eq!(u.len(), 2);
        assert!(u.iter().all(|(b, pi)| *pi && b.is_symmetric()));
        let w = Rational::new(1.into(), BigInt::from(10).pow(30));
        let r = refine_box(&p, &u[0].0, true, &w).unwrap();
        assert!(r.width() <= w && u[0].0.contains_box(&r));
        // x^3 - 2: one real, one upper
        let q = z(&[-2, 0, 0, 1]);
        let u = isolate_upper(&q, 1).unwrap();
        assert_eq!(u.len(), 1);
        assert!(!u[0].1);
    }
}
