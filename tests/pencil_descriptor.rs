//! Descriptor systems: minimal and irreducible descriptor realizations (improper systems
//! included), the bicycle of the minimal-realizations paper (sec. 4.2) through `pencil` and
//! `minreal --descriptor`, and textbook improper examples.
use exactlti::field::Q;
use exactlti::matrix::Matrix;
use exactlti::pencil::pencil_structure;
use exactlti::qmat;
use exactlti::realization::{minimal_descriptor, same_transfer, weierstrass_split};
use exactlti::system::Descriptor;

use crate::bicycle::bicycle_descriptor;

#[test]
fn bicycle_pencil_and_minimal_descriptor() {
    for v in ["2", "8"] {
        let desc = bicycle_descriptor(v);
        // regular 7x7 pencil: 6 finite eigenvalues and one non-dynamic mode (the input state)
        let ps = pencil_structure(&desc.a, &desc.e).unwrap();
        let k = &ps.structure;
        assert!(ps.verified && k.is_regular(), "v = {v}");
        assert_eq!(k.infinite_divisors, [1]);
        assert_eq!(k.finite_order(), 6);
        assert!(k.right_indices.is_empty() && k.left_indices.is_empty());
        // 7 -> 4, proper, irreducible 4 + the non-dynamic input state's contribution
        let m = minimal_descriptor(&desc).unwrap();
        assert!(m.verified, "v = {v}");
        assert_eq!(
            (m.order, m.finite_order, m.infinite_order),
            (4, 4, 0),
            "v = {v}"
        );
        assert_eq!(m.polynomial_degree, 0);
        assert_eq!(m.irreducible_order, 4);
        assert!(same_transfer(&desc, &m.system));
    }
}

fn desc(e: Matrix<Q>, a: Matrix<Q>, b: Matrix<Q>, c: Matrix<Q>, d: Matrix<Q>) -> Descriptor<Q> {
    Descriptor::new(e, a, b, c, d).unwrap()
}

#[test]
fn improper_examples() {
    // G(s) = s: E = [[0, 1], [0, 0]], A = I; least order 2 (one pole at infinity of order 1)
    let s = desc(
        qmat![[0, 1], [0, 0]],
        qmat![[1, 0], [0, 1]],
        qmat![[0], [-1]],
        qmat![[1, 0]],
        qmat![[0]],
    );
    let m = minimal_descriptor(&s).unwrap();
    assert!(m.verified);
    assert_eq!((m.order, m.polynomial_degree), (2, 1));
    let split = weierstrass_split(&s).unwrap();
    assert_eq!(split.polynomial_part()[1], qmat![[1]]);
    // the same with a redundant non-dynamic mode and an unobservable finite mode: 4 -> 2
    let s2 = desc(
        qmat![[0, 1, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, 1]],
        qmat![[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, -3]],
        qmat![[0], [-1], [1], [1]],
        qmat![[1, 0, 1, 0]],
        qmat![[0]],
    );
    let m2 = minimal_descriptor(&s2).unwrap();
    assert!(m2.verified);
    assert_eq!(m2.order, 2);
    // G = s - 1: the non-dynamic mode is not controllable at infinity beside the chain
    // (rank [E, B] = 3 < 4), so the irreducible order is 2 as well
    assert_eq!(m2.irreducible_order, 2);
    assert!(!same_transfer(&s, &m2.system));
    assert_eq!(m2.system.d, qmat![[-1]]);
    // a lone non-dynamic mode, G = -1: irreducible keeps it (order 1), minimal drops it
    let s1 = desc(qmat![[0]], qmat![[1]], qmat![[1]], qmat![[1]], qmat![[0]]);
    let m1 = minimal_descriptor(&s1).unwrap();
    assert!(m1.verified);
    assert_eq!((m1.order, m1.irreducible_order), (0, 1));
    assert_eq!(m1.system.d, qmat![[-1]]);
    // G(s) = s^2 + 1/(s + 1): orders 3 (infinite) + 1 (finite)
    let s3 = desc(
        qmat![[0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 0], [0, 0, 0, 1]],
        qmat![[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, -1]],
        qmat![[0], [0], [1], [1]],
        qmat![[1, 0, 0, 1]],
        qmat![[0]],
    );
    let m3 = minimal_descriptor(&s3).unwrap();
    assert!(m3.verified);
    assert_eq!(
        (
            m3.order,
            m3.finite_order,
            m3.infinite_order,
            m3.polynomial_degree
        ),
        (4, 1, 3, 2)
    );
    // the transfer matrix check is not vacuous: a different system differs
    assert!(!same_transfer(&s, &s3));
}

#[test]
fn singular_pencil_is_refused() {
    let z = Matrix::zeros(Q, 2, 2);
    let s = desc(z.clone(), z, qmat![[1], [0]], qmat![[1, 0]], qmat![[0]]);
    assert!(minimal_descriptor(&s).is_err());
}

#[test]
fn descriptor_zeros_agree_with_rosenbrock_zeros() {
    use exactlti::structure::descriptor_zeros::descriptor_zeros;
    use exactlti::structure::zeros::invariant_zeros;
    let mut rng = crate::common::Rng(5);
    for _ in 0..crate::common::iters(6) {
        let n = rng.int(1, 4) as usize;
        let (m, p) = (rng.int(1, 2) as usize, rng.int(1, 2) as usize);
        let a = crate::common::random_matrix(&Q, &None, n, n, &mut rng);
        let b = crate::common::random_matrix(&Q, &None, n, m, &mut rng);
        let c = crate::common::random_matrix(&Q, &None, p, n, &mut rng);
        let d = crate::common::random_matrix(&Q, &None, p, m, &mut rng);
        let z0 = invariant_zeros(&a, &b, &c, &d).unwrap();
        let sys = Descriptor::new(Matrix::identity(Q, n), a, b, c, d).unwrap();
        let z = descriptor_zeros(&sys).unwrap();
        assert!(z.pencil.verified);
        assert_eq!(z.polynomial, z0.polynomial, "{sys:?}");
        assert_eq!(z.pencil.normal_rank, z0.normal_rank, "{sys:?}");
    }
    // bicycle: the zeros of the descriptor model equal those of its standard form
    let desc = bicycle_descriptor("2");
    let sf = exactlti::realization::descriptor_to_standard(&desc)
        .unwrap()
        .system;
    let z0 = invariant_zeros(&sf.a, &sf.b, &sf.c, &sf.d).unwrap();
    let z = descriptor_zeros(&desc).unwrap();
    assert!(z.pencil.verified);
    assert_eq!(z.polynomial, z0.polynomial);
    // improper G = s: the finite zero 0, no infinite zero (s has a pole at infinity)
    let s = desc_s();
    let z = descriptor_zeros(&s).unwrap();
    assert_eq!(z.polynomial.to_string(), "x");
    assert!(z.infinite_zero_orders.is_empty());
}

fn desc_s() -> Descriptor<Q> {
    Descriptor::new(
        qmat![[0, 1], [0, 0]],
        qmat![[1, 0], [0, 1]],
        qmat![[0], [-1]],
        qmat![[1, 0]],
        qmat![[0]],
    )
    .unwrap()
}
