//! Displays of algebraic numbers and of extension fields $F[t]/(g)$: closed forms
//! (`1/2 + sqrt(5)/2`, `i*sqrt(2 - sqrt(3))`), else `root of <minpoly> near <10 digits>`;
//! elements of $F[t]/(g)$ as the radical form `u + v*sqrt(f)` when known, else as the
//! polynomial in the generator.

use super::poly::fmt_poly;
use super::scalar::{fmt_pair, fmt_rational, quadratic_display, quadratic_latex};
use crate::algebraic::digits::{quadratic_roots, round_sig};
use crate::algebraic::ext::Radical;
use crate::algebraic::{AlgebraicNumber, Ext, ExtElem};
use crate::field::{ElemDisplay, Field, Q, Rational, radical_text, rational_to_f64};
use crate::poly::Poly;
use num_bigint::BigInt;
use num_complex::Complex64;
use num_traits::{One, Signed, Zero};
use std::fmt;

/// The `near` part of `root of P near X`, from the decimal strings of the real and imaginary
/// parts: `1.259921050`, `1.931851653*i` (purely imaginary: `re` is `"0"`),
/// `-0.6299605249 - 1.091123636*i`; `real` drops the imaginary part.
pub fn near_text(re: &str, im: &str, real: bool) -> String {
    if real {
        re.to_string()
    } else if re == "0" {
        format!("{im}*i")
    } else if let Some(m) = im.strip_prefix('-') {
        format!("{re} - {m}*i")
    } else {
        format!("{re} + {im}*i")
    }
}

/// [`near_text`] of an `f64` approximation `(re, im)` to 10 significant digits (the exact
/// rounding of the `f64`s), as [`AlgebraicNumber::value_string`] writes its certified
/// digits: real when `im == 0`, purely imaginary when `re == 0`.
pub fn approx_text((re, im): (f64, f64)) -> String {
    let digits =
        |x: f64| Rational::from_float(x).map_or_else(|| format!("{x}"), |q| round_sig(&q, 10));
    near_text(&digits(re), &digits(im), im == 0.0)
}

/// Display of `a + b*sqrt(d)` (`d` square-free, `d != 1`; `d = -1` is `i`): the one display
/// of quadratic numbers, [`quadratic_display`].
pub fn quadratic_string(a: &Rational, b: &Rational, d: &BigInt) -> String {
    if d.is_zero() {
        return fmt_rational(a);
    }
    quadratic_display(a, b, d)
}

/// The closed form of a root of an irreducible polynomial, as values: a rational, a
/// quadratic number $a + b\sqrt f$, or the nested radical $\pm\sqrt{u}$ /
/// $\pm i\sqrt{-u}$ with $u = u_a + u_b\sqrt f$.
enum Closed {
    Rational(Rational),
    Quadratic(Rational, Rational, BigInt),
    Nested {
        neg: bool,
        imag: bool,
        inner: (Rational, Rational, BigInt),
    },
}

/// The closed form of the root of the irreducible monic `p` nearest `approx`: degree 1, 2,
/// and $x^4 + b x^2 + c$ with a real square root of the discriminant.
///
/// `approx` only chooses among the roots: it must be nearer the wanted root than half the
/// distance to the others (any certified approximation is).
fn closed_parts(p: &Poly<Q>, approx: (f64, f64)) -> Option<Closed> {
    match p.deg() {
        1 => Some(Closed::Rational(-p.coeff(0))),
        2 => {
            let (a0, s, f) = quadratic_roots(p)?;
            let positive = if f.is_negative() {
                approx.1 > 0.0
            } else {
                approx.0 > rational_to_f64(&a0)
            };
            let coef = if positive { s } else { -s };
            Some(Closed::Quadratic(a0, coef, f))
        }
        4 if p.coeff(1).is_zero() && p.coeff(3).is_zero() => {
            // theta^2 = u with u a root of y^2 + b y + c
            let q = Poly::new(Q, vec![p.coeff(0), p.coeff(2), Rational::one()]);
            let (a0, s, f) = quadratic_roots(&q)?;
            if !f.is_positive() {
                return None;
            }
            let z = Complex64::new(approx.0, approx.1);
            let u = z * z;
            let coef = if u.re > rational_to_f64(&a0) { s } else { -s };
            let u_pos = u.re > 0.0;
            let neg = if u_pos {
                approx.0 < 0.0
            } else {
                approx.1 < 0.0
            };
            let (ua, ub) = if u_pos { (a0, coef) } else { (-a0, -coef) };
            Some(Closed::Nested {
                neg,
                imag: !u_pos,
                inner: (ua, ub, f),
            })
        }
        _ => None,
    }
}

