//! The command line (issue 17, items 4 and 8): expressions starting with '-', `linalg` on
//! m x n matrices, `--help` texts, `--max-seconds` checks, one-line option errors, broken
//! pipes and full disks, improper descriptor files for commands that only need A, bounded
//! `freqresp` output, and user strings escaped in every output format.
use std::io::Read;
use std::process::{Command, Stdio};

fn bin() -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_exactlti"));
    c.current_dir(env!("CARGO_MANIFEST_DIR"));
    c
}

fn run(args: &[&str]) -> (i32, String, String) {
    crate::common::cli::run(args)
}

fn temp_file(name: &str, text: &str) -> std::path::PathBuf {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("exactlti-cli-options");
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

/// Exit 2 and exactly one line on stderr (the contract for bad input).
fn assert_one_line_exit_2(args: &[&str]) -> String {
    let (code, out, err) = run(args);
    assert_eq!(code, 2, "{args:?}: {err}");
    assert_eq!(err.lines().count(), 1, "{args:?}: one line, got:\n{err}");
    assert!(err.starts_with("exactlti: "), "{err}");
    assert!(out.is_empty(), "{args:?}: {out}");
    err
}

#[test]
fn expressions_may_start_with_a_minus() {
    let (code, out, err) = run(&["poly", "factor", "-4*x^3 + 1", "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["content"], "-4");
    assert_eq!(j["factors"][0]["poly"], "x^3 - 1/4");
    // roots: -x^2 + 2 has the roots ±sqrt(2)
    let (code, out, err) = run(&["poly", "roots", "-x^2 + 2", "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    let roots = j["roots"].as_array().unwrap();
    assert_eq!(roots.len(), 2, "{j}");
    for r in roots {
        let re = r["approx"][0].as_f64().unwrap();
        assert!((re * re - 2.0).abs() < 1e-9, "{r}");
    }
    // gcd of -(x^2 - 1) and -(x + 1) is x + 1 (up to a unit)
    let (code, out, err) = run(&["poly", "gcd", "-x^2 + 1", "-x - 1", "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("x + 1"), "{out}");
    // options after the expression still work
    let (code, _, err) = run(&["poly", "roots", "-x^3 + 2", "--digits", "5"]);
    assert_eq!(code, 0, "{err}");
}

#[test]
fn linalg_rank_rref_nullspace_take_any_m_by_n_matrix() {
    let f = temp_file("wide.json", r#"{"A": [[1, 2, 3], [2, 4, 6]]}"#);
    let f = f.to_str().unwrap();
    let (code, out, err) = run(&["linalg", "rank", f, "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["rank"], 1);
    assert!(j["note"].as_str().unwrap().contains("2x3"), "{j}");
    let (code, out, err) = run(&["linalg", "rref", f, "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(
        j["matrix"],
        serde_json::json!([["1", "2", "3"], ["0", "0", "0"]])
    );
    // the null space basis: 2 vectors, each with A v = 0
    let (code, out, err) = run(&["linalg", "nullspace", f, "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    let basis = j["basis"].as_array().unwrap();
    assert_eq!(basis.len(), 2);
    for v in basis {
        let v: Vec<f64> = v
            .as_array()
            .unwrap()
            .iter()
            .map(|x| {
                let s = x.as_str().unwrap();
                match s.split_once('/') {
                    Some((a, b)) => a.parse::<f64>().unwrap() / b.parse::<f64>().unwrap(),
                    None => s.parse().unwrap(),
                }
            })
            .collect();
        assert_eq!(v[0] + 2.0 * v[1] + 3.0 * v[2], 0.0, "{v:?}");
    }
    // a tall matrix too; det of a non-square matrix is refused in one line
    let tall = temp_file("tall.toml", "A = [[1, 0], [0, 1], [1, 1]]\n");
    let (code, out, _) = run(&["linalg", "rank", tall.to_str().unwrap(), "--format", "json"]);
    assert_eq!(code, 0);
    assert!(out.contains("\"rank\": 2"), "{out}");
    let err = assert_one_line_exit_2(&["linalg", "det", f]);
    assert!(err.contains("square"), "{err}");
    // a non-square A is still refused by the commands on systems
    let err = assert_one_line_exit_2(&["jordan", f]);
    assert!(err.contains("square"), "{err}");
}

#[test]
fn max_seconds_must_be_a_positive_number() {
    for bad in ["0", "-1", "nan", "NaN", "inf", "abc", "1e300"] {
        let err = assert_one_line_exit_2(&[
            "--max-seconds",
            bad,
            "linalg",
            "rank",
            "data/sliding-masses.json",
        ]);
        assert!(err.contains("max-seconds"), "{bad}: {err}");
    }
    let (code, _, err) = run(&[
        "--max-seconds",
        "0.5e2",
        "linalg",
        "rank",
        "data/sliding-masses.json",
    ]);
    assert_eq!(code, 0, "{err}");
}

#[test]
fn option_parser_errors_are_one_line_with_exit_2() {
    let err = assert_one_line_exit_2(&["jordan", "--bogus", "data/sliding-masses.json"]);
    assert!(err.contains("--bogus") && err.contains("usage"), "{err}");
    let err = assert_one_line_exit_2(&["jordan"]);
    assert!(err.contains("FILE"), "{err}");
    assert_one_line_exit_2(&["jordn", "data/sliding-masses.json"]);
    assert_one_line_exit_2(&[]);
    let err = assert_one_line_exit_2(&["--format", "xml", "jordan", "data/sliding-masses.json"]);
    assert!(err.contains("xml"), "{err}");
    assert_one_line_exit_2(&["freqresp", "data/sliding-masses.json", "--points", "x"]);
    // --help and --version still print in full, exit 0
    let (code, out, _) = run(&["--help"]);
    assert_eq!(code, 0);
    assert!(out.lines().count() > 10);
    let (code, out, _) = run(&["--version"]);
    assert_eq!(code, 0);
    assert!(out.starts_with("exactlti"));
}

#[test]
fn help_states_units_and_what_file_and_options_mean() {
    let (code, out, _) = run(&["freqresp", "--help"]);
    assert_eq!(code, 0);
    assert!(out.contains("in Hz"), "{out}");
    assert!(out.contains("System file"), "{out}");
    for opt in [
        "--from",
        "--to",
        "--points",
        "--svg",
        "--csv",
        "--max-seconds",
        "--format",
    ] {
        let line = out
            .lines()
            .find(|l| l.trim_start().starts_with(opt))
            .unwrap_or_else(|| panic!("{opt} missing:\n{out}"));
        // every option has a help text (on its line or the next)
        let i = out.find(line).unwrap() + line.len();
        let rest = out[i..].lines().nth(1).unwrap_or("");
        assert!(
            line.split_whitespace().count() > 2 || !rest.trim().is_empty(),
            "{opt}: no help:\n{out}"
        );
    }
    let (_, out, _) = run(&["--help"]);
    assert!(out.contains("FILE is a system file"), "{out}");
    assert!(out.contains("Exit status"), "{out}");
    // the program's own summary first (not a subcommand enum's doc), every subcommand listed
    // although their arguments are defined only when one is chosen (clap `defer`)
    assert!(
        out.starts_with("Exact structure of linear time-invariant systems"),
        "{out}"
    );
    for cmd in [
        "jordan",
        "minreal",
        "freqresp",
        "series",
        "c2d",
        "stepinfo",
        "bifurcations",
    ] {
        assert!(
            out.lines().any(|l| l.trim_start().starts_with(cmd)),
            "{cmd}:\n{out}"
        );
    }
    for cmd in ["jordan", "minreal", "linalg", "sweep", "critical", "poly"] {
        let (code, out, _) = run(&[cmd, "--help"]);
        assert_eq!(code, 0, "{cmd}");
        assert!(!out.is_empty());
    }
}

#[test]
fn broken_pipe_is_a_quiet_exit_and_a_full_disk_exits_2() {
    // the reader goes away before anything is written
    let mut child = bin()
        .args(["analyze"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take());
    let mut err = String::new();
    child
        .stderr
        .take()
        .unwrap()
        .read_to_string(&mut err)
        .unwrap();
    let status = child.wait().unwrap();
    assert_eq!(status.code(), Some(0), "{err}");
    assert!(err.is_empty(), "quiet: {err}");
    // a write error other than a closed pipe: exit 2, one line
    if std::path::Path::new("/dev/full").exists() {
        let out = bin()
            .args(["analyze"])
            .stdout(std::fs::File::create("/dev/full").unwrap())
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{err}");
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains("cannot write"), "{err}");
    }
}

#[test]
fn an_improper_descriptor_file_serves_commands_that_need_only_a() {
    // G(s) = s - 1 (improper): A is diag(1, 1, 1, -3)
    let f = "tests/data/improper_s.json";
    let (code, out, err) = run(&["linalg", "det", f, "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["det"], "-3");
    assert!(
        j["note"].as_str().unwrap().contains("only the matrix A"),
        "{j}"
    );
    let (code, out, err) = run(&["jordan", f, "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["verified"], true);
    assert!(j["note"].is_string(), "{j}");
    // commands that need the system still refuse it in one line
    assert_one_line_exit_2(&["scb", f]);
    // a typo in a system file is not hidden by the fallback
    let bad = temp_file("bad_entry.json", r#"{"A": [[1, "2x"]], "E": [[1, 0]]}"#);
    assert_one_line_exit_2(&["jordan", bad.to_str().unwrap()]);
}

#[test]
fn freqresp_refuses_absurd_output_sizes_and_still_answers_moderate_ones() {
    // 20 states, 20 inputs, 20 outputs, 100000 points: 40 million values (GBs before)
    let n = 20;
    let m = |r: usize, c: usize, seed: usize| -> serde_json::Value {
        (0..r)
            .map(|i| {
                (0..c)
                    .map(|j| {
                        let x = (i * 31 + j * 17 + seed * 7) % 11;
                        serde_json::json!(x as i64 - 5 - if i == j && seed == 0 { 20 } else { 0 })
                    })
                    .collect::<Vec<_>>()
            })
            .collect::<Vec<_>>()
            .into()
    };
    let sys = serde_json::json!({"A": m(n, n, 0), "B": m(n, n, 1), "C": m(n, n, 2)});
    let f = temp_file("big20.json", &sys.to_string());
    let f = f.to_str().unwrap();
    let t = std::time::Instant::now();
    let err = assert_one_line_exit_2(&["freqresp", f, "--points", "100000", "--format", "json"]);
    assert!(err.contains("at most") && err.contains("--points"), "{err}");
    assert!(t.elapsed().as_secs() < 30, "refused quickly");
    // the largest count it names is accepted
    let (code, out, err) = run(&["freqresp", f, "--points", "50", "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["frequencies_hz"].as_array().unwrap().len(), 50);
    assert_eq!(j["response"][0].as_array().unwrap().len(), n);
}

#[test]
fn user_strings_are_escaped_in_every_format() {
    let name = "evil\n\\end{document}\n== fake section ==\u{1b}[31m";
    let sys =
        serde_json::json!({"name": name, "A": [[0, 1], [-2, -3]], "B": [[0], [1]], "C": [[1, 0]]});
    let f = temp_file("evil.json", &sys.to_string());
    let f = f.to_str().unwrap();
    // JSON: the name round-trips exactly
    let (code, out, err) = run(&["analyze", f, "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["system"]["name"], name);
    // text: control characters shown escaped, no forged line
    let (code, out, _) = run(&["analyze", f]);
    assert_eq!(code, 0);
    assert!(
        out.contains("evil\\n\\end{document}\\n== fake section ==\\u{1b}[31m"),
        "{out}"
    );
    assert!(
        !out.lines().any(|l| l.starts_with("== fake section")),
        "{out}"
    );
    assert!(!out.contains('\u{1b}'));
    // LaTeX: no line of the name escapes its comment or its text
    for args in [
        vec!["analyze", f, "--format", "latex"],
        vec!["analyze", f, "--format", "latex", "--standalone"],
    ] {
        let (code, out, _) = run(&args);
        assert_eq!(code, 0);
        // the only line that ends the document is the standalone wrapper's last line
        let ends: Vec<&str> = out
            .lines()
            .filter(|l| l.trim_start().starts_with("\\end{document}"))
            .collect();
        assert_eq!(ends.len(), args.len() - 4, "{out}");
        // the comment holding the name is one line
        assert!(
            out.lines()
                .any(|l| l.starts_with("% exactlti: exactlti analysis: evil\\n")),
            "{out}"
        );
        assert!(!out.lines().any(|l| l.starts_with("== fake")), "{out}");
        assert!(!out.contains('\u{1b}'));
    }
    // stderr: a file name with a newline stays on one line
    let err = assert_one_line_exit_2(&["jordan", "no\nsuch-file.json"]);
    assert!(err.contains("no\\nsuch-file.json"), "{err}");
}
