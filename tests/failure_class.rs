//! The class of a command's failure (issue 23): an api `Failure` carries the
//! [`ErrorClass`] of its cause, so the command line's exit status and Python's exception type
//! follow the class (an unsupported case or a size bound is not reported as bad input).

use crate::common::cli::run;
use exactlti::api::{Command, Failure, execute};
use exactlti::error::{Error, ErrorClass};
use std::path::Path;

const CLASSES: [ErrorClass; 4] = [
    ErrorClass::Input,
    ErrorClass::Unsupported,
    ErrorClass::Limit,
    ErrorClass::Verification,
];

fn write(name: &str, text: &str) -> std::path::PathBuf {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("exactlti-failure-class");
    std::fs::create_dir_all(&dir).expect("temp dir");
    let p = dir.join(name);
    std::fs::write(&p, text).expect("write");
    p
}

/// A diagonal n x n system with n inputs and n outputs.
fn square_system(n: usize) -> String {
    let m = |d: i64| {
        let rows: Vec<String> = (0..n)
            .map(|i| {
                let r: Vec<String> = (0..n)
                    .map(|j| if i == j { d.to_string() } else { "0".into() })
                    .collect();
                format!("[{}]", r.join(", "))
            })
            .collect();
        format!("[{}]", rows.join(", "))
    };
    format!(
        r#"{{"A": {}, "B": {}, "C": {}, "D": {}}}"#,
        m(-1),
        m(1),
        m(1),
        m(0)
    )
}

fn failure(args: &[&str]) -> Failure {
    let cmd = Command::parse_args(args).expect("valid arguments");
    match execute(&cmd) {
        Err(f) => f,
        Ok(_) => panic!("{args:?} should fail"),
    }
}

#[test]
fn a_failure_keeps_the_class_of_its_error() {
    // every class, several messages: the class, the exit status of the class, the message
    let errors = |m: &str| {
        vec![
            Error::Invalid(m.into()),
            Error::Singular,
            Error::DivisionByZero,
            Error::Unsupported(m.into()),
            Error::Limit(m.into()),
            Error::Verification(m.into()),
        ]
    };
    for m in ["x", "a longer message: with a colon", ""] {
        for e in errors(m) {
            let (class, code, text) = (e.class(), e.exit_code(), e.to_string());
            let f = Failure::from(e.clone());
            assert_eq!((f.class, f.code, f.message.clone()), (class, code, text));
            let g = f.in_file(Path::new("sys.json"));
            assert_eq!((g.class, g.code), (class, code));
            assert!(g.message.starts_with("sys.json: "), "{}", g.message);
            // the library error stays reachable as the source, also with the file's name
            let src = std::error::Error::source(&g).expect("a failure from an Error has it");
            assert_eq!(src.downcast_ref::<Error>(), Some(&e));
        }
    }
    for class in CLASSES {
        let f = Failure::new(class, "m".into());
        assert!(
            std::error::Error::source(&f).is_none(),
            "a refusal has no cause"
        );
        assert_eq!((f.class, f.code), (class, class.exit_code()));
        let want = if class == ErrorClass::Verification {
            1
        } else {
            2
        };
        assert_eq!(f.code, want);
    }
    assert_eq!(Failure::input("m".into()).class, ErrorClass::Input);
    assert_eq!(
        Failure::unsupported("m".into()).class,
        ErrorClass::Unsupported
    );
    assert_eq!(Failure::limit("m".into()).class, ErrorClass::Limit);
    assert_eq!(Failure::verification("m".into()).code, 1);
}

#[test]
fn unsupported_and_limit_commands_carry_their_class() {
    // --steps of a Jordan form over Q(sqrt 2): not handled (Unsupported), exit 2
    let s2 = write(
        "s2.json",
        r#"{"A": [["sqrt(2)", 1], [0, 1]], "B": [[0], [1]], "C": [[1, 0]], "D": [[0]]}"#,
    );
    let s2 = s2.to_str().unwrap();
    // a real Jordan form over QQ(k) of a cubic factor (x^3 - k): refused, Unsupported
    let k = write(
        "k.json",
        r#"{"symbols": ["k"], "A": [[0, 0, "k"], [1, 0, 0], [0, 1, 0]], "B": [[0], [0], [1]], "C": [[1, 0, 0]], "D": [[0]]}"#,
    );
    let f = failure(&["jordan", k.to_str().unwrap(), "--real"]);
    assert_eq!(
        (f.class, f.code),
        (ErrorClass::Unsupported, 2),
        "{}",
        f.message
    );
    assert!(f.message.contains("degree 3"), "{}", f.message);
    let (code, _, err) = run(&["jordan", s2, "--steps"]);
    assert_eq!(code, 2);
    assert!(err.contains("needs rational entries"), "{err}");
    // a frequency response past the bound on its values: a Limit, exit 2
    for (n, points, over) in [(4, "100000", true), (4, "1000", false), (1, "2000", false)] {
        let p = write(&format!("d{n}.json"), &square_system(n));
        let p = p.to_str().unwrap();
        let args = ["freqresp", p, "--points", points];
        let cmd = Command::parse_args(&args).unwrap();
        match execute(&cmd) {
            Err(f) => {
                assert!(over, "{args:?}: {}", f.message);
                assert_eq!((f.class, f.code), (ErrorClass::Limit, 2), "{}", f.message);
                assert!(f.message.contains("at most 1000000"), "{}", f.message);
            }
            Ok(_) => assert!(!over, "{args:?} should exceed the bound"),
        }
    }
    // bad input stays Input
    let f = failure(&["jordan", "/nonexistent/sys.json"]);
    assert_eq!((f.class, f.code), (ErrorClass::Input, 2), "{}", f.message);
}
