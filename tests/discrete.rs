//! Discrete time: exact stability (Schur-Cohn / Jury and Sturm, against float root moduli
//! on random polynomials with a fixed seed), Tustin c2d/d2c (exact inverses, the bilinear
//! substitution at points), step/impulse sequences (difference equation, Markov
//! parameters), and the command line (`dt` key, refusals, mixed interconnections).

use crate::common::cli::run;
use exactlti::field::{ElemDisplay, Q, Rational};
use exactlti::matrix::Matrix;
use exactlti::poly::{Poly, parse_poly_q};
use exactlti::rng::SplitMix64;
use exactlti::system::StateSpace;
use exactlti::system::dcgain::gain_at;
use exactlti::system::discrete::stability::{
    Domain, Place, Verdict, classify_factor, schur_stable, stability_of,
};
use exactlti::system::discrete::{impulse_sequence, step_sequence, tustin, tustin_inverse};

fn r(n: i64, d: i64) -> Rational {
    Rational::new(n.into(), d.into())
}

fn p(text: &str) -> Poly<Q> {
    parse_poly_q(text).unwrap()
}

fn q(rows: &[&[i64]]) -> Matrix<Q> {
    Matrix::from_i64_rows(rows)
}

#[test]
fn schur_examples_and_edges() {
    assert!(schur_stable(&p("x - 1/2")));
    assert!(schur_stable(&p("x")));
    assert!(schur_stable(&p("3")));
    assert!(!schur_stable(&Poly::zero(Q)));
    assert!(!schur_stable(&p("x - 1")));
    assert!(!schur_stable(&p("x + 1")));
    assert!(!schur_stable(&p("2*x - 3")));
    // (1 +- i)/2: modulus sqrt(2)/2
    assert!(schur_stable(&p("x^2 - x + 1/2")));
    // roots 1/2 and 3/2
    assert!(!schur_stable(&p("x^2 - 2*x + 3/4")));
    // on the circle: exp(+-2 pi i/3)
    assert!(!schur_stable(&p("x^2 + x + 1")));
}

#[test]
fn factor_places() {
    assert_eq!(classify_factor(&p("x^2 + x + 1")), Place::Boundary);
    assert_eq!(classify_factor(&p("x - 1")), Place::Boundary);
    assert_eq!(classify_factor(&p("x^2 + 1")), Place::Boundary);
    // self-reciprocal with real roots 2.618, 0.382: one outside
    assert_eq!(classify_factor(&p("x^2 - 3*x + 1")), Place::Outside);
    // a Salem polynomial: one root outside, one inside, two on the circle
    assert_eq!(
        classify_factor(&p("x^4 - x^3 - x^2 - x + 1")),
        Place::Outside
    );
    // Phi_5 (primitive 5th roots of unity)
    assert_eq!(
        classify_factor(&p("x^4 + x^3 + x^2 + x + 1")),
        Place::Boundary
    );
    assert_eq!(classify_factor(&p("x^2 - x + 1/2")), Place::Inside);
    assert_eq!(classify_factor(&p("x - 3")), Place::Outside);
}

/// Float moduli of the roots (companion matrix eigenvalues).
fn float_moduli(f: &Poly<Q>) -> Vec<f64> {
    let n = f.deg();
    let lc = exactlti::field::rational_to_f64(&f.lc());
    let mut m = nalgebra::DMatrix::<f64>::zeros(n, n);
    for i in 1..n {
        m[(i, i - 1)] = 1.0;
    }
    for i in 0..n {
        m[(i, n - 1)] = -exactlti::field::rational_to_f64(&f.coeff(i)) / lc;
    }
    exactlti::float::eigenvalues(&m)
        .unwrap()
        .iter()
        .map(|z| z.norm())
        .collect()
}

/// Random products of (z - a) and (z^2 - 2 c z + m) with rational a, c, m around the
/// circle: the Jury decision equals "every float root modulus < 1" whenever no modulus is
/// within 1e-6 of 1, on stable and unstable polynomials alike.
#[test]
fn jury_decision_equals_float_moduli() {
    let mut rng = SplitMix64(0x005e_ed28);
    let (mut stable, mut unstable) = (0, 0);
    for _ in 0..300 {
        let mut f = Poly::one(Q);
        for _ in 0..rng.int(1, 4) {
            if rng.int(0, 1) == 0 {
                f = f.mul(&Poly::new(Q, vec![-r(rng.int(-13, 13), 10), r(1, 1)]));
            } else {
                let c = r(rng.int(-10, 10), 10);
                let m = r(rng.int(1, 16), 10);
                f = f.mul(&Poly::new(Q, vec![m, -(&c * r(2, 1)), r(1, 1)]));
            }
        }
        let mods = float_moduli(&f);
        if mods.iter().any(|x| (x - 1.0).abs() < 1e-6) {
            continue;
        }
        let want = mods.iter().all(|x| *x < 1.0);
        assert_eq!(schur_stable(&f), want, "{f}: moduli {mods:?}");
        if want {
            stable += 1;
        } else {
            unstable += 1;
        }
    }
    assert!(
        stable > 30 && unstable > 30,
        "{stable} stable, {unstable} unstable"
    );
}

