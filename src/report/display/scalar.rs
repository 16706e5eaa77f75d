//! Displays of the scalar fields: $\mathbb{Q}$ (`-3/7`, `-\frac{3}{7}`), $\mathbb{Q}(\sqrt d)$
//! (`1 - sqrt(2)/2`, `1 - \frac{\sqrt{2}}{2}`) and $F(i)$ (`2 + i`): the text every output
//! shows parses back to the same number (`exactlti::io::eval_expr`).

use crate::field::{
    ComplexField, ComplexPair, ElemDisplay, Field, Q, Quadratic, QuadraticField, Rational,
    radical_text,
};
use num_bigint::BigInt;
use num_traits::{One, Signed, ToPrimitive, Zero};
use std::fmt;

impl fmt::Display for Q {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "QQ")
    }
}

impl ElemDisplay<Rational> for Q {
    fn fmt_elem(&self, a: &Rational) -> String {
        fmt_rational(a)
    }
    fn latex_elem(&self, a: &Rational) -> String {
        if a.is_integer() {
            int_string(a.numer())
        } else {
            let s = if a.is_negative() { "-" } else { "" };
            format!("{s}\\frac{{{}}}{{{}}}", a.numer().abs(), a.denom())
        }
    }
}

/// `p/q` or `p` when the denominator is one.
pub fn fmt_rational(a: &Rational) -> String {
    if a.is_integer() {
        int_string(a.numer())
    } else {
        format!("{}/{}", a.numer(), a.denom())
    }
}

/// The decimal text of `x`, through a machine word when it fits one (the entries of an
/// identity or of a small-integer matrix: issue 29, 10^4 of them in one report).
fn int_string(x: &BigInt) -> String {
    match x.to_i64() {
        Some(v) => v.to_string(),
        None => x.to_string(),
    }
}

impl fmt::Display for QuadraticField {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if *self.d() == BigInt::from(-1) {
            write!(f, "QQ(i)")
        } else {
            write!(f, "QQ(sqrt({}))", self.d())
        }
    }
}

impl ElemDisplay<Quadratic> for QuadraticField {
    fn fmt_elem(&self, x: &Quadratic) -> String {
        quadratic_display(&x.a, &x.b, self.d())
    }
    fn latex_elem(&self, x: &Quadratic) -> String {
        quadratic_latex(&x.a, &x.b, self.d())
    }
}

/// The one display of the quadratic number $a + b\sqrt d$ (`d` square-free, `d = -1` is
/// $i$), used by every text and JSON output: the rational part first, then the radical with
/// its coefficient's numerator before and denominator after it.
///
/// `-6 + sqrt(1598)/10`, `-sqrt(3)/24`, `1/2 + 3*sqrt(5)/2`, `-1 + i`, `sqrt(2)*i/2`,
/// `-3/20 - sqrt(1991)*i/20`; a rational (`b = 0`) as `-7/2`. Every display parses back to the
/// same number (`exactlti::io::eval_expr`).
///
/// # Examples
/// ```
/// use exactlti::field::Rational;
/// use exactlti::report::display::quadratic_display;
/// let r = |n: i64, d: i64| Rational::new(n.into(), d.into());
/// assert_eq!(quadratic_display(&r(-6, 1), &r(1, 10), &1598.into()), "-6 + sqrt(1598)/10");
/// assert_eq!(quadratic_display(&r(0, 1), &r(-1, 24), &3.into()), "-sqrt(3)/24");
/// assert_eq!(quadratic_display(&r(0, 1), &r(1, 2), &(-2).into()), "sqrt(2)*i/2");
/// assert_eq!(quadratic_display(&r(-1, 1), &r(1, 1), &(-1).into()), "-1 + i");
/// ```
pub fn quadratic_display(a: &Rational, b: &Rational, d: &BigInt) -> String {
    fmt_pair(a, b, &radical_text(d))
}

/// The LaTeX of [`quadratic_display`], as the report's LaTeX output typesets that display:
/// `-6 + \frac{\sqrt{1598}}{10}`, `-\frac{\sqrt{3}}{24}`, `\frac{\sqrt{2}\,\mathrm{i}}{2}`,
/// `-1 + \mathrm{i}`.
pub fn quadratic_latex(a: &Rational, b: &Rational, d: &BigInt) -> String {
    let q = |x: &Rational| Q.latex_elem(x);
    if b.is_zero() {
        return q(a);
    }
    let rad = if *d == BigInt::from(-1) {
        "\\mathrm{i}".to_string()
    } else if d.is_negative() {
        format!("\\sqrt{{{}}}\\,\\mathrm{{i}}", -d)
    } else {
        format!("\\sqrt{{{d}}}")
    };
    let babs = b.abs();
    let num = babs.numer();
    let top = if num.is_one() {
        rad
    } else {
        format!("{num} {rad}")
    };
    let t = if babs.denom().is_one() {
        top
    } else {
        format!("\\frac{{{top}}}{{{}}}", babs.denom())
    };
    let op = if b.is_negative() { "-" } else { "+" };
    if a.is_zero() {
        if b.is_negative() { format!("-{t}") } else { t }
    } else {
        format!("{} {op} {t}", q(a))
    }
}

/// Formats `a + b*rad` with `rad` a radical text, e.g. `1 - sqrt(2)/2`, `-1 + i`
/// ([`quadratic_display`] when `rad` is the text of a square root).
pub fn fmt_pair(a: &Rational, b: &Rational, rad: &str) -> String {
    if b.is_zero() {
        return fmt_rational(a);
    }
    let babs = b.abs();
    let num = babs.numer();
    let den = babs.denom();
    let mut t = if num.is_one() {
        rad.to_string()
    } else {
        format!("{num}*{rad}")
    };
    if !den.is_one() {
        t = format!("{t}/{den}");
    }
    if a.is_zero() {
        if b.is_negative() { format!("-{t}") } else { t }
    } else {
        let op = if b.is_negative() { "-" } else { "+" };
        format!("{} {op} {t}", fmt_rational(a))
    }
}

impl<F: Field> fmt::Display for ComplexField<F> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "({})(i)", self.base)
    }
}

impl<F: Field> ElemDisplay<ComplexPair<F::Elem>> for ComplexField<F> {
    fn fmt_elem(&self, a: &ComplexPair<F::Elem>) -> String {
        let k = &self.base;
        if let (Some(r), Some(i)) = (k.to_rational(&a.re), k.to_rational(&a.im)) {
            return quadratic_display(&r, &i, &(-1).into());
        }
        let re = k.fmt_elem(&a.re);
        if k.is_zero(&a.im) {
            return re;
        }
        let im = k.fmt_elem(&a.im);
        let imt = if k.is_one(&a.im) {
            "i".to_string()
        } else {
            format!("({im})*i")
        };
        if k.is_zero(&a.re) {
            imt
        } else {
            format!("{re} + {imt}")
        }
    }
}
