//! The field $\mathbb{Q}(p_1, \dots, p_k)$ of rational functions in symbolic parameters, as a
//! [`Field`].
//!
//! An element is `num / den` with `num`, `den` in $\mathbb{Z}\lbrack p\rbrack$ ([`MPoly`]),
//! $\gcd(\text{num}, \text{den}) = 1$ in $\mathbb{Z}\lbrack p\rbrack$ (integer contents included)
//! and a positive (lex) leading coefficient of `den`; zero is `0/1`. This form is unique
//! ($\mathbb{Z}\lbrack p\rbrack$ is a UFD), so `==` is equality of rational functions and the
//! zero test is exact. `+` and `*` follow Henrici: only the gcds that can be nontrivial are
//! computed ($\gcd(b, d)$ for $a/b + c/d$, then the gcd of the numerator with it; cross gcds
//! for products).
//!
//! **Conditions.** Over $\mathbb{Q}(p)$ a nonzero pivot is nonzero *generically*. Every
//! [`Field::inv`] and [`Field::div`] by an element with a non-constant numerator records that
//! numerator in the field's shared condition log (interior mutability: all clones of one
//! field value share it, so a matrix computation reports what it divided by).
//! [`RatFuncField::conditions`] returns the distinct irreducible factors (sorted) that the
//! result assumes nonzero; [`RatFuncField::fresh`] gives the same field with an empty log for a
//! new computation. Matrices over $\mathbb{Q}(p)$ go through `Matrix<K>`, which calls the
//! evaluation/interpolation kernels of [`kernels`] for charpoly, det, RREF and rank.
//!
//! Display: `-cr/(m*u)`; numerator and denominator are shown factored where that is shorter
//! (`(a + b)^2/c`); LaTeX uses `\frac{}{}`.

pub mod condition;
pub(crate) mod kernels;

pub use condition::{Condition, Part, Reason, Structure};

/// The size budget of the determinant kernel (`Matrix::det` over $\mathbb{Q}(p)$ answers `Limit` beyond it).
pub use kernels::budget::{MAX_DET_TERMS, det_budget, det_terms_bound};
/// $\det B$ of a matrix over $\mathbb{Z}\lbrack p\rbrack$ by evaluation/interpolation (the kernel behind every Q(p) determinant).
pub use kernels::{charpoly_zp, det_zp};

use crate::error::{Error, Result};
use crate::field::{Field, Kernels, Rational};
use crate::mpoly::factor::cmp_poly;
use crate::mpoly::{MAX_VARS, MPoly, QPoly, factor, gcd};
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};
use std::collections::HashMap;
use std::fmt;
use std::sync::{Arc, Mutex};

/// A rational function `num / den` in lowest terms (see the module docs).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct RatFunc {
    num: MPoly,
    den: MPoly,
}

impl RatFunc {
    /// Numerator (integer polynomial).
    pub fn num(&self) -> &MPoly {
        &self.num
    }
    /// Denominator (integer polynomial, positive leading coefficient).
    pub fn den(&self) -> &MPoly {
        &self.den
    }
    /// Is it a polynomial with integer coefficients... i.e. is the denominator 1?
    pub fn is_integral_poly(&self) -> bool {
        self.den.is_one()
    }
    /// The constant value when the element lies in $\mathbb{Q}$.
    pub fn to_rational(&self) -> Option<Rational> {
        Some(Rational::new(
            self.num.to_constant()?,
            self.den.to_constant()?,
        ))
    }
}

/// The terms of an integer polynomial as (exponent vector, coefficient) pairs
/// ([`crate::field::value::Terms`]).
pub fn exp_terms(p: &MPoly) -> crate::field::value::Terms {
    p.terms()
        .iter()
        .map(|(m, c)| (p.exps(*m), c.clone()))
        .collect()
}

