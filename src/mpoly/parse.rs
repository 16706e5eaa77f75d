//! Parsing multivariate polynomials and rational functions from text such as
//! `m*u^2 - 3*cr`, `(a*b + c^2 + 1)^3*(a - b + 2*c)^2`, `2/3*x - 0.5`, `(s + 1)/(m*s^2 + k)`.
//!
//! Identifiers are `[A-Za-z_][A-Za-z0-9_]*`; numbers are exact (`0.08` is $2/25$, `1.5e-3` is
//! $3/2000$); `^` and `**` take non-negative integer exponents; juxtaposition multiplies
//! (`2x`, `3(x + 1)`). Sizes are bounded (degrees, terms and coefficient bits of powers), so
//! no input can make the parser slow; errors carry the 1-based column.

use super::{MAX_VARS, MPoly, QPoly, max_exponent};
use crate::error::{Error, Result};
use crate::field::Rational;
use crate::field::expr::{
    Algebra, Dialect, SyntaxError, error_at as at, evaluate, identifier_end, number_end,
    parse_number, reserved_message,
};
use num_bigint::BigInt;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// Largest degree in any variable of a parsed expression.
const MAX_DEGREE: u32 = 10_000;
/// Bound on the estimated number of terms of a power.
const MAX_POWER_TERMS: u64 = 1 << 20;
/// Bound on the estimated coefficient bits of a power.
const MAX_POWER_BITS: u64 = 1 << 16;

/// Parses a polynomial over $\mathbb{Q}$; its variables are all identifiers that occur,
/// sorted. Returns the variable names and the polynomial.
///
/// # Errors
/// `Parse` (column of the first problem) for bad text, a division by a non-constant, more
/// than [`MAX_VARS`] variables or too large sizes. Never panics.
///
/// # Examples
/// ```
/// use exactlti::mpoly::parse_mpoly;
/// let (vars, f) = parse_mpoly("m*u^2 - 3*cr").unwrap();
/// assert_eq!(vars, ["cr", "m", "u"]);
/// assert_eq!(f.to_string_vars(&vars), "m*u^2 - 3*cr");
/// ```
pub fn parse_mpoly(text: &str) -> Result<(Vec<String>, QPoly)> {
    let vars = identifiers(text)?;
    let refs: Vec<&str> = vars.iter().map(|s| s.as_str()).collect();
    let f = parse_mpoly_in(text, &refs)?;
    Ok((vars, f))
}

/// Parses a polynomial over $\mathbb{Q}$ in the given variables (an unknown identifier is an
/// error).
pub fn parse_mpoly_in(text: &str, vars: &[&str]) -> Result<QPoly> {
    let (num, den) = parse_fraction_in(text, vars, false)?;
    let d = den.to_constant().expect("constant denominator");
    Ok(QPoly::new(Rational::new(BigInt::one(), d), num))
}

/// Parses a rational function: `(num, den)` over $\mathbb{Z}$ with `den != 0` (not reduced).
///
/// # Errors
/// As [`parse_mpoly`]; also a division by the zero polynomial.
pub fn parse_ratfunc_in(text: &str, vars: &[&str]) -> Result<(MPoly, MPoly)> {
    parse_fraction_in(text, vars, true)
}

/// All identifiers in `text`, sorted and deduplicated.
///
/// # Errors
/// `Parse` when there are more than [`MAX_VARS`].
pub fn identifiers(text: &str) -> Result<Vec<String>> {
    let s = text.as_bytes();
    let mut out: Vec<String> = Vec::new();
    let mut i = 0;
    while i < s.len() {
        let c = s[i];
        if c.is_ascii_alphabetic() || c == b'_' {
            let start = i;
            i = identifier_end(s, i);
            let name = String::from_utf8_lossy(&s[start..i]).into_owned();
            if let Some(msg) = reserved_message(&name) {
                return Err(Error::Parse {
                    line: 1,
                    col: start + 1,
                    msg,
                });
            }
            out.push(name);
        } else if c.is_ascii_digit() || c == b'.' {
            // a number, with its exponent marker (`1e-3` names nothing)
            i = number_end(s, i, usize::MAX);
        } else {
            i += 1;
        }
    }
    out.sort();
    out.dedup();
    if out.len() > MAX_VARS {
        return Err(Error::Parse {
            line: 1,
            col: 1,
            msg: format!("more than {MAX_VARS} variables"),
        });
    }
    Ok(out)
}

