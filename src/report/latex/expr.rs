//! Exact display strings (`"-sqrt(2)/2"`, `"1/2 + sqrt(5)/2"`, `"0 + (b7)*i"`,
//! `"root of x^4 - 4*x^2 + 1 near 1.93"`, `"-cr/(m*u)"`) as LaTeX math.
//!
//! The display grammar is the crate's one expression grammar ([`crate::field::expr`]:
//! numbers, identifiers, `+ - * / ^`, parentheses, function calls), one `=`, and the phrase
//! `root of P near X`. A string outside the grammar (prose) is not math: [`to_math`]
//! answers `None` and the caller typesets it as text.

use crate::field::expr::{self, Dialect, Expr};

/// Longest string parsed as math (longer ones are shown as text).
const MAX_LEN: usize = 100_000;

/// The display tree: the shared reader's tree ([`crate::field::expr`]) with products as
/// binary nodes and the sign of a sum's first term on the term (`-a*b` is `-(a b)`).
#[derive(Clone, Debug)]
enum Node {
    Num(String),
    Id(String),
    Call(String, Vec<Node>),
    Paren(Box<Node>),
    Neg(Box<Node>),
    Sum(Vec<(bool, Node)>),
    Mul(Box<Node>, Box<Node>),
    Div(Box<Node>, Box<Node>),
    Pow(Box<Node>, Box<Node>),
}

/// Parses one expression (no `=`) with the crate's one reader.
fn parse(s: &str) -> Option<Node> {
    sum(&expr::parse(s, Dialect::EXACT).ok()?)
}

/// A negated leading factor (`-a*b`, `-2^2`): the factor without its sign.
fn unsigned(e: &Expr) -> Option<Expr> {
    match &e.node {
        expr::Node::Neg(x) => Some((**x).clone()),
        expr::Node::Product(fs) => {
            let first = unsigned(&fs[0].1)?;
            let mut fs = fs.clone();
            fs[0].1 = first;
            Some(Expr::new(expr::Node::Product(fs), e.start, e.end))
        }
        _ => None,
    }
}

/// An expression where a sum may stand (the whole text, parentheses, arguments): a sign
/// in front of the first term belongs to the term.
fn sum(e: &Expr) -> Option<Node> {
    let terms: Vec<(bool, &Expr)> = match &e.node {
        expr::Node::Sum(ts) => ts.iter().map(|(s, t)| (*s, t)).collect(),
        _ => vec![(false, e)],
    };
    let mut out = Vec::with_capacity(terms.len());
    for (k, (neg, t)) in terms.into_iter().enumerate() {
        match unsigned(t).filter(|_| k == 0) {
            Some(u) => out.push((true, node(&u)?)),
            None => out.push((neg, node(t)?)),
        }
    }
    Some(if out.len() == 1 && !out[0].0 {
        out.pop()?.1
    } else {
        Node::Sum(out)
    })
}

fn node(e: &Expr) -> Option<Node> {
    let b = |x: &Expr| node(x).map(Box::new);
    Some(match &e.node {
        expr::Node::Num(n) => {
            let digit_first = n.starts_with(|c: char| c.is_ascii_digit())
                || n.chars().nth(1).is_some_and(|c| c.is_ascii_digit());
            let ok = n.matches('.').count() <= 1 && digit_first;
            ok.then(|| Node::Num(n.clone()))?
        }
        expr::Node::Name(n) => Node::Id(n.clone()),
        expr::Node::Call(f, xs) => {
            Node::Call(f.clone(), xs.iter().map(sum).collect::<Option<_>>()?)
        }
        expr::Node::Paren(x) => Node::Paren(Box::new(sum(x)?)),
        expr::Node::Neg(x) => Node::Neg(b(x)?),
        expr::Node::Sum(_) => sum(e)?,
        expr::Node::Product(fs) => {
            let mut acc = node(&fs[0].1)?;
            for (div, f) in &fs[1..] {
                let (l, r) = (Box::new(acc), b(f)?);
                acc = if *div {
                    Node::Div(l, r)
                } else {
                    Node::Mul(l, r)
                };
            }
            acc
        }
        expr::Node::Pow(x, y) => Node::Pow(b(x)?, b(y)?),
    })
}

const GREEK: [&str; 24] = [
    "alpha", "beta", "gamma", "delta", "epsilon", "zeta", "eta", "theta", "iota", "kappa",
    "lambda", "mu", "nu", "xi", "pi", "rho", "sigma", "tau", "upsilon", "phi", "chi", "psi",
    "omega", "Omega",
];

