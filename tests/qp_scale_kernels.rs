//! The Q(p) kernels added for scale (issue 25), as identities (speed lives in
//! `benches/qp_matrix.rs` and `scripts/anchors/qp_matrix.py`):
//! - inverse by adjugate interpolation: $A A^{-1} = I$ and equal to Gauss–Jordan on
//!   $[A, I]$ (random, block-split and singular matrices);
//! - the product with one reduction per entry equals the entrywise sum of products;
//! - the Krylov matrix of the n-mass chain (n = 2..5): pivots $0..2n-1$, certified by the
//!   parameter factors $k$, $m$ of its determinant $\pm k^{n(n-1)} / m^{n(n+1)}$;
//! - a pivot minor without candidate factors (7 x 7, linear in 10 parameters) is recorded
//!   as one unfactored condition, equal to the determinant's numerator;
//! - diag(p0..p{n-1}): Rosenbrock and Ho–Kalman keep the Markov parameters; Rosenbrock up
//!   to n = 7 (its Krylov matrix is a Vandermonde matrix; the staircase's controllable part
//!   is read off the Krylov RREF / characteristic polynomial, never through $T^{-1}$);
//! - Ho–Kalman from the extended Hankel matrix's RREF (no one-sided inverses) up to n = 7;
//! - the inverse-free Rosenbrock and Ho–Kalman results equal those of the recorded path
//!   (`--steps`, which still forms $T^{-1}$, $L^+$, $R^+$) on planted MIMO and SISO systems;
//! - the controllable part equals the last k states of $T^{-1}(A, B, C)T$ for the
//!   staircase's $T$ (planted non-minimal MIMO systems over Q, random systems over Q(a, b)).

use crate::common::systems::diag_qp;
use crate::qp_scale::entry;
use exactlti::error::Error;
use exactlti::field::Field;
use exactlti::matrix::Matrix;
use exactlti::ratfunc::RatFuncField;
use exactlti::realization::{MinrealMethod, minimal};
use exactlti::realization::{controllability_matrix, controllable_part, controllable_staircase};
use exactlti::rng::SplitMix64;
use exactlti::system::StateSpace;

/// The oracle: Gauss–Jordan on $[A, I]$ (no kernel).
fn gauss_jordan_inverse(a: &Matrix<RatFuncField>) -> Option<Matrix<RatFuncField>> {
    let n = a.nrows();
    let aug = a.hstack(&Matrix::identity(a.field().clone(), n)).unwrap();
    let (r, piv) = aug.rref_gauss_jordan();
    (piv.len() == n && piv[n - 1] == n - 1).then(|| r.submatrix(0, n, n, 2 * n))
}

/// A random matrix; `singular`: the last row is the sum of the first two; `blocks`: two
/// square blocks on the diagonal, rows and columns permuted.
fn random_square(
    k: &RatFuncField,
    rng: &mut SplitMix64,
    n: usize,
    singular: bool,
    blocks: bool,
) -> Matrix<RatFuncField> {
    let h = n / 2;
    let mut a = Matrix::from_fn(k.clone(), n, n, |i, j| {
        if blocks && ((i < h) != (j < h)) {
            k.zero()
        } else {
            entry(k, rng)
        }
    });
    if singular {
        for j in 0..n {
            let x = k.add(a.get(0, j), a.get(1, j));
            a.set(n - 1, j, x);
        }
    }
    if blocks {
        let p: Vec<usize> = (0..n).map(|i| (i * 3 + 1) % n).collect();
        let q: Vec<usize> = (0..n).rev().collect();
        a = Matrix::from_fn(k.clone(), n, n, |i, j| a.get(p[i], q[j]).clone());
    }
    a
}

#[test]
fn inverse_kernel_equals_gauss_jordan() {
    let k = RatFuncField::new(&["a", "b", "c"]).unwrap();
    let mut rng = SplitMix64(25);
    for case in 0..16 {
        let n = rng.int(2, 5) as usize;
        let singular = case % 4 == 3 && n >= 3;
        let blocks = case % 3 == 1 && n >= 2 && !singular;
        let a = random_square(&k, &mut rng, n, singular, blocks);
        let oracle = gauss_jordan_inverse(&a);
        match a.inverse() {
            Ok(inv) => {
                assert_eq!(
                    &a * &inv,
                    Matrix::identity(k.clone(), n),
                    "A A^-1, case {case}"
                );
                assert_eq!(Some(inv), oracle, "case {case}");
            }
            Err(Error::Singular) => assert!(oracle.is_none(), "case {case}"),
            Err(e) => panic!("case {case}: {e}"),
        }
        if singular {
            assert!(oracle.is_none(), "case {case} is singular");
        }
    }
}

