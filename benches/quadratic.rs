//! Timings over quadratic fields (release, std::time): the dense 10x10 over Q(i) with an
//! irreducible characteristic polynomial of degree 10 (`jordan`, and the `minreal --method
//! jordan` realization of that A with one input and one output), and `tf` of an 8-state
//! 2x2 system over Q(i) (transfer matrix, Kalman realization, Markov check, the report's
//! poles, zeros and zpk factorizations over K). Entries `a + b*i` with integers a, b in
//! -5..=5 from a fixed xorshift stream. Prints `case<TAB>seconds` lines (median of repeats);
//! an argument keeps the cases whose label contains it.
//!
//! `charpoly|det dense N QQ(sqrt2) generic|kernel` (N = 2, 3, 5, 10, 20, 40): `Matrix::charpoly` /
//! `Matrix::det` (the field's multi-modular kernels, `qkernels::modular::quadratic`) beside
//! the generic algorithms they replaced (`charpoly_hessenberg`, `det_gauss`), entries
//! `a + b*sqrt(2)` with |a| <= 9, |b| <= 5 (as `scripts/anchors/quadratic_matrix.py`); the
//! generic 40x40 charpoly takes tens of seconds (one repetition), filter it out with an
//! argument (e.g. `kernel`) for a quick run. Each pair is checked equal.
//!
//! 2026-11-24 21:27 UTC, load average ~3 on 2 shared cores: jordan 10x10 0.16 s, minreal
//! --method jordan 0.18 s, tf 8-state 0.18-0.21 s. The CLI on inputs of the same distribution
//! (best of 3) before this kernel work: jordan 3.95 s, minreal 4.25 s, tf 1.44 s.

use exactlti::field::{Quadratic, QuadraticField, Rational};
use exactlti::jordan::jordan_over as jordan_over_k;
use exactlti::matrix::Matrix;
use exactlti::qkernels::modular::quadratic::{charpoly_quadratic, det_quadratic};
use exactlti::realization::minimal_jordan;
use exactlti::realization::realize_state_space;
use exactlti::report::sections::tf_report;
use exactlti::system::StateSpace;
use exactlti::system::discrete::stability::Domain;
use std::time::Instant;

struct Rng(u64);

impl Rng {
    fn int(&mut self, lo: i64, hi: i64) -> i64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        lo + (self.0 % (hi - lo + 1) as u64) as i64
    }
}

fn random(k: &QuadraticField, rng: &mut Rng, m: usize, n: usize) -> Matrix<QuadraticField> {
    Matrix::from_fn(k.clone(), m, n, |_, _| {
        let a = Rational::from_integer(rng.int(-5, 5).into());
        let b = Rational::from_integer(rng.int(-5, 5).into());
        Quadratic::new(a, b)
    })
}

fn system(n: usize, p: usize, seed: u64) -> StateSpace<QuadraticField> {
    let k = QuadraticField::gaussian();
    let mut rng = Rng(seed);
    let a = random(&k, &mut rng, n, n);
    let b = random(&k, &mut rng, n, p);
    let c = random(&k, &mut rng, p, n);
    StateSpace::new_strictly_proper(a, b, c).expect("shapes")
}

fn time(label: &str, reps: usize, mut f: impl FnMut() -> bool) {
    let mut ts = vec![];
    for _ in 0..reps {
        let t0 = Instant::now();
        let ok = f();
        ts.push(t0.elapsed().as_secs_f64());
        assert!(ok, "{label}: not verified");
    }
    ts.sort_by(f64::total_cmp);
    println!("{label}\t{:.6}", ts[ts.len() / 2]);
}

/// Dense `n x n` over Q(sqrt 2), entries `a + b sqrt 2` with |a| <= 9, |b| <= 5.
fn dense_sqrt2(n: usize, seed: u64) -> Matrix<QuadraticField> {
    let k = QuadraticField::new(2).expect("Q(sqrt 2)");
    let mut rng = Rng(seed);
    Matrix::from_fn(k, n, n, |_, _| {
        let a = Rational::from_integer(rng.int(-9, 9).into());
        let b = Rational::from_integer(rng.int(-5, 5).into());
        Quadratic::new(a, b)
    })
}

/// Generic algorithm vs the field's kernel (charpoly and det) on dense matrices; the kernel
/// is called directly (`Matrix::charpoly` / `det` take it from `MODULAR_MIN_N` rows on).
fn kernels_vs_generic(want: &dyn Fn(&str) -> bool) {
    for n in [2usize, 3, 5, 10, 20, 40] {
        let a = dense_sqrt2(n, 0x5DEE_CE66_D1CE_4E5B ^ n as u64);
        let (d, v) = (a.field().d().clone(), a.as_slice());
        let reps = if n >= 40 { 1 } else { 5 };
        let kernel = charpoly_quadratic(&d, n, v);
        assert_eq!(a.charpoly().expect("square").coeffs(), &kernel[..]);
        let label = format!("charpoly dense {n} QQ(sqrt2) kernel");
        if want(&label) {
            time(&label, 5, || charpoly_quadratic(&d, n, v) == kernel);
        }
        let label = format!("charpoly dense {n} QQ(sqrt2) generic");
        if want(&label) {
            time(&label, reps, || {
                a.charpoly_hessenberg().expect("square").coeffs() == &kernel[..]
            });
        }
        let det = det_quadratic(&d, n, v);
        assert_eq!(a.det().expect("square"), det);
        let label = format!("det dense {n} QQ(sqrt2) kernel");
        if want(&label) {
            time(&label, 5, || det_quadratic(&d, n, v) == det);
        }
        let label = format!("det dense {n} QQ(sqrt2) generic");
        if want(&label) {
            time(&label, reps, || a.det_gauss().expect("square") == det);
        }
    }
}

fn main() {
    let only: Option<String> = std::env::args().nth(1).filter(|s| !s.starts_with('-'));
    let want = |l: &str| only.as_ref().is_none_or(|o| l.contains(o.as_str()));
    kernels_vs_generic(&want);
    let dense = system(10, 1, 0x9E37_79B9_7F4A_7C15);
    if want("jordan dense 10x10 QQ(i)") {
        time("jordan dense 10x10 QQ(i)", 5, || {
            jordan_over_k(&dense.a).expect("jordan").verified
        });
    }
    if want("minreal jordan dense 10x10 QQ(i)") {
        time("minreal jordan dense 10x10 QQ(i)", 3, || {
            minimal_jordan(&dense).expect("minreal").verified
        });
    }
    if want("tf 8-state 2x2 QQ(i)") {
        let s = system(8, 2, 0x2545_F491_4F6C_DD1D);
        time("tf 8-state 2x2 QQ(i)", 3, || {
            let g = s.transfer_matrix().expect("transfer matrix");
            let r = realize_state_space(&s, &g).expect("realization");
            let markov = Some(g.matches_markov(&s));
            let rep = tf_report(&g, &r, markov, Domain::Continuous).expect("report");
            r.verified
                && matches!(
                    rep.get("verified"),
                    Some(exactlti::report::Value::Bool(true))
                )
        });
    }
}
