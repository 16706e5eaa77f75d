//! Issue 22, item 13 and the rest of its open parts: every command reads every matrix form,
//! ERA gives order 0 for a zero transfer function, and every system a command writes reads
//! back with the same transfer matrix.
//!
//! Generators (fixed seeds): random standard and descriptor systems written as nested lists
//! of numbers, nested lists of strings, MATLAB strings (blanks, commas, line breaks) and TOML;
//! zero-transfer systems (uncontrollable or unobservable by construction, then a random
//! similarity) and low-order systems hidden in larger ones; systems of order 0, with 0 inputs
//! or 0 outputs, standard and descriptor.

use crate::common::cli::{run, temp_file};
use crate::common::{Rng, unimodular};
use exactlti::field::{Field, Q, Rational};
use exactlti::float::{Tol, Truth, era_system, to_dmatrix};
use exactlti::matrix::Matrix;
use serde_json::Value;

type Rows = Vec<Vec<i64>>;

fn rand_rows(rng: &mut Rng, r: usize, c: usize) -> Rows {
    (0..r)
        .map(|_| (0..c).map(|_| rng.int(-4, 4)).collect())
        .collect()
}

/// The matrix forms the reader accepts, as JSON values or TOML values (text).
#[derive(Clone, Copy, Debug)]
enum Form {
    Numbers,
    Strings,
    MatlabBlanks,
    MatlabCommas,
    MatlabLines,
}

const FORMS: [Form; 5] = [
    Form::Numbers,
    Form::Strings,
    Form::MatlabBlanks,
    Form::MatlabCommas,
    Form::MatlabLines,
];

fn json_form(m: &Rows, f: Form) -> String {
    let row = |r: &Vec<i64>, sep: &str, quote: bool| {
        r.iter()
            .map(|x| {
                if quote {
                    format!("\"{x}\"")
                } else {
                    x.to_string()
                }
            })
            .collect::<Vec<_>>()
            .join(sep)
    };
    match f {
        Form::Numbers | Form::Strings => {
            let q = matches!(f, Form::Strings);
            let rows: Vec<String> = m.iter().map(|r| format!("[{}]", row(r, ", ", q))).collect();
            format!("[{}]", rows.join(", "))
        }
        Form::MatlabBlanks | Form::MatlabCommas | Form::MatlabLines => {
            let (sep, rsep) = match f {
                Form::MatlabBlanks => (" ", "; "),
                Form::MatlabCommas => (", ", ";"),
                _ => (" ", "\\n"),
            };
            let rows: Vec<String> = m.iter().map(|r| row(r, sep, false)).collect();
            format!("\"[{}]\"", rows.join(rsep))
        }
    }
}

/// A system file (`toml` or JSON) with the matrices `keys` in form `f`.
fn file_text(keys: &[(&str, &Rows)], f: Form, toml: bool) -> String {
    let kv: Vec<String> = keys
        .iter()
        .map(|(k, m)| {
            let v = json_form(m, f);
            if toml {
                format!("{k} = {v}")
            } else {
                format!("\"{k}\": {v}")
            }
        })
        .collect();
    if toml {
        kv.join("\n") + "\n"
    } else {
        format!("{{{}}}", kv.join(", "))
    }
}

/// One command's answer: exit code and stdout (JSON).
fn answer(args: &[&str]) -> (i32, String) {
    let (code, out, err) = run(args);
    assert_ne!(code, -1, "{args:?}: killed: {err}");
    (code, if code == 0 { out } else { err_kind(&err) })
}

/// An error reduced to what does not name the file.
fn err_kind(err: &str) -> String {
    err.split_once(": ").map_or(err, |x| x.1).to_string()
}

