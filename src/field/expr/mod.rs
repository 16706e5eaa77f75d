//! The one expression reader of the crate: a lexer ([`lex`]) and a grammar ([`parse()`])
//! giving a tree ([`Expr`]), and a fold ([`evaluate`]) of the tree into any
//! [`Algebra`]. Every text the crate reads as math goes through it: system-file entries over
//! $\mathbb{Q}$, $\mathbb{Q}(\sqrt d)$ and $\mathbb{Q}(i)$ (`io::expr`), polynomials over
//! $\mathbb{Q}$ (`poly::parse`), multivariate polynomials and rational functions
//! $\mathbb{Q}(p_1, \dots, p_k)$ (`mpoly::parse`), transfer functions in $\mathbb{Q}(s)$
//! (`io::transfer_expr`) and one-parameter families in $\mathbb{Q}(v)$ (`study::family`).
//! Each of those supplies only its [`Algebra`]: what a number, a name and each operation
//! mean in its field, and its size bounds.
//!
//! Grammar (`^` right-associative and binding tighter than a sign, so `-2^2 = -4` and
//! `2^3^2 = 2^9`):
//!
//! ```text
//! expr  := term (('+' | '-') term)*
//! term  := unary (('*' | '/') unary)*        juxtaposition multiplies in Dialect::POLY
//! unary := ('-' | '+') unary | power
//! power := atom ('^' unary)?                 `**` is `^`
//! atom  := number | name | name '(' expr (',' expr)* ')' | '(' expr ')'
//! ```
//!
//! A number written directly before `i` (`2i`, `0.5i`) is an implicit product bound exactly
//! like the written-out `*` (`2i^2 = 2*i^2 = -2`, `1/2i = 1/2*i = i/2`). Numbers are exact
//! decimals ([`lex::parse_number`]). Nesting is bounded by [`MAX_DEPTH`], so the tree and
//! its fold have bounded depth; sums and products are flat lists, so long texts do not
//! deepen the tree.

pub(crate) mod lex;
pub(crate) mod parse;

pub(crate) use lex::reserved_message;
pub use lex::{
    MAX_EXPONENT, MAX_NUMBER_LEN, RESERVED, identifier_end, number_end, parse_number,
    reserved_meaning,
};
pub use parse::parse;

use crate::error::Error;

/// Largest accepted nesting depth of parentheses, signs and exponents.
pub const MAX_DEPTH: usize = 256;

/// Which of the two readings of a text: [`Dialect::EXACT`] (system files; a name before
/// `(` is a function call, `2x` is an error) or [`Dialect::POLY`] (polynomial texts:
/// juxtaposition multiplies, `2x`, `3(x + 1)`, `a b`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Dialect {
    pub juxtapose: bool,
}

impl Dialect {
    pub const EXACT: Dialect = Dialect { juxtapose: false };
    pub const POLY: Dialect = Dialect { juxtapose: true };
}

/// Where and what a syntax error is: 0-based character position, a short message (for a
/// message that adds the column itself) and the full one naming the position and the text.
/// Not an error type of its own: each reader ([`Algebra::syntax`]) turns it into the
/// crate's [`Error`], as [`Error::Parse`] ([`SyntaxError::to_error`]) or
/// [`Error::Invalid`] ([`SyntaxError::into_invalid`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SyntaxError {
    pub pos: usize,
    pub short: String,
    pub msg: String,
}

impl SyntaxError {
    pub fn new(pos: usize, short: String, msg: String) -> Self {
        SyntaxError { pos, short, msg }
    }
    /// As [`Error::Parse`] (line 1, the 1-based column, the short message).
    pub fn to_error(&self) -> Error {
        error_at(self.pos, &self.short)
    }
    /// As [`Error::Invalid`] with the full message (position and text named in it).
    pub fn into_invalid(self) -> Error {
        Error::Invalid(self.msg)
    }
}

/// [`Error::Parse`] at the 0-based character position `pos` of a one-line text (the error
/// of the evaluators that report a column).
pub fn error_at(pos: usize, msg: &str) -> Error {
    Error::Parse {
        line: 1,
        col: pos + 1,
        msg: msg.into(),
    }
}

/// A node of the tree with its 0-based character span `[start, end)`.
#[derive(Clone, Debug, PartialEq)]
pub struct Expr {
    pub node: Node,
    pub start: usize,
    pub end: usize,
}

impl Expr {
    pub fn new(node: Node, start: usize, end: usize) -> Self {
        Expr { node, start, end }
    }
}

