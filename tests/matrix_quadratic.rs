//! Test triad for the kernels over Q(sqrt d) (`matrix::over_k`: integer product, inverse and
//! rank through the regular representation) and for the Lehmer-gcd rational operations under
//! the fields' arithmetic: known examples, properties against the generic (classical) loops,
//! and edge cases (singular, empty, rank-deficient only over K).

use exactlti::field::lehmer;
use exactlti::field::{Field, Quadratic, QuadraticField, Rational};
use exactlti::jordan::jordan_over as jordan_over_k;
use exactlti::matrix::Matrix;
use exactlti::matrix::over_k::{inverse_k, mul_k, mul_k_integer, rank_k, rref_k};
use proptest::prelude::*;

fn r(n: i64, d: i64) -> Rational {
    Rational::new(n.into(), d.into())
}

fn qm(k: &QuadraticField, rows: &[&[(i64, i64)]]) -> Matrix<QuadraticField> {
    Matrix::from_rows(
        k.clone(),
        rows.iter()
            .map(|row| {
                row.iter()
                    .map(|&(a, b)| Quadratic::new(r(a, 1), r(b, 1)))
                    .collect()
            })
            .collect(),
    )
    .unwrap()
}

/// The classical triple loop with the field's operations (the oracle of `mul_k`).
fn mul_naive(a: &Matrix<QuadraticField>, b: &Matrix<QuadraticField>) -> Matrix<QuadraticField> {
    let k = a.field();
    Matrix::from_fn(k.clone(), a.nrows(), b.ncols(), |i, j| {
        (0..a.ncols()).fold(k.zero(), |acc, l| {
            k.add(&acc, &k.mul(a.get(i, l), b.get(l, j)))
        })
    })
}

#[test]
fn known_examples_over_gaussian_rationals() {
    let k = QuadraticField::gaussian();
    let d = k.d().clone();
    // [[1, i], [i, -1]]: the second row is i times the first, rank 1 over Q(i) (its
    // regular representation, a 4x4 rational matrix, has rank 2)
    let a = qm(&k, &[&[(1, 0), (0, 1)], &[(0, 1), (-1, 0)]]);
    assert_eq!(rank_k(&d, 2, 2, a.as_slice()), 1);
    assert_eq!(a.rank(), 1);
    assert!(inverse_k(&d, 2, a.as_slice()).is_none());
    assert!(a.inverse().is_err());
    // [[1, i], [0, 2]]^{-1} = [[1, -i/2], [0, 1/2]]
    let b = qm(&k, &[&[(1, 0), (0, 1)], &[(0, 0), (2, 0)]]);
    let bi = b.inverse().unwrap();
    assert_eq!(bi.to_string(), "[[1, -i/2], [0, 1/2]]");
    assert!((&b * &bi).is_identity());
    // (1 + i)(1 - i) = 2 in a product with inner dimension 4
    let one_row: &[(i64, i64)] = &[(1, 1), (0, 0), (0, 0), (0, 0)];
    let row = qm(&k, &[one_row, one_row]);
    let col = qm(
        &k,
        &[
            &[(1, -1), (0, 0)],
            &[(0, 0), (0, 0)],
            &[(0, 0), (0, 0)],
            &[(0, 0), (0, 0)],
        ],
    );
    let p = mul_k(&d, 2, 4, 2, row.as_slice(), col.as_slice()).unwrap();
    assert_eq!(p[0], Quadratic::new(r(2, 1), r(0, 1)));
    assert_eq!(p[1], Quadratic::new(r(0, 1), r(0, 1)));
    // over Q(sqrt 2): (1 + sqrt 2)^{-1} = -1 + sqrt 2
    let k2 = QuadraticField::new(2).unwrap();
    let u = qm(&k2, &[&[(1, 1)]]);
    assert_eq!(u.inverse().unwrap().to_string(), "[[-1 + sqrt(2)]]");
}

#[test]
fn edge_cases_empty_small_and_singular() {
    let k = QuadraticField::new(-3).unwrap();
    let d = k.d().clone();
    // empty shapes
    assert_eq!(rank_k(&d, 0, 3, &[]), 0);
    assert_eq!(rank_k(&d, 3, 0, &[]), 0);
    assert_eq!(inverse_k(&d, 0, &[]), Some(vec![]));
    assert!(mul_k_integer(&d, (0, 2, 3), &[], &vec![k.zero(); 6]).is_empty());
    assert_eq!(mul_k_integer(&d, (2, 0, 2), &[], &[]), vec![k.zero(); 4]);
    // below the size threshold the generic loop is chosen
    assert!(mul_k(&d, 2, 1, 2, &[k.one(), k.one()], &[k.one(), k.one()]).is_none());
    // a zero matrix and a singular one
    let z = Matrix::zeros(k.clone(), 3, 3);
    assert_eq!(z.rank(), 0);
    assert!(z.inverse().is_err());
    let s = qm(&k, &[&[(1, 1), (2, 2)], &[(3, -1), (6, -2)]]);
    assert_eq!(s.rank(), 1);
    assert!(s.inverse().is_err());
}

