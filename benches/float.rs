//! Float backend benchmarks (plain `harness = false`, std::time).
//!
//! minreal on the random non-minimal family of `exactlti::float::random::random_nonminimal`
//! (n = 50, 100, 200, 400; 2 inputs, 2 outputs; seed = n). The systems are also written to
//! `target/float-bench/sys_<n>.txt` so that `scripts/anchors/float_minreal.py` times
//! python-control's minreal on exactly the same matrices.
//!
//! Output lines (parsed by the script):
//! `float minreal n=<n>: <best ms> ms (order <k>, expected <nm>, truth <t>)`.
//!
//! Environment: `EXACTLTI_BENCH_SIZES=50,100` restricts the sizes.

use std::fmt::Write as _;
use std::hint::black_box;
use std::path::PathBuf;
use std::time::Instant;

use exactlti::float::random::random_nonminimal;
use exactlti::float::{
    Tol, eigenvalues, era, invariant_zeros, jordan_guess, markov_parameters, minreal,
};
use nalgebra::DMatrix;

fn best_ms<T>(reps: usize, mut f: impl FnMut() -> T) -> (f64, T) {
    let mut best = f64::INFINITY;
    let mut last = None;
    for _ in 0..reps.max(1) {
        let t = Instant::now();
        let r = f();
        best = best.min(t.elapsed().as_secs_f64() * 1e3);
        last = Some(r);
    }
    (best, last.expect("at least one repetition"))
}

fn write_matrix(out: &mut String, name: &str, m: &DMatrix<f64>) {
    let _ = writeln!(out, "{name} {} {}", m.nrows(), m.ncols());
    for i in 0..m.nrows() {
        let row: Vec<String> = (0..m.ncols()).map(|j| format!("{:e}", m[(i, j)])).collect();
        let _ = writeln!(out, "{}", row.join(" "));
    }
}

fn out_dir() -> PathBuf {
    let target = std::env::var_os("CARGO_TARGET_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("target"));
    target.join("float-bench")
}

fn main() {
    let sizes: Vec<usize> = std::env::var("EXACTLTI_BENCH_SIZES")
        .ok()
        .map(|s| s.split(',').filter_map(|x| x.trim().parse().ok()).collect())
        .unwrap_or_else(|| vec![50, 100, 200, 400]);
    let dir = out_dir();
    let _ = std::fs::create_dir_all(&dir);
    let tol = Tol::default();
    for &n in &sizes {
        let sys = random_nonminimal(n, 2, 2, n as u64);
        let mut text = String::new();
        write_matrix(&mut text, "A", &sys.a);
        write_matrix(&mut text, "B", &sys.b);
        write_matrix(&mut text, "C", &sys.c);
        write_matrix(&mut text, "D", &sys.d);
        let _ = std::fs::write(dir.join(format!("sys_{n}.txt")), text);
        let reps = match n {
            0..=60 => 200,
            61..=120 => 30,
            121..=250 => 8,
            _ => 3,
        };
        let (ms, r) = best_ms(reps, || {
            minreal(
                black_box(&sys.a),
                black_box(&sys.b),
                black_box(&sys.c),
                black_box(&sys.d),
                &tol,
            )
            .expect("valid system")
        });
        println!(
            "float minreal n={n}: {ms:.3} ms (order {}, expected {}, truth {:?})",
            r.order, sys.minimal_order, r.truth
        );
    }
    // Secondary figures (not compared): eigenvalues, Jordan guess, ERA, zeros at n = 100.
    let sys = random_nonminimal(100, 2, 2, 100);
    let (ms, _) = best_ms(5, || eigenvalues(black_box(&sys.a)).expect("square"));
    println!("float eigenvalues n=100: {ms:.3} ms");
    let small = random_nonminimal(40, 2, 2, 40);
    let (ms, j) = best_ms(3, || {
        jordan_guess(black_box(&small.a), &tol).expect("square")
    });
    println!(
        "float jordan_guess n=40: {ms:.3} ms ({} clusters)",
        j.clusters.len()
    );
    let (ms, z) = best_ms(5, || {
        invariant_zeros(&sys.a, &sys.b, &sys.c, &sys.d, &tol).expect("valid system")
    });
    println!(
        "float invariant_zeros n=100: {ms:.3} ms ({} zeros)",
        z.len()
    );
    let h = markov_parameters(&small.a, &small.b, &small.c, &small.d, 61).expect("valid");
    let (ms, r) = best_ms(5, || era(black_box(&h), None, &tol).expect("valid"));
    println!(
        "float era 60 moments (n=40 system): {ms:.3} ms (order {})",
        r.order
    );
}
