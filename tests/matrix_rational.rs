//! Exact matrix kernels over Q on matrices of fractions p/q with large denominators (issue
//! 29): the kernels of `qkernels::modular::direct` (images of the rational matrix itself)
//! and the dispatch of `matrix::over_q` against the generic Gauss–Jordan / Hessenberg
//! algorithms of `Matrix<Q>`, on random matrices with a fixed seed (full, rank-deficient,
//! with zero rows, 0 x n, n x 0, 1 x 1), each result checked by its identity.

use exactlti::field::{Q, Rational};
use exactlti::matrix::Matrix;
use exactlti::matrix::over_q as oq;
use exactlti::qkernels::modular::direct;
use exactlti::rng::SplitMix64;
use num_traits::{One, Zero};

use crate::common::matmul_q as matmul;

fn qq(n: i64, d: i64) -> Rational {
    Rational::new(n.into(), d.into())
}

/// Entries p/q with |p| <= 10^6 and q <= `qmax`, a zero one time in `zeros`.
fn random(g: &mut SplitMix64, m: usize, n: usize, qmax: i64, zeros: i64) -> Vec<Rational> {
    crate::common::random_rationals(g, m, n, 1_000_000, qmax, zeros)
}

fn mat(m: usize, n: usize, a: &[Rational]) -> Matrix<Q> {
    Matrix::from_vec(Q, m, n, a.to_vec())
}

/// A family of test matrices: full, low rank (a product), zero rows, duplicated rows.
fn family(g: &mut SplitMix64, m: usize, n: usize) -> Vec<Vec<Rational>> {
    let full = random(g, m, n, 1_000_000, 0);
    let k = (m.min(n) / 2).max(1);
    let low = matmul(m, k, n, &random(g, m, k, 30, 0), &random(g, k, n, 30, 0));
    let mut zero_rows = random(g, m, n, 1000, 3);
    for i in (0..m).step_by(3) {
        zero_rows[i * n..(i + 1) * n].fill(Rational::zero());
    }
    let mut dup = random(g, m, n, 1_000_000, 0);
    if m >= 2 {
        let r0: Vec<Rational> = dup[..n].to_vec();
        for j in 0..n {
            dup[(m - 1) * n + j] = &r0[j] * qq(-3, 7) + &dup[n + j];
        }
    }
    vec![full, low, zero_rows, dup]
}

fn check_rect(m: usize, n: usize, a: &[Rational], ctx: &str) {
    let (r, piv) = oq::rref_q(m, n, a);
    let (rg, pg) = mat(m, n, a).rref_gauss_jordan();
    assert_eq!(r, rg.as_slice(), "rref {ctx}");
    assert_eq!(piv, pg, "pivots {ctx}");
    assert_eq!(oq::rank_q(m, n, a), piv.len(), "rank {ctx}");
    let ns = oq::nullspace_q(m, n, a);
    assert_eq!(ns.len() + piv.len(), n, "rank + nullity {ctx}");
    for v in &ns {
        assert!(
            matmul(m, n, 1, a, v).iter().all(Zero::is_zero),
            "A v = 0 {ctx}"
        );
    }
    if let Some(rk) = direct::rank_if_full(m, n, a) {
        assert_eq!(rk, piv.len(), "full-rank test {ctx}");
    }
}

fn check_square(n: usize, a: &[Rational], ctx: &str) {
    let m = mat(n, n, a);
    let (_, piv) = m.rref_gauss_jordan();
    let det = oq::det_q(n, a);
    assert_eq!(det, direct::det_direct(n, a), "det direct {ctx}");
    assert_eq!(det.is_zero(), piv.len() < n, "det = 0 iff singular {ctx}");
    let cp = oq::charpoly_q(n, a);
    assert_eq!(cp, direct::charpoly_direct(n, a), "charpoly direct {ctx}");
    let hess = m.charpoly_hessenberg().unwrap();
    assert_eq!(cp, hess.coeffs(), "charpoly against Hessenberg {ctx}");
    let sign = if n.is_multiple_of(2) {
        det.clone()
    } else {
        -det.clone()
    };
    assert_eq!(cp[0], sign, "charpoly(0) = (-1)^n det {ctx}");
    let inv = oq::inverse_q(n, a);
    assert_eq!(inv, direct::inverse_direct(n, a), "inverse direct {ctx}");
    assert_eq!(
        inv.is_none(),
        det.is_zero(),
        "singular iff no inverse {ctx}"
    );
    if let Some(x) = &inv {
        let id = Matrix::<Q>::identity(Q, n);
        assert_eq!(matmul(n, n, n, a, x), id.as_slice(), "A A^-1 = I {ctx}");
    }
    let b: Vec<Rational> = (0..n).map(|i| qq(i as i64 - 2, 3)).collect();
    match oq::solve_q(n, n, 1, a, &b) {
        Some(x) => assert_eq!(matmul(n, n, 1, a, &x), b, "A x = b {ctx}"),
        None => assert!(det.is_zero(), "inconsistent only when singular {ctx}"),
    }
    let mp = m.minpoly().unwrap();
    assert!(m.eval_poly(&mp).unwrap().is_zero(), "minpoly(A) = 0 {ctx}");
    assert!(hess.rem(&mp).is_zero(), "minpoly divides charpoly {ctx}");
    if direct::is_cyclic(n, a) {
        assert_eq!(mp.coeffs(), cp, "cyclic: minpoly = charpoly {ctx}");
    }
}

