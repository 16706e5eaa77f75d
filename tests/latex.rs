//! `--format latex` (issue 17, item 5): a fragment that `\input`s into an amsmath document,
//! `--standalone` a complete one, every result typeset as math. When `pdflatex` is installed
//! the seeds' examples are compiled (all fragments `\input` into one amsmath document, and
//! standalone documents); without it the compile step is skipped with a message.
//! `scripts/latex_check.sh` renders the same examples to PNG for a look.
use std::process::Command;

/// (arguments, file) pairs: the seeds' examples through the commands with exact results.
const CASES: &[(&[&str], &str)] = &[
    (&["jordan"], "data/sliding-masses.json"),
    (&["jordan", "--real"], "data/sliding-masses.json"),
    (&["minreal"], "data/sliding-masses.json"),
    (&["modes"], "data/sliding-masses.json"),
    (&["tf"], "data/sliding-masses.json"),
    (&["scb"], "data/yaw-plane-single-wheel.json"),
    (&["zeros"], "data/yaw-plane-single-wheel.json"),
    (&["mnf"], "data/yaw-plane-single-wheel.json"),
    (&["linalg", "charpoly"], "tests/data/gaussian.json"),
    (&["linalg", "minpoly"], "tests/data/sqrt2.toml"),
    (&["analyze"], "tests/data/everyday/quarter_car.json"),
    (&["linalg", "charpoly"], "tests/data/yaw_contract.json"),
];

fn latex(args: &[&str], file: &str, standalone: bool) -> String {
    let mut a: Vec<&str> = args.to_vec();
    a.extend([file, "--format", "latex"]);
    if standalone {
        a.push("--standalone");
    }
    let out = Command::new(env!("CARGO_BIN_EXE_exactlti"))
        .args(&a)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("runs");
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{a:?}: {err}");
    String::from_utf8(out.stdout).unwrap()
}

/// The typeset part: everything outside `%` comments.
fn body(t: &str) -> String {
    t.lines()
        .filter(|l| !l.starts_with('%'))
        .collect::<Vec<_>>()
        .join("\n")
}

#[test]
fn every_result_is_typeset_as_math() {
    // Jordan entries of the sliding masses: sqrt(2), the field generators b7, r7, i
    let t = body(&latex(
        &["jordan", "--real"],
        "data/sliding-masses.json",
        false,
    ));
    assert!(t.contains("\\sqrt{2}") && t.contains("b_{7}"), "{t}");
    // the field generators in their closed form, as the eigenvalues are shown
    assert!(t.contains("b_{7} = \\sqrt{2 + \\sqrt{3}}"), "{t}");
    assert!(!t.contains("sqrt("), "plain-text entries left:\n{t}");
    assert!(
        t.contains("\\left[\\begin{array}{*{20}{c}}"),
        "20 columns: array"
    );
    let t = body(&latex(&["jordan"], "data/sliding-masses.json", false));
    // entries of T over Q(sqrt -3) in the one display -sqrt(3)*i/3
    assert!(t.contains("-\\frac{\\sqrt{3}\\,\\mathrm{i}}{3}"), "{t}");
    // transfer function, eigenvalues, zeros, modes: in the body, as math
    let t = body(&latex(&["tf"], "data/sliding-masses.json", false));
    assert!(t.contains("\\frac{"), "transfer function typeset:\n{t}");
    let t = body(&latex(&["modes"], "data/sliding-masses.json", false));
    assert!(t.contains("frequency hz") && t.contains("$"), "{t}");
    let t = body(&latex(
        &["zeros"],
        "data/yaw-plane-single-wheel.json",
        false,
    ));
    assert!(t.contains("invariant zeros"), "{t}");
    for (args, file) in CASES {
        let t = body(&latex(args, file, false));
        // no exact display syntax outside math: '*' and '^' only appear escaped or in math
        for line in t.lines() {
            let outside: String = line.split('$').step_by(2).collect();
            assert!(
                !outside.contains("*x") && !outside.contains("sqrt("),
                "{args:?} {file}: plain-text math in: {line}"
            );
        }
        assert!(!t.contains("\\documentclass"), "a fragment has no preamble");
    }
}

fn pdflatex_available() -> bool {
    Command::new("pdflatex")
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success())
}

fn compile(dir: &std::path::Path, name: &str) -> Result<(), String> {
    let out = Command::new("pdflatex")
        .args(["-interaction=nonstopmode", "-halt-on-error", name])
        .current_dir(dir)
        .output()
        .map_err(|e| e.to_string())?;
    if out.status.success() {
        Ok(())
    } else {
        let log = String::from_utf8_lossy(&out.stdout);
        let err: Vec<&str> = log
            .lines()
            .skip_while(|l| !l.starts_with('!'))
            .take(12)
            .collect();
        Err(err.join("\n"))
    }
}

#[test]
fn the_seeds_examples_compile_with_pdflatex() {
    if !pdflatex_available() {
        eprintln!(
            "SKIPPED the_seeds_examples_compile_with_pdflatex: pdflatex not installed \
             (apt-get install texlive-latex-base texlive-latex-recommended)"
        );
        return;
    }
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("exactlti-latex");
    std::fs::create_dir_all(&dir).unwrap();
    // every fragment \input into one plain amsmath document
    let mut doc =
        String::from("\\documentclass{article}\n\\usepackage{amsmath}\n\\begin{document}\n");
    for (i, (args, file)) in CASES.iter().enumerate() {
        std::fs::write(dir.join(format!("frag{i}.tex")), latex(args, file, false)).unwrap();
        doc.push_str(&format!("\\input{{frag{i}.tex}}\n"));
    }
    doc.push_str("\\end{document}\n");
    std::fs::write(dir.join("fragments.tex"), doc).unwrap();
    compile(&dir, "fragments.tex").unwrap_or_else(|e| panic!("fragments do not compile:\n{e}"));
    // standalone documents, a name with LaTeX specials and a newline included
    let evil = dir.join("evil.json");
    std::fs::write(
        &evil,
        r#"{"name": "50% {x} $y$ #1 a_b ~ ^\n\\end{document} \\input{z}", "A": [[0, 1], [-2, -3]], "B": [[0], [1]], "C": [[1, 0]]}"#,
    )
    .unwrap();
    let evil = evil.to_str().unwrap().to_string();
    for (k, (args, file)) in [
        (&["jordan", "--real"][..], "data/sliding-masses.json"),
        (&["analyze"][..], evil.as_str()),
    ]
    .iter()
    .enumerate()
    {
        std::fs::write(
            dir.join(format!("standalone{k}.tex")),
            latex(args, file, true),
        )
        .unwrap();
        compile(&dir, &format!("standalone{k}.tex"))
            .unwrap_or_else(|e| panic!("{args:?} {file} --standalone does not compile:\n{e}"));
    }
    let _ = std::fs::remove_dir_all(&dir);
}
