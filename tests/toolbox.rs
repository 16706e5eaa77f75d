//! `damp` (damping table), `gram` (exact Gramians) and `stepinfo` (python-control's
//! `step_info` on the float step response): hand values incl. edge shapes (pole at 0,
//! unstable, integrator, zero final value), random systems with a fixed seed, and the
//! identities (Lyapunov residual exactly zero; wn^2 and 2 zeta wn against the poles).

use crate::common::cli::{run, temp_file};
use exactlti::field::{Q, Rational};
use exactlti::float::stepinfo::step_info;
use exactlti::matrix::Matrix;
use exactlti::realization::{GramType, damp, gramian};
use exactlti::rng::SplitMix64;
use exactlti::system::StateSpace;

fn q(rows: &[&[i64]]) -> Matrix<Q> {
    Matrix::from_i64_rows(rows)
}

fn rat(n: i64, d: i64) -> Rational {
    Rational::new(n.into(), d.into())
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * (1.0 + b.abs())
}

#[test]
fn damp_by_hand() {
    // s^2 + 2 s + 4 (wn 2, zeta 1/2), a pole at -3, one at 2 and one at 0
    let a = q(&[
        &[0, 1, 0, 0, 0],
        &[-4, -2, 0, 0, 0],
        &[0, 0, -3, 0, 0],
        &[0, 0, 0, 2, 0],
        &[0, 0, 0, 0, 0],
    ]);
    let rows = damp(&a).unwrap();
    assert_eq!(rows.len(), 5);
    let find = |re: f64, im: f64| {
        rows.iter()
            .find(|r| close(r.approx.0, re, 1e-12) && close(r.approx.1, im, 1e-12))
            .unwrap()
    };
    let s3 = 3f64.sqrt();
    for im in [s3, -s3] {
        let r = find(-1.0, im);
        assert!(close(r.wn_rad_s, 2.0, 1e-14) && close(r.wn_hz, 1.0 / std::f64::consts::PI, 1e-14));
        assert!(close(r.zeta.unwrap(), 0.5, 1e-14));
        assert_eq!(
            (r.wn_squared.clone(), r.two_zeta_wn.clone()),
            (Some(rat(4, 1)), Some(rat(2, 1)))
        );
        assert_eq!(r.time_constant_exact, Some(rat(1, 1)));
    }
    let r = find(-3.0, 0.0);
    assert_eq!(
        (r.zeta, r.wn_squared.clone(), r.two_zeta_wn.clone()),
        (Some(1.0), Some(rat(9, 1)), Some(rat(6, 1)))
    );
    assert_eq!(r.time_constant_exact, Some(rat(1, 3)));
    let r = find(2.0, 0.0);
    assert_eq!(
        (r.zeta, r.time_constant_exact.clone()),
        (Some(-1.0), Some(rat(-1, 2)))
    );
    let r = find(0.0, 0.0);
    assert_eq!(
        (r.zeta, r.time_constant_s, r.time_constant_exact.clone()),
        (None, None, None)
    );
    assert!(damp(&Matrix::zeros(Q, 0, 0)).unwrap().is_empty());
}

#[test]
fn damp_random_matrices_agree_with_their_poles() {
    let mut rng = SplitMix64(0xda3b_2026);
    for _ in 0..crate::common::iters(20) {
        let n = rng.int(1, 4) as usize;
        let v = (0..n * n)
            .map(|_| Rational::from_integer(rng.int(-3, 3).into()))
            .collect();
        let a = Matrix::from_vec(Q, n, n, v);
        let rows = damp(&a).unwrap();
        assert_eq!(rows.iter().map(|r| r.multiplicity).sum::<usize>(), n);
        for r in &rows {
            let (re, im) = r.approx;
            assert!(close(r.wn_rad_s, re.hypot(im), 1e-12));
            if let Some(w2) = &r.wn_squared {
                assert!(close(
                    exactlti::field::rational_to_f64(w2),
                    re * re + im * im,
                    1e-9
                ));
            }
            if let (Some(t), Some(z)) = (&r.two_zeta_wn, r.zeta) {
                assert!(close(
                    exactlti::field::rational_to_f64(t),
                    2.0 * z * r.wn_rad_s,
                    1e-9
                ));
            }
        }
    }
}

