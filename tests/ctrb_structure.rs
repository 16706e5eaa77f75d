//! Controllability / observability structure: planted Brunovsky structures with an
//! uncontrollable part scrambled by unimodular similarities, a naive Krylov-rank oracle,
//! and descriptor (finite / infinite) counts.

use crate::common::pencils::{PencilRng, planted_ctrb};
use exactlti::field::Q;
use exactlti::matrix::Matrix;
use exactlti::qmat;
use exactlti::realization::{
    controllability_matrix, controllability_structure, descriptor_controllability,
    observability_structure,
};
use exactlti::system::Descriptor;

/// Naive oracle: ranks of [B, AB, .., A^(k-1) B].
fn krylov_ranks(a: &Matrix<Q>, b: &Matrix<Q>) -> Vec<usize> {
    let n = a.nrows();
    let mut out = Vec::new();
    let mut blk = b.clone();
    let mut k = b.clone();
    for i in 0..n {
        if i > 0 {
            blk = a * &blk;
            k = k.hstack(&blk).unwrap();
        }
        out.push(k.rank());
    }
    out
}

#[test]
fn ctrb_planted_properties() {
    let mut rng = PencilRng(99);
    for it in 0..crate::common::iters(10) {
        let m = rng.int(1, 3) as usize;
        let mut kappa: Vec<usize> = (0..m).map(|_| rng.int(0, 4) as usize).collect();
        let nu = rng.int(0, 3) as usize;
        let a_u = Matrix::from_fn(Q, nu, nu, |i, j| {
            exactlti::field::Rational::from_integer(if j >= i { rng.int(-2, 2) } else { 0 }.into())
        });
        let (a, b) = planted_ctrb(&kappa, &a_u, 500 + it as u64, 12);
        let c = controllability_structure(&a, &b).unwrap();
        let ctx = format!("kappa {kappa:?}\nA = {a}\nB = {b}");
        assert!(c.verified, "{ctx}");
        kappa.sort_unstable_by(|x, y| y.cmp(x));
        assert_eq!(c.indices, kappa, "{ctx}");
        assert_eq!(c.order, kappa.iter().sum::<usize>(), "{ctx}");
        assert_eq!(c.controllability_index(), kappa[0]);
        assert_eq!(
            c.uncontrollable.charpoly().unwrap(),
            a_u.charpoly().unwrap(),
            "{ctx}"
        );
        // oracle: increments of the Krylov ranks are the staircase block dimensions
        let r = krylov_ranks(&a, &b);
        let mut inc: Vec<usize> = Vec::new();
        let mut prev = 0;
        for &x in &r {
            if x > prev {
                inc.push(x - prev);
            }
            prev = x;
        }
        assert_eq!(c.block_dims, inc, "{ctx}");
        assert_eq!(controllability_matrix(&a, &b).rank(), c.order);
        // duality
        let o = observability_structure(&a.transpose(), &b.transpose()).unwrap();
        assert_eq!(o.indices, c.indices);
    }
}

#[test]
fn ctrb_examples() {
    // no inputs: nothing controllable, every eigenvalue uncontrollable
    let c = controllability_structure(&qmat![[1, 2], [0, 3]], &Matrix::zeros(Q, 2, 0)).unwrap();
    assert_eq!((c.order, c.block_dims.len()), (0, 0));
    assert_eq!(c.uncontrollable, qmat![[1, 2], [0, 3]]);
    // two equal inputs: indices [2, 0], staircase [1, 1]
    let c = controllability_structure(&qmat![[0, 1], [0, 0]], &qmat![[0, 0], [1, 1]]).unwrap();
    assert_eq!(
        (c.indices.clone(), c.block_dims.clone()),
        (vec![2, 0], vec![1, 1])
    );
    assert!(c.verified);
    // 0 x 0
    let c = controllability_structure(&Matrix::zeros(Q, 0, 0), &Matrix::zeros(Q, 0, 1)).unwrap();
    assert_eq!((c.order, c.indices.clone()), (0, vec![0]));
}

#[test]
fn ctrb_descriptor_counts() {
    // finite mode -1 driven, an infinite chain of length 2 driven only at its head and a
    // non-dynamic mode not driven: finite 1/1, infinite 2 of 3 controllable
    let e = qmat![[1, 0, 0, 0], [0, 0, 1, 0], [0, 0, 0, 0], [0, 0, 0, 0]];
    let a = qmat![[-1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]];
    let b = qmat![[1], [0], [1], [0]];
    let c = qmat![[1, 1, 0, 1]];
    let sys = Descriptor::new(e, a, b, c, qmat![[0]]).unwrap();
    let dc = descriptor_controllability(&sys, false).unwrap();
    assert!(dc.verified());
    assert_eq!((dc.finite_order, dc.infinite_order), (1, 3));
    assert_eq!((dc.finite.order, dc.infinite.order), (1, 2));
    assert_eq!(dc.uncontrollable_infinite(), 1);
    assert_eq!(dc.controllable_order(), 3);
    let dob = descriptor_controllability(&sys, true).unwrap();
    // the output sees x2 + x4 only: rank [E; C] = 3 < 4, so one infinite mode is
    // unobservable (x2 and the non-dynamic x4 are seen only in their sum)
    assert_eq!((dob.finite.order, dob.infinite.order), (1, 2));
    let rank_ec = sys.e.vstack(&sys.c).unwrap().rank();
    assert_eq!(rank_ec, 3);
}
