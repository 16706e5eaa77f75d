//! Everyday models (issue 11): the corpus in `tests/data/everyday` (written by
//! `scripts/everyday_corpus.py`). Exact results stay verified and compact: the real Jordan
//! form keeps complex pairs of large real fields in the compact form (verified on the
//! complex side), the Jordan-method minimal realization has the order of the other methods.
//! Speed is measured in `benches/everyday.rs`, not here.

use crate::common;
use exactlti::field::{Field, Q};
use exactlti::io::load_system_path;
use exactlti::jordan::{RealJordanForm, jordan};
use exactlti::matrix::Matrix;
use exactlti::realization::{MinrealMethod, mcmillan_degree, minimal, minimal_jordan};
use exactlti::system::StateSpace;
use std::path::Path;

fn system(name: &str) -> StateSpace<Q> {
    let p = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/everyday")
        .join(format!("{name}.json"));
    let l = load_system_path(&p).unwrap();
    l.rational().expect("rational corpus").ss.clone()
}

/// The approximate real `T`, `J` of the report satisfy `A T = T J` to float accuracy and `T`
/// is well conditioned: checks the Re/Im column layout of the compact blocks against the
/// `[[a, b], [-b, a]]` convention (the exact identity is checked on the complex side).
fn check_real_layout(a: &Matrix<Q>, rf: &RealJordanForm) {
    let n = a.nrows();
    let (jo, to) = rf.j_t_out();
    let get = |m: &Vec<Vec<(f64, f64)>>| nalgebra::DMatrix::from_fn(n, n, |i, j| m[i][j].0);
    let (j, t) = (get(&jo.approx), get(&to.approx));
    let af = nalgebra::DMatrix::from_fn(n, n, |i, k| exactlti::field::rational_to_f64(a.get(i, k)));
    let res = (&af * &t - &t * &j).norm();
    let scale = af.norm() * t.norm() + 1.0;
    assert!(res <= 1e-8 * scale, "A T - T J = {res} (scale {scale})");
    let sv = t.singular_values();
    assert!(sv.min() > 1e-12 * sv.max(), "real T singular: {sv}");
}

fn check_case(name: &str) {
    let sys = system(name);
    let n = sys.nstates();
    let jf = jordan(&sys.a).unwrap();
    assert!(jf.verified, "{name}: complex Jordan form");
    let rf = jf.real_form().unwrap();
    assert!(rf.exact && rf.verified, "{name}: {:?}", rf.notes);
    assert!(rf.notes.is_empty(), "{name}: {:?}", rf.notes);
    let cols: usize = rf.blocks.iter().map(|b| b.t_approx[0].len()).sum();
    assert_eq!(cols, n);
    for b in &rf.blocks {
        if let Some(cp) = b.compact() {
            let e = &jf.eigenvalues[b.eigenvalue];
            assert!(b.pair && e.approx.1 > 0.0);
            // the compact chains are the component's, verified A V = V J in QQ(theta)
            let comp = &jf.components[e.component];
            assert_eq!(cp.v, comp.chains.map(&cp.field, |x| x.clone()));
            assert!(comp.verify(&sys.a));
            // exact parts, when computed, are the parts of the eigenvalue
            if let (Some(re), Some(im)) = (&cp.re, &cp.im) {
                assert!((re.approx().0 - e.approx.0).abs() < 1e-9 * (1.0 + e.approx.0.abs()));
                assert!((im.approx().0 - e.approx.1).abs() < 1e-9 * (1.0 + e.approx.1.abs()));
            }
        }
    }
    check_real_layout(&sys.a, &rf);
    // Jordan-method minimal realization: verified, the order of the Kalman method
    let jm = minimal_jordan(&sys).unwrap();
    assert!(jm.verified, "{name}: Jordan-method minreal");
    let mcm = mcmillan_degree(&sys);
    assert_eq!(jm.order(), mcm, "{name}");
    let k = minimal(&sys, MinrealMethod::Kalman).unwrap();
    assert_eq!(k.system.nstates(), mcm, "{name}: Kalman");
    // JSON is complete: every entry exact (no `~` approximations)
    let js = jm.report().to_json();
    for key in ["A", "B", "C"] {
        let rows = js[key].as_array().unwrap();
        assert!(
            rows.iter()
                .flat_map(|r| r.as_array().unwrap())
                .all(|x| !x.as_str().unwrap_or("0").starts_with('~')),
            "{name}: {key}"
        );
    }
}

