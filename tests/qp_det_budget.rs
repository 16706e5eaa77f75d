//! The size budget of the determinant kernel over Q(p) (`ratfunc::det_budget`, checked by
//! `Matrix::det` itself, so every caller is protected): a determinant whose numerator may
//! have more than `MAX_DET_TERMS` terms (by `det_terms_bound`, known before anything is
//! expanded) is a `Limit`, never an expansion; within the budget `det` is exact (equal to
//! the determinant of the matrix evaluated at random rational points), and for polynomial
//! matrices the bound is an upper bound of the numerator's true number of terms.

use crate::common::systems::diag_qp;
use exactlti::error::Error;
use exactlti::field::Rational;
use exactlti::matrix::Matrix;
use exactlti::matrix::qp_conditions::eval_at as at;
use exactlti::ratfunc::{MAX_DET_TERMS, RatFuncField, det_budget, det_terms_bound};
use exactlti::rng::SplitMix64;

/// The Krylov matrix [b, A b, ..., A^(n-1) b] of diag(p0..p(n-1)) with b = ones: the
/// Vandermonde matrix of the parameters (its determinant has n! terms).
fn vandermonde(n: usize) -> Matrix<RatFuncField> {
    let s = diag_qp(n);
    exactlti::realization::controllability_matrix(&s.a, &s.b)
}

fn bound(m: &Matrix<RatFuncField>) -> u128 {
    det_terms_bound(m.field().nvars(), m.nrows(), m.ncols(), m.as_slice())
}

#[test]
fn vandermonde_minors_past_the_budget_are_a_limit_of_det_itself() {
    // the class: Vandermonde matrices of n parameters; from n = 8 the bound exceeds 2e6
    // (C(36, 8) = 30260340; n = 7 gives C(28, 7) = 1184040 and is expanded)
    for n in 8..=10 {
        let v = vandermonde(n);
        assert!(bound(&v) > MAX_DET_TERMS, "n = {n}: {}", bound(&v));
        match v.det() {
            Err(Error::Limit(m)) => assert!(m.contains("minor may have up to"), "{m}"),
            other => panic!("n = {n}: det expanded past the budget: {other:?}"),
        }
        assert!(matches!(
            det_budget(n, n, n, v.as_slice()),
            Err(Error::Limit(_))
        ));
    }
}

#[test]
fn within_the_budget_det_is_exact_and_the_bound_holds() {
    for n in 2..=7 {
        let v = vandermonde(n);
        let d = v.det().expect("within the budget");
        // n! terms in the numerator: the bound is an upper bound of them
        let fact: usize = (1..=n).product();
        assert_eq!(d.num().len(), fact, "n = {n}");
        assert!(bound(&v) >= fact as u128, "n = {n}");
        // prod_{i<j} (p_j - p_i) at a point
        let p: Vec<Rational> = (0..n)
            .map(|i| Rational::from_integer((3 * i * i + 1).into()))
            .collect();
        let want = at(&v, &p).unwrap().det().unwrap();
        assert_eq!(v.field().eval(&d, &p), Some(want), "n = {n}");
    }
}

/// A random n x n matrix over Q(a, b, c) of low degree (a generator of matrices within the
/// budget): `det` is the determinant at every sampled point; for a polynomial matrix the
/// bound is at least the number of terms of the numerator (with several denominators in a
/// row it is a heuristic: their lcm is not counted).
#[test]
fn random_small_matrices_det_at_points() {
    let k = RatFuncField::new(&["a", "b", "c"]).unwrap();
    let mut rng = SplitMix64(0x5eed_23c5);
    let vars = ["a", "b", "c"];
    for case in 0..24 {
        let n = 2 + case % 4;
        let m = Matrix::from_fn(k.clone(), n, n, |_, _| {
            let v = vars[rng.int(0, 2) as usize];
            let text = match rng.int(0, 4) {
                0 => "0".to_string(),
                1 => format!("{}", rng.int(-4, 4)),
                2 => format!("{}*{v} + {}", rng.int(-3, 3), rng.int(-3, 3)),
                3 => format!("{v}^2 - {}", rng.int(0, 3)),
                4 if case % 2 == 0 => format!("1/({v} + {})", rng.int(1, 4)),
                _ => format!("{v}*{} - {}", vars[rng.int(0, 2) as usize], rng.int(0, 3)),
            };
            k.parse(&text).unwrap()
        });
        assert!(bound(&m) <= MAX_DET_TERMS, "case {case}");
        let d = m.det().expect("within the budget");
        let polynomial = m.as_slice().iter().all(|x| x.den().total_degree() == 0);
        if polynomial {
            assert!(bound(&m) >= d.num().len() as u128, "case {case}");
        }
        for _ in 0..3 {
            let p: Vec<Rational> = (0..3)
                .map(|_| Rational::from_integer(rng.int(-50, 50).into()))
                .collect();
            let (Some(mq), Some(dv)) = (at(&m, &p), k.eval(&d, &p)) else {
                continue;
            };
            assert_eq!(mq.det().unwrap(), dv, "case {case} at {p:?}");
        }
    }
}
