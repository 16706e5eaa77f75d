//! Slow exact paths, fields and mnf corner cases (issue 17 items 1, 2, 8; issue 11's
//! Jordan-method minreal): each test failed (or ran for minutes) before its fix. Timings are
//! in `benches/hardening.rs`; here only the identities are asserted.

use exactlti::cli::{Command, execute};
use exactlti::field::{Field, Q};
use exactlti::io::{SystemFormat, load_system_str};
use exactlti::matrix::Matrix;
use exactlti::qmat;
use exactlti::structure::mechanical::{input_compression, mechanical_normal_form};
use std::path::PathBuf;

fn data(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data").join(name)
}

fn tmp_file(name: &str, text: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("exactlti-slowpaths-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

// ---- mnf: dependent inputs, B = 0, a system already in second-order form ----

#[test]
fn mnf_recognises_a_second_order_system_with_two_dependent_inputs() {
    // M = [1], L = [0], K = [1], F = [[1, 1]]: q'' + q = u1 + u2 (was "p = 2 > n/2 = 1")
    let text = r#"{"M": [[1]], "L": [[0]], "K": [[1]], "F": [[1, 1]]}"#;
    let l = load_system_str(text, SystemFormat::Json, "so.json").unwrap();
    let s = &l.rational().unwrap().ss;
    let m = mechanical_normal_form(&s.a, &s.b, &s.c, &s.d).unwrap();
    assert!(m.exists, "{:?}", m.reason);
    assert!(m.verified && m.verify());
    let f = m.form.as_ref().unwrap();
    assert_eq!(f.stiffness, qmat![[1]]);
    assert_eq!(f.damping, qmat![[0]]);
    assert_eq!(f.input, qmat![[1, 1]]);
    // T B = [0; W] and T A T^-1 = A~ exactly
    assert_eq!(&f.t * &s.b, f.b_tilde);
    assert_eq!(&f.a_tilde * &f.t, &f.t * &s.a);
    // and through the command: exit status "verified"
    let p = tmp_file("so.json", text);
    let out = execute(&Command::Mnf { file: p }).unwrap();
    assert!(out.verified);
}

#[test]
fn mnf_with_zero_input_matrix_is_verified_or_refused_with_a_reason() {
    // B = 0, A = [[0, 1], [-1, 0]]: the oscillator q'' + q = 0 (no inputs) has the form
    let a = qmat![[0, 1], [-1, 0]];
    let b = Matrix::zeros(Q, 2, 1);
    let c = qmat![[1, 0]];
    let m = mechanical_normal_form(&a, &b, &c, &qmat![[0]]).unwrap();
    assert!(m.exists && m.verified && m.verify(), "{:?}", m.reason);
    assert_eq!(m.form.as_ref().unwrap().stiffness, qmat![[1]]);
    assert_eq!(m.form.as_ref().unwrap().input, qmat![[0]]);
    // B = 0, A = 2 I: eigenvalue 2 with two eigenvectors cannot live in one coordinate
    let m = mechanical_normal_form(&qmat![[2, 0], [0, 2]], &b, &c, &qmat![[0]]).unwrap();
    assert!(!m.exists && m.form.is_none());
    assert!(m.reason.unwrap().contains("geometric multiplicity"));
}

#[test]
fn mnf_with_rank_deficient_input_matrix_on_scrambled_systems() {
    // q'' + D q' + K q = W u with 3 inputs of rank 2, scrambled by x = S x'
    let k = qmat![[2, -1, 0], [-1, 2, -1], [0, -1, 1]];
    let d = qmat![[1, 0, 0], [0, 0, 0], [0, 0, 1]];
    let z = Matrix::zeros(Q, 3, 3);
    let i = Matrix::identity(Q, 3);
    let a = Matrix::block(Q, &[vec![&z, &i], vec![&-&k, &-&d]]).unwrap();
    let b = Matrix::zeros(Q, 3, 3)
        .vstack(&qmat![[0, 0, 0], [1, 2, -1], [0, 0, 1]])
        .unwrap();
    let s = qmat![
        [1, 2, 0, 0, 1, 0],
        [0, 1, 0, 3, 0, 0],
        [0, 0, 1, 0, 0, -1],
        [1, 0, 0, 1, 0, 0],
        [0, 0, 2, 0, 1, 0],
        [0, 1, 0, 0, 0, 1]
    ];
    let si = s.inverse().unwrap();
    let (a2, b2, c2) = (&(&si * &a) * &s, &si * &b, &qmat![[1, 0, 0, 0, 0, 0]] * &s);
    let m = mechanical_normal_form(&a2, &b2, &c2, &qmat![[0, 0, 0]]).unwrap();
    assert!(m.exists && m.verified && m.verify(), "{:?}", m.reason);
    let f = m.form.as_ref().unwrap();
    let (b1, r) = input_compression(&b2);
    assert_eq!((b1.ncols(), r.nrows()), (2, 2));
    assert_eq!(&b1 * &r, b2);
    // W = [0; R], and the second-order model has the original's Markov parameters
    assert_eq!(f.input.submatrix(1, 3, 0, 3), r);
    assert!(f.input.row(0).iter().all(|x| Q.is_zero(x)));
    assert_eq!(&f.output * &f.t, c2);
    assert!(m.conditions.iter().any(|c| c.name == "input_compression" && !c.decisive));
}