#[test]
fn quarter_car_compact_and_small() {
    check_case("quarter_car");
    let jf = jordan(&system("quarter_car").a).unwrap();
    let rf = jf.real_form().unwrap();
    // two complex pairs of an irreducible quartic: compact, parts as algebraic numbers
    assert_eq!(rf.blocks.len(), 2);
    for b in &rf.blocks {
        let cp = b.compact().expect("the real field has degree 12: compact");
        assert_eq!(cp.re.as_ref().unwrap().degree(), 6);
        assert_eq!(cp.im.as_ref().unwrap().degree(), 12);
    }
    let text = rf.report().to_text();
    assert!(text.len() < 4000, "{} bytes", text.len());
    assert!(text.contains("a1") && text.contains("Re(") && text.contains("-b1"));
    // on request the pairs are expanded into their real fields, exactly and verified
    let ex = jf.real_form_expanded().unwrap();
    assert!(
        ex.exact && ex.verified && ex.notes.is_empty(),
        "{:?}",
        ex.notes
    );
    assert!(
        ex.blocks
            .iter()
            .all(|b| b.exact_entries().is_some() && b.compact().is_none())
    );
}

#[test]
fn damped_chains_and_sliding_masses() {
    for name in [
        "damped_chain_3",
        "damped_chain_5_mimo",
        "sliding_masses_damped",
    ] {
        check_case(name);
    }
}

#[test]
fn dense_random_integer_systems() {
    for name in [
        "random_6_siso",
        "random_8_siso",
        "random_8_mimo",
        "random_12_siso",
    ] {
        check_case(name);
        // an irreducible characteristic polynomial: one simple component
        let jf = jordan(&system(name).a).unwrap();
        assert_eq!(jf.components.len(), 1, "{name}");
        assert_eq!(jf.components[0].multiplicity, 1);
    }
}

#[test]
fn papers_quadratic_and_biquadratic_pairs_stay_expanded() {
    // x^4 + 4 x^2 + 1 (roots i sqrt(2 +- sqrt 3)): real field Q(sqrt 3)-type of degree 4
    let a = exactlti::qmat![[0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1], [-1, 0, -4, 0]];
    let rf = jordan(&a).unwrap().real_form().unwrap();
    assert!(
        rf.blocks
            .iter()
            .all(|b| b.compact().is_none() && b.exact_entries().is_some())
    );
    assert!(rf.verified);
    // -1 +- i: over Q
    let a = exactlti::qmat![[-2, 0, 0], [0, 0, 1], [0, -2, -2]];
    let rf = jordan(&a).unwrap().real_form().unwrap();
    let (j, _) = rf.single_field().expect("over Q");
    assert_eq!(j.to_string(), "[[-2, 0, 0], [0, -1, 1], [0, -1, -1]]");
}

#[test]
fn simple_component_matches_the_general_chains() {
    // a simple irreducible factor beside a repeated one: the Krylov eigenvector and the
    // elimination give the same eigenspace (V' = V c for a scalar c in K)
    let mut rng = common::Rng(11);
    for _ in 0..common::iters(3) {
        let n = 5;
        let a = Matrix::from_fn(Q, n, n, |_, _| {
            exactlti::field::Rational::from_integer(rng.int(-4, 4).into())
        });
        let jf = jordan(&a).unwrap();
        assert!(jf.verified, "{a}");
        for c in jf.components.iter().filter(|c| c.multiplicity == 1) {
            let f = &c.field;
            let wv = &c.left_chains * &c.chains;
            assert!(wv.is_identity());
            assert!((0..n).any(|i| !f.is_zero(c.chains.get(i, 0))));
        }
    }
}

