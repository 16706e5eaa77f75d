//! Balanced truncation on the float path against the exact Gramians: the Hankel singular
//! values squared are the eigenvalues of $W_c W_o$ (both Gramians solved exactly over Q),
//! on random stable systems with a fixed seed; the truncated system is balanced and its
//! frequency response within the bound $2 \sum_{i > r} \sigma_i$.

use exactlti::field::Q;
use exactlti::float::{balred, to_dmatrix};
use exactlti::matrix::Matrix;
use exactlti::realization::gramians;
use exactlti::system::StateSpace;
use nalgebra::{Complex, DMatrix};

fn response([a, b, c, d]: [&DMatrix<f64>; 4], w: f64) -> DMatrix<Complex<f64>> {
    let n = a.nrows();
    let cx = |m: &DMatrix<f64>| m.map(|x| Complex::new(x, 0.0));
    let m = DMatrix::<Complex<f64>>::identity(n, n) * Complex::new(0.0, w) - cx(a);
    let x = m.lu().solve(&cx(b)).unwrap();
    cx(c) * x + cx(d)
}

#[test]
fn hankel_singular_values_equal_the_exact_gramian_product() {
    let mut rng = exactlti::rng::SplitMix64(0x0bab_0028);
    let mut tested = 0;
    for case in 0..40 {
        let n = rng.int(2, 5) as usize;
        // A = -(n+2) I + small integers: stable by diagonal dominance
        let rows: Vec<Vec<i64>> = (0..n)
            .map(|i| {
                (0..n)
                    .map(|j| {
                        if i == j {
                            -(n as i64) - 2
                        } else {
                            rng.int(-1, 1)
                        }
                    })
                    .collect()
            })
            .collect();
        let m = |r: &Vec<Vec<i64>>| {
            Matrix::<Q>::from_i64_rows(&r.iter().map(Vec::as_slice).collect::<Vec<_>>())
        };
        let b: Vec<Vec<i64>> = (0..n).map(|_| vec![rng.int(-2, 2)]).collect();
        let c: Vec<Vec<i64>> = vec![(0..n).map(|_| rng.int(-2, 2)).collect()];
        let s = StateSpace::new(m(&rows), m(&b), m(&c), m(&vec![vec![0]])).unwrap();
        let g = gramians(&s).unwrap();
        let prod = exactlti::float::to_dmatrix(&(&g.wc * &g.wo)).unwrap();
        let mut eig: Vec<f64> = exactlti::float::eigenvalues(&prod)
            .unwrap()
            .iter()
            .map(|z| z.re.max(0.0).sqrt())
            .collect();
        eig.sort_by(|x, y| y.total_cmp(x));
        let f = |x: &Matrix<Q>| to_dmatrix(x).unwrap();
        let (fa, fb, fc, fd) = (f(&s.a), f(&s.b), f(&s.c), f(&s.d));
        let top = eig[0];
        let nonzero = eig.iter().filter(|x| **x > 1e-9 * top).count();
        if nonzero < 2 {
            continue;
        }
        let r = nonzero - 1;
        let red = balred([&fa, &fb, &fc, &fd], r).unwrap();
        for (x, y) in red.hankel_singular_values.iter().zip(&eig) {
            // squares: sqrt amplifies the round-off of the tiny ones
            assert!(
                (x * x - y * y).abs() <= 1e-8 * top * top,
                "case {case}: {x} vs {y}"
            );
        }
        for w in [0.0, 0.3, 1.0, 3.0, 30.0] {
            let e =
                response([&fa, &fb, &fc, &fd], w) - response([&red.a, &red.b, &red.c, &red.d], w);
            assert!(
                e.norm() <= red.error_bound * (1.0 + 1e-8) + 1e-12,
                "case {case}"
            );
        }
        tested += 1;
    }
    assert!(tested > 20, "{tested}");
}
