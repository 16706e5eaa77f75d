//! The free response from an initial state (`exactlti response FILE --x0 ...`,
//! [`exactlti::jordan::StateResponse`]) and the modes ranked by contribution with their
//! truncation (`exactlti contributions FILE --keep K`, [`exactlti::realization::contribution`]).

use crate::common::cli::{run, temp_file};
use crate::response_modal::random_system;
use exactlti::field::{Field, Q, Rational};
use exactlti::float::modal::dense_transition;
use exactlti::float::to_dmatrix;
use exactlti::jordan::jordan;
use exactlti::matrix::Matrix;
use exactlti::ratfunc::RatFuncField;
use exactlti::realization::contribution::{Weight, contributions};
use exactlti::realization::lyapunov;
use exactlti::rng::SplitMix64;
use exactlti::system::StateSpace;
use serde_json::Value;

fn q(n: i64) -> Rational {
    Rational::from_integer(n.into())
}

#[test]
fn the_closed_form_solves_x_dot_equals_a_x_from_x0() {
    let mut rng = SplitMix64(25_036);
    for case in 0..25 {
        let n = 2 + case % 6;
        let (a, _, _) = random_system(&mut rng, n);
        let x0 = Matrix::from_fn(Q, n, 1, |_, _| q(rng.int(-3, 3)));
        let jf = jordan(&a).unwrap();
        let sr = jf.free_response().from_state(&x0);
        // exact: A g_k = s g_k + (k+1) g_(k+1) per component, sum of traces of g_0 = x0
        assert!(sr.verify(&jf, &x0), "case {case}");
        // a wrong initial state or a changed coefficient is caught
        let mut other = x0.clone();
        other.set(0, 0, &x0.get(0, 0).clone() + q(1));
        assert!(!sr.verify(&jf, &other), "case {case}: x(0) check");
        let mut bad = sr.clone();
        let (_, _, g) = &mut bad.terms[0];
        let e = g.field().clone();
        let v = e.add(g.get(0, 0), &e.one());
        g.set(0, 0, v);
        assert!(!bad.verify(&jf, &x0), "case {case}: derivative check");
        // the float value of the closed form is e^(At) x0
        let t = 0.7;
        let phi = dense_transition(&to_dmatrix(&a).unwrap(), t).unwrap();
        let x = sr.evaluate(&jf, t);
        let want: Vec<f64> = (0..n)
            .map(|r| {
                (0..n)
                    .map(|c| phi[(r, c)] * exactlti::field::rational_to_f64(x0.get(c, 0)))
                    .sum()
            })
            .collect();
        let scale = want.iter().fold(1.0f64, |m, w| m.max(w.abs()));
        for (xr, w) in x.iter().zip(&want) {
            assert!((xr - w).abs() < 1e-8 * scale, "case {case}: {xr} vs {w}");
        }
    }
}

fn json(args: &[&str]) -> Value {
    crate::common::cli::json_of(args)
}

#[test]
fn response_on_the_command_line_over_q() {
    // x'' + 3 x' + 2 x = 0 (poles -1, -2) and a double pole at -1
    let f = temp_file(
        "response_free",
        "two.json",
        r#"{"A": [[0, 1], [-2, -3]], "B": [[0], [1]], "C": [[1, 0]], "D": [[0]]}"#,
    );
    let p = f.to_str().unwrap();
    let r = json(&[
        "response", p, "--x0", "1, 0.5", "--times", "0,1", "--format", "json",
    ]);
    assert_eq!(r["verified"], true);
    assert_eq!(r["terms"].as_array().unwrap().len(), 2);
    // x(t) = (5/2 e^-t - 3/2 e^-2t, -5/2 e^-t + 3 e^-2t): x(0) = (1, 1/2)
    let v0 = &r["values"][0]["x"];
    assert!((v0[0].as_f64().unwrap() - 1.0).abs() < 1e-14);
    assert!((v0[1].as_f64().unwrap() - 0.5).abs() < 1e-14);
    let t1 = r["values"][1]["x"][0].as_f64().unwrap();
    assert!((t1 - (2.5 * (-1f64).exp() - 1.5 * (-2f64).exp())).abs() < 1e-12);
    // wrong number of entries, a bad number: exit 2 with one line
    let (code, _, err) = run(&["response", p, "--x0", "1"]);
    assert_eq!(code, 2);
    assert!(err.contains("--x0 needs 2"), "{err}");
    assert_eq!(err.trim().lines().count(), 1);
    let (code, _, err) = run(&["response", p, "--x0", "1,2#"]);
    assert_eq!(code, 2, "{err}");
    let (code, _, _) = run(&["response", p, "--x0", "1,2", "--times", "nan"]);
    assert_eq!(code, 2);
}

