//! CLI of the second-wave descriptor commands: `pencil`, `ctrb`, `obsv`, `tf`,
//! `minreal --descriptor`, `zeros` with `E`, and the key `G`.

/// The CLI with `--format json` appended: exit code, the output's JSON (`Null` when it is
/// not JSON) and stderr.
fn run(args: &[&str]) -> (i32, serde_json::Value, String) {
    let mut a = args.to_vec();
    a.extend(["--format", "json"]);
    let (code, out, err) = crate::common::cli::run(&a);
    let v = serde_json::from_str(&out).unwrap_or(serde_json::Value::Null);
    (code, v, err)
}

#[test]
fn cli_pencil_and_minreal_descriptor() {
    let (code, v, err) = run(&["pencil", "tests/data/improper_s.json"]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(v["regular"], true);
    assert_eq!(v["infinite_elementary_divisors"], serde_json::json!([1, 2]));
    assert_eq!(v["finite_eigenvalues"][0]["value"], "-3");
    assert_eq!(v["verified"], true);
    let (code, v, err) = run(&["minreal", "tests/data/improper_s.json", "--descriptor"]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(
        (v["order"].as_u64(), v["irreducible_order"].as_u64()),
        (Some(2), Some(2))
    );
    assert_eq!(v["D"], serde_json::json!([["-1"]]));
    assert_eq!(v["verified"], true);
    // without --descriptor an improper system is refused with the degree of its polynomial part
    let (code, _, err) = run(&["minreal", "tests/data/improper_s.json"]);
    assert_eq!(code, 2);
    assert!(err.contains("polynomial part of degree 1"), "{err}");
    // `standard` refuses too, stating the polynomial part itself (G(s) = s - 1 here)
    let (code, _, err) = run(&["standard", "tests/data/improper_s.json"]);
    assert_eq!(code, 2);
    assert!(err.contains("degree 1 in s, P(s) = [[s - 1]]"), "{err}");
}

#[test]
fn cli_zeros_ctrb_obsv() {
    let (code, v, err) = run(&["zeros", "tests/data/improper_s.json"]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(v["zero_polynomial"], "s^2 + 2*s - 3");
    assert_eq!(v["infinite_zero_orders"], serde_json::json!([]));
    let (code, v, err) = run(&["ctrb", "tests/data/improper_s.json"]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(v["controllable_infinite_order"], 2);
    assert_eq!(v["uncontrollable_infinite_eigenvalues"], 1);
    let (code, v, err) = run(&["ctrb", "tests/data/ctrb_planted.json"]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(v["controllability_indices"], serde_json::json!([2]));
    assert_eq!(v["staircase_block_dims"], serde_json::json!([1, 1]));
    assert_eq!(v["uncontrollable_eigenvalues"][0]["value"], "5");
    let (code, v, err) = run(&["obsv", "tests/data/ctrb_planted.json"]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(v["observable_order"], 3);
}

#[test]
fn cli_tf_from_g() {
    let (code, v, err) = run(&["tf", "tests/data/tf_G.json"]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(v["mcmillan_degree"], 3);
    assert_eq!(v["transfer_matrix"][0][1], "(2)/(s + 1)");
    assert_eq!(v["transfer_matrix"][1][1], "1/2");
    let poles: Vec<&str> = v["poles"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p["value"].as_str().unwrap())
        .collect();
    assert_eq!(poles, ["-1", "-2", "-3"]);
    assert_eq!(v["verified"], true);
    // a bad entry names key, row and column
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("exactlti_cli_pencil");
    std::fs::create_dir_all(&dir).unwrap();
    let bad = dir.join("bad_g.json");
    std::fs::write(&bad, r#"{"G": [["1/(s+1)", "1/(s - s)"]]}"#).unwrap();
    let (code, _, err) = run(&["tf", bad.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(err.contains("key G, row 1, column 2"), "{err}");
}

#[test]
fn cli_pencil_rectangular() {
    let (code, v, err) = run(&["pencil", "tests/data/pencil_rect.json"]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(v["normal_rank"], 3);
    assert_eq!(v["regular"], false);
    assert_eq!(v["right_kronecker_indices"], serde_json::json!([1]));
    assert_eq!(v["infinite_elementary_divisors"], serde_json::json!([1]));
    assert_eq!(v["finite_eigenvalues"][0]["value"], "2");
    assert_eq!(v["verified"], true);
    let (code, _, err) = run(&["ctrb", "tests/data/pencil_rect.json"]);
    assert_eq!(code, 2);
    assert!(err.contains("must be square"), "{err}");
}

/// The bicycle descriptor model of the minimal-realization paper (sec. 4.2, v = 2 m/s)
/// through the CLI: `pencil` (regular, one non-dynamic mode, 6 finite eigenvalues),
/// `standard` (7 -> 6), `minreal --descriptor` (-> 4, irreducible 4).
#[test]
fn cli_bicycle_descriptor() {
    use exactlti::field::Q;
    use exactlti::matrix::Matrix;
    use exactlti::report::display::fmt_rational;
    let d = crate::bicycle::bicycle_descriptor("2");
    let js = |m: &Matrix<Q>| {
        let rows: Vec<String> = (0..m.nrows())
            .map(|i| {
                let r: Vec<String> = m
                    .row(i)
                    .iter()
                    .map(|x| format!("\"{}\"", fmt_rational(x)))
                    .collect();
                format!("[{}]", r.join(", "))
            })
            .collect();
        format!("[{}]", rows.join(", "))
    };
    let text = format!(
        "{{\"E\": {}, \"A\": {}, \"B\": {}, \"C\": {}, \"D\": {}}}",
        js(&d.e),
        js(&d.a),
        js(&d.b),
        js(&d.c),
        js(&d.d)
    );
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("exactlti_cli_pencil");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("bicycle_descriptor_2.json");
    std::fs::write(&path, text).unwrap();
    let path = path.to_str().unwrap();
    let (code, v, err) = run(&["pencil", path]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(v["regular"], true);
    assert_eq!(v["normal_rank"], 7);
    assert_eq!(v["infinite_elementary_divisors"], serde_json::json!([1]));
    assert_eq!(v["right_kronecker_indices"], serde_json::json!([]));
    assert_eq!(v["left_kronecker_indices"], serde_json::json!([]));
    let nfin: usize = v["finite_eigenvalues"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| {
            x["blocks"]
                .as_array()
                .unwrap()
                .iter()
                .map(|b| b.as_u64().unwrap() as usize)
                .sum::<usize>()
        })
        .sum();
    assert_eq!(nfin, 6);
    assert_eq!(v["verified"], true);
    let (code, v, err) = run(&["standard", path]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(v["A"].as_array().map(Vec::len), Some(6));
    assert_eq!(v["verified"], true);
    let (code, v, err) = run(&["minreal", path, "--descriptor"]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(
        (v["order"].as_u64(), v["irreducible_order"].as_u64()),
        (Some(4), Some(4))
    );
    assert_eq!(v["verified"], true);
}

/// `tf` of a rational state-space file checks G against the system's Markov parameters
/// (as over Q(i) / Q(sqrt d)); a G given directly has no system to check against.
#[test]
fn cli_tf_of_a_state_space_checks_markov_parameters() {
    let (code, v, err) = run(&["tf", "data/quarter-car.json"]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(v["markov_verified"], true);
    assert_eq!(v["verified"], true);
    let (code, v, err) = run(&["tf", "tests/data/tf_G.json"]);
    assert_eq!(code, 0, "{err}");
    assert!(v.get("markov_verified").is_none());
}

/// `jordan` of a descriptor file with symbols is the Jordan form of the pencil's finite part
/// (as for numbers), not of `A` alone: E = diag(1, m, 0) leaves two finite eigenvalues, the
/// roots of s^2 + (c/m) s + k/m, and one non-dynamic mode (infinite block of size 1).
#[test]
fn jordan_of_a_symbolic_descriptor_is_the_finite_part() {
    let text = |params: &str| {
        format!(
            r#"{{"parameters": {{{params}}},
 "E": [[1,0,0],[0,"m",0],[0,0,0]],
 "A": [[0,1,0],[0,"-c",1],["-k",0,-1]],
 "B": [[0],[0],[1]], "C": [[1,0,0]], "D": [[0]]}}"#
        )
    };
    let sym = crate::common::cli::temp_file(
        "jordan-desc",
        "sym.json",
        &text(r#""m": null, "k": null, "c": null"#),
    );
    let num = crate::common::cli::temp_file(
        "jordan-desc",
        "num.json",
        &text(r#""m": 2, "k": 3, "c": 1"#),
    );
    for (file, real) in [(&sym, false), (&sym, true), (&num, false)] {
        let f = file.to_str().unwrap();
        let mut args = vec!["jordan", f];
        if real {
            args.push("--real");
        }
        let (code, v, err) = run(&args);
        assert_eq!(code, 0, "{args:?}: {err}");
        assert_eq!(
            v["infinite_blocks"],
            serde_json::json!([1]),
            "{args:?}: {v}"
        );
        assert!(v["note"].as_str().unwrap().contains("finite part"), "{v}");
        assert_eq!(v["n"], 2, "{args:?}: {v}");
    }
    let (_, v, _) = run(&["jordan", sym.to_str().unwrap()]);
    let chi = v["charpoly"].as_str().unwrap();
    assert!(chi.starts_with("s^2") && chi.contains("k/m"), "{chi}");
}
