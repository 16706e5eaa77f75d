//! Exact input: system files, MATLAB-style matrices, expressions.

use exactlti::Error;
use exactlti::field::{Rational, parse_rational};
use exactlti::io::{
    ExactScalar, Ground, InputError, MatrixEntries, SystemFile, eval_expr, parse_matlab_matrix,
    parse_system_json, parse_system_toml, read_system_file, split_matlab_matrix,
};
use num_bigint::BigInt;
use proptest::prelude::*;
use std::path::Path;

fn r(n: i64, d: i64) -> Rational {
    Rational::new(n.into(), d.into())
}

fn read(name: &str) -> SystemFile {
    let p = format!("tests/data/{name}");
    read_system_file(Path::new(&p)).unwrap_or_else(|e| panic!("{p}: {e}"))
}

fn show(s: &SystemFile, m: &Option<MatrixEntries>) -> String {
    m.as_ref().expect("matrix present").display(&s.ground)
}

#[test]
fn contract_example() {
    let s = read("yaw_contract.json");
    assert_eq!(s.name.as_deref(), Some("yaw plane, single wheel"));
    assert_eq!(s.path, "tests/data/yaw_contract.json");
    assert_eq!(s.ground, Ground::Rational);
    let a = s.a.as_ref().unwrap();
    assert_eq!(
        a.get(2, 2),
        &ExactScalar::from_rational(r(-8, 3)),
        "-cr/(m*u)"
    );
    assert_eq!(
        show(&s, &s.a),
        "[[0, 20, -1, 0], [0, 0, 0, -1], [0, 0, -8/3, -20], [0, 0, 0, 0]]"
    );
    assert_eq!(show(&s, &s.b), "[[0], [0], [1/1500], [0]]");
    assert_eq!(show(&s, &s.c), "[[1, 0, 0, 0]]");
    assert_eq!(show(&s, &s.d), "[[0]]");
    assert_eq!((s.nstates(), s.ninputs(), s.noutputs()), (4, 1, 1));
    assert_eq!(s.parameter("cr"), Some(&ExactScalar::from_i64(80000)));
    assert!(s.e.is_none() && s.m.is_none() && s.extra.is_empty());
    // the same system in TOML gives the same matrices
    let t = read("yaw_contract.toml");
    assert_eq!((&t.a, &t.b, &t.c, &t.d), (&s.a, &s.b, &s.c, &s.d));
    assert_eq!(t.parameters, s.parameters);
}

#[test]
fn single_track_toml_floats_are_exact() {
    let s = read("yaw_single_track.toml");
    assert_eq!(s.parameter("a"), Some(&ExactScalar::from_rational(r(6, 5))));
    assert_eq!(s.parameter("cr"), Some(&ExactScalar::from_i64(120_000)));
    assert_eq!(show(&s, &s.a), "[[-20/3, -84/5], [48/25, -1056/125]]");
    assert_eq!(show(&s, &s.b), "[[160/3], [192/5]]");
    assert_eq!(
        show(&s, &s.d),
        "[[0]]",
        "missing D is filled in as p x m zeros"
    );
    // strict keys (contract): the signal names key is `outputs`; an `output` key is refused
    assert_eq!(s.extra["outputs"], serde_json::json!(["yaw rate"]));
    assert_eq!(s.signals.outputs, Some(vec!["yaw rate".to_string()]));
    // the same entries by direct rational arithmetic
    let (m, izz, a, b, cf, cr, u) = (
        r(1500, 1),
        r(2500, 1),
        r(6, 5),
        r(8, 5),
        r(80000, 1),
        r(120000, 1),
        r(20, 1),
    );
    let a22 = -(&a * &a * &cf + &b * &b * &cr) / (&izz * &u);
    assert_eq!(s.a.as_ref().unwrap().get(1, 1).to_rational(), Some(a22));
    let a12 = -(&a * &cf - &b * &cr) / (&m * &u) - &u;
    assert_eq!(s.a.as_ref().unwrap().get(0, 1).to_rational(), Some(a12));
}