#[test]
fn yaw_plane_response_in_symbols_shows_the_eq36_sign_slip() {
    // x0 of eq. 37 at t = 0, with the file's m, u, cr as symbols
    let r = json(&[
        "response",
        "data/yaw-plane-single-wheel.json",
        "--symbolic",
        "--x0",
        "y0 + v0*m*u/cr, psi0, v0 - r0*m*u^2/cr, r0",
        "--format",
        "json",
    ]);
    assert_eq!(r["verified"], true, "{r}");
    let field = r["field"].as_str().unwrap();
    let vars: Vec<&str> = field[field.find('(').unwrap() + 1..]
        .trim_end_matches(')')
        .split(',')
        .map(str::trim)
        .collect();
    let k = RatFuncField::new(&vars).unwrap();
    let p = |s: &str| k.parse(s).unwrap();
    let term = |ev: &str, power: u64| {
        r["terms"]
            .as_array()
            .unwrap()
            .iter()
            .find(|t| {
                k.parse(t["eigenvalue"].as_str().unwrap()).unwrap() == p(ev) && t["power"] == power
            })
            .unwrap_or_else(|| panic!("term {ev} t^{power}"))["g"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| k.parse(x.as_str().unwrap()).unwrap())
            .collect::<Vec<_>>()
    };
    // eq. 37a: y(t) = y0 + (psi0 + r0 m u/cr) u t - r0 u t^2/2 + (v0 m u/cr) e^(st)
    assert_eq!(term("0", 0)[0], p("y0"));
    assert_eq!(term("0", 1)[0], p("(psi0 + r0*m*u/cr)*u"));
    // eq. 36 prints +r0 u/2 for this t^2 coefficient: a sign slip
    assert_eq!(term("0", 2)[0], p("-r0*u/2"));
    assert_ne!(term("0", 2)[0], p("r0*u/2"));
    assert_eq!(term("-cr/(m*u)", 0)[0], p("v0*m*u/cr"));
    // --times needs numbers
    let (code, _, err) = run(&[
        "response",
        "data/yaw-plane-single-wheel.json",
        "--symbolic",
        "--x0",
        "1,0,0,0",
        "--times",
        "1",
    ]);
    assert_eq!(code, 2, "{err}");
}

#[test]
fn contributions_rank_by_exact_h2_and_truncate_with_exact_error() {
    // G = 1/(s+1) + (1/10)/(s+2) + 0 (mode -3 not observed)
    let f = temp_file(
        "response_free",
        "diag.json",
        r#"{"A": [[-1, 0, 0], [0, -2, 0], [0, 0, -3]], "B": [[1], [1], [0]],
            "C": [[1, 0.1, 1]], "D": [[0]]}"#,
    );
    let p = f.to_str().unwrap();
    let r = json(&["contributions", p, "--keep", "1", "--format", "json"]);
    assert_eq!(r["verified"], true);
    let modes = r["modes"].as_array().unwrap();
    let ev: Vec<&str> = modes
        .iter()
        .map(|m| m["eigenvalues"][0].as_str().unwrap())
        .collect();
    assert_eq!(ev, ["-1", "-2", "-3"]);
    // r^2 / (2 a) for r/(s + a)
    let h2: Vec<&str> = modes
        .iter()
        .map(|m| m["h2_squared"].as_str().unwrap())
        .collect();
    assert_eq!(h2, ["1/2", "1/400", "0"]);
    let t = &r["truncation"];
    assert_eq!(t["order"], 1);
    assert_eq!(t["error_h2_squared"], "1/400");
    assert_eq!(t["error_dc_gain"][0][0], "1/20");
    assert_eq!(t["error_markov0"][0][0], "1/10");
}

/// $C A^k B$ for $k < 2n$.
fn markov(s: &StateSpace<Q>, count: usize) -> Vec<Matrix<Q>> {
    let mut out = vec![];
    let mut akb = s.b.clone();
    for _ in 0..count {
        out.push(&s.c * &akb);
        akb = &s.a * &akb;
    }
    out
}

#[test]
fn truncation_properties_on_random_stable_systems() {
    let mut rng = SplitMix64(33_027);
    for case in 0..12 {
        let n = 2 + case % 5;
        let (a, b, c) = random_system(&mut rng, n);
        let d = Matrix::zeros(Q, 2, 2);
        let ss = StateSpace::new(a, b, c, d).unwrap();
        let cs = contributions(&ss).unwrap();
        assert!(cs.verified, "case {case}");
        // heaviest first
        for w in cs.modes.windows(2) {
            if let (Weight::H2Squared(x), Weight::H2Squared(y)) = (&w[0].weight, &w[1].weight) {
                assert!(x >= y, "case {case}");
            }
        }
        let all = cs.truncate(cs.modes.len()).unwrap();
        assert_eq!(all.error_h2_squared, Some(Rational::from_integer(0.into())));
        assert_eq!(
            markov(&all.system, 2 * n),
            markov(&ss, 2 * n),
            "case {case}"
        );
        // keeping nothing: the error is the whole system, its H2^2 by one Lyapunov solve
        let none = cs.truncate(0).unwrap();
        let bbt = &ss.b * &ss.b.transpose();
        let w = lyapunov(&ss.a, &bbt).unwrap();
        let cwc = &(&ss.c * &w) * &ss.c.transpose();
        let h2 = (0..2).fold(Rational::from_integer(0.into()), |s, i| s + cwc.get(i, i));
        assert_eq!(none.error_h2_squared, Some(h2), "case {case}");
        // truncated + dropped = full, for every K (Markov parameters)
        for keep in 0..=cs.modes.len() {
            let t = cs.truncate(keep).unwrap();
            assert!(t.verified);
            let kept = markov(&t.system, 2 * n);
            let first = &kept[0] + &t.error_markov0;
            assert_eq!(first, markov(&ss, 1)[0], "case {case} keep {keep}");
        }
    }
}
