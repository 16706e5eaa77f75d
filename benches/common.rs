//! Minimal bench harness shared by the bench binaries (no criterion: keeps CI builds light).
#![allow(dead_code)]

use std::time::Instant;

/// Runs `f` repeatedly (at least `min_reps` times and ~`budget_ms` in total), prints
/// `name: best ms (median ms, reps)` and returns the best time in milliseconds.
pub fn bench<T>(name: &str, min_reps: usize, budget_ms: f64, mut f: impl FnMut() -> T) -> f64 {
    let mut times = vec![];
    let start = Instant::now();
    while times.len() < min_reps
        || (start.elapsed().as_secs_f64() * 1e3 < budget_ms && times.len() < 1000)
    {
        let t = Instant::now();
        std::hint::black_box(f());
        times.push(t.elapsed().as_secs_f64() * 1e3);
    }
    times.sort_by(|a, b| a.partial_cmp(b).unwrap());
    let best = times[0];
    let median = times[times.len() / 2];
    println!(
        "{name}: {best:.3} ms (median {median:.3} ms, {} reps)",
        times.len()
    );
    best
}

/// Only run benches whose name contains the first CLI argument (if any, and not a flag).
pub fn selected(name: &str) -> bool {
    match std::env::args().skip(1).find(|a| !a.starts_with('-')) {
        Some(f) => name.contains(&f),
        None => true,
    }
}
