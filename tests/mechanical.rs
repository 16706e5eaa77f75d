//! Mechanical normal form (Mayet & Kammermeier): the paper's App. B and App. C cases, random
//! mechanical systems scrambled by similarities, failing conditions and invalid shapes.

use crate::common;

use common::{Rng, iters, unimodular};
use exactlti::error::Error;
use exactlti::field::{Field, Q, Rational};
use exactlti::matrix::Matrix;
use exactlti::qmat;
use exactlti::structure::mechanical::transform::{transformation_family, transformation_from_x};
use exactlti::structure::mechanical::unify::unifying_transformation;
use exactlti::structure::mechanical::{
    MnfResult, decide_existence, mechanical_normal_form, mechanical_normal_form_descriptor,
};

fn r(n: i64) -> Rational {
    Rational::from_integer(n.into())
}

fn unit(n: usize, i: usize) -> Matrix<Q> {
    Matrix::from_fn(Q, n, 1, |r, _| if r == i { Q.one() } else { Q.zero() })
}

/// A random invertible rational matrix: unimodular * rational diagonal * unimodular.
fn random_invertible(n: usize, rng: &mut Rng) -> Matrix<Q> {
    let d: Vec<Rational> = (0..n)
        .map(|_| {
            let num = rng.int(1, 3) * if rng.int(0, 1) == 0 { 1 } else { -1 };
            Rational::new(num.into(), rng.int(1, 2).into())
        })
        .collect();
    &(&unimodular(&Q, n, rng) * &Matrix::diagonal(Q, &d)) * &unimodular(&Q, n, rng)
}

fn random_rational(m: usize, n: usize, rng: &mut Rng) -> Matrix<Q> {
    Matrix::from_fn(Q, m, n, |_, _| common::rational(rng, 4))
}

/// `x = S x'`: `(S^-1 A S, S^-1 B, C S)`.
fn scramble(
    a: &Matrix<Q>,
    b: &Matrix<Q>,
    c: &Matrix<Q>,
    s: &Matrix<Q>,
) -> (Matrix<Q>, Matrix<Q>, Matrix<Q>) {
    let si = s.inverse().unwrap();
    (&(&si * a) * s, &si * b, c * s)
}

/// `C A^j B` for `j < count`, as `(C A^i) (A^(j-i) B)` with `i <= count/2` (smaller powers).
fn markov(a: &Matrix<Q>, b: &Matrix<Q>, c: &Matrix<Q>, count: usize) -> Vec<Matrix<Q>> {
    let half = count.div_ceil(2).max(1);
    let mut left = vec![c.clone()];
    let mut right = vec![b.clone()];
    for i in 1..=half {
        left.push(&left[i - 1] * a);
        right.push(a * &right[i - 1]);
    }
    (0..count)
        .map(|j| {
            let i = j.min(half);
            &left[i] * &right[j - i]
        })
        .collect()
}

/// Checks the form against the original system independently of `verify`.
fn assert_normal_form(res: &MnfResult, a: &Matrix<Q>, b: &Matrix<Q>, c: &Matrix<Q>, ctx: &str) {
    assert!(res.exists, "{ctx}: {:?}", res.reason);
    assert!(res.verified, "{ctx}");
    let f = res.form.as_ref().unwrap();
    let n = a.nrows();
    let h = n / 2;
    let p = b.ncols();
    assert!(f.mass.is_identity(), "{ctx}");
    assert!(
        f.a_tilde.submatrix(0, h, 0, h).is_zero() && f.a_tilde.submatrix(0, h, h, n).is_identity(),
        "{ctx}: A~ = {}",
        f.a_tilde
    );
    assert_eq!(f.stiffness, -&f.a_tilde.submatrix(h, n, 0, h), "{ctx}");
    assert_eq!(f.damping, -&f.a_tilde.submatrix(h, n, h, n), "{ctx}");
    let mut w = Matrix::zeros(Q, h, p);
    for j in 0..p {
        w.set(h - p + j, j, Q.one());
    }
    assert_eq!(f.input, w, "{ctx}");
    // z = T x: A~ T = T A, B~ = T B, C~ T = C
    assert_eq!(&f.a_tilde * &f.t, &f.t * a, "{ctx}");
    assert_eq!(f.b_tilde, &f.t * b, "{ctx}");
    assert_eq!(&f.output * &f.t, *c, "{ctx}");
    assert_eq!(
        f.a_tilde.charpoly().unwrap(),
        a.charpoly().unwrap(),
        "{ctx}: eigenvalues"
    );
    assert_eq!(
        markov(&f.a_tilde, &f.b_tilde, &f.output, 2 * n),
        markov(a, b, c, 2 * n),
        "{ctx}: Markov parameters"
    );
}

