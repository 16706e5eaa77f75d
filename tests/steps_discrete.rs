//! `--steps` of a discrete-time system in its variable (issue 28): the transfer function is
//! G(z), characteristic polynomials chi_A(z) = det(zI - A), polynomials printed in z, in
//! text, JSON and LaTeX; the same file without `dt` prints s, so continuous time is unchanged.

use crate::common::cli::{run, temp_file};

const SYS: &str = r#""A": [[0.5, 0.1], [0, 0.8]], "B": [[0], [1]], "C": [[1, 0]], "D": [[0]]"#;

fn files() -> (String, String) {
    let d = temp_file(
        "steps_discrete",
        "d.json",
        &format!("{{\"dt\": \"1/10\", {SYS}}}"),
    );
    let c = temp_file("steps_discrete", "c.json", &format!("{{{SYS}}}"));
    (
        d.to_string_lossy().into_owned(),
        c.to_string_lossy().into_owned(),
    )
}

fn out(args: &[&str]) -> String {
    let (code, out, err) = run(args);
    assert_eq!(code, 0, "{args:?}: {err}");
    out
}

#[test]
fn tf_steps_in_z_text_json_latex() {
    let (d, c) = files();
    let text = out(&["tf", &d, "--steps"]);
    assert!(
        text.contains("chi_A(z) = det(z I - A) = z^2 - 13/10*z + 2/5"),
        "{text}"
    );
    assert!(text.contains("N(z0) = chi(z0) C (z0 I - A)^-1 B"), "{text}");
    assert!(text.contains("den: [z^2 - 13/10*z + 2/5]"), "{text}");
    assert!(!text.contains("(s") && !text.contains("*s"), "{text}");
    let json: serde_json::Value =
        serde_json::from_str(&out(&["tf", &d, "--steps", "--format", "json"])).unwrap();
    let j = json.to_string();
    assert!(
        j.contains("z^2 - 13/10*z + 2/5") && j.contains("det(z I - A)"),
        "{j}"
    );
    assert!(!j.contains("*s") && !j.contains("(s"), "{j}");
    let tex = out(&["tf", &d, "--steps", "--format", "latex"]);
    for want in [
        r"\chi_A(z) = \det(zI - A)",
        r"G(z) = \begin{bmatrix}",
        r"C A^j B\, z^{-j-1}",
        r"N(z_0)",
    ] {
        assert!(tex.contains(want), "{want}\n{tex}");
    }
    assert!(!tex.contains("(s)") && !tex.contains("sI"), "{tex}");
    // continuous time: the same derivation in s
    let tex = out(&["tf", &c, "--steps", "--format", "latex"]);
    assert!(
        tex.contains(r"\chi_A(s) = \det(sI - A)") && tex.contains(r"G(s) = \begin{bmatrix}"),
        "{tex}"
    );
    let text = out(&["tf", &c, "--steps"]);
    assert!(
        text.contains("chi_A(s) = det(s I - A) = s^2 - 13/10*s + 2/5"),
        "{text}"
    );
}

#[test]
fn jordan_and_zeros_steps_in_z() {
    let (d, _) = files();
    let text = out(&["jordan", &d, "--steps"]);
    assert!(text.contains("chi_A(z) = det(z I - A)"), "{text}");
    let text = out(&["zeros", &d, "--steps"]);
    assert!(text.contains("P(z) = P_0 - z E"), "{text}");
    assert!(!text.contains("P(s)") && !text.contains("s_0"), "{text}");
    let tex = out(&["zeros", &d, "--steps", "--format", "latex"]);
    assert!(
        tex.contains("P(z)") && !tex.contains("P(s)") && !tex.contains("s_0"),
        "{tex}"
    );
    // words keep their s: the plural of "chain(s)" and subscripts such as x_s
    let tex = out(&["zeros", &d, "--steps", "--format", "latex"]);
    assert!(tex.contains("x_s"), "{tex}");
}
