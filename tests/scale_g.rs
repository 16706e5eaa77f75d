//! Key `G` with symbols (issue 25, item 2): a transfer matrix in `s` whose coefficients are
//! rational functions of `null` parameters is realized over Q(p):
//! - at random rational parameter values and a random s0, C (s0 I - A)^-1 B + D of the
//!   realization equals G(s0) read by the rational reader with those values (an independent
//!   parser);
//! - the order is the McMillan degree (minimal), for a generator of random 1 x 2 and 2 x 1
//!   transfer matrices with planted common poles;
//! - bad files: an unknown name in an entry (key G, row and column named), `G` beside `A`, a
//!   parameter named `s`, an improper `G`: each an input error naming the key.

use crate::qp_scale::at;
use exactlti::field::{Field, Q, Rational};
use exactlti::io::symbolic::{SymbolicOptions, load_symbolic_str};
use exactlti::io::transfer_expr::parse_rational_function;
use exactlti::io::{SystemFormat, TypedAny};
use exactlti::matrix::Matrix;
use exactlti::rng::SplitMix64;
use exactlti::system::StateSpace;

fn load(text: &str) -> Result<StateSpace<exactlti::ratfunc::RatFuncField>, String> {
    let l = load_symbolic_str(
        text,
        SystemFormat::Json,
        "g.json",
        &SymbolicOptions::default(),
    )
    .map_err(|e| e.to_string())?;
    match l.system {
        TypedAny::RatFunc(t) => Ok(t.ss),
        _ => Err("not over Q(p)".into()),
    }
}

fn file(params: &[&str], rows: &[Vec<String>]) -> String {
    let ps: Vec<String> = params.iter().map(|p| format!("\"{p}\": null")).collect();
    let rs: Vec<String> = rows
        .iter()
        .map(|r| {
            let es: Vec<String> = r.iter().map(|e| format!("\"{e}\"")).collect();
            format!("[{}]", es.join(", "))
        })
        .collect();
    format!(
        "{{\"parameters\": {{{}}}, \"G\": [{}]}}",
        ps.join(", "),
        rs.join(", ")
    )
}

/// C (s0 I - A)^-1 B + D of `s` at the parameter values `x` against the entries' text read
/// over Q with those values.
fn check_at(
    s: &StateSpace<exactlti::ratfunc::RatFuncField>,
    rows: &[Vec<String>],
    rng: &mut SplitMix64,
) {
    let k = s.a.field().clone();
    let names = k.vars().to_vec();
    for _ in 0..3 {
        let x: Vec<Rational> = (0..names.len())
            .map(|_| Rational::new(rng.int(1, 20).into(), rng.int(1, 5).into()))
            .collect();
        let s0 = Rational::new(rng.int(30, 90).into(), 7.into());
        let (a, b, c, d) = (at(&s.a, &x), at(&s.b, &x), at(&s.c, &x), at(&s.d, &x));
        let n = a.nrows();
        let si_a = &Matrix::identity(Q, n).scale(&s0) - &a;
        let g = &(&(&c * &si_a.inverse().unwrap()) * &b) + &d;
        let values: Vec<(String, Rational)> = names.iter().cloned().zip(x.clone()).collect();
        for (i, row) in rows.iter().enumerate() {
            for (j, text) in row.iter().enumerate() {
                let f = parse_rational_function(text, &values).unwrap();
                let want = Q
                    .div(&f.num.eval(&s0), &f.den.eval(&s0))
                    .expect("no pole at s0");
                assert_eq!(
                    g.get(i, j),
                    &want,
                    "G[{i}][{j}] = {text} at {x:?}, s0 = {s0}"
                );
            }
        }
    }
}

#[test]
fn mass_spring_damper_g_is_realized_over_qp() {
    let d = "m*s^2 + c*s + k";
    let rows = vec![
        vec![format!("1/({d})"), "1/(m*s + c)".to_string()],
        vec![format!("s/({d})"), "0".to_string()],
    ];
    let s = load(&file(&["m", "c", "k"], &rows)).unwrap();
    // McMillan degree: 2 (the column of 1/d, s/d) + 1 (1/(m s + c))
    assert_eq!(s.nstates(), 3);
    check_at(&s, &rows, &mut SplitMix64(7));
}

#[test]
fn random_g_with_planted_poles_is_minimal() {
    let mut rng = SplitMix64(2525);
    let sym = ["a", "b"];
    for case in 0..6 {
        // entries n_j / (q1 q2^e): q1 = s + a, q2 = s^2 + b s + c0, shared by the row
        let c0 = rng.int(1, 9);
        let q2 = format!("(s^2 + b*s + {c0})");
        let e = 1 + case % 2;
        let den = if e == 1 {
            format!("(s + a)*{q2}")
        } else {
            format!("(s + a)*{q2}^2")
        };
        let num = |rng: &mut SplitMix64| format!("{}*s + {}*a", rng.int(1, 5), rng.int(-4, 4));
        let rows: Vec<Vec<String>> = if case < 3 {
            vec![vec![
                format!("({})/({den})", num(&mut rng)),
                format!("({})/({den})", num(&mut rng)),
            ]]
        } else {
            vec![
                vec![format!("({})/({den})", num(&mut rng))],
                vec![format!("({})/({den})", num(&mut rng))],
            ]
        };
        let s = load(&file(&sym, &rows)).unwrap();
        check_at(&s, &rows, &mut rng);
        // a 1 x 2 or 2 x 1 G: the order is at most that of one column's (row's) common
        // denominator, 1 + 2e, times the number of columns; at least the denominator degree
        assert!(
            (1 + 2 * e..=2 * (1 + 2 * e)).contains(&s.nstates()),
            "case {case}"
        );
        // minimal: controllable and observable (full-rank Kalman matrices at a point)
        let x = [
            Rational::from_integer(3.into()),
            Rational::from_integer(5.into()),
        ];
        let (a, b, c) = (at(&s.a, &x), at(&s.b, &x), at(&s.c, &x));
        let sq = StateSpace::new(a, b, c, at(&s.d, &x)).unwrap();
        let n = sq.nstates();
        assert_eq!(
            exactlti::realization::controllability_matrix(&sq.a, &sq.b).rank(),
            n
        );
        assert_eq!(
            exactlti::realization::controllability_matrix(&sq.a.transpose(), &sq.c.transpose())
                .rank(),
            n
        );
    }
}

#[test]
fn bad_g_files_name_the_key() {
    let unknown = file(&["m"], &[vec!["1/(m*s + q)".into()]]);
    let e = load(&unknown).unwrap_err();
    assert!(e.contains("G") && e.contains("row 1, column 1"), "{e}");
    let beside = r#"{"parameters": {"m": null}, "A": [[1]], "G": [["1/(m*s + 1)"]]}"#;
    let e = load(beside).unwrap_err();
    assert!(e.contains("key A") || e.contains("A:"), "{e}");
    let s_param = r#"{"parameters": {"s": null}, "G": [["1/(s + 1)"]]}"#;
    assert!(load(s_param).is_err());
    let improper = file(&["m"], &[vec!["m*s^2 + 1".into()]]);
    let e = load(&improper).unwrap_err();
    assert!(e.contains("improper"), "{e}");
}
