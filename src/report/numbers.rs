//! One display per number: the eigenvalues, zeros and modes of a report written the same way
//! in every place.
//!
//! The sections of a report come from different modules, which write the same algebraic
//! number in different closed forms (`root of x^4 + 4*x^2 + 1 near 1.93*i` beside
//! `i*sqrt(2 + sqrt(3))`). [`unify`] rewrites every number given with its `minpoly` and
//! `approx` in one display (the Jordan form's: closed forms for degree 1, 2 and the
//! biquadratic case, else `root of ... near ...`), and every string or matrix entry equal to
//! one of its old displays.

use super::{Report, Value};
use std::collections::HashMap;

/// The canonical display of the root of the irreducible `minpoly` nearest `approx`
/// (`None` when `minpoly` does not parse).
pub fn canonical(minpoly: &str, approx: (f64, f64)) -> Option<String> {
    let p = crate::poly::parse_poly_q(minpoly).ok()?;
    if p.deg() < 1 {
        return None;
    }
    Some(crate::report::display::value_display(&p, approx))
}

/// `value` with every display of a number rewritten in its canonical display.
pub fn unify(v: Value) -> Value {
    let mut map = HashMap::new();
    collect(&v, &mut map);
    map.retain(|old, new| old != new);
    if map.is_empty() { v } else { rewrite(v, &map) }
}

fn approx_of(v: Option<&Value>) -> Option<(f64, f64)> {
    match v? {
        Value::List(xs) => match xs.as_slice() {
            [Value::Float(a), Value::Float(b)] => Some((*a, *b)),
            [Value::Float(a)] => Some((*a, 0.0)),
            _ => None,
        },
        Value::Float(a) => Some((*a, 0.0)),
        _ => None,
    }
}

fn collect_report(r: &Report, map: &mut HashMap<String, String>) {
    if let (Some(Value::Str(mp)), Some(z)) = (r.get("minpoly"), approx_of(r.get("approx"))) {
        for key in ["value", "eigenvalue"] {
            if let Some(Value::Str(old)) = r.get(key)
                && let Some(new) = canonical(mp, z)
            {
                map.insert(old.clone(), new);
            }
        }
    }
    for (_, v) in &r.items {
        collect(v, map);
    }
}

fn collect(v: &Value, map: &mut HashMap<String, String>) {
    match v {
        Value::Obj(r) => collect_report(r, map),
        Value::List(xs) => xs.iter().for_each(|x| collect(x, map)),
        Value::Alt(a) => collect(&a.data, map),
        _ => {}
    }
}

fn rewrite(v: Value, map: &HashMap<String, String>) -> Value {
    match v {
        Value::Str(s) => Value::Str(map.get(&s).cloned().unwrap_or(s)),
        Value::List(xs) => Value::List(xs.into_iter().map(|x| rewrite(x, map)).collect()),
        Value::Obj(r) => Value::Obj(Report {
            title: r.title,
            items: r
                .items
                .into_iter()
                .map(|(k, v)| (k, rewrite(v, map)))
                .collect(),
        }),
        Value::Matrix(mut m) => {
            for row in m.exact.iter_mut().chain(m.latex.iter_mut()) {
                for x in row.iter_mut() {
                    if let Some(n) = map.get(x.as_str()) {
                        *x = n.clone();
                    }
                }
            }
            Value::Matrix(m)
        }
        Value::Alt(mut a) => {
            a.data = rewrite(a.data, map);
            if let super::AltText::Table { rows, .. } = &mut a.text {
                for x in rows.iter_mut().flatten() {
                    if let Some(n) = map.get(x.as_str()) {
                        *x = n.clone();
                    }
                }
            }
            Value::Alt(a)
        }
        other => other,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_display_per_number() {
        let z = (0.0, 1.9318516525781366);
        let item = |key: &str, shown: &str| {
            Value::Obj(
                Report::new()
                    .str("minpoly", "x^4 + 4*x^2 + 1")
                    .str(key, shown)
                    .list("approx", vec![Value::Float(z.0), Value::Float(z.1)]),
            )
        };
        let sec = Value::Obj(
            Report::titled("s")
                .list(
                    "zeros",
                    vec![item("value", "root of x^4 + 4*x^2 + 1 near 1.931851653*i")],
                )
                .list(
                    "modes",
                    vec![item(
                        "eigenvalue",
                        "root of x^4 + 4*x^2 + 1 near 1.931851653*i",
                    )],
                )
                .str("other", "root of x^4 + 4*x^2 + 1 near 1.931851653*i"),
        );
        let Value::Obj(r) = unify(sec) else {
            unreachable!()
        };
        let want = canonical("x^4 + 4*x^2 + 1", z).unwrap();
        assert_eq!(want, "i*sqrt(2 + sqrt(3))");
        assert_eq!(r.get("other"), Some(&Value::Str(want.clone())));
        let text = r.to_text();
        assert_eq!(text.matches(&want).count(), 3, "{text}");
        assert!(!text.contains("root of"));
    }
}