#[test]
fn every_command_reads_every_matrix_form() {
    let mut rng = Rng(2213);
    let cmds: [&[&str]; 9] = [
        &["jordan"],
        &["pencil"],
        &["ctrb"],
        &["obsv"],
        &["tf"],
        &["minreal"],
        &["minreal", "--descriptor"],
        &["zeros"],
        &["standard"],
    ];
    for case in 0..6 {
        let n = 2 + case % 2;
        let (m, p) = (1 + case % 2, 1);
        let a = rand_rows(&mut rng, n, n);
        let b = rand_rows(&mut rng, n, m);
        let c = rand_rows(&mut rng, p, n);
        let d = rand_rows(&mut rng, p, m);
        // descriptor cases: E with a zero row (singular) or the identity plus noise
        let mut e = rand_rows(&mut rng, n, n);
        if case % 3 == 0 {
            e[n - 1] = vec![0; n];
        }
        let mut keys: Vec<(&str, &Rows)> = vec![("A", &a), ("B", &b), ("C", &c), ("D", &d)];
        if case >= 2 {
            keys.push(("E", &e));
        }
        for cmd in cmds {
            let mut want = None;
            for toml in [false, true] {
                for f in FORMS {
                    let ext = if toml { "toml" } else { "json" };
                    let text = file_text(&keys, f, toml);
                    let path = temp_file("rest22", &format!("forms_{case}_{f:?}.{ext}"), &text);
                    let path = path.to_str().unwrap();
                    let mut args = cmd.to_vec();
                    args.extend([path, "--format", "json"]);
                    let got = answer(&args);
                    assert_ne!(got.0, 2, "{cmd:?} {f:?} refused {text}: {}", got.1);
                    match &want {
                        None => want = Some(got),
                        Some(w) => assert_eq!(w, &got, "{cmd:?} {f:?} toml={toml}: {text}"),
                    }
                }
            }
        }
        // a rectangular pencil (A, E of one non-square shape): `pencil` reads every form
        let (r, cc) = (n, n + 1);
        let (pa, pe) = (rand_rows(&mut rng, r, cc), rand_rows(&mut rng, r, cc));
        let mut want = None;
        for toml in [false, true] {
            for f in FORMS {
                let ext = if toml { "toml" } else { "json" };
                let text = file_text(&[("A", &pa), ("E", &pe)], f, toml);
                let path = temp_file("rest22", &format!("pencil_{case}_{f:?}.{ext}"), &text);
                let got = answer(&["pencil", path.to_str().unwrap(), "--format", "json"]);
                assert_eq!(got.0, 0, "{f:?}: {text}: {}", got.1);
                match &want {
                    None => want = Some(got),
                    Some(w) => assert_eq!(w, &got, "pencil {f:?} toml={toml}: {text}"),
                }
            }
        }
    }
}

#[test]
fn transfer_matrix_key_reads_matlab_strings() {
    let lists = temp_file(
        "rest22",
        "g_lists.json",
        r#"{"G": [["1/(s+1)", "2"], ["0", "s/(s+2)"]]}"#,
    );
    let text = temp_file(
        "rest22",
        "g_text.json",
        r#"{"G": "[1/(s+1) 2; 0 s/(s+2)]"}"#,
    );
    for cmd in ["tf", "pencil", "ctrb", "jordan", "minreal"] {
        let x = answer(&[cmd, lists.to_str().unwrap(), "--format", "json"]);
        let y = answer(&[cmd, text.to_str().unwrap(), "--format", "json"]);
        assert_eq!(x.0, 0, "{cmd}: {}", x.1);
        assert_eq!(x, y, "{cmd}");
    }
}

fn q(x: i64) -> Rational {
    Rational::from_integer(x.into())
}

fn qm(rows: &Rows) -> Matrix<Q> {
    let r: Vec<Vec<Rational>> = rows
        .iter()
        .map(|r| r.iter().map(|&x| q(x)).collect())
        .collect();
    if r.is_empty() {
        return Matrix::zeros(Q, 0, 0);
    }
    Matrix::from_rows(Q, r).unwrap()
}

/// A system with transfer function 0: `hidden` states uncontrollable (B vanishes there and A
/// keeps the controllable part invariant) or unobservable (the dual), in random coordinates.
fn zero_transfer(rng: &mut Rng, n: usize, m: usize, p: usize) -> [Matrix<Q>; 3] {
    let k = rng.int(0, n as i64) as usize; // controllable part: states 0..k
    let mut a = rand_rows(rng, n, n);
    for row in a.iter_mut().skip(k) {
        row[..k].fill(0);
    }
    let mut b = rand_rows(rng, n, m);
    b.iter_mut().skip(k).for_each(|r| r.fill(0));
    let mut c = rand_rows(rng, p, n);
    c.iter_mut().for_each(|r| r[..k].fill(0));
    let t = unimodular(&Q, n, rng);
    let ti = t.inverse().unwrap();
    let (a, b, c) = (qm(&a), qm(&b), qm(&c));
    let a = &(&ti * &a) * &t;
    [a, &ti * &b, &c * &t]
}

