//! Display of rational functions $\mathbb{Q}(p_1, \dots, p_k)$: `-cr/(m*u)`, `(a + b)^2/c`,
//! `\frac{...}{...}`; the field itself as `QQ(cr, m, u)`.
//!
//! Numerator and denominator are each shown expanded or factored, whichever is shorter
//! (factored on a tie); factoring is tried only for polynomials of at most
//! [`FACTOR_DISPLAY_TERMS`] terms, so display stays cheap.

use crate::field::ElemDisplay;
use crate::mpoly::{MPoly, factor};
use crate::ratfunc::{RatFunc, RatFuncField};
use num_traits::{One, Signed};
use std::fmt;

impl fmt::Display for RatFuncField {
    /// `QQ(cr, m, u)`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "QQ({})", self.vars().join(", "))
    }
}

impl ElemDisplay<RatFunc> for RatFuncField {
    fn fmt_elem(&self, a: &RatFunc) -> String {
        fmt(self.vars(), a, false)
    }
    fn latex_elem(&self, a: &RatFunc) -> String {
        fmt(self.vars(), a, true)
    }
}

impl RatFuncField {
    /// Display of a polynomial in this field's variables.
    pub fn fmt_poly(&self, p: &MPoly) -> String {
        p.to_string_vars(self.vars())
    }
}

/// Polynomials with more terms are displayed expanded only.
pub const FACTOR_DISPLAY_TERMS: usize = 64;

/// Does `s` have a `+`/`-` between terms outside parentheses?
fn is_sum(s: &str) -> bool {
    let mut depth = 0i32;
    for (i, c) in s.char_indices() {
        match c {
            '(' | '{' => depth += 1,
            ')' | '}' => depth -= 1,
            '+' | '-' if depth == 0 && i > 0 => return true,
            _ => {}
        }
    }
    false
}

/// Is `s` one atom (a number, a name, or a power of one), needing no parentheses as a
/// denominator?
fn is_atom(s: &str) -> bool {
    !s.contains(['*', ' ', '+', '/']) && !s[1.min(s.len())..].contains('-')
}

fn render(vars: &[String], p: &MPoly, latex: bool) -> String {
    if latex {
        p.to_latex(vars)
    } else {
        p.to_string_vars(vars)
    }
}

/// Factored display of a polynomial with positive leading coefficient, if it has more than
/// one factor or a content.
fn factored(vars: &[String], p: &MPoly, latex: bool) -> Option<String> {
    if p.is_constant() || p.len() > FACTOR_DISPLAY_TERMS {
        return None;
    }
    let fz = factor(p).ok()?;
    let nf: usize = fz.factors.iter().map(|f| f.1).sum();
    if nf <= 1 && fz.content.is_one() {
        return None;
    }
    let mut parts = Vec::new();
    if !fz.content.is_one() {
        parts.push(fz.content.to_string());
    }
    for (g, e) in &fz.factors {
        let s = render(vars, g, latex);
        let s = if is_sum(&s) { format!("({s})") } else { s };
        parts.push(match (*e, latex) {
            (1, _) => s,
            (_, false) => format!("{s}^{e}"),
            (_, true) if s.contains('^') && !s.starts_with('(') => format!("({s})^{{{e}}}"),
            (_, true) => format!("{s}^{{{e}}}"),
        });
    }
    Some(parts.join(if latex { " " } else { "*" }))
}

fn best(vars: &[String], p: &MPoly, latex: bool) -> String {
    let e = render(vars, p, latex);
    match factored(vars, p, latex) {
        Some(f) if f.len() <= e.len() => f,
        _ => e,
    }
}

/// Text (`latex = false`) or LaTeX display of `a`.
fn fmt(vars: &[String], a: &RatFunc, latex: bool) -> String {
    let neg = a.num().lc().is_negative();
    if a.den().is_one() {
        if !neg {
            return best(vars, a.num(), latex);
        }
        // Expanded, `-p` is `direct`: the expanded |p| (its signs flipped: at most one
        // character shorter) as `-(|p|)` or `-|p|` (one term) is never shorter. Only a
        // factored |p| can be, so |p| is rendered only when it has one.
        let direct = render(vars, a.num(), latex);
        let abs = a.num().neg();
        let Some(f) = factored(vars, &abs, latex) else {
            return direct;
        };
        let e = render(vars, &abs, latex);
        let num_abs = if f.len() <= e.len() { f } else { e };
        let factored = if is_sum(&num_abs) {
            format!("-({num_abs})")
        } else {
            format!("-{num_abs}")
        };
        return if factored.len() < direct.len() {
            factored
        } else {
            direct
        };
    }
    let abs = if neg { a.num().neg() } else { a.num().clone() };
    let num_abs = best(vars, &abs, latex);
    let den = best(vars, a.den(), latex);
    let sign = if neg { "-" } else { "" };
    if latex {
        return format!("{sign}\\frac{{{num_abs}}}{{{den}}}");
    }
    let den = if is_atom(&den) {
        den
    } else {
        format!("({den})")
    };
    if !neg {
        let num = if is_sum(&num_abs) {
            format!("({num_abs})")
        } else {
            num_abs
        };
        return format!("{num}/{den}");
    }
    // negative numerator: "-x/d" or "(-a - b)/d", whichever is shorter
    if !is_sum(&num_abs) {
        return format!("-{num_abs}/{den}");
    }
    let direct = format!("({})/{den}", render(vars, a.num(), false));
    let pulled = format!("-({num_abs})/{den}");
    if pulled.len() < direct.len() {
        pulled
    } else {
        direct
    }
}
