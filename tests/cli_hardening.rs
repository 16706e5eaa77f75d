//! Hardening of the command line (issue 17): the float path's disagreement is visible in the
//! exit status (3), float claims refuted by the exact path are never labelled true, ERA's
//! Hankel size, and bounded work on wide systems.
use std::process::Command;

fn run(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_exactlti"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn temp_file(name: &str, text: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("exactlti-hardening-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

/// Every comparison in a `check` report: a disagreement never carries float_truth "true".
fn assert_no_refuted_true(j: &serde_json::Value) {
    for (k, v) in j["comparisons"].as_object().unwrap() {
        if v["agree"] == false {
            assert_ne!(v["float_truth"], "true", "{k}: {v}");
        }
        if let Some(evs) = v["eigenvalues"].as_array() {
            for e in evs {
                if e["agree"] == false {
                    assert_ne!(e["float_truth"], "true", "{k}: {e}");
                }
            }
        }
    }
}

#[test]
fn check_exits_3_when_float_disagrees_and_never_labels_a_refuted_claim_true() {
    // ERA with a too small Hankel matrix disagrees: exit 3 and the report still printed
    let (code, out, err) = run(&[
        "minreal",
        "data/sliding-masses.json",
        "--method",
        "era",
        "--hankel",
        "5",
        "--format",
        "json",
    ]);
    assert_eq!(code, 3, "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["agree_with_exact"], false);
    assert_ne!(j["truth"], "true");
    assert!(
        j.get("A").is_none(),
        "a contradicted float result is not printed as an answer"
    );
    // Wilkinson's W20 (MATLAB wilkinson(20)): pairs 7.7e-13 apart, each eigenvalue simple
    let n = 20;
    let rows: Vec<Vec<String>> = (0..n)
        .map(|i: usize| {
            (0..n)
                .map(|j| {
                    if i == j {
                        format!("{}/2", (2 * i as i64 - 19).abs())
                    } else if i.abs_diff(j) == 1 {
                        "1".into()
                    } else {
                        "0".into()
                    }
                })
                .collect()
        })
        .collect();
    let w = temp_file("w20.json", &serde_json::json!({ "A": rows }).to_string());
    let (code, out, err) = run(&["check", w.to_str().unwrap(), "--format", "json"]);
    assert!(code == 0 || code == 3, "{code}: {err}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_no_refuted_true(&j);
    assert_eq!(code == 3, j["agree"] == false);
    // diag(-1e20, -2e20) with B = [1; 1]: float used to claim rank 0 as true
    let f = temp_file(
        "diag.json",
        r#"{"A": [[-1e20, 0], [0, -2e20]], "B": [[1], [1]], "C": [[1, 1]]}"#,
    );
    let (code, out, err) = run(&["check", f.to_str().unwrap(), "--format", "json"]);
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_no_refuted_true(&j);
    assert_eq!(j["comparisons"]["controllability_rank"]["float"], 2, "{j}");
    assert_eq!(code == 3, j["agree"] == false, "{err}");
}

#[test]
fn era_order_matches_mcmillan_degree_on_the_sliding_masses() {
    let (code, out, err) = run(&[
        "minreal",
        "data/sliding-masses.json",
        "--method",
        "era",
        "--format",
        "json",
    ]);
    assert_eq!(code, 0, "{err}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["order"], 8);
    assert_eq!(j["mcmillan_degree"], 8);
    assert_eq!(j["truth"], "true");
    assert_eq!(j["rank_stabilised"], true);
    assert!(j["gap_ratio"].as_f64().unwrap() > 1e6);
    assert_eq!(j["A"].as_array().unwrap().len(), 8);
    let (code, out, _) = run(&["check", "data/sliding-masses.json", "--format", "json"]);
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["comparisons"]["era_order"]["float"], 8);
    assert_eq!(code == 3, j["agree"] == false);
}

#[test]
fn era_on_a_very_wide_system_is_refused_with_exit_2() {
    let b: Vec<i32> = vec![1; 20000];
    let c: Vec<Vec<i32>> = vec![vec![1]; 200];
    let f = temp_file(
        "wide.json",
        &serde_json::json!({"A": [[-1]], "B": [b], "C": c}).to_string(),
    );
    let (code, _, err) = run(&["minreal", "--method", "era", f.to_str().unwrap()]);
    assert_eq!(code, 2, "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("Hankel"), "{err}");
}

#[test]
fn fuzz_crashers_stay_fixed() {
    // tests/data/fuzz_huge_entry.toml: an entry 1e300 hung the float eigenvalues (balancing)
    for cmd in [
        &["check"][..],
        &["minreal", "--method", "era"],
        &["freqresp"],
    ] {
        let mut a = cmd.to_vec();
        a.extend(["tests/data/fuzz_huge_entry.toml", "--max-seconds", "20"]);
        let (code, _, err) = run(&a);
        assert!([0, 2, 3].contains(&code), "{a:?}: {code} {err}");
    }
    // E = 0: no finite dynamics; freqresp is G = D (it panicked in nalgebra's LU)
    let f = temp_file(
        "e0.json",
        r#"{"E": [[0]], "A": [[1]], "B": [[1]], "C": [[1]]}"#,
    );
    let (code, _, err) = run(&["freqresp", f.to_str().unwrap(), "--points", "3"]);
    assert_eq!(code, 0, "{err}");
}
