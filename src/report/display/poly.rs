//! Displays of univariate polynomials: `x^4 + 4*x^2 + 1`, `(1 + sqrt(2))*t + 3` in text,
//! `x^{2} - \frac{1}{2} x + 3` in LaTeX. One sum writer ([`poly_sum`]) serves both: the
//! terms from the leading one down, the sign of a simple coefficient pulled into the sum,
//! compound coefficients (sums) in parentheses; a [`SumStyle`] says how each piece is
//! written.

use crate::field::Field;
use crate::poly::Poly;
use crate::poly::zpoly::ZPoly;
use num_bigint::Sign;
use num_traits::{One, Zero};
use std::fmt;

/// How [`poly_sum`] writes the pieces of a sum in one output format.
pub struct SumStyle {
    /// Is the coefficient's display a sum (so it needs parentheses beside a monomial)?
    pub compound: fn(&str) -> bool,
    /// The monomial `var^k` for `k >= 2`.
    pub power: fn(&str, usize) -> String,
    /// The opening and closing parentheses.
    pub parens: (&'static str, &'static str),
    /// Between a coefficient and its monomial.
    pub times: &'static str,
}

/// The text style: `(1 + sqrt(2))*x^2 - 3*x`.
pub const TEXT: SumStyle = SumStyle {
    compound: |t| t.len() > 1 && (t[1..].contains([' ', '+']) || t[1..].contains('-')),
    power: |var, k| format!("{var}^{k}"),
    parens: ("(", ")"),
    times: "*",
};

/// The LaTeX style: `\left(1 + \sqrt{2}\right) x^{2} - 3 x`.
pub const LATEX: SumStyle = SumStyle {
    compound: |t| t.len() > 1 && (t[1..].contains(" + ") || t[1..].contains(" - ")),
    power: |var, k| format!("{var}^{{{k}}}"),
    parens: ("\\left(", "\\right)"),
    times: " ",
};

/// The polynomial with coefficients `cs` (low degree first) in `var`, each coefficient
/// written by `elem`, the pieces by `style`; `0` for no nonzero coefficient.
pub fn poly_sum<K: Field>(
    k: &K,
    cs: &[K::Elem],
    var: &str,
    elem: &dyn Fn(&K::Elem) -> String,
    style: &SumStyle,
) -> String {
    let (open, close) = style.parens;
    let mut s = String::new();
    for i in (0..cs.len()).rev() {
        if k.is_zero(&cs[i]) {
            continue;
        }
        let mut t = elem(&cs[i]);
        let compound = (style.compound)(&t);
        let neg = t.starts_with('-') && !compound;
        if neg {
            t.remove(0);
        }
        let mono = match i {
            0 => String::new(),
            1 => var.to_string(),
            _ => (style.power)(var, i),
        };
        let body = match (i, t.as_str(), compound) {
            // a compound constant term in parentheses beside other terms, bare alone
            (0, _, true) if !s.is_empty() => format!("{open}{t}{close}"),
            (0, _, _) => t,
            (_, "1", _) => mono,
            (_, _, true) => format!("{open}{t}{close}{}{mono}", style.times),
            _ => format!("{t}{}{mono}", style.times),
        };
        if s.is_empty() {
            s = if neg { format!("-{body}") } else { body };
        } else {
            s.push_str(if neg { " - " } else { " + " });
            s.push_str(&body);
        }
    }
    if s.is_empty() { "0".into() } else { s }
}

/// Formats coefficients `cs` (low first) as `x^4 + 4*x^2 + 1` in variable `var`.
pub fn fmt_poly<K: Field>(k: &K, cs: &[K::Elem], var: &str) -> String {
    poly_sum(k, cs, var, &|c| k.fmt_elem(c), &TEXT)
}

impl<K: Field> Poly<K> {
    /// Display with a chosen variable name.
    pub fn to_string_var(&self, var: &str) -> String {
        fmt_poly(self.field(), self.coeffs(), var)
    }
}

impl<K: Field> fmt::Display for Poly<K> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", fmt_poly(self.field(), self.coeffs(), "x"))
    }
}

impl ZPoly {
    /// Display with `var` as the variable name, e.g. `s^2 + 1`.
    pub fn display_with<'a>(&'a self, var: &'a str) -> impl fmt::Display + 'a {
        struct D<'a>(&'a ZPoly, &'a str);
        impl fmt::Display for D<'_> {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                zpoly_fmt(self.0, f, self.1)
            }
        }
        D(self, var)
    }
}

fn zpoly_fmt(p: &ZPoly, f: &mut fmt::Formatter<'_>, var: &str) -> fmt::Result {
    if p.is_zero() {
        return write!(f, "0");
    }
    let mut first = true;
    for (k, c) in p.coeffs().iter().enumerate().rev() {
        if c.is_zero() {
            continue;
        }
        let neg = c.sign() == Sign::Minus;
        match (first, neg) {
            (true, true) => write!(f, "-")?,
            (true, false) => {}
            (false, true) => write!(f, " - ")?,
            (false, false) => write!(f, " + ")?,
        }
        first = false;
        let a = c.magnitude();
        if k == 0 {
            write!(f, "{a}")?;
            continue;
        }
        if !a.is_one() {
            write!(f, "{a}*")?;
        }
        if k == 1 {
            write!(f, "{var}")?;
        } else {
            write!(f, "{var}^{k}")?;
        }
    }
    Ok(())
}

impl fmt::Display for ZPoly {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        zpoly_fmt(self, f, "x")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::ElemDisplay;
    use crate::field::{Q, Rational};
    fn p(cs: &[i64]) -> Poly<Q> {
        Poly::from_i64s(cs)
    }
    #[test]
    fn text_and_latex() {
        let f = p(&[1, 0, 4, 0, 1]);
        assert_eq!(f.to_string(), "x^4 + 4*x^2 + 1");
        assert_eq!(p(&[-1, 1]).to_string(), "x - 1");
        assert_eq!(p(&[0, -2]).to_string(), "-2*x");
        // a constant in Q(sqrt 3) shows as the number itself (`1/6 - sqrt(3)/9`)
        let k = crate::field::QuadraticField::new(3).unwrap();
        let h = |n: i64, d: i64| Rational::new(n.into(), d.into());
        let c = crate::field::Quadratic::new(h(1, 6), h(-1, 9));
        assert_eq!(
            fmt_poly(&k, std::slice::from_ref(&c), "t"),
            "1/6 - sqrt(3)/9"
        );
        let lin = [c.clone(), k.one()];
        assert_eq!(fmt_poly(&k, &lin, "t"), "t + (1/6 - sqrt(3)/9)");
        // the same sum in LaTeX: the compound coefficient in \left( \right)
        let latex = poly_sum(&k, &lin, "t", &|c| k.latex_elem(c), &LATEX);
        assert_eq!(
            latex,
            "t + \\left(\\frac{1}{6} - \\frac{\\sqrt{3}}{9}\\right)"
        );
        let g = p(&[3, -1, 0, 2]);
        assert_eq!(g.to_string_var("s"), "2*s^3 - s + 3");
        assert_eq!(
            poly_sum(&Q, g.coeffs(), "s", &|c| Q.latex_elem(c), &LATEX),
            "2 s^{3} - s + 3"
        );
        assert_eq!(p(&[]).to_string(), "0");
    }
}