fn parse_fraction_in(text: &str, vars: &[&str], allow_div: bool) -> Result<(MPoly, MPoly)> {
    if vars.len() > MAX_VARS {
        return Err(Error::Parse {
            line: 1,
            col: 1,
            msg: format!("more than {MAX_VARS} variables"),
        });
    }
    let alg = Fractions { vars, allow_div };
    if let Some(num) = plain_polynomial(text, vars, alg.lim()) {
        return Ok((num, MPoly::one(vars.len())));
    }
    let (mut num, mut den) = evaluate(&alg, text, Dialect::POLY)?;
    if den.lc().is_negative() {
        num = num.neg();
        den = den.neg();
    }
    Ok((num, den))
}

/// The fast path of [`parse_fraction_in`] for the texts most files hold: a sum of terms
/// `[-]c`, `[-][c*]x^e*y*...` (integer `c` of at most 18 digits, variables of `vars`,
/// explicit `*`, exponents at most `lim`), such as `-2 - 1*a + 2*b + 0*c`. Read in one pass
/// into terms, no tree and no polynomial product per operation. `None` for anything else
/// (parentheses, `/`, decimals, juxtaposition, `**`, a repeated sign, an unknown or reserved
/// name, an error): the general reader then gives the value or the error. Where it answers,
/// the value is the one of the general reader (the same grammar, read left to right: a sign
/// before a term applies to the whole product, below `^`), and the general reader would not
/// fail (every degree is at most `lim`, as its checks require).
fn plain_polynomial(text: &str, vars: &[&str], lim: u32) -> Option<MPoly> {
    let s = text.as_bytes();
    let n = vars.len();
    let mut i = 0usize;
    let skip = |i: &mut usize| {
        while *i < s.len() && matches!(s[*i], b' ' | b'\t') {
            *i += 1;
        }
    };
    // digits at `i` (no leading zero unless alone, at most 18, not followed by a letter,
    // digit, `_` or `.`): the value and the end
    let integer = |i: usize| -> Option<(i64, usize)> {
        let mut j = i;
        while j < s.len() && s[j].is_ascii_digit() {
            j += 1;
        }
        let len = j - i;
        if len == 0 || len > 18 || (len > 1 && s[i] == b'0') {
            return None;
        }
        if j < s.len() && (s[j].is_ascii_alphanumeric() || matches!(s[j], b'_' | b'.')) {
            return None;
        }
        std::str::from_utf8(&s[i..j])
            .ok()?
            .parse()
            .ok()
            .map(|v| (v, j))
    };
    let mut terms: Vec<(u128, BigInt)> = Vec::new();
    skip(&mut i);
    let mut neg = false;
    if i < s.len() && s[i] == b'-' {
        neg = true;
        i += 1;
        skip(&mut i);
    }
    loop {
        // one term: a number, or [number '*'] factor ('*' factor)*
        let mut coef = 1i64;
        let mut exps = [0u32; super::MAX_VARS];
        let mut expect_factor = true;
        if i < s.len() && s[i].is_ascii_digit() {
            let (v, j) = integer(i)?;
            coef = v;
            i = j;
            skip(&mut i);
            if i < s.len() && s[i] == b'*' {
                i += 1;
                skip(&mut i);
            } else {
                expect_factor = false;
            }
        }
        while expect_factor {
            let start = i;
            if i >= s.len() || !(s[i].is_ascii_alphabetic() || s[i] == b'_') {
                return None;
            }
            i = identifier_end(s, i);
            let name = std::str::from_utf8(&s[start..i]).ok()?;
            if crate::field::expr::reserved_meaning(name).is_some() {
                return None;
            }
            let v = vars.iter().position(|x| *x == name)?;
            skip(&mut i);
            let mut e = 1u32;
            if i < s.len() && s[i] == b'^' {
                i += 1;
                skip(&mut i);
                let (x, j) = integer(i)?;
                e = u32::try_from(x).ok().filter(|&x| x <= lim)?;
                i = j;
                skip(&mut i);
                if i < s.len() && s[i] == b'^' {
                    return None;
                }
            }
            exps[v] = exps[v].checked_add(e).filter(|&x| x <= lim)?;
            if i < s.len() && s[i] == b'*' {
                i += 1;
                if i < s.len() && s[i] == b'*' {
                    return None;
                }
                skip(&mut i);
            } else {
                expect_factor = false;
            }
        }
        terms.push((
            super::pack(n, &exps[..n]),
            BigInt::from(if neg { -coef } else { coef }),
        ));
        if i >= s.len() {
            break;
        }
        neg = match s[i] {
            b'+' => false,
            b'-' => true,
            _ => return None,
        };
        i += 1;
        skip(&mut i);
        if i < s.len() && matches!(s[i], b'+' | b'-') {
            return None;
        }
    }
    Some(MPoly::from_terms(n, terms))
}

