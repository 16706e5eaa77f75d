//! Jordan decomposition over K = Q(i) and Q(sqrt d) (issue 17 item 2): exact identities in
//! each component's field, eigenvalue sets of the Hermitian examples, the conj(A) trap
//! (eigenvalues of A, not of its Galois conjugate), planted non-trivial blocks, and a
//! proptest over both fields.

use crate::common::cli::{self, run};
use crate::common::{quadratic as q, quadratic_matrix as mat};
use exactlti::field::{Field, Quadratic, QuadraticField};
use exactlti::jordan::{JordanForm, jordan_over as jordan_over_k};
type JordanFormK = JordanForm<QuadraticField>;
use exactlti::matrix::Matrix;
use proptest::prelude::*;

#[path = "jordan_fields/real.rs"]
mod real;
#[path = "jordan_fields/symbols.rs"]
mod symbols;

fn values(jf: &JordanFormK) -> Vec<String> {
    jf.eigenvalues
        .iter()
        .map(exactlti::report::sections::eigenvalue_text)
        .collect()
}

/// |chi_A(z)| small against the size of its terms at every eigenvalue's approximation.
fn approx_roots_of_charpoly(jf: &JordanFormK) -> bool {
    let k = jf.base();
    jf.eigenvalues.iter().all(|e| {
        let z = num_complex::Complex64::new(e.approx.0, e.approx.1);
        let (mut v, mut scale) = (num_complex::Complex64::new(0.0, 0.0), 0.0);
        for (i, c) in jf.charpoly.coeffs().iter().enumerate() {
            let (re, im) = k.approx(c);
            let t = num_complex::Complex64::new(re, im) * z.powi(i as i32);
            v += t;
            scale += t.norm();
        }
        // a root of multiplicity m is only determined to about eps^(1/m)
        v.norm() <= 1e-6 * scale.max(1.0)
    })
}

/// The exact identities and dimensions, and the eigenvalues' approximations are roots.
fn check(jf: &JordanFormK) {
    assert!(jf.verified, "{:?}", values(jf));
    for c in &jf.components {
        assert!(c.verify(&jf.a));
        assert_eq!(c.blocks.iter().sum::<usize>(), c.multiplicity);
    }
    let total: usize = jf
        .eigenvalues
        .iter()
        .map(|e| e.algebraic_multiplicity)
        .sum();
    assert_eq!(total, jf.n());
    assert!(approx_roots_of_charpoly(jf), "{:?}", values(jf));
}

#[test]
fn hermitian_examples_have_real_eigenvalues_2_pm_sqrt6() {
    let k = QuadraticField::gaussian();
    let a = mat(&k, &[&[(1, 0), (2, 1)], &[(2, -1), (3, 0)]]);
    let jf = jordan_over_k(&a).unwrap();
    check(&jf);
    assert_eq!(values(&jf), ["2 + sqrt(6)", "2 - sqrt(6)"]);
    assert!(jf.eigenvalues.iter().all(|e| e.number.is_real()));
    // [[1, 2 + sqrt 3], [2 - sqrt 3, 3]]: chi = x^2 - 4x + 2, eigenvalues 2 +- sqrt(2)
    let k = QuadraticField::new(3).unwrap();
    let a = mat(&k, &[&[(1, 0), (2, 1)], &[(2, -1), (3, 0)]]);
    let jf = jordan_over_k(&a).unwrap();
    check(&jf);
    assert_eq!(values(&jf), ["2 + sqrt(2)", "2 - sqrt(2)"]);
}

