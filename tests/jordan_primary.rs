//! The Jordan-method minimal realization written over the base field
//! (`minimal_jordan_primary`), one generic test over Q and Q(p): the realization's own
//! Markov parameters equal C A^k B for k < n + r, its order is the McMillan degree, and the
//! sliding masses (paper sec. 4.1) go 20 -> 16 -> 8 over Q and over Q(m, k).

use crate::common::{Rng, systems, unimodular};
use exactlti::field::{Field, Q};
use exactlti::io::TypedAny;
use exactlti::io::symbolic::{SymbolicOptions, load_symbolic_path};
use exactlti::jordan::primary::Component;
use exactlti::matrix::Matrix;
use exactlti::ratfunc::RatFuncField;
use exactlti::realization::{mcmillan_degree, minimal_jordan_primary, minimal_jordan_qp};
use exactlti::system::StateSpace;
use std::path::Path;

/// Every identity of the result, recomputed here; returns the stages.
fn check<F: Field + 'static>(sys: &StateSpace<F>, comps: Vec<Component<F>>) -> [usize; 3] {
    let r = minimal_jordan_primary(sys, comps).unwrap();
    assert!(r.verified);
    let m = &r.system;
    let order = m.nstates();
    assert_eq!(order, mcmillan_degree(sys));
    assert_eq!(r.stages[2], order);
    let kmax = sys.nstates() + order;
    assert_eq!(m.markov(kmax), sys.markov(kmax));
    assert_eq!(m.d, sys.d);
    // the blocks tile the state space, each a multiple of its factor's degree
    let mut off = 0;
    for b in &r.blocks {
        assert_eq!(b.offset, off);
        let d = r.components[b.component].degree();
        assert_eq!(b.order, d * b.blocks.iter().sum::<usize>());
        off += b.order;
    }
    assert_eq!(off, order);
    r.stages
}

fn components_q(sys: &StateSpace<Q>) -> Vec<Component<Q>> {
    exactlti::jordan::jordan(&sys.a).unwrap().components
}

fn components_qp(sys: &StateSpace<RatFuncField>) -> Vec<Component<RatFuncField>> {
    exactlti::jordan::over_qp::components_qp(&sys.a).unwrap().1
}

#[test]
fn sliding_masses_20_16_8_over_q_and_qp() {
    let sys = systems::sliding_masses();
    assert_eq!(check(&sys, components_q(&sys)), [20, 16, 8]);
    let opts = SymbolicOptions::from_args(Some(""), None).unwrap();
    let l = load_symbolic_path(Path::new("data/sliding-masses-symbolic.json"), &opts).unwrap();
    let TypedAny::RatFunc(t) = &l.system else {
        panic!("expected QQ(k, m)")
    };
    assert_eq!(check(&t.ss, components_qp(&t.ss)), [20, 16, 8]);
    // the public entry point says the same
    let r = minimal_jordan_qp(&t.ss).unwrap();
    assert!(r.verified && r.stages == [20, 16, 8]);
}

/// A = U diag(blocks) U^-1 with U unimodular: a double eigenvalue 2a + 1 in one Jordan
/// block of size 2, a simple eigenvalue a, the roots of x^2 + a (twice, diagonalizable);
/// B, C with zero rows so that modes drop.
fn planted_qp(rng: &mut Rng) -> StateSpace<RatFuncField> {
    let k = RatFuncField::new(&["a"]).unwrap();
    let e = |s: &str| k.parse(s).unwrap();
    let z = || "0";
    let rows: [[&str; 7]; 7] = [
        ["2*a+1", "1", z(), z(), z(), z(), z()],
        [z(), "2*a+1", z(), z(), z(), z(), z()],
        [z(), z(), "a", z(), z(), z(), z()],
        [z(), z(), z(), "0", "-a", z(), z()],
        [z(), z(), z(), "1", "0", z(), z()],
        [z(), z(), z(), z(), z(), "0", "-a"],
        [z(), z(), z(), z(), z(), "1", "0"],
    ];
    let j = Matrix::from_fn(k.clone(), 7, 7, |r, c| e(rows[r][c]));
    let u = unimodular(&k, 7, rng);
    let a = u
        .try_mul(&j)
        .unwrap()
        .try_mul(&u.inverse().unwrap())
        .unwrap();
    let pick = |rng: &mut Rng| match rng.int(0, 3) {
        0 => k.zero(),
        1 => k.var(0),
        v => k.from_i64(v - 2),
    };
    let b0 = Matrix::from_fn(k.clone(), 7, 2, |_, _| pick(rng));
    let c0 = Matrix::from_fn(k.clone(), 2, 7, |_, _| pick(rng));
    let b = u.try_mul(&b0).unwrap();
    let c = c0.try_mul(&u.inverse().unwrap()).unwrap();
    StateSpace::new(a, b, c, Matrix::zeros(k, 2, 2)).unwrap()
}