fn run(a: &Matrix<Q>, b: &Matrix<Q>, c: &Matrix<Q>) -> MnfResult {
    let d = Matrix::zeros(Q, c.nrows(), b.ncols());
    mechanical_normal_form(a, b, c, &d).unwrap()
}

// ---------------------------------------------------------------- App. B

#[test]
fn appendix_b_natural_choice_is_singular_but_algorithm_succeeds() {
    let (w1, w2) = (2, 3);
    let a = qmat![
        [0, 0, 1, 0],
        [0, 0, 0, 1],
        [-w1 * w1, 0, 0, 0],
        [0, -w2 * w2, 0, 0]
    ];
    let b = qmat![[0], [0], [0], [1]];
    let c = qmat![[1, 0, 0, 0], [0, 1, 0, 0]];
    // eq. 19: X = [e1, e3] satisfies B^T X = 0 but gives a singular T
    let x = unit(4, 0).hstack(&unit(4, 2)).unwrap();
    assert!((&b.transpose() * &x).is_zero());
    let t_bad = transformation_from_x(&a, &x).unwrap();
    assert_eq!(
        t_bad.transpose(),
        qmat![[1, 0, 0, -4], [0, 0, 0, 0], [0, 1, 1, 0], [0, 0, 0, 0]]
    );
    assert!(Q.is_zero(&t_bad.det().unwrap()));
    // X = [e1, e2] gives T = I (the system already has the form)
    let x_good = unit(4, 0).hstack(&unit(4, 1)).unwrap();
    assert!(transformation_from_x(&a, &x_good).unwrap().is_identity());
    // the algorithm finds a non-singular T
    let res = run(&a, &b, &c);
    assert_normal_form(&res, &a, &b, &c, "App. B");
    let f = res.form.as_ref().unwrap();
    assert!(!Q.is_zero(&f.t.det().unwrap()));
    // the eigenvalues +-2i, +-3i survive: det(s^2 I + D s + K) = (s^2 + 4)(s^2 + 9)
    assert_eq!(
        f.a_tilde.charpoly().unwrap().to_string(),
        "x^4 + 13*x^2 + 36"
    );
    // the report carries the CLI keys
    let j = res.report().to_json();
    for key in [
        "exists",
        "reason",
        "mass",
        "damping",
        "stiffness",
        "input",
        "output",
        "feedthrough",
        "T",
        "verified",
    ] {
        assert!(j.get(key).is_some(), "missing key {key}");
    }
    assert_eq!(j["verified"], serde_json::Value::Bool(true));
}

// ---------------------------------------------------------------- App. C

/// `n = m + 2`, `B = e_n`, `A e_n = e_{n-1}`, `A[0..m, 0..m] = J`: then `G = J` exactly
/// (U_B2 = [e_1..e_{n-1}], U_K1 = e_{n-1}, U_K2 = [e_1..e_m]). `coupling` feeds the
/// velocity-like state into the J part (0 leaves it uncontrollable).
fn block_system(j: &Matrix<Q>, coupling: i64) -> (Matrix<Q>, Matrix<Q>, Matrix<Q>) {
    let m = j.nrows();
    let n = m + 2;
    let mut a = Matrix::zeros(Q, n, n);
    a.set_block(0, 0, j);
    for i in 0..m {
        a.set(i, m, r(coupling * (i as i64 % 2 + 1)));
        a.set(m, i, r(i as i64 + 1));
        a.set(m + 1, i, r(1 - i as i64));
    }
    a.set(m, m + 1, r(1));
    a.set(m + 1, m, r(-2));
    let b = unit(n, m + 1);
    let c = Matrix::from_fn(Q, 1, n, |_, j| r(j as i64 + 1));
    (a, b, c)
}

