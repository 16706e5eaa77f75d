//! The Whipple bicycle benchmark (Meijaard et al. 2007) along its forward speed $v$:
//! $M q'' + v C_1 q' + (g K_0 + v^2 K_2) q = f$, $q = (\varphi, \delta)$.
//!
//! Exact critical speeds on $[0, 10]$ m/s (weave speed: imaginary pair, capsize speed: zero
//! eigenvalue, and where the weave pair's real eigenvalues coincide), the self-stable
//! speed range with 30 digits, and an SVG sweep plot of the eigenvalues (like the paper's
//! Fig. 3) written to `target/bicycle_sweep.svg`.
//!
//! Run: `cargo run --release --example bicycle_study`

use exactlti::field::Rational;
use exactlti::study::{CriticalKind, ParamFamily, critical_values, sweep, sweep_values};
use std::path::Path;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("data/bicycle-whipple.json");
    let fam = ParamFamily::from_file(&path, "v")?;
    let t = std::time::Instant::now();
    let cv = critical_values(
        &fam,
        &Rational::from_integer(0.into()),
        &Rational::from_integer(10.into()),
    )?;
    println!(
        "critical speeds on [0, 10] m/s ({:.1} ms, verified: {}):",
        t.elapsed().as_secs_f64() * 1e3,
        cv.verified
    );
    for c in &cv.critical {
        let (d, _) = c.value.digits(30);
        println!("  v = {d:<34} {}", c.kind.name());
        println!("      minimal polynomial: {}", c.value.minpoly());
        for e in &c.eigenvalues_at {
            println!(
                "      eigenvalue {:+.6} {:+.6}i  multiplicity {}  blocks {:?}",
                e.approx.0, e.approx.1, e.multiplicity, e.blocks
            );
        }
    }
    for (r, why) in &cv.rejected {
        println!(
            "  rejected root of the Hurwitz determinant v = {}: {why}",
            r.digits(12).0
        );
    }
    println!("intervals:");
    for iv in &cv.intervals {
        println!(
            "  ({:>10}, {:>10}) stable: {:5}  unstable eigenvalues: {}  {:?}",
            iv.from.digits(8).0,
            iv.to.digits(8).0,
            iv.stable,
            iv.counts.unstable(),
            iv.counts
        );
    }
    let stable: Vec<_> = cv.intervals.iter().filter(|i| i.stable).collect();
    for s in &stable {
        println!(
            "self-stable speed range: {} < v < {} m/s",
            s.from.digits(30).0,
            s.to.digits(30).0
        );
    }
    let weave = cv
        .critical
        .iter()
        .find(|c| c.kind == CriticalKind::ImaginaryPair);
    if let Some(w) = weave {
        println!(
            "weave speed {} m/s, weave frequency {:.6} rad/s",
            w.value.digits(30).0,
            w.omega.unwrap_or(f64::NAN)
        );
    }
    let vals = sweep_values(0.0, 10.0, 401);
    let sw = sweep(&fam, &vals, None)?;
    let out = Path::new(env!("CARGO_MANIFEST_DIR")).join("target/bicycle_sweep.svg");
    let title = fam.name.clone().unwrap_or_else(|| "bicycle".into());
    let marks: Vec<(f64, String)> = cv
        .critical
        .iter()
        .map(|c| (c.value.approx().0, c.kind.name().replace('_', " ")))
        .collect();
    std::fs::write(
        &out,
        exactlti::report::plot::sweep::sweep_svg(&sw, &title, "v [m/s]", &marks),
    )?;
    println!("sweep plot: {}", out.display());
    Ok(())
}