#[test]
fn gram_by_hand_and_unstable_refused() {
    // x' = -x + u: Wc = 1/2; 1/((s+1)(s+2)) companion form: Wc = [[1/12, 0], [0, 1/6]]
    let s = StateSpace::new(q(&[&[-1]]), q(&[&[1]]), q(&[&[2]]), q(&[&[0]])).unwrap();
    let g = gramian(&s, GramType::Controllability).unwrap();
    assert!(g.verified);
    assert_eq!(g.w, q(&[&[1]]).scale(&rat(1, 2)));
    assert_eq!(gramian(&s, GramType::Observability).unwrap().w, q(&[&[2]]));
    let s = StateSpace::new(
        q(&[&[0, 1], &[-2, -3]]),
        q(&[&[0], &[1]]),
        q(&[&[1, 0]]),
        q(&[&[0]]),
    )
    .unwrap();
    let g = gramian(&s, GramType::Controllability).unwrap();
    assert!(g.verified);
    let w12 = Matrix::from_vec(Q, 2, 2, vec![rat(1, 12), rat(0, 1), rat(0, 1), rat(1, 6)]);
    assert_eq!(g.w, w12);
    // unstable and marginally stable: refused (the integral diverges)
    for a in [q(&[&[1]]), q(&[&[0]])] {
        let s = StateSpace::new(a, q(&[&[1]]), q(&[&[1]]), q(&[&[0]])).unwrap();
        assert!(gramian(&s, GramType::Controllability).is_err());
    }
}

#[test]
fn gram_random_stable_systems_satisfy_lyapunov() {
    let mut rng = SplitMix64(0x67a3_2026);
    for _ in 0..crate::common::iters(15) {
        let n = rng.int(1, 4) as usize;
        // upper triangular with a negative diagonal: stable
        let mut a = Matrix::zeros(Q, n, n);
        for i in 0..n {
            for j in i..n {
                let x = if i == j {
                    rng.int(-4, -1)
                } else {
                    rng.int(-3, 3)
                };
                a.set(i, j, Rational::from_integer(x.into()));
            }
        }
        let m = rng.int(1, 2) as usize;
        let b = Matrix::from_vec(
            Q,
            n,
            m,
            (0..n * m)
                .map(|_| Rational::from_integer(rng.int(-2, 2).into()))
                .collect(),
        );
        let c = Matrix::from_vec(
            Q,
            1,
            n,
            (0..n)
                .map(|_| Rational::from_integer(rng.int(-2, 2).into()))
                .collect(),
        );
        let s = StateSpace::new(a.clone(), b.clone(), c.clone(), Matrix::zeros(Q, 1, m)).unwrap();
        let wc = gramian(&s, GramType::Controllability).unwrap();
        let wo = gramian(&s, GramType::Observability).unwrap();
        assert!(wc.verified && wo.verified);
        let zero = Matrix::zeros(Q, n, n);
        let rc = &(&(&a * &wc.w) + &(&wc.w * &a.transpose())) + &(&b * &b.transpose());
        let ro = &(&(&a.transpose() * &wo.w) + &(&wo.w * &a)) + &(&c.transpose() * &c);
        assert_eq!((rc, ro), (zero.clone(), zero));
        // positive semidefinite: every diagonal entry >= 0
        for i in 0..n {
            assert!(wc.w.get(i, i) >= &Rational::from_integer(0.into()));
        }
    }
}

