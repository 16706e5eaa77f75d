//! Issue 17 item 2 for the commands other than Jordan: `tf` exact over Q(i) and Q(sqrt d),
//! and the complex float path (`freqresp`, `check`, `minreal --method era`) over Q(i).
use crate::common::cli::{self, run};
use crate::common::{quadratic as q, quadratic_matrix as mat};
use exactlti::algebraic::{factor_over_quadratic, norm_over_q};
use exactlti::field::{Field, QuadraticField};
use exactlti::float::{Tol, Truth, era_system, freqresp, markov_parameters, to_cmatrix};
use exactlti::matrix::Matrix;
use exactlti::poly::Poly;
use exactlti::realization::realize_transfer;
use exactlti::system::StateSpace;
use num_complex::Complex;

fn temp_file(name: &str, text: &str) -> std::path::PathBuf {
    cli::temp_file("fields-float", name, text)
}

fn json(args: &[&str]) -> (i32, serde_json::Value, String) {
    let mut a = args.to_vec();
    a.extend(["--format", "json"]);
    let (code, out, err) = run(&a);
    let j = serde_json::from_str(&out).unwrap_or(serde_json::Value::Null);
    (code, j, err)
}

/// A 3-state SISO system over Q(i) with McMillan degree 2: the mode 2i is unobservable.
fn gaussian_system() -> StateSpace<QuadraticField> {
    let k = QuadraticField::gaussian();
    let a = mat(
        &k,
        &[
            &[(-1, 1), (1, 0), (0, 0)],
            &[(0, 0), (-2, 0), (0, 0)],
            &[(0, 0), (0, 0), (0, 2)],
        ],
    );
    let b = mat(&k, &[&[(0, 0)], &[(1, 0)], &[(1, 1)]]);
    let c = mat(&k, &[&[(1, 0), (0, 1), (0, 0)]]);
    let d = mat(&k, &[&[(0, 0)]]);
    StateSpace::new(a, b, c, d).unwrap()
}

#[test]
fn factorization_over_quadratic_fields_multiplies_back() {
    let k = QuadraticField::gaussian();
    let lin = |a: i64, b: i64| Poly::new(k.clone(), vec![k.neg(&q(a, b)), k.one()]);
    // (s - i)^2 (s^2 + 2) (s + 1 + i), times 3: s^2 + 2 has roots +-i sqrt 2, not in Q(i)
    let s2 = Poly::new(k.clone(), vec![q(2, 0), q(0, 0), q(1, 0)]);
    let p = lin(0, 1)
        .mul(&lin(0, 1))
        .mul(&s2)
        .mul(&lin(-1, -1))
        .scale(&q(3, 0));
    let fs = factor_over_quadratic(&p).unwrap();
    let mut shape: Vec<(usize, usize)> = fs.iter().map(|(f, e)| (f.deg(), *e)).collect();
    shape.sort();
    assert_eq!(shape, [(1, 1), (1, 2), (2, 1)]);
    let mut prod = Poly::new(k.clone(), vec![p.lc()]);
    for (f, e) in &fs {
        assert!(k.is_one(&f.lc()));
        for _ in 0..*e {
            prod = prod.mul(f);
        }
    }
    assert_eq!(prod, p);
    // s^2 - 2 splits over Q(sqrt 2), not over Q(sqrt 3); the norm of s - sqrt 2 is s^2 - 2
    for (d, parts) in [(2, 2), (3, 1)] {
        let kd = QuadraticField::new(d).unwrap();
        let p = Poly::new(kd.clone(), vec![q(-2, 0), q(0, 0), q(1, 0)]);
        assert_eq!(factor_over_quadratic(&p).unwrap().len(), parts, "d = {d}");
    }
    let k2 = QuadraticField::new(2).unwrap();
    let f = Poly::new(k2.clone(), vec![q(0, -1), q(1, 0)]);
    assert_eq!(norm_over_q(&f).to_string(), "x^2 - 2");
}