/// Sec. 2.1 with the paper's App. C choice: X = U_B2 [U_K1, U_K2 Z], checked invertible
/// together with Z^T J Z_perp; then the unifying W of sec. 2.2 lands in the eq. 15 family.
fn check_paper_choice(j: &Matrix<Q>, z: &Matrix<Q>, z_perp: &Matrix<Q>, want: &Matrix<Q>) {
    assert!((&z.transpose() * z_perp).is_zero());
    assert_eq!(&(&z.transpose() * j) * z_perp, *want);
    let (a, b, _) = block_system(j, 1);
    let m = j.nrows();
    let n = m + 2;
    let zpad = z.vstack(&Matrix::zeros(Q, 2, z.ncols())).unwrap();
    let x = unit(n, m).hstack(&zpad).unwrap();
    let t_hat = transformation_from_x(&a, &x).unwrap();
    assert!(!Q.is_zero(&t_hat.det().unwrap()), "J = {j}");
    let w = unifying_transformation(&t_hat, &b).unwrap();
    let t = &w * &t_hat;
    let h = n / 2;
    let at = &(&t * &a) * &t.inverse().unwrap();
    assert!(at.submatrix(0, h, 0, h).is_zero() && at.submatrix(0, h, h, n).is_identity());
    assert_eq!(&t * &b, unit(n, n - 1));
    // t solves L vec(T) = R: it is T0 + sum alpha_k T_k for some alpha
    let fam = transformation_family(None, &a, &b).unwrap();
    let mut dirs = Matrix::zeros(Q, n * n, 0);
    for d in &fam.directions {
        dirs = dirs.hstack(&d.vec()).unwrap();
    }
    let rhs = &t.vec() - &fam.particular.vec();
    assert!(dirs.solve(&rhs).unwrap().is_some());
}

fn check_block_case(j: &Matrix<Q>, seed: u64, name: &str) {
    let mut rng = Rng(seed);
    for coupling in [0, 1] {
        let (a, b, c) = block_system(j, coupling);
        let ctx = format!("{name}, coupling {coupling}");
        assert_normal_form(&run(&a, &b, &c), &a, &b, &c, &ctx);
        let s = random_invertible(a.nrows(), &mut rng);
        let (a2, b2, c2) = scramble(&a, &b, &c, &s);
        assert_normal_form(
            &run(&a2, &b2, &c2),
            &a2,
            &b2,
            &c2,
            &format!("{ctx}, scrambled"),
        );
    }
}

#[test]
fn appendix_c1_complex_pair() {
    let (a, b) = (1, 2);
    let j = qmat![[a, -b], [b, a]];
    check_paper_choice(
        &j,
        &qmat![[a], [b]],
        &qmat![[b], [-a]],
        &qmat![[b * (a * a + b * b)]],
    );
    check_block_case(&j, 11, "C.1");
}

#[test]
fn appendix_c2_two_distinct_reals() {
    let j = qmat![[3, 0], [0, 0]]; // lambda_2 = 0 is allowed
    check_paper_choice(&j, &qmat![[1], [1]], &qmat![[1], [-1]], &qmat![[3]]);
    check_block_case(&j, 12, "C.2");
}

#[test]
fn appendix_c3_real_eigenvalue_with_2x2_block() {
    let j = qmat![[-2, 1], [0, -2]];
    check_paper_choice(&j, &qmat![[1], [0]], &qmat![[0], [1]], &qmat![[1]]);
    check_block_case(&j, 13, "C.3");
}

#[test]
fn appendix_c4_odd_multiplicity_3x3_block() {
    // eq. 20 with lambda_1 = 2, lambda_2 = -1
    let j = qmat![[2, 1, 0, 0], [0, 2, 1, 0], [0, 0, 2, 0], [0, 0, 0, -1]];
    let z = qmat![[1, 0], [0, 0], [0, 1], [0, 1]];
    let zp = qmat![[0, 0], [1, 0], [0, 1], [0, -1]];
    // unnormalised: Z^T J Z_perp = diag(1, lambda_1 - lambda_2) = diag(1, 3) (with the
    // paper's 1/sqrt(2) normalisation the second entry is (lambda_1 - lambda_2)/2)
    check_paper_choice(&j, &z, &zp, &qmat![[1, 0], [0, 3]]);
    check_block_case(&j, 14, "C.4");
}

