//! Text and LaTeX display of [`MPoly`] with variable names: `m*u^2 - 3*cr`,
//! `m u^{2} - 3 \mathit{cr}`. Terms are listed by total degree, largest first, then in lex
//! order, so univariate polynomials print as [`crate::poly::zpoly::ZPoly`] does.

use super::MPoly;
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

impl MPoly {
    /// Term indices in display order (total degree descending, then lex descending).
    fn display_order(&self) -> Vec<usize> {
        let tdeg = |m: u128| (0..self.nvars).map(|i| self.exp(m, i)).sum::<u32>();
        let mut idx: Vec<(u32, u128, usize)> = self
            .terms
            .iter()
            .enumerate()
            .map(|(i, t)| (tdeg(t.0), t.0, i))
            .collect();
        idx.sort_unstable_by(|a, b| b.0.cmp(&a.0).then(b.1.cmp(&a.1)));
        idx.into_iter().map(|t| t.2).collect()
    }

    /// Appends the monomial `m` (`a*b^2`, `a b^{2}`) to `s`.
    fn push_monomial(&self, s: &mut String, m: u128, vars: &[String], latex: bool) {
        let mut first = true;
        for (i, v) in vars.iter().enumerate().take(self.nvars) {
            let e = self.exp(m, i);
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

    fn render(&self, vars: &[String], latex: bool) -> String {
        if self.is_zero() {
            return "0".into();
        }
        let mut s = String::with_capacity(16 * self.len());
        for (k, &t) in self.display_order().iter().enumerate() {
            let (m, c) = &self.terms[t];
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
            self.push_monomial(&mut s, *m, vars, latex);
        }
        s
    }

    /// Display with variable names, e.g. `m*u^2 - 3*cr`.
    pub fn display<'a>(&'a self, vars: &'a [String]) -> impl fmt::Display + 'a {
        struct D<'a>(&'a MPoly, &'a [String]);
        impl fmt::Display for D<'_> {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str(&self.0.render(self.1, false))
            }
        }
        D(self, vars)
    }

    /// `to_string` with variable names.
    pub fn to_string_vars(&self, vars: &[String]) -> String {
        self.render(vars, false)
    }

    /// LaTeX with variable names, e.g. `m u^{2} - 3 \mathit{cr}`.
    pub fn to_latex(&self, vars: &[String]) -> String {
        self.render(vars, true)
    }

    /// Is the first displayed term (largest total degree, then lex) negative?
    pub fn display_lead_negative(&self) -> bool {
        self.display_order()
            .first()
            .is_some_and(|&i| self.terms[i].1.is_negative())
    }

    /// `f` or `-f`, whichever displays with a positive first term (for lists of factors and
    /// conditions, where the sign is immaterial or carried elsewhere).
    pub fn display_normalized(&self) -> MPoly {
        if self.display_lead_negative() {
            self.neg()
        } else {
            self.clone()
        }
    }

    /// Is the display a single term (no `+`/`-` between terms)?
    pub fn is_monomial_term(&self) -> bool {
        self.len() <= 1
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
