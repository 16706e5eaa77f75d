//! The float paths through the Jordan blocks ([`exactlti::float::modal`]) against the dense
//! ones: $G(j\omega)$ by eq. 56 equals the dense LU solve, and stepping with $e^{Jh}$ equals
//! stepping with the dense $e^{Ah}$, on random rational systems (fixed seed) with repeated
//! eigenvalues (Jordan blocks up to size 3) and complex pairs.

use exactlti::field::{Q, Rational};
use exactlti::float::modal::{ModalSystem, dense_transition, simulate_dense, simulate_modal};
use exactlti::float::{freqresp, to_dmatrix};
use exactlti::jordan::jordan;
use exactlti::matrix::Matrix;
use exactlti::rng::SplitMix64;

fn q(n: i64) -> Rational {
    Rational::from_integer(n.into())
}

/// $A = T J T^{-1}$ with $J$ block diagonal: Jordan blocks of sizes 1-3 at eigenvalues from
/// $\{-1, -2, -1/2\}$ (so they repeat across blocks) and companion blocks of complex pairs;
/// $T$ a product of unit triangular integer matrices (det 1).
pub fn random_system(rng: &mut SplitMix64, n: usize) -> (Matrix<Q>, Matrix<Q>, Matrix<Q>) {
    let mut j = Matrix::zeros(Q, n, n);
    let mut i = 0;
    while i < n {
        let kind = rng.int(0, 2);
        if kind == 2 && i + 2 <= n {
            // s^2 + p s + r with p^2 < 4 r
            let p = rng.int(1, 3);
            let r = p * p + rng.int(1, 6);
            j.set(i, i + 1, q(1));
            j.set(i + 1, i, q(-r));
            j.set(i + 1, i + 1, q(-p));
            i += 2;
            continue;
        }
        let theta =
            [q(-1), q(-2), Rational::new((-1).into(), 2.into())][rng.int(0, 2) as usize].clone();
        let size = (rng.int(1, 3) as usize).min(n - i);
        for k in 0..size {
            j.set(i + k, i + k, theta.clone());
            if k + 1 < size {
                j.set(i + k, i + k + 1, q(1));
            }
        }
        i += size;
    }
    let lower = Matrix::from_fn(Q, n, n, |r, c| match r.cmp(&c) {
        std::cmp::Ordering::Equal => q(1),
        std::cmp::Ordering::Greater => q(rng.int(-2, 2)),
        std::cmp::Ordering::Less => q(0),
    });
    let upper = Matrix::from_fn(Q, n, n, |r, c| match r.cmp(&c) {
        std::cmp::Ordering::Equal => q(1),
        std::cmp::Ordering::Less => q(rng.int(-2, 2)),
        std::cmp::Ordering::Greater => q(0),
    });
    let t = &lower * &upper;
    let a = &(&t * &j) * &t.inverse().unwrap();
    let b = Matrix::from_fn(Q, n, 2, |_, _| q(rng.int(-2, 2)));
    let c = Matrix::from_fn(Q, 2, n, |_, _| q(rng.int(-2, 2)));
    (a, b, c)
}

#[test]
fn block_frequency_response_equals_the_dense_lu() {
    let mut rng = SplitMix64(27_056);
    let freqs = [0.0, 0.013, 0.1, 0.37, 1.0, 4.2, 30.0];
    let mut repeated = 0;
    for case in 0..30 {
        let n = 3 + case % 5;
        let (a, b, c) = random_system(&mut rng, n);
        let d = Matrix::from_fn(Q, 2, 2, |r, s| q((r + 2 * s) as i64));
        let jf = jordan(&a).unwrap();
        assert!(jf.verified);
        if jf
            .eigenvalues
            .iter()
            .any(|e| e.blocks.iter().any(|&s| s > 1))
        {
            repeated += 1;
        }
        let sys = ModalSystem::from_jordan(&jf, &b, &c, &d).unwrap();
        let f = |m: &Matrix<Q>| to_dmatrix(m).unwrap();
        let dense = freqresp([&f(&a), &f(&b), &f(&c), &f(&d)], &freqs, None).unwrap();
        let modal = sys.freqresp(&freqs).unwrap();
        for (g, h) in dense.iter().zip(&modal) {
            let scale = g.iter().map(|z| z.norm()).fold(1.0, f64::max);
            let err = (g - h).iter().map(|z| z.norm()).fold(0.0, f64::max);
            assert!(
                err <= 1e-9 * scale,
                "case {case}: error {err} (scale {scale})"
            );
        }
    }
    assert!(
        repeated >= 10,
        "only {repeated} systems with a Jordan block > 1"
    );
}

#[test]
fn sparse_jordan_stepping_equals_the_dense_transition() {
    let mut rng = SplitMix64(27_057);
    for case in 0..30 {
        let n = 3 + case % 5;
        let (a, b, c) = random_system(&mut rng, n);
        let d = Matrix::zeros(Q, 2, 2);
        let jf = jordan(&a).unwrap();
        let sys = ModalSystem::from_jordan(&jf, &b, &c, &d).unwrap();
        let x0: Vec<f64> = (0..n).map(|_| rng.int(-3, 3) as f64).collect();
        let h = 0.05;
        let phi = dense_transition(&to_dmatrix(&a).unwrap(), h).unwrap();
        let xs = simulate_modal(&sys, h, 100, &x0);
        let ys = simulate_dense(&phi, 100, &x0);
        assert_eq!(xs.len(), 101);
        // relative to the largest state along the trajectory: T = L U may be ill-conditioned
        // (seen: 1.3e-9 relative after 9 steps at n = 7)
        let scale = ys.iter().flatten().fold(1.0f64, |m, x| m.max(x.abs()));
        for (k, (x, y)) in xs.iter().zip(&ys).enumerate() {
            for (u, v) in x.iter().zip(y) {
                assert!(
                    (u - v).abs() <= 1e-7 * scale,
                    "case {case}, step {k}: {u} vs {v} (scale {scale})"
                );
            }
        }
        // the transition is sparse: one triangle per Jordan block
        let nnz = sys.transition(h).nonzeros();
        let blocks: usize = jf
            .eigenvalues
            .iter()
            .map(|e| e.blocks.iter().map(|s| s * (s + 1) / 2).sum::<usize>())
            .sum();
        assert_eq!(nnz, blocks);
        assert!(nnz <= n * (n + 1) / 2);
    }
}

#[test]
fn modal_shapes_are_checked() {
    let v = nalgebra::DMatrix::identity(2, 2);
    let blocks = vec![exactlti::float::modal::ModalBlock {
        theta: num_complex::Complex64::new(-1.0, 0.0),
        size: 1,
        offset: 0,
    }];
    let b = nalgebra::DMatrix::zeros(2, 1);
    let c = nalgebra::DMatrix::zeros(1, 2);
    let d = nalgebra::DMatrix::zeros(1, 1);
    // the blocks cover 1 of 2 states
    assert!(ModalSystem::from_parts(blocks, v.clone(), v, &b, &c, &d).is_err());
}
