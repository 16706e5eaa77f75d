//! Everyday models (issue 11): the corpus of `tests/data/everyday` (quarter car, damped
//! chains, sliding masses with dashpots, dense random integer systems n = 6..16).
//!
//! For each case: library timings of the complex Jordan form, the real form (compact) and
//! the Jordan-method minimal realization, and the command line (`jordan --real`,
//! `minreal --method jordan`, `analyze`) as wall time and size of the text output. Goals:
//! `analyze` <= 2 s and <= 200 KB, `jordan --real` <= 1 s, Jordan-method `minreal` <= 1 s,
//! all verified. Prints one line per case (best of repeats); `cargo bench --bench everyday`.

use exactlti::io::load_system_path;
use exactlti::jordan::jordan;
use exactlti::realization::minimal_jordan;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

const CASES: [&str; 11] = [
    "quarter_car",
    "damped_chain_3",
    "damped_chain_5_mimo",
    "sliding_masses_damped",
    "random_6_siso",
    "random_8_siso",
    "random_8_mimo",
    "random_12_siso",
    "random_12_mimo",
    "random_16_siso",
    "random_16_mimo",
];

fn best<T>(reps: usize, mut f: impl FnMut() -> T) -> (f64, T) {
    let mut out = None;
    let mut best = f64::INFINITY;
    for _ in 0..reps {
        let t = Instant::now();
        let r = f();
        best = best.min(t.elapsed().as_secs_f64());
        out = Some(r);
    }
    (best, out.expect("reps >= 1"))
}

/// Runs the CLI with a 20 s cap; returns (seconds, bytes of stdout, exit code).
fn cli(args: &[&str], file: &Path) -> (f64, usize, i32) {
    let bin = env!("CARGO_BIN_EXE_exactlti");
    let mut best = (f64::INFINITY, 0, -1);
    for _ in 0..2 {
        let t = Instant::now();
        let out = Command::new(bin)
            .args(args)
            .arg(file)
            .args(["--max-seconds", "20"])
            .output()
            .expect("run exactlti");
        let s = t.elapsed().as_secs_f64();
        if s < best.0 {
            best = (s, out.stdout.len(), out.status.code().unwrap_or(-1));
        }
        if s > 10.0 {
            break;
        }
    }
    best
}

fn main() {
    let dir: PathBuf = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/everyday");
    println!(
        "# everyday models: library best-of seconds, CLI wall seconds / KB of text (exit code)\n\
         {:<24} {:>3} {:>9} {:>9} {:>9} | {:>16} {:>16} {:>18}",
        "case", "n", "jordan", "real", "minreal", "jordan --real", "minreal jordan", "analyze"
    );
    for name in CASES {
        let file = dir.join(format!("{name}.json"));
        let l = load_system_path(&file).expect("corpus file");
        let sys = l.rational().expect("rational").ss.clone();
        let reps = if sys.nstates() >= 12 { 2 } else { 5 };
        let (tj, jf) = best(reps, || jordan(&sys.a).expect("jordan"));
        let (tr, rf) = best(reps, || jf.real_form().expect("real form"));
        let (tm, jm) = best(reps, || minimal_jordan(&sys).expect("minreal"));
        assert!(
            jf.verified && rf.verified && rf.exact && jm.verified,
            "{name}"
        );
        let fmt = |(s, b, c): (f64, usize, i32)| {
            format!("{s:>7.3} s {:>5.0} KB ({c})", b as f64 / 1024.0)
        };
        let r = cli(&["jordan", "--real"], &file);
        let m = cli(&["minreal", "--method", "jordan"], &file);
        let a = cli(&["analyze"], &file);
        println!(
            "{name:<24} {:>3} {tj:>9.4} {tr:>9.4} {tm:>9.4} | {} {} {}",
            sys.nstates(),
            fmt(r),
            fmt(m),
            fmt(a)
        );
    }
}
