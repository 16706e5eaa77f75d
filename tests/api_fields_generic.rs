//! The api's commands written once over the ground field (issue 23: no type probing in the
//! api): `response --x0 --times`, `response --steps`, `margin`, `damp`, `pzmap`, `check` run
//! over $\mathbb{Q}$, $\mathbb{Q}(\sqrt 2)$ and $\mathbb{Q}(i)$ from one generic test each,
//! and over $\mathbb{Q}(p)$ the one refusal line of a command that needs numbers.
//!
//! Identities asserted: the free response at `t` equals $e^{At} x_0$ (a Taylor series of the
//! embedded matrix, independent of the exact path), its imaginary part is reported exactly
//! when $A$ or $x_0$ is not real; `--x0` entries in the system's field (radicals, `i`) are
//! read exactly (the reported `x0` is the one given); the damping table's $\omega_n$ is
//! $|\lambda|$ of the poles `pzmap` reports; `check` agrees with the exact path.

use exactlti::api::{Command, Options, RunContext, System, execute_on};
use exactlti::io::SystemFormat;
use exactlti::rng::SplitMix64;
use num_complex::Complex64;
use serde_json::Value;

/// The three numeric fields, by the unit their entries use (`1`: Q).
const UNITS: [&str; 3] = ["1", "sqrt(2)", "i"];

fn sys_of(text: &str) -> System {
    System::from_text(text, SystemFormat::Json, "x.json", &Options::default()).unwrap()
}

fn run(args: &[&str], sys: &System) -> Result<(Value, bool), String> {
    let cmd = Command::parse_args(args).map_err(|e| e.to_string())?;
    execute_on(&cmd, sys, &RunContext::default())
        .map(|o| (o.report.to_json(), o.verified))
        .map_err(|f| f.message)
}

/// The embedding of an exact entry written `a + b*unit`.
fn embed(a: i64, b: i64, unit: &str) -> Complex64 {
    let u = match unit {
        "1" => Complex64::new(1.0, 0.0),
        "sqrt(2)" => Complex64::new(2f64.sqrt(), 0.0),
        _ => Complex64::new(0.0, 1.0),
    };
    Complex64::new(a as f64, 0.0) + u * b as f64
}

/// $e^{At} x_0$ by a Taylor series in complex floats (the matrices are small, $|At|$ small).
fn expm_times(a: &[Vec<Complex64>], x0: &[Complex64], t: f64) -> Vec<Complex64> {
    let n = x0.len();
    let mut term = x0.to_vec();
    let mut sum = x0.to_vec();
    for k in 1..80 {
        let next: Vec<Complex64> = (0..n)
            .map(|i| (0..n).map(|j| a[i][j] * term[j]).sum::<Complex64>() * (t / k as f64))
            .collect();
        term = next;
        for i in 0..n {
            sum[i] += term[i];
        }
    }
    sum
}

/// A random `n x n` system over the field of `unit` (entries `a + b*unit`) and an initial
/// state in the same field: the file text, the embedded `A` and `x0`, and `--x0`.
fn random_case(
    rng: &mut SplitMix64,
    n: usize,
    unit: &str,
) -> (String, Vec<Vec<Complex64>>, Vec<Complex64>, String) {
    let mut rows = vec![];
    let mut a = vec![];
    for _ in 0..n {
        let mut row = vec![];
        let mut arow = vec![];
        for _ in 0..n {
            let (p, q) = (rng.int(-2, 2), if unit == "1" { 0 } else { rng.int(-1, 1) });
            row.push(format!("\"{p} + {q}*{unit}\""));
            arow.push(embed(p, q, unit));
        }
        rows.push(format!("[{}]", row.join(", ")));
        a.push(arow);
    }
    let mut xs = vec![];
    let mut x0 = vec![];
    for _ in 0..n {
        let (p, q) = (rng.int(-2, 2), if unit == "1" { 0 } else { rng.int(-2, 2) });
        // over Q `--x0` takes numbers; over Q(sqrt 2), Q(i) expressions in the field
        xs.push(if unit == "1" {
            format!("{p}")
        } else {
            format!("{p} + {q}*{unit}")
        });
        x0.push(embed(p, q, unit));
    }
    let text = format!("{{\"A\": [{}]}}", rows.join(", "));
    (text, a, x0, xs.join(", "))
}

