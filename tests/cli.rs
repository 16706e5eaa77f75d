//! End-to-end runs of the `exactlti` binary: outputs, JSON fields and exit codes.
use crate::common::cli::run;

fn json(args: &[&str]) -> serde_json::Value {
    crate::common::cli::run_json(args)
}

#[test]
fn minreal_sliding_masses_every_exact_method() {
    for m in ["kalman", "rosenbrock", "ho-kalman", "jordan"] {
        let j = json(&["minreal", "data/sliding-masses.json", "--method", m]);
        assert_eq!(j["order"], 8, "method {m}");
        assert_eq!(j["mcmillan_degree"], 8);
        assert_eq!(j["verified"], true);
        assert_eq!(j["A"].as_array().unwrap().len(), 8);
        assert_eq!(j["A_approx"].as_array().unwrap().len(), 8);
    }
    let j = json(&["minreal", "data/sliding-masses.json", "--method", "jordan"]);
    assert_eq!(j["stages"], serde_json::json!([20, 16, 8]));
}

#[test]
fn linalg_commands() {
    let f = "tests/data/yaw_contract.json";
    assert_eq!(
        json(&["linalg", "charpoly", f])["charpoly"],
        "x^4 + 8/3*x^3"
    );
    assert_eq!(json(&["linalg", "rank", f])["rank"], 3);
    assert_eq!(json(&["linalg", "det", f])["det"], "0");
    assert_eq!(json(&["linalg", "minpoly", f])["minpoly"], "x^4 + 8/3*x^3");
    assert_eq!(
        json(&["linalg", "nullspace", f])["basis"]
            .as_array()
            .unwrap()
            .len(),
        1
    );
    let r = json(&["linalg", "rref", f]);
    assert_eq!(r["rank"], 3);
    let (code, _, err) = run(&["linalg", "inverse", f]);
    assert_eq!(code, 2);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("singular"), "{err}");
}

#[test]
fn bad_input_exits_2_with_one_line() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data");
    for entry in std::fs::read_dir(&dir).unwrap() {
        let p = entry.unwrap().path();
        let name = p.file_name().unwrap().to_string_lossy().into_owned();
        if !name.starts_with("invalid_") {
            continue;
        }
        let (code, out, err) = run(&["minreal", p.to_str().unwrap()]);
        assert_eq!(code, 2, "{name}: {err}");
        assert!(out.is_empty(), "{name}");
        assert_eq!(err.trim_end().lines().count(), 1, "{name}: {err}");
        assert!(err.contains(&name), "{name}: message names the file: {err}");
    }
    let (code, _, err) = run(&["minreal", "no/such/file.json"]);
    assert_eq!(code, 2);
    assert_eq!(err.trim_end().lines().count(), 1);
    let (code, _, _) = run(&["nonsense"]);
    assert_eq!(code, 2);
}

#[test]
fn standard_form_of_a_plain_system_is_itself() {
    let j = json(&["standard", "tests/data/yaw_contract.json"]);
    assert_eq!(j["order"], 4);
    assert_eq!(j["removed_infinite"], 0);
}

#[test]
fn latex_and_text_formats() {
    let (code, out, _) = run(&[
        "minreal",
        "tests/data/yaw_contract.json",
        "--format",
        "latex",
    ]);
    assert_eq!(code, 0);
    assert!(out.contains("\\begin{bmatrix}"));
    let (code, out, _) = run(&["minreal", "tests/data/yaw_contract.json"]);
    assert_eq!(code, 0);
    assert!(out.contains("order:"));
}

#[test]
fn structure_commands() {
    let j = json(&["scb", "data/sliding-masses.json"]);
    assert_eq!(j["verified"], true);
    let dims = &j["dims"];
    let total: i64 = ["a", "b", "c", "d"]
        .iter()
        .map(|k| dims[k].as_i64().unwrap())
        .sum();
    assert_eq!(total, 20);
    for k in [
        "G1",
        "G2",
        "G3",
        "U",
        "Y",
        "A",
        "B",
        "C",
        "D",
        "chains",
        "invariant_zeros",
        "left_invertible",
        "right_invertible",
    ] {
        assert!(j.get(k).is_some(), "scb key {k}");
    }
    let z = json(&["zeros", "data/sliding-masses.json"]);
    assert!(z["invariant_zeros"].is_array());
    let m = json(&["mnf", "tests/data/mass_spring.json"]);
    assert_eq!(m["exists"], true);
    assert_eq!(m["verified"], true);
    for k in [
        "mass",
        "damping",
        "stiffness",
        "input",
        "output",
        "feedthrough",
        "T",
        "reason",
    ] {
        assert!(m.get(k).is_some(), "mnf key {k}");
    }
    // an odd number of states has no mechanical normal form: exists = false, not an error
    let m = json(&["mnf", "tests/data/vehicle_eq11.json"]);
    assert_eq!(m["exists"], false);
    assert!(m["reason"].is_string());
}

#[test]
fn float_commands() {
    let c = json(&["check", "data/sliding-masses.json"]);
    assert!(c["agree"].is_boolean());
    assert!(c["differences"].is_array());
    assert_eq!(c["comparisons"]["minreal_order"]["exact"], 8);
    let e = json(&["minreal", "data/sliding-masses.json", "--method", "era"]);
    assert_eq!(e["mcmillan_degree"], 8);
    assert_eq!(e["exact"], false);
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"));
    let svg = dir.join("exactlti-test.svg");
    let csv = dir.join("exactlti-test.csv");
    let f = json(&[
        "freqresp",
        "data/sliding-masses.json",
        "--points",
        "50",
        "--svg",
        svg.to_str().unwrap(),
        "--csv",
        csv.to_str().unwrap(),
    ]);
    assert_eq!(f["frequencies_hz"].as_array().unwrap().len(), 50);
    assert_eq!(f["response"][0][0][0].as_array().unwrap().len(), 2);
    assert!(std::fs::read_to_string(&svg).unwrap().contains("<svg"));
    assert_eq!(std::fs::read_to_string(&csv).unwrap().lines().count(), 51);
    let (code, _, err) = run(&["freqresp", "data/sliding-masses.json", "--from", "-1"]);
    assert_eq!(code, 2, "{err}");
}