struct Ctx {
    vars: Vec<String>,
    /// Each recorded divisor with its first reason (the least in [`Reason`]'s order).
    log: Mutex<HashMap<MPoly, Reason>>,
    /// The irreducible factors of each recorded divisor, once computed.
    factored: Mutex<HashMap<MPoly, Vec<MPoly>>>,
}

/// The field $\mathbb{Q}(p_1, \dots, p_k)$ (a domain value; clones share the condition log).
#[derive(Clone)]
pub struct RatFuncField {
    ctx: Arc<Ctx>,
}

impl PartialEq for RatFuncField {
    fn eq(&self, other: &Self) -> bool {
        Arc::ptr_eq(&self.ctx, &other.ctx) || self.ctx.vars == other.ctx.vars
    }
}

impl Eq for RatFuncField {}

impl fmt::Debug for RatFuncField {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "RatFuncField({:?})", self.ctx.vars)
    }
}

impl RatFuncField {
    /// $\mathbb{Q}(v_1, \dots, v_k)$ with the given parameter names (in this order).
    ///
    /// # Errors
    /// `Invalid` for more than [`MAX_VARS`] names, duplicates, names that are not
    /// identifiers, or reserved names (`i`, `sqrt`, `pi`: [`crate::field::expr::RESERVED`]).
    pub fn new<S: AsRef<str>>(vars: &[S]) -> Result<Self> {
        let vars: Vec<String> = vars.iter().map(|s| s.as_ref().to_string()).collect();
        if vars.len() > MAX_VARS {
            return Err(Error::Invalid(format!(
                "at most {MAX_VARS} symbolic parameters"
            )));
        }
        for (i, v) in vars.iter().enumerate() {
            let ok = v
                .chars()
                .next()
                .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
                && v.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
            if !ok || vars[..i].contains(v) {
                return Err(Error::Invalid(format!("bad or repeated symbol name '{v}'")));
            }
            if let Some(m) = crate::field::expr::reserved_meaning(v) {
                return Err(Error::Invalid(format!(
                    "'{v}' is reserved ({m}) and cannot name a symbol"
                )));
            }
        }
        Ok(RatFuncField {
            ctx: Arc::new(Ctx {
                vars,
                log: Mutex::new(HashMap::new()),
                factored: Mutex::new(HashMap::new()),
            }),
        })
    }
    /// The same field with an empty condition log (a new computation).
    pub fn fresh(&self) -> Self {
        Self::new(&self.ctx.vars).expect("names already checked")
    }
    /// Parameter names.
    pub fn vars(&self) -> &[String] {
        &self.ctx.vars
    }
    pub fn nvars(&self) -> usize {
        self.ctx.vars.len()
    }
    /// `num / den` brought to lowest terms; `None` when `den` is zero.
    pub fn frac(&self, num: MPoly, den: MPoly) -> Option<RatFunc> {
        if den.is_zero() {
            return None;
        }
        Some(canonical(num, den))
    }
    /// A polynomial with integer coefficients.
    pub fn from_mpoly(&self, p: MPoly) -> RatFunc {
        RatFunc {
            den: MPoly::one(p.nvars()),
            num: p,
        }
    }
    /// A polynomial over $\mathbb{Q}$.
    pub fn from_qpoly(&self, p: &QPoly) -> RatFunc {
        let n = self.nvars();
        canonical(
            p.prim.scale(p.content.numer()),
            MPoly::constant(n, p.content.denom().clone()),
        )
    }
    /// The parameter $p_i$.
    pub fn var(&self, i: usize) -> RatFunc {
        self.from_mpoly(MPoly::var(self.nvars(), i))
    }
    /// Parses a rational function in this field's parameters (`(s + 1)/(m*s^2 + k)`).
    ///
    /// # Errors
    /// `Parse` for bad text or unknown symbols.
    pub fn parse(&self, text: &str) -> Result<RatFunc> {
        let names: Vec<&str> = self.ctx.vars.iter().map(|s| s.as_str()).collect();
        let (n, d) = crate::mpoly::parse::parse_ratfunc_in(text, &names)?;
        Ok(canonical(n, d))
    }
    /// Value at a rational point; `None` when the denominator vanishes there.
    pub fn eval(&self, a: &RatFunc, point: &[Rational]) -> Option<Rational> {
        let n = eval_q(&a.num, point);
        let d = eval_q(&a.den, point);
        if d.is_zero() { None } else { Some(n / d) }
    }
    /// Substitutes the value `v` for parameter `i` (the parameter stays, unused); `None` when
    /// the denominator vanishes identically after the substitution.
    pub fn substitute(&self, a: &RatFunc, i: usize, v: &Rational) -> Option<RatFunc> {
        let (p, q) = (v.numer(), v.denom());
        // num(p/q) * q^D / (den(p/q) * q^D) with D = max degree
        let d = a.num.deg(i).max(a.den.deg(i));
        let hom = |f: &MPoly| -> MPoly {
            let cs = f.to_univariate(i);
            let n = f.nvars();
            let mut acc = MPoly::zero(n);
            for (k, c) in cs.iter().enumerate() {
                let w = num_traits::pow(p.clone(), k) * num_traits::pow(q.clone(), d as usize - k);
                acc = acc.add(&c.scale(&w));
            }
            acc
        };
        self.frac(hom(&a.num), hom(&a.den))
    }
    /// Records that `p` is assumed nonzero (its primitive part; constants are ignored), as a
    /// pivot of the elimination ([`Reason::Pivot`]).
    pub fn record_condition(&self, p: &MPoly) {
        self.record_because(p, Reason::Pivot);
    }
    /// Records that `p` is assumed nonzero for `reason` (a polynomial recorded twice keeps the
    /// lesser reason in [`Reason`]'s order: input, structure, pole, proof, pivot).
    pub fn record_because(&self, p: &MPoly, reason: Reason) {
        if p.is_constant() {
            return;
        }
        let q = p.primitive_part();
        if let Ok(mut log) = self.ctx.log.lock() {
            let slot = log.entry(q).or_insert(reason);
            *slot = (*slot).min(reason);
        }
    }
    /// Records that `p` is assumed nonzero, **unfactored**: [`RatFuncField::conditions`]
    /// lists it as one condition (a pivot minor whose factors were not found; factoring it
    /// could cost more than the computation that needed it).
    pub fn record_condition_unfactored(&self, p: &MPoly, reason: Reason) {
        if p.is_constant() {
            return;
        }
        let q = p.primitive_part();
        if let Ok(mut m) = self.ctx.factored.lock() {
            m.insert(q.clone(), vec![q.clone()]);
        }
        self.record_because(&q, reason);
    }
    /// The raw recorded divisors (primitive, not factored), in no particular order.
    pub fn recorded(&self) -> Vec<MPoly> {
        self.ctx
            .log
            .lock()
            .map(|l| l.keys().cloned().collect())
            .unwrap_or_default()
    }
    /// The raw recorded divisors with their reasons, in no particular order.
    pub fn recorded_with_reasons(&self) -> Vec<(MPoly, Reason)> {
        self.ctx
            .log
            .lock()
            .map(|l| l.iter().map(|(p, r)| (p.clone(), *r)).collect())
            .unwrap_or_default()
    }
    /// Empties the condition log.
    pub fn clear_conditions(&self) {
        if let Ok(mut log) = self.ctx.log.lock() {
            log.clear();
        }
    }
    /// The irreducible factors of `p` (primitive, positive leading coefficient; cached).
    fn factors_of(&self, p: &MPoly) -> Result<Vec<MPoly>> {
        let known = self
            .ctx
            .factored
            .lock()
            .ok()
            .and_then(|m| m.get(p).cloned());
        if let Some(fs) = known {
            return Ok(fs);
        }
        let fs: Vec<MPoly> = factor(p)?
            .factors
            .into_iter()
            .map(|(g, _)| g.primitive_part())
            .collect();
        if let Ok(mut m) = self.ctx.factored.lock() {
            m.insert(p.clone(), fs.clone());
        }
        Ok(fs)
    }
    /// The conditions: distinct irreducible factors of every recorded divisor, sorted (total
    /// degree, number of terms, terms), each primitive with positive leading coefficient.
    ///
    /// # Errors
    /// As [`crate::mpoly::factor()`] (`Limit`).
    pub fn conditions(&self) -> Result<Vec<MPoly>> {
        Ok(self.explained()?.into_iter().map(|c| c.poly).collect())
    }
    /// [`RatFuncField::conditions`] with the reason of each (the least reason of the
    /// divisors it divides).
    ///
    /// # Errors
    /// As [`RatFuncField::conditions`].
    pub fn explained(&self) -> Result<Vec<Condition>> {
        self.explain(self.recorded_with_reasons())
    }
    /// The distinct irreducible factors of `items` (non-constant polynomials with reasons),
    /// each with the least reason of the polynomials it divides, sorted as
    /// [`RatFuncField::conditions`].
    ///
    /// # Errors
    /// As [`crate::mpoly::factor()`] (`Limit`).
    pub fn explain(&self, items: Vec<(MPoly, Reason)>) -> Result<Vec<Condition>> {
        let mut set: HashMap<MPoly, Reason> = HashMap::new();
        for (p, why) in items {
            if p.is_constant() {
                continue;
            }
            for f in self.factors_of(&p.primitive_part())? {
                let f = if f.lc().is_negative() { f.neg() } else { f };
                let slot = set.entry(f).or_insert(why);
                *slot = (*slot).min(why);
            }
        }
        let mut v: Vec<Condition> = set
            .into_iter()
            .map(|(poly, reason)| Condition { poly, reason })
            .collect();
        v.sort_by(|a, b| cmp_poly(&a.poly, &b.poly));
        Ok(v)
    }
    /// [`RatFuncField::conditions`] as display strings.
    pub fn conditions_strings(&self) -> Result<Vec<String>> {
        Ok(self
            .conditions()?
            .iter()
            .map(|p| p.display_normalized().to_string_vars(self.vars()))
            .collect())
    }
    /// `a / b` for nonzero `b` (no condition recorded: internal use by callers that record
    /// themselves).
    pub fn div_unrecorded(&self, a: &RatFunc, b: &RatFunc) -> Option<RatFunc> {
        if b.num.is_zero() {
            return None;
        }
        Some(self.mul(a, &invert(b)))
    }
}

