//! Text and LaTeX display of [`MPoly`] with variable names: `m*u^2 - 3*cr`,
//! `m u^{2} - 3 \mathit{cr}`. Terms are listed by total degree, largest first, then in lex
//! order, so univariate polynomials print as [`crate::poly::zpoly::ZPoly`] does.

use super::MPoly;
use num_bigint::BigInt;
use num_traits::{One, Signed};
use std::fmt;

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
        let mut idx: Vec<usize> = (0..self.len()).collect();
        let tdeg = |m: u128| (0..self.nvars).map(|i| self.exp(m, i)).sum::<u32>();
        idx.sort_by(|&a, &b| {
            let (ma, mb) = (self.terms[a].0, self.terms[b].0);
            tdeg(mb).cmp(&tdeg(ma)).then(mb.cmp(&ma))
        });
        idx
    }

    fn fmt_monomial(&self, m: u128, vars: &[String], latex: bool) -> String {
        let mut parts = Vec::new();
        for (i, v) in vars.iter().enumerate().take(self.nvars) {
            let e = self.exp(m, i);
            let name = if latex { latex_name(v) } else { v.clone() };
            match (e, latex) {
                (0, _) => {}
                (1, _) => parts.push(name),
                (_, false) => parts.push(format!("{name}^{e}")),
                (_, true) => parts.push(format!("{name}^{{{e}}}")),
            }
        }
        parts.join(if latex { " " } else { "*" })
    }

    fn render(&self, vars: &[String], latex: bool) -> String {
        if self.is_zero() {
            return "0".into();
        }
        let mut s = String::new();
        for (k, &t) in self.display_order().iter().enumerate() {
            let (m, c) = &self.terms[t];
            let neg = c.is_negative();
            s.push_str(match (k == 0, neg) {
                (true, true) => "-",
                (true, false) => "",
                (false, true) => " - ",
                (false, false) => " + ",
            });
            let a: BigInt = c.abs();
            if *m == 0 {
                s.push_str(&a.to_string());
                continue;
            }
            if !a.is_one() {
                s.push_str(&a.to_string());
                s.push_str(if latex { " " } else { "*" });
            }
            s.push_str(&self.fmt_monomial(*m, vars, latex));
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
