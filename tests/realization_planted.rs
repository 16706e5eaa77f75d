//! Planted non-minimal systems (tests/common/systems.rs `planted`): the exact McMillan degree
//! is known by construction, and every exact minimal-realization method must return it,
//! verified. Sizes stay at n <= 20 so the debug build runs them quickly; the benchmark
//! (`cargo bench --bench realization`) runs n up to 100.
use crate::common;

use common::systems::{Planted, planted, planted_scaled};
use exactlti::field::{Q, Rational};
use exactlti::float::{Tol, minreal as float_minreal, to_dmatrix};
use exactlti::matrix::Matrix;
use exactlti::realization::{
    MinrealMethod, controllability_matrix, kalman_decomposition, mcmillan_degree, minimal,
    observability_matrix,
};

const METHODS: [MinrealMethod; 3] = [
    MinrealMethod::Kalman,
    MinrealMethod::Rosenbrock,
    MinrealMethod::HoKalman,
];

/// Construction invariants: T T^-1 = I with det T = +-1, the transfer matrix is the core's,
/// and the ranks of the Krylov matrices are the planted part sizes.
fn check_construction(pl: &Planted) {
    let n = pl.sys.nstates();
    assert_eq!(pl.parts.iter().sum::<usize>(), n);
    assert!((&pl.t * &pl.tinv).is_identity());
    let det = pl.t.det().unwrap();
    assert!(det == Rational::from_integer(1.into()) || det == Rational::from_integer((-1).into()));
    // G(s) = C1 (sI - A11)^-1 B1: equal Markov parameters up to n + r suffice.
    assert!(pl.sys.same_markov(&pl.core, n + pl.order));
    let [co, cno, nco, ncno] = pl.parts;
    assert_eq!(
        controllability_matrix(&pl.sys.a, &pl.sys.b).rank(),
        co + cno
    );
    assert_eq!(observability_matrix(&pl.sys.a, &pl.sys.c).rank(), co + nco);
    let _ = ncno;
    // entries stay exactly representable in binary floating point (denominators 1 or 2)
    let two = num_bigint::BigInt::from(2);
    for m in [&pl.sys.a, &pl.sys.b, &pl.sys.c] {
        for x in m.as_slice() {
            assert!(x.denom() == &num_bigint::BigInt::from(1) || x.denom() == &two);
        }
    }
}

#[test]
fn planted_examples() {
    // n = 10: parts (5, 2, 2, 1)
    let pl = planted(10, 1);
    assert_eq!(pl.parts, [5, 2, 2, 1]);
    assert_eq!(pl.order, 5);
    check_construction(&pl);
    assert_eq!(mcmillan_degree(&pl.sys), 5);
    let kd = kalman_decomposition(&pl.sys).unwrap();
    // dims in the order (c-not-o, co, not-c-not-o, not-c-o)
    assert_eq!(kd.dims, [2, 5, 1, 2]);
    for m in METHODS {
        let r = minimal(&pl.sys, m).unwrap();
        assert_eq!(r.order, 5, "{m:?}");
        assert!(r.verified, "{m:?}");
        assert!(r.system.same_markov(&pl.core, 10));
    }
}

#[test]
fn planted_every_method_finds_the_true_order() {
    for (n, seeds) in [(6usize, 0..4u64), (12, 10..11), (20, 20..21)] {
        for seed in seeds {
            let pl = planted(n, seed);
            check_construction(&pl);
            assert_eq!(mcmillan_degree(&pl.sys), pl.order, "n {n} seed {seed}");
            for m in METHODS {
                let r = minimal(&pl.sys, m).unwrap();
                assert_eq!(r.order, pl.order, "n {n} seed {seed} {m:?}");
                assert!(r.verified, "n {n} seed {seed} {m:?}");
                assert_eq!(r.original_order, n);
            }
        }
    }
}

#[test]
fn stiff_planted_every_method_finds_the_true_order() {
    // Hidden modes 16 times larger than the core: the exact order does not move.
    for (n, seed) in [(8usize, 1u64), (14, 2)] {
        let pl = planted_scaled(n, seed, 16);
        check_construction(&pl);
        for m in METHODS {
            let r = minimal(&pl.sys, m).unwrap();
            assert_eq!(r.order, pl.order, "n {n} seed {seed} {m:?}");
            assert!(r.verified, "n {n} seed {seed} {m:?}");
        }
    }
    // scale 1 is the plain family
    assert_eq!(planted_scaled(8, 4, 1).sys.a, planted(8, 4).sys.a);
}

#[test]
fn planted_float_image_is_exact() {
    // The f64 image of the planted system is the same system (every entry is a dyadic
    // rational of moderate size), so a float tool is judged on the very matrices the exact
    // path saw; on small cases the float staircase agrees with the exact order.
    let pl = planted(10, 3);
    let back = |m: &Matrix<Q>| {
        let f = to_dmatrix(m).unwrap();
        Matrix::from_fn(Q, m.nrows(), m.ncols(), |i, j| {
            Rational::from_float(f[(i, j)]).unwrap()
        })
    };
    assert_eq!(back(&pl.sys.a), pl.sys.a);
    assert_eq!(back(&pl.sys.b), pl.sys.b);
    assert_eq!(back(&pl.sys.c), pl.sys.c);
    let f = float_minreal(
        &to_dmatrix(&pl.sys.a).unwrap(),
        &to_dmatrix(&pl.sys.b).unwrap(),
        &to_dmatrix(&pl.sys.c).unwrap(),
        &to_dmatrix(&pl.sys.d).unwrap(),
        &Tol::default(),
    )
    .unwrap();
    assert_eq!(f.order, pl.order);
}

#[test]
fn planted_is_deterministic_and_seed_dependent() {
    let a = planted(8, 7);
    let b = planted(8, 7);
    let c = planted(8, 8);
    assert_eq!(a.sys.a, b.sys.a);
    assert_ne!(a.sys.a, c.sys.a);
}