#[test]
fn eigenvalues_are_those_of_a_not_of_its_conjugate() {
    // triangular over Q(i) with diagonal i, 2i: eigenvalues i and 2i, never -i or -2i
    let k = QuadraticField::gaussian();
    let a = mat(&k, &[&[(0, 1), (3, 1)], &[(0, 0), (0, 2)]]);
    let jf = jordan_over_k(&a).unwrap();
    check(&jf);
    let mut v = values(&jf);
    v.sort();
    assert_eq!(v, ["2*i", "i"]);
    // over Q(sqrt 2): diagonal sqrt 2, 1 + sqrt 2 (not -sqrt 2, 1 - sqrt 2)
    let k = QuadraticField::new(2).unwrap();
    let a = mat(&k, &[&[(0, 1), (5, 0)], &[(0, 0), (1, 1)]]);
    let jf = jordan_over_k(&a).unwrap();
    check(&jf);
    let mut v = values(&jf);
    v.sort();
    assert_eq!(v, ["1 + sqrt(2)", "sqrt(2)"]);
    // a non-linear factor that is not rational: x^2 - i (roots +-(1 + i)/sqrt 2), whose
    // Q-minimal polynomial x^4 + 1 also has the roots of x^2 + i (eigenvalues of conj A)
    let k = QuadraticField::gaussian();
    let a = mat(&k, &[&[(0, 0), (0, 1)], &[(1, 0), (0, 0)]]);
    let jf = jordan_over_k(&a).unwrap();
    check(&jf);
    assert_eq!(jf.eigenvalues.len(), 2);
    for e in &jf.eigenvalues {
        // z^2 = i: re^2 - im^2 = 0 and 2 re im = 1 (so re and im have the same sign)
        let (re, im) = e.approx;
        assert!((re * re - im * im).abs() < 1e-12 && (2.0 * re * im - 1.0).abs() < 1e-12);
        assert_eq!(e.minpoly.to_string(), "x^4 + 1");
    }
}

/// `S J S^-1` for a unit-triangular product `S = L U` over `k` (exactly invertible).
fn planted(
    k: &QuadraticField,
    j: &Matrix<QuadraticField>,
    seed: &[(i64, i64)],
) -> Matrix<QuadraticField> {
    let n = j.nrows();
    let mut it = seed.iter().cycle();
    let mut next = || {
        let &(a, b) = it.next().unwrap();
        q(a, b)
    };
    let mut l = Matrix::identity(k.clone(), n);
    let mut u = Matrix::identity(k.clone(), n);
    for r in 0..n {
        for c in 0..r {
            l.set(r, c, next());
            u.set(c, r, next());
        }
    }
    let s = &l * &u;
    &(&s * j) * &s.inverse().unwrap()
}

fn jordan_matrix(k: &QuadraticField, blocks: &[(Quadratic, usize)]) -> Matrix<QuadraticField> {
    let n: usize = blocks.iter().map(|b| b.1).sum();
    crate::jcommon::jordan_blocks(k, blocks, n)
}

#[test]
fn planted_jordan_blocks_over_qi_and_q_sqrt2() {
    let seed = [(1, 1), (-2, 0), (0, 1), (3, -1), (1, 0), (-1, 2)];
    for d in [-1, 2] {
        let k = QuadraticField::new(d).unwrap();
        // blocks: (1 + alpha) of sizes 3, 1; (-2) of size 2
        let j = jordan_matrix(&k, &[(q(1, 1), 3), (q(1, 1), 1), (q(-2, 0), 2)]);
        let a = planted(&k, &j, &seed);
        let jf = jordan_over_k(&a).unwrap();
        check(&jf);
        let e = jf
            .eigenvalues
            .iter()
            .find(|e| e.algebraic_multiplicity == 4)
            .unwrap();
        assert_eq!(e.blocks, [3, 1]);
        assert_eq!(
            exactlti::report::sections::eigenvalue_text(e),
            if d == -1 { "1 + i" } else { "1 + sqrt(2)" }
        );
        let e = jf
            .eigenvalues
            .iter()
            .find(|e| exactlti::report::sections::eigenvalue_text(e) == "-2")
            .unwrap();
        assert_eq!(e.blocks, [2]);
        // every eigenvalue in K: one exact pair (J, T) over K with A T = T J
        let (jj, t) = jf.single_field().unwrap();
        let e = jj.field().clone();
        assert_eq!(e.degree(), 1);
        assert_eq!(&a.map(&e, |x| e.from_base(x)) * &t, &t * &jj);
        assert!(t.inverse().is_ok());
    }
    // a block of a non-linear factor: x^2 - alpha with a 2-block (chi = (x^2 - alpha)^2)
    for d in [-1, 2] {
        let k = QuadraticField::new(d).unwrap();
        // companion of x^2 - alpha, doubled with a coupling: [[C, I], [0, C]]
        let mut j = Matrix::zeros(k.clone(), 4, 4);
        for off in [0, 2] {
            j.set(off, off + 1, k.one());
            j.set(off + 1, off, q(0, 1));
        }
        j.set(0, 2, k.one());
        j.set(1, 3, k.one());
        let a = planted(&k, &j, &seed);
        let jf = jordan_over_k(&a).unwrap();
        check(&jf);
        assert_eq!(jf.eigenvalues.len(), 2);
        assert!(jf.eigenvalues.iter().all(|e| e.blocks == [2]));
    }
}