/// `x(t)` of the report (`x`, and `x_imag` when present) at the `k`-th time.
fn reported(r: &Value, k: usize) -> (f64, Vec<Complex64>, bool) {
    let v = &r["values"][k];
    let re: Vec<f64> = v["x"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    let im: Option<Vec<f64>> = v.get("x_imag").map(|xs| {
        xs.as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_f64().unwrap())
            .collect()
    });
    let z = re
        .iter()
        .enumerate()
        .map(|(i, &x)| Complex64::new(x, im.as_ref().map_or(0.0, |m| m[i])))
        .collect();
    (v["t"].as_f64().unwrap(), z, im.is_some())
}

#[test]
fn response_times_equals_the_matrix_exponential_over_every_field() {
    let mut rng = SplitMix64(23);
    for unit in UNITS {
        for n in [1usize, 2, 3] {
            let (text, a, x0, xs) = random_case(&mut rng, n, unit);
            let sys = sys_of(&text);
            let (r, ok) = run(
                &["response", "x.json", "--x0", &xs, "--times", "0,0.25,0.7"],
                &sys,
            )
            .unwrap_or_else(|e| panic!("{unit} {text} x0 {xs}: {e}"));
            assert!(ok, "{unit} {text}: not verified");
            assert_eq!(r["verified"], Value::Bool(true));
            let real = a.iter().flatten().chain(&x0).all(|z| z.im == 0.0);
            for k in 0..3 {
                let (t, got, has_imag) = reported(&r, k);
                assert_eq!(
                    has_imag, !real,
                    "{unit} {text}: x_imag exactly when complex"
                );
                let want = expm_times(&a, &x0, t);
                let scale = 1.0 + want.iter().map(|z| z.norm()).fold(0.0, f64::max);
                for (g, w) in got.iter().zip(&want) {
                    assert!(
                        (g - w).norm() <= 1e-9 * scale,
                        "{unit} {text} x0 {xs} t={t}: {got:?} vs {want:?}"
                    );
                }
            }
        }
    }
}

