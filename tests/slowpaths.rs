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
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data")
        .join(name)
}

fn tmp_file(name: &str, text: &str) -> PathBuf {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("exactlti-slowpaths");
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
    assert!(m.reason_text().unwrap().contains("geometric multiplicity"));
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
    assert!(
        m.conditions
            .iter()
            .any(|c| c.name() == "input_compression" && !c.decisive)
    );
}

// ---- zeros through the SCB: oracle and an independent identity ----

fn sys_of(file: &str) -> exactlti::system::StateSpace<Q> {
    let l = exactlti::io::load_system_path(&data(file)).unwrap();
    l.rational().unwrap().ss.clone()
}

fn p_at(s: &exactlti::system::StateSpace<Q>, s0: i64) -> Matrix<Q> {
    let n = s.nstates();
    let shift = Matrix::identity(Q, n).scale(&Q.from_i64(s0));
    let top = s.a.try_sub(&shift).unwrap().hstack(&s.b).unwrap();
    top.vstack(&s.c.hstack(&s.d).unwrap()).unwrap()
}

#[test]
fn zeros_of_square_planted_systems_are_det_p_up_to_a_constant() {
    use exactlti::structure::zeros::invariant_zeros;
    // before: > 120 s for n = 16 (polynomial Smith form); square P(s): det P(s) = c z(s)
    for f in ["hardening/nilpotent_20.json", "hardening/planted_12.json"] {
        let s = sys_of(f);
        let z = invariant_zeros(&s.a, &s.b, &s.c, &s.d).unwrap();
        let (rows, cols) = z.size;
        let mut ratio = None;
        for s0 in [0, 1, -1, 2, 5] {
            let det = p_at(&s, s0).det().unwrap();
            let zv = z.polynomial.eval(&Q.from_i64(s0));
            if Q.is_zero(&zv) {
                assert!(Q.is_zero(&det), "{f}: P({s0}) regular at a zero");
                continue;
            }
            let r = Q.div(&det, &zv).unwrap();
            assert!(
                ratio.get_or_insert(r.clone()) == &r,
                "{f}: det P / z not constant"
            );
        }
        if rows == cols && z.normal_rank == rows {
            // det P(s) has degree n - (relative degree), z has the same degree: nonzero c
            assert!(ratio.is_some_and(|r| !Q.is_zero(&r)), "{f}");
        }
    }
}

#[test]
fn zeros_through_the_scb_agree_with_the_smith_form_oracle() {
    use exactlti::structure::zeros::{invariant_zeros, invariant_zeros_smith};
    let mut rng = crate::common::Rng(1717);
    for case in 0..40 {
        let n = 1 + case % 5;
        let (m, p) = (1 + rng.int(0, 2) as usize, 1 + rng.int(0, 2) as usize);
        let mut g = |r: usize, c: usize, range: i64| {
            Matrix::from_fn(Q, r, c, |_, _| Q.from_i64(rng.int(-range, range)))
        };
        let a = g(n, n, 3);
        let mut b = g(n, m, 2);
        let mut c = g(p, n, 2);
        let d = if case % 3 == 0 {
            g(p, m, 1)
        } else {
            Matrix::zeros(Q, p, m)
        };
        if case % 4 == 1 && m > 1 {
            // a dependent input column
            for i in 0..n {
                let v = b.get(i, 0).clone();
                b.set(i, m - 1, Q.add(&v, &v));
            }
        }
        if case % 7 == 2 {
            c = Matrix::zeros(Q, p, n);
        }
        let fast = invariant_zeros(&a, &b, &c, &d).unwrap();
        let slow = invariant_zeros_smith(&a, &b, &c, &d).unwrap();
        assert_eq!(fast.polynomial, slow.polynomial, "case {case}");
        assert_eq!(fast.normal_rank, slow.normal_rank, "case {case}");
    }
}

// ---- Rosenbrock: staircase from the nested Krylov spaces ----

