//! The imaginary axis over a quadratic field: $p(j\omega)$ for $p$ with coefficients in
//! $\mathbb{Q}$, $\mathbb{Q}(\sqrt d)$ or $\mathbb{Q}(i)$ has real and imaginary parts in
//! $\mathbb{Q}(\sqrt e)[\omega]$ ($e = d$ for a real field, $e = |d|$ for an imaginary one,
//! $e = 1$, i.e. $\mathbb{Q}$, for $\mathbb{Q}$ and $\mathbb{Q}(i)$), held as pairs
//! $q + \sqrt e\, r$ of polynomials over $\mathbb{Q}$ ([`AxisPoly`]). The margins are computed
//! once for every such field on these pairs; over $\mathbb{Q}$ every $r$ is $0$ and each
//! operation is the rational one.
//!
//! At a real algebraic $w$ (minimal polynomial $m$): with $N(P) = q^2 - e\,r^2 \in
//! \mathbb{Q}[\omega]$,
//! - the real roots of $P$ are the roots $w$ of $N(P)$ with $r(w) = 0$ or
//!   $\mathrm{sign}\, q(w) = -\mathrm{sign}\, r(w)$ (then $q(w) = -\sqrt e\, r(w)$);
//! - $\mathrm{sign}\, P(w)$ is $\mathrm{sign}\, q(w)$ when $|q(w)| > \sqrt e\,|r(w)|$ (the
//!   sign of $N(P)(w)$) and $\mathrm{sign}\, r(w)$ otherwise: signs of rational polynomials
//!   at $w$, decided exactly;
//! - a value $h = a(w)/b(w)$ is a root of $\mathrm{Norm}_{\mathbb{Q}(w)/\mathbb{Q}}\big(
//!   (x\,b_q - a_q)^2 - e\,(x\,b_r - a_r)^2\big) \in \mathbb{Q}[x]$ (degree $\le 2 \deg m$,
//!   by evaluation at $2\deg m + 1$ points and interpolation); the root meant is the only
//!   one meeting the interval image of $a/b$ on refined intervals of $w$ and $\sqrt e$
//!   (exact rational interval arithmetic). When $\sqrt e \in \mathbb{Q}(w)$ makes that norm
//!   vanish identically, $\sqrt e = b_q(w)/b_r(w)$ and $h \in \mathbb{Q}(w)$.

use super::algebra::{mult_matrix, range, sign_at, value_at, value_in_field};
use crate::algebraic::isolate_real::{RealRoot, bisect, isolate_real_roots};
use crate::algebraic::number::Loc;
use crate::algebraic::{AlgebraicNumber, NumberField, factor_q};
use crate::error::{Error, Result};
use crate::field::{Field, Q, QuadraticField, Rational};
use crate::poly::Poly;
use crate::poly::zslice as zp;
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;

/// $q + \sqrt e\, r$ with $q, r \in \mathbb{Q}[\omega]$.
#[derive(Clone, Debug, PartialEq)]
pub struct AxisPoly {
    pub q: Poly<Q>,
    pub r: Poly<Q>,
    /// The radicand $e \ge 1$ (1: $r$ is zero, the polynomial is rational).
    pub e: BigInt,
}

impl AxisPoly {
    pub fn rational(q: Poly<Q>) -> Self {
        AxisPoly {
            q,
            r: Poly::zero(Q),
            e: BigInt::one(),
        }
    }
    pub fn is_zero(&self) -> bool {
        self.q.is_zero() && self.r.is_zero()
    }
    pub fn is_rational(&self) -> bool {
        self.r.is_zero()
    }
    fn er(&self) -> Rational {
        Rational::from_integer(self.e.clone())
    }
    pub fn add(&self, o: &Self) -> Self {
        self.with(self.q.add(&o.q), self.r.add(&o.r), o)
    }
    pub fn sub(&self, o: &Self) -> Self {
        self.with(self.q.sub(&o.q), self.r.sub(&o.r), o)
    }
    pub fn neg(&self) -> Self {
        self.with(self.q.neg(), self.r.neg(), self)
    }
    pub fn mul(&self, o: &Self) -> Self {
        let e = if self.is_rational() {
            o.er()
        } else {
            self.er()
        };
        let q = self.q.mul(&o.q).add(&self.r.mul(&o.r).scale(&e));
        let r = self.q.mul(&o.r).add(&self.r.mul(&o.q));
        self.with(q, r, o)
    }
    /// $q^2 - e\,r^2 \in \mathbb{Q}[\omega]$, a multiple of this polynomial.
    pub fn norm(&self) -> Poly<Q> {
        self.q
            .mul(&self.q)
            .sub(&self.r.mul(&self.r).scale(&self.er()))
    }
    fn with(&self, q: Poly<Q>, r: Poly<Q>, o: &Self) -> Self {
        let e = if self.e.is_one() {
            o.e.clone()
        } else {
            self.e.clone()
        };
        AxisPoly { q, r, e }
    }
    /// The value at a float $\omega$.
    pub fn eval_f64(&self, w: f64) -> f64 {
        let ev = |p: &Poly<Q>| {
            p.coeffs()
                .iter()
                .rev()
                .fold(0.0, |acc, c| acc * w + crate::field::rational_to_f64(c))
        };
        let se = crate::field::rational_to_f64(&self.er()).sqrt();
        ev(&self.q) + se * ev(&self.r)
    }
}