fn eval_q(f: &MPoly, point: &[Rational]) -> Rational {
    let mut s = Rational::zero();
    for (m, c) in f.terms() {
        let mut t = Rational::from_integer(c.clone());
        for (i, v) in point.iter().enumerate().take(f.nvars()) {
            let e = f.exp(*m, i);
            if e > 0 {
                t *= num_traits::pow(v.clone(), e as usize);
            }
        }
        s += t;
    }
    s
}

/// Lowest terms, positive leading coefficient of the denominator.
fn canonical(num: MPoly, den: MPoly) -> RatFunc {
    let n = den.nvars();
    if num.is_zero() {
        return RatFunc {
            num,
            den: MPoly::one(n),
        };
    }
    if den.is_one() {
        // gcd(num, 1) = 1 and the denominator is positive: canonical as it is
        return RatFunc { num, den };
    }
    let g = gcd(&num, &den);
    let (mut a, mut b) = if g.is_one() {
        (num, den)
    } else {
        (
            num.div_exact(&g).expect("gcd divides"),
            den.div_exact(&g).expect("gcd divides"),
        )
    };
    if b.lc().is_negative() {
        a = a.neg();
        b = b.neg();
    }
    RatFunc { num: a, den: b }
}

fn invert(a: &RatFunc) -> RatFunc {
    if a.num.lc().is_negative() {
        RatFunc {
            num: a.den.neg(),
            den: a.num.neg(),
        }
    } else {
        RatFunc {
            num: a.den.clone(),
            den: a.num.clone(),
        }
    }
}