#[test]
fn transfer_matrix_over_gaussian_rationals_has_the_markov_parameters_and_degree() {
    let s = gaussian_system();
    let g = s.transfer_matrix().unwrap();
    assert!(g.matches_markov(&s));
    let r = realize_transfer(&g).unwrap();
    assert!(r.verified);
    assert_eq!(r.mcmillan_degree, 2);
    let m = r.state_space.as_ref().expect("proper");
    // the pole polynomial (charpoly of a minimal realization) is the SISO denominator
    assert_eq!(m.a.charpoly().unwrap(), g.entries[0][0].den);
    assert!(g.matches_markov(m));
    // a transfer matrix one coefficient off is not the system's
    let mut wrong = g.clone();
    let k = QuadraticField::gaussian();
    let n = &wrong.entries[0][0].num;
    wrong.entries[0][0].num = n.add(&Poly::new(k.clone(), vec![q(0, 1)]));
    assert!(!wrong.matches_markov(&s));
}

#[test]
fn tf_command_over_gaussian_rationals() {
    let f = temp_file(
        "g3.json",
        r#"{"A": [["-1+i", 1, 0], [0, -2, 0], [0, 0, "2i"]], "B": [[0], [1], ["1+i"]], "C": [[1, "i", 0]]}"#,
    );
    let (code, j, err) = json(&["tf", f.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(j["verified"], true);
    assert_eq!(j["markov_verified"], true);
    assert_eq!(j["mcmillan_degree"], 2);
    // G = (i s + 1 + 3i - ... ) / ((s + 1 - i)(s + 2)): poles -1 + i and -2, exactly
    let poles: Vec<&str> = j["poles"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p["value"].as_str().unwrap())
        .collect();
    assert_eq!(poles.len(), 2, "{j}");
    assert!(
        poles.contains(&"-2") && poles.contains(&"-1 + i"),
        "{poles:?}"
    );
    assert_eq!(
        j["pole_polynomial"].as_str().unwrap(),
        "s^2 + (3 - i)*s + (2 - 2*i)",
        "{j}"
    );
    let den = j["transfer_matrix"][0][0].as_str().unwrap();
    assert!(den.ends_with("/(s^2 + (3 - i)*s + (2 - 2*i))"), "{den}");
}

#[test]
fn tf_command_over_sqrt2() {
    let f = temp_file(
        "s2.json",
        r#"{"A": [[0, 1], [-2, "sqrt(2)"]], "B": [[0], [1]], "C": [[1, "sqrt(2)"]]}"#,
    );
    let (code, j, err) = json(&["tf", f.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(j["field"], "QQ(sqrt(2))");
    assert_eq!(
        j["transfer_matrix"][0][0],
        "(sqrt(2)*s + 1)/(s^2 - sqrt(2)*s + 2)"
    );
    assert_eq!(j["pole_polynomial"], "s^2 - sqrt(2)*s + 2");
    assert_eq!(j["mcmillan_degree"], 2);
    // the zero -1/sqrt(2) = -sqrt(2)/2 exactly; the pole pair is irreducible over Q(sqrt 2)
    assert_eq!(j["transmission_zeros"][0]["value"], "-sqrt(2)/2");
    assert_eq!(j["poles"][0]["degree"], 2);
    assert_eq!(j["poles"][0]["minpoly"], "x^4 + 2*x^2 + 4");
    // its roots (sqrt 2 +- i sqrt 6)/2, not those of the conjugate factor s^2 + sqrt(2) s + 2
    let roots = j["poles"][0]["roots"].as_array().unwrap();
    assert_eq!(roots.len(), 2);
    for r in roots {
        let (re, im) = (
            r["approx"][0].as_f64().unwrap(),
            r["approx"][1].as_f64().unwrap(),
        );
        assert!((re - 2f64.sqrt() / 2.0).abs() < 1e-9, "{r}");
        assert!((im.abs() - 6f64.sqrt() / 2.0).abs() < 1e-9, "{r}");
    }
    assert_eq!(j["verified"], true);
    // a descriptor system over Q(sqrt 2): polynomial part kept
    let f = temp_file(
        "s2e.json",
        r#"{"E": [[1, 0], [0, 0]], "A": [["sqrt(2)", 0], [0, 1]], "B": [[1], [1]], "C": [[1, 1]]}"#,
    );
    let (code, j, err) = json(&["tf", f.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(
        j["transfer_matrix"][0][0],
        "(-s + (1 + sqrt(2)))/(s - sqrt(2))"
    );
    assert_eq!(j["verified"], true);
}

/// The exact transfer function over Q(i) evaluated in complex floats at `s`.
fn eval_exact(p: &Poly<QuadraticField>, s: Complex<f64>) -> Complex<f64> {
    let k = p.field().clone();
    p.coeffs()
        .iter()
        .rev()
        .fold(Complex::new(0.0, 0.0), |acc, c| {
            let (re, im) = k.approx(c);
            acc * s + Complex::new(re, im)
        })
}

#[test]
fn complex_freqresp_matches_the_exact_transfer_function() {
    let s = gaussian_system();
    let g = s.transfer_matrix().unwrap();
    let [a, b, c, d] = [&s.a, &s.b, &s.c, &s.d].map(|m| to_cmatrix(m).unwrap());
    let freqs = [-2.0, -0.3, -0.05, 0.05, 0.3, 2.0];
    let resp = freqresp([&a, &b, &c, &d], &freqs, None).unwrap();
    let f = &g.entries[0][0];
    for (hz, r) in freqs.iter().zip(&resp) {
        let jw = Complex::new(0.0, 2.0 * std::f64::consts::PI * hz);
        let want = eval_exact(&f.num, jw) / eval_exact(&f.den, jw);
        assert!(
            (r[(0, 0)] - want).norm() <= 1e-12 * want.norm(),
            "{hz}: {r} {want}"
        );
    }
    // not conjugate-symmetric: G(-jw) != conj G(jw)
    assert!((resp[0][(0, 0)] - resp[5][(0, 0)].conj()).norm() > 1e-3);
}

#[test]
fn freqresp_command_of_one_over_s_minus_i_is_two_sided() {
    // G(s) = 1/(s - i): G(jw) = -i/(w - 1), peaked at w = 1 (f = 0.159 Hz), so the samples
    // 0.01..0.1 Hz and their negatives stay away from it
    let f = temp_file("si.json", r#"{"A": [["i"]], "B": [[1]], "C": [[1]]}"#);
    let (code, j, err) = json(&[
        "freqresp",
        f.to_str().unwrap(),
        "--from",
        "0.01",
        "--to",
        "0.1",
        "--points",
        "4",
    ]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(j["two_sided"], true);
    let fs = j["frequencies_hz"].as_array().unwrap();
    assert_eq!(fs.len(), 8);
    assert!(fs[0].as_f64().unwrap() < 0.0 && fs[7].as_f64().unwrap() > 0.0);
    for (hz, g) in fs.iter().zip(j["response"].as_array().unwrap()) {
        let w = 2.0 * std::f64::consts::PI * hz.as_f64().unwrap();
        let want = Complex::new(0.0, -1.0 / (w - 1.0));
        let got = Complex::new(g[0][0][0].as_f64().unwrap(), g[0][0][1].as_f64().unwrap());
        assert!(
            (got - want).norm() <= 1e-12 * want.norm(),
            "{w}: {got} {want}"
        );
    }
}

#[test]
fn complex_era_finds_the_mcmillan_degree_and_reproduces_the_markov_parameters() {
    let s = gaussian_system();
    let [a, b, c, d] = [&s.a, &s.b, &s.c, &s.d].map(|m| to_cmatrix(m).unwrap());
    let r = era_system(&a, &b, &c, &d, None, &Tol::default()).unwrap();
    let e = &r.realization;
    assert_eq!((e.order, e.truth), (2, Truth::True));
    assert!(
        e.a.iter().any(|z| z.im.abs() > 1e-3),
        "a complex realization"
    );
    let want = markov_parameters(&a, &b, &c, &d, 12).unwrap();
    let got = markov_parameters(&e.a, &e.b, &e.c, &e.d, 12).unwrap();
    for (k, (x, y)) in want.iter().zip(&got).enumerate() {
        assert!((x - y).norm() <= 1e-9 * (1.0 + x.norm()), "M_{k}: {x} {y}");
    }
}

#[test]
fn check_and_era_commands_over_gaussian_rationals() {
    let f = temp_file(
        "g3c.json",
        r#"{"A": [["-1+i", 1, 0], [0, -2, 0], [0, 0, "2i"]], "B": [[0], [1], ["1+i"]], "C": [[1, "i", 0]]}"#,
    );
    let p = f.to_str().unwrap();
    let (code, j, err) = json(&["check", p]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(j["agree"], true);
    let cmp = &j["comparisons"];
    assert_eq!(cmp["minreal_order"]["exact"], 2);
    assert_eq!(cmp["minreal_order"]["float"], 2);
    assert_eq!(cmp["controllability_rank"]["float"], 3);
    assert_eq!(cmp["observability_rank"]["float"], 2);
    assert_eq!(cmp["era_order"]["float"], 2);
    // eigenvalues of A and of its conjugate: -1 +- i, -2 (twice), +-2i
    assert_eq!(
        cmp["jordan_structure_real_form"]["eigenvalues"]
            .as_array()
            .unwrap()
            .len(),
        5
    );
    // the exact G(ri) over Q(i) against the float one, at r = -3, -1/2, 1/3, 2, 5 except the
    // pole 2i (sI - A singular there, left out)
    let fr = &cmp["frequency_response"];
    assert_eq!(fr["agree"], true);
    assert_eq!(fr["omega"].as_array().unwrap().len(), 4, "{fr}");
    assert!(fr["max_abs_error"].as_f64().unwrap() < 1e-12, "{fr}");
    let (code, j, err) = json(&["minreal", p, "--method", "era"]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(
        (j["order"].clone(), j["agree_with_exact"].clone()),
        (2.into(), true.into())
    );
    assert!(
        j["A"][0][0].is_array(),
        "complex entries as [re, im]: {}",
        j["A"]
    );
    // a 1 x 1 Hankel matrix cannot show order 2: disagreement, exit 3
    let (code, j, err) = json(&["minreal", p, "--method", "era", "--hankel", "1"]);
    assert_eq!(code, 3, "{err}");
    assert_eq!(j["agree_with_exact"], false);
}

#[test]
fn check_exits_3_when_the_complex_float_path_misses_a_close_mode() {
    // eigenvalues i and i + 1e-12: exactly controllable (distinct), numerically not
    let f = temp_file(
        "close.json",
        r#"{"A": [["i", 0], [0, "i + 1/1000000000000"]], "B": [[1], [1]], "C": [[1, 1]]}"#,
    );
    let (code, j, err) = json(&["check", f.to_str().unwrap()]);
    assert_eq!(code, 3, "{err} {j}");
    assert_eq!(j["agree"], false);
    let c = &j["comparisons"]["controllability_rank"];
    assert_eq!(c["exact"], 2);
    assert_eq!(c["agree"], false);
    assert_ne!(c["float_truth"], "true");
}

mod cross_check {
    //! The float path against the exact one over every quadratic field: random small systems
    //! over Q(i) and Q(sqrt 2), the exact transfer matrix over K (its coefficients rounded
    //! once at the end) against the complex float frequency response of the state space, and
    //! the exact McMillan degree against the complex ERA's order where the ERA is certain.
    use super::*;
    use exactlti::realization::{MinrealMethod, minimal};
    use proptest::prelude::*;

    fn entry() -> impl Strategy<Value = (i64, i64)> {
        (-3i64..=3, -2i64..=2)
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 24, .. ProptestConfig::default() })]
        #[test]
        fn float_frequency_response_matches_the_exact_transfer_matrix(
            d in prop::sample::select(vec![-1i64, 2]),
            n in 1usize..=4,
            m in 1usize..=2,
            p in 1usize..=2,
            e in prop::collection::vec(entry(), 16 + 8 + 8),
        ) {
            let k = QuadraticField::new(d).unwrap();
            let a = Matrix::from_fn(k.clone(), n, n, |i, j| { let (x, y) = e[i * n + j]; q(x, y) });
            let b = Matrix::from_fn(k.clone(), n, m, |i, j| { let (x, y) = e[16 + i * m + j]; q(x, y) });
            let c = Matrix::from_fn(k.clone(), p, n, |i, j| { let (x, y) = e[24 + i * n + j]; q(x, y) });
            let s = StateSpace::new_strictly_proper(a, b, c).unwrap();
            let g = s.transfer_matrix().unwrap();
            prop_assert!(g.matches_markov(&s));
            let [fa, fb, fc, fd] = [&s.a, &s.b, &s.c, &s.d].map(|x| to_cmatrix(x).unwrap());
            let freqs = [-1.7, -0.37, 0.013, 0.29, 1.3];
            // a frequency within reach of a pole is singular for the float solve: skip it
            let Ok(resp) = freqresp([&fa, &fb, &fc, &fd], &freqs, None) else { return Ok(()) };
            for (hz, r) in freqs.iter().zip(&resp) {
                let jw = Complex::new(0.0, 2.0 * std::f64::consts::PI * hz);
                for i in 0..p {
                    for j in 0..m {
                        let f = &g.entries[i][j];
                        let den = eval_exact(&f.den, jw);
                        prop_assume!(den.norm() > 1e-6);
                        let want = eval_exact(&f.num, jw) / den;
                        prop_assert!(
                            (r[(i, j)] - want).norm() <= 1e-8 * (1.0 + want.norm()),
                            "{} Hz ({}, {}): float {} exact {}", hz, i, j, r[(i, j)], want
                        );
                    }
                }
            }
            // the exact McMillan degree bounds the ERA's order; where its gap test is
            // certain (`True`) they agree
            let exact = minimal(&s, MinrealMethod::Kalman).unwrap();
            prop_assert!(exact.verified);
            if let Ok(era) = era_system(&fa, &fb, &fc, &fd, None, &Tol::default()) {
                let r = &era.realization;
                prop_assert!(r.order <= n);
                if r.truth == Truth::True {
                    prop_assert_eq!(r.order, exact.order);
                }
            }
        }
    }
}

/// `check` over Q(sqrt -3) compares the eigenvalues too: the exact spectrum of the real form
/// [[X, -Y], [Y, X]] is that of A and of its conjugate, from the Jordan form of A over K.
/// Here A has sqrt(-3) and its conjugate -sqrt(-3) (the real form doubles each), 2, and the
/// four roots of x^4 + 3 (two from x^2 - sqrt(-3) over K, two from the conjugate factor).
#[test]
fn check_compares_the_eigenvalues_over_q_sqrt_minus_3() {
    let f = temp_file(
        "s3.json",
        r#"{"A": [["sqrt(-3)", 1, 0, 0, 0], [0, "-sqrt(-3)", 0, 0, 0], [0, 0, 2, 0, 0],
                  [0, 0, 0, 0, 1], [0, 0, 0, "sqrt(-3)", 0]],
            "B": [[1], [1], [1], [0], [1]], "C": [[1, 1, 1, 1, 0]]}"#,
    );
    let (code, j, err) = json(&["check", f.to_str().unwrap()]);
    assert_eq!(code, 0, "{err} {j}");
    assert_eq!(j["agree"], true);
    let c = &j["comparisons"]["jordan_structure_real_form"];
    assert_eq!(c["agree"], true, "{c}");
    assert_eq!(c["exact_verified"], true);
    let evs = c["eigenvalues"].as_array().unwrap();
    assert_eq!(evs.len(), 7, "{c}");
    let blocks = |v: &str| {
        evs.iter()
            .find(|e| e["eigenvalue"] == v)
            .map(|e| e["exact_blocks"].clone())
    };
    for doubled in ["sqrt(3)*i", "-sqrt(3)*i", "2"] {
        assert_eq!(
            blocks(doubled),
            Some(serde_json::json!([1, 1])),
            "{doubled}"
        );
    }
    let quartic = evs
        .iter()
        .filter(|e| {
            e["eigenvalue"]
                .as_str()
                .unwrap()
                .starts_with("root of x^4 + 3 near")
        })
        .count();
    assert_eq!(quartic, 4);
    let skipped = j["skipped"].to_string();
    assert!(!skipped.contains("jordan_structure"), "{skipped}");
}

#[test]
fn check_exits_3_when_the_float_eigenvalues_merge_over_q_sqrt_minus_3() {
    // sqrt(-3) and sqrt(-3) + 1e-12: two simple eigenvalues exactly, one double one in floats
    let f = temp_file(
        "s3close.json",
        r#"{"A": [["sqrt(-3)", 0], [0, "sqrt(-3) + 1/1000000000000"]], "B": [[1], [0]], "C": [[1, 1]]}"#,
    );
    let (code, j, err) = json(&["check", f.to_str().unwrap()]);
    assert_eq!(code, 3, "{err} {j}");
    assert_eq!(j["agree"], false);
    let c = &j["comparisons"]["jordan_structure_real_form"];
    assert_eq!(c["agree"], false, "{c}");
    for e in c["eigenvalues"].as_array().unwrap() {
        assert_eq!(e["exact_blocks"], serde_json::json!([1]), "{e}");
        assert_eq!(e["agree"], false, "{e}");
        assert_ne!(e["float_truth"], "true", "{e}");
    }
}