/// A field whose polynomials split on the imaginary axis into [`AxisPoly`] parts.
pub trait AxisField: Field {
    /// $(\mathrm{Re}\, p(j\omega), \mathrm{Im}\, p(j\omega))$.
    fn split_axis(&self, p: &Poly<Self>) -> (AxisPoly, AxisPoly);
}

impl AxisField for Q {
    fn split_axis(&self, p: &Poly<Q>) -> (AxisPoly, AxisPoly) {
        let (re, im) = super::algebra::split_imaginary_axis(p);
        (AxisPoly::rational(re), AxisPoly::rational(im))
    }
}

impl AxisField for QuadraticField {
    /// $c = a + b\sqrt d$: for $d > 0$ both parts are real ($e = d$); for $d < 0$,
    /// $c = a + j\,b\sqrt{|d|}$ ($e = |d|$, or $\mathbb{Q}$ when $d = -1$).
    fn split_axis(&self, p: &Poly<QuadraticField>) -> (AxisPoly, AxisPoly) {
        let d = self.d().clone();
        let pa = Poly::new(Q, p.coeffs().iter().map(|c| c.a.clone()).collect());
        let pb = Poly::new(Q, p.coeffs().iter().map(|c| c.b.clone()).collect());
        let (ra, ia) = super::algebra::split_imaginary_axis(&pa);
        let (rb, ib) = super::algebra::split_imaginary_axis(&pb);
        if d.is_positive() {
            let mk = |q, r| AxisPoly { q, r, e: d.clone() };
            return (mk(ra, rb), mk(ia, ib));
        }
        // p(jw) = (ra + j ia) + j sqrt|d| (rb + j ib)
        let e = -d;
        if e.is_one() {
            return (
                AxisPoly::rational(ra.sub(&ib)),
                AxisPoly::rational(ia.add(&rb)),
            );
        }
        let mk = |q, r| AxisPoly { q, r, e: e.clone() };
        (mk(ra, ib.neg()), mk(ia, rb))
    }
}

/// The positive real roots of a nonzero `p`, ascending, each once.
///
/// # Errors
/// `Invalid` for the zero polynomial; `Limit` from a sign decision.
pub fn positive_roots(p: &AxisPoly) -> Result<Vec<AlgebraicNumber>> {
    if p.is_rational() {
        return super::algebra::positive_roots(&p.q);
    }
    let mut out = vec![];
    for w in super::algebra::positive_roots(&p.norm())? {
        let sr = sign_at(&p.r, &w)?;
        if sr == Ordering::Equal || sign_at(&p.q, &w)? == sr.reverse() {
            out.push(w);
        }
    }
    Ok(out)
}

/// The exact sign of `p(w)` for a real algebraic `w`.
///
/// # Errors
/// `Limit` from [`sign_at`].
pub fn axis_sign_at(p: &AxisPoly, w: &AlgebraicNumber) -> Result<Ordering> {
    let sq = sign_at(&p.q, w)?;
    if p.is_rational() {
        return Ok(sq);
    }
    let sr = sign_at(&p.r, w)?;
    if sr == Ordering::Equal || sq == sr {
        return Ok(sq);
    }
    if sq == Ordering::Equal {
        return Ok(sr);
    }
    Ok(match sign_at(&p.norm(), w)? {
        Ordering::Greater => sq,
        Ordering::Less => sr,
        Ordering::Equal => Ordering::Equal,
    })
}