fn small_entry() -> impl Strategy<Value = (i64, i64)> {
    (-3i64..=3, -2i64..=2)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, .. ProptestConfig::default() })]
    /// Random 1..4 x 4 matrices over Q(i) and Q(sqrt 2), and planted blocks of a repeated
    /// eigenvalue in K: verified (Jordan form, real form over Q(sqrt 2), free response,
    /// Jordan-method realization), block sizes add up to n, approximations are roots.
    #[test]
    fn jordan_over_k_is_verified(
        d in prop::sample::select(vec![-1i64, 2]),
        n in 1usize..=4,
        entries in prop::collection::vec(small_entry(), 16),
        theta in small_entry(),
        sizes in prop::sample::select(vec![vec![1usize], vec![2], vec![2, 1], vec![1, 1], vec![3]]),
    ) {
        let k = QuadraticField::new(d).unwrap();
        let a = Matrix::from_fn(k.clone(), n, n, |i, j| {
            let (x, y) = entries[i * n + j];
            q(x, y)
        });
        let jf = jordan_over_k(&a).unwrap();
        check(&jf);
        // the real form over Q(sqrt 2) (pairs in their real field when small, checked there)
        // and the free response (x(0) = x0, x' = A x)
        if d > 0 {
            let rf = jf.real_form().unwrap();
            prop_assert!(rf.verified, "A = {}", a);
        }
        prop_assert!(jf.free_response().verify(&jf), "A = {}", a);
        // the Jordan-method minimal realization of (A, B, C) with B, C from the entries:
        // verified (Markov parameters, McMillan degree) and of the Kalman order
        let b = Matrix::from_fn(k.clone(), n, 1, |i, _| q(entries[i].1, entries[15 - i].0));
        let c = Matrix::from_fn(k.clone(), 1, n, |_, i| q(entries[8 + i].0, 0));
        let sys = exactlti::system::StateSpace::new_strictly_proper(a.clone(), b, c).unwrap();
        let r = exactlti::realization::minimal_jordan(&sys).unwrap();
        let kal = exactlti::realization::minimal(&sys, exactlti::realization::MinrealMethod::Kalman).unwrap();
        prop_assert!(r.verified);
        prop_assert_eq!(r.order(), kal.order);
        let blocks: Vec<(Quadratic, usize)> = sizes.iter().map(|&s| (q(theta.0, theta.1), s)).collect();
        let j = jordan_matrix(&k, &blocks);
        let a = planted(&k, &j, &entries);
        let jf = jordan_over_k(&a).unwrap();
        check(&jf);
        prop_assert_eq!(jf.eigenvalues.len(), 1);
        prop_assert_eq!(&jf.eigenvalues[0].blocks, &sizes);
    }
}

/// The real form's approximations satisfy A T = T J (its exact check is on the complex side).
fn real_form_close(
    a: &Matrix<QuadraticField>,
    rf: &exactlti::jordan::RealJordanForm<QuadraticField>,
) {
    let k = a.field();
    let n = a.nrows();
    let av: Vec<Vec<f64>> = (0..n)
        .map(|i| (0..n).map(|j| k.approx(a.get(i, j)).0).collect())
        .collect();
    let (jo, to) = rf.j_t_out();
    let re = |m: &Vec<Vec<(f64, f64)>>| -> Vec<Vec<f64>> {
        m.iter().map(|r| r.iter().map(|z| z.0).collect()).collect()
    };
    let (t, j) = (&re(&to.approx), &re(&jo.approx));
    for r in 0..n {
        for c in 0..n {
            let at: f64 = (0..n).map(|l| av[r][l] * t[l][c]).sum();
            let tj: f64 = (0..n).map(|l| t[r][l] * j[l][c]).sum();
            assert!(
                (at - tj).abs() < 1e-8 * (1.0 + at.abs()),
                "{r},{c}: {at} vs {tj}"
            );
        }
    }
}

