//! The fast reader of plain rational matrix files (issue 29: `linalg`'s command-line floor)
//! and the reports built for one output: examples (edge shapes 0x0 and 1x1, huge
//! numerators, decimals, negative exponents, JSON numbers), what it declines, a property
//! test against the general reader on generated matrices and on generated near misses, and
//! invariants (whitespace, row order, printing and reading back, one output's report renders
//! as the full report).

use exactlti::field::{Q, Rational};
use exactlti::io::plain_matrix::{plain_entry, plain_square_matrix};
use exactlti::io::{FromScalars, Ground, parse_system_json};
use exactlti::matrix::Matrix;
use exactlti::report::display::fmt_rational;
use exactlti::report::{Report, Target};
use exactlti::rng::SplitMix64;
use num_bigint::BigInt;

fn r(p: i64, q: i64) -> Rational {
    Rational::new(p.into(), q.into())
}

/// The matrix `A` as the general reader (proxy tree, expression parser) reads `text`;
/// `None` when it refuses the file.
fn general(text: &str) -> Option<Matrix<Q>> {
    let f = parse_system_json(text, "t.json").ok()?;
    assert_eq!(f.ground, Ground::Rational, "{text}");
    Some(Q.matrix_from_entries(f.a.as_ref()?))
}

fn fast(text: &str) -> Option<Matrix<Q>> {
    plain_square_matrix(text, "A")
}

