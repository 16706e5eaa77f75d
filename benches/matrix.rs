//! Exact matrix kernels over Q: timings of the benchmark cases of issue 3.
//!
//! Run with `cargo bench --bench matrix` (release). One line per case, `name: X ms`, the best
//! of a few repetitions. The matrices come from a 64-bit LCG shared with
//! `scripts/anchors/matrix.py`, so the Python anchors time the very same inputs:
//! `x <- (6364136223846793005 x + 1442695040888963407) mod 2^64`, entry
//! `((x >> 33) mod 19) - 9` in -9..9.
//!
//! Cases: rank, rref, null space of `L R` with `L` 100x50 and `R` 50x200 (rank 50, factor
//! entries -9..9); det, charpoly, inverse of a 100x100 matrix with entries -9..9. Extra
//! lines compare the algorithms (`*_bareiss`, `*_berkowitz`) on smaller sizes.

use exactlti::field::Rational;
use exactlti::matrix::over_q as oq;
use exactlti::qkernels as qk;
use exactlti::qkernels::{fraction_free as ff, modular as mm};
use exactlti::rng::Lcg64;
use std::hint::black_box;
use std::time::Instant;

struct Lcg(Lcg64);

impl Lcg {
    fn entry(&mut self) -> i64 {
        (self.0.next_u31() % 19) as i64 - 9
    }
    fn matrix(&mut self, m: usize, n: usize) -> Vec<i64> {
        (0..m * n).map(|_| self.entry()).collect()
    }
}

fn matmul(m: usize, k: usize, n: usize, a: &[i64], b: &[i64]) -> Vec<i64> {
    let mut c = vec![0i64; m * n];
    for i in 0..m {
        for l in 0..k {
            for j in 0..n {
                c[i * n + j] += a[i * k + l] * b[l * n + j];
            }
        }
    }
    c
}

fn to_q(a: &[i64]) -> Vec<Rational> {
    a.iter()
        .map(|&x| Rational::from_integer(x.into()))
        .collect()
}

fn time<T>(name: &str, reps: usize, mut f: impl FnMut() -> T) {
    if let Ok(filter) = std::env::var("BENCH_FILTER")
        && !name.contains(&filter)
    {
        return;
    }
    let mut best = f64::INFINITY;
    for _ in 0..reps {
        let t = Instant::now();
        black_box(f());
        best = best.min(t.elapsed().as_secs_f64());
    }
    println!("{name}: {:.3} ms", best * 1e3);
}