/// The value $a(w)/b(w)$ ($b(w) \ne 0$) as an algebraic number, and whether its check held
/// (module docs).
///
/// # Errors
/// `DivisionByZero` when $b(w) = 0$; `Limit` when the roots are not told apart in bound.
pub fn axis_value_at(
    a: &AxisPoly,
    b: &AxisPoly,
    w: &AlgebraicNumber,
) -> Result<(AlgebraicNumber, bool)> {
    if a.is_rational() && b.is_rational() {
        return value_at(&a.q, &b.q, w);
    }
    let e = if a.is_rational() { b.er() } else { a.er() };
    if let Some(x) = w.to_rational() {
        // a rational w: a value in Q(sqrt e), a root of x^2 - 2 u x + (u^2 - e v^2)
        return value_rational_w(a, b, &x, &e);
    }
    let m = w.minpoly();
    let k = NumberField::new_unchecked(m, w.approx());
    let at = |p: &Poly<Q>| k.from_poly(p);
    let (aq, ar, bq, br) = (at(&a.q), at(&a.r), at(&b.q), at(&b.r));
    // F(x) = (x bq - aq)^2 - e (x br - ar)^2 = f2 x^2 + f1 x + f0 over Q(w)
    let ek = k.from_rational(&e);
    let two = k.from_rational(&Rational::from_integer(2.into()));
    let f2 = k.sub(&k.mul(&bq, &bq), &k.mul(&ek, &k.mul(&br, &br)));
    let f1 = k.mul(
        &two,
        &k.sub(&k.mul(&ek, &k.mul(&br, &ar)), &k.mul(&bq, &aq)),
    );
    let f0 = k.sub(&k.mul(&aq, &aq), &k.mul(&ek, &k.mul(&ar, &ar)));
    if k.is_zero(&f2) && k.is_zero(&f1) && k.is_zero(&f0) {
        // sqrt e = bq / br in Q(w) (module docs): h = a / b in Q(w)
        let root_e = k.mul(&bq, &k.inv(&br).ok_or(Error::DivisionByZero)?);
        let num = k.add(&aq, &k.mul(&root_e, &ar));
        let den = k.add(&bq, &k.mul(&root_e, &br));
        let h = k.mul(&num, &k.inv(&den).ok_or(Error::DivisionByZero)?);
        return value_in_field(&k, &h, w, k.mul(&den, &h) == num);
    }
    let norm = norm_quadratic(&k, [&f0, &f1, &f2])?;
    let (_, factors) = factor_q(&norm)?;
    let cands: Vec<(Poly<Q>, RealRoot)> = factors
        .into_iter()
        .flat_map(|(f, _)| {
            let z = zp::from_poly_q(&f);
            isolate_real_roots(&z)
                .into_iter()
                .map(move |r| (f.clone(), r))
        })
        .collect();
    // the check: h is a root of F over Q(w), and the chosen f shares a root with F there
    let (f, r) = pick(
        cands,
        w,
        |lo, hi, sq| {
            let (aq, ar) = (range(&a.q, lo, hi), range(&a.r, lo, hi));
            let (bq, br) = (range(&b.q, lo, hi), range(&b.r, lo, hi));
            let num = add_iv(aq, mul_iv(sq.clone(), ar));
            let den = add_iv(bq, mul_iv(sq.clone(), br));
            div_iv(num, den)
        },
        &e,
    )?;
    let fk = Poly::new(
        k.clone(),
        f.coeffs().iter().map(|c| k.from_rational(c)).collect(),
    );
    let fx = Poly::new(k.clone(), vec![f0, f1, f2]);
    let check = !fk.gcd(&fx).is_constant();
    if f.deg() == 1 {
        return Ok((AlgebraicNumber::from_rational(&-f.coeff(0)), check));
    }
    Ok((AlgebraicNumber::from_parts(f, Loc::Real(r)), check))
}

/// $\mathrm{Norm}_{\mathbb{Q}(w)/\mathbb{Q}}(f_0 + f_1 x + f_2 x^2)$: $\det$ of the
/// multiplication matrix at $2\deg m + 1$ rational points, interpolated.
fn norm_quadratic(k: &NumberField, f: [&<NumberField as Field>::Elem; 3]) -> Result<Poly<Q>> {
    let d = k.degree();
    let pts: Vec<Rational> = (0..=2 * d as i64)
        .map(|t| Rational::from_integer(t.into()))
        .collect();
    let mut vals = Vec::with_capacity(pts.len());
    for x in &pts {
        let xk = k.from_rational(x);
        let v = k.add(f[0], &k.mul(&xk, &k.add(f[1], &k.mul(&xk, f[2]))));
        vals.push(mult_matrix(k, &v).det()?);
    }
    Ok(interpolate(&pts, &vals))
}

/// Lagrange interpolation over $\mathbb{Q}$.
fn interpolate(xs: &[Rational], ys: &[Rational]) -> Poly<Q> {
    let mut out = Poly::zero(Q);
    for (i, (xi, yi)) in xs.iter().zip(ys).enumerate() {
        if yi.is_zero() {
            continue;
        }
        let mut basis = Poly::constant(Q, yi.clone());
        for (j, xj) in xs.iter().enumerate() {
            if i != j {
                let lin = Poly::new(Q, vec![-xj.clone(), Rational::one()]);
                basis = basis.mul(&lin).scale(&(Rational::one() / (xi - xj)));
            }
        }
        out = out.add(&basis);
    }
    out
}