#[test]
fn era_of_a_zero_transfer_function_has_order_0() {
    let mut rng = Rng(2222);
    for case in 0..40 {
        let n = 2 + case % 6;
        let (m, p) = (1 + case % 2, 1 + case % 3);
        let [a, b, c] = zero_transfer(&mut rng, n, m, p);
        // exact: every Markov parameter is 0
        let mut x = b.clone();
        for _ in 0..2 * n {
            assert!(
                (&c * &x).is_zero(),
                "case {case}: not a zero transfer function"
            );
            x = &a * &x;
        }
        let f = |m: &Matrix<Q>| to_dmatrix(m).unwrap();
        let d = nalgebra::DMatrix::zeros(p, m);
        let r = era_system(&f(&a), &f(&b), &f(&c), &d, None, &Tol::default()).unwrap();
        let real = &r.realization;
        assert_eq!(real.order, 0, "case {case}: {:?}", real.singular_values);
        assert_eq!(real.truth, Truth::True, "case {case}: {:?}", real.rank_gap);
        assert_eq!((real.a.shape(), real.b.shape()), ((0, 0), (0, m)));
    }
}

#[test]
fn era_of_a_low_order_system_hidden_in_a_larger_one() {
    let mut rng = Rng(2223);
    let mut found = 0;
    for case in 0..30 {
        // order-r part (diagonal, distinct stable poles, full B and C) plus a zero-transfer part
        let r = 1 + case % 3;
        let h = 1 + case % 4;
        let (m, p) = (1, 1 + case % 2);
        let [za, zb, zc] = zero_transfer(&mut rng, h, m, p);
        let n = r + h;
        let mut a = Matrix::zeros(Q, n, n);
        let mut b = Matrix::zeros(Q, n, m);
        let mut c = Matrix::zeros(Q, p, n);
        for i in 0..r {
            a.set(i, i, q(-(i as i64) - 1));
            b.set(i, 0, q(1 + rng.int(0, 3)));
            for o in 0..p {
                c.set(o, i, q(rng.int(1, 4) * if o == i % p { 1 } else { 0 } + 1));
            }
        }
        for i in 0..h {
            for j in 0..h {
                a.set(r + i, r + j, za.get(i, j).clone());
            }
            b.set(r + i, 0, zb.get(i, 0).clone());
            for o in 0..p {
                c.set(o, r + i, zc.get(o, i).clone());
            }
        }
        let t = unimodular(&Q, n, &mut rng);
        let ti = t.inverse().unwrap();
        let (a, b, c) = (&(&ti * &a) * &t, &ti * &b, &c * &t);
        let ss = exactlti::system::StateSpace::new(a, b, c, Matrix::zeros(Q, p, m)).unwrap();
        let exact = exactlti::realization::mcmillan_degree(&ss);
        let f = |m: &Matrix<Q>| to_dmatrix(m).unwrap();
        let d = nalgebra::DMatrix::zeros(p, m);
        let e = era_system(&f(&ss.a), &f(&ss.b), &f(&ss.c), &d, None, &Tol::default()).unwrap();
        assert!(exact >= 1 && exact <= r, "case {case}: degree {exact}");
        if e.realization.truth == Truth::True {
            assert_eq!(e.realization.order, exact, "case {case}");
            found += 1;
        }
    }
    assert!(found >= 20, "only {found} of 30 clear");
}

#[test]
fn era_on_the_command_line_reports_order_0_for_a_zero_transfer_function() {
    let mut rng = Rng(2224);
    let [a, b, c] = zero_transfer(&mut rng, 5, 1, 1);
    let rows = |m: &Matrix<Q>| -> Value {
        (0..m.nrows())
            .map(|i| {
                (0..m.ncols())
                    .map(|j| Value::from(m.get(i, j).to_string()))
                    .collect::<Vec<Value>>()
            })
            .collect()
    };
    let text = serde_json::json!({"A": rows(&a), "B": rows(&b), "C": rows(&c), "D": [[0]]});
    let p = temp_file("rest22", "era_zero.json", &text.to_string());
    let (code, out, err) = run(&[
        "minreal",
        p.to_str().unwrap(),
        "--method",
        "era",
        "--format",
        "json",
    ]);
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["order"], 0, "{out}");
    assert_eq!(v["mcmillan_degree"], 0, "{out}");
    assert_eq!(v["truth"], "true", "{out}");
}

