//! Exact realization benchmarks, with the float staircase on the same systems.
//!
//! Cases: the 10-DOF sliding masses (20 states, McMillan degree 8); the planted rational
//! non-minimal systems of `tests/common/systems.rs` (`planted(n, seed = n)`: 2 inputs,
//! 2 outputs, true McMillan degree n/2, hidden parts as large as the core, scrambled by an
//! integer unimodular similarity); and their `stiff` variants (`planted_scaled`, hidden
//! diagonal blocks times `EXACTLTI_HIDDEN_SCALE`, default 16), on which float staircases lose
//! the order. For each case: exact `minimal` by Kalman, Rosenbrock and Ho-Kalman (order and
//! `verified` printed; Rosenbrock only up to n = 20 and the others up to n = 60 unless
//! `EXACTLTI_BENCH_ALL=1`), then `exactlti::float::minreal` (default `Tol`) on the f64 image
//! of the same matrices, which is exact (every entry is a dyadic rational). Each system is
//! written to `target/realization-bench/<case>.txt` (the format of `benches/float.rs`) so
//! that `scripts/anchors/realization.py` times python-control on it.
//!
//! Output lines (parsed by the script):
//! - `case <case>: n <n>, true order <r>, file <path>`
//! - `<label>: <best> ms (median <ms> ms, <reps> reps)` (the harness line), then
//! - `result <label>: order <k>, verified <bool>` (exact) or
//!   `result <label>: order <k>, truth <Truth>` (float),
//!
//! with `<label>` = `exact minreal <method> <case-label>` or `float minreal <case-label>`.
//!
//! Run: `cargo bench --bench realization [FILTER]`; `EXACTLTI_BENCH_SIZES=10,20` restricts
//! the planted sizes. `cargo bench --bench realization stages` instead times the stages of the
//! exact Kalman and Ho-Kalman paths at n = 20 and 40 (`stage <what>: <ms> ms`).
#[path = "common.rs"]
mod common;
#[path = "../tests/common/systems.rs"]
mod systems;

use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::Instant;

use exactlti::field::Q;
use exactlti::float::{Tol, minreal as float_minreal, to_dmatrix};
use exactlti::realization::{
    MinrealMethod, controllability_matrix, hankel_matrix, is_controllable, is_observable,
    kalman_decomposition, mcmillan_degree, minimal, observability_matrix,
};
use exactlti::system::StateSpace;
use nalgebra::DMatrix;

const METHODS: [(&str, MinrealMethod); 3] = [
    ("kalman", MinrealMethod::Kalman),
    ("rosenbrock", MinrealMethod::Rosenbrock),
    ("ho-kalman", MinrealMethod::HoKalman),
];