#[test]
fn product_kernel_equals_the_entrywise_sum() {
    let k = RatFuncField::new(&["a", "b"]).unwrap();
    let mut rng = SplitMix64(7);
    for case in 0..12 {
        let (m, l, n) = (
            rng.int(1, 4) as usize,
            rng.int(1, 5) as usize,
            rng.int(1, 4) as usize,
        );
        let mut random = |r, c| {
            Matrix::from_fn(k.clone(), r, c, |_, _| {
                if rng.int(0, 4) == 0 {
                    k.zero()
                } else {
                    entry(&k, &mut rng)
                }
            })
        };
        let (x, y) = (random(m, l), random(l, n));
        let got = &x * &y;
        for i in 0..m {
            for j in 0..n {
                let want = (0..l).fold(k.zero(), |acc, t| {
                    k.add(&acc, &k.mul(x.get(i, t), y.get(t, j)))
                });
                assert_eq!(got.get(i, j), &want, "case {case}, entry {i},{j}");
            }
        }
    }
}

#[test]
fn chain_krylov_pivots_are_certified_by_parameter_factors() {
    for n in 2..=5 {
        let s = crate::common::systems::chain_qp(n);
        let k = s.a.field().clone();
        k.clear_conditions();
        let kry = controllability_matrix(&s.a, &s.b);
        assert_eq!(kry.pivots(), (0..2 * n).collect::<Vec<_>>(), "n = {n}");
        let conds = k.conditions_strings().unwrap();
        assert!(
            conds.iter().all(|c| c == "k" || c == "m") && conds.contains(&"k".to_string()),
            "n = {n}: {conds:?}"
        );
        let want = k
            .parse(&format!("k^{}/m^{}", n * (n - 1), n * (n + 1)))
            .unwrap();
        let det = kry.det().unwrap();
        assert!(det == want || det == k.neg(&want), "n = {n}: {det:?}");
    }
}

#[test]
fn an_irreducible_pivot_minor_is_recorded_unfactored() {
    let names: Vec<String> = (0..10).map(|i| format!("p{i}")).collect();
    let k = RatFuncField::new(&names).unwrap();
    let mut rng = SplitMix64(11);
    let a = Matrix::from_fn(k.clone(), 7, 7, |_, _| {
        let mut s = format!("{}", rng.int(-5, 5));
        for v in &names {
            s.push_str(&format!(" + {}*{v}", rng.int(-5, 5)));
        }
        k.parse(&s).unwrap()
    });
    k.clear_conditions();
    assert_eq!(a.rank(), 7);
    let conds = k.conditions().unwrap();
    assert_eq!(conds.len(), 1, "one unfactored condition");
    let det = a.det().unwrap().num().primitive_part();
    assert!(
        conds[0] == det || conds[0] == det.neg(),
        "the condition is det A"
    );
}

/// diag(p0..p(n-1)) by Rosenbrock and by Ho–Kalman: the whole system (order n), verified,
/// the Markov parameters kept.
fn diag_keeps_the_markov_parameters(n: usize) {
    let s = diag_qp(n);
    for method in [MinrealMethod::Rosenbrock, MinrealMethod::HoKalman] {
        let r = minimal(&s, method).unwrap();
        assert_eq!(r.order, n, "n = {n}, {method:?}");
        assert!(r.verified, "n = {n}, {method:?}");
        assert_eq!(s.markov(2 * n + 1), r.system.markov(2 * n + 1), "n = {n}");
    }
}

#[test]
fn diag_rosenbrock_and_ho_kalman_keep_the_markov_parameters() {
    for n in 2..=4 {
        diag_keeps_the_markov_parameters(n);
    }
}

