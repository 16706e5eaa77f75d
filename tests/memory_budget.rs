//! Issue 22 items 11-13: bounded memory and work on hostile inputs. Every command answers or
//! refuses in one line with exit 2 (never an abort), under a 4 GB address-space limit (the
//! limit of every binary run by the suite: `common::cli::run`). Hostile files are generated
//! here (classes, fixed seeds), not committed.
use crate::common::cli::{run, run_stdin, temp_file};
use exactlti::cli::{Command, execute};
use exactlti::rng::SplitMix64;

fn tmp(name: &str, text: &str) -> String {
    temp_file("membudget", name, text)
        .to_str()
        .unwrap()
        .to_string()
}

/// Exit 0, or exit 2 with exactly one line on stderr; never a signal or exit 1.
fn answers_or_refuses(args: &[&str]) -> (i32, String, String) {
    let (code, out, err) = run(args);
    assert!(
        code == 0 || (code == 2 && err.lines().count() == 1),
        "{args:?}: exit {code}: {err}"
    );
    (code, out, err)
}

/// Dense n x n integer matrix with `digits`-digit entries (the class of the 18 MB file).
fn dense(g: &mut SplitMix64, n: usize, digits: usize) -> String {
    let rows: Vec<String> = (0..n)
        .map(|_| {
            let cells: Vec<String> = (0..n)
                .map(|_| {
                    let mut s = String::with_capacity(digits);
                    s.push(char::from(b'1' + (g.next_u64() % 9) as u8));
                    for _ in 1..digits {
                        s.push(char::from(b'0' + (g.next_u64() % 10) as u8));
                    }
                    s
                })
                .collect();
            format!("[{}]", cells.join(","))
        })
        .collect();
    format!("{{\"A\": [{}]}}", rows.join(","))
}

#[test]
fn dense_matrices_past_the_memory_budget_are_refused_in_one_line() {
    let mut g = SplitMix64(22);
    // the class: dense matrices with long entries; a small budget makes each cross it
    for (n, digits) in [(30, 40), (45, 30), (60, 20)] {
        let f = tmp(
            &format!("dense_{n}_{digits}.json"),
            &dense(&mut g, n, digits),
        );
        let cmds: &[&[&str]] = if n == 60 {
            &[&["jordan"], &["pencil"], &["linalg", "inverse"]]
        } else {
            &[&["linalg", "inverse"]]
        };
        for cmd in cmds {
            let mut a = cmd.to_vec();
            a.extend([f.as_str(), "--max-memory", "4", "--max-seconds", "60"]);
            let (code, _, err) = run(&a);
            assert_eq!(code, 2, "{a:?}: {err}");
            assert_eq!(err.lines().count(), 1, "{a:?}: {err}");
            assert!(err.contains("out of memory"), "{a:?}: {err}");
            assert!(err.contains("--max-memory 4 MiB"), "{a:?}: {err}");
        }
        // the default budget answers the same small problem
        let (code, out, err) = run(&["linalg", "rank", &f]);
        assert_eq!(code, 0, "{err}");
        assert!(out.contains(&format!("rank: {n}")), "{out}");
    }
}

#[test]
fn the_hostile_files_of_issue_22_answer_or_refuse_under_4_gb() {
    let mut g = SplitMix64(2900);
    // the 18 MB file: 600 x 600, 50-digit entries (inside the reader's 64 MiB cap)
    let big = tmp("big18.json", &dense(&mut g, 600, 50));
    assert!(std::fs::metadata(&big).unwrap().len() > 18_000_000);
    answers_or_refuses(&["linalg", "rank", &big, "--max-seconds", "60"]);
    answers_or_refuses(&[
        "pencil",
        &big,
        "--max-memory",
        "1024",
        "--max-seconds",
        "60",
    ]);
    // 2900 x 2900 companion-like matrix: `jordan` asked for 3.5 GB and aborted
    let n = 2900;
    let rows: Vec<String> = (0..n)
        .map(|i| {
            let cells: Vec<String> = (0..n)
                .map(|j| {
                    let x = if i + 1 < n {
                        u64::from(j == i + 1)
                    } else {
                        g.next_u64() % 3
                    };
                    x.to_string()
                })
                .collect();
            format!("[{}]", cells.join(","))
        })
        .collect();
    let f = tmp("big2900.json", &format!("{{\"A\": [{}]}}", rows.join(",")));
    answers_or_refuses(&["jordan", &f, "--max-seconds", "60"]);
    // a 20-state sweep far longer than the streaming threshold: bounded memory, streamed
    let rows: Vec<String> = (0..20)
        .map(|i| {
            let cells: Vec<String> = (0..20)
                .map(|j| {
                    if i == j {
                        "\"-v\"".into()
                    } else {
                        ((g.next_u64() % 5) as i64 - 2).to_string()
                    }
                })
                .collect();
            format!("[{}]", cells.join(","))
        })
        .collect();
    let sw = tmp(
        "sweep20.json",
        &format!(
            "{{\"parameters\": {{\"v\": 1}}, \"A\": [{}]}}",
            rows.join(",")
        ),
    );
    let (code, out, _) = answers_or_refuses(&[
        "sweep",
        &sw,
        "--param",
        "v",
        "--from",
        "0",
        "--to",
        "1",
        "--points",
        "30000",
        "--format",
        "json",
        "--max-memory",
        "64",
    ]);
    assert_eq!(code, 0);
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["eigenvalues_approx"].as_array().unwrap().len(), 30000);
}