#[test]
fn rosenbrock_staircase_has_the_eq17_pattern_and_matches_kalman() {
    use exactlti::realization::controllable_staircase;
    use exactlti::realization::{MinrealMethod, minimal};
    for f in ["hardening/rosen_30.json", "everyday/random_8_mimo.json"] {
        let s = sys_of(f);
        let n = s.nstates();
        let (t, k) = controllable_staircase(&s.a, &s.b).unwrap();
        let ti = t.inverse().unwrap();
        let at = &(&ti * &s.a) * &t;
        let bt = &ti * &s.b;
        // [A11 0; A21 A22], B = [0; B2]: the controllable states are the last k
        assert!(at.submatrix(0, n - k, n - k, n).is_zero(), "{f}");
        assert!(bt.submatrix(0, n - k, 0, s.ninputs()).is_zero(), "{f}");
        let ros = minimal(&s, MinrealMethod::Rosenbrock).unwrap();
        let kal = minimal(&s, MinrealMethod::Kalman).unwrap();
        assert!(ros.verified, "{f}");
        assert_eq!(ros.system.nstates(), kal.system.nstates(), "{f}");
    }
}

// ---- the real-field marking (issue 17 item 1): sextic and septic factors ----

#[test]
fn real_jordan_form_is_exact_for_sextic_and_septic_factors() {
    use crate::jcommon::companion;
    use exactlti::jordan::jordan;
    // x^6 + 3x + 3 and x^7 - 3x + 3 (Eisenstein at 3), x^3 - 2: irreducible, complex pairs
    let six = companion(&[3, 3, 0, 0, 0, 0, 1]);
    let seven = companion(&[3, -3, 0, 0, 0, 0, 0, 1]);
    let three = companion(&[-2, 0, 0, 1]);
    let cases = [
        six.clone(),
        Matrix::block_diag(Q, &[seven, qmat![[2]]]),
        Matrix::block_diag(Q, &[six, three]),
    ];
    let mut rng = crate::common::Rng(6789);
    for (i, j) in cases.iter().enumerate() {
        let p = crate::common::unimodular(&Q, j.nrows(), &mut rng);
        let a = &(&p * j) * &p.inverse().unwrap();
        let jf = jordan(&a).unwrap();
        assert!(jf.verified, "case {i}");
        let rf = jf.real_form().unwrap();
        assert!(
            rf.exact && rf.verified,
            "case {i}: exact {} verified {}",
            rf.exact,
            rf.verified
        );
    }
    // the fuzzer's reproducers through the commands: verified (exit 0)
    for f in ["fuzz_jordan_marking.json", "fuzz_slow_real_jordan.json"] {
        let out = execute(&Command::Jordan {
            file: data(f),
            real: true,
            expand: false,
            normalize: None,
        })
        .unwrap();
        assert!(out.verified, "{f}");
    }
}

// ---- fields: mnf over Q(i) ----

#[test]
fn mnf_over_gaussian_rationals_is_verified() {
    // the Hermitian stiffness [[1, 2+i], [2-i, 3]] of q'' + K q = [0; 1] u, scrambled
    let text = r#"{"A": [[0, 0, 1, 0], [0, 0, 0, 1], ["-1", "-2-i", 0, 0], ["-2+i", "-3", 0, 0]],
                   "B": [[1], [0], [0], [1]], "C": [["1+i", 0, 0, 0]]}"#;
    let p = tmp_file("hermitian.json", text);
    let out = execute(&Command::Mnf { file: p }).unwrap();
    assert!(out.verified);
    assert!(matches!(
        out.report.get("exists"),
        Some(exactlti::report::Value::Bool(true))
    ));
}

// ---- tf of a state-space file with a 1e300 entry ----

/// The fuzzer's case: `tf` realized G entry by entry (a stacked descriptor system reduced by
/// a Weierstrass split with 10^3-digit coefficients) and ran for minutes; a state-space input
/// now keeps its own Kalman minimal realization, G checked by Markov parameters.
#[test]
fn tf_of_a_state_space_with_a_huge_entry_is_realized_from_the_system() {
    let out = execute(&Command::Tf {
        file: data("fuzz_tf_huge_entry.json"),
    })
    .unwrap();
    assert!(out.verified);
    let get = |k: &str| out.report.get(k).cloned();
    assert_eq!(
        get("markov_verified"),
        Some(exactlti::report::Value::Bool(true))
    );
    assert!(
        matches!(
            get("mcmillan_degree"),
            Some(exactlti::report::Value::Int(4))
        ),
        "{:?}",
        get("mcmillan_degree")
    );
}
