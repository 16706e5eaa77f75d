//! Dixon's p-adic solve over Q (`qkernels::modular::dixon`, issue 29): `X = A^{-1} B` for a
//! nonsingular rational `A`, reached by `over_q::solve_q` and by `Matrix::solve` through the
//! field's kernel hooks. Every result is checked by `A X = B` exactly and against the old
//! multi-modular CRT solve (`direct::solve_direct`) or the generic RREF of `[A | B]`.

use exactlti::field::{Q, Rational};
use exactlti::matrix::Matrix;
use exactlti::matrix::over_q as oq;
use exactlti::qkernels::modular::{direct, dixon};
use exactlti::rng::SplitMix64;
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};
use proptest::prelude::*;
use proptest::test_runner::{RngAlgorithm, TestRng, TestRunner};

use crate::common::{matmul_q as matmul, random_rationals as random};

fn qq(n: i64, d: i64) -> Rational {
    Rational::new(n.into(), d.into())
}

/// The particular solution of the generic RREF of `[A | B]` (None: inconsistent).
fn generic_solve(
    m: usize,
    n: usize,
    k: usize,
    a: &[Rational],
    b: &[Rational],
) -> Option<Vec<Rational>> {
    let mut aug = Vec::new();
    for i in 0..m {
        aug.extend_from_slice(&a[i * n..(i + 1) * n]);
        aug.extend_from_slice(&b[i * k..(i + 1) * k]);
    }
    let (r, piv) = Matrix::from_vec(Q, m, n + k, aug).rref_gauss_jordan();
    if piv.last().is_some_and(|&p| p >= n) {
        return None;
    }
    let mut x = vec![Rational::zero(); n * k];
    for (i, &p) in piv.iter().enumerate() {
        x[p * k..(p + 1) * k].clone_from_slice(&r.as_slice()[i * (n + k) + n..(i + 1) * (n + k)]);
    }
    Some(x)
}

/// Checks one nonsingular case every way: Dixon, the CRT solve, `solve_q`, `Matrix::solve`.
fn check_nonsingular(n: usize, k: usize, a: &[Rational], b: &[Rational], ctx: &str) {
    let x = dixon::solve_dixon(n, k, a, b).unwrap_or_else(|| panic!("nonsingular: {ctx}"));
    assert_eq!(matmul(n, n, k, a, &x), b, "A X = B: {ctx}");
    assert_eq!(
        Some(x.clone()),
        direct::solve_direct(n, k, a, b),
        "CRT solve: {ctx}"
    );
    assert_eq!(
        Some(x.clone()),
        oq::solve_q(n, n, k, a, b),
        "solve_q: {ctx}"
    );
    let (x0, null) = Matrix::from_vec(Q, n, n, a.to_vec())
        .solve(&Matrix::from_vec(Q, n, k, b.to_vec()))
        .expect("shapes")
        .expect("consistent");
    assert_eq!(x0.as_slice(), &x[..], "Matrix::solve: {ctx}");
    assert_eq!((null.nrows(), null.ncols()), (n, 0), "null space: {ctx}");
    // canonical fractions and (delta, N) with delta > 0 and X = N / delta
    let (den, nums) = dixon::solve_dixon_int(n, k, a, b).expect("nonsingular");
    assert!(den.is_positive(), "{ctx}");
    for (v, nu) in x.iter().zip(&nums) {
        assert_eq!(
            v,
            &Rational::new(nu.clone(), den.clone()),
            "N / delta: {ctx}"
        );
    }
}

#[test]
fn examples_small_shapes() {
    // 0 x 0 and k = 0
    assert_eq!(dixon::solve_dixon(0, 2, &[], &[]), Some(vec![]));
    assert_eq!(
        dixon::solve_dixon(2, 0, &[qq(1, 2), qq(0, 1), qq(0, 1), qq(3, 1)], &[]),
        Some(vec![])
    );
    // 1 x 1: x = b / a, negative and fractional
    assert_eq!(
        dixon::solve_dixon(1, 1, &[qq(-3, 7)], &[qq(5, 2)]),
        Some(vec![qq(-35, 6)])
    );
    assert_eq!(
        dixon::solve_dixon(1, 2, &[qq(4, 1)], &[qq(-8, 1), qq(0, 1)]),
        Some(vec![qq(-2, 1), qq(0, 1)])
    );
    // 1 x 1 singular, 0 x 0 with k = 0
    assert_eq!(dixon::solve_dixon(1, 1, &[qq(0, 1)], &[qq(1, 1)]), None);
    assert_eq!(dixon::solve_dixon(0, 0, &[], &[]), Some(vec![]));
}