#[test]
fn response_x0_with_radicals_is_read_in_the_systems_field() {
    // A over Q(sqrt 2), x0 = (1 + sqrt 2, -sqrt(2)/2): exact x0 in the report, x(0) = x0
    let sys = sys_of(r#"{"A": [["-sqrt(2)", 1], [0, -1]]}"#);
    let (r, ok) = run(
        &[
            "response",
            "x.json",
            "--x0",
            "1 + sqrt(2), -sqrt(2)/2",
            "--times",
            "0",
        ],
        &sys,
    )
    .unwrap();
    assert!(ok);
    let x0: Vec<&str> = r["x0"]
        .as_array()
        .unwrap()
        .iter()
        .map(|row| row[0].as_str().unwrap())
        .collect();
    assert_eq!(x0, ["1 + sqrt(2)", "-sqrt(2)/2"]);
    let (_, x, _) = reported(&r, 0);
    assert!(
        (x[0].re - (1.0 + 2f64.sqrt())).abs() < 1e-12
            && (x[1].re + 2f64.sqrt() / 2.0).abs() < 1e-12
    );
    // over Q(i): i in x0; a radical of another field is refused with one line
    let sys = sys_of(r#"{"A": [["i", 1], [0, -1]]}"#);
    let (r, ok) = run(
        &["response", "x.json", "--x0", "i, 1 - i", "--times", "1"],
        &sys,
    )
    .unwrap();
    assert!(ok);
    let (_, x, imag) = reported(&r, 0);
    assert!(imag);
    let a = vec![
        vec![Complex64::new(0.0, 1.0), Complex64::new(1.0, 0.0)],
        vec![Complex64::new(0.0, 0.0), Complex64::new(-1.0, 0.0)],
    ];
    let want = expm_times(
        &a,
        &[Complex64::new(0.0, 1.0), Complex64::new(1.0, -1.0)],
        1.0,
    );
    assert!(
        (x[0] - want[0]).norm() < 1e-10 && (x[1] - want[1]).norm() < 1e-10,
        "{x:?} {want:?}"
    );
    let err = run(&["response", "x.json", "--x0", "sqrt(3), 0"], &sys).unwrap_err();
    assert!(
        err.contains("--x0 entry \"sqrt(3)\"") && !err.contains('\n'),
        "{err}"
    );
}

#[test]
fn response_steps_reads_x0_in_the_field() {
    for (text, x0) in [
        (r#"{"A": [[0, 1], [-2, -3]]}"#, "1, -1/2"),
        (r#"{"A": [["-sqrt(2)", 1], [0, -1]]}"#, "1 + sqrt(2), 1"),
        (r#"{"A": [["i", 1], [0, -1]]}"#, "i, 2"),
    ] {
        let sys = sys_of(text);
        let cmd = Command::parse_args(&["response", "x.json", "--x0", x0]).unwrap();
        let s = exactlti::api::steps::steps_on(&cmd, &sys)
            .unwrap_or_else(|f| panic!("{text}: {}", f.message));
        assert!(s.verified, "{text}: every identity of the derivation holds");
    }
}

#[test]
fn damp_and_pzmap_agree_over_every_field() {
    // poles of a companion matrix s^2 + c1 s + c0 with c in the field: damp's wn = |pole|
    for (unit, c1, c0) in [
        ("1", "3", "2"),
        ("sqrt(2)", "sqrt(2)", "1"),
        ("i", "1 + i", "2"),
    ] {
        let text = format!(
            r#"{{"A": [[0, 1], ["-({c0})", "-({c1})"]], "B": [[0], [1]], "C": [[1, 0]], "D": [[0]]}}"#
        );
        let sys = sys_of(&text);
        let (pz, _) = run(&["pzmap", "x.json"], &sys).unwrap();
        assert_eq!(pz["exact"], Value::Bool(true), "{unit}");
        let mut poles: Vec<f64> = pz["poles"]
            .as_array()
            .unwrap()
            .iter()
            .map(|p| {
                let a = p["approx"].as_array().unwrap();
                Complex64::new(a[0].as_f64().unwrap(), a[1].as_f64().unwrap()).norm()
            })
            .collect();
        let (d, _) = run(&["damp", "x.json"], &sys).unwrap_or_else(|e| panic!("{unit}: {e}"));
        let rows = d
            .as_object()
            .unwrap()
            .values()
            .find_map(|v| v.as_array())
            .expect("a table");
        let mut wn: Vec<f64> = rows
            .iter()
            .filter_map(|r| {
                r.get("wn_rad_s")
                    .or_else(|| r.get("natural_frequency_rad_s"))
                    .and_then(Value::as_f64)
            })
            .collect();
        poles.sort_by(f64::total_cmp);
        wn.sort_by(f64::total_cmp);
        assert_eq!(wn.len(), poles.len(), "{unit}: {d}");
        for (w, p) in wn.iter().zip(&poles) {
            assert!(
                (w - p).abs() < 1e-9 * (1.0 + p),
                "{unit}: wn {wn:?} poles {poles:?}"
            );
        }
        // margins exist on every numeric field (exact crossovers)
        let (m, ok) = run(&["margin", "x.json"], &sys).unwrap_or_else(|e| panic!("{unit}: {e}"));
        assert!(ok, "{unit}: {m}");
        // the float path agrees with the exact one
        let (c, agree) = run(&["check", "x.json"], &sys).unwrap_or_else(|e| panic!("{unit}: {e}"));
        assert!(agree, "{unit}: {c}");
    }
}

#[test]
fn numbers_asked_of_symbols_are_refused_in_one_line() {
    let sys = sys_of(
        r#"{"parameters": {"m": null, "u": null}, "A": [[0, 1], ["-1/m", "-u"]], "B": [[0], [1]], "C": [[1, 0]], "D": [[0]]}"#,
    );
    for cmd in ["margin", "damp", "pzmap", "check"] {
        let err = run(&[cmd, "x.json"], &sys).unwrap_err();
        assert!(
            err.contains(&format!("`{cmd}` needs numbers"))
                && err.contains("QQ(m, u)")
                && err.contains("--at")
                && !err.contains('\n'),
            "{cmd}: {err}"
        );
    }
    // with values the same commands run, over Q
    let at = Options::from_args(None, Some("m=2, u=3")).unwrap();
    let text = r#"{"parameters": {"m": null, "u": null}, "A": [[0, 1], ["-1/m", "-u"]], "B": [[0], [1]], "C": [[1, 0]], "D": [[0]]}"#;
    let sys = System::from_text(text, SystemFormat::Json, "x.json", &at).unwrap();
    for cmd in ["margin", "damp", "pzmap"] {
        assert!(run(&[cmd, "x.json"], &sys).is_ok(), "{cmd}");
    }
}
