//! Discrete time in the output a person reads (issue 28): a system with `dt` prints its
//! transfer matrix, zpk, poles/zeros polynomials and LaTeX in `z` (the same strings as the
//! continuous file with `s` renamed, JSON keys unchanged), `minimum_phase` is decided on
//! |z| < 1, and `freqresp --svg` / `step --svg` draw the sampled system (Nyquist line,
//! stairs).

use crate::common::cli::{run, run_json, temp_file};

fn write(name: &str, text: &str) -> String {
    temp_file("dtext", name, text).display().to_string()
}

fn json(args: &[&str]) -> serde_json::Value {
    run_json(args)
}

/// Every string of a JSON value (keys excluded).
fn strings(v: &serde_json::Value, out: &mut Vec<String>) {
    match v {
        serde_json::Value::String(s) => out.push(s.clone()),
        serde_json::Value::Array(xs) => xs.iter().for_each(|x| strings(x, out)),
        serde_json::Value::Object(o) => o.values().for_each(|x| strings(x, out)),
        _ => {}
    }
}

const BODY: &str = r#""A": [[0.5, 0.1, 0], [0, 0.8, 1], [0, 0, -0.25]], "B": [[0, 1], [1, 0], [0, 1]], "C": [[1, 0, 0], [0, 1, 1]], "D": [[0, 0], [0, 1]]"#;