type Frac = (MPoly, MPoly);

/// Fractions of integer polynomials in `vars` (division only by constants unless
/// `allow_div`), every operation size-checked.
struct Fractions<'a> {
    vars: &'a [&'a str],
    allow_div: bool,
}

impl Fractions<'_> {
    fn n(&self) -> usize {
        self.vars.len()
    }
    fn lim(&self) -> u32 {
        MAX_DEGREE.min(max_exponent(self.n()) / 2)
    }
    fn check(&self, f: Frac, pos: usize) -> Result<Frac> {
        let lim = self.lim();
        if f.0
            .degrees_array()
            .iter()
            .chain(f.1.degrees_array().iter())
            .any(|&d| d > lim)
        {
            return Err(at(pos, "degree too large"));
        }
        Ok(f)
    }
    fn check_mul(&self, a: &MPoly, b: &MPoly, pos: usize) -> Result<()> {
        let lim = self.lim();
        let (da, db) = (a.degrees_array(), b.degrees_array());
        if da.iter().zip(&db).any(|(x, y)| x + y > lim) {
            return Err(at(pos, "degree too large"));
        }
        if (a.len() as u64).saturating_mul(b.len() as u64) > MAX_POWER_TERMS * 4 {
            return Err(at(pos, "expression too large"));
        }
        Ok(())
    }
    fn product(&self, a: &Frac, b: &Frac, pos: usize) -> Result<Frac> {
        self.check_mul(&a.0, &b.0, pos)?;
        self.check_mul(&a.1, &b.1, pos)?;
        self.check((a.0.mul(&b.0), a.1.mul(&b.1)), pos)
    }
    /// Rejects powers whose size estimate is too large.
    fn check_power(&self, f: &MPoly, e: u32, pos: usize) -> Result<()> {
        let lim = self.lim() as u64;
        let degs = f.degrees();
        if degs.iter().any(|&d| d as u64 * e as u64 > lim) || e as u64 > lim {
            return Err(at(pos, "degree too large"));
        }
        // terms of f^e at most prod_i (e deg_i + 1); bits about e (log2 |f|_inf + log2 len)
        let terms = degs
            .iter()
            .fold(1u64, |acc, &d| acc.saturating_mul(e as u64 * d as u64 + 1));
        let bits = (e as u64)
            .saturating_mul(f.max_norm().bits() + (f.len().max(1) as u64).ilog2() as u64 + 1);
        if terms.min(binomial_bound(f.len() as u64, e as u64)) > MAX_POWER_TERMS
            || bits > MAX_POWER_BITS
        {
            return Err(at(pos, "power too large"));
        }
        Ok(())
    }
}