/// Random families x' = A(v) x with `n` states (entries integers, `v` on some of them).
fn family(g: &mut SplitMix64, n: usize) -> String {
    let rows: Vec<String> = (0..n)
        .map(|_| {
            let cells: Vec<String> = (0..n)
                .map(|_| match g.next_u64() % 4 {
                    0 => "\"v\"".to_string(),
                    1 => "\"-2*v + 1\"".to_string(),
                    _ => ((g.next_u64() % 7) as i64 - 3).to_string(),
                })
                .collect();
            format!("[{}]", cells.join(","))
        })
        .collect();
    format!(
        "{{\"parameters\": {{\"v\": 1}}, \"A\": [{}]}}",
        rows.join(",")
    )
}

#[test]
fn a_streamed_sweep_is_the_in_memory_sweep() {
    let mut g = SplitMix64(11);
    for case in 0..3 {
        let n = 2 + case;
        let f = tmp(&format!("fam{case}.json"), &family(&mut g, n));
        let csv = temp_file("membudget", &format!("fam{case}.csv"), "");
        let points = 10_001 + case;
        let p = points.to_string();
        let (code, out, err) = run(&[
            "sweep",
            &f,
            "--param",
            "v",
            "--from",
            "-3",
            "--to",
            "2",
            "--points",
            &p,
            "--format",
            "json",
            "--csv",
            csv.to_str().unwrap(),
        ]);
        assert_eq!(code, 0, "{err}");
        let streamed: serde_json::Value = serde_json::from_str(&out).unwrap();
        assert_eq!(streamed["streamed"], true);
        let cmd = Command::Sweep {
            file: f.clone().into(),
            param: "v".into(),
            from: -3.0,
            to: 2.0,
            points,
            svg: None,
            locus_svg: None,
            csv: None,
        };
        let whole = execute(&cmd).unwrap().report.to_json();
        for key in [
            "param",
            "points",
            "values",
            "eigenvalues_approx",
            "stable_points",
        ] {
            assert_eq!(streamed[key], whole[key], "case {case}: {key}");
        }
        let lines = std::fs::read_to_string(&csv).unwrap().lines().count();
        assert_eq!(lines, points + 1);
        // text: one row per line, LaTeX refused past the threshold
        let (code, out, _) = run(&[
            "sweep", &f, "--param", "v", "--from", "0", "--to", "1", "--points", &p,
        ]);
        assert_eq!(code, 0);
        assert!(out.lines().count() > points, "{}", out.lines().count());
        let (code, _, err) = run(&[
            "sweep", &f, "--param", "v", "--from", "0", "--to", "1", "--points", &p, "--format",
            "latex",
        ]);
        assert_eq!((code, err.lines().count()), (2, 1), "{err}");
    }
}

#[test]
fn long_expressions_are_refused_by_their_length_before_parsing() {
    // the class: sums, products, nested parentheses of every length past the bound, in A
    // (numeric and symbolic) and in G
    let mut g = SplitMix64(300);
    for k in 0..6 {
        let len = 10_001 + (g.next_u64() % 300_000) as usize;
        let unit = ["(x+1)*", "x+", "((x)-1)*"][k % 3];
        let mut e = unit.repeat(len / unit.len() + 1);
        e.truncate(len);
        let e = e.trim_end_matches(['*', '+', '-', '(']).to_string() + "1";
        let files = [
            format!("{{\"parameters\": {{\"x\": \"1/3\"}}, \"A\": [[\"{e}\"]]}}"),
            format!("{{\"symbols\": [\"x\"], \"A\": [[\"{e}\"]]}}"),
            format!("{{\"G\": [[\"{}\"]]}}", e.replace('x', "s")),
        ];
        for (i, text) in files.iter().enumerate() {
            let f = tmp(&format!("long{k}_{i}.json"), text);
            let (code, _, err) = run(&["jordan", &f, "--max-seconds", "20"]);
            assert_eq!(code, 2, "{err}");
            assert_eq!(err.lines().count(), 1, "{err}");
            assert!(err.contains("at most 10000"), "{err}");
        }
    }
    // at the bound: read
    let e = "1+".repeat(4_999) + "1";
    assert_eq!(e.len(), 9_999);
    let f = tmp("at_bound.json", &format!("{{\"A\": [[\"{e}\"]]}}"));
    let (code, out, err) = run(&["linalg", "det", &f]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("5000"), "{out}");
}