#[test]
fn appendix_c5_several_zero_eigenvalues() {
    // even and odd numbers of zero eigenvalues with rank G >= n/2 - p
    let j4 = Matrix::diagonal(Q, &[r(1), r(2), r(0), r(0)]);
    check_block_case(&j4, 15, "C.5 (two zeros)");
    let j6 = Matrix::diagonal(Q, &[r(1), r(2), r(3), r(0), r(0), r(0)]);
    check_block_case(&j6, 16, "C.5 (three zeros)");
    // a nilpotent 3x3 block next to a zero: rank G = 2 = n/2 - p
    let jn = qmat![[0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 0], [0, 0, 0, 0]];
    check_block_case(&jn, 17, "C.5 (nilpotent)");
    // too many zeros: rank G = 1 < 2 and the zero mode is uncontrollable 3 times
    let (a, b, c) = block_system(&Matrix::diagonal(Q, &[r(1), r(0), r(0), r(0)]), 0);
    let res = run(&a, &b, &c);
    assert!(!res.exists);
    assert!(res.reason_text().unwrap().contains("uncontrollable"));
}

// ---------------------------------------------------------------- property test

/// A random mechanical system M q'' + D q' + K q = W u (M symmetric positive definite, W of
/// rank p) in first-order form x = [q; q'].
fn random_mechanical(
    h: usize,
    p: usize,
    rng: &mut Rng,
) -> (Matrix<Q>, Matrix<Q>, Matrix<Q>, Matrix<Q>) {
    let small =
        |rng: &mut Rng, m: usize, n: usize| Matrix::from_fn(Q, m, n, |_, _| r(rng.int(-2, 2)));
    let l = small(rng, h, h);
    let m = &(&l * &l.transpose()) + &Matrix::identity(Q, h);
    let d = small(rng, h, h);
    let k = random_rational(h, h, rng);
    let w = loop {
        let w = small(rng, h, p);
        if w.rank() == p {
            break w;
        }
    };
    let mi = m.inverse().unwrap();
    let zero = Matrix::zeros(Q, h, h);
    let id = Matrix::identity(Q, h);
    let a = Matrix::block(
        Q,
        &[vec![&zero, &id], vec![&(-&(&mi * &k)), &(-&(&mi * &d))]],
    )
    .unwrap();
    let b = Matrix::zeros(Q, h, p).vstack(&(&mi * &w)).unwrap();
    let c = random_rational(2, 2 * h, rng);
    let dd = random_rational(2, p, rng);
    (a, b, c, dd)
}

/// A sparse random similarity: `n` elementary operations with factors +-1, +-2 and a
/// diagonal with entries in {+-1, +-2, +-1/2}, so that n = 12 stays cheap in a debug build.
fn random_similarity(n: usize, rng: &mut Rng) -> Matrix<Q> {
    let d: Vec<Rational> = (0..n)
        .map(|_| {
            let v = [r(1), r(-1), r(2), r(-2), Rational::new(1.into(), 2.into())];
            v[rng.int(0, 4) as usize].clone()
        })
        .collect();
    let mut s = Matrix::diagonal(Q, &d);
    for _ in 0..n {
        let (i, j) = (
            rng.int(0, n as i64 - 1) as usize,
            rng.int(0, n as i64 - 1) as usize,
        );
        if i == j {
            continue;
        }
        let f = r([1, -1, 2, -2][rng.int(0, 3) as usize]);
        for c in 0..n {
            let v = s.get(i, c) + &(&f * s.get(j, c));
            s.set(i, c, v);
        }
    }
    s
}

