//! Strict and bounded input (issue 17 items 3, 8; issue 10 item 2): unknown keys with a
//! suggestion, duplicate JSON keys, bare numbers under the same size limit as strings, the
//! bicycle benchmark's raw data refused as a system, signal names, capped file reads,
//! implicit multiplication by `i`, and key `G` in the state-space commands.
use crate::common::cli::{self, run};
use exactlti::io::{
    Ground, InputErrorKind, SystemFormat, eval_expr, load_system_path, load_system_str,
    parse_system_json, parse_system_toml, read_text,
};
use std::path::Path;

fn temp_file(name: &str, text: &str) -> std::path::PathBuf {
    cli::temp_file("inputs", name, text)
}

fn data(p: &str) -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(p)
}

#[test]
fn unknown_keys_are_errors_with_a_suggestion() {
    let e = parse_system_json(r#"{"A": [[1]], "Bee": [[1]], "C": [[1]]}"#, "x.json").unwrap_err();
    assert_eq!(e.kind, InputErrorKind::UnknownKey);
    assert_eq!(
        e.to_string(),
        "x.json: unknown key 'Bee'; did you mean 'B'?"
    );
    let e = parse_system_toml("A = [[1]]\nparamters = { k = 1 }\n", "x.toml").unwrap_err();
    assert_eq!(
        e.to_string(),
        "x.toml: unknown key 'paramters'; did you mean 'parameters'?"
    );
    let e = parse_system_json(r#"{"A": [[1]], "zzzzzz": 1}"#, "x.json").unwrap_err();
    assert!(
        e.to_string()
            .starts_with("x.json: unknown key 'zzzzzz'; a system file has the keys"),
        "{e}"
    );
    // lower-case matrix keys keep their own message
    let e = parse_system_json(r#"{"a": [[1]]}"#, "x.json").unwrap_err();
    assert!(e.to_string().contains("did you mean 'A'?"), "{e}");
    // the symbolic reader and the descriptor reader are as strict
    let p = temp_file(
        "bee.json",
        r#"{"parameters": {"m": null}, "A": [["m"]], "Bee": [[1]]}"#,
    );
    let (code, out, err) = run(&["jordan", p.to_str().unwrap()]);
    assert_eq!(code, 2, "{out}{err}");
    assert!(
        err.contains("unknown key 'Bee'; did you mean 'B'?"),
        "{err}"
    );
    assert_eq!(err.trim().lines().count(), 1, "{err}");
    for cmd in ["pencil", "tf", "scb"] {
        let p = temp_file("bee2.json", r#"{"A": [[1]], "Bee": [[1]], "C": [[1]]}"#);
        let (code, _, err) = run(&[cmd, p.to_str().unwrap()]);
        assert_eq!(code, 2, "{cmd}: {err}");
        assert!(err.contains("unknown key 'Bee'"), "{cmd}: {err}");
    }
}

#[test]
fn duplicate_json_keys_are_errors() {
    let e = parse_system_json(r#"{"A": [[1]], "A": [[2, 3], [4, 5]]}"#, "d.json").unwrap_err();
    assert_eq!(e.kind, InputErrorKind::DuplicateKey);
    assert_eq!(e.key.as_deref(), Some("A"));
    let e = parse_system_json(
        r#"{"parameters": {"k": 1, "k": 2}, "A": [["k"]]}"#,
        "d.json",
    )
    .unwrap_err();
    assert_eq!(e.kind, InputErrorKind::DuplicateKey);
    assert_eq!(e.key.as_deref(), Some("k"));
    let p = temp_file("dup.json", r#"{"A": [[1]], "A": [[2, 3], [4, 5]]}"#);
    let (code, _, err) = run(&["linalg", "det", p.to_str().unwrap()]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("key A: key given twice"), "{err}");
}

#[test]
fn bare_numbers_obey_the_size_limit_of_strings() {
    for text in [
        r#"{"A": [[1e9999]]}"#.to_string(),
        format!(r#"{{"A": [[{}]]}}"#, "9".repeat(10_000)),
        r#"{"parameters": {"k": 1e9999}, "A": [["k"]]}"#.to_string(),
    ] {
        let bare = parse_system_json(&text, "n.json").unwrap_err();
        let quoted = text.replace("1e9999", "\"1e9999\"");
        let s = parse_system_json(&quoted, "n.json").unwrap_err();
        assert!(
            bare.msg.contains("too large") || bare.msg.contains("more than"),
            "{bare}"
        );
        assert_eq!(bare.msg, s.msg);
    }
    let e = parse_system_toml("A = [[1e9999]]\n", "n.toml").unwrap_err();
    assert!(e.msg.contains("more than 16384 bits"), "{e}");
    // just under the limit is fine
    parse_system_json(r#"{"A": [[1e4000]]}"#, "n.json").unwrap();
}

#[test]
fn bicycle_benchmark_data_is_refused_with_the_right_form() {
    let e = exactlti::io::read_system_file(&data("data/bicycle-benchmark.json")).unwrap_err();
    assert_eq!(e.kind, InputErrorKind::NotASystem);
    assert!(e.msg.contains("data/bicycle-whipple.json"), "{e}");
    assert!(e.msg.contains("critical"), "{e}");
    let (code, _, err) = run(&["modes", "data/bicycle-benchmark.json"]);
    assert_eq!(code, 2);
    assert!(err.contains("bicycle-whipple.json"), "{err}");
    // the system form loads, with its signal names, and the study commands read it
    let l = load_system_path(&data("data/bicycle-whipple.json")).unwrap();
    let s = &l.file.signals;
    assert_eq!(
        s.inputs.as_deref(),
        Some(&["roll torque".to_string(), "steer torque".to_string()][..])
    );
    assert_eq!(s.states.as_ref().map(Vec::len), Some(4));
    assert_eq!(s.outputs.as_ref().map(Vec::len), Some(2));
    let (code, out, err) = run(&[
        "critical",
        "data/bicycle-whipple.json",
        "--param",
        "v",
        "--from",
        "0",
        "--to",
        "10",
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("imaginary_pair"), "{out}");
}

#[test]
fn signal_names_are_checked_against_the_system() {
    let ok = r#"{"A": [[0, 1], [-2, -3]], "B": [[0], [1]], "C": [[1, 0]],
                 "inputs": ["force"], "outputs": ["position"], "states": ["x", "v"]}"#;
    let l = load_system_str(ok, SystemFormat::Json, "s.json").unwrap();
    assert_eq!(
        l.file.signals.inputs.as_deref(),
        Some(&["force".to_string()][..])
    );
    let bad = ok.replace(r#"["force"]"#, r#"["force", "torque"]"#);
    let e = load_system_str(&bad, SystemFormat::Json, "s.json").unwrap_err();
    assert_eq!(e.kind, InputErrorKind::Shape);
    assert_eq!(e.to_string(), "s.json: key inputs: 2 names for 1 inputs");
    let bad = ok.replace(r#"["x", "v"]"#, r#"["x", 2]"#);
    let e = load_system_str(&bad, SystemFormat::Json, "s.json").unwrap_err();
    assert!(
        e.to_string()
            .starts_with("s.json: key states: expected a list of names"),
        "{e}"
    );
    // the symbolic reader checks them too
    let sym = r#"{"parameters": {"m": null}, "A": [["m"]], "B": [[1]], "C": [[1]],
                  "inputs": ["a", "b"]}"#;
    let opts = exactlti::io::symbolic::SymbolicOptions::default();
    let e = exactlti::io::symbolic::load_symbolic_str(sym, SystemFormat::Json, "y.json", &opts)
        .unwrap_err();
    assert_eq!(e.to_string(), "y.json: key inputs: 2 names for 1 inputs");
}

#[test]
fn huge_and_endless_files_are_refused_quickly() {
    let p = temp_file("big.json", &" ".repeat(5000));
    let e = exactlti::io::read::read_text_capped(&p, 4096).unwrap_err();
    assert_eq!(e.kind, InputErrorKind::TooLarge);
    assert!(read_text(&p).is_ok());
    if Path::new("/dev/zero").exists() {
        // every command that reads a file (jordan and linalg read A alone; critical and
        // sweep read a parameter family): each through the capped reader
        for cmd in [
            &["jordan"][..],
            &["linalg", "det"],
            &["minreal"],
            &["analyze"],
            &["check"],
            &["freqresp"],
            &["pencil"],
            &["tf"],
            &["bifurcations"],
            &["critical", "--param", "v", "--from", "0", "--to", "1"],
            &["sweep", "--param", "v", "--from", "0", "--to", "1"],
        ] {
            let t = std::time::Instant::now();
            let mut a = cmd.to_vec();
            a.push("/dev/zero");
            let (code, out, err) = run(&a);
            assert_eq!(code, 2, "{a:?}: {out}{err}");
            assert_eq!(err.trim().lines().count(), 1, "{a:?}: {err}");
            assert!(err.contains("larger than"), "{a:?}: {err}");
            // a generous bound (debug build, busy machine): without the cap this never ends
            assert!(t.elapsed().as_secs() < 60, "{a:?}");
        }
    }
}

#[test]
fn implicit_multiplication_by_i_binds_as_written_out() {
    let ev = |s: &str| {
        let (x, g) = eval_expr(s, &[], &Ground::Rational).unwrap();
        g.fmt_scalar(&x)
    };
    assert_eq!(ev("2i^2"), ev("2*i^2"));
    assert_eq!(ev("2i^2"), "-2");
    assert_eq!(ev("1/2i"), ev("1/2*i"));
    assert_eq!(ev("1/2i"), "i/2");
    assert_eq!(ev("3i"), "3*i");
    assert!(eval_expr("2x", &[], &Ground::Rational).is_err());
    let s = parse_system_json(r#"{"A": [["2i^2", "1/2i"], [0, 1]]}"#, "i.json").unwrap();
    assert_eq!(s.a.unwrap().display(&s.ground), "[[-2, i/2], [0, 1]]");
}

#[test]
fn transfer_matrix_key_works_in_state_space_commands() {
    // G = [[1/(s+1), 2/(s+1)], [(s^2+5s+7)/(s^2+5s+6), 1/2]]: McMillan degree 3
    let l = load_system_path(&data("tests/data/tf_G.json")).unwrap();
    let t = l.rational().unwrap();
    assert_eq!(t.ss.nstates(), 3);
    // the realization reproduces G: Markov parameter C B and D
    let cb = t.ss.c.try_mul(&t.ss.b).unwrap();
    let want = [["1", "2"], ["0", "0"]];
    for (i, row) in want.iter().enumerate() {
        for (j, w) in row.iter().enumerate() {
            assert_eq!(cb.get(i, j).to_string(), *w, "CB[{i}][{j}]");
        }
    }
    assert_eq!(t.ss.d.get(0, 0).to_string(), "0");
    assert_eq!(t.ss.d.get(1, 0).to_string(), "1");
    assert_eq!(t.ss.d.get(1, 1).to_string(), "1/2");
    for cmd in ["jordan", "modes", "scb", "minreal"] {
        let (code, out, err) = run(&[cmd, "tests/data/tf_G.json"]);
        assert_eq!(code, 0, "{cmd}: {err}");
        assert!(!out.is_empty());
    }
    let (code, out, _) = run(&["jordan", "tests/data/tf_G.json", "--format", "json"]);
    assert_eq!(code, 0);
    assert!(out.contains("x^3 + 6*x^2 + 11*x + 6"), "{out}");
    // an improper G is refused by them, accepted by tf
    let p = temp_file("gimp.json", r#"{"G": [["s + 1"]]}"#);
    let (code, _, err) = run(&["jordan", p.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(err.contains("key G: improper transfer matrix"), "{err}");
    let (code, _, err) = run(&["tf", p.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    // G beside A is an error
    let e = parse_system_json(r#"{"A": [[1]], "G": [["1/s"]]}"#, "g.json").unwrap_err();
    assert!(e.to_string().contains("cannot be combined"), "{e}");
}
