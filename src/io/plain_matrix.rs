//! The fast reader of a plain rational matrix file (issue 29: the command line's floor on
//! `linalg` of a 100x100 rational matrix was the general reader, not the kernel).
//!
//! A JSON text whose one key is the matrix's (`{"A": [[...], ...]}`), an array of equally
//! long rows whose entries are JSON numbers or strings of the plain form `[-]D[/D]` (`D` an
//! unsigned decimal literal `digits[.digits][(e|E)[+|-]digits]`), is read in one pass over
//! its bytes straight into a [`Matrix<Q>`], with no proxy tree and no expression parser.
//! The value is exact and the same as the general reader's (decimals are the rationals they
//! spell: `"0.08"` is $2/25$, `1.5e-3` is $3/2000$, `"-3/7"` is $-3/7$).
//!
//! The reader only *accepts or declines*: every text outside that subset (another key, a
//! string with an escape or a space, an expression, a ragged or non-square matrix, a zero
//! denominator, a literal longer than [`MAX_PLAIN_LEN`] characters or with an exponent
//! beyond [`MAX_PLAIN_EXPONENT`], anything that is not valid JSON) gives `None`, and the
//! caller reads the file with the general reader ([`super::system_file`]), which gives the
//! value or the error message naming the file, key, row and column. The bounds keep every
//! accepted value far inside the general reader's own size limits (a literal of at most
//! 4000 characters, exponents up to $10^4$, values below $2^{14}$ bits), so nothing the
//! general reader refuses is accepted here.

use crate::field::{Q, Rational, parse_rational};
use crate::matrix::Matrix;
use num_bigint::BigInt;

/// Longest entry (characters) the fast reader takes; longer ones go to the general reader.
pub const MAX_PLAIN_LEN: usize = 1000;

/// Largest |exponent| of a literal (`1e-300`) the fast reader takes.
pub const MAX_PLAIN_EXPONENT: u32 = 1000;

/// The square matrix under `key` when `text` is a JSON object with that one key holding a
/// plain rational matrix (see the module docs); `None` for every other text.
///
/// # Examples
/// ```
/// use exactlti::io::plain_matrix::plain_square_matrix;
/// let a = plain_square_matrix(r#"{"A": [[1, "-3/7"], [0.08, "1.5e-3"]]}"#, "A").unwrap();
/// assert_eq!(a.to_string(), "[[1, -3/7], [2/25, 3/2000]]");
/// assert!(plain_square_matrix(r#"{"A": [[1, "x"], [0, 1]]}"#, "A").is_none());
/// assert!(plain_square_matrix(r#"{"A": [[1, 2]]}"#, "A").is_none());
/// ```
pub fn plain_square_matrix(text: &str, key: &str) -> Option<Matrix<Q>> {
    let mut c = Cursor {
        s: text,
        b: text.as_bytes(),
        i: 0,
    };
    c.ws();
    c.eat(b'{')?;
    c.ws();
    if c.string()? != key {
        return None;
    }
    c.ws();
    c.eat(b':')?;
    c.ws();
    let (nrows, ncols, data) = c.rows()?;
    c.ws();
    c.eat(b'}')?;
    c.ws();
    (c.i == c.b.len() && nrows == ncols).then(|| Matrix::from_vec(Q, nrows, ncols, data))
}

/// A position in the bytes of the text.
struct Cursor<'a> {
    s: &'a str,
    b: &'a [u8],
    i: usize,
}

