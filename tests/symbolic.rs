//! Symbolic parameters (contract, second wave): the single-wheel yaw-plane model of the
//! vehicle-dynamics paper (eq. 27) over QQ(cr, m, u).

use crate::common::cli::run;
use exactlti::field::ElemDisplay;
use exactlti::field::Field;
use exactlti::io::TypedAny;
use exactlti::io::symbolic::{SymbolicOptions, load_symbolic_path};
use std::path::Path;

const YAW: &str = "data/yaw-plane-single-wheel.json";

fn all_symbolic() -> SymbolicOptions {
    SymbolicOptions::from_args(Some(""), None).unwrap()
}

#[test]
fn yaw_plane_charpoly_is_s3_times_s_plus_cr_over_mu() {
    let l = load_symbolic_path(Path::new(YAW), &all_symbolic()).unwrap();
    let TypedAny::RatFunc(t) = &l.system else {
        panic!("expected QQ(p)")
    };
    let k = t.a_raw.field().clone();
    assert_eq!(k.to_string(), "QQ(cr, m, u)");
    let p = t.a_raw.charpoly().unwrap();
    // s^3 (s + cr/(m u)): coefficients 0, 0, 0, cr/(m u), 1
    let c = k.parse("cr/(m*u)").unwrap();
    let want = [k.zero(), k.zero(), k.zero(), c, k.one()];
    assert_eq!(p.coeffs(), &want[..]);
    // Cayley-Hamilton as rational functions: A^4 + cr/(m u) A^3 = 0
    let a = &t.a_raw;
    let a2 = a.try_mul(a).unwrap();
    let a3 = a2.try_mul(a).unwrap();
    let a4 = a3.try_mul(a).unwrap();
    for i in 0..4 {
        for j in 0..4 {
            let v = k.add(a4.get(i, j), &k.mul(&want[3], a3.get(i, j)));
            assert!(k.is_zero(&v), "Cayley-Hamilton fails at ({i}, {j})");
        }
    }
}

#[test]
fn at_values_give_the_rational_system() {
    let o = SymbolicOptions::from_args(Some(""), Some("m=1500, u=20, cr=80000")).unwrap();
    let l = load_symbolic_path(Path::new(YAW), &o).unwrap();
    let TypedAny::Rational(t) = &l.system else {
        panic!("expected QQ")
    };
    assert_eq!(t.a_raw.get(2, 2).to_string(), "-8/3");
    let o = SymbolicOptions::from_args(Some("m"), None).unwrap();
    let l = load_symbolic_path(Path::new(YAW), &o).unwrap();
    let TypedAny::RatFunc(t) = &l.system else {
        panic!("expected QQ(m)")
    };
    let k = t.a_raw.field();
    assert_eq!(k.fmt_elem(t.a_raw.get(2, 2)), "-4000/m");
}

#[test]
fn cli_rank_of_a_is_3_with_conditions() {
    let (code, out, _) = run(&["linalg", "rank", YAW, "--symbolic", "--format", "json"]);
    assert_eq!(code, 0);
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["rank"], 3);
    assert_eq!(j["field"], "QQ(cr, m, u)");
    // cr: the rank drops below 3 there; m and u: denominators of A[3,3] (the model is
    // undefined), listed with their reasons (issue 25 item 3)
    assert_eq!(j["conditions"], serde_json::json!(["cr", "m", "u"]));
    let kinds: Vec<&str> = j["condition_reasons"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["kind"].as_str().unwrap())
        .collect();
    assert_eq!(
        kinds,
        ["structure_change", "input_denominator", "input_denominator"]
    );
    let (code, out, _) = run(&["linalg", "rref", YAW, "--symbolic", "--format", "json"]);
    assert_eq!(code, 0);
    assert!(
        !out.contains("approx"),
        "no approx fields over QQ(p): {out}"
    );
}

