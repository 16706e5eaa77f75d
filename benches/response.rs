//! The Jordan blocks against the dense matrices (issue 27 item 5; `cargo bench --bench
//! response`):
//!
//! - frequency response (minimal-realizations paper eq. 56): $G(j\omega)$ at 200 frequencies
//!   through the Jordan blocks ([`exactlti::float::modal::ModalSystem::freqresp`], closed-form
//!   block inverse) against one dense complex LU of $j\omega I - A$ per frequency
//!   ([`exactlti::float::freqresp`]);
//! - time stepping (Jordan paper sec. II): 1000 steps of $z \leftarrow e^{Jh} z$ (the sparse
//!   transition, output $y = CVz$ per step) against $x \leftarrow e^{Ah} x$ (dense, $y = Cx$).
//!
//! Systems: $A = V J V^{-1}$ for $n = 10, 20, 50, 100, 200$ with $V = Q U$ ($Q$ a random
//! orthogonal matrix, $U$ taking each rotation block to its complex eigenvector pair), $J$ of
//! complex pairs and size-2 Jordan blocks of repeated real eigenvalues (a fifth of the
//! states); 2 inputs, 2 outputs; fixed seeds. The decomposition is given (built in floats
//! here): what is timed is the response from it. Lines: `name n=<n>: <best ms> ms (median ...)`
//! and `ratio n=<n>: dense / jordan = <r>`. `EXACTLTI_BENCH_SIZES=10,50` restricts the sizes.

#[path = "common.rs"]
mod common;

use exactlti::float::freqresp;
use exactlti::float::modal::{ModalBlock, ModalSystem, dense_transition};
use exactlti::float::random::Lcg;
use nalgebra::DMatrix;
use num_complex::Complex64 as C;

fn system(n: usize) -> (ModalSystem, DMatrix<f64>) {
    let mut rng = Lcg::new(27_000 + n as u64);
    let q = rng.orthogonal(n);
    let mut u = DMatrix::<C>::zeros(n, n);
    let mut j = DMatrix::<f64>::zeros(n, n);
    let mut blocks = vec![];
    let mut i = 0;
    while i < n {
        if i + 2 <= n && (i / 2) % 5 == 4 {
            // a size-2 Jordan block at a real eigenvalue repeated across blocks
            let theta = -0.5 - (i % 3) as f64;
            j[(i, i)] = theta;
            j[(i + 1, i + 1)] = theta;
            j[(i, i + 1)] = 1.0;
            u[(i, i)] = C::new(1.0, 0.0);
            u[(i + 1, i + 1)] = C::new(1.0, 0.0);
            blocks.push(ModalBlock {
                theta: C::new(theta, 0.0),
                size: 2,
                offset: i,
            });
            i += 2;
        } else if i + 2 <= n {
            // [[a, b], [-b, a]]: eigenvectors (1, +-i) at a +- ib
            let (a, b) = (
                -0.05 - 0.3 * rng.uniform().abs(),
                1.0 + 20.0 * rng.uniform().abs(),
            );
            j[(i, i)] = a;
            j[(i + 1, i + 1)] = a;
            j[(i, i + 1)] = b;
            j[(i + 1, i)] = -b;
            u[(i, i)] = C::new(1.0, 0.0);
            u[(i + 1, i)] = C::new(0.0, 1.0);
            u[(i, i + 1)] = C::new(1.0, 0.0);
            u[(i + 1, i + 1)] = C::new(0.0, -1.0);
            for (k, s) in [(0, b), (1, -b)] {
                blocks.push(ModalBlock {
                    theta: C::new(a, s),
                    size: 1,
                    offset: i + k,
                });
            }
            i += 2;
        } else {
            j[(i, i)] = -1.0;
            u[(i, i)] = C::new(1.0, 0.0);
            blocks.push(ModalBlock {
                theta: C::new(-1.0, 0.0),
                size: 1,
                offset: i,
            });
            i += 1;
        }
    }
    let qc = q.map(|x| C::new(x, 0.0));
    let v = &qc * &u;
    let w = v.clone().try_inverse().expect("V invertible");
    let a = &q * &j * q.transpose();
    let b = rng.matrix(n, 2, 1.0);
    let c = rng.matrix(2, n, 1.0);
    let d = DMatrix::zeros(2, 2);
    let sys = ModalSystem::from_parts(blocks, v, w, &b, &c, &d).expect("shapes fit");
    (sys, a)
}

fn sizes() -> Vec<usize> {
    match std::env::var("EXACTLTI_BENCH_SIZES") {
        Ok(s) => s.split(',').filter_map(|x| x.trim().parse().ok()).collect(),
        Err(_) => vec![10, 20, 50, 100, 200],
    }
}

fn main() {
    let freqs: Vec<f64> = (0..200)
        .map(|k| 10f64.powf(-2.0 + 4.0 * k as f64 / 199.0))
        .collect();
    for n in sizes() {
        let (sys, a) = system(n);
        let breal = (&sys.v * &sys.bm).map(|z| z.re);
        let creal = (&sys.cm * &sys.w).map(|z| z.re);
        let d = DMatrix::zeros(2, 2);
        if common::selected("freqresp") {
            // the two paths agree before they are timed
            let g1 = freqresp([&a, &breal, &creal, &d], &freqs[..5], None).unwrap();
            let g2 = sys.freqresp(&freqs[..5]).unwrap();
            let err = g1
                .iter()
                .zip(&g2)
                .map(|(x, y)| (x - y).norm() / x.norm().max(1.0))
                .fold(0.0, f64::max);
            assert!(err < 1e-8, "n={n}: paths differ by {err}");
            let dense = common::bench(&format!("freqresp dense LU n={n}"), 3, 300.0, || {
                freqresp([&a, &breal, &creal, &d], &freqs, None).unwrap()
            });
            let modal = common::bench(&format!("freqresp jordan n={n}"), 3, 300.0, || {
                sys.freqresp(&freqs).unwrap()
            });
            println!(
                "freqresp ratio n={n}: dense / jordan = {:.1} (200 frequencies)",
                dense / modal
            );
        }
        if common::selected("stepping") {
            let h = 0.01;
            let phi = dense_transition(&a, h).unwrap();
            let phij = sys.transition(h);
            let x0: Vec<f64> = (0..n).map(|i| ((i % 7) as f64) - 3.0).collect();
            let z0 = sys.to_modal(&x0);
            let steps = 1000;
            let xv0 = nalgebra::DVector::from_vec(x0.clone());
            let c0 = creal.row(0).transpose();
            let dense = common::bench(&format!("stepping dense n={n}"), 3, 300.0, || {
                // x <- e^(Ah) x by nalgebra's gemv, y = C x
                let mut x = xv0.clone();
                let mut next = nalgebra::DVector::zeros(n);
                let mut y = 0.0;
                for _ in 0..steps {
                    next.gemv(1.0, &phi, &x, 0.0);
                    std::mem::swap(&mut x, &mut next);
                    y += c0.dot(&x);
                }
                y
            });
            let modal = common::bench(&format!("stepping jordan n={n}"), 3, 300.0, || {
                let mut z = z0.clone();
                let mut y = 0.0;
                for _ in 0..steps {
                    phij.step(&mut z);
                    y += (0..n).map(|k| sys.cm[(0, k)] * z[k]).sum::<C>().re;
                }
                y
            });
            println!(
                "stepping ratio n={n}: dense / jordan = {:.1} ({} of {} entries of e^(Jh) nonzero, 1000 steps)",
                dense / modal,
                phij.nonzeros(),
                n * n
            );
        }
    }
}