/// A value at a rational $w$: $u + \sqrt e\, v$ as the root of its minimal polynomial.
fn value_rational_w(
    a: &AxisPoly,
    b: &AxisPoly,
    x: &Rational,
    e: &Rational,
) -> Result<(AlgebraicNumber, bool)> {
    let (aq, ar, bq, br) = (a.q.eval(x), a.r.eval(x), b.q.eval(x), b.r.eval(x));
    let nb = &bq * &bq - e * &br * &br;
    if nb.is_zero() {
        return Err(Error::DivisionByZero);
    }
    // (aq + s ar)(bq - s br) / nb with s = sqrt e
    let u = (&aq * &bq - e * &ar * &br) / &nb;
    let v = (&ar * &bq - &aq * &br) / &nb;
    if v.is_zero() {
        return Ok((AlgebraicNumber::from_rational(&u), true));
    }
    let f = Poly::new(Q, vec![&u * &u - e * &v * &v, -(&u + &u), Rational::one()]);
    let z = zp::from_poly_q(&f);
    let cands: Vec<(Poly<Q>, RealRoot)> = isolate_real_roots(&z)
        .into_iter()
        .map(|r| (f.clone(), r))
        .collect();
    let w = AlgebraicNumber::from_rational(x);
    let image = |_: &Rational, _: &Rational, sq: &Iv| {
        Some(add_iv(
            (u.clone(), u.clone()),
            mul_iv(sq.clone(), (v.clone(), v.clone())),
        ))
    };
    let (f, r) = pick(cands, &w, image, e)?;
    Ok((AlgebraicNumber::from_parts(f, Loc::Real(r)), true))
}

type Iv = (Rational, Rational);

fn add_iv(a: Iv, b: Iv) -> Iv {
    (a.0 + b.0, a.1 + b.1)
}
fn mul_iv(a: Iv, b: Iv) -> Iv {
    let ps = [&a.0 * &b.0, &a.0 * &b.1, &a.1 * &b.0, &a.1 * &b.1];
    let lo = ps.iter().min().cloned().unwrap_or_default();
    let hi = ps.iter().max().cloned().unwrap_or_default();
    (lo, hi)
}
/// `None` when the divisor's interval holds 0.
fn div_iv(a: Iv, b: Iv) -> Option<Iv> {
    if !b.0.is_positive() && !b.1.is_negative() {
        return None;
    }
    Some(mul_iv(a, (Rational::one() / &b.1, Rational::one() / &b.0)))
}

/// An interval holding $\sqrt e$ of width $\le 2^{-k}$.
fn sqrt_iv(e: &Rational, k: u32) -> Iv {
    // e is a positive integer here
    let scale = BigInt::one() << (2 * k);
    let s = (e.to_integer() * &scale).sqrt();
    let den = BigInt::one() << k;
    (
        Rational::new(s.clone(), den.clone()),
        Rational::new(s + 1, den),
    )
}

/// The one candidate root meeting the interval image of the value, on refined intervals.
fn pick(
    mut cands: Vec<(Poly<Q>, RealRoot)>,
    w: &AlgebraicNumber,
    image: impl Fn(&Rational, &Rational, &Iv) -> Option<Iv>,
    e: &Rational,
) -> Result<(Poly<Q>, RealRoot)> {
    let mut w = w.clone();
    for step in 0..2000u32 {
        let (lo, hi) = w.interval().unwrap_or_else(|| {
            let x = w.to_rational().unwrap_or_default();
            (x.clone(), x)
        });
        if let Some((ylo, yhi)) = image(&lo, &hi, &sqrt_iv(e, 8 + step)) {
            cands.retain(|(_, r)| r.hi >= ylo && r.lo <= yhi);
            if cands.len() == 1 {
                return Ok(cands.pop().unwrap_or_else(|| unreachable!()));
            }
            if cands.is_empty() {
                return Err(Error::Verification(
                    "the value lies in no isolating interval".into(),
                ));
            }
        }
        if w.to_rational().is_none() {
            w = w.refined(&((&hi - &lo) / Rational::from_integer(2.into())))?;
        }
        cands = cands
            .iter()
            .map(|(f, r)| (f.clone(), bisect(&zp::from_poly_q(f), r)))
            .collect();
    }
    Err(Error::Limit(
        "telling apart the roots of a value's minimal polynomial".into(),
    ))
}