fn main() {
    let mut g = Lcg(Lcg64(20240601));
    let l = g.matrix(100, 50);
    let r = g.matrix(50, 200);
    let low = to_q(&matmul(100, 50, 200, &l, &r));
    let sq = to_q(&g.matrix(100, 100));
    let reps = 5;
    if std::env::var("KERNELS").is_ok() {
        kernels(&sq, &low);
        return;
    }
    if std::env::var("SWEEP_ONLY").is_ok() {
        sweep();
        return;
    }

    let det = oq::det_q(100, &sq);
    let check = det.numer() % num_bigint::BigInt::from(1_000_000_007u64);
    let check = (check + 1_000_000_007u64) % 1_000_000_007u64;
    println!("check det100 mod 1000000007: {check}");
    time("rank 100x200 r50", reps, || oq::rank_q(100, 200, &low));
    time("rref 100x200 r50", reps, || oq::rref_q(100, 200, &low));
    time("nullspace 100x200 r50", reps, || {
        oq::nullspace_q(100, 200, &low)
    });
    time("det 100x100", reps, || oq::det_q(100, &sq));
    time("charpoly 100x100", reps, || oq::charpoly_q(100, &sq));
    time("inverse 100x100", reps, || oq::inverse_q(100, &sq));

    sweep();
    // inverse of the rational sweep matrices: CRT solve against Dixon's lifting (A X = I)
    for n in [10usize, 25] {
        let a = sweep_matrix(true, n, false);
        let mut id = vec![Rational::from_integer(0.into()); n * n];
        (0..n).for_each(|i| id[i * n + i] = Rational::from_integer(1.into()));
        time(&format!("inverse_direct rat {n}"), 3, || {
            mm::direct::inverse_direct(n, &a)
        });
        time(&format!("inverse_dixon rat {n}"), 3, || {
            mm::dixon::solve_dixon(n, n, &a, &id)
        });
    }
    // algorithm against algorithm on small sizes (dispatch thresholds)
    for n in [4usize, 8, 12, 16, 24] {
        let a = to_q(&g.matrix(n, n));
        let w = to_q(&g.matrix(n, 2 * n));
        time(&format!("det_bareiss n={n}"), reps, || {
            ff::det_bareiss(n, &a)
        });
        time(&format!("det_modular n={n}"), reps, || {
            mm::det_modular(n, &a)
        });
        time(&format!("charpoly_berkowitz n={n}"), reps, || {
            ff::charpoly_berkowitz(n, &a)
        });
        time(&format!("charpoly_modular n={n}"), reps, || {
            mm::charpoly_modular(n, &a)
        });
        time(&format!("inverse_bareiss n={n}"), reps, || {
            ff::inverse_bareiss(n, &a)
        });
        time(&format!("inverse_modular n={n}"), reps, || {
            mm::inverse_modular(n, &a)
        });
        time(&format!("rref_bareiss {n}x{}", 2 * n), reps, || {
            ff::rref_bareiss(n, 2 * n, &w)
        });
        time(&format!("rref_modular {n}x{}", 2 * n), reps, || {
            mm::rref_modular(n, 2 * n, &w)
        });
    }
}
/// Sizes of the sweep per operation and entry kind (`int`: |p| <= 10^6; `rat`: p/q with
/// |p|, q <= 10^6). `scripts/anchors/matrix.py` keeps the same table.
const SWEEP: &[(&str, &[usize], &[usize])] = &[
    ("rank", &[10, 25, 50, 100, 200], &[10, 25, 50, 100, 200]),
    ("rref", &[10, 25, 50, 100, 200], &[10, 25, 50, 100, 200]),
    (
        "nullspace",
        &[10, 25, 50, 100, 200],
        &[10, 25, 50, 100, 200],
    ),
    ("det", &[10, 25, 50, 100, 200], &[10, 25, 50, 100]),
    ("solve", &[10, 25, 50, 100, 200], &[10, 25, 50, 100]),
    ("solve-rand", &[10, 25, 50, 100], &[10, 25, 50]),
    ("inverse", &[10, 25, 50, 100], &[10, 25, 50]),
    ("charpoly", &[10, 25, 50, 100], &[10, 25, 50]),
    ("minpoly", &[10, 25, 50, 100], &[10, 25, 50]),
    ("rref-def", &[10, 25, 50], &[10, 25, 50]),
];

/// Sweep matrices: `square` n x n and `deficient` (rank n - 1: last row = row 0 + row 1,
/// for `rref-def`, whose RREF has a free column of ~n^2 log(10^6)-bit entries),
/// from `Lcg64(seed)`, entry `p = (x mod 2000001) - 10^6`, `q = (x mod 10^6) + 1` (rat).
fn sweep_matrix(rat: bool, n: usize, deficient: bool) -> Vec<Rational> {
    let seed = if rat { 1000 } else { 2000 } + n as u64 + if deficient { 500 } else { 0 };
    let mut g = Lcg64(seed);
    let mut a: Vec<Rational> = (0..n * n)
        .map(|_| {
            let p = (g.next_u31() % 2_000_001) as i64 - 1_000_000;
            let q = if rat {
                (g.next_u31() % 1_000_000) as i64 + 1
            } else {
                1
            };
            Rational::new(p.into(), q.into())
        })
        .collect();
    if deficient && n >= 2 {
        for j in 0..n {
            a[(n - 1) * n + j] = &a[j] + &a[n + j];
        }
    }
    a
}

