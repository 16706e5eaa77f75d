//! Factorization over Q: wall-clock timings (release build, std::time).
//!
//! `cargo bench --bench factor` prints one line per case, `name: X ms` (the median of
//! repeated runs), and writes the case polynomials to `target/factor-bench-cases.txt`
//! (`name<TAB>polynomial` per line) so `scripts/anchors/factor.py` can time SymPy and FLINT
//! on exactly the same inputs.

use exactlti::poly::factor::{factor_zpoly, factor_zpoly_zassenhaus, is_irreducible};
use exactlti::poly::zpoly::ZPoly;
use num_bigint::BigInt;
use num_traits::One;
use std::hint::black_box;
use std::time::{Duration, Instant};

#[path = "../tests/common/polys.rs"]
mod polys;
use polys::swinnerton_dyer;

use exactlti::rng::SplitMix64 as SplitMix;

/// Product of `k` random irreducible polynomials of degree `n` with 64-bit coefficients.
fn random_product(seed: u64, k: usize, n: usize) -> ZPoly {
    let mut rng = SplitMix(seed);
    let mut f = ZPoly::one();
    let mut found = 0;
    while found < k {
        let c: Vec<BigInt> = (0..=n)
            .map(|_| {
                let v = BigInt::from(rng.next_u64());
                if rng.next_u64() & 1 == 1 { -v } else { v }
            })
            .collect();
        let g = ZPoly::new(c);
        if g.deg0() == n && is_irreducible(&g) {
            f = &f * &g;
            found += 1;
        }
    }
    f
}

fn sliding_charpoly() -> ZPoly {
    let s2 = |c: i64| ZPoly::from_i64s(&[c, 0, 1]);
    let base = s2(1) * s2(2) * s2(3) * ZPoly::from_i64s(&[1, 0, 4, 0, 1]);
    &base * &base
}

/// Median wall time over at least 3 runs and about 0.5 s.
fn time(f: &ZPoly, run: fn(&ZPoly) -> usize) -> Duration {
    let mut times = Vec::new();
    let start = Instant::now();
    while times.len() < 3 || (start.elapsed() < Duration::from_millis(500) && times.len() < 1000) {
        let t = Instant::now();
        black_box(run(black_box(f)));
        times.push(t.elapsed());
    }
    times.sort();
    times[times.len() / 2]
}

/// A timed operation; returns the number of factors (kept alive against optimization).
type Run = fn(&ZPoly) -> usize;

fn main() {
    let x120 = ZPoly::monomial(BigInt::one(), 120) - ZPoly::one();
    let cases: Vec<(&str, ZPoly, Run)> = vec![
        ("sliding_charpoly", sliding_charpoly(), |f| {
            factor_zpoly(f).unwrap().1.len()
        }),
        ("x^120-1", x120.clone(), |f| {
            factor_zpoly(f).unwrap().1.len()
        }),
        ("x^120-1 (zassenhaus, no cyclotomic shortcut)", x120, |f| {
            factor_zpoly_zassenhaus(f).unwrap().1.len()
        }),
        ("swinnerton_dyer_8", swinnerton_dyer(&[2, 3, 5]), |f| {
            factor_zpoly(f).unwrap().1.len()
        }),
        ("swinnerton_dyer_16", swinnerton_dyer(&[2, 3, 5, 7]), |f| {
            factor_zpoly(f).unwrap().1.len()
        }),
        (
            "random_4x_deg12_64bit",
            random_product(0xBE7C4, 4, 12),
            |f| factor_zpoly(f).unwrap().1.len(),
        ),
    ];
    let mut dump = String::new();
    for (name, f, run) in &cases {
        let d = time(f, *run);
        println!("{name}: {:.3} ms", d.as_secs_f64() * 1e3);
        dump.push_str(&format!("{name}\t{f}\n"));
    }
    let dir = std::env::var("CARGO_TARGET_DIR").unwrap_or_else(|_| "target".into());
    let path = std::path::Path::new(&dir).join("factor-bench-cases.txt");
    if let Err(e) = std::fs::write(&path, dump) {
        eprintln!("could not write {}: {e}", path.display());
    }
}