impl<'a> Cursor<'a> {
    fn peek(&self) -> Option<u8> {
        self.b.get(self.i).copied()
    }
    /// Skips JSON whitespace.
    fn ws(&mut self) {
        while matches!(self.peek(), Some(b' ' | b'\t' | b'\n' | b'\r')) {
            self.i += 1;
        }
    }
    fn eat(&mut self, want: u8) -> Option<()> {
        (self.peek()? == want).then(|| self.i += 1)
    }
    /// The contents of a JSON string without escapes or control characters.
    fn string(&mut self) -> Option<&'a str> {
        self.eat(b'"')?;
        let start = self.i;
        loop {
            match self.peek()? {
                b'"' => break,
                b'\\' | 0..=0x1f => return None,
                _ => self.i += 1,
            }
        }
        // both ends are at an ASCII quote, hence at character boundaries
        let s = self.s.get(start..self.i)?;
        self.i += 1;
        Some(s)
    }
    /// A JSON number token (strict JSON grammar: `-?(0|[1-9]d*)(.d+)?([eE][+-]?d+)?`).
    fn number(&mut self) -> Option<&'a str> {
        let start = self.i;
        if self.peek() == Some(b'-') {
            self.i += 1;
        }
        match self.peek()? {
            b'0' => self.i += 1,
            b'1'..=b'9' => self.digits(),
            _ => return None,
        }
        if self.peek() == Some(b'.') {
            self.i += 1;
            self.digits1()?;
        }
        if matches!(self.peek(), Some(b'e' | b'E')) {
            self.i += 1;
            if matches!(self.peek(), Some(b'+' | b'-')) {
                self.i += 1;
            }
            self.digits1()?;
        }
        self.s.get(start..self.i)
    }
    fn digits(&mut self) {
        while self.peek().is_some_and(|c| c.is_ascii_digit()) {
            self.i += 1;
        }
    }
    /// At least one digit.
    fn digits1(&mut self) -> Option<()> {
        let start = self.i;
        self.digits();
        (self.i > start).then_some(())
    }
    /// One entry: a JSON number or a plain string.
    fn entry(&mut self) -> Option<Rational> {
        match self.peek()? {
            b'"' => plain_entry(self.string()?),
            _ => plain_entry(self.number()?),
        }
    }
    /// `[row, ...]` with rows `[entry, ...]` of one length: (rows, columns, row-major data).
    fn rows(&mut self) -> Option<(usize, usize, Vec<Rational>)> {
        self.eat(b'[')?;
        self.ws();
        let mut data = Vec::new();
        let (mut nrows, mut ncols) = (0, None);
        if self.eat(b']').is_some() {
            return Some((0, 0, data));
        }
        loop {
            let len = self.row(&mut data)?;
            if *ncols.get_or_insert(len) != len {
                return None;
            }
            nrows += 1;
            if nrows == 1 {
                data.reserve(len * len);
            }
            self.ws();
            match self.peek()? {
                b',' => self.i += 1,
                b']' => break,
                _ => return None,
            }
            self.ws();
        }
        self.i += 1;
        Some((nrows, ncols.unwrap_or(0), data))
    }
    /// One row appended to `data`; its length.
    fn row(&mut self, data: &mut Vec<Rational>) -> Option<usize> {
        self.eat(b'[')?;
        self.ws();
        if self.eat(b']').is_some() {
            return Some(0);
        }
        let mut len = 0;
        loop {
            self.ws();
            data.push(self.entry()?);
            len += 1;
            self.ws();
            match self.peek()? {
                b',' => self.i += 1,
                b']' => break,
                _ => return None,
            }
        }
        self.i += 1;
        Some(len)
    }
}

/// The value of `[-]D[/D]` (see the module docs); `None` for any other text, a zero
/// denominator, or a literal beyond the bounds.
pub fn plain_entry(s: &str) -> Option<Rational> {
    if let Some(q) = word_fraction(s.as_bytes()) {
        return Some(q);
    }
    if s.len() > MAX_PLAIN_LEN {
        return None;
    }
    let (neg, body) = match s.strip_prefix('-') {
        Some(rest) => (true, rest),
        None => (false, s),
    };
    let q = match body.split_once('/') {
        None => literal(body)?,
        Some((p, q)) => match (small(p), small(q)) {
            // the common shape of decimal data as fractions: one word gcd
            (Some(p), Some(q)) if q != 0 => {
                let g = num_integer::Integer::gcd(&p, &q);
                Rational::new_raw(BigInt::from(p / g), BigInt::from(q / g))
            }
            _ => {
                let d = literal(q)?;
                if d == Rational::from_integer(BigInt::ZERO) {
                    return None;
                }
                literal(p)? / d
            }
        },
    };
    Some(if neg { -q } else { q })
}