fn check_random_mechanical(cases: &[(usize, usize)], seed: u64) {
    let mut rng = Rng(seed);
    for &(h, p) in cases {
        let (a, b, c, d) = random_mechanical(h, p, &mut rng);
        let s = random_similarity(2 * h, &mut rng);
        let (a2, b2, c2) = scramble(&a, &b, &c, &s);
        let res = mechanical_normal_form(&a2, &b2, &c2, &d).unwrap();
        let ctx = format!("n = {}, p = {p}, A = {a2}, B = {b2}", 2 * h);
        assert!(res.exists && res.verified, "{ctx}: {:?}", res.reason);
        let f = res.form.as_ref().unwrap();
        assert_eq!(f.feedthrough, d);
        assert!(f.mass.is_identity());
        assert!(
            f.a_tilde.submatrix(0, h, 0, h).is_zero()
                && f.a_tilde.submatrix(0, h, h, 2 * h).is_identity(),
            "{ctx}"
        );
        assert_eq!(&f.a_tilde * &f.t, &f.t * &a2, "{ctx}");
        // same eigenvalues and Markov parameters as the unscrambled mechanical system
        assert_eq!(
            f.a_tilde.charpoly().unwrap(),
            a.charpoly().unwrap(),
            "{ctx}"
        );
        assert_eq!(
            markov(&f.a_tilde, &f.b_tilde, &f.output, 4 * h),
            markov(&a, &b, &c, 4 * h),
            "{ctx}"
        );
    }
}

#[test]
fn random_mechanical_systems_small() {
    let mut cases = vec![];
    for _ in 0..iters(1) {
        for h in 1..=4 {
            for p in 1..=h {
                cases.push((h, p));
            }
        }
    }
    check_random_mechanical(&cases, 2024);
}

#[test]
fn random_mechanical_systems_n10_n12() {
    let cases: Vec<(usize, usize)> = [(5, 2), (6, 1), (6, 3)]
        .into_iter()
        .cycle()
        .take(3 * iters(1))
        .collect();
    check_random_mechanical(&cases, 4048);
}

#[test]
fn descriptor_systems() {
    let mut rng = Rng(77);
    for (h, p) in [(1, 1), (2, 1), (2, 2), (3, 1), (3, 2)] {
        // F x' = A x + B u with F = blkdiag(I, M), A = [[0, I], [-K, -D]], B = [0; W],
        // then F' = P F S, A' = P A S, B' = P B, C' = C S.
        let l = random_rational(h, h, &mut rng);
        let m = &(&l * &l.transpose()) + &Matrix::identity(Q, h);
        let id = Matrix::identity(Q, h);
        let zero = Matrix::zeros(Q, h, h);
        let k = random_rational(h, h, &mut rng);
        let dmp = random_rational(h, h, &mut rng);
        let f = Matrix::block_diag(Q, &[id.clone(), m]);
        let a = Matrix::block(Q, &[vec![&zero, &id], vec![&(-&k), &(-&dmp)]]).unwrap();
        let w = Matrix::from_fn(
            Q,
            h,
            p,
            |i, j| if i == j { r(1) } else { r(i as i64 - j as i64) },
        );
        let b = Matrix::zeros(Q, h, p).vstack(&w).unwrap();
        let c = random_rational(1, 2 * h, &mut rng);
        let pl = random_invertible(2 * h, &mut rng);
        let sr = random_invertible(2 * h, &mut rng);
        let (f2, a2, b2, c2) = (&(&pl * &f) * &sr, &(&pl * &a) * &sr, &pl * &b, &c * &sr);
        let d = Matrix::zeros(Q, 1, p);
        let res = mechanical_normal_form_descriptor(&f2, &a2, &b2, &c2, &d).unwrap();
        assert!(
            res.exists && res.verified,
            "h = {h}, p = {p}: {:?}",
            res.reason_text()
        );
        let form = res.form.as_ref().unwrap();
        // z = (T F) x: A~ (T F) = T A, T B = B~
        let left = form.left.as_ref().unwrap();
        assert_eq!(&(left * &f2), &form.t);
        assert_eq!(&form.a_tilde * &form.t, left * &a2);
        assert_eq!(form.b_tilde, left * &b2);
        // same eigenvalues as the pencil: det(sF - A) ~ charpoly(F^-1 A)
        let fa = f2.solve(&a2).unwrap().unwrap().0;
        assert_eq!(form.a_tilde.charpoly().unwrap(), fa.charpoly().unwrap());
        assert!(res.report().to_json().get("T_rows").is_some());
    }
    // singular F is an error, a non-existing form is not
    let f = qmat![[1, 0], [0, 0]];
    let (a, b, c, d) = (
        qmat![[0, 1], [1, 0]],
        qmat![[0], [1]],
        qmat![[1, 0]],
        qmat![[0]],
    );
    assert!(matches!(
        mechanical_normal_form_descriptor(&f, &a, &b, &c, &d),
        Err(Error::Invalid(_))
    ));
    // F = 2 I, A = I: A B lies in the span of B, rank K = 0 < p
    let two = Matrix::diagonal(Q, &[r(2), r(2)]);
    let res = mechanical_normal_form_descriptor(&two, &Matrix::identity(Q, 2), &b, &c, &d).unwrap();
    assert!(!res.exists && res.reason_text().unwrap().contains("rank(U_B2^T A U_B1)"));
}

