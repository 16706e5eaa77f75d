//! Published examples of the float tools, rebuilt exactly from their sources and asserted as
//! the sources state them.
//!
//! * SLICOT AG08BD documentation example (`examples/AG08BD.dat` / `AG08BD.res` of
//!   SLICOT-Reference): a 9-state descriptor system with 3 inputs and 3 outputs; the `.res`
//!   file lists the Kronecker structure of $A - \lambda E$, of $[A - \lambda E; C]$, of
//!   $[A - \lambda E, B]$ and of the system pencil $[A - \lambda E, B; C, D]$.
//! * SLICOT AB01MD documentation example (single-input controllability staircase):
//!   $A = [[1, 2, 0], [4, -1, 0], [0, 0, 1]]$, $b = [1, 0, 1]^T$, NCONT = 3.
//! * MatrixPencils.jl `test/test_klfapps.jl` (`pkstruct`, `prank`, `peigvals`, `pzeros`,
//!   `isregular`): the 5 x 5 integer pencil $M - \lambda N$ and Beelen's Example 2.2.1
//!   (14 x 16, before the random orthogonal transformations of the test, which do not
//!   change the structure). `pkstruct` reports multiplicity vectors: `rki[i]` right
//!   indices equal to $i - 1$, `lki[i]` left indices equal to $i - 1$, `id[i]` infinite
//!   elementary divisors of size $i$, `nf` finite eigenvalues.

use exactlti::field::Q;
use exactlti::matrix::Matrix;
use exactlti::pencil::{kronecker_structure, pencil_structure};
use exactlti::realization::controllability_structure;

fn m(rows: &[&[i64]]) -> Matrix<Q> {
    Matrix::from_i64_rows(rows)
}

/// (A, E, B, C, D).
type Descriptor = (Matrix<Q>, Matrix<Q>, Matrix<Q>, Matrix<Q>, Matrix<Q>);

/// AG08BD.dat, read as the example program reads it (A, E, B, C, D row by row).
fn ag08bd() -> Descriptor {
    let a = Matrix::identity(Q, 9);
    let mut e = Matrix::zeros(Q, 9, 9);
    let one = exactlti::field::Rational::from_integer(1.into());
    for (i, j) in [(1, 0), (2, 1), (4, 3), (5, 4), (7, 6), (8, 7)] {
        e.set(i, j, one.clone());
    }
    let mut b = Matrix::zeros(Q, 9, 3);
    for (i, j) in [(0, 0), (3, 1), (6, 2)] {
        b.set(i, j, -one.clone());
    }
    let c = m(&[
        &[0, 1, 1, 0, 3, 4, 0, 0, 2],
        &[0, 1, 0, 0, 4, 0, 0, 2, 0],
        &[0, 0, 1, 0, -1, 4, 0, -2, 2],
    ]);
    let d = m(&[&[1, 2, -2], &[0, -1, -2], &[0, 0, 0]]);
    (a, e, b, c, d)
}

#[test]
fn slicot_ag08bd_pencil_a_minus_lambda_e() {
    // "Multiplicities of infinite eigenvalues of A-lambda*E are 3 3 3";
    // "The system has no finite poles"
    let (a, e, ..) = ag08bd();
    let k = kronecker_structure(&a, &e).unwrap();
    assert!(k.verified);
    assert_eq!(k.infinite_divisors, vec![3, 3, 3]);
    assert_eq!(k.finite_order(), 0);
    assert!(k.is_regular());
}

#[test]
fn slicot_ag08bd_observability_pencil() {
    // [A - lambda E; C]: infinite multiplicities 1 3 3, left Kronecker indices 0 1 1,
    // no finite output decoupling zeros
    let (a, e, _, c, _) = ag08bd();
    let ac = a.vstack(&c).unwrap();
    let ez = e.vstack(&Matrix::zeros(Q, 3, 9)).unwrap();
    let k = kronecker_structure(&ac, &ez).unwrap();
    assert!(k.verified);
    assert_eq!(k.infinite_divisors, vec![1, 3, 3]);
    assert_eq!(k.left_indices, vec![0, 1, 1]);
    assert!(k.right_indices.is_empty());
    assert_eq!(k.finite_order(), 0);
}

#[test]
fn slicot_ag08bd_controllability_pencil() {
    // [A - lambda E, B]: infinite multiplicities 1 1 1, right Kronecker indices 2 2 2,
    // no finite input decoupling zeros
    let (a, e, b, ..) = ag08bd();
    let ab = a.hstack(&b).unwrap();
    let ez = e.hstack(&Matrix::zeros(Q, 9, 3)).unwrap();
    let k = kronecker_structure(&ab, &ez).unwrap();
    assert!(k.verified);
    assert_eq!(k.infinite_divisors, vec![1, 1, 1]);
    assert_eq!(k.right_indices, vec![2, 2, 2]);
    assert!(k.left_indices.is_empty());
    assert_eq!(k.finite_order(), 0);
}

#[test]
fn slicot_ag08bd_system_pencil() {
    // [A - lambda E, B; C, D]: one finite zero at 1.0, infinite multiplicities 1 1 1 1 3
    // (one infinite zero of order 2), right indices [2], left indices [1]; normal rank of
    // the transfer matrix 2, i.e. normal rank 9 + 2 of the system pencil
    let (a, e, b, c, d) = ag08bd();
    let s = a
        .hstack(&b)
        .unwrap()
        .vstack(&c.hstack(&d).unwrap())
        .unwrap();
    let ez = e
        .hstack(&Matrix::zeros(Q, 9, 3))
        .unwrap()
        .vstack(&Matrix::zeros(Q, 3, 12))
        .unwrap();
    let ps = pencil_structure(&s, &ez).unwrap();
    assert!(ps.verified);
    let k = &ps.structure;
    assert_eq!(k.infinite_divisors, vec![1, 1, 1, 1, 3]);
    assert_eq!(k.right_indices, vec![2]);
    assert_eq!(k.left_indices, vec![1]);
    assert_eq!(k.normal_rank, 9 + 2);
    // the finite zero: the exact value 1, one block of size 1
    assert_eq!(ps.finite.components.len(), 1);
    let comp = &ps.finite.components[0];
    assert_eq!(comp.factor, exactlti::poly::Poly::<Q>::from_i64s(&[-1, 1]));
    assert_eq!(comp.blocks, vec![1]);
}

