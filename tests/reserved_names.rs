//! Reserved names (issue 22 item 5): `i`, `sqrt` and `pi` mean something to the expression
//! reader, so a symbol, parameter or polynomial variable of that name would silently change
//! what a text means (`det` of `i^2 + 1` as a symbol instead of 0 with the unit;
//! `poly factor "x^2 - sqrt(2)"` reading `sqrt` as a variable). A generator places each
//! reserved name in every place a name can stand (the `symbols` key in JSON and TOML, a null
//! parameter, `--symbolic`, random polynomials for `poly factor`, `gcd`, `roots`); each is
//! refused with one line naming the file and key (or the polynomial and column), exit 2,
//! while the same texts with ordinary names (`e`, `I`, `x1`) are still read.

use crate::common::Rng;
use crate::common::cli::{run, temp_file};
use exactlti::field::expr::RESERVED;
use exactlti::mpoly::parse_mpoly;
use exactlti::ratfunc::RatFuncField;

/// A file using `name` as a symbol in four ways; the expected key of the refusal.
fn files(name: &str) -> Vec<(String, &'static str, &'static str)> {
    let e = if name == "sqrt" || name == "pi" {
        "m"
    } else {
        name
    };
    vec![
        (
            format!(r#"{{"A": [["{e}", 1], [-1, "{e}"]], "symbols": ["{name}"]}}"#),
            "json",
            "key symbols: ",
        ),
        (
            format!("symbols = [\"m\", \"{name}\"]\nA = [[\"m\"]]\n"),
            "toml",
            "key symbols: ",
        ),
        (
            format!(r#"{{"A": [["m", 1], [-1, 0]], "parameters": {{"{name}": null, "m": null}}}}"#),
            "json",
            "key parameters.",
        ),
        (
            format!(r#"{{"A": [["m", 1], [-1, 0]], "parameters": {{"{name}": 2}}}}"#),
            "json",
            "key parameters.",
        ),
    ]
}

#[test]
fn reserved_names_are_refused_in_system_files() {
    for name in RESERVED {
        for (k, (text, ext, key)) in files(name).into_iter().enumerate() {
            let f = temp_file("reserved", &format!("r_{name}_{k}.{ext}"), &text);
            let p = f.to_str().unwrap();
            for args in [
                vec!["linalg", "det", p],
                vec!["jordan", p],
                vec!["linalg", "det", p, "--symbolic"],
            ] {
                let (code, out, err) = run(&args);
                assert_eq!(code, 2, "{args:?} on {text}: {out}{err}");
                let line = err.trim_end();
                assert!(!line.contains('\n'), "{line}");
                assert!(line.contains(p) && line.contains(key), "{text}: {line}");
                assert!(line.contains(&format!("'{name}' is reserved")), "{line}");
            }
        }
    }
    // ordinary names that look like constants elsewhere are still symbols
    let f = temp_file(
        "reserved",
        "ok.json",
        r#"{"A": [["e", 1], [-1, "I"]], "symbols": ["e", "I"]}"#,
    );
    let (code, out, err) = run(&["linalg", "det", f.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    assert!(
        out.contains("det: I*e + 1") || out.contains("det: e*I + 1"),
        "{out}"
    );
}

/// A random polynomial text in the variables `vars` (2 to 4 terms).
fn random_poly(vars: &[&str], rng: &mut Rng) -> String {
    let terms = rng.int(2, 4);
    let mut out = String::new();
    for t in 0..terms {
        let c = rng.int(1, 9);
        out.push_str(if t == 0 {
            ""
        } else if rng.int(0, 1) == 0 {
            " + "
        } else {
            " - "
        });
        out.push_str(&c.to_string());
        for v in vars {
            match rng.int(0, 2) {
                0 => {}
                1 => out.push_str(&format!("*{v}")),
                _ => out.push_str(&format!("*{v}^{}", rng.int(2, 3))),
            }
        }
    }
    out
}

#[test]
fn reserved_names_are_refused_as_polynomial_variables() {
    let mut rng = Rng(22_05);
    for case in 0..36 {
        let name = RESERVED[case % 3];
        // the name as a variable, or sqrt(2) / pi as a coefficient
        let spelled = match (name, case % 2) {
            ("sqrt", 0) => "sqrt(2)".to_string(),
            (n, _) => n.to_string(),
        };
        let p = random_poly(&["x", &spelled], &mut rng);
        let p = if p.contains(&spelled) {
            p
        } else {
            format!("{p} + {spelled}*x")
        };
        let col = p.find(name).unwrap() + 1;
        for args in [
            vec!["poly", "factor", &p],
            vec!["poly", "gcd", &p, "x + 1"],
            vec!["poly", "gcd", "x^2 - 1", &p],
        ] {
            let (code, out, err) = run(&args);
            assert_eq!(code, 2, "{args:?}: {out}");
            let line = err.trim_end();
            assert!(!line.contains('\n'), "{line}");
            assert!(line.contains(&format!("polynomial \"{p}\"")), "{line}");
            assert!(
                line.contains(&format!("column {col}: '{name}' is")),
                "{line}"
            );
        }
        assert!(parse_mpoly(&p).is_err(), "{p}");
        // the same polynomial with an ordinary name is read
        let ok = p.replace("sqrt(2)", "y").replace(name, "y");
        let (code, _, err) = run(&["poly", "factor", &ok]);
        assert_eq!(code, 0, "{ok}: {err}");
    }
    // univariate: `i^2 + 1` is not a polynomial in a variable i
    for args in [["poly", "factor", "i^2 + 1"], ["poly", "roots", "i^2 + 1"]] {
        let (code, _, err) = run(&args);
        assert_eq!(code, 2);
        assert!(err.contains("'i' is the imaginary unit"), "{err}");
    }
    // the reproducer
    let (code, out, err) = run(&["poly", "factor", "x^2 - sqrt(2)"]);
    assert_eq!(code, 2, "{out}");
    assert!(
        err.contains("column 7: 'sqrt' is the square root, not a variable"),
        "{err}"
    );
    // the library refuses them as symbols too
    for name in RESERVED {
        let e = RatFuncField::new(&["m", name]).unwrap_err();
        assert!(e.to_string().contains("is reserved"), "{e}");
    }
    assert!(RatFuncField::new(&["e", "I"]).is_ok());
}
