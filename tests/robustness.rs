//! Degenerate shapes through every library command (issue 17): n = 0 finite states, no
//! inputs, no outputs, E = 0, empty matrices. Each answers or errs with a typed error; no panic.

use crate::common::cli::run;
use exactlti::float;
use nalgebra::DMatrix;

#[test]
fn float_freqresp_with_no_states() {
    let a = DMatrix::<f64>::zeros(0, 0);
    let b = DMatrix::<f64>::zeros(0, 1);
    let c = DMatrix::<f64>::zeros(1, 0);
    let d = DMatrix::from_element(1, 1, 2.0);
    let g = float::freqresp([&a, &b, &c, &d], &[0.1, 1.0], None).unwrap();
    assert_eq!(g.len(), 2);
    assert_eq!(g[1][(0, 0)].re, 2.0);
    // no inputs, no outputs
    let g = float::freqresp(
        [
            &DMatrix::from_element(1, 1, -1.0),
            &DMatrix::zeros(1, 0),
            &DMatrix::zeros(0, 1),
            &DMatrix::zeros(0, 0),
        ],
        &[1.0],
        None,
    )
    .unwrap();
    assert_eq!(g[0].shape(), (0, 0));
}

/// Every command on n = 0 finite states (E = 0), no inputs, no outputs, an empty system and
/// B = 0: an answer (exit 0) or a one-line refusal (exit 2); never a panic or exit 1.
#[test]
fn every_command_on_degenerate_shapes() {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("exactlti-robust");
    std::fs::create_dir_all(&dir).unwrap();
    let files = [
        ("e0", r#"{"E": [[0]], "A": [[1]], "B": [[1]], "C": [[1]]}"#),
        (
            "e00",
            r#"{"E": [[0, 0], [0, 0]], "A": [[1, 0], [0, 1]], "B": [[1], [1]], "C": [[1, 1]]}"#,
        ),
        (
            "noin",
            r#"{"A": [[1, 2], [3, 4]], "B": [[], []], "C": [[1, 0]]}"#,
        ),
        (
            "noout",
            r#"{"A": [[1, 2], [3, 4]], "B": [[1], [0]], "C": []}"#,
        ),
        ("empty", r#"{"A": [], "B": [], "C": []}"#),
        ("zerob", r#"{"A": [[-1]], "B": [[0]], "C": [[0]]}"#),
    ];
    let cmds: &[&[&str]] = &[
        &["jordan"],
        &["jordan", "--real"],
        &["minreal"],
        &["minreal", "--method", "rosenbrock"],
        &["minreal", "--method", "ho-kalman"],
        &["minreal", "--method", "jordan"],
        &["minreal", "--method", "era"],
        &["standard"],
        &["scb"],
        &["mnf"],
        &["zeros"],
        &["pencil"],
        &["ctrb"],
        &["obsv"],
        &["tf"],
        &["modes"],
        &["freqresp", "--points", "3"],
        &["check"],
        &["analyze"],
        &["linalg", "det"],
        &["linalg", "rank"],
        &["linalg", "charpoly"],
        &["linalg", "inverse"],
        &["linalg", "nullspace"],
        &["linalg", "rref"],
    ];
    for (name, text) in files {
        let p = dir.join(format!("{name}.json"));
        std::fs::write(&p, text).unwrap();
        for cmd in cmds {
            let mut a = cmd.to_vec();
            a.push(p.to_str().unwrap());
            let (code, _, err) = run(&a);
            assert!(
                code == 0 || (code == 2 && err.lines().count() == 1),
                "{name}: {a:?}: exit {code}: {err}"
            );
        }
    }
    // E = 0: no finite dynamics, G = -C A^-1 B = -1 at every frequency (this panicked)
    let p = dir.join("e0.json");
    let (code, out, err) = run(&[
        "freqresp",
        p.to_str().unwrap(),
        "--points",
        "3",
        "--format",
        "json",
    ]);
    assert_eq!(code, 0, "{err}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    for g in j["response"].as_array().unwrap() {
        assert_eq!(g[0][0][0].as_f64(), Some(-1.0), "{g}");
        assert_eq!(g[0][0][1].as_f64(), Some(0.0), "{g}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