impl Algebra for Fractions<'_> {
    type Value = Frac;
    type Error = Error;
    fn syntax(&self, e: SyntaxError) -> Error {
        e.to_error()
    }
    fn number(&self, s: &str, pos: usize) -> Result<Frac> {
        let n = self.n();
        let q = parse_number(s).map_err(|m| at(pos, &m))?;
        if q.is_zero() {
            return Ok((MPoly::zero(n), MPoly::one(n)));
        }
        Ok((
            MPoly::constant(n, q.numer().clone()),
            MPoly::constant(n, q.denom().clone()),
        ))
    }
    fn name(&self, name: &str, pos: usize) -> Result<Frac> {
        if let Some(msg) = reserved_message(name) {
            return Err(at(pos, &msg));
        }
        let Some(i) = self.vars.iter().position(|v| *v == name) else {
            return Err(at(pos, &format!("unknown symbol '{name}'")));
        };
        Ok((MPoly::var(self.n(), i), MPoly::one(self.n())))
    }
    fn call(&self, f: &str, _: Vec<Frac>, pos: usize) -> Result<Frac> {
        self.name(f, pos)
    }
    fn neg(&self, a: Frac, _: usize) -> Result<Frac> {
        Ok((a.0.neg(), a.1))
    }
    fn add(&self, a: Frac, b: Frac, subtract: bool, pos: usize) -> Result<Frac> {
        let nb = if subtract { b.0.neg() } else { b.0 };
        if a.1 == b.1 {
            return self.check((a.0.add(&nb), a.1), pos);
        }
        self.check_mul(&a.0, &b.1, pos)?;
        self.check_mul(&a.1, &b.1, pos)?;
        self.check((a.0.mul(&b.1).add(&nb.mul(&a.1)), a.1.mul(&b.1)), pos)
    }
    fn mul(&self, a: Frac, b: Frac, divide: bool, pos: usize) -> Result<Frac> {
        if !divide {
            return self.product(&a, &b, pos);
        }
        if b.0.is_zero() {
            return Err(at(pos, "division by zero"));
        }
        if !self.allow_div && !b.0.is_constant() {
            return Err(at(pos, "division only by a non-zero constant"));
        }
        self.product(&a, &(b.1, b.0), pos)
    }
    fn pow(&self, base: Frac, e: Frac, pos: usize) -> Result<Frac> {
        let exp = (e.0.is_constant() && e.1.is_constant())
            .then(|| {
                let num = e.0.to_constant().unwrap_or_default();
                let den = e.1.to_constant().unwrap_or_else(BigInt::one);
                (num.is_zero() || (&num % &den).is_zero()).then(|| &num / &den)
            })
            .flatten()
            .filter(|n| !n.is_negative())
            .and_then(|n| n.to_u32());
        let Some(e) = exp else {
            return Err(at(pos, "expected a non-negative integer exponent"));
        };
        self.check_power(&base.0, e, pos)?;
        self.check_power(&base.1, e, pos)?;
        Ok((base.0.pow(e), base.1.pow(e)))
    }
}

/// Test helper: an integer polynomial in `a, b, c` from text (the content cleared).
#[cfg(test)]
pub(crate) fn abc(s: &str) -> MPoly {
    let f = parse_mpoly_in(s, &["a", "b", "c"]).unwrap();
    f.prim.scale(&f.content.to_integer())
}

