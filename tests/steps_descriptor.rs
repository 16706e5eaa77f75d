//! `--steps` of `zeros` and `jordan --real` on descriptor files (through the standard form),
//! the reasons given for what has no derivation, and the derivation as data with its LaTeX
//! and HTML for notebooks (`api::steps::steps_on`, what the Python package shows), and the
//! free constants of generalized eigenvectors on the chain steps (the vehicle paper's eq. 30,
//! 32: `v_j + K c` solves `N x = v_(j-1)` for every `c`).

use crate::common;
use crate::common::cli::{json_of as json, step_names};
use crate::jcommon;
use exactlti::field::Field;
use exactlti::jordan::derivation::StepKind;
use exactlti::jordan::steps::jordan_steps;
use exactlti::matrix::Matrix;

/// The invariant zeros of a descriptor file: the steps (standard form first) end with the
/// zero polynomial of the standard system, which is the descriptor pencil's (`zeros`
/// without `--steps` computes it on the pencil itself).
#[test]
fn zeros_steps_of_a_descriptor_file_match_the_pencil() {
    for model in [
        "data/models/quarter-car-2mass.toml",
        "data/models/bounce-pitch.toml",
        "data/models/quarter-car-a-arm-pushrod.toml",
    ] {
        let j = json(&["zeros", model, "--steps", "--format", "json"]);
        assert_eq!(j["verified"], true, "{model}");
        let names = step_names(&j);
        assert_eq!(names[0], "compress_e", "{model}");
        let std_at = names.iter().position(|n| n == "standard_form").unwrap();
        assert!(names[std_at + 1..].contains(&"system_pencil".to_string()));
        // the zero polynomial z of the last step that states it (normal rank or Smith form)
        let last_z = j["steps"]
            .as_array()
            .unwrap()
            .iter()
            .rfind(|s| s.get("z").is_some())
            .unwrap();
        let z = json(&["zeros", model, "--format", "json"]);
        let want = z["zero_polynomial"].as_str();
        assert!(want.is_some(), "{z}");
        let got = last_z["z"].as_str();
        assert_eq!(got, want, "{model}: {last_z}\n{z}");
    }
}

#[test]
fn real_jordan_steps_of_a_descriptor_file() {
    let model = "data/models/spring-mass-damper.toml";
    let j = json(&["jordan", model, "--real", "--steps", "--format", "json"]);
    assert_eq!(j["verified"], true);
    let names = step_names(&j);
    assert_eq!(names[0], "compress_e");
    assert!(names.contains(&"standard_form".to_string()));
    assert!(names.contains(&"real_pair".to_string()), "{names:?}");
    // the real Jordan form is that of the standard form's A (what `jordan --real` reports)
    let r = json(&["jordan", model, "--real", "--format", "json"]);
    let last = j["steps"].as_array().unwrap().last().unwrap();
    assert_eq!(last["J"], r["J"], "{last}\n{r}");
}

#[test]
fn refusals_say_why() {
    let f = "data/sliding-masses.json";
    let args = ["minreal", f, "--method", "era", "--steps"];
    let (code, out, err) = common::cli::run(&args);
    assert_eq!(code, 2, "{args:?}: {err}");
    assert!(out.is_empty());
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    assert!(err.contains("float path"), "{err}");
    // `minreal --descriptor --steps` was refused here (the infinite part had no
    // derivation); it now derives the minimal descriptor realization
    let j = json(&[
        "minreal",
        "data/models/spring-mass-damper.toml",
        "--descriptor",
        "--steps",
        "--format",
        "json",
    ]);
    assert_eq!(j["verified"], true);
    assert_eq!(
        step_names(&j).last().map(String::as_str),
        Some("minimal_descriptor")
    );
}