fn exact(a: &MPoly, b: &MPoly) -> MPoly {
    if b.is_one() {
        return a.clone();
    }
    a.div_exact(b).expect("gcd divides")
}

impl Field for RatFuncField {
    type Elem = RatFunc;
    fn zero(&self) -> RatFunc {
        let n = self.nvars();
        RatFunc {
            num: MPoly::zero(n),
            den: MPoly::one(n),
        }
    }
    fn one(&self) -> RatFunc {
        let n = self.nvars();
        RatFunc {
            num: MPoly::one(n),
            den: MPoly::one(n),
        }
    }
    fn is_zero(&self, a: &RatFunc) -> bool {
        a.num.is_zero()
    }
    fn is_one(&self, a: &RatFunc) -> bool {
        a.num.is_one() && a.den.is_one()
    }
    /// Henrici: $a/b + c/d$ with $g = \gcd(b, d)$, $t = a (d/g) + c (b/g)$,
    /// result $\frac{t / h}{(b/g)(d/g)(g/h)}$ with $h = \gcd(t, g)$.
    fn add(&self, x: &RatFunc, y: &RatFunc) -> RatFunc {
        if x.num.is_zero() {
            return y.clone();
        }
        if y.num.is_zero() {
            return x.clone();
        }
        if x.den == y.den {
            let t = x.num.add(&y.num);
            if x.den.is_one() {
                return RatFunc {
                    num: t,
                    den: x.den.clone(),
                };
            }
            return canonical(t, x.den.clone());
        }
        let g = gcd(&x.den, &y.den);
        if g.is_one() {
            return RatFunc {
                num: x.num.mul(&y.den).add(&y.num.mul(&x.den)),
                den: x.den.mul(&y.den),
            };
        }
        let bp = exact(&x.den, &g);
        let dp = exact(&y.den, &g);
        let t = x.num.mul(&dp).add(&y.num.mul(&bp));
        if t.is_zero() {
            return self.zero();
        }
        let h = gcd(&t, &g);
        RatFunc {
            num: exact(&t, &h),
            den: bp.mul(&dp).mul(&exact(&g, &h)),
        }
    }
    fn sub(&self, x: &RatFunc, y: &RatFunc) -> RatFunc {
        self.add(x, &self.neg(y))
    }
    /// Henrici: $\frac{a}{b} \cdot \frac{c}{d} = \frac{(a/g_1)(c/g_2)}{(b/g_2)(d/g_1)}$ with
    /// $g_1 = \gcd(a, d)$, $g_2 = \gcd(c, b)$.
    fn mul(&self, x: &RatFunc, y: &RatFunc) -> RatFunc {
        if x.num.is_zero() || y.num.is_zero() {
            return self.zero();
        }
        if x.den.is_one() && y.den.is_one() {
            return RatFunc {
                num: x.num.mul(&y.num),
                den: x.den.clone(),
            };
        }
        let g1 = gcd(&x.num, &y.den);
        let g2 = gcd(&y.num, &x.den);
        let num = exact(&x.num, &g1).mul(&exact(&y.num, &g2));
        let den = exact(&x.den, &g2).mul(&exact(&y.den, &g1));
        if den.lc().is_negative() {
            RatFunc {
                num: num.neg(),
                den: den.neg(),
            }
        } else {
            RatFunc { num, den }
        }
    }
    fn neg(&self, a: &RatFunc) -> RatFunc {
        RatFunc {
            num: a.num.neg(),
            den: a.den.clone(),
        }
    }
    /// The sign where it is the same for every parameter value: constants only (`None` for
    /// an element that depends on the parameters).
    fn sign(&self, a: &RatFunc) -> Option<std::cmp::Ordering> {
        let q = a.to_rational()?;
        Some(q.cmp(&Rational::zero()))
    }
    /// Records the numerator of `a` as a condition (see the module docs).
    fn inv(&self, a: &RatFunc) -> Option<RatFunc> {
        if a.num.is_zero() {
            return None;
        }
        self.record_condition(&a.num);
        Some(invert(a))
    }
    fn div(&self, a: &RatFunc, b: &RatFunc) -> Option<RatFunc> {
        self.inv(b).map(|bi| self.mul(a, &bi))
    }
    fn from_rational(&self, q: &Rational) -> RatFunc {
        let n = self.nvars();
        if q.is_zero() {
            return self.zero();
        }
        RatFunc {
            num: MPoly::constant(n, q.numer().clone()),
            den: MPoly::constant(n, q.denom().clone()),
        }
    }
    fn from_i64(&self, k: i64) -> RatFunc {
        let n = self.nvars();
        RatFunc {
            num: MPoly::constant(n, BigInt::from(k)),
            den: MPoly::one(n),
        }
    }
    fn to_rational(&self, a: &RatFunc) -> Option<Rational> {
        a.to_rational()
    }
    /// Evaluation/interpolation kernels ([`kernels`]).
    fn kernels(&self) -> Kernels<'_, RatFuncField> {
        Kernels::Table(&kernels::QP_KERNELS)
    }
    /// Only constants have an approximation (no values are attached to the parameters).
    fn elem_value(&self, a: &RatFunc) -> Option<crate::field::ElemValue> {
        Some(crate::field::ElemValue::RatFunc {
            vars: self.vars().to_vec(),
            num: exp_terms(&a.num),
            den: exp_terms(&a.den),
        })
    }
    fn approx(&self, a: &RatFunc) -> Option<(f64, f64)> {
        let q = a.to_rational()?;
        Some((crate::field::rational_to_f64(&q), 0.0))
    }
}