/// The right-hand side of `solve-rand`: `n` entries drawn as those of [`sweep_matrix`]
/// from `Lcg64(seed + 700)` (`solve` takes column 0 of the matrix, whose solution is
/// `e_1`; this one has a solution of ~`n^2 log2(10^6)` bits for rational entries).
fn sweep_rhs(rat: bool, n: usize) -> Vec<Rational> {
    let seed = if rat { 1000 } else { 2000 } + n as u64 + 700;
    let mut g = Lcg64(seed);
    (0..n)
        .map(|_| {
            let p = (g.next_u31() % 2_000_001) as i64 - 1_000_000;
            let q = if rat {
                (g.next_u31() % 1_000_000) as i64 + 1
            } else {
                1
            };
            Rational::new(p.into(), q.into())
        })
        .collect()
}

/// One line per case: `sweep KIND OP N: X ms`.
fn sweep() {
    for rat in [false, true] {
        let kind = if rat { "rat" } else { "int" };
        for &(op, int_sizes, rat_sizes) in SWEEP {
            for &n in if rat { rat_sizes } else { int_sizes } {
                let name = format!("sweep {kind} {op} {n}");
                let def = sweep_matrix(rat, n, op == "rref-def");
                let sq = sweep_matrix(rat, n, false);
                let b: Vec<Rational> = sq.chunks(n).map(|r| r[0].clone()).collect();
                let reps = if n <= 50 { 3 } else { 1 };
                match op {
                    "rank" => time(&name, reps, || oq::rank_q(n, n, &sq)),
                    "rref" | "rref-def" => time(&name, reps, || oq::rref_q(n, n, &def)),
                    "nullspace" => time(&name, reps, || oq::nullspace_q(n, n, &sq)),
                    "det" => time(&name, reps, || oq::det_q(n, &sq)),
                    "solve" => time(&name, reps, || oq::solve_q(n, n, 1, &sq, &b)),
                    "solve-rand" => {
                        let r = sweep_rhs(rat, n);
                        time(&name, reps, || oq::solve_q(n, n, 1, &sq, &r))
                    }
                    "inverse" => time(&name, reps, || oq::inverse_q(n, &sq)),
                    "charpoly" => time(&name, reps, || oq::charpoly_q(n, &sq)),
                    _ => time(&name, reps, || mq(n, &sq).minpoly()),
                }
            }
        }
    }
}

#[allow(dead_code)]
fn kernels(sq: &[Rational], low: &[Rational]) {
    use qk::intmat::integer_rows;
    let pr = qk::prime::nth_prime(0);
    let (b, _) = integer_rows(100, 100, sq);
    time("  integer_rows 100x100", 5, || integer_rows(100, 100, sq));
    time("  reduce 100x100", 5, || b.reduce(&pr));
    time("  hadamard 100x100", 5, || mm::det::hadamard_log2(&b));
    let a0 = b.reduce(&pr);
    time("  det_mod_p 100", 5, || {
        mm::det::det_mod_p(&pr, 100, &mut a0.clone())
    });
    time("  charpoly_mod_p 100", 5, || {
        mm::charpoly::charpoly_mod_p(&pr, 100, &mut a0.clone())
    });
    time("  inverse_mod_p 100", 5, || {
        mm::inverse::inverse_mod_p(&pr, 100, &mut a0.clone())
    });
    let (bl, _) = integer_rows(100, 200, low);
    let l0 = bl.reduce(&pr);
    time("  rref_mod_p 100x200", 5, || {
        mm::rref::rref_mod_p(&pr, 100, 200, &mut l0.clone())
    });
}

fn mq(n: usize, a: &[Rational]) -> exactlti::matrix::Matrix<exactlti::field::Q> {
    exactlti::matrix::Matrix::from_vec(exactlti::field::Q, n, n, a.to_vec())
}