fn cli_json(args: &[&str]) -> serde_json::Value {
    common::cli::run_json(args)
}

const SECTIONS: [&str; 8] = [
    "system",
    "realization",
    "structure",
    "zeros",
    "jordan",
    "pbh",
    "modes",
    "mechanical",
];

#[test]
fn analyze_random_12_has_every_section_done_or_marked() {
    let f = "tests/data/everyday/random_12_siso.json";
    let j = cli_json(&["analyze", f]);
    for key in SECTIONS {
        let sec = &j[key];
        assert!(sec.is_object(), "{key} missing");
        // done (its own keys), skipped (with the reason), failed or not applicable
        assert!(
            !sec.as_object().unwrap().is_empty()
                || sec.get("error").is_some()
                || sec.get("not_applicable").is_some(),
            "{key}: {sec}"
        );
        if let Some(s) = sec.get("skipped") {
            assert!(s.as_str().unwrap().contains("to insist") && sec.get("reason").is_some());
        }
    }
    // the free response of a dense 12 x 12 is computed or announced with its size
    let fr = &j["jordan"]["free_response"];
    assert!(
        fr.get("terms").is_some()
            || fr.get("not_computed").is_some()
            || fr.get("skipped").is_some(),
        "{fr}"
    );
    // the eigenvalue test of the PBH section agrees with the Kalman ranks
    if j["pbh"].get("controllable").is_some() {
        assert_eq!(j["pbh"]["controllable"], j["realization"]["controllable"]);
        assert_eq!(j["pbh"]["observable"], j["realization"]["observable"]);
    }
    // a section budget that nothing fits: every section is still there, marked, exit 0
    let (code, out, err) = common::cli::run(&["analyze", f, "--section-seconds", "0.001"]);
    assert_eq!(code, 0, "{err}");
    for title in ["== eigenvalues and Jordan form ==", "== modal table =="] {
        assert!(out.contains(title), "{title}:\n{out}");
    }
    assert!(
        out.contains("skipped: after") && out.contains("to insist"),
        "{out}"
    );
    assert!(out.contains("--section-seconds"), "{out}");
}

#[test]
fn compact_text_by_default_full_on_request() {
    let f = "tests/data/everyday/random_8_siso.json";
    let j = cli_json(&["jordan", "--real", f]);
    let long: String = j["T"]
        .as_array()
        .unwrap()
        .iter()
        .flat_map(|r| r.as_array().unwrap())
        .map(|x| x.as_str().unwrap().to_string())
        .max_by_key(String::len)
        .unwrap();
    assert!(long.len() > 24, "{long}");
    let (code, compact, _) = common::cli::run(&["jordan", "--real", f]);
    assert_eq!(code, 0);
    assert!(compact.contains("T (8x8) ~ (4 digits"), "{compact}");
    assert!(!compact.contains(&long));
    let (code, full, _) = common::cli::run(&["jordan", "--real", f, "--full"]);
    assert_eq!(code, 0);
    assert!(full.contains(&long) && !full.contains("~ (4 digits"));
    // short entries stay exact in compact mode; wide matrices come in column blocks
    let (code, out, _) = common::cli::run(&["jordan", "data/sliding-masses.json"]);
    assert_eq!(code, 0);
    assert!(
        out.contains("sqrt(2)*i") && out.contains("columns 1.."),
        "{out}"
    );
    assert!(
        out.lines()
            .filter(|l| l.trim_start().starts_with("[ "))
            .all(|l| l.chars().count() <= 100)
    );
}