impl RatFuncField {
    /// Is `a` a constant of $\mathbb{Q}$ equal to one? (Helper for displays.)
    pub fn is_constant(&self, a: &RatFunc) -> bool {
        a.num.is_constant() && a.den.is_constant()
    }
    /// The integer polynomial `a * den(a)`... the numerator when the denominator is 1.
    pub fn as_integer_poly(&self, a: &RatFunc) -> Option<MPoly> {
        a.den.is_one().then(|| a.num.clone())
    }
    /// Unit check used by tests.
    pub fn is_unit_den(&self, a: &RatFunc) -> bool {
        a.den.to_constant().is_some_and(|c| c.is_one())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::ElemDisplay;
    #[test]
    fn examples() {
        let k = RatFuncField::new(&["cr", "m", "u"]).unwrap();
        let a = k.parse("-cr/(m*u)").unwrap();
        assert_eq!(k.fmt_elem(&a), "-cr/(m*u)");
        let b = k.parse("cr/(m*u) + 1").unwrap();
        assert_eq!(k.fmt_elem(&k.add(&a, &b)), "1");
        let c = k.parse("(m^2 - u^2)/(m + u)").unwrap();
        assert_eq!(k.fmt_elem(&c), "m - u");
        assert_eq!(
            k.fmt_elem(&k.from_rational(&Rational::new(3.into(), 6.into()))),
            "1/2"
        );
        assert!(k.conditions().unwrap().is_empty());
        let d = k.div(&k.one(), &k.parse("m^2*u - m*u").unwrap()).unwrap();
        assert_eq!(k.fmt_elem(&d), "1/(m*u*(m - 1))");
        assert_eq!(k.conditions_strings().unwrap(), ["m", "u", "m - 1"]);
        assert_eq!(k.latex_elem(&a), "-\\frac{\\mathit{cr}}{m u}");
        assert_eq!(k.to_string(), "QQ(cr, m, u)");
    }
}