#[test]
fn slicot_ab01md_single_input() {
    // "NCONT = 3" (fully controllable): one chain of length 3
    let a = m(&[&[1, 2, 0], &[4, -1, 0], &[0, 0, 1]]);
    let b = m(&[&[1], &[0], &[1]]);
    let c = controllability_structure(&a, &b).unwrap();
    assert!(c.verified);
    assert_eq!((c.order, c.indices.clone()), (3, vec![3]));
    assert_eq!(c.block_dims, vec![1, 1, 1]);
}

/// Expands a MatrixPencils.jl multiplicity vector: `v[i]` copies of `i + offset`.
fn expand(v: &[usize], offset: usize) -> Vec<usize> {
    v.iter()
        .enumerate()
        .flat_map(|(i, &c)| std::iter::repeat_n(i + offset, c))
        .collect()
}

#[test]
fn matrixpencils_pkstruct_5x5() {
    // rki == [1], lki == [1], id == [1], nf == 3; prank == 4; !isregular;
    // peigvals: 1 infinite, 3 finite; pzeros: 3 finite, none infinite
    let mm = m(&[
        &[22, 34, 31, 31, 17],
        &[45, 45, 42, 19, 29],
        &[39, 47, 49, 26, 34],
        &[27, 31, 26, 21, 15],
        &[38, 44, 44, 24, 30],
    ]);
    let nn = m(&[
        &[13, 26, 25, 17, 24],
        &[31, 46, 40, 26, 37],
        &[26, 40, 19, 25, 25],
        &[16, 25, 27, 14, 23],
        &[24, 35, 18, 21, 22],
    ]);
    let ps = pencil_structure(&mm, &nn).unwrap();
    assert!(ps.verified);
    let k = &ps.structure;
    assert_eq!(k.right_indices, expand(&[1], 0));
    assert_eq!(k.left_indices, expand(&[1], 0));
    assert_eq!(k.infinite_divisors, expand(&[1], 1));
    assert_eq!(k.finite_order(), 3);
    assert_eq!(k.normal_rank, 4);
    assert!(!k.is_regular());
    // infinite eigenvalues counted with multiplicity (peigvals), infinite zeros = blocks
    // of size k >= 2 contribute k - 1 (pzeros)
    assert_eq!(k.infinite_order(), 1);
    let inf_zeros: usize = k.infinite_divisors.iter().map(|&d| d - 1).sum();
    assert_eq!(inf_zeros, 0);
}

#[test]
fn matrixpencils_beelen_example_2_2_1() {
    // Test Suite 2 (Example 2.2.1, Beelen): rki == [2, 1, 1], lki == [1, 0, 0, 1],
    // id == [1, 1], nf == 3; prank == 12; peigvals: 3 infinite + 3 finite; pzeros: 1
    // infinite + 3 finite
    let mut mm = Matrix::zeros(Q, 14, 16);
    let i1 = [1, 2, 3, 6, 7, 8, 9, 10, 11, 12, 13, 13, 14];
    let j1 = [4, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 16];
    let aval = [1, 1, 1, 1, 1, 1, 1, 1, 1, 2, 3, 1, 3];
    for ((i, j), v) in i1.iter().zip(j1).zip(aval) {
        mm.set(
            i - 1,
            j - 1,
            exactlti::field::Rational::from_integer(v.into()),
        );
    }
    let mut nn = Matrix::zeros(Q, 14, 16);
    let i1 = [1, 2, 3, 5, 6, 7, 10, 12, 13, 14];
    let j1 = [3, 5, 6, 8, 9, 10, 13, 14, 15, 16];
    for (i, j) in i1.iter().zip(j1) {
        nn.set(
            i - 1,
            j - 1,
            exactlti::field::Rational::from_integer(1.into()),
        );
    }
    let check = |mm: &Matrix<Q>, nn: &Matrix<Q>| {
        let ps = pencil_structure(mm, nn).unwrap();
        assert!(ps.verified);
        let k = &ps.structure;
        assert_eq!(k.right_indices, expand(&[2, 1, 1], 0));
        assert_eq!(k.left_indices, expand(&[1, 0, 0, 1], 0));
        assert_eq!(k.infinite_divisors, expand(&[1, 1], 1));
        assert_eq!(k.finite_order(), 3);
        assert_eq!(k.normal_rank, 12);
        assert_eq!(k.infinite_order(), 3);
        let inf_zeros: usize = k.infinite_divisors.iter().map(|&d| d - 1).sum();
        assert_eq!(inf_zeros, 1);
    };
    check(&mm, &nn);
    // the test scrambles by random orthogonal Q, Z; here by fixed unimodular ones
    let mut q = Matrix::identity(Q, 14);
    let mut z = Matrix::identity(Q, 16);
    let one = exactlti::field::Rational::from_integer(1.into());
    for i in 0..13 {
        q.set(i, i + 1, one.clone());
    }
    for j in 0..15 {
        z.set(j + 1, j, -one.clone());
    }
    check(&(&(&q * &mm) * &z), &(&(&q * &nn) * &z));
}