#[test]
fn matrix_verdicts() {
    let d = |a: Matrix<Q>| stability_of(&a, Domain::Discrete).unwrap().verdict;
    let c = |a: Matrix<Q>| stability_of(&a, Domain::Continuous).unwrap().verdict;
    let half = q(&[&[1, 0], &[0, -1]]).scale(&r(1, 2));
    assert_eq!(d(half), Verdict::AsymptoticallyStable);
    assert_eq!(d(q(&[&[0, -1], &[1, 0]])), Verdict::MarginallyStable);
    assert_eq!(d(q(&[&[1, 1], &[0, 1]])), Verdict::UnstableJordan);
    assert_eq!(d(q(&[&[1, 0], &[0, 1]])), Verdict::MarginallyStable);
    assert_eq!(d(q(&[&[2]])), Verdict::Unstable);
    assert_eq!(d(q(&[&[0, 0], &[0, 0]])), Verdict::AsymptoticallyStable);
    assert_eq!(c(q(&[&[0, 1], &[-2, -3]])), Verdict::AsymptoticallyStable);
    assert_eq!(c(q(&[&[0, 1], &[-1, 0]])), Verdict::MarginallyStable);
    assert_eq!(c(q(&[&[0, 1], &[0, 0]])), Verdict::UnstableJordan);
    assert_eq!(c(q(&[&[1]])), Verdict::Unstable);
    assert_eq!(c(q(&[&[0, 1], &[2, -1]])), Verdict::Unstable);
}

fn random_system(rng: &mut SplitMix64, n: usize, m: usize, p: usize) -> StateSpace<Q> {
    let mut mat = |r: usize, c: usize| {
        let rows: Vec<Vec<i64>> = (0..r)
            .map(|_| (0..c).map(|_| rng.int(-4, 4)).collect())
            .collect();
        let refs: Vec<&[i64]> = rows.iter().map(Vec::as_slice).collect();
        Matrix::from_i64_rows(&refs)
    };
    StateSpace::new(mat(n, n), mat(n, m), mat(p, n), mat(p, m)).unwrap()
}

/// Tustin and its inverse are exact inverses; the discrete transfer matrix is the
/// continuous one at s = (2/T)(z - 1)/(z + 1); the continuous verdict equals the discrete
/// verdict of the discretization (the bilinear map sends Re s < 0 onto |z| < 1).
#[test]
fn tustin_identities_on_random_systems() {
    let mut rng = SplitMix64(28);
    let k = Q;
    for case in 0..25 {
        let n = 1 + case % 4;
        let s = random_system(&mut rng, n, 1 + case % 2, 1 + case % 3);
        let dt = r(rng.int(1, 9), rng.int(1, 9));
        let Ok(d) = tustin(&s, &dt) else { continue };
        assert_eq!(tustin_inverse(&d, &dt).unwrap(), s, "case {case}");
        assert_eq!(tustin(&tustin_inverse(&d, &dt).unwrap(), &dt).unwrap(), d);
        for z0 in [r(3, 1), r(-5, 2), r(7, 3)] {
            let sv = &(&r(2, 1) / &dt) * &(&(&z0 - &r(1, 1)) / &(&z0 + &r(1, 1)));
            let (gd, gc) = (gain_at(&d, &z0).unwrap(), gain_at(&s, &sv).unwrap());
            if gd.matrix.is_some() && gc.matrix.is_some() {
                assert_eq!(gd.matrix, gc.matrix, "case {case} at z = {z0}");
            }
        }
        let vc = stability_of(&s.a, Domain::Continuous).unwrap().verdict;
        let vd = stability_of(&d.a, Domain::Discrete).unwrap().verdict;
        assert_eq!(vc, vd, "case {case}: {}", k.fmt_elem(&dt));
    }
}

/// y[k] from iterating x[k+1] = A x[k] + B u[k]; step differences are the Markov
/// parameters; the impulse is the unit-area pulse 1/T.
#[test]
fn sequences_follow_the_difference_equation() {
    let mut rng = SplitMix64(7);
    for case in 0..10 {
        let s = random_system(&mut rng, 1 + case % 3, 2, 2);
        let dt = r(1, 4);
        let st = step_sequence(&s, 8);
        let im = impulse_sequence(&s, 8, &dt);
        let mut x = Matrix::zeros(Q, s.nstates(), s.ninputs());
        let ones = Matrix::identity(Q, s.ninputs());
        for (kk, y) in st.iter().enumerate() {
            assert_eq!(*y, &(&s.c * &x) + &s.d, "case {case} k {kk}");
            x = &(&s.a * &x) + &(&s.b * &ones);
        }
        let mk = s.markov(7);
        for kk in 1..8 {
            assert_eq!(&st[kk] - &st[kk - 1], mk[kk - 1]);
            assert_eq!(im[kk].scale(&dt), mk[kk - 1]);
        }
        assert_eq!(im[0].scale(&dt), s.d);
    }
}