#[test]
fn cli_refuses_unsupported_commands_with_one_line() {
    // scb, minreal, zeros, ctrb work over Q(p) now (tests/symbolic_scb.rs); so does
    // pencil (the Kronecker structure is generic over the field; issue 24)
    let (code, out, err) = run(&["pencil", YAW, "--symbolic", "m,u", "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["field"], "QQ(m, u)");
    assert_eq!(j["verified"], true);
    // numbers asked of symbols: not a question, and the one line says why
    for cmd in ["freqresp", "check", "step", "pzmap"] {
        let (code, out, err) = run(&[cmd, YAW, "--symbolic", "m,u"]);
        assert_eq!(code, 2, "{cmd}: {err}");
        assert!(out.is_empty());
        assert_eq!(err.lines().count(), 1, "{cmd}: {err}");
        assert!(
            err.contains(&format!("`{cmd}` needs numbers (a float computation), this system's entries lie in QQ(m, u); give every symbol a value with --at")),
            "{cmd}: {err}"
        );
    }
    let (code, _, err) = run(&["linalg", "rank", YAW, "--symbolic", "x"]);
    assert_eq!(code, 2);
    assert!(err.contains("--symbolic: unknown parameter 'x'"), "{err}");
}

#[test]
fn a_alone_is_a_system_without_inputs_and_outputs() {
    use exactlti::io::SystemFormat;
    use exactlti::io::symbolic::load_symbolic_str;
    let text = r#"{"parameters": {"a": null}, "A": [["a", 1], [0, "a"]]}"#;
    let l = load_symbolic_str(
        text,
        SystemFormat::Json,
        "x.json",
        &SymbolicOptions::default(),
    )
    .unwrap();
    let TypedAny::RatFunc(t) = &l.system else {
        panic!("expected QQ(a)")
    };
    assert_eq!(t.ss.b.shape(), (2, 0));
    assert_eq!(t.ss.c.shape(), (0, 2));
    assert_eq!(t.ss.d.shape(), (0, 0));
    // the Jordan form of a single block: J = A, two chains of one eigenvalue a
    let jf = exactlti::jordan::jordan_qp(&t.a_raw).unwrap();
    assert!(jf.verified && jf.complete());
    assert_eq!(jf.components[0].blocks, vec![2]);
}

/// `--symbolic` takes an optional value: a file name after it is the FILE, not names
/// (`--symbolic x.json` was read as the names `x.json`, the FILE then missing); names and
/// `--symbolic=NAMES` keep their meaning.
#[test]
fn symbolic_before_the_file_does_not_swallow_it() {
    let expect = |args: &[&str], field: &str| {
        let (code, out, err) = run(args);
        assert_eq!(code, 0, "{args:?}: {err}");
        let j: serde_json::Value = serde_json::from_str(&out).unwrap();
        assert_eq!(j["field"], field, "{args:?}");
        out
    };
    let after = expect(
        &["linalg", "charpoly", YAW, "--symbolic", "--format", "json"],
        "QQ(cr, m, u)",
    );
    for args in [
        &["linalg", "charpoly", "--symbolic", YAW, "--format", "json"][..],
        &["--symbolic", "linalg", "charpoly", YAW, "--format", "json"][..],
        &["linalg", "--symbolic", "charpoly", YAW, "--format", "json"][..],
    ] {
        // the last two: `charpoly`/`linalg` is a list of names, taken as NAMES (an unknown
        // parameter: refused, one line) as before
        let (code, out, err) = run(args);
        if args[0] == "linalg" && args[2] == "--symbolic" {
            assert_eq!(code, 0, "{args:?}: {err}");
            assert_eq!(out, after, "{args:?}");
        } else {
            assert_eq!(code, 2, "{args:?}: {out}");
            assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
        }
    }
    // names stay names, spelled either way, before or after the file
    for args in [
        &[
            "linalg",
            "charpoly",
            "--symbolic",
            "m,u",
            YAW,
            "--format",
            "json",
        ][..],
        &[
            "linalg",
            "charpoly",
            "--symbolic=m,u",
            YAW,
            "--format",
            "json",
        ][..],
        &[
            "linalg",
            "charpoly",
            YAW,
            "--symbolic",
            "m,u",
            "--format",
            "json",
        ][..],
    ] {
        expect(args, "QQ(m, u)");
    }
    // a path is never a list of names, even when it does not exist: the file is missing
    let (code, _, err) = run(&["linalg", "charpoly", "--symbolic", "no/such.json"]);
    assert_eq!(code, 2);
    assert!(err.contains("no/such.json"), "{err}");
    assert!(!err.contains("unknown parameter"), "{err}");
}
