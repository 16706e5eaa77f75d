use super::*;
use crate::field::Rational;
use num_traits::{One, Zero};

/// The structure of a tree, fully parenthesized: `(a + (b*c))`.
struct Shape;

impl Algebra for Shape {
    type Value = String;
    type Error = String;
    fn syntax(&self, e: SyntaxError) -> String {
        e.msg
    }
    fn number(&self, t: &str, _: usize) -> Result<String, String> {
        Ok(t.into())
    }
    fn name(&self, n: &str, _: usize) -> Result<String, String> {
        Ok(n.into())
    }
    fn call(&self, f: &str, a: Vec<String>, _: usize) -> Result<String, String> {
        Ok(format!("{f}[{}]", a.join(", ")))
    }
    fn neg(&self, a: String, _: usize) -> Result<String, String> {
        Ok(format!("(-{a})"))
    }
    fn add(&self, a: String, b: String, s: bool, _: usize) -> Result<String, String> {
        Ok(format!("({a} {} {b})", if s { '-' } else { '+' }))
    }
    fn mul(&self, a: String, b: String, d: bool, _: usize) -> Result<String, String> {
        Ok(format!("({a}{}{b})", if d { '/' } else { '*' }))
    }
    fn pow(&self, a: String, e: String, _: usize) -> Result<String, String> {
        Ok(format!("({a}^{e})"))
    }
}

/// Exact rationals with integer powers; `at` of a division by zero is reported.
struct Q;

impl Algebra for Q {
    type Value = Rational;
    type Error = String;
    fn syntax(&self, e: SyntaxError) -> String {
        e.msg
    }
    fn number(&self, t: &str, _: usize) -> Result<Rational, String> {
        parse_number(t)
    }
    fn name(&self, n: &str, _: usize) -> Result<Rational, String> {
        Err(format!("unknown '{n}'"))
    }
    fn call(&self, f: &str, _: Vec<Rational>, _: usize) -> Result<Rational, String> {
        Err(format!("unknown function '{f}'"))
    }
    fn neg(&self, a: Rational, _: usize) -> Result<Rational, String> {
        Ok(-a)
    }
    fn add(&self, a: Rational, b: Rational, s: bool, _: usize) -> Result<Rational, String> {
        Ok(if s { a - b } else { a + b })
    }
    fn mul(&self, a: Rational, b: Rational, d: bool, at: usize) -> Result<Rational, String> {
        if d && b.is_zero() {
            return Err(format!("division by zero at {}", at + 1));
        }
        Ok(if d { a / b } else { a * b })
    }
    fn pow(&self, a: Rational, e: Rational, _: usize) -> Result<Rational, String> {
        let n: i32 = e.to_integer().try_into().map_err(|_| "exponent")?;
        if !e.is_integer() || n.abs() > 64 {
            return Err("exponent".into());
        }
        Ok(num_traits::pow(a, n.unsigned_abs() as usize))
            .map(|p| if n < 0 { Rational::one() / p } else { p })
    }
}

fn shape(s: &str, d: Dialect) -> Result<String, String> {
    evaluate(&Shape, s, d)
}