#[test]
fn examples_structured_solutions() {
    let mut g = SplitMix64(29_2026);
    for n in [9, 12, 25] {
        let a = random(&mut g, n, n, 1_000_000, 1_000_000, 0);
        // b = column 0: x = e_1 (the residual is zero after one step)
        let b: Vec<Rational> = (0..n).map(|i| a[i * n].clone()).collect();
        let mut e1 = vec![Rational::zero(); n];
        e1[0] = Rational::one();
        assert_eq!(dixon::solve_dixon(n, 1, &a, &b), Some(e1), "e_1 {n}");
        // b = -A 1: x = -1 everywhere (digits p - 1, never a zero residual)
        let ones = vec![-Rational::one(); n];
        let b = matmul(n, n, 1, &a, &ones);
        assert_eq!(dixon::solve_dixon(n, 1, &a, &b), Some(ones), "-1 {n}");
        // b = 0
        let zero = vec![Rational::zero(); 2 * n];
        assert_eq!(
            dixon::solve_dixon(n, 2, &a, &zero),
            Some(zero.clone()),
            "zero {n}"
        );
        // several right-hand sides, random
        let b = random(&mut g, n, 3, 1_000_000, 1_000_000, 5);
        check_nonsingular(n, 3, &a, &b, &format!("random n {n} k 3"));
    }
}

#[test]
fn examples_huge_entries_and_integers() {
    let mut g = SplitMix64(7);
    let n = 10;
    let big = BigInt::one() << 200u32;
    let a: Vec<Rational> = (0..n * n)
        .map(|t| {
            let num = &big * g.int(-1000, 1000) + g.int(-5, 5);
            let den = (BigInt::one() << 150u32) + g.int(1, 1 << 20);
            if t % 7 == 3 {
                Rational::zero()
            } else {
                Rational::new(num, den)
            }
        })
        .collect();
    let b = random(&mut g, n, 2, 1_000_000_000_000, 1 << 40, 0);
    check_nonsingular(n, 2, &a, &b, "huge entries");
    // integer matrix, integer right-hand side
    let a = random(&mut g, 30, 30, 1_000_000, 1, 0);
    let b = random(&mut g, 30, 1, 1_000_000, 1, 0);
    check_nonsingular(30, 1, &a, &b, "integers 30");
    // an identity-like triangular system with a unit lower part
    let mut t = vec![Rational::zero(); n * n];
    for i in 0..n {
        for j in 0..=i {
            t[i * n + j] = if i == j {
                Rational::one()
            } else {
                qq(g.int(-9, 9), g.int(1, 9))
            };
        }
    }
    let b = random(&mut g, n, 4, 100, 100, 0);
    check_nonsingular(n, 4, &t, &b, "unit triangular");
}

#[test]
fn singular_systems_keep_the_rref_path() {
    let mut g = SplitMix64(31);
    let n = 12;
    let mut a = random(&mut g, n, n, 1_000_000, 1_000_000, 0);
    // last row = row 0 + row 1: rank n - 1
    for j in 0..n {
        a[(n - 1) * n + j] = &a[j] + &a[n + j];
    }
    // consistent right-hand side (in the column space) and an inconsistent one
    let y = random(&mut g, n, 1, 1000, 1000, 0);
    let consistent = matmul(n, n, 1, &a, &y);
    let mut inconsistent = consistent.clone();
    inconsistent[n - 1] += Rational::one();
    for b in [&consistent, &inconsistent] {
        assert_eq!(
            dixon::solve_dixon(n, 1, &a, b),
            None,
            "singular: no Dixon solution"
        );
        assert_eq!(oq::solve_q(n, n, 1, &a, b), generic_solve(n, n, 1, &a, b));
    }
    let x = oq::solve_q(n, n, 1, &a, &consistent).expect("consistent");
    assert_eq!(matmul(n, n, 1, &a, &x), consistent);
    assert_eq!(oq::solve_q(n, n, 1, &a, &inconsistent), None);
    let (_, null) = Matrix::from_vec(Q, n, n, a.clone())
        .solve(&Matrix::from_vec(Q, n, 1, consistent))
        .expect("shapes")
        .expect("consistent");
    assert_eq!(null.ncols(), 1, "rank n - 1: one null vector");
}