// ---------------------------------------------------------------- conditions that fail

fn reason_of(a: &Matrix<Q>, b: &Matrix<Q>) -> (String, bool) {
    let c = Matrix::zeros(Q, 1, a.nrows());
    let res = run(a, b, &c);
    assert!(!res.verified && res.form.is_none());
    let j = res.report().to_json();
    assert_eq!(j["exists"], serde_json::Value::Bool(false));
    assert!(j["T"].is_null());
    (res.reason_text().unwrap_or_default(), res.exists)
}

#[test]
fn failing_conditions_give_reasons() {
    // odd n
    let (why, ok) = reason_of(
        &qmat![[0, 1, 0], [0, 0, 1], [1, 0, 0]],
        &qmat![[0], [0], [1]],
    );
    assert!(!ok && why.contains("odd"), "{why}");
    // p > n/2
    let b3 = qmat![[1, 0, 0], [0, 1, 0], [0, 0, 1], [0, 0, 0]];
    let (why, ok) = reason_of(&Matrix::identity(Q, 4), &b3);
    assert!(!ok && why.contains("p = 3 > n/2 = 2"), "{why}");
    // rank-deficient B: decided for the compressed B1 (B = B1 R), here A B1 = B1
    let (why, ok) = reason_of(
        &Matrix::identity(Q, 4),
        &qmat![[0, 0], [0, 0], [1, 2], [1, 2]],
    );
    assert!(
        !ok && why.contains("rank(U_B2^T A U_B1) = 0 < p = 1"),
        "{why}"
    );
    // rank(U_B2^T A U_B1) < p: A B lies in the span of B
    let a = Matrix::diagonal(Q, &[r(1), r(2), r(3), r(4)]);
    let (why, ok) = reason_of(&a, &unit(4, 3));
    assert!(
        !ok && why.contains("rank(U_B2^T A U_B1) = 0 < p = 1"),
        "{why}"
    );
    // Theorem 2.1's conditions all hold, yet no form exists: two uncontrollable modes at 2
    let a = qmat![[2, 0, 0, 0], [0, 2, 0, 0], [0, 0, 0, 1], [0, 0, -1, 0]];
    let b = unit(4, 3);
    let e = decide_existence(&a, &b);
    assert!(
        e.conditions
            .iter()
            .any(|c| c.name() == "paper_rank_g" && c.holds)
    );
    let (why, ok) = reason_of(&a, &b);
    assert!(
        !ok && why.contains("uncontrollable") && why.contains("x - 2"),
        "{why}"
    );
    // and indeed no member of the eq. 15 family is invertible (det is identically zero)
    let fam = transformation_family(None, &a, &b).unwrap();
    let mut rng = Rng(5);
    for _ in 0..20 {
        let alpha: Vec<i64> = (0..fam.directions.len()).map(|_| rng.int(-9, 9)).collect();
        assert!(Q.is_zero(&fam.member(&alpha).det().unwrap()));
    }
    // the same for p = 0 is covered by A = 2 I_2 (no inputs): 2 eigenvectors > n/2 = 1
    let (why, ok) = reason_of(&Matrix::diagonal(Q, &[r(2), r(2)]), &Matrix::zeros(Q, 2, 0));
    assert!(!ok && why.contains("uncontrollable"), "{why}");
}

#[test]
fn paper_rank_g_condition_is_not_necessary() {
    // G = 0 (rank 0 < n/2 - p = 1), but a normal form exists.
    let a = qmat![[0, 0, 1, 0], [0, 0, 0, 0], [0, 0, 0, 1], [0, 0, 0, 0]];
    let b = unit(4, 3);
    let c = qmat![[1, 1, 1, 1]];
    let res = run(&a, &b, &c);
    assert!(
        res.conditions
            .iter()
            .any(|c| c.name() == "paper_rank_g" && !c.holds && !c.decisive)
    );
    assert_normal_form(&res, &a, &b, &c, "rank G = 0");
}