#[test]
fn real_jordan_form_over_q_sqrt2() {
    let k = QuadraticField::new(2).unwrap();
    // [[1, sqrt 2], [-sqrt 2, 1]]: chi = x^2 - 2x + 3, roots 1 +- sqrt(2) i (radical form)
    let a = mat(&k, &[&[(1, 0), (0, 1)], &[(0, -1), (1, 0)]]);
    let jf = jordan_over_k(&a).unwrap();
    check(&jf);
    let rf = jf.real_form().unwrap();
    assert!(rf.verified && !rf.blocks.iter().any(|b| b.is_compact()));
    assert_eq!(rf.j_t_out().0.exact, [["1", "sqrt(2)"], ["-sqrt(2)", "1"]]);
    real_form_close(&a, &rf);
    // [[sqrt 2, 1], [-1, sqrt 2]] (roots sqrt 2 +- i, minimal polynomial of degree 4), a
    // real root, and a 2-block of a complex pair: planted
    let a = real::pair_block_matrix(&k);
    let jf = jordan_over_k(&a).unwrap();
    check(&jf);
    let pair: Vec<_> = jf
        .eigenvalues
        .iter()
        .filter(|e| e.approx.1 != 0.0)
        .collect();
    assert_eq!(pair.len(), 2);
    assert!(pair.iter().all(|e| e.blocks == [2]));
    // the pair's real field is Q(sqrt 2) itself: expanded, as over Q (tests/jordan_fields/real.rs)
    let rf = jf.real_form().unwrap();
    assert!(
        rf.verified && !rf.blocks.iter().any(|b| b.is_compact()),
        "{rf:?}"
    );
    real_form_close(&a, &rf);
    // Q(i): no real form
    let a = mat(&QuadraticField::gaussian(), &[&[(0, 1)]]);
    assert!(jordan_over_k(&a).unwrap().real_form().is_err());
}

#[test]
fn jordan_method_minreal_over_k_is_minimal_and_verified() {
    use exactlti::realization::{MinrealMethod, minimal, minimal_jordan};
    use exactlti::system::StateSpace;
    for d in [-1, 2, 3] {
        let k = QuadraticField::new(d).unwrap();
        // a 3-block and a 1-block of 1 + alpha, a simple -2, and x^2 - alpha
        let mut j = jordan_matrix(&k, &[(q(1, 1), 3), (q(1, 1), 1), (q(-2, 0), 1)]);
        let mut big = Matrix::zeros(k.clone(), 7, 7);
        for r in 0..5 {
            for c in 0..5 {
                big.set(r, c, j.get(r, c).clone());
            }
        }
        big.set(5, 6, k.one());
        big.set(6, 5, q(0, 1));
        j = big;
        let a = planted(&k, &j, &[(1, 0), (0, 1), (-1, 0), (1, -1), (0, 0)]);
        for (b, c) in [
            (
                vec![(1, 0), (0, 1), (0, 0), (2, 0), (0, 0), (1, 0), (0, 0)],
                vec![(1, 0), (0, 0), (0, 1), (1, 0), (0, 0), (0, 0), (1, 1)],
            ),
            (
                vec![(0, 0), (0, 0), (1, 0), (0, 0), (0, 0), (0, 0), (0, 0)],
                vec![(1, 0), (0, 0), (0, 0), (0, 0), (0, 0), (0, 0), (0, 0)],
            ),
        ] {
            let bm = Matrix::from_fn(k.clone(), 7, 1, |i, _| q(b[i].0, b[i].1));
            let cm = Matrix::from_fn(k.clone(), 1, 7, |_, i| q(c[i].0, c[i].1));
            let sys = StateSpace::new_strictly_proper(a.clone(), bm, cm).unwrap();
            let r = minimal_jordan(&sys).unwrap();
            let kal = minimal(&sys, MinrealMethod::Kalman).unwrap();
            assert!(r.verified, "d = {d}");
            assert_eq!(r.order(), kal.order, "d = {d}");
            assert_eq!(r.order(), r.mcmillan_degree);
        }
    }
}

