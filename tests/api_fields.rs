//! The front door over extension fields (issue 24): `pzmap` exact over $\mathbb{Q}(i)$ and
//! $\mathbb{Q}(\sqrt d)$ (the roots of $A$'s own factors, never its conjugate's), `step` and
//! `impulse` of a complex system (a complex response, as python-control and MATLAB give),
//! `sweep` of a file over $\mathbb{Q}(\sqrt 2)$ or $\mathbb{Q}(i)$ (the system read again at
//! each value), `System::with_values`, and `dcgain` / interconnections run on systems already
//! read (`execute_on`, `execute_on_many`), a file with only `D` read by the one reader.

use exactlti::api::{Command, Options, RunContext, System, execute_on, execute_on_many};
use exactlti::io::SystemFormat;
use exactlti::rng::SplitMix64;
use num_complex::Complex;
use serde_json::Value;

fn temp_file(name: &str, text: &str) -> std::path::PathBuf {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("exactlti-api-fields");
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

fn run(args: &[&str], sys: &System) -> Result<Value, String> {
    let cmd = Command::parse_args(args).map_err(|e| e.to_string())?;
    execute_on(&cmd, sys, &RunContext::default())
        .map(|o| o.report.to_json())
        .map_err(|f| f.message)
}

fn sys_of(text: &str) -> System {
    System::from_text(text, SystemFormat::Json, "x.json", &Options::default()).unwrap()
}

fn approx(v: &Value) -> Complex<f64> {
    let a = v["approx"].as_array().unwrap();
    Complex::new(a[0].as_f64().unwrap(), a[1].as_f64().unwrap())
}

/// A random entry `a + b i` (or `a + b sqrt(2)`) with small integers.
fn entry(rng: &mut SplitMix64, unit: &str) -> String {
    let a = rng.int(-3, 3);
    let b = rng.int(-2, 2);
    format!("{a} + {b}*{unit}")
}

#[test]
fn pzmap_over_gaussian_rationals_is_exact_and_not_the_conjugate() {
    // s^2 - i s + 1: poles i (1 +- sqrt 5)/2; the conjugates -i (1 +- sqrt 5)/2 are not poles
    let s = sys_of(r#"{"A": [[0, 1], [-1, "i"]], "B": [[0], [1]], "C": [[1, 0]], "D": [[0]]}"#);
    let r = run(&["pzmap", "x.json"], &s).unwrap();
    assert_eq!(r["exact"], Value::Bool(true));
    assert_eq!(r["pole_count"], 2);
    let g = (1.0 + 5f64.sqrt()) / 2.0;
    let mut got: Vec<Complex<f64>> = r["poles"].as_array().unwrap().iter().map(approx).collect();
    got.sort_by(|a, b| a.im.partial_cmp(&b.im).unwrap());
    assert!(
        (got[0] - Complex::new(0.0, 1.0 - g)).norm() < 1e-12,
        "{got:?}"
    );
    assert!((got[1] - Complex::new(0.0, g)).norm() < 1e-12, "{got:?}");
}

#[test]
fn pzmap_poles_are_eigenvalues_property() {
    // random 3x3 matrices over Q(i) and Q(sqrt 2): every pole z satisfies det(zI - A) ~ 0,
    // the pole count is n, and the zeros are those of the exact zero polynomial
    let mut rng = SplitMix64(24);
    for case in 0..12 {
        let unit = if case % 2 == 0 { "i" } else { "sqrt(2)" };
        let rows: Vec<String> = (0..3)
            .map(|_| {
                let r: Vec<String> = (0..3)
                    .map(|_| format!("\"{}\"", entry(&mut rng, unit)))
                    .collect();
                format!("[{}]", r.join(", "))
            })
            .collect();
        let text = format!(
            r#"{{"A": [{}], "B": [[1], [0], [1]], "C": [[0, 1, 1]], "D": [[0]]}}"#,
            rows.join(", ")
        );
        let s = sys_of(&text);
        let r = run(&["pzmap", "x.json"], &s).unwrap();
        assert_eq!(r["exact"], Value::Bool(true), "{text}");
        let count: u64 = r["poles"]
            .as_array()
            .unwrap()
            .iter()
            .map(|p| p["multiplicity"].as_u64().unwrap())
            .sum();
        assert_eq!(count, 3, "{text}");
        // the float image of A: det(zI - A) vanishes at each pole (relative to |A|)
        let a = exactlti::float::to_cmatrix(&match &s.loaded().system {
            exactlti::io::TypedAny::Quadratic(t) => t.ss.a.clone(),
            _ => panic!("a quadratic field"),
        })
        .unwrap();
        for p in r["poles"].as_array().unwrap() {
            let z = approx(p);
            let m = nalgebra::DMatrix::<Complex<f64>>::identity(3, 3) * z - &a;
            let scale = 1.0 + a.norm() + z.norm();
            assert!(m.determinant().norm() < 1e-8 * scale.powi(3), "{text}: {z}");
        }
    }
}

#[test]
fn step_and_impulse_of_a_complex_system_are_complex() {
    // x' = (-1/2 + i) x + u, y = x: impulse e^{lt}, step (e^{lt} - 1)/l
    let s = sys_of(r#"{"A": [["-1/2 + i"]], "B": [[1]], "C": [[1]], "D": [[0]]}"#);
    let l = Complex::new(-0.5, 1.0);
    for (what, f) in [
        (
            "impulse",
            Box::new(|t: f64| (l * t).exp()) as Box<dyn Fn(f64) -> Complex<f64>>,
        ),
        ("step", Box::new(|t: f64| ((l * t).exp() - 1.0) / l)),
    ] {
        let r = run(&[what, "x.json", "--to", "4", "--points", "41"], &s).unwrap();
        assert_eq!(r["stable"], Value::Bool(true));
        let ts = r["times_s"].as_array().unwrap();
        let re = r["response"].as_array().unwrap();
        let im = r["response_imag"].as_array().unwrap();
        assert_eq!(ts.len(), 41);
        for (k, t) in ts.iter().enumerate() {
            let t = t.as_f64().unwrap();
            let y = Complex::new(re[k][0][0].as_f64().unwrap(), im[k][0][0].as_f64().unwrap());
            assert!((y - f(t)).norm() < 1e-10, "{what} at {t}: {y} vs {}", f(t));
        }
    }
    // a real system keeps its real report (no imaginary part)
    let q = sys_of(r#"{"A": [[-1]], "B": [[1]], "C": [[1]], "D": [[0]]}"#);
    let r = run(&["step", "x.json", "--to", "1", "--points", "3"], &q).unwrap();
    assert!(r.get("response_imag").is_none());
}

#[test]
fn sweep_over_quadratic_fields_reads_the_system_at_each_value() {
    // A(c) = [[0, 1], [-2, -c sqrt 2]]: s^2 + c sqrt2 s + 2, at c = 1: -sqrt2/2 +- i sqrt6/2
    let text = r#"{"parameters": {"c": "3"}, "A": [[0, 1], [-2, "-c*sqrt(2)"]], "B": [[0], [1]], "C": [[1, 0]], "D": [[0]]}"#;
    let p = temp_file("q2.json", text);
    let s = System::open(&p, &Options::default()).unwrap();
    let r = run(
        &[
            "sweep",
            p.to_str().unwrap(),
            "--param",
            "c",
            "--from",
            "1",
            "--to",
            "3",
            "--points",
            "3",
        ],
        &s,
    )
    .unwrap();
    let ev = r["eigenvalues_approx"].as_array().unwrap();
    assert_eq!(ev.len(), 3);
    let at = |k: usize| -> Vec<Complex<f64>> {
        ev[k]
            .as_array()
            .unwrap()
            .iter()
            .map(|z| Complex::new(z[0].as_f64().unwrap(), z[1].as_f64().unwrap()))
            .collect()
    };
    for (k, c) in [1.0f64, 2.0, 3.0].iter().enumerate() {
        // roots of s^2 + c sqrt2 s + 2
        let b = c * 2f64.sqrt();
        let d = Complex::new(b * b - 8.0, 0.0).sqrt();
        let want = [(-b - d) / 2.0, (-b + d) / 2.0];
        // (c = 2 is a double root: float accuracy sqrt(eps))
        for w in want {
            assert!(
                at(k).iter().any(|z| (z - w).norm() < 1e-6),
                "c = {c}: {:?} vs {w}",
                at(k)
            );
        }
    }
    assert_eq!(r["stable_points"], 3);
    // over Q(i): A(c) = [[i c]] has the eigenvalue i c (not its conjugate)
    let p = temp_file(
        "qi.json",
        r#"{"parameters": {"c": "1"}, "A": [["i*c"]], "B": [[1]], "C": [[1]], "D": [[0]]}"#,
    );
    let s = System::open(&p, &Options::default()).unwrap();
    let r = run(
        &[
            "sweep",
            p.to_str().unwrap(),
            "--param",
            "c",
            "--from",
            "-1",
            "--to",
            "2",
            "--points",
            "4",
        ],
        &s,
    )
    .unwrap();
    for (k, z) in r["eigenvalues_approx"]
        .as_array()
        .unwrap()
        .iter()
        .enumerate()
    {
        let c = -1.0 + k as f64;
        assert!(
            (z[0][0].as_f64().unwrap()).abs() < 1e-15
                && (z[0][1].as_f64().unwrap() - c).abs() < 1e-12
        );
    }
    // a parameter the file does not have: the answer names those it has
    let e = run(
        &[
            "sweep",
            p.to_str().unwrap(),
            "--param",
            "k",
            "--from",
            "0",
            "--to",
            "1",
        ],
        &s,
    )
    .unwrap_err();
    assert!(
        e.contains("no parameter 'k'") && e.contains("the file has: c"),
        "{e}"
    );
}

#[test]
fn with_values_is_the_file_read_with_at() {
    let text = r#"{"parameters": {"c": "3"}, "A": [[0, 1], [-2, "-c*sqrt(2)"]]}"#;
    let s = sys_of(text);
    let v = s.with_values(&[("c".into(), "1/2".into())]).unwrap();
    let at = Options::from_args(None, Some("c=1/2")).unwrap();
    let w = System::from_text(text, SystemFormat::Json, "x.json", &at).unwrap();
    assert_eq!(v.ground(), w.ground());
    assert_eq!(v.ground().to_string(), "QQ(sqrt(2))");
    assert_eq!(
        format!("{:?}", v.loaded().system),
        format!("{:?}", w.loaded().system)
    );
    // a name that is not a parameter is an error; a system of matrices has no text
    assert!(s.with_values(&[("k".into(), "1".into())]).is_err());
    let m = System::from_typed("m", v.loaded().system.clone());
    assert!(m.with_values(&[("c".into(), "1".into())]).is_err());
}

#[test]
fn dcgain_and_interconnections_run_on_systems_already_read() {
    let g = sys_of(r#"{"A": [[-2]], "B": [[1]], "C": [[3]], "D": [[0]]}"#);
    let r = run(&["dcgain", "g.json"], &g).unwrap();
    assert_eq!(r["verified"], Value::Bool(true));
    assert!(r.to_string().contains("3/2"), "{r}");
    // a file with only D is a static gain for the one reader (and for dcgain)
    let k = temp_file("k.json", r#"{"D": [["5/7"]]}"#);
    let ks = System::open_or_gain(&k, &Options::default()).unwrap();
    assert_eq!(ks.loaded().rational().unwrap().ss.nstates(), 0);
    assert!(System::open(&k, &Options::default()).is_err());
    let r = run(&["dcgain", k.to_str().unwrap()], &ks).unwrap();
    assert!(r.to_string().contains("5/7"), "{r}");
    // feedback of g with k (negative): G/(1 + K G), at s = 0: (3/2)/(1 + 15/14) = 21/29
    let cmd = Command::parse_args(&["feedback", "g.json", "k.json"]).unwrap();
    let out = execute_on_many(&cmd, &[&g, &ks], &RunContext::default()).unwrap();
    assert!(out.verified);
    let fb = out.report.to_json();
    let r = run(&["dcgain", "fb.json"], &sys_of(&written(&fb))).unwrap();
    assert!(r.to_string().contains("21/29"), "{r}");
    // execute_on reads the other files of the command through the one reader
    let gp = temp_file(
        "g.json",
        r#"{"A": [[-2]], "B": [[1]], "C": [[3]], "D": [[0]]}"#,
    );
    let cmd = Command::parse_args(&["series", gp.to_str().unwrap(), k.to_str().unwrap()]).unwrap();
    let out = execute_on(&cmd, &g, &RunContext::default()).unwrap();
    assert!(out.verified);
    // the wrong number of systems is refused
    let e = execute_on_many(&cmd, &[&g], &RunContext::default()).unwrap_err();
    assert!(e.message.contains("needs 2 systems"), "{}", e.message);
}

/// A system file of the matrices `A`, `B`, `C`, `D` of an interconnection report.
fn written(r: &Value) -> String {
    let m = |k: &str| serde_json::to_string(&r[k]).unwrap();
    format!(
        r#"{{"A": {}, "B": {}, "C": {}, "D": {}}}"#,
        m("A"),
        m("B"),
        m("C"),
        m("D")
    )
}