/// An identifier: `i` as the imaginary unit, Greek names as letters, a trailing number or
/// `_part` as a subscript (`b7` → `b_{7}`), other multi-letter names in italic.
pub fn ident(name: &str) -> String {
    if name == "i" {
        return "\\mathrm{i}".into();
    }
    if name == "QQ" {
        return "\\mathbf{Q}".into();
    }
    if let Some((base, sub)) = name.split_once('_')
        && !base.is_empty()
        && !sub.is_empty()
    {
        return format!("{}_{{{}}}", ident(base), sub.replace('_', ","));
    }
    let digits = name.len() - name.trim_end_matches(|c: char| c.is_ascii_digit()).len();
    if digits > 0 && digits < name.len() {
        let (base, sub) = name.split_at(name.len() - digits);
        return format!("{}_{{{sub}}}", ident(base));
    }
    if GREEK.contains(&name) {
        return format!("\\{name}");
    }
    if name.len() == 1 {
        name.to_string()
    } else {
        format!("\\mathit{{{}}}", name.replace('_', "\\_"))
    }
}

/// A decimal or integer as LaTeX; `1.5e-3` → `1.5 \times 10^{-3}`. Long digit strings get
/// break points every 60 digits inside text, none in math (TeX does not break them).
fn number(n: &str) -> String {
    match n.split_once(['e', 'E']) {
        Some((m, e)) => {
            let e = e.trim_start_matches('+');
            format!("{m} \\times 10^{{{e}}}")
        }
        None => n.to_string(),
    }
}

/// Binding strength for parenthesising: sum 1, product 2, unary minus 3, power 4, atom 5.
fn prec(n: &Node) -> u8 {
    match n {
        Node::Sum(_) => 1,
        Node::Mul(..) => 2,
        Node::Neg(_) => 3,
        Node::Div(..) => 5, // \frac is a closed box
        Node::Pow(..) => 4,
        _ => 5,
    }
}

fn strip(n: &Node) -> &Node {
    match n {
        Node::Paren(x) => strip(x),
        x => x,
    }
}

fn wrap(s: String) -> String {
    format!("\\left({s}\\right)")
}

/// Does the rendering of `n` start with a digit (a product with it needs `\cdot`)?
fn starts_with_digit(n: &Node) -> bool {
    match n {
        Node::Num(_) => true,
        Node::Mul(a, _) | Node::Pow(a, _) => starts_with_digit(a),
        _ => false,
    }
}

/// Does the rendering of `n` end with a radical (`\sqrt{2}\,\mathrm{i}` needs a thin space)?
fn ends_with_sqrt(n: &Node) -> bool {
    match n {
        Node::Call(f, _) => f == "sqrt",
        Node::Mul(_, b) => ends_with_sqrt(b),
        _ => false,
    }
}

/// A multi-letter name typeset in italic (`cr`), which needs a thin space in a product.
fn is_word(n: &Node) -> bool {
    matches!(n, Node::Id(x) if x.len() > 1
        && !GREEK.contains(&x.as_str())
        && !x.chars().any(|c| c.is_ascii_digit() || c == '_'))
}

fn render(n: &Node) -> String {
    match n {
        Node::Num(x) => number(x),
        Node::Id(x) => ident(x),
        Node::Paren(x) => wrap(render(x)),
        Node::Call(f, args) if f == "sqrt" && args.len() == 1 => {
            format!("\\sqrt{{{}}}", render(strip(&args[0])))
        }
        Node::Call(f, args) => {
            let a: Vec<String> = args.iter().map(|x| render(strip(x))).collect();
            let name = match f.as_str() {
                "QQ" => "\\mathbf{Q}".to_string(),
                "exp" | "log" | "sin" | "cos" | "tan" | "ln" => format!("\\{f}"),
                _ => format!("\\operatorname{{{}}}", f.replace('_', "\\_")),
            };
            format!("{name}{}", wrap(a.join(", ")))
        }
        Node::Neg(x) => {
            let s = render(x);
            if prec(x) <= 2 && !matches!(**x, Node::Mul(..)) {
                format!("-{}", wrap(s))
            } else {
                format!("-{s}")
            }
        }
        Node::Sum(ts) => {
            let mut out = String::new();
            for (k, (neg, t)) in ts.iter().enumerate() {
                let s = render(t);
                match (k, neg) {
                    (0, false) => out.push_str(&s),
                    (0, true) => out.push_str(&format!("-{s}")),
                    (_, false) => out.push_str(&format!(" + {s}")),
                    (_, true) => out.push_str(&format!(" - {s}")),
                }
            }
            out
        }
        Node::Mul(a, b) => {
            let ra = if prec(a) < 2 {
                wrap(render(a))
            } else {
                render(a)
            };
            let rb = if prec(b) <= 3 {
                wrap(render(b))
            } else {
                render(b)
            };
            let sep = if starts_with_digit(b) && !matches!(**b, Node::Paren(_)) {
                " \\cdot "
            } else if is_word(a) || is_word(b) || ends_with_sqrt(a) {
                "\\,"
            } else {
                " "
            };
            format!("{ra}{sep}{rb}")
        }
        Node::Div(a, b) => format!("\\frac{{{}}}{{{}}}", render(strip(a)), render(strip(b))),
        Node::Pow(a, e) => {
            let base = if prec(a) < 5 || matches!(**a, Node::Div(..)) {
                wrap(render(strip(a)))
            } else {
                render(a)
            };
            format!("{base}^{{{}}}", render(strip(e)))
        }
    }
}