/// The closed form of the root of the irreducible monic `p` nearest `approx`, the one used
/// by every report: the rational for degree 1, [`quadratic_display`] for degree 2 (the sign
/// of the radical read off `approx`), and for $x^4 + b x^2 + c$ with a real square root of
/// the discriminant the nested radical `sqrt(u)` / `i*sqrt(-u)` (`i*sqrt(2 - sqrt(3))`);
/// `None` otherwise (the caller writes `root of p near ...`).
pub fn closed_form(p: &Poly<Q>, approx: (f64, f64)) -> Option<String> {
    Some(match closed_parts(p, approx)? {
        Closed::Rational(q) => fmt_rational(&q),
        Closed::Quadratic(a, b, f) => quadratic_display(&a, &b, &f),
        Closed::Nested { neg, imag, inner } => {
            let body = quadratic_display(&inner.0, &inner.1, &inner.2);
            let i = if imag { "i*" } else { "" };
            let sign = if neg { "-" } else { "" };
            format!("{sign}{i}sqrt({body})")
        }
    })
}

/// The LaTeX of [`closed_form`], made from the same values: `-\frac{1}{2}`,
/// `\frac{1}{2} + \frac{\sqrt{5}}{2}`, `\mathrm{i} \sqrt{2 - \sqrt{3}}`.
pub fn closed_form_latex(p: &Poly<Q>, approx: (f64, f64)) -> Option<String> {
    Some(match closed_parts(p, approx)? {
        Closed::Rational(q) => Q.latex_elem(&q),
        Closed::Quadratic(a, b, f) => quadratic_latex(&a, &b, &f),
        Closed::Nested { neg, imag, inner } => {
            let body = quadratic_latex(&inner.0, &inner.1, &inner.2);
            let i = if imag { "\\mathrm{i} " } else { "" };
            let sign = if neg { "-" } else { "" };
            format!("{sign}{i}\\sqrt{{{body}}}")
        }
    })
}

/// Exact display of the root of the irreducible `p` nearest `approx`: the closed form of
/// [`closed_form`] (the same as [`AlgebraicNumber::value_string`]'s), else
/// `root of p near ...` with [`approx_text`]'s 10 digits.
pub fn value_display(p: &Poly<Q>, approx: (f64, f64)) -> String {
    closed_form(p, approx).unwrap_or_else(|| format!("root of {p} near {}", approx_text(approx)))
}

impl AlgebraicNumber {
    /// Exact closed form up to degree 2 and for $x^4 + b x^2 + c$ (the nested radicals of
    /// [`closed_form`], the display every report uses), else
    /// `root of <minpoly> near <10 digits>`.
    pub fn value_string(&self) -> String {
        if let Some((a, b, d)) = self.quadratic_parts() {
            return quadratic_string(&a, &b, &d);
        }
        if self.degree() == 4
            && let Some(s) = closed_form(self.minpoly(), self.approx())
        {
            return s;
        }
        let (re, im) = self.digits(10);
        let near = near_text(&re, &im, self.is_real());
        format!("root of {} near {near}", self.minpoly())
    }
}

impl fmt::Display for AlgebraicNumber {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.value_string())
    }
}

impl<F: Field> fmt::Display for Ext<F> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let k = self.base();
        write!(f, "{k}[t]/({})", fmt_poly(k, self.modulus().coeffs(), "t"))
    }
}

impl<F: Field> ElemDisplay<ExtElem<F::Elem>> for Ext<F> {
    fn fmt_elem(&self, a: &ExtElem<F::Elem>) -> String {
        if let Some(r) = &self.0.radical {
            return fmt_radical(self, a, r);
        }
        match self.radical_pair(a) {
            Some((c0, c1, d)) => quadratic_display(&c0, &c1, &d),
            None => fmt_poly(self.base(), &a.0, self.var()),
        }
    }
    fn latex_elem(&self, a: &ExtElem<F::Elem>) -> String {
        match self.radical_pair(a) {
            Some((c0, c1, d)) if self.0.radical.is_none() => quadratic_latex(&c0, &c1, &d),
            _ => self.fmt_elem(a),
        }
    }
}

