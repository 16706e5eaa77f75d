//! The lexer of the one expression grammar ([`super`]), and the literal rules every reader
//! of the crate shares.
//!
//! * a number is a run of digits and dots, then an exponent `e`/`E`, an optional sign and
//!   digits, taken only when a digit follows (`2e` is `2` followed by the name `e`); its
//!   value is the exact rational the decimal spells ([`parse_number`]);
//! * an identifier is `[A-Za-z_][A-Za-z0-9_]*`;
//! * operators are `+ - * / ^ ( )`, `,` between arguments, and `**` is `^`;
//! * a number written directly before `i` (`2i`, `0.5i`) is followed by an implicit `*`
//!   (a zero-width token), so it binds exactly like the written-out product.

use super::SyntaxError;
use crate::field::rational::{Rational, parse_rational};

/// Names the expression reader gives a meaning (`i` the imaginary unit, `sqrt` the square
/// root, `pi` refused as transcendental): never a parameter, symbol or polynomial variable,
/// since a variable of that name would silently change what a text means (`i^2 + 1` is 0
/// with the unit and a nonzero polynomial with a variable `i`).
pub const RESERVED: [&str; 3] = ["i", "sqrt", "pi"];

/// Longest accepted number literal (characters).
pub const MAX_NUMBER_LEN: usize = 4_000;
/// Largest accepted |exponent|, in literals (`1e-3`) and in powers `x^n`.
pub const MAX_EXPONENT: u32 = 10_000;

/// What a reserved name means (`None` for any other name), for error messages.
pub fn reserved_meaning(name: &str) -> Option<&'static str> {
    match name {
        "i" => Some("the imaginary unit"),
        "sqrt" => Some("the square root"),
        "pi" => Some("the transcendental constant pi"),
        _ => None,
    }
}

/// The refusal of a reserved name ([`RESERVED`]) as a variable.
pub(crate) fn reserved_message(name: &str) -> Option<String> {
    reserved_meaning(name).map(|m| {
        format!(
            "'{name}' is {m}, not a variable: polynomials here have rational coefficients \
             (no i, sqrt or pi)"
        )
    })
}

/// End (exclusive) of the number starting at `i`; an exponent with more than
/// `max_exp_digits` digits is not taken (the number then ends before `e`).
pub fn number_end<T: Copy + Into<char>>(s: &[T], i: usize, max_exp_digits: usize) -> usize {
    let at = |k: usize| s.get(k).map(|&c| c.into());
    let mut i = i;
    while at(i).is_some_and(|c| c.is_ascii_digit() || c == '.') {
        i += 1;
    }
    if matches!(at(i), Some('e' | 'E')) {
        let mut j = i + 1;
        if matches!(at(j), Some('+' | '-')) {
            j += 1;
        }
        let d0 = j;
        while at(j).is_some_and(|c| c.is_ascii_digit()) {
            j += 1;
        }
        if j > d0 && j - d0 <= max_exp_digits {
            i = j;
        }
    }
    i
}

/// End (exclusive) of the run of identifier characters `[A-Za-z0-9_]` starting at `i`.
pub fn identifier_end<T: Copy + Into<char>>(s: &[T], i: usize) -> usize {
    let mut i = i;
    while s
        .get(i)
        .is_some_and(|&c| c.into().is_ascii_alphanumeric() || c.into() == '_')
    {
        i += 1;
    }
    i
}

/// The exact value of a number literal, within the size limits (checked before any
/// big-number work): at most [`MAX_NUMBER_LEN`] characters, a decimal exponent of at most
/// [`MAX_EXPONENT`] in absolute value.
///
/// # Errors
/// The limit exceeded, or the message of [`parse_rational`] (`'1.2.3' is not a number`).
pub fn parse_number(s: &str) -> Result<Rational, String> {
    // fast path: a plain integer that fits in i64 (most entries of most files)
    let digits = s.strip_prefix(['-', '+']).unwrap_or(s);
    if !digits.is_empty()
        && digits.len() <= 18
        && digits.bytes().all(|c| c.is_ascii_digit())
        && let Ok(n) = s.parse::<i64>()
    {
        return Ok(Rational::from_integer(n.into()));
    }
    if s.len() > MAX_NUMBER_LEN {
        return Err(format!("number with more than {MAX_NUMBER_LEN} characters"));
    }
    if let Some(p) = s.find(['e', 'E']) {
        let e = s[p + 1..].trim_start_matches(['+', '-']);
        if e.len() > 5 || e.parse::<u32>().is_ok_and(|e| e > MAX_EXPONENT) {
            return Err(format!(
                "exponent of '{s}' is too large (at most {MAX_EXPONENT} in absolute value)"
            ));
        }
    }
    parse_rational(s)
}