#[test]
fn no_inputs_and_full_inputs() {
    // p = 0: a cyclic A has a normal form (companion-like), with W empty
    let a = qmat![[0, 1], [-6, 5]];
    let b = Matrix::zeros(Q, 2, 0);
    let c = qmat![[1, 0]];
    let res = run(&a, &b, &c);
    assert!(res.exists && res.verified, "{:?}", res.reason);
    // p = n/2: the normal form is unique (sec. 2.2): for the companion system it is itself
    let a = qmat![[0, 1], [-4, -1]];
    let res = run(&a, &unit(2, 1), &c);
    let f = res.form.unwrap();
    assert!(f.t.is_identity());
    assert_eq!(
        (f.stiffness.to_string(), f.damping.to_string()),
        ("[[4]]".into(), "[[1]]".into())
    );
}

#[test]
fn invalid_shapes_are_errors() {
    let a = Matrix::identity(Q, 4);
    let b = unit(4, 3);
    let c = Matrix::zeros(Q, 1, 4);
    let d = Matrix::zeros(Q, 1, 1);
    let non_square = Matrix::zeros(Q, 3, 4);
    assert!(matches!(
        mechanical_normal_form(&non_square, &b, &c, &d),
        Err(Error::NotSquare { .. })
    ));
    assert!(matches!(
        mechanical_normal_form(&a, &unit(3, 0), &c, &d),
        Err(Error::Shape { .. })
    ));
    assert!(matches!(
        mechanical_normal_form(&a, &b, &Matrix::zeros(Q, 1, 3), &d),
        Err(Error::Shape { .. })
    ));
    assert!(matches!(
        mechanical_normal_form(&a, &b, &c, &Matrix::zeros(Q, 2, 1)),
        Err(Error::Shape { .. })
    ));
    assert!(matches!(
        mechanical_normal_form_descriptor(&Matrix::identity(Q, 3), &a, &b, &c, &d),
        Err(Error::Shape { .. })
    ));
}

/// The decisive condition against the search: systems with a controllable part and an
/// uncontrollable part `c I_u` (geometric multiplicity `u`), scrambled. A normal form must
/// exist iff `u <= n/2 - p`; when it does not, random members of the eq. 15 family are all
/// singular (the determinant polynomial is identically zero).
#[test]
fn uncontrollable_multiplicity_decides() {
    let mut rng = Rng(99);
    for (n, p, u) in [
        (4, 1, 1),
        (4, 1, 2),
        (6, 1, 2),
        (6, 1, 3),
        (6, 2, 1),
        (6, 2, 2),
        (8, 2, 2),
        (8, 2, 3),
    ] {
        let nc = n - u;
        let ac = random_rational(nc, nc, &mut rng);
        let bc = random_rational(nc, p, &mut rng);
        let x = random_rational(nc, u, &mut rng);
        let cu = Matrix::identity(Q, u).scale(&r(rng.int(-3, 3)));
        let a = Matrix::block(Q, &[vec![&ac, &x], vec![&Matrix::zeros(Q, u, nc), &cu]]).unwrap();
        let b = bc.vstack(&Matrix::zeros(Q, u, p)).unwrap();
        let c = random_rational(1, n, &mut rng);
        let (a2, b2, c2) = scramble(&a, &b, &c, &random_similarity(n, &mut rng));
        let res = run(&a2, &b2, &c2);
        let ctx = format!("n = {n}, p = {p}, u = {u}, A = {a2}, B = {b2}");
        assert_eq!(res.exists, u <= n / 2 - p, "{ctx}: {:?}", res.reason);
        if res.exists {
            assert_normal_form(&res, &a2, &b2, &c2, &ctx);
        } else {
            assert!(
                res.reason_text().unwrap().contains("uncontrollable"),
                "{ctx}"
            );
            let fam = transformation_family(None, &a2, &b2).unwrap();
            for _ in 0..10 {
                let alpha: Vec<i64> = (0..fam.directions.len()).map(|_| rng.int(-9, 9)).collect();
                assert!(Q.is_zero(&fam.member(&alpha).det().unwrap()), "{ctx}");
            }
        }
    }
}