/// `[-]p[/q]` with `p`, `q` of at most 18 digits each and `q != 0`, in one pass over the
/// bytes and one word gcd (the shape of decimal data written as fractions: 10^4 entries of
/// a 100x100 matrix); `None` for every other text.
fn word_fraction(b: &[u8]) -> Option<Rational> {
    let (neg, b) = match b.first()? {
        b'-' => (true, &b[1..]),
        _ => (false, b),
    };
    let (p, rest) = word_digits(b)?;
    let q = match rest.split_first() {
        None => 1,
        Some((b'/', d)) => match word_digits(d)? {
            (q, []) if q != 0 => q,
            _ => return None,
        },
        Some(_) => return None,
    };
    let g = if q == 1 {
        1
    } else {
        num_integer::Integer::gcd(&p, &q)
    };
    let p = BigInt::from(p / g);
    Some(Rational::new_raw(
        if neg { -p } else { p },
        BigInt::from(q / g),
    ))
}

/// The value of the leading run of 1 to 18 decimal digits of `b`, and the rest of `b`.
fn word_digits(b: &[u8]) -> Option<(u64, &[u8])> {
    let mut v: u64 = 0;
    let mut i = 0;
    while let Some(&c) = b.get(i).filter(|c| c.is_ascii_digit()) {
        if i == 18 {
            return None;
        }
        v = v * 10 + u64::from(c - b'0');
        i += 1;
    }
    (i > 0).then_some((v, &b[i..]))
}

/// An unsigned integer of at most 18 digits.
fn small(s: &str) -> Option<u64> {
    (!s.is_empty() && s.len() <= 18 && s.bytes().all(|b| b.is_ascii_digit()))
        .then(|| s.parse().ok())
        .flatten()
}

/// An unsigned decimal literal `digits[.digits][(e|E)[+|-]digits]` with an exponent of at
/// most [`MAX_PLAIN_EXPONENT`], exactly.
fn literal(s: &str) -> Option<Rational> {
    if let Some(n) = small(s) {
        return Some(Rational::from_integer(BigInt::from(n)));
    }
    let (mant, exp) = match s.find(['e', 'E']) {
        Some(p) => (&s[..p], Some(&s[p + 1..])),
        None => (s, None),
    };
    let (int, frac) = mant.split_once('.').unwrap_or((mant, "0"));
    let all_digits = |t: &str| !t.is_empty() && t.bytes().all(|b| b.is_ascii_digit());
    if !all_digits(int) || !all_digits(frac) {
        return None;
    }
    if let Some(e) = exp {
        let e = e.strip_prefix(['+', '-']).unwrap_or(e);
        if !all_digits(e) || e.len() > 4 || e.parse::<u32>().ok()? > MAX_PLAIN_EXPONENT {
            return None;
        }
    }
    parse_rational(s).ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn literals() {
        let q = |s: &str| {
            plain_entry(s).map(|x| crate::field::ElemDisplay::fmt_elem(&crate::field::Q, &x))
        };
        assert_eq!(q("0.08").as_deref(), Some("2/25"));
        assert_eq!(q("-1.5e-3").as_deref(), Some("-3/2000"));
        assert_eq!(q("2E3").as_deref(), Some("2000"));
        assert_eq!(q("-6/4").as_deref(), Some("-3/2"));
        assert_eq!(q("0.5/0.25").as_deref(), Some("2"));
        assert_eq!(q("-0").as_deref(), Some("0"));
        for bad in [
            "", "-", "1/0", "0.0/0", "1/", "/2", "1/2/3", "+1", " 1", "1 ", ".5", "5.", "1e",
            "1e1001", "1/2e1001", "--1", "1-2", "x", "1.2.3", "1e+-3", "i", "sqrt(2)",
        ] {
            assert_eq!(q(bad), None, "{bad:?}");
        }
    }
}