#[derive(Clone, Debug, PartialEq)]
pub enum Node {
    /// A number literal as written (exact value: [`parse_number`]).
    Num(String),
    Name(String),
    /// `f(x, y, ...)`.
    Call(String, Vec<Expr>),
    Neg(Box<Expr>),
    /// Terms with their sign (`true`: subtracted); the first is never subtracted.
    Sum(Vec<(bool, Expr)>),
    /// Factors with their operation (`true`: divided by); the first is never a divisor.
    Product(Vec<(bool, Expr)>),
    Pow(Box<Expr>, Box<Expr>),
    /// A parenthesized expression (kept for display; its value is the inner one).
    Paren(Box<Expr>),
}

/// What the operations of the grammar mean in one field (or ring). Each method receives
/// the 0-based character position its error should name (the operand's start).
pub trait Algebra {
    type Value;
    type Error;
    /// A syntax error as this reader reports it.
    fn syntax(&self, e: SyntaxError) -> Self::Error;
    fn number(&self, text: &str, at: usize) -> Result<Self::Value, Self::Error>;
    fn name(&self, name: &str, at: usize) -> Result<Self::Value, Self::Error>;
    /// `f(args)`: only [`Dialect::EXACT`] has calls.
    fn call(&self, f: &str, args: Vec<Self::Value>, at: usize) -> Result<Self::Value, Self::Error>;
    fn neg(&self, a: Self::Value, at: usize) -> Result<Self::Value, Self::Error>;
    /// `a + b`, or `a - b` when `subtract`.
    fn add(
        &self,
        a: Self::Value,
        b: Self::Value,
        subtract: bool,
        at: usize,
    ) -> Result<Self::Value, Self::Error>;
    /// `a * b`, or `a / b` when `divide`.
    fn mul(
        &self,
        a: Self::Value,
        b: Self::Value,
        divide: bool,
        at: usize,
    ) -> Result<Self::Value, Self::Error>;
    /// `a ^ e` (`e` evaluated in the same algebra; the algebra decides which exponents it
    /// accepts).
    fn pow(&self, a: Self::Value, e: Self::Value, at: usize) -> Result<Self::Value, Self::Error>;
}

/// The value of `text` (read in `dialect`) in `alg`.
///
/// # Errors
/// A syntax error ([`Algebra::syntax`]) or the first error of an operation, left to
/// right.
pub fn evaluate<A: Algebra>(alg: &A, text: &str, dialect: Dialect) -> Result<A::Value, A::Error> {
    let e = parse(text, dialect).map_err(|e| alg.syntax(e))?;
    fold(alg, &e)
}

/// The value of the tree `e` in `alg`.
///
/// # Errors
/// The first error of an operation, left to right.
pub fn fold<A: Algebra>(alg: &A, e: &Expr) -> Result<A::Value, A::Error> {
    match &e.node {
        Node::Num(s) => alg.number(s, e.start),
        Node::Name(n) => alg.name(n, e.start),
        Node::Call(f, xs) => {
            let vs = xs.iter().map(|x| fold(alg, x)).collect::<Result<_, _>>()?;
            alg.call(f, vs, e.start)
        }
        Node::Neg(x) => {
            let v = fold(alg, x)?;
            alg.neg(v, e.start)
        }
        Node::Paren(x) => fold(alg, x),
        Node::Sum(ts) | Node::Product(ts) => {
            let sum = matches!(e.node, Node::Sum(_));
            let mut acc = fold(alg, &ts[0].1)?;
            for (op, t) in &ts[1..] {
                let v = fold(alg, t)?;
                acc = if sum {
                    alg.add(acc, v, *op, t.start)?
                } else {
                    alg.mul(acc, v, *op, t.start)?
                };
            }
            Ok(acc)
        }
        Node::Pow(b, x) => {
            let base = fold(alg, b)?;
            let n = fold(alg, x)?;
            alg.pow(base, n, x.start)
        }
    }
}

/// Names `text` refers to (names not called as functions, [`RESERVED`] excluded), in
/// order of first appearance; empty when `text` does not even lex.
pub fn referenced_names(text: &str) -> Vec<String> {
    let Ok(toks) = lex::lex(text) else {
        return Vec::new();
    };
    let mut names: Vec<String> = Vec::new();
    for (k, t) in toks.iter().enumerate() {
        if let lex::Tok::Name(n) = &t.tok {
            let call = toks.get(k + 1).map(|t| &t.tok) == Some(&lex::Tok::Op('('));
            if !call && !RESERVED.contains(&n.as_str()) && !names.contains(n) {
                names.push(n.clone());
            }
        }
    }
    names
}

#[cfg(test)]
mod tests;
