//! The grammar of [`super`]: tokens ([`super::lex`]) to a tree ([`Expr`]), by recursive
//! descent with bounded nesting.

use super::lex::{Tok, Token, lex};
use super::{Dialect, Expr, MAX_DEPTH, Node, SyntaxError};

/// The tree of `text` in `dialect`.
///
/// # Errors
/// The first syntax error, with its 1-based position: an unexpected token or character, a
/// missing `)`, an empty text, letters glued to a number (`12abc`, unless the dialect
/// multiplies by juxtaposition), nesting deeper than [`MAX_DEPTH`].
pub fn parse(text: &str, dialect: Dialect) -> Result<Expr, SyntaxError> {
    let toks = lex(text)?;
    if toks.is_empty() {
        return Err(SyntaxError::new(
            0,
            "empty expression".into(),
            "empty expression".into(),
        ));
    }
    let mut p = Parser {
        text,
        toks,
        pos: 0,
        depth: 0,
        dialect,
    };
    let e = p.expr()?;
    if p.pos < p.toks.len() {
        return p.unexpected();
    }
    Ok(e)
}

struct Parser<'a> {
    text: &'a str,
    toks: Vec<Token>,
    pos: usize,
    depth: usize,
    dialect: Dialect,
}

fn boxed(e: Expr) -> Box<Expr> {
    Box::new(e)
}

impl Parser<'_> {
    fn peek(&self) -> Option<&Tok> {
        self.toks.get(self.pos).map(|t| &t.tok)
    }
    fn eat(&mut self, ops: &[char]) -> Option<char> {
        match self.peek() {
            Some(Tok::Op(c)) if ops.contains(c) => {
                let c = *c;
                self.pos += 1;
                Some(c)
            }
            _ => None,
        }
    }
    /// End of the last consumed token.
    fn last_end(&self) -> usize {
        self.pos
            .checked_sub(1)
            .and_then(|k| self.toks.get(k))
            .map_or(0, |t| t.end)
    }
    fn unexpected<T>(&self) -> Result<T, SyntaxError> {
        let text = self.text;
        match self.toks.get(self.pos) {
            None => Err(SyntaxError::new(
                text.chars().count(),
                "unexpected end of expression".into(),
                format!("unexpected end of expression '{text}'"),
            )),
            Some(t) => {
                let shown = match &t.tok {
                    Tok::Num(s) | Tok::Name(s) => s.clone(),
                    Tok::Op(c) => c.to_string(),
                };
                Err(SyntaxError::new(
                    t.start,
                    format!("unexpected '{shown}'"),
                    format!(
                        "unexpected '{shown}' at position {} in '{text}'",
                        t.start + 1
                    ),
                ))
            }
        }
    }
    fn enter(&mut self) -> Result<(), SyntaxError> {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            let m = format!("expression nested too deeply (more than {MAX_DEPTH} levels)");
            let at = self.toks.get(self.pos).map_or(0, |t| t.start);
            return Err(SyntaxError::new(at, m.clone(), m));
        }
        Ok(())
    }
    /// `expr := term (('+' | '-') term)*`
    fn expr(&mut self) -> Result<Expr, SyntaxError> {
        self.enter()?;
        let first = self.term()?;
        let start = first.start;
        let mut terms = vec![(false, first)];
        while let Some(c) = self.eat(&['+', '-']) {
            terms.push((c == '-', self.term()?));
        }
        self.depth -= 1;
        Ok(if terms.len() == 1 {
            terms.pop().map(|(_, e)| e).expect("one term")
        } else {
            Expr::new(Node::Sum(terms), start, self.last_end())
        })
    }
    /// Juxtaposition multiplies here: a name or `(` after a factor.
    fn implicit(&self) -> bool {
        self.dialect.juxtapose && matches!(self.peek(), Some(Tok::Name(_) | Tok::Op('(')))
    }
    /// `term := unary (('*' | '/')? unary)*` (without the operator: juxtaposition)
    fn term(&mut self) -> Result<Expr, SyntaxError> {
        let first = self.unary()?;
        let start = first.start;
        let mut factors = vec![(false, first)];
        loop {
            let divide = match self.eat(&['*', '/']) {
                Some(c) => c == '/',
                None if self.implicit() => false,
                None => break,
            };
            factors.push((divide, self.unary()?));
        }
        Ok(if factors.len() == 1 {
            factors.pop().map(|(_, e)| e).expect("one factor")
        } else {
            Expr::new(Node::Product(factors), start, self.last_end())
        })
    }
    /// `unary := ('-' | '+') unary | power`
    fn unary(&mut self) -> Result<Expr, SyntaxError> {
        let start = self.toks.get(self.pos).map_or(0, |t| t.start);
        let Some(c) = self.eat(&['+', '-']) else {
            return self.power();
        };
        self.enter()?;
        let v = self.unary()?;
        self.depth -= 1;
        Ok(if c == '-' {
            Expr::new(Node::Neg(boxed(v)), start, self.last_end())
        } else {
            v
        })
    }
    /// `power := atom ('^' unary)?` (right-associative, binding tighter than a sign)
    fn power(&mut self) -> Result<Expr, SyntaxError> {
        let base = self.atom()?;
        if self.eat(&['^']).is_none() {
            return Ok(base);
        }
        self.enter()?;
        let e = self.unary()?;
        self.depth -= 1;
        let start = base.start;
        Ok(Expr::new(
            Node::Pow(boxed(base), boxed(e)),
            start,
            self.last_end(),
        ))
    }
    fn close(&mut self) -> Result<(), SyntaxError> {
        match self.peek() {
            Some(Tok::Op(')')) => {
                self.pos += 1;
                Ok(())
            }
            None => {
                let n = self.text.chars().count();
                Err(SyntaxError::new(
                    n,
                    "missing ')'".into(),
                    format!("missing ')' at the end of '{}'", self.text),
                ))
            }
            Some(_) => self.unexpected(),
        }
    }
    /// `atom := number | name | name '(' expr (',' expr)* ')' | '(' expr ')'` (no calls when the
    /// dialect multiplies by juxtaposition: `a(b + 1)` is a product)
    fn atom(&mut self) -> Result<Expr, SyntaxError> {
        let Some(t) = self.toks.get(self.pos) else {
            return self.unexpected();
        };
        let (tok, start, end) = (t.tok.clone(), t.start, t.end);
        match tok {
            Tok::Num(s) => {
                self.pos += 1;
                if let Some(Token {
                    tok: Tok::Name(n),
                    start: next,
                    ..
                }) = self.toks.get(self.pos)
                    && *next == end
                    && !self.dialect.juxtapose
                {
                    let m = format!("'{s}{n}' is not a number");
                    return Err(SyntaxError::new(start, m.clone(), m));
                }
                Ok(Expr::new(Node::Num(s), start, end))
            }
            Tok::Name(n) => {
                self.pos += 1;
                if self.dialect.juxtapose || self.peek() != Some(&Tok::Op('(')) {
                    return Ok(Expr::new(Node::Name(n), start, end));
                }
                self.pos += 1;
                let mut args = vec![self.expr()?];
                while self.eat(&[',']).is_some() {
                    args.push(self.expr()?);
                }
                self.close()?;
                Ok(Expr::new(Node::Call(n, args), start, self.last_end()))
            }
            Tok::Op('(') => {
                self.pos += 1;
                let e = self.expr()?;
                self.close()?;
                Ok(Expr::new(Node::Paren(boxed(e)), start, self.last_end()))
            }
            Tok::Op(_) => self.unexpected(),
        }
    }
}
