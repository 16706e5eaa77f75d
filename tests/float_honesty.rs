//! The float path never labels a claim `True` that the exact path refutes (issue 17):
//! controllability of diag(-1e20, -2e20), Jordan structure of Wilkinson matrices, clusters of
//! distinct eigenvalues closer than the clustering radius.

use exactlti::float::{Tol, Truth, controllability_rank, jordan_guess, observability_rank};
use nalgebra::DMatrix;

#[test]
fn controllability_of_widely_scaled_diagonal_is_not_claimed_wrong() {
    // exact: rank [B, AB] = 2 (distinct eigenvalues, B = [1; 1]).
    let a = DMatrix::from_row_slice(2, 2, &[-1e20, 0.0, 0.0, -2e20]);
    let b = DMatrix::from_row_slice(2, 1, &[1.0, 1.0]);
    let r = controllability_rank(&a, &b, &Tol::default()).unwrap();
    assert!(r.rank == 2 || r.truth != Truth::True, "{r:?}");
    let o = observability_rank(&a, &b.transpose(), &Tol::default()).unwrap();
    assert!(o.rank == 2 || o.truth != Truth::True, "{o:?}");
}

fn check_distinct(a: &DMatrix<f64>, exact: &[f64]) {
    let j = jordan_guess(a, &Tol::default()).unwrap();
    for c in &j.clusters {
        // every exact eigenvalue is simple: a cluster claimed True must be one simple value
        // close to one exact eigenvalue
        if c.truth == Truth::True {
            assert_eq!(c.block_sizes, vec![1], "cluster {c:?} claimed True");
            let d = exact
                .iter()
                .map(|e| (c.center.re - e).hypot(c.center.im))
                .fold(f64::INFINITY, f64::min);
            assert!(
                d <= 1e-6 * (1.0 + j.norm),
                "cluster {c:?} far from exact ({d})"
            );
        }
    }
    if j.truth == Truth::True {
        assert_eq!(j.clusters.len(), exact.len());
    }
}

#[test]
fn wilkinson_bidiagonal_20() {
    // diag 20, 19, ..., 1, superdiagonal 20: eigenvalues 1..20, each simple
    let n = 20;
    let a = DMatrix::from_fn(n, n, |i, j| {
        if i == j {
            (n - i) as f64
        } else if j == i + 1 {
            20.0
        } else {
            0.0
        }
    });
    let exact: Vec<f64> = (1..=20).map(|k| k as f64).collect();
    check_distinct(&a, &exact);
}

/// The symmetric tridiagonal `n x n` matrix with diagonal `diag(i)` and ones beside it.
fn tridiagonal_ones(n: usize, diag: impl Fn(usize) -> f64) -> DMatrix<f64> {
    DMatrix::from_fn(n, n, |i, j| {
        if i == j {
            diag(i)
        } else if i.abs_diff(j) == 1 {
            1.0
        } else {
            0.0
        }
    })
}

/// No cluster of `a`'s float Jordan guess claims (`True`) a multiple eigenvalue: `a` has
/// simple eigenvalues only.
fn no_true_multiple(a: &DMatrix<f64>) {
    let j = jordan_guess(a, &Tol::default()).unwrap();
    for c in &j.clusters {
        if c.truth == Truth::True {
            assert_eq!(c.algebraic_multiplicity, 1, "{c:?}");
        }
    }
}

#[test]
fn wilkinson_symmetric_21() {
    // W21+: diag |10 - i|, off-diagonal 1; eigenvalues simple, the largest pairs agree to 1e-14
    // symmetric: every block has size 1; a pair merged into one cluster must not be True
    // with algebraic multiplicity 2 (the exact eigenvalues are simple)
    no_true_multiple(&tridiagonal_ones(21, |i| (10.0 - i as f64).abs()));
}

#[test]
fn clusters_of_close_distinct_eigenvalues_are_not_true() {
    // eigenvalues 1, 1 + 0.005 * 10, -10: the two near ones are within 0.01 * ||A||
    let a = DMatrix::from_row_slice(3, 3, &[1.0, 0.0, 0.0, 0.0, 1.05, 0.0, 0.0, 0.0, -10.0]);
    check_distinct(&a, &[1.0, 1.05, -10.0]);
}

#[test]
fn four_distinct_eigenvalues_within_1e9_are_not_a_true_multiple_eigenvalue() {
    let d = [1.0, 1.0 + 1e-9, 1.0 + 2e-9, 1.0 + 3e-9, -10.0];
    no_true_multiple(&DMatrix::from_fn(
        5,
        5,
        |i, j| if i == j { d[i] } else { 0.0 },
    ));
}

#[test]
fn wilkinson_20_pairs_not_claimed_double() {
    // MATLAB wilkinson(20): diag |-9.5..9.5|, off-diagonal 1; every eigenvalue simple
    no_true_multiple(&tridiagonal_ones(20, |i| (i as f64 - 9.5).abs()));
}

#[test]
fn invariant_zeros_of_widely_scaled_diagonal() {
    // exact: G(s) = 1/(s+1e20) + 1/(s+2e20) has one zero at -1.5e20
    let a = DMatrix::from_row_slice(2, 2, &[-1e20, 0.0, 0.0, -2e20]);
    let b = DMatrix::from_row_slice(2, 1, &[1.0, 1.0]);
    let c = b.transpose();
    let d = DMatrix::zeros(1, 1);
    let z = exactlti::float::invariant_zeros_report(&a, &b, &c, &d, &Tol::default()).unwrap();
    assert!(
        z.truth != Truth::True || (z.zeros.len() == 1 && (z.zeros[0].re + 1.5e20).abs() < 1e6),
        "{z:?}"
    );
    let m = exactlti::float::minreal(&a, &b, &c, &d, &Tol::default()).unwrap();
    assert!(m.truth != Truth::True || m.order == 2, "{m:?}");
}