/// The regression of issue 25: diag(p0..p6) by Rosenbrock went through $T^{-1}$ of the
/// Vandermonde Krylov matrix (minutes, gigabytes at n = 10). The minimal realization is the
/// whole system and keeps the Markov parameters.
#[test]
fn diag_rosenbrock_without_the_vandermonde_inverse() {
    for n in [5, 7] {
        diag_keeps_the_markov_parameters(n);
    }
}

#[test]
fn inverse_free_paths_equal_the_recorded_paths() {
    use exactlti::field::Q;
    use exactlti::jordan::derivation::{Method, Recorder};
    use exactlti::realization::{minimal_ho_kalman_recorded, minimal_rosenbrock_recorded};
    for seed in 0..8 {
        let p = crate::common::systems::planted(4 + seed as usize % 4, seed);
        let siso = StateSpace::new(
            p.sys.a.clone(),
            p.sys.b.select_cols(&[1]),
            p.sys.c.select_rows(&[0]),
            p.sys.d.submatrix(0, 1, 1, 2),
        )
        .unwrap();
        for (s, tag) in [(&p.sys, "mimo"), (&siso, "siso")] {
            let mut rec = Recorder::new(Method::Rosenbrock, Q);
            let old = minimal_rosenbrock_recorded(s, Some(&mut rec)).unwrap();
            let new = minimal(s, MinrealMethod::Rosenbrock).unwrap();
            assert_eq!(new.system, old.system, "rosenbrock {tag}, seed {seed}");
            let mut rec = Recorder::new(Method::HoKalman, Q);
            let old = minimal_ho_kalman_recorded(s, Some(&mut rec)).unwrap();
            let new = minimal(s, MinrealMethod::HoKalman).unwrap();
            assert_eq!(new.system, old.system, "ho-kalman {tag}, seed {seed}");
            assert!(new.verified, "{tag}, seed {seed}");
        }
    }
}

/// `controllable_part` = the last k states of `sys.transform(T)`, T from the staircase.
fn assert_part_is_the_staircase_part<K: exactlti::field::Field>(s: &StateSpace<K>, tag: &str) {
    let n = s.nstates();
    let (t, k) = controllable_staircase(&s.a, &s.b).unwrap();
    let want = s
        .transform(&t)
        .unwrap()
        .select_states(&(n - k..n).collect::<Vec<_>>());
    let (got, kk) = controllable_part(s).unwrap();
    assert_eq!(kk, k, "{tag}");
    assert_eq!(got.a, want.a, "{tag}: A22");
    assert_eq!(got.b, want.b, "{tag}: B2");
    assert_eq!(got.c, want.c, "{tag}: C2");
    assert_eq!(got.d, want.d, "{tag}: D");
}

#[test]
fn controllable_part_equals_the_transformed_staircase() {
    for seed in 0..12 {
        let n = 3 + (seed as usize % 6);
        let p = crate::common::systems::planted(n, seed);
        assert_part_is_the_staircase_part(&p.sys, &format!("planted n = {n}, seed {seed}"));
        assert_part_is_the_staircase_part(&p.sys.dual(), &format!("dual, seed {seed}"));
        // one input (the Cayley-Hamilton branch when controllable)
        let one = StateSpace::new(
            p.sys.a.clone(),
            p.sys.b.select_cols(&[0]),
            p.sys.c.clone(),
            p.sys.d.select_cols(&[0]),
        )
        .unwrap();
        assert_part_is_the_staircase_part(&one, &format!("one input, seed {seed}"));
    }
    let k = RatFuncField::new(&["a", "b"]).unwrap();
    let mut rng = SplitMix64(31);
    for case in 0..6 {
        let (n, m) = (rng.int(2, 4) as usize, rng.int(1, 2) as usize);
        let mut random = |r, c| {
            Matrix::from_fn(k.clone(), r, c, |_, _| {
                if rng.int(0, 2) == 0 {
                    k.zero()
                } else {
                    entry(&k, &mut rng)
                }
            })
        };
        let (a, b, c) = (random(n, n), random(n, m), random(1, n));
        let s = StateSpace::new_strictly_proper(a, b, c).unwrap();
        assert_part_is_the_staircase_part(&s, &format!("Q(a, b) case {case}"));
    }
}
