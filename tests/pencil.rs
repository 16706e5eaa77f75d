//! Kronecker structure of pencils: planted structures scrambled by unimodular
//! transformations (the structure is known by construction), small textbook cases.

use crate::common::pencils::{PencilRng, Planted};
use exactlti::field::Q;
use exactlti::matrix::Matrix;
use exactlti::pencil::{kronecker_structure, pencil_structure};
use exactlti::qmat;

/// Finite eigenvalue block sizes by eigenvalue minpoly, sorted.
fn finite_blocks(p: &Planted) -> Vec<(String, usize)> {
    let mut v: Vec<(String, usize)> = p
        .jordan
        .iter()
        .map(|&(l, k)| {
            (
                exactlti::poly::Poly::<Q>::from_i64s(&[-l, 1]).to_string(),
                k,
            )
        })
        .collect();
    for c in &p.companions {
        let mut cs = c.clone();
        cs.push(1);
        v.push((exactlti::poly::Poly::<Q>::from_i64s(&cs).to_string(), 0));
    }
    v.sort();
    v
}

fn check_planted(p: &Planted, seed: u64) {
    let (a, e) = p.scrambled(seed, 4 * (p.eps.len() + p.eta.len() + 8));
    let ps = pencil_structure(&a, &e).unwrap();
    let k = &ps.structure;
    let ctx = format!("planted {p:?} seed {seed}\nA = {a}\nE = {e}");
    assert_eq!(k.right_indices, p.eps, "{ctx}");
    assert_eq!(k.left_indices, p.eta, "{ctx}");
    assert_eq!(k.infinite_divisors, p.inf, "{ctx}");
    assert!(ps.verified, "{ctx}");
    // finite part: the Jordan blocks per eigenvalue (companions: one block of each root)
    let mut got: Vec<(String, usize)> = Vec::new();
    for comp in &ps.finite.components {
        for &b in &comp.blocks {
            let size = if comp.factor.deg() == 1 { b } else { 0 };
            got.push((comp.factor.to_string(), size));
        }
    }
    got.sort();
    let mut want = finite_blocks(p);
    // several companion blocks with the same polynomial give one component, one block each
    want.sort();
    assert_eq!(got, want, "{ctx}");
}

#[test]
fn pencil_planted_properties() {
    let mut rng = PencilRng(20261122);
    for it in 0..crate::common::iters(12) {
        let p = Planted::random(&mut rng, 4 + it % 10);
        check_planted(&p, 1000 + it as u64);
    }
}

#[test]
fn pencil_planted_chosen() {
    let p = Planted {
        eps: vec![0, 1, 3],
        eta: vec![0, 2],
        inf: vec![1, 1, 3],
        jordan: vec![(2, 2), (2, 1), (-1, 3)],
        companions: vec![vec![1, 0], vec![-2, 0]],
    };
    check_planted(&p, 7);
}

#[test]
fn pencil_examples() {
    // 0 x 0, 0 x n, n x 0
    let k = kronecker_structure(&Matrix::zeros(Q, 0, 0), &Matrix::zeros(Q, 0, 0)).unwrap();
    assert!(k.verified && k.is_regular());
    let k = kronecker_structure(&Matrix::zeros(Q, 0, 3), &Matrix::zeros(Q, 0, 3)).unwrap();
    assert_eq!(k.right_indices, [0, 0, 0]);
    let k = kronecker_structure(&Matrix::zeros(Q, 2, 0), &Matrix::zeros(Q, 2, 0)).unwrap();
    assert_eq!(k.left_indices, [0, 0]);
    // a regular pencil: E x' = A x with a double finite eigenvalue 1 and a non-dynamic mode
    let ps = pencil_structure(
        &qmat![[1, 1, 0], [0, 1, 0], [0, 0, 1]],
        &qmat![[1, 0, 0], [0, 1, 0], [0, 0, 0]],
    )
    .unwrap();
    assert!(ps.verified && ps.structure.is_regular());
    assert_eq!(ps.structure.infinite_divisors, [1]);
    assert_eq!(ps.finite.eigenvalues[0].blocks, [2]);
    // the zero 2 x 2 pencil: two L_0 and two L_0^T
    let k = kronecker_structure(&Matrix::zeros(Q, 2, 2), &Matrix::zeros(Q, 2, 2)).unwrap();
    assert_eq!(
        (k.right_indices, k.left_indices, k.normal_rank),
        (vec![0, 0], vec![0, 0], 0)
    );
    // shape mismatch is an error
    assert!(kronecker_structure(&Matrix::zeros(Q, 2, 2), &Matrix::zeros(Q, 2, 3)).is_err());
}