/// Terms of $(t_1 + \dots + t_n)^e$ at most $\binom{n + e - 1}{e}$ (saturating).
fn binomial_bound(n: u64, e: u64) -> u64 {
    if n <= 1 {
        return 1;
    }
    let mut r: u64 = 1;
    for i in 0..e.min(n - 1) {
        let (num, den) = (n - 1 + e - i, i + 1);
        r = r.saturating_mul(num) / den;
        if r > MAX_POWER_TERMS * 16 {
            return u64::MAX;
        }
    }
    r
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The fast path answers exactly where the general reader gives the same polynomial
    /// (and a denominator 1), and steps aside for everything else.
    #[test]
    fn plain_polynomials_agree_with_the_general_reader() {
        let vars = ["a", "b", "c", "x2", "_k"];
        let general = |t: &str| {
            evaluate(
                &Fractions {
                    vars: &vars,
                    allow_div: true,
                },
                t,
                Dialect::POLY,
            )
        };
        let lim = Fractions {
            vars: &vars,
            allow_div: true,
        }
        .lim();
        let fast = [
            "-2 - 1*a + 2*b + 0*c",
            "0 - 2*a - 3*b - 2*c",
            "  5 +2*a+ 5*b -1*c ",
            "a",
            "-a",
            "0",
            "-0",
            "7",
            "a*b*a^2 - 3*c^0 + x2^3*_k",
            "a ^ 2 * b",
            "123456789012345678*a - 999999999999999999",
            "a^10000",
            "\t3*a\t",
        ];
        for t in fast {
            let got = plain_polynomial(t, &vars, lim).unwrap_or_else(|| panic!("{t}"));
            let (num, den) = general(t).unwrap();
            assert!(den.is_one(), "{t}");
            assert_eq!(got, num, "{t}");
        }
        let other = [
            "",
            "-",
            "a -",
            "+a",
            "a + -b",
            "a - -b",
            "--a",
            "2a",
            "2 a",
            "a b",
            "2.5*a",
            "1e3*a",
            "2e",
            "02*a",
            "a^02",
            "a**2",
            "a^-1",
            "a^2^3",
            "-2^2",
            "(a + b)",
            "a/2",
            "2*3",
            "a*2",
            "a*-b",
            "d",
            "i",
            "sqrt(a)",
            "a^10001",
            "a^5000*a^5001",
            "1234567890123456789*a",
            "a^2.5",
            "a^2b",
            "a +",
            "* a",
            "a * ",
            "aé",
        ];
        for t in other {
            assert!(plain_polynomial(t, &vars, lim).is_none(), "{t}");
        }
        // where the general reader answers too, the values agree
        assert_eq!(
            parse_fraction_in("a - -b", &vars, true).unwrap().0,
            parse_fraction_in("a + b", &vars, true).unwrap().0
        );
    }

    #[test]
    fn examples() {
        let (v, f) = parse_mpoly("m*u^2 - 3*cr").unwrap();
        assert_eq!(v, ["cr", "m", "u"]);
        assert_eq!(f.to_string_vars(&v), "m*u^2 - 3*cr");
        let (v, f) = parse_mpoly("2/3*x - 0.5*y").unwrap();
        assert_eq!(f.content, Rational::new(1.into(), 6.into()));
        assert_eq!(f.prim.display(&v).to_string(), "4*x - 3*y");
        assert!(parse_mpoly("x/y").is_err());
        assert!(parse_mpoly("(x+y+z+w)^1000").is_err());
        assert!(parse_mpoly("x^").is_err());
        assert_eq!(
            parse_mpoly("x + -2*y").unwrap().1,
            parse_mpoly("x - 2*y").unwrap().1
        );
        assert!(parse_mpoly("x + ").is_err());
        assert!(parse_mpoly("").is_err());
        assert!(parse_mpoly("(a + b)^20").is_ok());
        assert_eq!(identifiers("1e-3*x2 + e").unwrap(), ["e", "x2"]);
        let (n, d) = parse_ratfunc_in("(s + 1)/(-2*s)", &["s"]).unwrap();
        assert_eq!(n.display(&["s".to_string()]).to_string(), "-s - 1");
        assert_eq!(d.display(&["s".to_string()]).to_string(), "2*s");
    }
}
