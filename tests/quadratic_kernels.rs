//! Test triad for the multi-modular determinant and characteristic polynomial over
//! Q(sqrt d) and Q(i) (`qkernels::modular::quadratic`, reached by `Matrix::charpoly` /
//! `Matrix::det` through the field's kernel entry): planted examples (transposed companion,
//! triangular, T D T^-1 with known eigenvalues), properties against the generic algorithms
//! (Berkowitz, Hessenberg, Gaussian elimination) on random matrices with fractional and
//! large entries for d in {2, 3, -1, 5, -7}, and invariants (det = (-1)^n charpoly(0),
//! similarity invariance, det(AB) = det A det B).

use exactlti::field::{Field, Quadratic, QuadraticField, Rational};
use exactlti::matrix::Matrix;
use exactlti::matrix::over_k::{MODULAR_MIN_N, charpoly_k, det_k};
use exactlti::poly::Poly;
use exactlti::qkernels::modular::quadratic::{charpoly_quadratic, det_quadratic};
use num_bigint::BigInt;
use proptest::prelude::*;

type K = QuadraticField;

fn r(n: i64, d: i64) -> Rational {
    Rational::new(n.into(), d.into())
}

fn el(a: i64, b: i64) -> Quadratic {
    Quadratic::new(r(a, 1), r(b, 1))
}

/// Both kernels' answers for `m` (the direct kernel and the matrix layer), checked equal.
fn kernel_charpoly(m: &Matrix<K>) -> Vec<Quadratic> {
    let n = m.nrows();
    let c = charpoly_quadratic(m.field().d(), n, m.as_slice());
    assert_eq!(m.charpoly().unwrap().coeffs(), &c[..], "Matrix::charpoly");
    if n >= MODULAR_MIN_N {
        assert_eq!(
            charpoly_k(m.field().d(), n, m.as_slice()).as_ref(),
            Some(&c)
        );
    }
    c
}

fn kernel_det(m: &Matrix<K>) -> Quadratic {
    let n = m.nrows();
    let d = det_quadratic(m.field().d(), n, m.as_slice());
    assert_eq!(m.det().unwrap(), d, "Matrix::det");
    if n >= MODULAR_MIN_N {
        assert_eq!(det_k(m.field().d(), n, m.as_slice()), Some(d.clone()));
    }
    d
}

/// $\prod_i (x - \lambda_i)$ over `k`.
fn from_roots(k: &K, roots: &[Quadratic]) -> Vec<Quadratic> {
    roots
        .iter()
        .fold(Poly::one(k.clone()), |p, l| {
            p.mul(&Poly::new(k.clone(), vec![k.neg(l), k.one()]))
        })
        .coeffs()
        .to_vec()
}

/// The transpose of the companion matrix of the monic `x^n + sum c_i x^i` (ones on the
/// superdiagonal, `-c` in the last row: not the shape `companion_charpoly` reads off).
fn companion_t(k: &K, c: &[Quadratic]) -> Matrix<K> {
    let n = c.len();
    Matrix::from_fn(k.clone(), n, n, |i, j| {
        if i == n - 1 {
            k.neg(&c[j])
        } else if j == i + 1 {
            k.one()
        } else {
            k.zero()
        }
    })
}

#[test]
fn planted_companion_over_sqrt2_and_gaussian() {
    for k in [QuadraticField::new(2).unwrap(), QuadraticField::gaussian()] {
        // x^5 + (1 + s) x^4 - 3/2 s x^2 + (7 - 2 s) x - 1/3, s = sqrt d
        let c = vec![
            Quadratic::new(r(-1, 3), r(0, 1)),
            el(7, -2),
            Quadratic::new(r(0, 1), r(-3, 2)),
            el(0, 0),
            el(1, 1),
        ];
        let a = companion_t(&k, &c);
        let mut want = c.clone();
        want.push(k.one());
        assert_eq!(kernel_charpoly(&a), want);
        // det = (-1)^n c_0 = 1/3
        assert_eq!(kernel_det(&a), Quadratic::new(r(1, 3), r(0, 1)));
    }
}

#[test]
fn planted_triangular_and_edge_shapes() {
    for k in [QuadraticField::new(2).unwrap(), QuadraticField::gaussian()] {
        let diag = [
            el(1, 1),
            el(-2, 0),
            Quadratic::new(r(1, 2), r(-5, 3)),
            el(0, 7),
        ];
        let n = diag.len();
        let a = Matrix::from_fn(k.clone(), n, n, |i, j| {
            if i == j {
                diag[i].clone()
            } else if j > i {
                el((i * 3 + j) as i64 - 4, 2 - j as i64)
            } else {
                el(0, 0)
            }
        });
        assert_eq!(kernel_charpoly(&a), from_roots(&k, &diag));
        let prod = diag.iter().fold(k.one(), |p, x| k.mul(&p, x));
        assert_eq!(kernel_det(&a), prod);
        // lower triangular (the transpose) and a zero row / empty / 1x1 matrices
        assert_eq!(kernel_charpoly(&a.transpose()), from_roots(&k, &diag));
        let mut z = a.clone();
        for j in 0..n {
            z.set(2, j, k.zero());
        }
        assert_eq!(kernel_det(&z), k.zero());
        assert_eq!(kernel_charpoly(&z).first(), Some(&k.zero()));
        let empty = Matrix::zeros(k.clone(), 0, 0);
        assert_eq!(kernel_charpoly(&empty), vec![k.one()]);
        assert_eq!(kernel_det(&empty), k.one());
        let one = Matrix::from_fn(k.clone(), 1, 1, |_, _| el(3, -4));
        assert_eq!(kernel_charpoly(&one), vec![el(-3, 4), k.one()]);
    }
}

