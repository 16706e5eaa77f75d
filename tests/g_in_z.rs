//! A transfer-matrix file with a sample time `dt` is written in `z` (python-control's
//! `tf(num, den, dt)`): read in `z`, realized (minimally or as written), `dt` kept; `s` in
//! such a file, or `z` without `dt`, is an unknown name naming the entry.

use crate::common::cli::{run, temp_file};

fn file(name: &str, body: &str) -> String {
    temp_file("g_in_z", name, body)
        .to_str()
        .unwrap()
        .to_string()
}

#[test]
fn g_in_z_realizes_with_dt_and_prints_z() {
    let f = file(
        "gz.json",
        r#"{"G": [["(z + 1/2)/((z - 4/5)*(z - 1/2))"]], "dt": "1/10"}"#,
    );
    let (code, out, err) = run(&["tf", &f]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains('z') && !out.contains("(s"), "{out}");
    let (code, out, err) = run(&["pzmap", &f, "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("4/5") && out.contains("1/2"), "{out}");
    // as written keeps a cancelled factor: two poles 1/2 and 4/5 plus the written (z + 1/2)
    let f2 = file(
        "gz2.json",
        r#"{"G": [["(z + 1/2)/((z + 1/2)*(z - 4/5))"]], "dt": "1/10", "realize": "as_written"}"#,
    );
    let (code, out, err) = run(&["pzmap", &f2, "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("-1/2") && out.contains("4/5"), "{out}");
    let (code, out, err) = run(&["zeros", &f, "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("-1/2"), "{out}");
}

#[test]
fn the_other_variable_is_an_unknown_name() {
    let f = file("gs.json", r#"{"G": [["1/(s + 1)"]], "dt": "1/10"}"#);
    let (code, _out, err) = run(&["tf", &f]);
    assert_eq!(code, 2);
    assert!(
        err.contains("the variable is z") && err.contains("G"),
        "{err}"
    );
    assert_eq!(err.trim().lines().count(), 1, "{err}");
    let f = file("zc.json", r#"{"G": [["1/(z + 1)"]]}"#);
    let (code, _out, err) = run(&["tf", &f]);
    assert_eq!(code, 2);
    assert!(err.contains("the variable is s"), "{err}");
}
