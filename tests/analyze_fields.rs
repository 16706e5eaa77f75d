//! `analyze` over Q, Q(sqrt 2), Q(i) and Q(a) (issue 23: the eigenvalue consumers of the
//! front door on every field). On one family of systems per field -- `diag(l1, -1, -2)`
//! seen by `C = [1 1 1]`, excited by `B = [1 1 b3]'`, with `l1` in the field (`a` over
//! Q(a)) -- the report's sections are checked against each other, by identities between
//! independent methods:
//!
//! * PBH (per irreducible factor, by ranks over `F[t]/(g)` or from the Jordan form) agrees
//!   with the Kalman ranks of the realization section (`rank [B, AB, ...] = n`), both ways
//!   (`b3 = 0`: the mode -2 is not excited);
//! * the modal table accounts for every eigenvalue: over a number field the modes'
//!   multiplicities add up to `n`; over Q(a) the factors' degrees times their
//!   multiplicities add up to `n` (the modes as formulas, as `modes`);
//! * the stability section is present over every numeric field and decides the sign of
//!   the real parts (all negative here: asymptotically stable); over Q(a) the eigenvalue
//!   `-a` has a sign that depends on `a`, and the report says so ("not decided in
//!   symbols"), never a guess.

use crate::common::cli::{run, temp_file};

fn json(args: &[&str]) -> serde_json::Value {
    let (code, out, err) = run(args);
    assert_eq!(code, 0, "{args:?}: {err}");
    serde_json::from_str(&out).unwrap()
}

/// The system file of the family over the field of `l1` (`symbols` for Q(a)).
fn file(name: &str, l1: &str, b3: &str, symbols: bool) -> std::path::PathBuf {
    let sym = if symbols { r#""symbols": ["a"], "# } else { "" };
    let text = format!(
        r#"{{{sym}"A": [["{l1}", 0, 0], [0, -1, 0], [0, 0, -2]], "B": [[1], [1], [{b3}]], "C": [[1, 1, 1]], "D": [[0]]}}"#
    );
    temp_file("analyze_fields", name, &text)
}

const FIELDS: [(&str, &str, bool); 4] = [
    ("q", "-3", false),
    ("qsqrt2", "-sqrt(2)", false),
    ("qi", "-1 + i", false),
    ("qa", "-a", true),
];

#[test]
fn analyze_pbh_modes_and_stability_over_every_field() {
    for (name, l1, symbolic) in FIELDS {
        for b3 in ["1", "0"] {
            let f = file(&format!("{name}_{b3}.json"), l1, b3, symbolic);
            let j = json(&["analyze", f.to_str().unwrap(), "--format", "json"]);
            let n = 3;
            // PBH against the Kalman rank of the realization section
            let pbh = &j["pbh"];
            let rz = &j["realization"];
            assert!(pbh["controllable"].is_boolean(), "{name}: {pbh}");
            assert_eq!(
                pbh["controllable"], rz["controllable"],
                "{name} b3={b3}: {j}"
            );
            assert_eq!(pbh["observable"], rz["observable"], "{name} b3={b3}");
            assert_eq!(pbh["controllable"], b3 == "1", "{name} b3={b3}");
            assert_eq!(pbh["observable"], true, "{name}");
            // the modal table accounts for every eigenvalue
            let modes = j["modes"]["modes"]
                .as_array()
                .unwrap_or_else(|| panic!("{j}"));
            let count: u64 = if symbolic {
                modes
                    .iter()
                    .map(|m| {
                        let g = m["factor"].as_str().unwrap();
                        // monic factors in s of degree 1 here (the eigenvalues lie in Q(a))
                        let deg = if g.contains("s^") { 2 } else { 1 };
                        deg * m["multiplicity"].as_u64().unwrap()
                    })
                    .sum()
            } else {
                modes
                    .iter()
                    .map(|m| m["multiplicity"].as_u64().unwrap())
                    .sum()
            };
            assert_eq!(count, n, "{name}: {}", j["modes"]);
            // stability: decided over the numeric fields, "not decided" over Q(a)
            let st = &j["jordan"]["stability"];
            if symbolic {
                let s = st.as_str().unwrap_or_else(|| panic!("{}", j["jordan"]));
                assert!(s.contains("not decided in symbols"), "{s}");
            } else {
                let v = st["verdict"].as_str().unwrap_or_else(|| panic!("{st}"));
                assert!(v.starts_with("asymptotically stable"), "{name}: {v}");
            }
        }
    }
}