fn write(name: &str, text: &str) -> String {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("exactlti-discrete");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path.display().to_string()
}

#[test]
fn cli_dt_key_commands_and_refusals() {
    let d = write(
        "d.json",
        r#"{"dt": 0.1, "A": [[0.5, 0.1], [0, 0.8]], "B": [[0], [1]], "C": [[1, 0]], "D": [[0]]}"#,
    );
    let (code, out, _) = run(&["stability", &d]);
    assert_eq!(code, 0);
    assert!(
        out.contains("asymptotically stable (every eigenvalue in |z| < 1)"),
        "{out}"
    );
    let (code, out, _) = run(&["dcgain", &d]);
    assert_eq!(code, 0);
    assert!(
        out.contains("DC gain G(1)") && out.contains("[ 1 ]"),
        "{out}"
    );
    let (code, out, _) = run(&["step", &d, "--points", "4", "--format", "json"]);
    assert_eq!(code, 0);
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["exact"][3][0][0], "23/100", "{out}");
    let (code, _, err) = run(&["margin", &d]);
    assert_eq!(code, 2);
    assert!(
        err.contains("continuous-time") && err.contains("dt = 1/10"),
        "{err}"
    );
    // bad values of dt name the key
    for bad in [r#"-1"#, r#""abc""#, "true", "[1]"] {
        let f = write(
            "bad.json",
            &format!(r#"{{"dt": {bad}, "A": [[1]], "B": [[1]], "C": [[1]]}}"#),
        );
        let (code, _, err) = run(&["tf", &f]);
        assert_eq!(code, 2, "{bad}");
        assert!(err.contains("dt"), "{bad}: {err}");
    }
    // dt = 0 is continuous time
    let f = write(
        "zero.json",
        r#"{"dt": 0, "A": [[-1]], "B": [[1]], "C": [[1]]}"#,
    );
    let (code, out, _) = run(&["stability", &f]);
    assert_eq!(code, 0);
    assert!(out.contains("Re s < 0"), "{out}");
    // mixing time domains is refused, naming both
    let c = write("c.json", r#"{"A": [[-1]], "B": [[1]], "C": [[1]]}"#);
    let (code, _, err) = run(&["feedback", &c, &d]);
    assert_eq!(code, 2);
    assert!(
        err.contains("continuous time") && err.contains("dt = 1/10"),
        "{err}"
    );
}

#[test]
fn cli_c2d_d2c_round_trip_through_files() {
    let c = write(
        "plant.json",
        r#"{"A": [[0, 1], [-2, -3]], "B": [[0], [1]], "C": [[1, 0]], "inputs": ["u"], "outputs": ["y"]}"#,
    );
    let d = write("plant_d.json", "");
    let (code, out, err) = run(&["c2d", &c, "--dt", "1/10", "--out", &d]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("verified: true"), "{out}");
    let text = std::fs::read_to_string(&d).unwrap();
    assert!(
        text.contains(r#""dt": "1/10""#) && text.contains(r#""inputs": ["u"]"#),
        "{text}"
    );
    let back = write("plant_c.json", "");
    let (code, _, err) = run(&["d2c", &d, "--out", &back]);
    assert_eq!(code, 0, "{err}");
    let (_, a, _) = run(&["tf", &c]);
    let (_, b, _) = run(&["tf", &back]);
    assert_eq!(
        a.lines().skip(1).collect::<Vec<_>>(),
        b.lines().skip(1).collect::<Vec<_>>()
    );
    // zoh (float path) keeps the sample time and the DC gain to float accuracy
    let z = write("plant_z.json", "");
    let (code, _, err) = run(&["c2d", &c, "--dt", "0.1", "--method", "zoh", "--out", &z]);
    assert_eq!(code, 0, "{err}");
    let (_, out, _) = run(&["dcgain", &z, "--format", "json"]);
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    let g = exactlti::field::parse_rational(j["dc_gain"][0][0].as_str().unwrap()).unwrap();
    assert!(
        (exactlti::field::rational_to_f64(&g) - 0.5).abs() < 1e-12,
        "{g}"
    );
    let (code, _, err) = run(&["c2d", &d, "--dt", "1"]);
    assert_eq!(code, 2);
    assert!(err.contains("already a discrete-time system"), "{err}");
}