#[test]
fn examples_edge_shapes_and_literals() {
    let m = fast(r#"{"A": []}"#).expect("0x0");
    assert_eq!((m.nrows(), m.ncols()), (0, 0));
    assert_eq!(fast(r#"{"A": [[5]]}"#).unwrap().get(0, 0), &r(5, 1));
    assert_eq!(fast(r#"{"A": [["-6/4"]]}"#).unwrap().get(0, 0), &r(-3, 2));
    // decimals are the rationals they spell, as strings and as JSON numbers
    let m = fast(r#"{"A": [[0.08, "0.08"], [-1.5e-3, "1.5E-3"]]}"#).unwrap();
    assert_eq!(m.get(0, 0), &r(2, 25));
    assert_eq!(m.get(0, 1), &r(2, 25));
    assert_eq!(m.get(1, 0), &r(-3, 2000));
    assert_eq!(m.get(1, 1), &r(3, 2000));
    // negative exponents, a fraction of decimals, zero with a sign
    let text = r#"{"A": [["2.5e-10/5e-11", "-0"], [1e3, "-7/0.5"]]}"#;
    let m = fast(text).unwrap();
    assert_eq!(general(text).as_ref(), Some(&m));
    assert_eq!(m.get(0, 0), &r(5, 1));
    assert_eq!(m.get(0, 1), &r(0, 1));
    assert_eq!(m.get(1, 0), &r(1000, 1));
    assert_eq!(m.get(1, 1), &r(-14, 1));
    // huge numerators and denominators (past a machine word): exact
    let big = "123456789012345678901234567890123456789";
    let m = fast(&format!(r#"{{"A": [["-{big}/7"]]}}"#)).unwrap();
    let want = Rational::new(-big.parse::<BigInt>().unwrap(), 7.into());
    assert_eq!(m.get(0, 0), &want);
    let m = fast(&format!(r#"{{"A": [[{big}]]}}"#)).unwrap();
    assert_eq!(m.get(0, 0), &Rational::from_integer(big.parse().unwrap()));
    // JSON whitespace anywhere between tokens
    let m = fast("\n{ \"A\" :\t[ [ 1 , \"2/3\" ] ,\r\n [ 3,4 ] ] }\n").unwrap();
    assert_eq!(m.get(0, 1), &r(2, 3));
    assert_eq!(m.get(1, 1), &r(4, 1));
}

#[test]
fn declines_what_it_does_not_read() {
    for text in [
        r#"{"A": [[1, 2]]}"#,          // not square
        r#"{"A": [[]]}"#,              // 1x0
        r#"{"A": [[1, 2], [3]]}"#,     // ragged
        r#"{"A": [[1]], "B": [[1]]}"#, // another key
        r#"{"B": [[1]]}"#,             // not A
        r#"{"A": [[1]], "A": [[2]]}"#, // a key twice
        r#"{"A": [["x"]]}"#,           // a name
        r#"{"A": [["1/0"]]}"#,         // a zero denominator
        r#"{"A": [["1 /2"]]}"#,        // a space
        r#"{"A": [["+1"]]}"#,          // a plus sign
        r#"{"A": [["sqrt(2)"]]}"#,     // an expression
        r#"{"A": [["1\u002f2"]]}"#,    // an escape
        r#"{"A": [[01]]}"#,            // not JSON
        r#"{"A": [[1.]]}"#,            // not JSON
        r#"{"A": [[1]]} x"#,           // trailing text
        r#"{"A": [[1],]}"#,            // trailing comma
        r#"{"A": "[1 2; 3 4]"}"#,      // MATLAB-style text
        r#"{"A": [[true]]}"#,          // not a number
        r#"{"A": [["1e1001"]]}"#,      // past the exponent bound
        r#"{"A": [[1e99999]]}"#,       // past every bound
        r#"["A"]"#,
        "",
    ] {
        assert!(fast(text).is_none(), "{text}");
    }
    let long = format!(r#"{{"A": [["{}"]]}}"#, "9".repeat(1001));
    assert!(fast(&long).is_none());
}

/// A random entry of the shapes the reader takes (integers, fractions with small and huge
/// parts, decimals with exponents of both signs, as strings and as JSON numbers).
fn entry(g: &mut SplitMix64) -> String {
    let digits = |g: &mut SplitMix64, n: u64| -> String {
        let len = 1 + g.next_u64() % n;
        (0..len)
            .map(|i| {
                let d = g.next_u64() % 10;
                // no leading zero (JSON numbers have none)
                let d = if i == 0 && len > 1 { 1 + d % 9 } else { d };
                char::from(b'0' + d as u8)
            })
            .collect()
    };
    // a denominator: never zero (a zero denominator is a near miss, generated below)
    let den = |g: &mut SplitMix64, n: u64| -> String {
        let d = digits(g, n);
        if d.bytes().all(|b| b == b'0') {
            "7".into()
        } else {
            d
        }
    };
    let sign = if g.next_u64().is_multiple_of(2) {
        "-"
    } else {
        ""
    };
    match g.next_u64() % 7 {
        0 => format!("{sign}{}", digits(g, 8)),
        1 => format!("\"{sign}{}/{}\"", digits(g, 7), den(g, 7)),
        2 => format!("\"{sign}{}/{}\"", digits(g, 40), den(g, 30)),
        3 => format!("{sign}{}.{}", digits(g, 5), digits(g, 12)),
        4 => format!(
            "{sign}{}.{}e{}{}",
            digits(g, 3),
            digits(g, 4),
            if g.next_u64().is_multiple_of(2) {
                "-"
            } else {
                "+"
            },
            g.next_u64() % 40
        ),
        5 => format!("\"{sign}{}E-{}\"", digits(g, 20), g.next_u64() % 30),
        _ => format!("\"{sign}{}\"", digits(g, 25)),
    }
}

fn matrix_text(n: usize, cell: &mut dyn FnMut(usize, usize) -> String) -> String {
    let rows: Vec<String> = (0..n)
        .map(|i| {
            let xs: Vec<String> = (0..n).map(|j| cell(i, j)).collect();
            format!("[{}]", xs.join(", "))
        })
        .collect();
    format!("{{\"A\": [{}]}}", rows.join(", "))
}

/// Property: on generated plain matrices the fast reader gives the general reader's matrix.
#[test]
fn agrees_with_the_general_reader_on_generated_matrices() {
    let mut g = SplitMix64(2929);
    for case in 0..200 {
        let n = (g.next_u64() % 7) as usize;
        let text = matrix_text(n, &mut |_, _| entry(&mut g));
        let want = general(&text).unwrap_or_else(|| panic!("case {case}: {text}"));
        assert_eq!(fast(&text), Some(want), "case {case}: {text}");
    }
}

/// Property over the class of near misses: a generated plain file with one byte changed,
/// inserted or removed. Whatever the fast reader accepts, the general reader reads to the
/// same matrix; whatever the general reader refuses, the fast reader declines (so every
/// error message stays the general reader's).
#[test]
fn near_misses_are_declined_or_read_the_same() {
    let mut g = SplitMix64(29029);
    let noise = b" x/.-+e0\"[],{}:\\1";
    let (mut accepted, mut declined) = (0, 0);
    for case in 0..600 {
        let n = 1 + (g.next_u64() % 3) as usize;
        let text = matrix_text(n, &mut |_, _| entry(&mut g));
        let mut b = text.into_bytes();
        let at = (g.next_u64() % b.len() as u64) as usize;
        let c = noise[(g.next_u64() % noise.len() as u64) as usize];
        match g.next_u64() % 3 {
            0 => b[at] = c,
            1 => b.insert(at, c),
            _ => {
                b.remove(at);
            }
        }
        let text = String::from_utf8(b).expect("ASCII");
        match fast(&text) {
            Some(m) => {
                accepted += 1;
                assert_eq!(general(&text), Some(m), "case {case}: {text}");
            }
            None => declined += 1,
        }
    }
    // the generator reaches both sides
    assert!(accepted > 50 && declined > 50, "{accepted} {declined}");
}

/// Invariants: printing the matrix and reading it back gives it again; reversing the rows
/// of the file reverses the rows of the matrix; every entry alone reads as in the matrix.
#[test]
fn invariants_round_trip_row_order_entries() {
    let mut g = SplitMix64(4242);
    for _ in 0..60 {
        let n = 1 + (g.next_u64() % 6) as usize;
        let cells: Vec<Vec<String>> = (0..n)
            .map(|_| (0..n).map(|_| entry(&mut g)).collect())
            .collect();
        let text = matrix_text(n, &mut |i, j| cells[i][j].clone());
        let m = fast(&text).expect("plain");
        let back = matrix_text(n, &mut |i, j| format!("\"{}\"", fmt_rational(m.get(i, j))));
        assert_eq!(fast(&back).as_ref(), Some(&m));
        let rev = matrix_text(n, &mut |i, j| cells[n - 1 - i][j].clone());
        let mr = fast(&rev).expect("plain");
        for (i, row) in cells.iter().enumerate() {
            for (j, cell) in row.iter().enumerate() {
                assert_eq!(mr.get(i, j), m.get(n - 1 - i, j));
                let t = cell.trim_matches('"');
                assert_eq!(plain_entry(t).as_ref(), Some(m.get(i, j)), "{t}");
            }
        }
    }
}

/// A report built for one output renders, in that output, exactly as the report with
/// every rendering: text (compact and `--full`), JSON and LaTeX, on matrices with short
/// and with long entries.
#[test]
fn report_for_one_output_renders_as_the_full_report() {
    use exactlti::api::Format;
    use exactlti::cli::render_full;
    let mut g = SplitMix64(77);
    for case in 0..12 {
        let n = 1 + (g.next_u64() % 5) as usize;
        let long = case % 2 == 1;
        let m = Matrix::from_fn(Q, n, n, |_, _| {
            let p = g.next_u64() % 2000;
            let q = if long {
                1 + g.next_u64()
            } else {
                1 + g.next_u64() % 9
            };
            Rational::new(BigInt::from(p) - 1000, q.into())
        });
        let every = Report::titled("t").matrix("matrix", &m);
        for (format, full, target) in [
            (Format::Text, false, Target::Text { full: false }),
            (Format::Text, true, Target::Text { full: true }),
            (Format::Json, false, Target::Json),
            (Format::Latex, false, Target::Latex),
        ] {
            let one = Report::titled("t").matrix_for("matrix", &m, target);
            assert_eq!(
                render_full(&one, format, false, full),
                render_full(&every, format, false, full),
                "case {case} {format:?} full {full}"
            );
        }
    }
}

/// The command line: a plain JSON file (the fast path) and the same matrix as TOML (the
/// general reader) give the same output, for every operation and format; a plain file
/// with a zero denominator or a non-square matrix still gets the general reader's answer.
#[test]
fn cli_fast_path_prints_what_the_general_path_prints() {
    use crate::common::cli::run;
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("exactlti-plain");
    std::fs::create_dir_all(&dir).unwrap();
    let mut g = SplitMix64(5);
    let n = 5;
    let cells: Vec<Vec<String>> = (0..n)
        .map(|i| {
            (0..n)
                .map(|j| {
                    if i == n - 1 && j == 0 {
                        return "\"0.25e-2\"".into();
                    }
                    let p = (g.next_u64() % 2001) as i64 - 1000;
                    format!("\"{p}/{}\"", 1 + g.next_u64() % 97)
                })
                .collect()
        })
        .collect();
    let json = dir.join("a.json");
    std::fs::write(&json, matrix_text(n, &mut |i, j| cells[i][j].clone())).unwrap();
    let toml = dir.join("a.toml");
    let rows: Vec<String> = cells
        .iter()
        .map(|r| format!("[{}]", r.join(", ")))
        .collect();
    std::fs::write(&toml, format!("A = [{}]\n", rows.join(", "))).unwrap();
    let (j, t) = (json.to_str().unwrap(), toml.to_str().unwrap());
    for op in [
        "rank",
        "rref",
        "nullspace",
        "det",
        "inverse",
        "charpoly",
        "minpoly",
    ] {
        for format in ["text", "json", "latex"] {
            let a = run(&["linalg", op, j, "--format", format]);
            let b = run(&["linalg", op, t, "--format", format]);
            assert_eq!(a.0, 0, "{op} {format}: {}", a.2);
            assert_eq!((a.0, a.1.replace(j, t), a.2), b, "{op} {format}");
        }
    }
    let (code, _, err) = run(&["linalg", "rref", j, "--full"]);
    assert_eq!(code, 0, "{err}");
    std::fs::write(&json, r#"{"A": [["1/0", 1], [2, 3]]}"#).unwrap();
    let (code, out, err) = run(&["linalg", "rank", j]);
    assert_eq!((code, out.as_str()), (2, ""));
    assert!(
        err.contains("key A, row 1, column 1: division by zero"),
        "{err}"
    );
    std::fs::write(&json, r#"{"A": [[1, 2, 3]]}"#).unwrap();
    let (code, out, _) = run(&["linalg", "rank", j]);
    assert_eq!(code, 0);
    assert!(out.contains("linalg reads A as a 1x3 matrix"), "{out}");
    let _ = std::fs::remove_dir_all(&dir);
}