#[test]
fn property_dixon_equals_crt_solve_and_solves_exactly() {
    // random nonsingular (or singular: a repeated row) systems, fixed seed
    let strategy = (
        1usize..=18,
        1usize..=4,
        any::<u64>(),
        0usize..4,
        any::<bool>(),
    );
    let config = ProptestConfig::with_cases(40);
    let rng = TestRng::deterministic_rng(RngAlgorithm::ChaCha);
    let mut runner = TestRunner::new_with_rng(config, rng);
    runner
        .run(&strategy, |(n, k, seed, kind, singular)| {
            let mut g = SplitMix64(seed);
            let (pmax, qmax) = [(1_000_000, 1_000_000), (9, 1), (1 << 40, 3), (100, 1 << 30)][kind];
            let mut a = random(&mut g, n, n, pmax, qmax, 6);
            if singular && n >= 2 {
                let r0 = a[..n].to_vec();
                a[(n - 1) * n..].clone_from_slice(&r0);
            }
            let b = random(&mut g, n, k, pmax, qmax, 4);
            let got = dixon::solve_dixon(n, k, &a, &b);
            let old = direct::solve_direct(n, k, &a, &b);
            prop_assert_eq!(&got, &old);
            if let Some(x) = &got {
                prop_assert_eq!(matmul(n, n, k, &a, x), b.clone());
            }
            prop_assert_eq!(oq::solve_q(n, n, k, &a, &b), generic_solve(n, n, k, &a, &b));
            Ok(())
        })
        .unwrap();
}

#[test]
fn invariants_scaling_and_permutation() {
    // X(cA, B) = X(A, B) / c; X(PA, PB) = X(A, B); X(A, B1 + B2) = X(A, B1) + X(A, B2)
    let mut g = SplitMix64(99);
    let (n, k) = (14, 2);
    let a = random(&mut g, n, n, 1_000_000, 1_000_000, 0);
    let b1 = random(&mut g, n, k, 1_000_000, 1_000_000, 0);
    let b2 = random(&mut g, n, k, 1000, 1, 0);
    let x1 = dixon::solve_dixon(n, k, &a, &b1).expect("nonsingular");
    let x2 = dixon::solve_dixon(n, k, &a, &b2).expect("nonsingular");
    let c = qq(-7, 3);
    let ca: Vec<Rational> = a.iter().map(|v| v * &c).collect();
    let xc = dixon::solve_dixon(n, k, &ca, &b1).expect("nonsingular");
    assert_eq!(xc, x1.iter().map(|v| v / &c).collect::<Vec<_>>());
    let perm: Vec<usize> = (0..n).rev().collect();
    let pa: Vec<Rational> = perm
        .iter()
        .flat_map(|&i| a[i * n..(i + 1) * n].to_vec())
        .collect();
    let pb: Vec<Rational> = perm
        .iter()
        .flat_map(|&i| b1[i * k..(i + 1) * k].to_vec())
        .collect();
    assert_eq!(dixon::solve_dixon(n, k, &pa, &pb), Some(x1.clone()));
    let bs: Vec<Rational> = b1.iter().zip(&b2).map(|(u, v)| u + v).collect();
    let xs: Vec<Rational> = x1.iter().zip(&x2).map(|(u, v)| u + v).collect();
    assert_eq!(dixon::solve_dixon(n, k, &a, &bs), Some(xs));
    // the inverse: A X = I solved column by column equals inverse_q
    let id: Vec<Rational> = (0..n * n)
        .map(|t| {
            if t / n == t % n {
                Rational::one()
            } else {
                Rational::zero()
            }
        })
        .collect();
    assert_eq!(dixon::solve_dixon(n, n, &a, &id), oq::inverse_q(n, &a));
}