#[test]
fn freqresp_and_modes_as_tables() {
    let f = "tests/data/everyday/quarter_car.json";
    let (code, out, _) = common::cli::run(&[
        "freqresp", f, "--points", "5", "--from", "0.01", "--to", "10",
    ]);
    assert_eq!(code, 0);
    assert!(
        out.contains("frequency (Hz)  magnitude (dB)  phase (deg)"),
        "{out}"
    );
    assert_eq!(
        out.lines().filter(|l| l.starts_with("  10 ")).count(),
        1,
        "{out}"
    );
    // JSON unchanged: the frequencies and [re, im] per channel
    let j = cli_json(&["freqresp", f, "--points", "5"]);
    assert_eq!(j["frequencies_hz"].as_array().unwrap().len(), 5);
    assert_eq!(j["response"][0][0][0].as_array().unwrap().len(), 2);
    let (code, out, _) = common::cli::run(&["modes", f]);
    assert_eq!(code, 0);
    assert!(
        out.contains("mode") && out.contains("frequency (Hz)") && out.contains("damping ratio"),
        "{out}"
    );
    assert_eq!(out.matches("11.33").count(), 1, "{out}");
    let j = cli_json(&["modes", f]);
    assert!(j["modes"][0]["frequency_hz"].as_f64().unwrap() > 0.0);
}

#[test]
fn one_display_per_number_in_analyze() {
    // x^4 + 4 x^2 + 1 is a zero and an eigenvalue of the sliding masses: one display
    let j = cli_json(&["analyze"]);
    let mut seen: std::collections::HashMap<String, std::collections::HashSet<String>> =
        Default::default();
    fn walk(
        v: &serde_json::Value,
        seen: &mut std::collections::HashMap<String, std::collections::HashSet<String>>,
    ) {
        match v {
            serde_json::Value::Object(m) => {
                if let (Some(mp), Some(ap)) = (m.get("minpoly"), m.get("approx")) {
                    let shown = m.get("value").or_else(|| m.get("eigenvalue"));
                    if let Some(s) = shown {
                        let f = |x: &serde_json::Value| x.as_f64().unwrap_or(0.0) + 0.0;
                        let key = format!("{mp} {:.6} {:.6}", f(&ap[0]), f(&ap[1]));
                        seen.entry(key)
                            .or_default()
                            .insert(s.as_str().unwrap().to_string());
                    }
                }
                m.values().for_each(|x| walk(x, seen));
            }
            serde_json::Value::Array(xs) => xs.iter().for_each(|x| walk(x, seen)),
            _ => {}
        }
    }
    walk(&j, &mut seen);
    assert!(
        seen.keys().any(|k| k.starts_with("\"x^4 + 4*x^2 + 1\"")),
        "{seen:?}"
    );
    for (k, shown) in &seen {
        assert_eq!(shown.len(), 1, "{k}: {shown:?}");
    }
    assert!(
        seen.values()
            .flatten()
            .any(|s| s == "i*sqrt(2 + sqrt(3))" || s == "-i*sqrt(2 + sqrt(3))")
    );
}

/// On a terminal (a pseudo-terminal made by util-linux `script`, when installed), work that
/// passes a second shows a spinner line on stderr naming the section, with the time since the
/// command started, and clears it; through a pipe stderr carries no control sequences.
#[test]
fn spinner_on_a_terminal_only() {
    let f = "tests/data/everyday/random_16_mimo.json";
    let args = [
        "analyze",
        f,
        "--full",
        "--section-seconds",
        "1.5",
        "--max-seconds",
        "3",
    ];
    let (_, _, err) = common::cli::run(&args);
    assert!(!err.contains('\u{1b}'), "{err:?}");
    let have_script = std::process::Command::new("script")
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success());
    if !have_script {
        eprintln!("util-linux `script` not found: terminal part skipped");
        return;
    }
    let command = format!(
        "{} {} > /dev/null",
        env!("CARGO_BIN_EXE_exactlti"),
        args.join(" ")
    );
    let out = std::process::Command::new("script")
        .args(["-q", "-c", &command, "/dev/null"])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("script runs");
    let tty = String::from_utf8_lossy(&out.stdout);
    assert!(tty.contains("\u{1b}[2K"), "no progress line: {tty:?}");
    // the clock counts from the start: the first frame is shown after one second
    let first = tty.split("\u{1b}[2K").next().unwrap_or_default();
    assert!(!first.contains(" 0s "), "{first:?}");
    assert!(
        ["Jordan", "response", "PBH", "modal", "eigen"]
            .iter()
            .any(|w| tty.contains(w)),
        "no section named: {tty:?}"
    );
}