/// Is the string worth typesetting as math? A lone multi-letter word (`kalman`, `true`) is
/// prose, not a product of letters.
fn mathy(n: &Node) -> bool {
    !matches!(n, Node::Id(x) if x.len() > 1 && !x.chars().any(|c| c.is_ascii_digit()) && !GREEK.contains(&x.as_str()))
}

/// One side of the display grammar: an expression, or `root of P near X`.
fn side(s: &str) -> Option<String> {
    let s = s.trim();
    if let Some(rest) = s.strip_prefix("root of ") {
        let (p, x) = match rest.split_once(" near ") {
            Some((p, x)) => (p, Some(x)),
            None => (rest, None),
        };
        let p = render(&parse(p)?);
        return Some(match x {
            Some(x) => format!(
                "\\text{{root of }} {p} \\text{{ near }} {}",
                render(&parse(x)?)
            ),
            None => format!("\\text{{root of }} {p}"),
        });
    }
    let n = parse(s)?;
    mathy(&n).then(|| render(&n))
}

/// The exact display string `s` as LaTeX math (without delimiters), or `None` for a string
/// outside the display grammar (prose, which the caller typesets as text).
///
/// # Examples
/// ```
/// use exactlti::report::latex::to_math;
/// assert_eq!(to_math("-sqrt(2)/2").unwrap(), "-\\frac{\\sqrt{2}}{2}");
/// assert_eq!(to_math("1/2 + sqrt(5)/2").unwrap(), "\\frac{1}{2} + \\frac{\\sqrt{5}}{2}");
/// assert_eq!(to_math("(1 + sqrt(5))/2").unwrap(), "\\frac{1 + \\sqrt{5}}{2}");
/// assert_eq!(to_math("0 + (b7)*i").unwrap(), "0 + \\left(b_{7}\\right) \\mathrm{i}");
/// assert_eq!(to_math("x^4 + 4*x^2 + 1").unwrap(), "x^{4} + 4 x^{2} + 1");
/// assert!(to_math("the float path disagrees").is_none());
/// assert!(to_math("kalman").is_none());
/// ```
pub fn to_math(s: &str) -> Option<String> {
    if s.len() > MAX_LEN || s.trim().is_empty() {
        return None;
    }
    let parts: Vec<&str> = s.split(" = ").collect();
    if parts.len() > 2 {
        return None;
    }
    let rendered: Option<Vec<String>> = parts.iter().map(|p| side(p)).collect();
    Some(rendered?.join(" = "))
}

#[cfg(test)]
mod tests {
    use super::to_math;

    #[test]
    fn display_strings_become_math() {
        let m = |s: &str| to_math(s).unwrap_or_else(|| panic!("{s}"));
        assert_eq!(m("r7"), "r_{7}");
        assert_eq!(m("sqrt(2)*i"), "\\sqrt{2}\\,\\mathrm{i}");
        assert_eq!(m("-sqrt(3)*i/24"), "-\\frac{\\sqrt{3}\\,\\mathrm{i}}{24}");
        assert_eq!(m("-6 + sqrt(1598)/10"), "-6 + \\frac{\\sqrt{1598}}{10}");
        assert_eq!(m("-cr/(m*u)"), "-\\frac{\\mathit{cr}}{m u}");
        assert_eq!(m("2*b7^3 - 7*b7"), "2 b_{7}^{3} - 7 b_{7}");
        assert_eq!(
            m("(s^2 + 5*s + 7)/(s^2 + 5*s + 6)"),
            "\\frac{s^{2} + 5 s + 7}{s^{2} + 5 s + 6}"
        );
        assert_eq!(
            m("b7 = root of x^4 - 4*x^2 + 1 near 1.9318516526"),
            "b_{7} = \\text{root of } x^{4} - 4 x^{2} + 1 \\text{ near } 1.9318516526"
        );
        assert_eq!(m("1.5e-3"), "1.5 \\times 10^{-3}");
        assert_eq!(m("(-1)^2"), "\\left(-1\\right)^{2}");
        assert_eq!(m("2*3"), "2 \\cdot 3");
        assert_eq!(m("-(a + b)"), "-\\left(a + b\\right)");
        assert_eq!(
            m("QQ(cr, m, u)"),
            "\\mathbf{Q}\\left(\\mathit{cr}, m, u\\right)"
        );
        assert_eq!(m("sigma1"), "\\sigma_{1}");
        assert!(to_math("p = 2 > n/2 = 1").is_none());
        assert!(to_math("a $ b").is_none());
        assert!(to_math("((((").is_none());
        let deep = format!("{}1{}", "(".repeat(1000), ")".repeat(1000));
        assert!(to_math(&deep).is_none(), "depth bounded");
    }
}
