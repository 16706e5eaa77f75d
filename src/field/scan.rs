//! Scanning text for exact literals: the one tokenizer rule every expression parser of the
//! crate shares (polynomials, multivariate polynomials, rational functions, system-file
//! expressions).
//!
//! * a number is a run of digits and dots, then an exponent `e`/`E`, an optional sign and
//!   digits, taken only when a digit follows (`2e` is `2` followed by the name `e`);
//! * an identifier is `[A-Za-z_][A-Za-z0-9_]*`.
//!
//! [`Cursor`] walks a byte string for the recursive-descent parsers and reports errors as
//! [`Error::Parse`] with the 1-based column.

use super::rational::{Rational, parse_rational};
use crate::error::Error;

/// Names the expression reader gives a meaning (`i` the imaginary unit, `sqrt` the square
/// root, `pi` refused as transcendental): never a parameter, symbol or polynomial variable,
/// since a variable of that name would silently change what a text means (`i^2 + 1` is 0
/// with the unit and a nonzero polynomial with a variable `i`).
pub const RESERVED: [&str; 3] = ["i", "sqrt", "pi"];

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

/// A position in a byte string, for hand-written recursive-descent parsers.
pub struct Cursor<'a> {
    pub s: &'a [u8],
    pub pos: usize,
    /// Current nesting depth (see [`Cursor::enter`]).
    pub depth: usize,
}

impl<'a> Cursor<'a> {
    pub fn new(text: &'a str) -> Self {
        Cursor {
            s: text.as_bytes(),
            pos: 0,
            depth: 0,
        }
    }
    /// `Parse` error at the current column.
    pub fn err(&self, msg: &str) -> Error {
        self.err_at(self.pos, msg)
    }
    /// `Parse` error at the 0-based byte offset `pos`.
    pub fn err_at(&self, pos: usize, msg: &str) -> Error {
        Error::Parse {
            line: 1,
            col: pos + 1,
            msg: msg.into(),
        }
    }
    /// Skips white space.
    pub fn ws(&mut self) {
        while self.s.get(self.pos).is_some_and(u8::is_ascii_whitespace) {
            self.pos += 1;
        }
    }
    /// The next byte after white space (not consumed).
    pub fn peek(&mut self) -> Option<u8> {
        self.ws();
        self.s.get(self.pos).copied()
    }
    /// Consumes the next byte (after white space) when it is one of `ops`.
    pub fn eat_any(&mut self, ops: &[u8]) -> Option<u8> {
        let c = self.peek().filter(|c| ops.contains(c))?;
        self.pos += 1;
        Some(c)
    }
    /// Error unless only white space is left.
    pub fn finish(&mut self) -> Result<(), Error> {
        match self.peek() {
            None => Ok(()),
            Some(_) => Err(self.err("unexpected character")),
        }
    }
    /// One level deeper (a parenthesis, a unary operator); error beyond `max`.
    pub fn enter(&mut self, max: usize) -> Result<(), Error> {
        self.depth += 1;
        if self.depth > max {
            return Err(self.err("nesting too deep"));
        }
        Ok(())
    }
    /// Consumes an opening parenthesis one level deeper (see [`Cursor::enter`]).
    pub fn open(&mut self, max: usize) -> Result<(), Error> {
        self.enter(max)?;
        self.expect(b'(')
    }
    /// Consumes the closing parenthesis of [`Cursor::open`].
    pub fn close(&mut self) -> Result<(), Error> {
        self.expect(b')')?;
        self.depth -= 1;
        Ok(())
    }
    /// Consumes `c` (after white space) or fails with "expected 'c'".
    pub fn expect(&mut self, c: u8) -> Result<(), Error> {
        if self.peek() != Some(c) {
            return Err(self.err(&format!("expected '{}'", c as char)));
        }
        self.pos += 1;
        Ok(())
    }
    /// The identifier at the cursor (consumed).
    pub fn identifier(&mut self) -> &'a str {
        let start = self.pos;
        self.pos = identifier_end(self.s, start);
        std::str::from_utf8(&self.s[start..self.pos]).unwrap_or("")
    }
    /// The number at the cursor (consumed), exact; on a malformed literal the message of
    /// [`parse_rational`].
    pub fn number(&mut self, max_exp_digits: usize) -> Result<Rational, String> {
        let start = self.pos;
        self.pos = number_end(self.s, start, max_exp_digits);
        let t = std::str::from_utf8(&self.s[start..self.pos]).unwrap_or("");
        parse_rational(t)
    }
    /// After a base: the exponent of `^ n` or `** n` (a non-negative integer literal), or
    /// `None` when no power operator follows.
    pub fn power_exponent<E: std::str::FromStr>(&mut self) -> Result<Option<E>, Error> {
        let op = match self.peek() {
            Some(b'^') => 1,
            Some(b'*') if self.s.get(self.pos + 1) == Some(&b'*') => 2,
            _ => return Ok(None),
        };
        self.pos += op;
        self.ws();
        let start = self.pos;
        while self.s.get(self.pos).is_some_and(u8::is_ascii_digit) {
            self.pos += 1;
        }
        std::str::from_utf8(&self.s[start..self.pos])
            .ok()
            .and_then(|t| t.parse().ok())
            .map(Some)
            .ok_or_else(|| self.err("expected a non-negative integer exponent"))
    }
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
        let mut c = Cursor::new("  x^12 ");
        assert_eq!(c.identifier(), "");
        c.ws();
        assert_eq!(c.identifier(), "x");
        assert_eq!(c.power_exponent::<u32>().unwrap(), Some(12));
        assert!(c.finish().is_ok());
        assert_eq!(
            Cursor::new("7/").number(usize::MAX),
            Ok(Rational::from_integer(7.into()))
        );
    }
}