#[test]
fn poly_commands() {
    let f = json(&[
        "poly",
        "factor",
        "((s^2+1)*(s^2+2)*(s^2+3)*(s^4+4*s^2+1))^2",
    ]);
    let factors = f["factors"].as_array().unwrap();
    assert_eq!(factors.len(), 4);
    assert!(factors.iter().all(|x| x["multiplicity"] == 2));
    assert!(factors.iter().any(|x| x["poly"] == "x^4 + 4*x^2 + 1"));
    let r = json(&["poly", "roots", "x^2 - x - 1"]);
    let roots = r["roots"].as_array().unwrap();
    assert_eq!(roots.len(), 2);
    assert_eq!(roots[1]["value"], "1/2 + sqrt(5)/2");
    assert!((roots[1]["approx"][0].as_f64().unwrap() - 1.618033988749895).abs() < 1e-15);
    // the biquadratic case in the Jordan form's nested radicals (one display per number)
    let r = json(&["poly", "roots", "x^4 + 4*x^2 + 1"]);
    let shown: Vec<&str> = r["roots"]
        .as_array()
        .unwrap()
        .iter()
        .map(|z| z["value"].as_str().unwrap())
        .collect();
    assert_eq!(
        shown,
        [
            "-i*sqrt(2 + sqrt(3))",
            "-i*sqrt(2 - sqrt(3))",
            "i*sqrt(2 - sqrt(3))",
            "i*sqrt(2 + sqrt(3))"
        ]
    );
    // multivariate input is valid since the second wave (`poly factor "x + y"`)
    for bad in ["x^", "x + * y", "", "(x"] {
        let (code, _, err) = run(&["poly", "factor", bad]);
        assert_eq!(code, 2, "{bad}: {err}");
        assert_eq!(err.trim_end().lines().count(), 1);
    }
}

#[test]
fn modes_command() {
    let m = json(&["modes", "data/sliding-masses.json"]);
    let modes = m["modes"].as_array().unwrap();
    assert_eq!(modes.len(), 5);
    for k in [
        "eigenvalue",
        "frequency_hz",
        "damping_ratio",
        "time_constant_s",
        "period_s",
    ] {
        assert!(modes[0].get(k).is_some(), "{k}");
    }
}

#[test]
fn jordan_and_check_commands() {
    let j = json(&["jordan", "tests/data/vehicle_eq11.json"]);
    assert_eq!(j["verified"], true);
    let evs = j["eigenvalues"].as_array().unwrap();
    assert_eq!(evs.len(), 3);
    for k in [
        "minpoly",
        "value",
        "approx",
        "algebraic_multiplicity",
        "geometric_multiplicity",
        "blocks",
    ] {
        assert!(evs[0].get(k).is_some(), "eigenvalue key {k}");
    }
    assert!(evs.iter().any(|e| e["value"] == "-1 + i"));
    assert!(j["J_approx"].is_array() && j["T_approx"].is_array());
    let r = json(&["jordan", "--real", "tests/data/vehicle_eq11.json"]);
    assert_eq!(r["verified"], true);
    assert_eq!(
        r["J"],
        serde_json::json!([["-2", "0", "0"], ["0", "-1", "1"], ["0", "-1", "-1"]])
    );
    // the scrambled 3x3 nilpotent block: exact path one block [3]; float sees a scattered triple
    let c = json(&["check", "tests/data/yaw_scrambled.json"]);
    let js = &c["comparisons"]["jordan_structure"];
    assert_eq!(js["exact_verified"], true);
    assert!(
        js["max_float_eigenvalue_error"].as_f64().unwrap() > 1e-8,
        "float scatters the triple zero"
    );
    assert!(!js["float_warnings"].as_array().unwrap().is_empty());
    let e0 = js["eigenvalues"]
        .as_array()
        .unwrap()
        .iter()
        .find(|e| e["eigenvalue"] == "0")
        .unwrap();
    assert_eq!(e0["exact_blocks"], serde_json::json!([3]));
    let (code, _, err) = run(&["jordan", "tests/data/invalid_shape.json"]);
    assert_eq!(code, 2, "{err}");
}

#[test]
fn max_seconds_bounds_the_exact_work() {
    // Every computed section of this 16-state MIMO system needs far more than the bound (the
    // first takes over 0.2 s in a test build, 200 times 1 ms), and what arrives after the
    // bound is never printed, so the outcome does not depend on the machine's load.
    let f = "tests/data/everyday/random_16_mimo.json";
    let (code, out, err) = run(&["analyze", f, "--max-seconds", "0.001"]);
    assert_eq!(code, 2, "{err}");
    // What finished before the bound is printed: at most the report's title and the system's
    // description (a race with loading the file), never a computed section.
    for header in out.lines().filter(|l| l.starts_with("== ")) {
        assert!(
            header.starts_with("== exactlti analysis") || header == "== system ==",
            "{out}"
        );
    }
    assert!(err.contains("--max-seconds"), "{err}");
    assert_eq!(err.trim_end().lines().count(), 1);
}