#[test]
fn examples_edge_shapes() {
    for (m, n) in [(0, 0), (0, 3), (3, 0), (1, 1), (1, 4), (4, 1)] {
        let a = random(&mut SplitMix64(7), m, n, 1_000_000, 0);
        check_rect(m, n, &a, &format!("{m}x{n}"));
        if m == n {
            check_square(n, &a, &format!("{n}x{n}"));
        }
    }
    assert_eq!(direct::det_direct(0, &[]), Rational::one());
    assert_eq!(direct::charpoly_direct(0, &[]), vec![Rational::one()]);
    assert_eq!(direct::det_direct(1, &[qq(-3, 7)]), qq(-3, 7));
    assert_eq!(
        direct::inverse_direct(1, &[qq(-3, 7)]),
        Some(vec![qq(-7, 3)])
    );
    assert_eq!(direct::inverse_direct(1, &[Rational::zero()]), None);
    // 2x2 by hand: det [[1/2, 1/3], [1/5, 1/7]] = 1/14 - 1/15 = 1/210
    let a = [qq(1, 2), qq(1, 3), qq(1, 5), qq(1, 7)];
    assert_eq!(direct::det_direct(2, &a), qq(1, 210));
    assert_eq!(
        direct::inverse_direct(2, &a),
        Some(vec![qq(30, 1), qq(-70, 1), qq(-42, 1), qq(105, 1)])
    );
    // derogatory: the identity's minimal polynomial is x - 1
    let id = Matrix::<Q>::identity(Q, 12);
    assert!(!direct::is_cyclic(12, id.as_slice()));
    assert_eq!(id.minpoly().unwrap().coeffs(), [qq(-1, 1), qq(1, 1)]);
}

#[test]
fn properties_against_generic_gauss_jordan() {
    let mut g = SplitMix64(29);
    for (m, n) in [(3, 3), (5, 4), (4, 7), (9, 9), (12, 12), (10, 14), (16, 11)] {
        for (t, a) in family(&mut g, m, n).into_iter().enumerate() {
            check_rect(m, n, &a, &format!("{m}x{n} kind {t}"));
            if m == n {
                check_square(n, &a, &format!("{n}x{n} kind {t}"));
            }
        }
    }
}

#[test]
fn derogatory_minpoly_over_rationals() {
    // block diag(B, B) with a random rational 5x5 B: minpoly = charpoly(B), degree 5
    let mut g = SplitMix64(3);
    let b = random(&mut g, 5, 5, 1000, 0);
    let bm = mat(5, 5, &b);
    let d = Matrix::block_diag(Q, &[bm.clone(), bm.clone()]);
    assert!(!direct::is_cyclic(10, d.as_slice()));
    let mp = d.minpoly().unwrap();
    assert_eq!(mp, bm.charpoly_hessenberg().unwrap());
    assert!(d.eval_poly(&mp).unwrap().is_zero());
}

#[test]
fn solve_and_inverse_lift_det_scaled_numerators() {
    // solve_direct lifts N = det(DA) X by CRT alone: several right-hand columns, integer and
    // rational inputs, against the generic RREF of [A | B] and by A X = B
    let mut g = SplitMix64(2929);
    for (n, k, qmax) in [
        (9, 3, 1_000_000),
        (14, 2, 1),
        (20, 5, 1000),
        (11, 11, 1_000_000),
    ] {
        let a = random(&mut g, n, n, qmax, 0);
        let b = random(&mut g, n, k, qmax, 4);
        let x = direct::solve_direct(n, k, &a, &b).expect("a random matrix is nonsingular");
        assert_eq!(matmul(n, n, k, &a, &x), b, "A X = B {n}x{n} k {k}");
        let mut aug = Vec::new();
        for i in 0..n {
            aug.extend_from_slice(&a[i * n..(i + 1) * n]);
            aug.extend_from_slice(&b[i * k..(i + 1) * k]);
        }
        let (r, _) = mat(n, n + k, &aug).rref_gauss_jordan();
        let want: Vec<Rational> = (0..n)
            .flat_map(|i| r.as_slice()[i * (n + k) + n..(i + 1) * (n + k)].to_vec())
            .collect();
        assert_eq!(x, want, "against the generic RREF {n}x{n} k {k}");
        let inv = direct::inverse_direct(n, &a).expect("nonsingular");
        let id = Matrix::<Q>::identity(Q, n);
        assert_eq!(matmul(n, n, n, &inv, &a), id.as_slice(), "A^-1 A = I {n}");
    }
    // singular (a repeated row): no solution is claimed, no inverse
    let mut a = random(&mut g, 10, 10, 1000, 0);
    let r0 = a[..10].to_vec();
    a[90..].clone_from_slice(&r0);
    assert_eq!(direct::inverse_direct(10, &a), None);
    assert_eq!(
        direct::solve_direct(10, 1, &a, &random(&mut g, 10, 1, 7, 0)),
        None
    );
}

#[test]
fn deficient_rref_on_images_of_a() {
    // rank-deficient rational matrices take the multi-modular RREF on images of A itself:
    // canonical RREF equal to the generic one, every row of A in its row space
    let mut g = SplitMix64(4242);
    for (m, n) in [(18, 18), (15, 22), (24, 13)] {
        let mut a = random(&mut g, m, n, 1_000_000, 0);
        for j in 0..n {
            a[(m - 1) * n + j] = &a[j] * qq(5, 3) - &a[n + j];
        }
        let (r, piv) = oq::rref_q(m, n, &a);
        let (rg, pg) = mat(m, n, &a).rref_gauss_jordan();
        assert_eq!((r.as_slice(), &piv), (rg.as_slice(), &pg), "{m}x{n}");
        assert_eq!(piv.len(), m.min(n) - usize::from(m <= n), "rank {m}x{n}");
        for v in oq::nullspace_q(m, n, &a) {
            assert!(matmul(m, n, 1, &a, &v).iter().all(Zero::is_zero));
        }
    }
}