#[test]
fn tf_of_a_discrete_system_is_written_in_z() {
    let c = write("c.json", &format!("{{{BODY}}}"));
    let d = write("d.json", &format!(r#"{{"dt": 0.1, {BODY}}}"#));
    let (jc, jd) = (json(&["tf", &c]), json(&["tf", &d]));
    assert_eq!(jd["variable"], "z");
    assert_eq!(jd["dt"], "1/10");
    assert_eq!(jc["variable"], "s");
    // the same keys, and every polynomial string the continuous one with s -> z
    let keys = |j: &serde_json::Value| {
        let mut k: Vec<String> = j.as_object().unwrap().keys().cloned().collect();
        k.retain(|x| x != "dt");
        k
    };
    assert_eq!(keys(&jc), keys(&jd));
    for key in ["transfer_matrix", "zpk"] {
        let (mut a, mut b) = (vec![], vec![]);
        strings(&jc[key], &mut a);
        strings(&jd[key], &mut b);
        assert!(a.iter().any(|x| x.contains('s')), "{a:?}");
        let renamed: Vec<String> = a.iter().map(|x| x.replace('s', "z")).collect();
        assert_eq!(renamed, b, "{key}");
        assert!(b.iter().all(|x| !x.contains('s')), "{b:?}");
    }
    // the text names the variable and the sample time, and never writes s
    let (code, text, _) = run(&["tf", &d]);
    assert_eq!(code, 0);
    assert!(
        text.contains("variable: z") && text.contains("dt: 1/10"),
        "{text}"
    );
    assert!(text.contains("z^2") && text.contains("*z"), "{text}");
    assert!(!text.contains("s^") && !text.contains("*s"), "{text}");
    let (code, tex, _) = run(&["tf", &d, "--format", "latex"]);
    assert_eq!(code, 0);
    assert!(tex.contains("z^{2}") && !tex.contains("s^{2}"), "{tex}");
}

#[test]
fn tf_over_a_quadratic_field_is_written_in_z() {
    let f = |dt: &str| {
        format!(
            r#"{{{dt}"A": [["sqrt(2)", 1], [0, "1/2"]], "B": [[0], [1]], "C": [[1, 1]], "D": [[0]]}}"#
        )
    };
    let jc = json(&["tf", &write("qc.json", &f(""))]);
    let jd = json(&["tf", &write("qd.json", &f(r#""dt": "1/4", "#))]);
    assert_eq!(jd["variable"], "z");
    assert_eq!(jd["dt"], "1/4");
    assert_eq!(
        jc["pole_polynomial"]
            .as_str()
            .unwrap()
            .replace('s', "z")
            .replace("zqrt", "sqrt"),
        jd["pole_polynomial"].as_str().unwrap()
    );
    let (mut b, mut fs) = (vec![], vec![]);
    strings(&jd["transfer_matrix"], &mut b);
    strings(&jd["poles"], &mut fs);
    assert!(
        b.iter().all(|x| x.contains('z') && !x.contains("s^")),
        "{b:?}"
    );
    assert!(fs.iter().any(|x| x.contains('z')), "{fs:?}");
}

#[test]
fn zeros_of_a_discrete_system_minimum_phase_on_the_unit_disk() {
    // G = 1 + (5/2)/(z - 1/2) = (z + 2)/(z - 1/2): the zero -2 is in Re < 0 but |z| > 1
    let body = r#""A": [[0.5]], "B": [[1]], "C": [[2.5]], "D": [[1]]"#;
    let c = json(&["zeros", &write("zc.json", &format!("{{{body}}}"))]);
    let d = json(&[
        "zeros",
        &write("zd.json", &format!(r#"{{"dt": 1, {body}}}"#)),
    ]);
    assert_eq!(c["zero_polynomial"], "s + 2");
    assert_eq!(c["minimum_phase"], true);
    assert_eq!(d["zero_polynomial"], "z + 2");
    assert_eq!(d["minimum_phase"], false);
    assert_eq!(d["variable"], "z");
    // a zero inside the circle: minimum phase in discrete time
    let body = r#""A": [[0.5]], "B": [[1]], "C": [[0.25]], "D": [[1]]"#;
    let d = json(&[
        "zeros",
        &write("zd2.json", &format!(r#"{{"dt": 1, {body}}}"#)),
    ]);
    assert_eq!(d["zero_polynomial"], "z - 1/4");
    assert_eq!(d["minimum_phase"], true);
}

#[test]
fn discrete_bode_and_step_plots() {
    let d = write(
        "plot.json",
        r#"{"name": "lag", "dt": 0.1, "A": [[0.5, 0.1], [0, 0.8]], "B": [[0], [1]], "C": [[1, 0]], "D": [[0]]}"#,
    );
    let svg = write("bode.svg", "");
    let j = json(&["freqresp", &d, "--svg", &svg]);
    assert_eq!(j["svg"], svg.as_str());
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(
        text.starts_with("<svg") || text.starts_with("<?xml"),
        "{text}"
    );
    assert!(text.contains("Nyquist 1/(2T) = 5 Hz"), "{text}");
    assert!(text.contains("T = 1/10 s"));
    // the last frequency is the Nyquist frequency
    let f = j["frequencies_hz"].as_array().unwrap();
    assert!((f.last().unwrap().as_f64().unwrap() - 5.0).abs() < 1e-12);
    let step = write("step.svg", "");
    let j = json(&["step", &d, "--points", "30", "--svg", &step]);
    assert_eq!(j["svg"], step.as_str());
    let text = std::fs::read_to_string(&step).unwrap();
    assert!(text.contains("step response (discrete time)"), "{text}");
    // stable (|z| < 1 decided exactly): the exact final value G(1) = 1 is drawn
    assert!(text.contains("final value G(1) (exact)"), "{text}");
    // stairs: 30 samples held over a period each (2 points per sample) and 30 dots
    assert_eq!(text.matches("<circle").count(), 30, "{text}");
    let imp = write("imp.svg", "");
    let (code, _, err) = run(&["impulse", &d, "--svg", &imp]);
    assert_eq!(code, 0, "{err}");
    assert!(
        !std::fs::read_to_string(&imp)
            .unwrap()
            .contains("final value")
    );
}

fn q(rows: &[&[i64]]) -> exactlti::matrix::Matrix<exactlti::field::Q> {
    exactlti::matrix::Matrix::from_i64_rows(rows)
}

#[test]
fn exact_zoh_of_nilpotent_systems() {
    use exactlti::field::{Rational, rational_to_f64};
    use exactlti::system::StateSpace;
    use exactlti::system::discrete::zoh_exact;
    let dt = Rational::new(1.into(), 10.into());
    // the double integrator: A_d = [[1, T], [0, 1]], B_d = [[T^2/2], [T]]
    let s = StateSpace::new(
        q(&[&[0, 1], &[0, 0]]),
        q(&[&[0], &[1]]),
        q(&[&[1, 0]]),
        q(&[&[0]]),
    )
    .unwrap();
    let z = zoh_exact(&s, &dt).unwrap().expect("nilpotent");
    assert!(z.verified);
    let r = |n: i64, d: i64| Rational::new(n.into(), d.into());
    assert_eq!(z.system.a.get(0, 1), &r(1, 10));
    assert_eq!(z.system.a.get(0, 0), &r(1, 1));
    assert_eq!(z.system.b.get(0, 0), &r(1, 200));
    assert_eq!(z.system.b.get(1, 0), &r(1, 10));
    // a stable A has no exact zoh
    let s2 = StateSpace::new(q(&[&[-1]]), q(&[&[1]]), q(&[&[1]]), q(&[&[0]])).unwrap();
    assert!(zoh_exact(&s2, &dt).unwrap().is_none());
    // A = [[0, 1], [-1, 0]] is not nilpotent (A^2 = -I)
    let s3 = StateSpace::new(
        q(&[&[0, 1], &[-1, 0]]),
        q(&[&[0], &[1]]),
        q(&[&[1, 0]]),
        q(&[&[0]]),
    )
    .unwrap();
    assert!(zoh_exact(&s3, &dt).unwrap().is_none());
    // random nilpotent A = P N P^-1 (N strictly upper triangular): exact = float zoh
    let mut rng = exactlti::rng::SplitMix64(0x2800_0201);
    for case in 0..20 {
        let n = rng.int(1, 4) as usize;
        let mut nm = vec![vec![0i64; n]; n];
        let mut p = vec![vec![0i64; n]; n];
        for i in 0..n {
            p[i][i] = 1;
            for j in i + 1..n {
                nm[i][j] = rng.int(-3, 3);
                p[i][j] = rng.int(-2, 2);
            }
        }
        // P unit upper triangular, and its transpose mixed in: P^T N P^-T
        let rows = |m: &Vec<Vec<i64>>| q(&m.iter().map(Vec::as_slice).collect::<Vec<_>>());
        let pm = &rows(&p).transpose() * &rows(&p);
        let a = &(&pm * &rows(&nm)) * &pm.inverse().unwrap();
        let b = q(&(0..n)
            .map(|i| [i as i64 - 1])
            .collect::<Vec<_>>()
            .iter()
            .map(|r| &r[..])
            .collect::<Vec<_>>());
        let c = q(&[&vec![1; n][..]]);
        let s = StateSpace::new(a, b, c, q(&[&[0]])).unwrap();
        let dt = Rational::new(rng.int(1, 9).into(), rng.int(1, 9).into());
        let z = zoh_exact(&s, &dt)
            .unwrap()
            .expect("nilpotent by construction");
        assert!(z.verified, "case {case}");
        let f = |m: &exactlti::matrix::Matrix<exactlti::field::Q>| {
            exactlti::float::to_dmatrix(m).unwrap()
        };
        let (ad, bd) =
            exactlti::float::time_response::zoh(&f(&s.a), &f(&s.b), rational_to_f64(&dt)).unwrap();
        let scale = 1.0 + ad.amax() + bd.amax();
        assert!(
            (&f(&z.system.a) - &ad).amax() < 1e-10 * scale,
            "case {case}"
        );
        assert!(
            (&f(&z.system.b) - &bd).amax() < 1e-10 * scale,
            "case {case}"
        );
    }
}

#[test]
fn cli_zoh_exact_for_an_integrator_chain_float_with_the_reason_else() {
    let c = write(
        "dint.json",
        r#"{"A": [[0, 1], [0, 0]], "B": [[0], [1]], "C": [[1, 0]]}"#,
    );
    let j = json(&["c2d", &c, "--dt", "0.1", "--method", "zoh"]);
    assert_eq!(j["verified"], true);
    assert_eq!(j["B"][0][0], "1/200", "{j}");
    assert_eq!(j["A"][0][1], "1/10", "{j}");
    let f = write("lag1.json", r#"{"A": [[-1]], "B": [[1]], "C": [[1]]}"#);
    let j = json(&["c2d", &f, "--dt", "0.1", "--method", "zoh"]);
    assert!(
        j["why_float"].as_str().unwrap().contains("Lindemann"),
        "{j}"
    );
}