#[test]
fn exact_numbers() {
    let s = parse_system_json(
        r#"{"A": [[0.08, 1.5e-3, 123456789012345678901234567890, -3E2, "-3/7"]],
            "C": [], "B": []}"#,
        "n.json",
    );
    // A is 1x5: not square
    assert_eq!(
        s.unwrap_err().to_string(),
        "n.json: key A: A must be square, found 1x5"
    );
    let (m, _) =
        parse_matlab_matrix("[0.08 1.5e-3 123456789012345678901234567890 -3E2 -3/7]").unwrap();
    let j = parse_system_json(
        r#"{"parameters": {"x": 0.08, "y": 1.5e-3, "z": 123456789012345678901234567890},
            "A": [["x", "y"], ["z", 0.1]]}"#,
        "n.json",
    )
    .unwrap();
    let t = parse_system_toml(
        "A = [[0.08, 1.5e-3], [123456789012345678901234567890, 0.1]]",
        "n.toml",
    );
    let want = [
        r(2, 25),
        r(3, 2000),
        Rational::from_integer("123456789012345678901234567890".parse::<BigInt>().unwrap()),
    ];
    for (k, w) in want.iter().enumerate() {
        assert_eq!(m.data[k].to_rational().as_ref(), Some(w));
    }
    assert_eq!(m.data[3].to_rational(), Some(r(-300, 1)));
    assert_eq!(m.data[4].to_rational(), Some(r(-3, 7)));
    let a = j.a.unwrap();
    assert_eq!(
        a.data[..3].iter().map(|x| x.a.clone()).collect::<Vec<_>>(),
        want
    );
    assert_eq!(a.data[3].a, r(1, 10));
    // TOML integers beyond i64 are read exactly from their text too
    assert_eq!(t.unwrap().a.as_ref(), Some(&a));
    let t = parse_system_toml(
        "A = [[0.08, 1.5e-3], [\"123456789012345678901234567890\", 0.1]]",
        "n.toml",
    )
    .unwrap();
    assert_eq!(t.a, Some(a));
}