/// `u + v sqrt f` for $t = a_0 + s\sqrt f$ (the radical form of the generator).
fn fmt_radical<F: Field>(e: &Ext<F>, a: &ExtElem<F::Elem>, (a0, s, f): &Radical) -> String {
    let k = e.base();
    // c0 + c1 (a0 + s sqrt f) = (c0 + a0 c1) + (s c1) sqrt f
    let c0 = a.0.first().cloned().unwrap_or_else(|| k.zero());
    let c1 = a.0.get(1).cloned().unwrap_or_else(|| k.zero());
    let u = k.add(&c0, &k.mul(&k.from_rational(a0), &c1));
    let v = k.mul(&k.from_rational(s), &c1);
    let rad = radical_text(f);
    match (k.to_rational(&u), k.to_rational(&v)) {
        (Some(u), Some(v)) => fmt_pair(&u, &v, &rad),
        _ if k.is_zero(&v) => k.fmt_elem(&u),
        _ => {
            // u + v sqrt f, written "u - w sqrt f" when v = -w displays with a sign
            let neg = k.fmt_elem(&v).starts_with('-');
            let w = if neg { k.neg(&v) } else { v };
            let wt = if k.is_one(&w) {
                rad
            } else {
                format!("{}*{rad}", paren(k.fmt_elem(&w)))
            };
            let op = if neg { "-" } else { "+" };
            if k.is_zero(&u) {
                if neg { format!("-{wt}") } else { wt }
            } else {
                format!("{} {op} {wt}", k.fmt_elem(&u))
            }
        }
    }
}

/// `x` in parentheses when it is a sum or difference (for a coefficient before a product).
fn paren(x: String) -> String {
    if (super::poly::TEXT.compound)(&x) {
        format!("({x})")
    } else {
        x
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    fn r(n: i64, d: i64) -> Rational {
        Rational::new(n.into(), d.into())
    }
    #[test]
    fn quadratics() {
        let b = BigInt::from;
        assert_eq!(
            quadratic_string(&r(1, 2), &r(1, 2), &b(5)),
            "1/2 + sqrt(5)/2"
        );
        assert_eq!(quadratic_string(&r(-1, 1), &r(1, 1), &b(-1)), "-1 + i");
        assert_eq!(quadratic_string(&r(0, 1), &r(1, 2), &b(-2)), "sqrt(2)*i/2");
        assert_eq!(quadratic_string(&r(0, 1), &r(-1, 1), &b(-3)), "-sqrt(3)*i");
    }
    #[test]
    fn certified_roots_displays() {
        let p = |cs: &[i64]| Poly::from_i64s(cs);
        let vs = |q: &Poly<Q>| -> Vec<String> {
            crate::jordan::certified_roots(q)
                .unwrap()
                .iter()
                .map(|z| value_display(q, z.1))
                .collect()
        };
        assert_eq!(vs(&p(&[2, 2, 1])), ["-1 + i", "-1 - i"]);
        let v = vs(&p(&[1, 0, 4, 0, 1]));
        assert!(v.contains(&"i*sqrt(2 - sqrt(3))".to_string()), "{v:?}");
        assert!(v.contains(&"-i*sqrt(2 + sqrt(3))".to_string()), "{v:?}");
        let v = vs(&p(&[1, 0, -4, 0, 1]));
        assert!(v.contains(&"-sqrt(2 + sqrt(3))".to_string()), "{v:?}");
        assert_eq!(vs(&p(&[-1, -1, 1])), ["1/2 + sqrt(5)/2", "1/2 - sqrt(5)/2"]);
    }
    /// The LaTeX of a closed form, made from its values, is what re-parsing its text gave.
    #[cfg(feature = "cli")]
    #[test]
    fn closed_form_latex_is_the_typeset_text() {
        let p = |cs: &[i64]| Poly::from_i64s(cs);
        for q in [
            p(&[1, 0, 4, 0, 1]),
            p(&[1, 0, -4, 0, 1]),
            p(&[-1, -1, 1]),
            p(&[2, 2, 1]),
            p(&[3, 2]).monic(),
            p(&[-2, 0, 1]),
        ] {
            for (_, z) in crate::jordan::certified_roots(&q).unwrap() {
                let text = closed_form(&q, z).unwrap();
                let latex = closed_form_latex(&q, z).unwrap();
                assert_eq!(Some(latex), crate::report::latex::to_math(&text), "{text}");
            }
        }
    }
}