/// A unit upper triangular times a unit lower triangular matrix (invertible, det 1) from
/// `seed`, entries small integers plus sqrt d parts.
fn unimodular(k: &K, n: usize, seed: i64) -> Matrix<K> {
    let u = Matrix::from_fn(k.clone(), n, n, |i, j| match j.cmp(&i) {
        std::cmp::Ordering::Equal => k.one(),
        std::cmp::Ordering::Greater => el(
            (seed + (i * j) as i64) % 3 - 1,
            (i + seed as usize) as i64 % 2,
        ),
        std::cmp::Ordering::Less => k.zero(),
    });
    let l = Matrix::from_fn(k.clone(), n, n, |i, j| match j.cmp(&i) {
        std::cmp::Ordering::Equal => k.one(),
        std::cmp::Ordering::Less => el(
            (seed * 7 + (i + 2 * j) as i64) % 5 - 2,
            -((j as i64 + seed) % 2),
        ),
        std::cmp::Ordering::Greater => k.zero(),
    });
    &u * &l
}

#[test]
fn planted_similarity_t_d_t_inverse() {
    for k in [QuadraticField::new(2).unwrap(), QuadraticField::gaussian()] {
        // eigenvalues with a repeated one (a Jordan block of size 2) and fractions
        let eig = [
            el(2, 1),
            el(2, 1),
            Quadratic::new(r(-1, 2), r(0, 1)),
            el(0, -3),
            el(5, 0),
            el(-1, 1),
        ];
        let n = eig.len();
        let d = Matrix::from_fn(k.clone(), n, n, |i, j| {
            if i == j {
                eig[i].clone()
            } else if j == i + 1 && i == 0 {
                k.one()
            } else {
                k.zero()
            }
        });
        let t = unimodular(&k, n, 3);
        let a = &(&t * &d) * &t.inverse().unwrap();
        assert_eq!(kernel_charpoly(&a), from_roots(&k, &eig));
        let prod = eig.iter().fold(k.one(), |p, x| k.mul(&p, x));
        assert_eq!(kernel_det(&a), prod);
        assert_eq!(kernel_det(&t), k.one());
    }
}

/// Entries `(num_a / den_a) + (num_b / den_b) sqrt d`, some with 70-bit numerators.
fn entry() -> impl Strategy<Value = Quadratic> {
    (-9i64..=9, 1i64..=4, -5i64..=5, 1i64..=3, 0u8..20).prop_map(|(a, da, b, db, big)| {
        let mut x = Quadratic::new(r(a, da), r(b, db));
        if big == 0 {
            x.a = &x.a * Rational::from_integer(BigInt::from(1u64) << 70u32) + r(1, 7);
        }
        x
    })
}

fn case() -> impl Strategy<Value = (i64, usize, Vec<Quadratic>)> {
    (prop::sample::select(vec![2i64, 3, -1, 5, -7]), 0usize..=6)
        .prop_flat_map(|(d, n)| (Just(d), Just(n), prop::collection::vec(entry(), n * n)))
}

fn matrix(d: i64, n: usize, v: Vec<Quadratic>) -> Matrix<K> {
    Matrix::from_fn(QuadraticField::new(d).unwrap(), n, n, |i, j| {
        v[i * n + j].clone()
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, rng_seed: proptest::test_runner::RngSeed::Fixed(23), ..ProptestConfig::default() })]

    /// The kernels equal the generic algorithms (Berkowitz, Hessenberg, elimination).
    #[test]
    fn kernels_match_the_generic_algorithms((d, n, v) in case()) {
        let a = matrix(d, n, v);
        let c = kernel_charpoly(&a);
        prop_assert_eq!(a.charpoly_berkowitz().unwrap().coeffs().to_vec(), c.clone());
        prop_assert_eq!(a.charpoly_hessenberg().unwrap().coeffs().to_vec(), c.clone());
        prop_assert_eq!(kernel_det(&a), a.det_gauss().unwrap());
    }

    /// det = (-1)^n charpoly(0); charpoly(T A T^-1) = charpoly(A); det(AB) = det A det B.
    #[test]
    fn invariants((d, n, v) in case(), seed in 0i64..50) {
        let a = matrix(d, n, v);
        let k = a.field().clone();
        let c = kernel_charpoly(&a);
        let det = kernel_det(&a);
        let c0 = if n % 2 == 0 { c[0].clone() } else { k.neg(&c[0]) };
        prop_assert_eq!(&det, &c0);
        let t = unimodular(&k, n, seed);
        let b = &(&t * &a) * &t.inverse().unwrap();
        prop_assert_eq!(kernel_charpoly(&b), c);
        let ab = &a * &b;
        prop_assert_eq!(kernel_det(&ab), k.mul(&det, &det));
    }
}