/// The derivation for notebooks: the same steps as `--steps --format json`, the LaTeX of
/// `--format latex`, and HTML whose steps are the JSON's in order.
#[test]
fn steps_on_renders_every_format() {
    let path = std::path::Path::new("data/yaw-plane-single-wheel.json");
    let sys = exactlti::api::System::open(path, &Default::default()).unwrap();
    let cmd = exactlti::api::Command::parse_args(&["jordan", "data/yaw-plane-single-wheel.json"])
        .unwrap();
    let s = exactlti::api::steps::steps_on(&cmd, &sys).unwrap();
    assert!(s.verified);
    let cli = json(&[
        "jordan",
        "data/yaw-plane-single-wheel.json",
        "--steps",
        "--format",
        "json",
    ]);
    assert_eq!(s.report.to_json(), cli);
    let (code, latex, _) = common::cli::run(&[
        "jordan",
        "data/yaw-plane-single-wheel.json",
        "--steps",
        "--format",
        "latex",
    ]);
    assert_eq!(code, 0);
    assert_eq!(s.latex, latex);
    // every step in order, with its identity's verdict
    let mut at = 0;
    for name in step_names(&cli) {
        let tag = format!("<code>{name}</code>");
        let found = s.html[at..].find(&tag).unwrap_or_else(|| panic!("{tag}"));
        at += found + tag.len();
    }
    assert_eq!(
        s.html.matches("holds exactly").count(),
        cli["steps"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|st| st["holds"] == true)
            .count()
    );
    assert!(!s.html.contains("\\texttt") && !s.html.contains("\\subsection"));
    let open = s.html.matches("<li>").count();
    assert_eq!(open, s.html.matches("</li>").count());
    assert_eq!(open, step_names(&cli).len());
}

/// Every chain of length >= 2 carries K, a basis of ker N: N K = 0, as many columns as
/// eigenvectors, and each member v_j + K c of the family (c from a fixed-seed generator)
/// still solves N x = v_(j-1). Planted Jordan structures of sizes 3..7, and the yaw plane
/// (one free constant for the triple zero root, where eq. 30 prints two: x2 is fixed by the
/// equation, +-1/u).
#[test]
fn chain_steps_carry_the_family_of_generalized_eigenvectors() {
    let mut families = 0;
    for seed in 0..common::iters(12) as u64 {
        let (a, _) = jcommon::planted(3 + (seed as usize % 5), seed);
        let d = jordan_steps(&a).unwrap();
        for ks in d.of_kind(StepKind::KernelSequence) {
            let nm = ks.matrix("N").unwrap();
            let k = nm.field().clone();
            let eigvecs = ks.counts("dims").unwrap()[0];
            for ch in d.of_kind(StepKind::Chain).filter(|s| s.part == ks.part) {
                let v = ch.matrix("V").unwrap();
                let Some(kb) = ch.matrix("K") else {
                    assert_eq!(v.ncols(), 1, "a chain of length >= 2 has its family");
                    continue;
                };
                assert!((nm * kb).is_zero(), "N K = 0");
                assert_eq!((kb.ncols(), kb.rank()), (eigvecs, eigvecs));
                let n = v.nrows();
                for j in 1..v.ncols() {
                    let c = Matrix::from_fn(k.clone(), kb.ncols(), 1, |i, _| {
                        k.from_i64(((seed as i64 * 7 + i as i64 * 3 + j as i64) % 11) - 5)
                    });
                    let member = &v.submatrix(0, n, j, j + 1) + &(kb * &c);
                    assert_eq!(nm * &member, v.submatrix(0, n, j - 1, j), "N (v_j + K c)");
                }
                families += 1;
            }
        }
    }
    assert!(families > 0);
    let j = json(&[
        "jordan",
        "data/yaw-plane-single-wheel.json",
        "--steps",
        "--format",
        "json",
    ]);
    let top3 = j["steps"]
        .as_array()
        .unwrap()
        .iter()
        .find(|s| s["step"] == "chain" && s["top"] == 3)
        .unwrap();
    assert_eq!(top3["K"], serde_json::json!([["1"], ["0"], ["0"], ["0"]]));
}
