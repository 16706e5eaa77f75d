//! Parameter studies (issue 15): `cargo bench --bench study`.
//!
//! Targets on this machine: `sweep` of the 4-state bicycle with 20,000 speeds <= 2 s;
//! `critical` for the bicycle on [0, 10] <= 200 ms; a 20-state damped sliding-mass chain
//! swept over a stiffness scale with 2,000 points <= 5 s. `scripts/anchors/study.py` runs a
//! numpy eigenvalue loop over the same points and prints ratios. Output lines:
//! `case <name> <best ms>`.

use exactlti::field::{Field, Rational};
use exactlti::matrix::Matrix;
use exactlti::ratfunc::{RatFunc, RatFuncField};
use exactlti::study::{ParamFamily, critical_values, sweep, sweep_values};
use std::path::Path;
use std::time::Instant;

fn best_ms(reps: usize, mut f: impl FnMut()) -> f64 {
    (0..reps)
        .map(|_| {
            let t = Instant::now();
            f();
            t.elapsed().as_secs_f64() * 1e3
        })
        .fold(f64::INFINITY, f64::min)
}

fn qs() -> RatFuncField {
    RatFuncField::new(&["s"]).expect("a symbol")
}

fn rf(s: &str) -> RatFunc {
    qs().parse(s).expect("valid")
}

/// Ten masses in a chain, wall at the left: m_i = 1 + i/10, springs s (1 + i), dampers
/// (i + 1)/10 (the same formulas as `scripts/anchors/study.py`).
#[allow(clippy::needless_range_loop)] // symmetric index pairs (i, i - 1)
pub fn chain(n: usize) -> ParamFamily {
    let z = || rf("0");
    let mut m = vec![vec![z(); n]; n];
    let mut l = vec![vec![z(); n]; n];
    let mut k = vec![vec![z(); n]; n];
    for i in 0..n {
        m[i][i] = rf(&format!("1 + {i}/10"));
        // spring/damper i joins mass i to mass i-1 (or the wall)
        let (ks, cs) = (format!("s*{}", i + 1), format!("{}/10", i + 1));
        let add = |x: &mut Vec<Vec<RatFunc>>, a: usize, b: usize, e: &str, sign: &str| {
            x[a][b] = qs().add(&x[a][b], &rf(&format!("{sign}({e})")));
        };
        add(&mut k, i, i, &ks, "");
        add(&mut l, i, i, &cs, "");
        if i > 0 {
            add(&mut k, i - 1, i - 1, &ks, "");
            add(&mut k, i, i - 1, &ks, "-");
            add(&mut k, i - 1, i, &ks, "-");
            add(&mut l, i - 1, i - 1, &cs, "");
            add(&mut l, i, i - 1, &cs, "-");
            add(&mut l, i - 1, i, &cs, "-");
        }
    }
    let mat = |rows| Matrix::from_rows(qs(), rows).expect("rectangular");
    ParamFamily::second_order("s", mat(m), mat(l), mat(k)).expect("square")
}

fn main() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("data/bicycle-whipple.json");
    let bike = ParamFamily::from_file(&path, "v").expect("bicycle");
    let vals = sweep_values(0.0, 10.0, 20_000);
    let t = best_ms(3, || {
        sweep(&bike, &vals, None).expect("sweep");
    });
    println!("case bicycle_sweep_20000 {t:.1}   (target <= 2000 ms)");
    let (a, b) = (
        Rational::from_integer(0.into()),
        Rational::from_integer(10.into()),
    );
    let t = best_ms(5, || {
        let cv = critical_values(&bike, &a, &b).expect("critical");
        assert_eq!(cv.critical.len(), 3);
    });
    println!("case bicycle_critical {t:.1}   (target <= 200 ms)");
    let fam = chain(10);
    let vals = sweep_values(0.1, 10.0, 2_000);
    let t = best_ms(3, || {
        let r = sweep(&fam, &vals, None).expect("sweep");
        assert_eq!(r.eigenvalues[0].len(), 20);
    });
    println!("case chain20_sweep_2000 {t:.1}   (target <= 5000 ms)");
    println!("threads {}", rayon::current_num_threads());
}