#[test]
#[should_panic(expected = "mul_k: slice of length 3")]
fn mul_k_rejects_a_slice_of_the_wrong_length() {
    let k = QuadraticField::gaussian();
    let _ = mul_k(k.d(), 2, 2, 2, &vec![k.one(); 3], &vec![k.one(); 4]);
}

#[test]
fn a_tampered_left_chain_fails_the_simple_check() {
    let k = QuadraticField::gaussian();
    // chi irreducible of degree 3 over Q(i): one simple component checked on coefficients
    let a = qm(
        &k,
        &[
            &[(0, 0), (1, 0), (0, 0)],
            &[(0, 0), (0, 0), (1, 0)],
            &[(2, 1), (0, 0), (1, 0)],
        ],
    );
    let jf = jordan_over_k(&a).unwrap();
    assert!(jf.verified);
    let c = &jf.components[0];
    assert_eq!((c.multiplicity, c.factor.deg()), (1, 3));
    assert!(c.verify(&a));
    let mut bad = c.clone();
    bad.left_chains = bad.left_chains.scale(&bad.field.from_rational(&r(2, 1)));
    assert!(!bad.verify(&a));
    // t V still satisfies A (t V) = t (t V), but W (t V) = t is not 1
    let mut bad = c.clone();
    bad.chains = bad.chains.scale(&bad.field.generator());
    assert!(!bad.verify(&a));
}

fn entry() -> impl Strategy<Value = Quadratic> {
    // small and large numerators over a few denominators, with zeros
    let part = prop_oneof![
        3 => Just(Rational::from_integer(0.into())),
        4 => (-9i64..=9, 1i64..=6).prop_map(|(n, d)| r(n, d)),
        2 => (any::<i64>(), 1i64..=1_000_000_007).prop_map(|(n, d)| r(n, d)),
    ];
    (part.clone(), part).prop_map(|(a, b)| Quadratic::new(a, b))
}

fn field() -> impl Strategy<Value = QuadraticField> {
    prop_oneof![Just(-1i64), Just(2), Just(-3), Just(5)]
        .prop_map(|d| QuadraticField::new(d).unwrap())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn kernels_agree_with_the_generic_loops(
        k in field(),
        m in 0usize..5, kk in 0usize..6, n in 0usize..5,
        xs in proptest::collection::vec(entry(), 30),
        ys in proptest::collection::vec(entry(), 30),
        rankdef in any::<bool>(),
    ) {
        let a = Matrix::from_vec(k.clone(), m, kk, xs[..m * kk].to_vec());
        let b = Matrix::from_vec(k.clone(), kk, n, ys[..kk * n].to_vec());
        let d = k.d().clone();
        // product: integer kernel against the classical loop
        let p = mul_k_integer(&d, (m, kk, n), a.as_slice(), b.as_slice());
        let naive = mul_naive(&a, &b);
        prop_assert_eq!(p.as_slice(), naive.as_slice());
        // rank and inverse against Gauss-Jordan over K; a planted dependent row
        let mut sq = Matrix::from_vec(k.clone(), m, m, xs[..m * m].to_vec());
        if rankdef && m >= 2 {
            let c = ys[0].clone();
            for j in 0..m {
                let v = k.mul(&c, sq.get(0, j));
                sq.set(m - 1, j, v);
            }
        }
        let (gj_r, piv) = sq.rref_gauss_jordan();
        prop_assert_eq!(rank_k(&d, m, m, sq.as_slice()), piv.len());
        // RREF through the regular representation: Gauss-Jordan's, also on the rectangular A
        let (rk, pk) = rref_k(&d, m, m, sq.as_slice());
        prop_assert_eq!((rk.as_slice(), &pk), (gj_r.as_slice(), &piv));
        let (ra, pa) = a.rref_gauss_jordan();
        let (rk, pk) = rref_k(&d, m, kk, a.as_slice());
        prop_assert_eq!((rk.as_slice(), pk), (ra.as_slice(), pa));
        let inv = inverse_k(&d, m, sq.as_slice());
        prop_assert_eq!(inv.is_some(), piv.len() == m);
        if let Some(x) = inv {
            let x = Matrix::from_vec(k.clone(), m, m, x);
            prop_assert!(mul_naive(&sq, &x).is_identity());
            let aug = sq.hstack(&Matrix::identity(k.clone(), m)).unwrap();
            let gj = aug.rref_gauss_jordan().0.submatrix(0, m, m, 2 * m);
            prop_assert_eq!(x, gj);
        }
    }

    #[test]
    fn lehmer_rational_ops_match_num_rational(
        a in any::<i128>(), b in 1u64.., c in any::<i128>(), e in 1u64.., shared in 1u64..1000,
    ) {
        let x = Rational::new(a.into(), (u128::from(b) * u128::from(shared)).into());
        let y = Rational::new(c.into(), (u128::from(e) * u128::from(shared)).into());
        prop_assert_eq!(lehmer::add(&x, &y), &x + &y);
        prop_assert_eq!(lehmer::sub(&x, &y), &x - &y);
        prop_assert_eq!(lehmer::mul(&x, &y), &x * &y);
        prop_assert_eq!(lehmer::sub(&x, &x), Rational::from_integer(0.into()));
    }
}
