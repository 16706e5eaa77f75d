//! Jordan decomposition timings (release, std::time). Cases as in
//! /work/shared/anchors/cases.py: the seed 3x3, point-mass A2, single-wheel yaw plane, the
//! 3x3 of SymPy issue 24942, the 10-DOF sliding masses, planted A = P J P^-1 (n = 8..64).
//! Prints `case<TAB>seconds` lines (median of repeats).

use exactlti::field::{Q, Rational};
use exactlti::jordan::jordan;
use exactlti::matrix::Matrix;
use exactlti::qmat;
use std::time::Instant;

fn r(n: i64, d: i64) -> Rational {
    Rational::new(n.into(), d.into())
}

#[path = "../tests/common/systems.rs"]
mod systems;
use systems::PlantRng as Rng;

fn sliding_masses() -> Matrix<Q> {
    systems::sliding_masses().a
}

/// Same distribution as cases.planted_jordan (not the same random stream).
fn planted(n: usize, seed: u64) -> Matrix<Q> {
    let mut rng = Rng::new(seed);
    let evs = [r(0, 1), r(-1, 1), r(2, 1), r(-3, 1), r(1, 2)];
    let mut j = Matrix::zeros(Q, n, n);
    let mut size = 0;
    while size < n {
        let k = [1, 1, 2, 3][rng.int(0, 3) as usize].min(n - size);
        let lam = evs[rng.int(0, 4) as usize].clone();
        for i in 0..k {
            j.set(size + i, size + i, lam.clone());
            if i + 1 < k {
                j.set(size + i, size + i + 1, r(1, 1));
            }
        }
        size += k;
    }
    loop {
        let p = Matrix::from_fn(Q, n, n, |_, _| {
            Rational::from_integer(rng.int(-2, 2).into())
        });
        if let Ok(pi) = p.inverse() {
            return &(&p * &j) * &pi;
        }
    }
}

fn time(label: &str, a: &Matrix<Q>, reps: usize) {
    let mut ts = vec![];
    for _ in 0..reps {
        let t0 = Instant::now();
        let jf = jordan(a).expect("jordan");
        ts.push(t0.elapsed().as_secs_f64());
        assert!(jf.verified, "{label}: not verified");
    }
    ts.sort_by(f64::total_cmp);
    println!("{label}\t{:.6}", ts[ts.len() / 2]);
}

fn main() {
    let only: Option<String> = std::env::args().nth(1).filter(|s| !s.starts_with('-'));
    let want = |l: &str| only.as_ref().is_none_or(|o| l.contains(o.as_str()));
    let cases: Vec<(&str, Matrix<Q>, usize)> = vec![
        ("seed 3x3", qmat![[-2, 0, 0], [0, 0, 1], [0, -2, -2]], 20),
        (
            "point-mass A2 4x4",
            qmat![[0, 0, 1, 0], [0, 0, 0, 1], [-1, 0, -2, 0], [0, 0, 0, 0]],
            20,
        ),
        (
            "yaw-plane single wheel 4x4",
            Matrix::from_rows(
                Q,
                vec![
                    vec![r(0, 1), r(20, 1), r(-1, 1), r(0, 1)],
                    vec![r(0, 1), r(0, 1), r(0, 1), r(-1, 1)],
                    vec![r(0, 1), r(0, 1), r(-8, 3), r(-20, 1)],
                    vec![r(0, 1), r(0, 1), r(0, 1), r(0, 1)],
                ],
            )
            .unwrap(),
            20,
        ),
        (
            "sympy issue 24942 3x3",
            qmat![[-3, 1, 2], [1, -1, 0], [1, 0, -2]],
            20,
        ),
        ("sliding masses 20x20", sliding_masses(), 5),
        ("planted n=8", planted(8, 8), 5),
        ("planted n=12", planted(12, 12), 5),
        ("planted n=16", planted(16, 16), 3),
        ("planted n=24", planted(24, 24), 3),
        ("planted n=64", planted(64, 64), 1),
    ];
    for (label, a, reps) in cases {
        if want(label) {
            time(label, &a, reps);
        }
    }
}