fn out_dir() -> PathBuf {
    let target = std::env::var_os("CARGO_TARGET_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("target"));
    target.join("realization-bench")
}

fn write_matrix(out: &mut String, name: &str, m: &DMatrix<f64>) {
    let _ = writeln!(out, "{name} {} {}", m.nrows(), m.ncols());
    for i in 0..m.nrows() {
        let row: Vec<String> = (0..m.ncols()).map(|j| format!("{:e}", m[(i, j)])).collect();
        let _ = writeln!(out, "{}", row.join(" "));
    }
}

/// The f64 image `(A, B, C, D)`; every entry of the bench systems is exact in f64.
fn to_float(sys: &StateSpace<Q>) -> [DMatrix<f64>; 4] {
    [&sys.a, &sys.b, &sys.c, &sys.d].map(|m| to_dmatrix(m).expect("real entries"))
}

/// Whether an exact method runs on a case of size `n` whose family allows up to `family_max`
/// (everything with `EXACTLTI_BENCH_ALL=1`): Rosenbrock's staircase takes minutes at n = 40,
/// Kalman and Ho-Kalman most of a minute at n = 60.
fn exact_runs(m: MinrealMethod, n: usize, family_max: usize) -> bool {
    if std::env::var_os("EXACTLTI_BENCH_ALL").is_some() {
        return true;
    }
    let method_max = match m {
        MinrealMethod::Rosenbrock => 20,
        _ => usize::MAX,
    };
    n <= family_max.min(method_max)
}

/// One timed run.
fn timed<T>(name: &str, f: impl FnOnce() -> T) -> T {
    let t = Instant::now();
    let r = f();
    println!("stage {name}: {:.1} ms", t.elapsed().as_secs_f64() * 1e3);
    r
}

/// Where the exact Kalman and Ho-Kalman paths spend their time (run with the filter `stages`).
fn stages(label: &str, sys: &StateSpace<Q>) {
    let n = sys.nstates();
    let ctrb = timed(&format!("controllability matrix {label}"), || {
        controllability_matrix(&sys.a, &sys.b)
    });
    timed(&format!("column space of it {label}"), || {
        ctrb.column_space()
    });
    let obsv = timed(&format!("observability matrix {label}"), || {
        observability_matrix(&sys.a, &sys.c)
    });
    timed(&format!("null space of it {label}"), || obsv.nullspace());
    let kd = timed(&format!("kalman decomposition (all) {label}"), || {
        kalman_decomposition(sys).expect("valid")
    });
    timed(&format!("transform by T {label}"), || {
        sys.transform(&kd.t).expect("invertible")
    });
    let min = kd.minimal_part();
    timed(&format!("verify: min controllable {label}"), || {
        is_controllable(&min.a, &min.b)
    });
    timed(&format!("verify: min observable {label}"), || {
        is_observable(&min.a, &min.c)
    });
    timed(&format!("verify: original markov 2n {label}"), || {
        sys.markov(2 * n)
    });
    timed(&format!("verify: minimal markov 2n {label}"), || {
        min.markov(2 * n)
    });
    let h = timed(&format!("ho-kalman hankel H0 {label}"), || {
        hankel_matrix(sys, n, n, 0)
    });
    timed(&format!("ho-kalman rref H0 {label}"), || h.rref());
}

/// Benches every exact method and the float staircase on one system.
fn run_case(case: &str, label: &str, sys: &StateSpace<Q>, true_order: usize, exact_max: usize) {
    let n = sys.nstates();
    let f = to_float(sys);
    let mut text = String::new();
    for (name, m) in ["A", "B", "C", "D"].iter().zip(&f) {
        write_matrix(&mut text, name, m);
    }
    let path = out_dir().join(format!("{case}.txt"));
    let _ = std::fs::write(&path, text);
    println!(
        "case {case}: n {n}, true order {true_order}, file {}",
        path.display()
    );
    // at least `reps` runs and up to 1 s
    let reps = if n <= 20 { 3 } else { 1 };
    for (name, m) in METHODS {
        let label = format!("exact minreal {name} {label}");
        if !common::selected(&label) || !exact_runs(m, n, exact_max) {
            continue;
        }
        let mut last = None;
        common::bench(&label, reps, 1000.0, || {
            last = Some(minimal(sys, m).expect("valid system"));
        });
        let r = last.expect("ran once");
        println!("result {label}: order {}, verified {}", r.order, r.verified);
        assert_eq!(r.order, true_order, "{label}");
        assert!(r.verified, "{label}");
    }
    let label = format!("float minreal {label}");
    if common::selected(&label) {
        let tol = Tol::default();
        let mut last = None;
        common::bench(&label, 5, 300.0, || {
            last = Some(float_minreal(&f[0], &f[1], &f[2], &f[3], &tol).expect("valid system"));
        });
        let r = last.expect("ran once");
        println!("result {label}: order {}, truth {:?}", r.order, r.truth);
    }
}

fn main() {
    let _ = std::fs::create_dir_all(out_dir());
    if std::env::args().skip(1).any(|a| a == "stages") {
        for n in [20, 40] {
            stages(
                &format!("planted n={n}"),
                &systems::planted(n, n as u64).sys,
            );
        }
        return;
    }
    let sys = systems::sliding_masses();
    if common::selected("mcmillan") {
        common::bench("exact mcmillan degree sliding 20x20", 3, 500.0, || {
            mcmillan_degree(&sys)
        });
    }
    run_case("sliding", "sliding 20x20", &sys, 8, 20);
    let sizes: Vec<usize> = std::env::var("EXACTLTI_BENCH_SIZES")
        .ok()
        .map(|s| s.split(',').filter_map(|x| x.trim().parse().ok()).collect())
        .unwrap_or_else(|| vec![10, 20, 40, 60, 100]);
    let scale: i64 = std::env::var("EXACTLTI_HIDDEN_SCALE")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(16);
    for n in &sizes {
        let n = *n;
        let label = format!("planted n={n}");
        let pl = systems::planted(n, n as u64);
        run_case(&format!("planted_{n}"), &label, &pl.sys, pl.order, 60);
    }
    for n in &sizes {
        let n = *n;
        let label = format!("stiff n={n}");
        let pl = systems::planted_scaled(n, n as u64, scale);
        run_case(&format!("stiff_{n}"), &label, &pl.sys, pl.order, 60);
    }
}