#[test]
fn quadratic_files() {
    let g = read("gaussian.json");
    assert_eq!(g.ground.to_string(), "QQ(i)");
    assert_eq!(show(&g, &g.a), "[[2*i, 1], [0, -2*i]]");
    assert_eq!(show(&g, &g.b), "[[1 + i], [2/5 - i/5]]");
    assert_eq!(show(&g, &g.c), "[[1, 0]]");
    assert_eq!(show(&g, &g.d), "[[0]]");
    assert_eq!(g.ground.radicand(), Some(&BigInt::from(-1)));
    let s = read("sqrt2.toml");
    assert_eq!(s.ground.to_string(), "QQ(sqrt(2))");
    assert_eq!(show(&s, &s.a), "[[0, 1], [-2, -2*sqrt(2)]]");
    assert_eq!(show(&s, &s.b), "[[0], [sqrt(2)/2]]");
    assert_eq!(show(&s, &s.c), "[[1 - sqrt(2)/2, sqrt(2)]]");
    assert_eq!(show(&s, &s.d), "[[1/4]]");
    // a file whose square roots are all rational stays over Q
    let q = parse_system_json(r#"{"A": [["sqrt(9/4)", "sqrt(2)^2"]], "E": []}"#, "q.json");
    assert!(q.is_err(), "1x2 A is not square");
    let q = parse_system_json(r#"{"A": "[sqrt(9/4) sqrt(2)^2; 0 i^2]"}"#, "q.json").unwrap();
    assert_eq!(q.ground, Ground::Rational);
    assert_eq!(show(&q, &q.a), "[[3/2, 2], [0, -1]]");
}

#[test]
fn second_order_and_filled_in_shapes() {
    let s = read("mass_spring.json");
    assert!(s.is_second_order());
    assert_eq!((s.nstates(), s.ninputs(), s.noutputs()), (4, 1, 1));
    assert_eq!(show(&s, &s.l), "[[1/10, -1/10], [-1/10, 1/10]]");
    assert_eq!(show(&s, &s.k), "[[3/2, -3/2], [-3/2, 3/2]]");
    assert_eq!(show(&s, &s.d), "[[0]]");
    assert!(s.a.is_none() && s.b.is_none());
    // no B, no C: n x 0 and 0 x n, D 0 x 0
    let s = parse_system_json(r#"{"A": [[1, 2], [3, 4]]}"#, "x.json").unwrap();
    let dims = |m: &Option<MatrixEntries>| m.as_ref().map(|m| (m.nrows, m.ncols));
    assert_eq!(
        (dims(&s.b), dims(&s.c), dims(&s.d)),
        (Some((2, 0)), Some((0, 2)), Some((0, 0)))
    );
    // D alone fixes the number of inputs and outputs; `[]` takes the shape with a zero side
    let s = parse_system_json(r#"{"A": [[1]], "D": [[5, 6]], "E": [[2]]}"#, "x.json").unwrap();
    assert_eq!((dims(&s.b), dims(&s.c)), (Some((1, 2)), Some((1, 1))));
    assert_eq!(show(&s, &s.e), "[[2]]");
    let s = parse_system_json(r#"{"A": [], "B": [], "C": "[]"}"#, "x.json").unwrap();
    assert_eq!(
        (dims(&s.a), dims(&s.b), dims(&s.c)),
        (Some((0, 0)), Some((0, 0)), Some((0, 0)))
    );
    let s = parse_system_json(r#"{"A": [[0, 1], [0, 0]], "B": [], "C": []}"#, "x.json").unwrap();
    assert_eq!((dims(&s.b), dims(&s.c)), (Some((2, 0)), Some((0, 2))));
    // M alone is a valid second-order system (L, K zero; F has no columns)
    let s = parse_system_toml("M = \"[1 0; 0 1]\"\nK = [[2, 0], [0, 3]]", "x.toml").unwrap();
    assert_eq!(
        (dims(&s.l), dims(&s.f), dims(&s.c)),
        (Some((2, 2)), Some((2, 0)), Some((0, 4)))
    );
}

#[test]
fn invalid_files_give_one_line() {
    let cases = [
        (
            "invalid_ragged.json",
            "key A, row 2: this row has 1 entry but row 1 has 2 entries",
        ),
        (
            "invalid_shape.json",
            "key B: B must have 2 rows (A is 2x2), found 3x1",
        ),
        (
            "invalid_unknown_parameter.json",
            "key A, row 2, column 2: unknown parameter 'cf'",
        ),
        (
            "invalid_bad_number.json",
            "key A, row 2, column 2: '1.2.3' is not a number",
        ),
        (
            "invalid_division_by_zero.json",
            "key A, row 2, column 1: division by zero",
        ),
        (
            "invalid_two_roots.json",
            "key A, row 2, column 2: value lies in QQ(i) but key A, row 1, column 1 lies in \
             QQ(sqrt(2)); all values must lie in one quadratic field",
        ),
        (
            "invalid_cycle.json",
            "key parameters.a: parameters depend on each other in a cycle: a -> b -> c -> a",
        ),
        (
            "invalid_reserved.toml",
            "key parameters.pi: 'pi' is reserved and cannot name a parameter",
        ),
        (
            "invalid_pi.json",
            "key A, row 2, column 1: pi is transcendental; give a rational approximation \
             such as 355/113",
        ),
        (
            "invalid_inf.toml",
            "key A, row 2, column 2: 'inf' is not a number",
        ),
        (
            "invalid_no_system.json",
            "no system: give A (first-order form) or M, L, K, F (second-order form)",
        ),
        (
            "invalid_mixed_forms.json",
            "key M: cannot mix the first-order form (A, B, E) with the second-order form \
             (M, L, K, F)",
        ),
    ];
    for (file, want) in cases {
        let p = format!("tests/data/{file}");
        let e = read_system_file(Path::new(&p)).expect_err(file);
        assert_eq!(e.to_string(), format!("{p}: {want}"));
        let crate_err: exactlti::Error = e.clone().into();
        // the crate error keeps the place and the kind, and says the same line
        assert_eq!(crate_err, exactlti::Error::Input(Box::new(e.clone())));
        assert_eq!(crate_err.to_string(), e.to_string());
        assert_eq!(crate_err.class(), exactlti::error::ErrorClass::Input);
        assert_eq!(crate_err.exit_code(), 2);
    }
    let e = read_system_file(Path::new("tests/data/no_such_file.json")).unwrap_err();
    assert!(
        e.to_string()
            .starts_with("tests/data/no_such_file.json: cannot read the file")
    );
}

#[test]
fn invalid_text_examples() {
    let j = |t: &str| parse_system_json(t, "f.json").unwrap_err().to_string();
    assert_eq!(
        j(r#"{"A": [[1, true]]}"#),
        "f.json: key A, row 1, column 2: expected a number or a string, found a boolean"
    );
    assert_eq!(
        j(r#"{"A": [1, 2]}"#),
        "f.json: key A, row 1: expected a row (an array of entries, e.g. [[1, 2], [3, 4]]), \
         found a number"
    );
    assert_eq!(
        j(r#"{"A": "[1 2; 3]"}"#),
        "f.json: key A, row 2: this row has 1 entry but row 1 has 2 entries"
    );
    assert_eq!(
        j(r#"{"A": "[1 x; 3 4]"}"#),
        "f.json: key A, row 1, column 2: unknown parameter 'x'"
    );
    assert_eq!(
        j(r#"{"a": [[1]]}"#),
        "f.json: key a: matrix keys are upper case: did you mean 'A'?"
    );
    assert_eq!(
        j(r#"{"parameters": {"2x": 1}, "A": [[1]]}"#),
        "f.json: key parameters.2x: '2x' is not a valid parameter name (letters, digits, '_'; \
         not starting with a digit)"
    );
    assert_eq!(
        j(r#"{"parameters": {"s": "sqrt(3)"}, "A": [["i"]]}"#),
        "f.json: key A, row 1, column 1: value lies in QQ(i) but parameter 's' lies in \
         QQ(sqrt(3)); all values must lie in one quadratic field"
    );
    assert_eq!(
        j(r#"{"A": [[0, 1], [1, 0]], "C": [[1, 0, 0]]}"#),
        "f.json: key C: C must have 2 columns (A is 2x2), found 1x3"
    );
    assert_eq!(
        j(r#"{"M": [[1]], "C": [[1]]}"#),
        "f.json: key C: C must have 2 columns (the state [q; q'] has 2 entries), found 1x1"
    );
    assert_eq!(
        j(r#"{"A": [[0]], "B": [[1]], "C": [[1]], "D": [[0, 0]]}"#),
        "f.json: key D: D must be 1x1 (outputs x inputs), found 1x2"
    );
    assert_eq!(
        j("[1, 2]"),
        "f.json: expected a table of keys, found an array"
    );
    assert!(j("{\"A\": [[1]],}").starts_with("f.json: invalid JSON: "));
    let big = format!(r#"{{"A": [["2^{}"]]}}"#, 20000);
    assert!(j(&big).contains("exponent 20000 is too large"));
}

#[test]
fn expressions_over_parameters() {
    let p = vec![
        ("m".to_string(), ExactScalar::from_i64(1500)),
        ("u".to_string(), ExactScalar::from_rational(r(41, 2))),
    ];
    let ev = |t: &str| {
        let (x, g) = eval_expr(t, &p, &Ground::Rational).unwrap();
        g.fmt_scalar(&x)
    };
    assert_eq!(ev("-(2*m - u)/(m*u)"), "-5959/61500");
    assert_eq!(ev("u^-2"), "4/1681");
    assert_eq!(ev("m^0 + 0.5"), "3/2");
    assert_eq!(ev("(1 + sqrt(2))^2"), "3 + 2*sqrt(2)");
    // parameters living in a quadratic field
    let k = exactlti::field::QuadraticField::new(2).unwrap();
    let q = vec![(
        "s".to_string(),
        ExactScalar {
            a: r(0, 1),
            b: r(1, 1),
        },
    )];
    let (x, g) = eval_expr("s*s + s/2", &q, &Ground::Quadratic(k.clone())).unwrap();
    assert_eq!(g, Ground::Quadratic(k.clone()));
    assert_eq!(g.fmt_scalar(&x), "2 + sqrt(2)/2");
    let e = eval_expr("s + i", &q, &Ground::Quadratic(k)).unwrap_err();
    // an invalid expression is the crate error `Invalid` whose message is the text
    assert!(
        matches!(&e, Error::Invalid(m) if m.contains("cannot be mixed")),
        "{e}"
    );
}

#[test]
fn matlab_examples() {
    let pm = |t: &str| {
        let (m, g) = parse_matlab_matrix(t).unwrap_or_else(|e| panic!("{t}: {e}"));
        ((m.nrows, m.ncols), m.display(&g))
    };
    assert_eq!(pm("[0 1; -2 -3]"), ((2, 2), "[[0, 1], [-2, -3]]".into()));
    assert_eq!(
        pm("[1, 2/3; 0.5 -1e-2]"),
        ((2, 2), "[[1, 2/3], [1/2, -1/100]]".into())
    );
    assert_eq!(pm("[]"), ((0, 0), "[]".into()));
    assert_eq!(pm("[1 - 2, 3]"), ((1, 2), "[[-1, 3]]".into()));
    assert_eq!(pm("[1 -2 +3]"), ((1, 3), "[[1, -2, 3]]".into()));
    assert_eq!(pm("[2^-1 (1+2)*3]"), ((1, 2), "[[1/2, 9]]".into()));
    assert_eq!(pm("[1\n2\n3]"), ((3, 1), "[[1], [2], [3]]".into()));
    assert_eq!(
        pm("[1 sqrt(2); -sqrt(2) 1]").1,
        "[[1, sqrt(2)], [-sqrt(2), 1]]"
    );
    assert_eq!(
        split_matlab_matrix("[1 2; 3]").unwrap_err().to_string(),
        "row 2, this row has 1 entry but row 1 has 2 entries"
    );
    let e = parse_matlab_matrix("[1 i; sqrt(2) 0]").unwrap_err();
    let Error::MatrixText { row, col, .. } = e else {
        panic!("a matrix text error, got {e:?}")
    };
    assert_eq!((row, col), (Some(2), Some(1)));
    let e = parse_matlab_matrix("[1 1/0]").unwrap_err();
    assert_eq!(e.to_string(), "row 1, column 2, division by zero");
}

// ---- properties ----

/// A random rational expression and its value by direct arithmetic (`None`: undefined).
#[derive(Clone, Debug)]
enum Ex {
    Int(i64),
    Frac(i64, i64),
    Dec(i64, u32),
    Param(usize),
    Neg(Box<Ex>),
    Bin(char, Box<Ex>, Box<Ex>),
    Pow(Box<Ex>, i32),
}

const PARAMS: [(&str, &str); 3] = [("p0", "3/7"), ("p1", "-0.125"), ("p_2", "1e3")];

fn param_values() -> Vec<(String, ExactScalar)> {
    PARAMS
        .iter()
        .map(|(n, v)| {
            (
                n.to_string(),
                ExactScalar::from_rational(parse_rational(v).unwrap()),
            )
        })
        .collect()
}

impl Ex {
    fn value(&self, ps: &[(String, ExactScalar)]) -> Option<Rational> {
        use num_traits::Zero;
        Some(match self {
            Ex::Int(n) => r(*n, 1),
            Ex::Frac(n, d) => r(*n, *d),
            Ex::Dec(m, s) => Rational::new((*m).into(), BigInt::from(10).pow(*s)),
            Ex::Param(k) => ps[*k].1.a.clone(),
            Ex::Neg(x) => -x.value(ps)?,
            Ex::Bin(op, x, y) => {
                let (x, y) = (x.value(ps)?, y.value(ps)?);
                match op {
                    '+' => x + y,
                    '-' => x - y,
                    '*' => x * y,
                    _ if y.is_zero() => return None,
                    _ => x / y,
                }
            }
            Ex::Pow(x, e) => {
                let x = x.value(ps)?;
                if x.is_zero() && *e < 0 {
                    return None;
                }
                num_traits::pow::Pow::pow(x, *e)
            }
        })
    }
    fn text(&self) -> String {
        match self {
            Ex::Int(n) => format!("({n})"),
            Ex::Frac(n, d) => format!("({n}/{d})"),
            Ex::Dec(m, s) => {
                let digits = format!("{:0>width$}", m.unsigned_abs(), width = *s as usize + 1);
                let (ip, fp) = digits.split_at(digits.len() - *s as usize);
                let sign = if *m < 0 { "-" } else { "" };
                format!("({sign}{ip}.{fp})")
            }
            Ex::Param(k) => PARAMS[*k].0.to_string(),
            Ex::Neg(x) => format!("-{}", x.text()),
            Ex::Bin(op, x, y) => format!("({} {op} {})", x.text(), y.text()),
            Ex::Pow(x, e) => format!("({})^({e})", x.text()),
        }
    }
}

fn ex_strategy() -> impl Strategy<Value = Ex> {
    let leaf = prop_oneof![
        (-30i64..30).prop_map(Ex::Int),
        (-30i64..30, 1i64..12).prop_map(|(n, d)| Ex::Frac(n, d)),
        (-5000i64..5000, 0u32..4).prop_map(|(m, s)| Ex::Dec(m, s)),
        (0usize..PARAMS.len()).prop_map(Ex::Param),
    ];
    leaf.prop_recursive(5, 40, 2, |inner| {
        prop_oneof![
            inner.clone().prop_map(|x| Ex::Neg(Box::new(x))),
            (
                prop::sample::select(vec!['+', '-', '*', '/']),
                inner.clone(),
                inner.clone()
            )
                .prop_map(|(op, x, y)| Ex::Bin(op, Box::new(x), Box::new(y))),
            (inner, -3i32..4).prop_map(|(x, e)| Ex::Pow(Box::new(x), e)),
        ]
    })
}

fn noise_strategy() -> impl Strategy<Value = String> {
    let piece = prop::sample::select(vec![
        "sqrt(", "(", ")", "^", "-", "+", "*", "/", "i", "2", "10", "9999", "0", "0.5", "1e9",
        "p0", "pi", " ", ";", ",", "[", "]", "\n", "e", ".", "1/3", "x", "^-",
    ]);
    prop::collection::vec(piece, 0..40).prop_map(|v| v.concat())
}

/// 256 cases, scaled by `EXACTLTI_TEST_MULTIPLIER` (STYLE.md 7.5).
fn cases() -> u32 {
    let k = std::env::var("EXACTLTI_TEST_MULTIPLIER")
        .ok()
        .and_then(|v| v.parse::<u32>().ok())
        .unwrap_or(1);
    256 * k.max(1)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(), ..ProptestConfig::default() })]

    #[test]
    fn random_valid_expressions_match_rational_arithmetic(x in ex_strategy()) {
        let ps = param_values();
        let text = x.text();
        let got = eval_expr(&text, &ps, &Ground::Rational);
        match x.value(&ps) {
            Some(v) => {
                let (s, g) = got.unwrap_or_else(|e| panic!("{text}: {e}"));
                prop_assert_eq!(g, Ground::Rational);
                prop_assert_eq!(s, ExactScalar::from_rational(v), "{}", text);
            }
            None => {
                let e = got.expect_err(&text);
                prop_assert!(matches!(&e, Error::Invalid(m) if m.starts_with("division by zero")), "{}: {}", text, e);
            }
        }
    }

    #[test]
    fn random_text_never_panics(t in noise_strategy(), raw in "[ -~]{0,40}") {
        let ps = param_values();
        for s in [&t, &raw] {
            let _ = eval_expr(s, &ps, &Ground::Rational);
            let _ = parse_matlab_matrix(s);
            let _ = parse_system_json(&format!("{{\"A\": \"{}\"}}", s.replace(['"', '\\'], "")), "f");
            let _ = parse_system_toml(s, "f");
        }
    }

    #[test]
    fn matrix_text_round_trips(rows in prop::collection::vec(
        prop::collection::vec((-50i64..50, 1i64..9), 3), 0..4)) {
        // any rational matrix written MATLAB-style reads back exactly, JSON and TOML alike
        let text = format!("[{}]", rows.iter().map(|row| {
            row.iter().map(|(n, d)| format!("{n}/{d}")).collect::<Vec<_>>().join(" ")
        }).collect::<Vec<_>>().join("; "));
        let (m, g) = parse_matlab_matrix(&text).unwrap();
        prop_assert_eq!(g, Ground::Rational);
        prop_assert_eq!(m.nrows, rows.len());
        for (i, row) in rows.iter().enumerate() {
            for (j, (n, d)) in row.iter().enumerate() {
                prop_assert_eq!(m.get(i, j).to_rational(), Some(r(*n, *d)));
            }
        }
        let json_rows: Vec<Vec<String>> = rows.iter()
            .map(|row| row.iter().map(|(n, d)| format!("{n}/{d}")).collect()).collect();
        let n = rows.len();
        let a = serde_json::json!({ "A": vec![vec![0; n]; n], "C": json_rows });
        if n == 3 || n == 0 {
            let s = parse_system_json(&a.to_string(), "p.json").unwrap();
            prop_assert_eq!(s.c.unwrap().data, m.data.clone());
        }
    }
}

#[test]
fn input_error_display() {
    let e = InputError::entry("yaw.json", "A", 2, 3, "unknown parameter 'cf'");
    assert_eq!(
        e.to_string(),
        "yaw.json: key A, row 2, column 3: unknown parameter 'cf'"
    );
    let e = InputError::file("yaw.json", "line one\nline two");
    assert_eq!(e.to_string(), "yaw.json: line one line two");
}
