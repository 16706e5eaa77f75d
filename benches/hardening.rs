//! Slow exact paths (issue 17 item 1): the corpus of `tests/data/hardening`
//! (`scripts/hardening_corpus.py`) through the command line, plus the everyday corpus's
//! Jordan-method `minreal` (issue 11 goal: <= 1 s).
//!
//! Cases: a 20x20 nilpotent matrix scrambled by a unimodular T (`zeros`, `check`,
//! `analyze`); planted integer structures n = 12..20 under a dense integer T (`zeros`,
//! `scb`); complex pairs under T = U diag(d) with 20-30 digit d (`jordan`); Rosenbrock at
//! n = 30, 40 with 20-digit entries; a dense 7x7 integer system (Jordan-method `minreal`).
//! Prints wall seconds (best of 2 when fast), the exit code and KB of output;
//! `cargo bench --bench hardening`. Each run is capped at 60 s (`--max-seconds 60`).

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

const CASES: &[(&str, &[&str])] = &[
    (
        "hardening/nilpotent_20",
        &["zeros", "scb", "check", "analyze", "jordan"],
    ),
    ("hardening/planted_12", &["zeros", "scb"]),
    ("hardening/planted_16", &["zeros", "scb"]),
    ("hardening/planted_20", &["zeros", "scb", "jordan"]),
    ("hardening/bigq_18", &["jordan", "zeros"]),
    ("hardening/bigq_36", &["jordan"]),
    (
        "hardening/rosen_30",
        &["minreal --method rosenbrock", "minreal --method kalman"],
    ),
    ("hardening/rosen_40", &["minreal --method rosenbrock"]),
    (
        "hardening/dense_7",
        &["minreal --method jordan", "jordan --real"],
    ),
    (
        "fuzz_jordan_marking",
        &["jordan --real", "minreal --method jordan", "mnf"],
    ),
    (
        "fuzz_slow_real_jordan",
        &["jordan --real", "minreal --method jordan"],
    ),
    ("everyday/random_8_siso", &["minreal --method jordan"]),
    ("everyday/random_12_siso", &["minreal --method jordan"]),
    ("everyday/random_12_mimo", &["minreal --method jordan"]),
    ("everyday/random_16_siso", &["minreal --method jordan"]),
    ("everyday/random_16_mimo", &["minreal --method jordan"]),
];

/// Runs the CLI; returns (best seconds, KB of stdout, exit code).
fn cli(args: &str, file: &Path) -> (f64, f64, i32) {
    let bin = env!("CARGO_BIN_EXE_exactlti");
    let mut best = (f64::INFINITY, 0.0, -1);
    for _ in 0..2 {
        let t = Instant::now();
        let out = Command::new(bin)
            .args(args.split_whitespace())
            .arg(file)
            .args(["--max-seconds", "60"])
            .output()
            .expect("run exactlti");
        let s = t.elapsed().as_secs_f64();
        if s < best.0 {
            best = (
                s,
                out.stdout.len() as f64 / 1024.0,
                out.status.code().unwrap_or(-1),
            );
        }
        if s > 5.0 {
            break;
        }
    }
    best
}

fn main() {
    let dir: PathBuf = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data");
    let only = std::env::args().nth(1).filter(|a| !a.starts_with('-'));
    println!(
        "# hardening: CLI wall seconds (exit code, KB of text)\n{:<28} {:<28} {:>9} {:>5} {:>9}",
        "case", "command", "seconds", "exit", "KB"
    );
    for (name, cmds) in CASES {
        if only.as_ref().is_some_and(|o| !name.contains(o.as_str())) {
            continue;
        }
        let file = dir.join(format!("{name}.json"));
        for cmd in *cmds {
            let (s, kb, code) = cli(cmd, &file);
            println!("{name:<28} {cmd:<28} {s:>9.3} {code:>5} {kb:>9.1}");
        }
    }
}