#[test]
fn stepinfo_second_order_and_random_first_order() {
    // wn = 1, zeta = 1/2: overshoot 100 exp(-pi zeta / sqrt(1 - zeta^2)) = 16.30 %, peak time
    // pi / wd, on a grid of step 1e-3
    let (z, wd) = (0.5f64, 0.75f64.sqrt());
    let t: Vec<f64> = (0..=20_000).map(|k| k as f64 * 1e-3).collect();
    let y: Vec<f64> = t
        .iter()
        .map(|&t| 1.0 - (-z * t).exp() * ((wd * t).cos() + z / wd * (wd * t).sin()))
        .collect();
    let s = step_info(&t, &y, 1.0).unwrap();
    let os = 100.0 * (-std::f64::consts::PI * z / wd).exp();
    assert!((s.overshoot - os).abs() < 1e-4, "{}", s.overshoot);
    assert!((s.peak_time - std::f64::consts::PI / wd).abs() <= 1e-3);
    assert!((s.peak - (1.0 + os / 100.0)).abs() < 1e-6);
    assert!(s.settling_min <= 1.0 && s.settling_max >= s.peak - 1e-12);
    // k / (s + a): rise ln 9 / a, settling ln 50 / a, final k / a, within one step
    let mut rng = SplitMix64(0x57e9_2026);
    for _ in 0..crate::common::iters(20) {
        let (k, a) = (rng.int(-5, 5) as f64, rng.int(1, 8) as f64);
        if k == 0.0 {
            continue;
        }
        let dt = 1e-3 / a;
        let t: Vec<f64> = (0..=10_000).map(|i| i as f64 * dt).collect();
        let y: Vec<f64> = t.iter().map(|t| k / a * (1.0 - (-a * t).exp())).collect();
        let s = step_info(&t, &y, k / a).unwrap();
        assert!((s.rise_time - 9f64.ln() / a).abs() <= 2.0 * dt);
        assert!((s.settling_time.unwrap() - 50f64.ln() / a).abs() <= 2.0 * dt);
        assert_eq!((s.overshoot, s.undershoot), (0.0, 0.0));
        assert!(close(s.steady_state_value, k / a, 1e-15));
    }
}

#[test]
fn command_line() {
    let f = temp_file(
        "toolbox",
        "second.json",
        r#"{"A": [[0, 1], [-1, -1]], "B": [[0], [1]], "C": [[1, 0]], "inputs": ["u"], "outputs": ["y"]}"#,
    );
    let path = f.to_str().unwrap();
    let (code, out, err) = run(&[
        "stepinfo", path, "--to", "20", "--points", "20001", "--format", "json",
    ]);
    assert_eq!(code, 0, "{err}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    let ch = &j["channels"][0];
    assert!(
        (ch["Overshoot"].as_f64().unwrap() - 16.303_353_482_158_1).abs() < 1e-3,
        "{ch}"
    );
    assert_eq!(ch["SteadyStateValue"].as_f64(), Some(1.0));
    let (code, out, _) = run(&["damp", path, "--format", "json"]);
    assert_eq!(code, 0);
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["poles"].as_array().unwrap().len(), 2);
    assert_eq!(j["poles"][0]["wn_squared"], "1");
    assert_eq!(j["poles"][0]["two_zeta_wn"], "1");
    let (code, out, _) = run(&["gram", path, "--type", "o", "--format", "json"]);
    assert_eq!(code, 0);
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    // A^T W + W A + C^T C = 0 for A = [[0, 1], [-1, -1]], C = [1, 0]: W = [[1, 1/2], [1/2, 1/2]]
    assert_eq!(j["W"], serde_json::json!([["1", "1/2"], ["1/2", "1/2"]]));
    assert_eq!(j["verified"], true);
    for cmd in ["stepinfo", "damp", "gram", "margin"] {
        let (code, out, _) = run(&[cmd, path]);
        assert_eq!(code, 0, "{cmd}");
        assert!(
            out.lines().all(|l| l.chars().count() <= 200),
            "{cmd}: {out}"
        );
    }
    // integrator and unstable channels: no step characteristics, with the reason
    let f = temp_file(
        "toolbox",
        "integ.json",
        r#"{"A": [[0, 0], [0, 1]], "B": [[1, 0], [0, 1]], "C": [[1, 0], [0, 1]]}"#,
    );
    let (code, out, _) = run(&["stepinfo", f.to_str().unwrap(), "--format", "json"]);
    assert_eq!(code, 0);
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    let chans = j["channels"].as_array().unwrap();
    assert_eq!(chans.len(), 4);
    assert!(
        chans[0]["reason"]
            .as_str()
            .unwrap()
            .contains("left half-plane")
    );
    assert!(
        chans[3]["reason"]
            .as_str()
            .unwrap()
            .contains("left half-plane")
    );
    assert!(
        chans[1]["reason"]
            .as_str()
            .unwrap()
            .contains("final value is 0")
    );
    // unstable A: gram refused with one line, exit 2
    let (code, _, err) = run(&["gram", f.to_str().unwrap()]);
    assert_eq!((code, err.trim_end().lines().count()), (2, 1), "{err}");
    let (code, _, err) = run(&["stepinfo", path, "--points", "1"]);
    assert_eq!((code, err.trim_end().lines().count()), (2, 1), "{err}");
}