/// A token of the grammar.
#[derive(Clone, Debug, PartialEq)]
pub enum Tok {
    /// A number literal, as written.
    Num(String),
    /// An identifier.
    Name(String),
    /// One of `+ - * / ^ ( ) ,` (`**` is `^`).
    Op(char),
}

/// A token with its 0-based character span `[start, end)` (`start == end`: the implicit
/// `*` of `2i`).
#[derive(Clone, Debug)]
pub struct Token {
    pub tok: Tok,
    pub start: usize,
    pub end: usize,
}

/// The tokens of `text`.
///
/// # Errors
/// A character outside the grammar, with its 1-based position.
pub fn lex(text: &str) -> Result<Vec<Token>, SyntaxError> {
    let cs: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < cs.len() {
        let c = cs[i];
        let start = i;
        if c.is_whitespace() {
            i += 1;
            continue;
        }
        let tok = if c.is_ascii_digit() || c == '.' {
            i = number_end(&cs, i, usize::MAX);
            let num = Tok::Num(cs[start..i].iter().collect());
            if cs.get(i) == Some(&'i')
                && !cs
                    .get(i + 1)
                    .is_some_and(|c| c.is_ascii_alphanumeric() || *c == '_')
            {
                out.push(Token {
                    tok: num,
                    start,
                    end: i,
                });
                out.push(Token {
                    tok: Tok::Op('*'),
                    start: i,
                    end: i,
                });
                continue;
            }
            num
        } else if c.is_ascii_alphabetic() || c == '_' {
            i = identifier_end(&cs, i);
            Tok::Name(cs[start..i].iter().collect())
        } else if c == '*' && cs.get(i + 1) == Some(&'*') {
            i += 2;
            Tok::Op('^')
        } else if "+-*/^(),".contains(c) {
            i += 1;
            Tok::Op(c)
        } else {
            return Err(SyntaxError::new(
                start,
                format!("unexpected character '{c}'"),
                format!(
                    "unexpected character '{c}' at position {} in '{text}'",
                    start + 1
                ),
            ));
        };
        out.push(Token { tok, start, end: i });
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn literals() {
        let b = |t: &str| t.as_bytes().to_vec();
        assert_eq!(number_end(&b("1.5e-3*x"), 0, usize::MAX), 6);
        assert_eq!(number_end(&b("2e"), 0, usize::MAX), 1);
        assert_eq!(number_end(&b("2e+x"), 0, usize::MAX), 1);
        assert_eq!(number_end(&b("1e12345"), 0, 4), 1);
        let cs: Vec<char> = "x_2 + 1".chars().collect();
        assert_eq!(identifier_end(&cs, 0), 3);
        assert_eq!(parse_number("7"), Ok(Rational::from_integer(7.into())));
        assert_eq!(parse_number("0.08"), Ok(Rational::new(2.into(), 25.into())));
        assert!(parse_number("1e-10001").unwrap_err().contains("too large"));
    }
    #[test]
    fn tokens() {
        let t = |s: &str| -> Vec<Tok> { lex(s).unwrap().into_iter().map(|t| t.tok).collect() };
        assert_eq!(
            t("2i^2"),
            [
                Tok::Num("2".into()),
                Tok::Op('*'),
                Tok::Name("i".into()),
                Tok::Op('^'),
                Tok::Num("2".into())
            ]
        );
        assert_eq!(t("x**2"), t("x^2"));
        assert_eq!(t("2i3").len(), 2);
        let spans: Vec<(usize, usize)> = lex(" ab+1.5e3 ")
            .unwrap()
            .iter()
            .map(|t| (t.start, t.end))
            .collect();
        assert_eq!(spans, [(1, 3), (3, 4), (4, 9)]);
        assert_eq!(
            lex("1 # 2").unwrap_err().msg,
            "unexpected character '#' at position 3 in '1 # 2'"
        );
    }
}