#[test]
fn digits_are_bounded_by_200() {
    for d in ["201", "1000"] {
        let (code, _, err) = run(&["poly", "roots", "x^2 - 2", "--digits", d]);
        assert_eq!((code, err.lines().count()), (2, 1), "{err}");
        let (code, _, err) = run(&[
            "critical",
            "data/bicycle-whipple.json",
            "--param",
            "v",
            "--from",
            "0",
            "--to",
            "10",
            "--digits",
            d,
        ]);
        assert_eq!((code, err.lines().count()), (2, 1), "{err}");
        assert!(err.contains("200"), "{err}");
    }
    let (code, out, err) = run(&["poly", "roots", "x^2 - 2", "--digits", "200"]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("1.41421356237309504880"), "{out}");
}

#[test]
fn piped_input_reads_like_the_file() {
    // the class: every corpus file through a pipe (`/dev/stdin`, `-`) for commands that
    // read their file more than once
    let files = [
        "tests/data/mass_spring.json",
        "tests/data/tf_G.json",
        "tests/data/pencil_rect.json",
        "tests/data/yaw_contract.json",
    ];
    for f in files {
        let text = std::fs::read_to_string(f).unwrap();
        for cmd in ["jordan", "zeros", "tf", "pencil", "standard"] {
            let (want_code, want, _) = run(&[cmd, f]);
            for name in ["/dev/stdin", "-"] {
                let (code, out, err) = run_stdin(&[cmd, name, "--max-seconds", "30"], &text);
                assert_eq!(code, want_code, "{cmd} {f} via {name}: {err}");
                // the file name appears in some reports: compare from the second line
                let strip = |s: &str| s.replace(f, name);
                assert_eq!(strip(&want), out, "{cmd} {f} via {name}");
            }
        }
    }
}

#[test]
fn mnf_of_an_odd_order_system_is_not_applicable_never_false() {
    let mut g = SplitMix64(7);
    for n in [1usize, 3, 5, 7] {
        let a: Vec<Vec<i64>> = (0..n)
            .map(|_| (0..n).map(|_| (g.next_u64() % 7) as i64 - 3).collect())
            .collect();
        let b: Vec<Vec<i64>> = (0..n).map(|_| vec![(g.next_u64() % 3) as i64]).collect();
        let c: Vec<Vec<i64>> = vec![(0..n).map(|_| (g.next_u64() % 3) as i64).collect()];
        let f = tmp(
            &format!("odd{n}.json"),
            &serde_json::json!({"A": a, "B": b, "C": c}).to_string(),
        );
        let (code, out, err) = run(&["mnf", &f, "--format", "json"]);
        assert_eq!(code, 0, "{err}");
        let j: serde_json::Value = serde_json::from_str(&out).unwrap();
        assert_eq!(j["exists"], false);
        assert_eq!(j["verified"], "not applicable", "{j}");
        assert!(j["reason"].as_str().unwrap().contains("odd"));
    }
}

#[test]
fn a_proper_siso_g_in_lowest_terms_is_its_companion_realization() {
    use exactlti::io::transfer_expr::parse_rational_function;
    use exactlti::realization::realize_transfer;
    use exactlti::system::transfer::TransferMatrix;
    // the class: random proper n/d (common factors included) and (s^2 + s + 1)^k
    let mut g = SplitMix64(60);
    let mut cases: Vec<String> = (1..=30)
        .step_by(7)
        .map(|k| format!("(s - 2)/(s^2 + s + 1)^{k}"))
        .collect();
    for _ in 0..12 {
        fn poly(g: &mut SplitMix64, deg: u64) -> String {
            (0..=deg)
                .map(|e| format!("({})*s^{e}", (g.next_u64() % 9) as i64 - 4))
                .collect::<Vec<_>>()
                .join(" + ")
        }
        let dd = 1 + g.next_u64() % 8;
        let nd = g.next_u64() % (dd + 1);
        let (num, den) = (poly(&mut g, nd), poly(&mut g, dd));
        cases.push(format!(
            "({num})*(s + 3)/(({den} + s^{}) * (s + 3))",
            dd + 1
        ));
    }
    for text in &cases {
        let f = parse_rational_function(text, &[]).unwrap();
        let common = f.num.gcd(&f.den).deg();
        let want = if f.num.is_zero() {
            0
        } else {
            f.den.deg() - common
        };
        let tm = TransferMatrix {
            entries: vec![vec![f.clone()]],
        };
        let r = realize_transfer(&tm).unwrap();
        assert!(r.verified, "{text}");
        assert_eq!(r.mcmillan_degree, want, "{text}");
        let ss = r.state_space.as_ref().unwrap();
        assert_eq!(ss.a.nrows(), want, "{text}");
        // independent check: the realization's own transfer function is n/d
        let back = &ss.transfer_matrix().unwrap().entries[0][0];
        assert_eq!(back.num.mul(&f.den), f.num.mul(&back.den), "{text}");
    }
}

#[test]
fn the_slow_path_corpus_answers_or_refuses_under_4_gb() {
    // tests/data/hardening/* (scripts/hardening_corpus.py) under the suite's address-space
    // limit: an answer or one line with exit 2 (time or memory), never an abort
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/hardening");
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    files.sort();
    assert!(files.len() >= 9);
    for f in files {
        let f = f.to_str().unwrap().to_string();
        answers_or_refuses(&["jordan", &f, "--max-seconds", "5"]);
    }
}