#[test]
fn planted_systems_over_qp_and_at_a_point() {
    let mut rng = Rng(2311);
    for _ in 0..crate::common::iters(4) {
        let sys = planted_qp(&mut rng);
        let stages = check(&sys, components_qp(&sys));
        assert_eq!(stages[0], 7);
        // the same system at a = 3 over Q: the same orders
        let p = [exactlti::field::Rational::from_integer(3.into())];
        let kf = sys.a.field().clone();
        let at = |m: &Matrix<RatFuncField>| {
            Matrix::from_fn(Q, m.nrows(), m.ncols(), |i, j| {
                kf.eval(m.get(i, j), &p).unwrap()
            })
        };
        let sq = StateSpace::new(at(&sys.a), at(&sys.b), at(&sys.c), at(&sys.d)).unwrap();
        let sq_stages = check(&sq, components_q(&sq));
        assert_eq!(sq_stages[2], stages[2]);
    }
}

/// Every identity of `minimal_jordan_qp` recomputed here: verified, order = McMillan degree,
/// C A^k B equal for k < n + r, D unchanged; returns (stages, restriction blocks).
fn check_qp(sys: &StateSpace<RatFuncField>) -> ([usize; 3], usize) {
    let r = minimal_jordan_qp(sys).unwrap();
    assert!(r.verified);
    let m = &r.system;
    assert_eq!(m.nstates(), mcmillan_degree(sys));
    let kmax = sys.nstates() + m.nstates();
    assert_eq!(m.markov(kmax), sys.markov(kmax));
    assert_eq!(m.d, sys.d);
    let restricted = r.blocks.iter().filter(|b| b.is_restriction()).count();
    for b in r.blocks.iter().filter(|b| b.is_restriction()) {
        assert_eq!(b.order, r.components[b.component].degree());
    }
    (r.stages, restricted)
}

/// The single-track models in 8 symbols (an irreducible quartic chi: the whole system is one
/// simple primary block; > 300 s through chains over E before): minimal of order 4.
#[test]
fn single_track_symbolic_minreal_jordan_is_its_primary_block() {
    for f in [
        "data/scb/single-track-front.json",
        "data/scb/single-track-rear.json",
    ] {
        let opts = SymbolicOptions::from_args(Some(""), None).unwrap();
        let l = load_symbolic_path(Path::new(f), &opts).unwrap();
        let TypedAny::RatFunc(t) = &l.system else {
            panic!("expected QQ(p) for {f}")
        };
        assert_eq!(check_qp(&t.ss), ([4, 4, 4], 1), "{f}");
    }
}

/// A = U diag(a, [[0, -a], [1, 0]], [[0, -2a], [1, 0]]) U^-1 (U unimodular): two simple
/// quadratic factors, each a restriction block of 2 states (ker g(A) smaller than the
/// space), or dropped when B or C misses it.
#[test]
fn simple_quadratic_factors_as_restriction_blocks() {
    let mut rng = Rng(2512);
    let k = RatFuncField::new(&["a"]).unwrap();
    let e = |s: &str| k.parse(s).unwrap();
    let rows: [[&str; 5]; 5] = [
        ["a", "0", "0", "0", "0"],
        ["0", "0", "-a", "0", "0"],
        ["0", "1", "0", "0", "0"],
        ["0", "0", "0", "0", "-2*a"],
        ["0", "0", "0", "1", "0"],
    ];
    let j = Matrix::from_fn(k.clone(), 5, 5, |r, c| e(rows[r][c]));
    for case in 0..crate::common::iters(3) {
        let u = unimodular(&k, 5, &mut rng);
        let ui = u.inverse().unwrap();
        let a = u.try_mul(&j).unwrap().try_mul(&ui).unwrap();
        // case 0: everything excited and observed; else the last pair not excited
        let b0 = Matrix::from_fn(k.clone(), 5, 1, |i, _| {
            if case > 0 && i >= 3 {
                k.zero()
            } else {
                k.one()
            }
        });
        let c0 = Matrix::from_fn(k.clone(), 1, 5, |_, j| k.from_i64(j as i64 + 1));
        let sys = StateSpace::new(
            a,
            u.try_mul(&b0).unwrap(),
            c0.try_mul(&ui).unwrap(),
            Matrix::zeros(k.clone(), 1, 1),
        )
        .unwrap();
        let (stages, restricted) = check_qp(&sys);
        if case == 0 {
            assert_eq!((stages, restricted), ([5, 5, 5], 2));
        } else {
            assert_eq!((stages, restricted), ([5, 3, 3], 1));
        }
    }
}
