//! Hardening of the command line (issue 17): the float path's disagreement is visible in the
//! exit status (3), float claims refuted by the exact path are never labelled true, ERA's
//! Hankel size, and bounded work on wide systems.
use crate::common::cli::{self, run};

fn temp_file(name: &str, text: &str) -> std::path::PathBuf {
    cli::temp_file("hardening", name, text)
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

#[test]
fn analyze_names_every_section_it_does_not_compute() {
    // Q(i) entries: the Jordan form and the modal table are computed over Q(i), the real
    // form does not apply (A is not real); no inputs: no realization; B = 0: the SCB does
    // not apply. Each says so; none is silently absent.
    let herm = temp_file(
        "herm.json",
        r#"{"A": [["1", "2+i"], ["2-i", "3"]], "B": [[1], [0]], "C": [[1, 0]]}"#,
    );
    let noin = temp_file(
        "noin.json",
        r#"{"A": [[1, 2, 0], [3, 4, 0], [0, 0, 5]], "B": [[], [], []], "C": [[1, 0, 0]]}"#,
    );
    let zero_b = temp_file("zerob.json", r#"{"A": [[-1]], "B": [[0]], "C": [[1]]}"#);
    let cases: [(&std::path::Path, &[(&str, &str)]); 3] = [
        (&herm, &[]),
        (
            &noin,
            &[
                ("realization", "0 inputs"),
                ("structure", "0 inputs"),
                ("zeros", "0 inputs"),
                ("pbh", "no inputs"),
                ("mechanical", "no inputs"),
            ],
        ),
        (&zero_b, &[("structure", "rank 0"), ("mechanical", "odd")]),
    ];
    for (file, want) in cases {
        let (code, out, err) = run(&["analyze", file.to_str().unwrap(), "--format", "json"]);
        assert_eq!(code, 0, "{file:?}: {err}");
        let j: serde_json::Value = serde_json::from_str(&out).unwrap();
        for key in [
            "system",
            "realization",
            "structure",
            "zeros",
            "jordan",
            "modes",
        ] {
            assert!(j[key].is_object(), "{file:?}: section {key} missing: {j}");
        }
        for (key, why) in want {
            let sec = &j[*key];
            let reason = sec["not_applicable"]
                .as_str()
                .or(sec["error"].as_str())
                .unwrap_or_else(|| panic!("{file:?}: {key} has no reason: {sec}"));
            assert!(reason.contains(why), "{file:?}: {key}: {reason}");
        }
    }
    // the mechanical normal form is exact over Q(i) too (it was skipped with the Jordan form)
    let (_, out, _) = run(&["analyze", herm.to_str().unwrap(), "--format", "json"]);
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["jordan"]["verified"], true, "{j}");
    assert!(
        j["jordan"]["real_form"]["not_applicable"]
            .as_str()
            .unwrap()
            .contains("not real"),
        "{j}"
    );
    assert!(j["modes"]["modes"].is_array(), "{j}");
    assert_eq!(j["mechanical"]["exists"], true, "{j}");
    assert_eq!(j["mechanical"]["verified"], true, "{j}");
    // the file's signal names are part of the report
    let (code, out, err) = run(&["analyze", "data/bicycle-whipple.json", "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(
        j["system"]["input_names"],
        serde_json::json!(["roll torque", "steer torque"])
    );
}

#[test]
fn every_fuzz_reproducer_runs_its_command_within_the_budget() {
    // each tests/data/fuzz_* file with the command it was slow or failing on: exit 0, 3 (the
    // float path disagrees: `check`) or a one-line exit 2 (the --max-seconds bound), never a
    // panic, exit 1 or a hang
    let cases: &[(&[&str], &str)] = &[
        (&["jordan", "--real"], "fuzz_jordan_marking.json"),
        (&["jordan", "--real"], "fuzz_slow_real_jordan.json"),
        (
            &["minreal", "--method", "jordan"],
            "fuzz_slow_real_minreal.json",
        ),
        (&["analyze"], "fuzz_slow_analyze.toml"),
        (&["jordan"], "fuzz_symbolic_jordan_slow.json"),
        (&["check"], "fuzz_huge_entry.toml"),
        (&["tf"], "fuzz_tf_huge_entry.json"),
    ];
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data");
    let mut listed: Vec<&str> = cases.iter().map(|c| c.1).collect();
    listed.sort();
    listed.dedup();
    let mut on_disk: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .filter(|n| n.starts_with("fuzz_"))
        .collect();
    on_disk.sort();
    assert_eq!(listed, on_disk, "a fuzz reproducer without a test");
    for (cmd, file) in cases {
        let mut a = cmd.to_vec();
        let p = format!("tests/data/{file}");
        a.extend([p.as_str(), "--max-seconds", "60"]);
        let (code, _, err) = run(&a);
        assert!(
            code == 0 || ((code == 2 || code == 3) && err.lines().count() == 1),
            "{a:?}: exit {code}: {err}"
        );
        // the file itself is a valid system (not refused by the reader, e.g. a stale key)
        assert!(!err.contains("unknown key"), "{a:?}: {err}");
    }
}

/// The fields each command accepts (issue 17 item 2; docs/hardening.md): exit status over
/// Q, Q(i), Q(sqrt 3) (a Hermitian-type matrix with irrational off-diagonal entries) and
/// Q(p) (`--symbolic`). A refusal is exit 2 with one line naming why; no command answers
/// over a field it does not support. Change a row here when a command gains a field.
#[test]
fn fields_each_command_accepts() {
    let q = temp_file(
        "fq.json",
        r#"{"A": [[-1, 2], [0, -3]], "B": [[1], [1]], "C": [[1, 0]]}"#,
    );
    let qi = temp_file(
        "fqi.json",
        r#"{"A": [["1", "2+i"], ["2-i", "3"]], "B": [[1], [0]], "C": [[1, 0]]}"#,
    );
    let qs = temp_file(
        "fqs.json",
        r#"{"A": [["1", "2+sqrt(3)"], ["2-sqrt(3)", "3"]], "B": [[1], [0]], "C": [[1, 0]]}"#,
    );
    let qp = "tests/data/everyday/quarter_car.json";
    // command, exit over [Q, Q(i), Q(sqrt 3), Q(p)]
    let table: &[(&str, [i32; 4])] = &[
        ("jordan", [0, 0, 0, 0]),
        ("jordan --real", [0, 2, 0, 2]),
        ("jordan --real --expand", [0, 2, 0, 2]),
        ("minreal", [0, 0, 0, 0]),
        ("minreal --method rosenbrock", [0, 0, 0, 0]),
        ("minreal --method ho-kalman", [0, 0, 0, 0]),
        ("minreal --method jordan", [0, 0, 0, 0]),
        ("minreal --method era", [0, 0, 0, 2]),
        ("standard", [0, 0, 0, 0]),
        ("scb", [0, 0, 0, 0]),
        ("mnf", [0, 0, 0, 0]),
        ("zeros", [0, 0, 0, 0]),
        ("pencil", [0, 0, 0, 0]), // the Kronecker structure over Q(p) (issue 24)
        ("ctrb", [0, 0, 0, 0]),
        ("obsv", [0, 0, 0, 0]),
        ("tf", [0, 0, 0, 0]),
        ("modes", [0, 0, 0, 0]),
        ("freqresp --points 5", [0, 0, 0, 2]),
        ("check", [0, 0, 0, 2]),
        ("linalg det", [0, 0, 0, 0]),
        ("linalg rank", [0, 0, 0, 0]),
        ("linalg charpoly", [0, 0, 0, 0]),
        ("linalg minpoly", [0, 0, 0, 0]),
        ("linalg inverse", [0, 0, 0, 0]),
        ("linalg nullspace", [0, 0, 0, 0]),
        ("linalg rref", [0, 0, 0, 0]),
        ("analyze", [0, 0, 0, 0]),
    ];
    let files = [
        q.to_str().unwrap(),
        qi.to_str().unwrap(),
        qs.to_str().unwrap(),
        qp,
    ];
    let mut wrong = vec![];
    for (cmd, want) in table {
        for (k, file) in files.iter().enumerate() {
            let mut a: Vec<&str> = cmd.split(' ').collect();
            a.push(file);
            if k == 3 {
                a.push("--symbolic");
            }
            let (code, _, err) = run(&a);
            if code != want[k] {
                wrong.push(format!("{a:?}: exit {code}, table says {}: {err}", want[k]));
            } else if code == 2 {
                assert_eq!(err.lines().count(), 1, "{a:?}: {err}");
            }
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}
