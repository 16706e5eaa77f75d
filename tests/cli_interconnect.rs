//! `exactlti series|parallel|feedback|append`: reports, the `--out` system file read back,
//! `--minreal` after feedback (the classic cancellation), fields (Q, Q(sqrt 2), Q(a, k)),
//! static gains (a file with only `D`), and one-line refusals with exit status 2.

use crate::common::cli::{run, temp_file};
use exactlti::field::ElemDisplay;
use exactlti::io::symbolic::{SymbolicOptions, load_symbolic_path};
use exactlti::io::{TypedAny, load_system_path};
use std::path::PathBuf;

const D: &str = "tests/data/interconnect";

fn json(args: &[&str]) -> serde_json::Value {
    crate::common::cli::run_json(args)
}

fn data(name: &str) -> String {
    format!("{D}/{name}")
}

/// A fresh path for `--out` in this module's temp directory.
fn out_path(name: &str) -> PathBuf {
    let p = temp_file("interconnect", name, "");
    std::fs::remove_file(&p).unwrap();
    p
}

/// Exit 2 and exactly one line on stderr containing `needle`.
fn refused(args: &[&str], needle: &str) {
    let (code, out, err) = run(args);
    assert_eq!(code, 2, "{args:?}: {out}");
    assert_eq!(err.trim_end().lines().count(), 1, "one line: {err}");
    assert!(err.contains(needle), "{args:?}: {err}");
}

#[test]
fn feedback_then_minreal_drops_the_cancelled_pole() {
    let l = out_path("L.json");
    let j = json(&[
        "series",
        &data("plant.json"),
        &data("pi.json"),
        "--out",
        l.to_str().unwrap(),
    ]);
    assert_eq!(
        (j["states"].as_u64(), j["verified"].as_bool()),
        (Some(3), Some(true))
    );
    assert_eq!(j["transfer_matrix"], "G = G2 G1");
    let t = out_path("T.json");
    let j = json(&[
        "feedback",
        l.to_str().unwrap(),
        &data("unity.json"),
        "--minreal",
        "--out",
        t.to_str().unwrap(),
    ]);
    assert_eq!(j["sign"], -1);
    assert_eq!(j["states"], 3);
    assert_eq!(j["verified"], true);
    assert_eq!(j["minimal"]["order"], 2);
    assert_eq!(j["minimal"]["verified"], true);
    // the written minimal realization reads back, with the closed loop 10/(s^2 + 2 s + 10)
    let back = load_system_path(&t).unwrap();
    let r = back.rational().unwrap();
    assert_eq!(r.ss.nstates(), 2);
    assert_eq!(
        serde_json::json!(r.ss.a.to_rows_strings()),
        j["minimal"]["A"]
    );
    let tf = json(&["tf", t.to_str().unwrap()]);
    assert_eq!(
        tf["transfer_matrix"],
        serde_json::json!([["(10)/(s^2 + 2*s + 10)"]])
    );
}

#[test]
fn written_system_reads_back_to_the_same_matrices() {
    let o = out_path("fb.json");
    let j = json(&[
        "feedback",
        &data("plant.json"),
        &data("pi.json"),
        "--positive",
        "--out",
        o.to_str().unwrap(),
    ]);
    assert_eq!(j["sign"], 1);
    let r = load_system_path(&o).unwrap();
    let s = &r.rational().unwrap().ss;
    for (key, m) in [("A", &s.a), ("B", &s.b), ("C", &s.c), ("D", &s.d)] {
        assert_eq!(serde_json::json!(m.to_rows_strings()), j[key], "{key}");
    }
}

#[test]
fn parallel_append_and_formats() {
    let j = json(&["parallel", &data("plant.json"), &data("pi.json")]);
    assert_eq!(
        (j["states"].as_u64(), j["verified"].as_bool()),
        (Some(3), Some(true))
    );
    let j = json(&[
        "append",
        &data("plant.json"),
        &data("pi.json"),
        &data("unity.json"),
    ]);
    assert_eq!(
        (j["inputs"].as_u64(), j["outputs"].as_u64()),
        (Some(3), Some(3))
    );
    assert_eq!(j["parts"].as_array().unwrap().len(), 3);
    for fmt in ["text", "latex"] {
        let (code, out, err) = run(&[
            "feedback",
            &data("plant.json"),
            &data("unity.json"),
            "--minreal",
            "--format",
            fmt,
        ]);
        assert_eq!(code, 0, "{err}");
        assert!(out.contains("feedback") && out.contains("minimal"), "{out}");
    }
}

#[test]
fn rational_file_lifted_into_q_sqrt2() {
    let j = json(&["series", &data("plant.json"), "tests/data/sqrt2.toml"]);
    assert_eq!(j["field"], "QQ(sqrt(2))");
    assert_eq!(j["verified"], true);
}

#[test]
fn symbolic_plant_with_symbolic_gain() {
    let o = out_path("sym.json");
    let j = json(&[
        "feedback",
        &data("plant_sym.json"),
        &data("gain_sym.json"),
        "--minreal",
        "--out",
        o.to_str().unwrap(),
    ]);
    assert_eq!(j["field"], "QQ(a, k)");
    assert_eq!(j["A"], serde_json::json!([["-a - k"]]));
    assert_eq!(j["verified"], true);
    assert_eq!(
        j["conditions"],
        serde_json::json!([]),
        "the check's points add no condition"
    );
    let l = load_symbolic_path(&o, &SymbolicOptions::default()).unwrap();
    let TypedAny::RatFunc(t) = &l.system else {
        panic!("read back over Q(a, k)")
    };
    let k = t.ss.field();
    assert_eq!(k.fmt_elem(t.ss.a.get(0, 0)), "-a - k");
    // a rational gain with the symbolic plant: lifted into Q(a, k)
    let j = json(&[
        "feedback",
        &data("plant_sym.json"),
        &data("unity.json"),
        "--positive",
    ]);
    assert_eq!(j["A"], serde_json::json!([["-a + 1"]]));
}

#[test]
fn refusals_are_one_line_exit_2() {
    let (p, u) = (data("plant.json"), data("unity.json"));
    refused(&["feedback", &u, &u, "--positive"], "ill-posed");
    refused(
        &[
            "series",
            &p,
            "tests/data/mass_spring.json",
            "tests/data/x.json",
        ],
        "unexpected argument",
    );
    let two = temp_file("interconnect", "two_in.json", r#"{"D": [[1, 2]]}"#);
    refused(&["feedback", &p, two.to_str().unwrap()], "feedback");
    refused(&["parallel", &p, two.to_str().unwrap()], "parallel");
    refused(
        &["series", &p, "tests/data/no-such-file.json"],
        "no-such-file.json",
    );
    refused(
        &["series", "tests/data/sqrt2.toml", "tests/data/sqrt3.json"],
        "one field",
    );
    let bad = out_path("x.toml");
    refused(&["series", &p, &p, "--out", bad.to_str().unwrap()], "JSON");
    refused(&["append"], "required");
}