/// The matrices `keys` of a command's JSON output as a system file (JSON or TOML).
fn system_of_output(out: &Value, keys: &[&str], toml: bool) -> String {
    let mut parts = Vec::new();
    for k in keys {
        let Some(m) = out.get(*k) else { continue };
        let s = serde_json::to_string(m).unwrap();
        parts.push(if toml {
            format!("{k} = {s}")
        } else {
            format!("\"{k}\": {s}")
        });
    }
    if toml {
        parts.join("\n") + "\n"
    } else {
        format!("{{{}}}", parts.join(", "))
    }
}

fn tf_of(path: &str) -> Value {
    let (code, out, err) = run(&["tf", path, "--format", "json"]);
    assert_eq!(code, 0, "{path}: {err}");
    let v: Value = serde_json::from_str(&out).unwrap();
    v["transfer_matrix"].clone()
}

#[test]
fn every_system_written_reads_back_with_the_same_transfer_matrix() {
    let mut rng = Rng(2225);
    let writers: [(&[&str], &[&str]); 4] = [
        (&["minreal"], &["A", "B", "C", "D"]),
        (
            &["minreal", "--method", "rosenbrock"],
            &["A", "B", "C", "D"],
        ),
        (&["standard"], &["A", "B", "C", "D"]),
        (&["minreal", "--descriptor"], &["E", "A", "B", "C", "D"]),
    ];
    for case in 0..12 {
        // order 0 (static), 0 inputs, 0 outputs, a zero transfer function, descriptor
        let n = [0, 2, 3][case % 3];
        let m = [1, 0, 2, 1][case % 4];
        let p = [1, 2, 0][case % 3].max(usize::from(m == 0 && n == 0));
        let a = rand_rows(&mut rng, n, n);
        let b = rand_rows(&mut rng, n, m);
        let c = rand_rows(&mut rng, p, n);
        let d = rand_rows(&mut rng, p, m);
        let mut keys: Vec<(&str, &Rows)> = vec![("A", &a), ("B", &b), ("C", &c), ("D", &d)];
        let mut e = rand_rows(&mut rng, n, n);
        if n > 0 {
            e[0] = vec![0; n];
            e[0][0] = 1;
        }
        if case % 2 == 1 && n > 0 {
            keys.push(("E", &e));
        }
        let text = serde_json::to_string(&serde_json::json!(
            keys.iter()
                .map(|(k, v)| (k.to_string(), serde_json::json!(v)))
                .collect::<serde_json::Map<_, _>>()
        ))
        .unwrap();
        let src = temp_file("rest22", &format!("rt_{case}.json"), &text);
        let src = src.to_str().unwrap();
        let (code, _, err) = run(&["tf", src]);
        if code != 0 {
            // a descriptor system that is not regular: nothing to write
            assert_eq!(code, 2, "{err}");
            continue;
        }
        let want = tf_of(src);
        for (cmd, mats) in writers {
            let mut args = cmd.to_vec();
            args.extend([src, "--format", "json"]);
            let (code, out, err) = run(&args);
            if code == 2 {
                // refused (an improper system without --descriptor): nothing written
                continue;
            }
            assert_eq!(code, 0, "{cmd:?} {text}: {err}");
            let v: Value = serde_json::from_str(&out).unwrap();
            if (m == 0 || p == 0) && v["order"] == 0 {
                // no matrix of an order-0 system with no inputs (outputs) carries the number of
                // outputs (inputs): nested lists cannot spell a 0 x k matrix
                continue;
            }
            for toml in [false, true] {
                let ext = if toml { "toml" } else { "json" };
                let back = system_of_output(&v, mats, toml);
                let path = temp_file("rest22", &format!("rt_{case}_{}.{ext}", cmd.len()), &back);
                let got = tf_of(path.to_str().unwrap());
                assert_eq!(got, want, "{cmd:?} of {text} wrote {back}");
            }
        }
    }
}

#[test]
fn static_gain_writes_what_reads_back() {
    // the case of the issue: a static G (order 0) writes B: [], C: [[]]
    let p = temp_file("rest22", "static.json", r#"{"G": [["3", "1/2"]]}"#);
    let (code, out, err) = run(&["minreal", p.to_str().unwrap(), "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["order"], 0);
    let back = system_of_output(&v, &["A", "B", "C", "D"], false);
    let q = temp_file("rest22", "static_back.json", &back);
    assert_eq!(
        tf_of(q.to_str().unwrap()),
        serde_json::json!([["3", "1/2"]]),
        "{back}"
    );
    let _ = Q.zero();
}
