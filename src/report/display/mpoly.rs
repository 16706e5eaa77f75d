//! Text and LaTeX display of multivariate polynomials with variable names: `m*u^2 - 3*cr`,
//! `m u^{2} - 3 \mathit{cr}`, in the term order of [`MPoly::display_order`] (total degree,
//! largest first, then lex), so univariate polynomials print as [`crate::poly::ZPoly`] does.

use crate::mpoly::{MPoly, QPoly};
use num_traits::{Signed, ToPrimitive};
use std::fmt::{self, Write as _};

const GREEK: [&str; 24] = [
    "alpha", "beta", "gamma", "delta", "epsilon", "zeta", "eta", "theta", "iota", "kappa",
    "lambda", "mu", "nu", "xi", "pi", "rho", "sigma", "tau", "upsilon", "phi", "chi", "psi",
    "omega", "Omega",
];

/// LaTeX form of a variable name: `x`, `\omega_{1}`, `\mathit{cr}`.
pub fn latex_name(name: &str) -> String {
    let (base, sub) = match name.split_once('_') {
        Some((b, s)) if !b.is_empty() && !s.is_empty() => (b, Some(s)),
        _ => {
            // trailing digits are a subscript: omega1 -> \omega_{1}
            let cut = name.trim_end_matches(|c: char| c.is_ascii_digit()).len();
            if cut > 0 && cut < name.len() {
                (&name[..cut], Some(&name[cut..]))
            } else {
                (name, None)
            }
        }
    };
    let b = if base.chars().count() == 1 {
        base.to_string()
    } else if GREEK.contains(&base) {
        format!("\\{base}")
    } else {
        format!("\\mathit{{{base}}}")
    };
    match sub {
        Some(s) => format!("{b}_{{{s}}}"),
        None => b,
    }
}

/// Appends the monomial `m` of `p` (`a*b^2`, `a b^{2}`) to `s`.
fn push_monomial(p: &MPoly, s: &mut String, m: u128, vars: &[String], latex: bool) {
    let mut first = true;
    for (i, v) in vars.iter().enumerate().take(p.nvars()) {
        let e = p.exp(m, i);
        if e == 0 {
            continue;
        }
        if !first {
            s.push_str(if latex { " " } else { "*" });
        }
        first = false;
        if latex {
            s.push_str(&latex_name(v));
        } else {
            s.push_str(v);
        }
        match (e, latex) {
            (1, _) => {}
            (_, false) => {
                let _ = write!(s, "^{e}");
            }
            (_, true) => {
                let _ = write!(s, "^{{{e}}}");
            }
        }
    }
}

fn render(p: &MPoly, vars: &[String], latex: bool) -> String {
    if p.is_zero() {
        return "0".into();
    }
    let mut s = String::with_capacity(16 * p.len());
    for (k, &t) in p.display_order().iter().enumerate() {
        let (m, c) = &p.terms()[t];
        let neg = c.is_negative();
        s.push_str(match (k == 0, neg) {
            (true, true) => "-",
            (true, false) => "",
            (false, true) => " - ",
            (false, false) => " + ",
        });
        // |c|: machine words print without a big-integer conversion
        let small = c.magnitude().to_u64();
        let one = small == Some(1);
        if *m == 0 || !one {
            match small {
                Some(v) => {
                    let _ = write!(s, "{v}");
                }
                None => {
                    let _ = write!(s, "{}", c.magnitude());
                }
            }
            if *m == 0 {
                continue;
            }
            s.push_str(if latex { " " } else { "*" });
        }
        push_monomial(p, &mut s, *m, vars, latex);
    }
    s
}

impl MPoly {
    /// Display with variable names, e.g. `m*u^2 - 3*cr`.
    pub fn display<'a>(&'a self, vars: &'a [String]) -> impl fmt::Display + 'a {
        struct D<'a>(&'a MPoly, &'a [String]);
        impl fmt::Display for D<'_> {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str(&render(self.0, self.1, false))
            }
        }
        D(self, vars)
    }

    /// `to_string` with variable names.
    pub fn to_string_vars(&self, vars: &[String]) -> String {
        render(self, vars, false)
    }

    /// LaTeX with variable names, e.g. `m u^{2} - 3 \mathit{cr}`.
    pub fn to_latex(&self, vars: &[String]) -> String {
        render(self, vars, true)
    }
}

impl QPoly {
    fn render(&self, vars: &[String], latex: bool) -> String {
        let show = |p: &MPoly| {
            if latex {
                p.to_latex(vars)
            } else {
                p.to_string_vars(vars)
            }
        };
        if let Some(p) = self.to_integer_poly() {
            return show(&p);
        }
        // rational content: the integer numerator times the polynomial, over the denominator
        let num = self.prim.scale(self.content.numer());
        let d = self.content.denom();
        if latex {
            format!("\\frac{{{}}}{{{d}}}", show(&num))
        } else if num.len() == 1 {
            format!("{}/{d}", show(&num))
        } else {
            format!("({})/{d}", show(&num))
        }
    }
    /// Display with variable names: `m*u^2 - 3*cr`, `(2*x - y)/3`.
    pub fn to_string_vars(&self, vars: &[String]) -> String {
        self.render(vars, false)
    }
    /// LaTeX display: `m u^{2} - 3 \mathit{cr}`, `\frac{2 x - y}{3}`.
    pub fn to_latex(&self, vars: &[String]) -> String {
        self.render(vars, true)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn names() {
        assert_eq!(latex_name("x"), "x");
        assert_eq!(latex_name("omega_1"), "\\omega_{1}");
        assert_eq!(latex_name("omega1"), "\\omega_{1}");
        assert_eq!(latex_name("cr"), "\\mathit{cr}");
        let v: Vec<String> = ["cr", "m", "u"].iter().map(|s| s.to_string()).collect();
        let f = crate::mpoly::parse_mpoly_in("m*u^2 - 3*cr", &["cr", "m", "u"]).unwrap();
        assert_eq!(f.to_latex(&v), "m u^{2} - 3 \\mathit{cr}");
    }
}
