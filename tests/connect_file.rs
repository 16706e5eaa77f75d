//! `exactlti connect CONNECTION_FILE`: systems connected by signal names on the command
//! line (python-control's `interconnect`), the result's transfer matrix checked exactly
//! against the one computed by hand (and by `feedback`), bad connection files refused with
//! one line naming the key.

use crate::common::cli::{run, run_json, temp_file};

/// A directory of its own per test (the tests run in parallel).
fn dir(tag: &str) -> std::path::PathBuf {
    let d =
        std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("exactlti-connect-{tag}"));
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn write(tag: &str, name: &str, text: &str) -> String {
    temp_file(&format!("connect-{tag}"), name, text)
        .display()
        .to_string()
}

fn json(args: &[&str]) -> serde_json::Value {
    run_json(args)
}

fn plant_and_controller(tag: &str) -> (String, String) {
    // G = 1/(s (s + 1)), K = (s + 2)/(s + 3) (a lead), names u -> y and e -> v
    let g = write(
        tag,
        "plant.json",
        r#"{"A": [[0, 1], [0, -1]], "B": [[0], [1]], "C": [[1, 0]], "inputs": ["u"], "outputs": ["y"]}"#,
    );
    let k = write(
        tag,
        "lead.json",
        r#"{"A": [[-3]], "B": [[1]], "C": [[-1]], "D": [[1]], "inputs": ["e"], "outputs": ["v"]}"#,
    );
    (g, k)
}

#[test]
fn unity_feedback_by_names_equals_the_closed_loop_transfer_function() {
    let t = "unity";
    let (plant, lead) = plant_and_controller(t);
    let conn = write(
        t,
        "loop.json",
        r#"{"systems": ["plant.json", "lead.json"], "connections": [["u", "v"], ["e", "-y"]], "inputs": ["e"], "outputs": ["y"]}"#,
    );
    let out = dir(t).join("closed.json").display().to_string();
    let j = json(&["connect", &conn, "--out", &out]);
    assert_eq!(j["verified"], true);
    assert_eq!(j["connections"][1], "e <- -y");
    // T = G K / (1 + G K) = (s + 2) / (s^3 + 4 s^2 + 4 s + 2), exactly
    assert_eq!(
        j["transfer_matrix"][0][0],
        "(s + 2)/(s^3 + 4*s^2 + 4*s + 2)"
    );
    // the same transfer matrix as feedback(series(K, G), 1) by the operations
    let ser = dir(t).join("ser.json").display().to_string();
    let (code, _, err) = run(&["series", &lead, &plant, "--out", &ser]);
    assert_eq!(code, 0, "{err}");
    let one = write(t, "one.json", r#"{"D": [[1]]}"#);
    let fb = dir(t).join("fb.json").display().to_string();
    let (code, _, err) = run(&["feedback", &ser, &one, "--out", &fb]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(
        json(&["tf", &out])["transfer_matrix"],
        json(&["tf", &fb])["transfer_matrix"]
    );
    // the written file keeps the external names
    let text = std::fs::read_to_string(&out).unwrap();
    assert!(
        text.contains(r#""inputs": ["e"]"#) && text.contains(r#""outputs": ["y"]"#),
        "{text}"
    );
}

#[test]
fn connection_with_two_outputs_and_a_minimal_realization() {
    let t = "two";
    plant_and_controller(t);
    // TOML, the control v as a second output, and the minimal realization
    let conn = write(
        t,
        "loop.toml",
        "systems = [\"plant.json\", \"lead.json\"]\nconnections = [[\"u\", \"v\"], [\"e\", \"-y\"]]\ninputs = [\"e\"]\noutputs = [\"y\", \"v\"]\n",
    );
    let j = json(&["connect", &conn, "--minreal"]);
    assert_eq!(j["states"], 3);
    assert_eq!(j["minimal"]["order"], 3);
    // v = K (e - y) = K / (1 + G K) e = (s + 2) s (s + 1) / (s^3 + 4 s^2 + 4 s + 2)
    assert_eq!(
        j["transfer_matrix"][1][0],
        "(s^3 + 3*s^2 + 2*s)/(s^3 + 4*s^2 + 4*s + 2)"
    );
}

#[test]
fn bad_connection_files_name_the_key() {
    let t = "bad";
    plant_and_controller(t);
    for (text, want) in [
        (
            r#"{"connections": [], "inputs": [], "outputs": []}"#,
            "key systems: missing",
        ),
        (
            r#"{"systems": ["plant.json"], "inputs": ["u"], "outputs": ["y"], "extra": 1}"#,
            "key extra: unknown",
        ),
        (
            r#"{"systems": ["plant.json"], "connections": [["u"]], "inputs": [], "outputs": ["y"]}"#,
            "key connections[0]",
        ),
        (
            r#"{"systems": ["plant.json"], "connections": [["u", 3]], "inputs": [], "outputs": ["y"]}"#,
            "key connections[0][1]",
        ),
        (
            r#"{"systems": ["plant.json"], "inputs": ["w"], "outputs": ["y"]}"#,
            "unknown input 'w'",
        ),
        (
            r#"{"systems": ["plant.json"], "inputs": ["u"], "outputs": ["q"]}"#,
            "unknown output 'q'",
        ),
        (
            r#"{"systems": ["nothere.json"], "inputs": ["u"], "outputs": ["y"]}"#,
            "nothere.json",
        ),
        ("[1, 2]", "a connection file is an object"),
    ] {
        let f = write(t, "bad.json", text);
        let (code, _, err) = run(&["connect", &f]);
        assert_eq!(code, 2, "{text}: {err}");
        assert!(err.contains(want), "{text}: {err}");
        assert_eq!(err.trim().lines().count(), 1, "{err}");
    }
}