#[test]
fn modal_table_over_lists_the_eigenvalues_of_a() {
    use exactlti::realization::modal_table_over;
    let k = QuadraticField::gaussian();
    let a = mat(&k, &[&[(0, 1), (3, 1)], &[(0, 0), (-1, 2)]]);
    let t = modal_table_over(&a).unwrap();
    let mut v: Vec<String> = t
        .modes
        .iter()
        .map(|m| m.eigenvalue.value_string())
        .collect();
    v.sort();
    assert_eq!(v, ["-1 + 2*i", "i"]);
    assert!(t.modes.iter().all(|m| !m.paired));
    // -1 + 2i: omega_n = sqrt 5, zeta = 1/sqrt 5, tau = 1
    let m = t
        .modes
        .iter()
        .find(|m| m.eigenvalue.value_string() == "-1 + 2*i")
        .unwrap();
    assert!((m.damping_ratio.unwrap() - 1.0 / 5f64.sqrt()).abs() < 1e-12);
    assert!((m.time_constant_s.unwrap() - 1.0).abs() < 1e-12);
    // a real matrix over Q(sqrt 2) with a complex pair: one mode for the pair
    let k = QuadraticField::new(2).unwrap();
    let a = mat(&k, &[&[(0, 1), (1, 0)], &[(-1, 0), (0, 1)]]);
    let t = modal_table_over(&a).unwrap();
    assert_eq!(t.modes.len(), 1);
    assert!(t.modes[0].paired);
}

fn temp_file(name: &str, text: &str) -> std::path::PathBuf {
    cli::temp_file("jfields", name, text)
}

#[test]
fn cli_commands_over_quadratic_fields() {
    let qi = temp_file(
        "qi.json",
        r#"{"A": [["1", "2+i"], ["2-i", "3"]], "B": [[1], [0]], "C": [[1, 0]]}"#,
    );
    let qs = temp_file(
        "qs.json",
        r#"{"A": [["1", "2+sqrt(3)"], ["2-sqrt(3)", "3"]], "B": [[1], [0]], "C": [[1, 0]]}"#,
    );
    let json = |args: &[&str]| -> serde_json::Value {
        let (code, out, err) = run(args);
        assert_eq!(code, 0, "{args:?}: {err}");
        serde_json::from_str(&out).unwrap()
    };
    for (f, want) in [
        (&qi, ["2 + sqrt(6)", "2 - sqrt(6)"]),
        (&qs, ["2 + sqrt(2)", "2 - sqrt(2)"]),
    ] {
        let f = f.to_str().unwrap();
        let j = json(&["jordan", f, "--format", "json"]);
        for key in ["eigenvalues", "J", "T", "verified"] {
            assert!(!j[key].is_null(), "{key}: {j}");
        }
        assert_eq!(j["verified"], true);
        let vals: Vec<&str> = j["eigenvalues"]
            .as_array()
            .unwrap()
            .iter()
            .map(|e| e["value"].as_str().unwrap())
            .collect();
        assert_eq!(vals, want);
        assert_eq!(j["eigenvalues"][0]["blocks"], serde_json::json!([1]));
        let j = json(&["modes", f, "--format", "json"]);
        assert_eq!(j["modes"].as_array().unwrap().len(), 2, "{j}");
        let j = json(&["minreal", "--method", "jordan", f, "--format", "json"]);
        let kal = json(&["minreal", f, "--format", "json"]);
        assert_eq!(j["verified"], true);
        assert_eq!(j["order"], kal["order"]);
        let j = json(&["analyze", f, "--format", "json"]);
        assert_eq!(j["jordan"]["verified"], true, "{j}");
        assert!(j["modes"]["modes"].is_array(), "{j}");
        assert!(j["pbh"]["controllable"].is_boolean(), "{j}");
    }
    // --real: the real Jordan form over Q(sqrt 3); none over Q(i) (A is not real)
    let j = json(&["jordan", "--real", qs.to_str().unwrap(), "--format", "json"]);
    assert_eq!(j["verified"], true);
    assert_eq!(j["exact"], true);
    let (code, _, err) = run(&["jordan", "--real", qi.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains("not real") && err.contains("`jordan`"),
        "{err}"
    );
}