#[test]
fn precedence_and_dialects() {
    let e = Dialect::EXACT;
    assert_eq!(shape("-2^2", e).unwrap(), "(-(2^2))");
    assert_eq!(shape("2^3^2", e).unwrap(), "(2^(3^2))");
    assert_eq!(shape("2^-x", e).unwrap(), "(2^(-x))");
    assert_eq!(shape("a - b*c/d", e).unwrap(), "(a - ((b*c)/d))");
    assert_eq!(shape("1/2i", e).unwrap(), "((1/2)*i)");
    assert_eq!(shape("2i^2", e).unwrap(), "(2*(i^2))");
    assert_eq!(shape("x**2", e).unwrap(), "(x^2)");
    assert_eq!(shape("sqrt(2)/2", e).unwrap(), "(sqrt[2]/2)");
    assert_eq!(shape("a*-b", e).unwrap(), "(a*(-b))");
    assert_eq!(shape("QQ(a, b+1)", e).unwrap(), "QQ[a, (b + 1)]");
    let p = Dialect::POLY;
    assert_eq!(shape("2x^2", p).unwrap(), "(2*(x^2))");
    assert_eq!(shape("3(x + 1)y", p).unwrap(), "((3*(x + 1))*y)");
    assert_eq!(shape("a(b)", p).unwrap(), "(a*b)");
    assert_eq!(shape("2 e", p).unwrap(), "(2*e)");
    // errors name the position and the text
    assert_eq!(
        shape("2 e", e).unwrap_err(),
        "unexpected 'e' at position 3 in '2 e'"
    );
    assert_eq!(shape("12abc", e).unwrap_err(), "'12abc' is not a number");
    assert_eq!(
        shape("(1+2", e).unwrap_err(),
        "missing ')' at the end of '(1+2'"
    );
    assert_eq!(
        shape("1+", e).unwrap_err(),
        "unexpected end of expression '1+'"
    );
    assert_eq!(shape(" ", p).unwrap_err(), "empty expression");
    let deep = parse(&"(".repeat(300), e).unwrap_err();
    assert!(deep.msg.contains("nested too deeply"), "{}", deep.msg);
    let err = parse("x + )", p).unwrap_err().to_error();
    assert_eq!(err.to_string(), "line 1, column 5: unexpected ')'");
}

/// A random expression over small integers (signs, powers, parentheses, products).
fn random_expr(g: &mut crate::rng::SplitMix64, depth: u32) -> String {
    let r = g.next_u64() % 7;
    if depth == 0 || r == 0 {
        return (g.next_u64() % 9 + 1).to_string();
    }
    let a = random_expr(g, depth - 1);
    let b = random_expr(g, depth - 1);
    match r {
        1 => format!("{a} + {b}"),
        2 => format!("{a} - {b}"),
        3 => format!("{a}*{b}"),
        4 => format!("({a})/({b})"),
        5 => format!("-({a})"),
        _ => format!("({a})^{}", g.next_u64() % 4),
    }
}

/// Properties: the fully parenthesized shape reads back to the same value; spaces do not
/// matter; `**` is `^`; the value does not depend on the dialect for texts without
/// juxtaposition.
#[test]
fn shapes_read_back_to_the_same_value() {
    let mut g = crate::rng::SplitMix64(0xe4);
    for _ in 0..300 {
        let s = random_expr(&mut g, 4);
        // the value, or the error without its position
        let val = |t: &str, d: Dialect| {
            evaluate(&Q, t, d).map_err(|e| e.split(" at ").next().unwrap_or("").to_string())
        };
        let v = val(&s, Dialect::EXACT);
        let shown = shape(&s, Dialect::EXACT).unwrap();
        assert_eq!(val(&shown, Dialect::EXACT), v, "{s} -> {shown}");
        assert_eq!(val(&s, Dialect::POLY), v, "{s}");
        let tight: String = s.chars().filter(|c| *c != ' ').collect();
        assert_eq!(val(&tight, Dialect::EXACT), v, "{s}");
        assert_eq!(val(&s.replace('^', "**"), Dialect::EXACT), v, "{s}");
    }
}

#[test]
fn values_and_positions() {
    let q = |s: &str| evaluate(&Q, s, Dialect::EXACT);
    assert_eq!(q("1.5e-3*2000").unwrap(), Rational::from_integer(3.into()));
    assert_eq!(q("(1/2)^-3").unwrap(), Rational::from_integer(8.into()));
    assert_eq!(q("1 + 2/(3 - 3)").unwrap_err(), "division by zero at 7");
    assert_eq!(
        referenced_names("-(a*cf - b)/sqrt(a) + i"),
        ["a", "cf", "b"]
    );
    // the tree's spans cover the text they came from
    let t = parse("  a*(b + 1) ", Dialect::EXACT).unwrap();
    assert_eq!((t.start, t.end), (2, 11));
}
