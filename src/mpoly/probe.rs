//! Degrees probed on random lines, and the check that accepts a polynomial interpolated with
//! them ([`super::interp`]).
//!
//! The certified bounds of [`Bounds::of_rows`] (row maxima, the assignment bound) see no
//! cancellation, so a matrix whose entries
//! are large rational functions (the dual Krylov matrix of a companion form, $f(A)$ for a
//! factor $f$ of the characteristic polynomial) gets a grid of millions of points for
//! polynomials of modest degree. When the certified grid exceeds [`PROBE_MIN`] points:
//!
//! - **Probe.** Modulo a side prime $q$ (none of the interpolation primes), the per-point map
//!   is evaluated on a random line $x = a + t d$; the degree in $t$ of each output is its total
//!   degree unless its leading form vanishes at $d$ (probability $\le D/q$). Along
//!   $x = a + t e_v$ the degree in $t$ is the degree in $p_v$ unless the leading coefficient
//!   vanishes at $a$. The largest degrees over the outputs give the probed bounds (never
//!   above the certified ones).
//! - **Verify.** The polynomials interpolated on the probed grid (and lifted by the CRT with
//!   the certified coefficient bound) are evaluated at two random points modulo another side
//!   prime and compared with the per-point map there. A wrong polynomial of degree at most
//!   $D$ agrees at a random point with probability at most $D/q$ (Schwartz–Zippel,
//!   $q > 2^{61}$), so an accepted result is wrong with probability below $(D/q)^2 <
//!   2^{-80}$ for $D < 2^{20}$ (a Monte Carlo result, as the peeled conditions of
//!   [`crate::ratfunc::kernels::minor_cond`]); when the check fails the certified grid runs.
//!
//! Grids up to [`PROBE_MIN`] points stay certified without a probe.
//!
//! **Decision (issue 25): a documented Monte Carlo step, with a switch.** A deterministic
//! certificate of the probed degrees would need the values at the certified grid's extra
//! points (as costly as the certified grid) or a structural degree bound that sees the
//! cancellations the probe measures (none is known for $f(A)$ or a dual Krylov matrix). So a
//! probed result is accepted with error probability below $(D/q)^2$ per call; where the caller
//! has an exact check of its own (the RREF's $\Delta B_{i,F} = B_{i,P} N$ of
//! [`crate::ratfunc::kernels`]) the result stays certified. To run every grid certified (no
//! probe), set the environment variable `EXACTLTI_CERTIFIED_GRID=1` (the whole process) or
//! call [`with_certified_grid`] (this thread; tests compare both).

use super::MPoly;
use super::bounds::{Bounds, grid_points, small_inverses};
use super::modp::{ReducedPoly, eval_mod_p, powers};
use crate::qkernels::prime::{Prime, is_prime_u64};
use crate::rng::SplitMix64;
use std::cell::Cell;
use std::sync::{Mutex, OnceLock};

/// Certified grids up to this many points are used without a probe.
pub const PROBE_MIN: usize = 1 << 12;

/// Largest certified total degree for which a probe runs (a line takes at most that many
/// points plus one; it usually stops early).
const MAX_LINE: u32 = 1 << 16;

static SIDE: OnceLock<Mutex<Vec<u64>>> = OnceLock::new();

thread_local! {
    static CERTIFIED_ONLY: Cell<bool> = const { Cell::new(false) };
}

/// Are probes off (the certified grids only)? On with `EXACTLTI_CERTIFIED_GRID` set to
/// anything but `0` or empty, or inside [`with_certified_grid`].
pub fn certified_only() -> bool {
    static ENV: OnceLock<bool> = OnceLock::new();
    CERTIFIED_ONLY.with(Cell::get)
        || *ENV.get_or_init(|| {
            std::env::var("EXACTLTI_CERTIFIED_GRID").is_ok_and(|v| !v.is_empty() && v != "0")
        })
}

/// Runs `f` with probes off on this thread (every interpolation on its certified grid),
/// restoring the previous setting afterwards (also when `f` panics).
pub fn with_certified_grid<T>(f: impl FnOnce() -> T) -> T {
    struct Restore(bool);
    impl Drop for Restore {
        fn drop(&mut self) {
            CERTIFIED_ONLY.with(|c| c.set(self.0));
        }
    }
    let _restore = Restore(CERTIFIED_ONLY.with(|c| c.replace(true)));
    f()
}

/// The `i`-th prime below $2^{62} - 2^{32}$ (decreasing, cached): word primes with Barrett
/// products that are none of the interpolation primes of
/// [`crate::qkernels::prime::nth_prime`] (those start at $2^{62}$ and would need $10^8$
/// indices to reach this range). Used for profile points, probes and checks.
pub fn side_prime(i: usize) -> Prime {
    let cache = SIDE.get_or_init(|| Mutex::new(Vec::new()));
    let mut v = cache.lock().unwrap_or_else(|e| e.into_inner());
    let mut c = v.last().copied().unwrap_or((1u64 << 62) - (1u64 << 32));
    while v.len() <= i {
        c -= if c % 2 == 0 { 1 } else { 2 };
        if is_prime_u64(c) {
            v.push(c);
        }
    }
    Prime::new(v[i])
}

/// Consecutive zero Newton coefficients (of every output) after which a line stops early.
const STOP_ZEROS: usize = 3;

/// The degree in $t$ of the map's outputs along `x(t)`, `t = 0, 1, ..., pts - 1` (the largest
/// over outputs), by Newton's divided differences point by point: the line stops early once
/// [`STOP_ZEROS`] new coefficients in a row vanish for every output (a random line makes
/// that a degree with high probability; [`verify`] checks the result). `None` when the map is
/// undefined at one of the points.
fn line_degree<F>(
    pr: &Prime,
    red: &[ReducedPoly],
    pts: u32,
    x_of: impl Fn(u64) -> Vec<u64>,
    f: &F,
) -> Option<u32>
where
    F: Fn(&Prime, &mut [u64]) -> Option<Vec<u64>>,
{
    let maxe = red.iter().map(ReducedPoly::max_exp).max().unwrap_or(0);
    let invs = small_inverses(pr, pts as usize);
    // per output: Newton coefficients c_0..c_t at the nodes 0, 1, ..., t
    let mut newton: Vec<Vec<u64>> = Vec::new();
    let mut deg = 0u32;
    let mut zeros = 0usize;
    for t in 0..pts as usize {
        let pw = powers(pr, &x_of(t as u64), maxe);
        let mut a: Vec<u64> = red.iter().map(|e| e.eval(pr, &pw)).collect();
        let out = f(pr, &mut a)?;
        if newton.is_empty() {
            newton = vec![Vec::with_capacity(pts as usize); out.len()];
        }
        let mut all_zero = true;
        for (c, y) in newton.iter_mut().zip(out) {
            // c_t = (..((y - c_0)/(t - 0) - c_1)/(t - 1) .. - c_{t-1})/(t - (t-1))
            let mut v = y;
            for (j, &cj) in c.iter().enumerate() {
                v = pr.mul(pr.sub(v, cj), invs[t - j]);
            }
            c.push(v);
            if v != 0 {
                all_zero = false;
                deg = deg.max(t as u32);
            }
        }
        zeros = if all_zero { zeros + 1 } else { 0 };
        if zeros >= STOP_ZEROS {
            break;
        }
    }
    // the Newton and monomial bases give the same degree
    Some(deg)
}

impl Bounds {
    /// These bounds with the degrees probed on random lines (see the module docs) when the
    /// certified grid exceeds [`PROBE_MIN`] points and the probe lowers it; the certified
    /// bounds are kept in [`Bounds::certified`]. `f` is the per-point map of
    /// `interpolate_zp` ([`super::interp`]) on the matrix `b`.
    #[must_use]
    pub fn probe<F>(self, b: &[MPoly], f: &F) -> Bounds
    where
        F: Fn(&Prime, &mut [u64]) -> Option<Vec<u64>>,
    {
        let nv = self.dv.len();
        if grid_points(&self) <= PROBE_MIN || nv == 0 || self.dtot >= MAX_LINE || certified_only() {
            return self;
        }
        let pr = side_prime(0);
        let red: Vec<ReducedPoly> = b.iter().map(|e| ReducedPoly::new(&pr, e)).collect();
        let mut rng = SplitMix64(0x9b0b_e5ed ^ nv as u64);
        let a: Vec<u64> = (0..nv).map(|_| rng.next_u64() % pr.p).collect();
        let d: Vec<u64> = (0..nv).map(|_| 1 + rng.next_u64() % (pr.p - 1)).collect();
        let on_line = |t: u64| -> Vec<u64> {
            a.iter()
                .zip(&d)
                .map(|(&ai, &di)| pr.add(ai, pr.mul(di, t)))
                .collect()
        };
        let Some(dtot) = line_degree(&pr, &red, self.dtot + 1, on_line, f) else {
            return self;
        };
        let mut dv = Vec::with_capacity(nv);
        for v in 0..nv {
            let bound = self.dv[v].min(dtot);
            let along = |t: u64| -> Vec<u64> {
                let mut x = a.clone();
                x[v] = pr.add(a[v], t);
                x
            };
            match line_degree(&pr, &red, bound + 1, along, f) {
                Some(dg) => dv.push(dg),
                None => return self,
            }
        }
        let probed = Bounds {
            dv,
            dtot,
            coef: self.coef.clone(),
            certified: None,
        };
        if grid_points(&probed) >= grid_points(&self) {
            return self;
        }
        Bounds {
            certified: Some(Box::new(self)),
            ..probed
        }
    }
}

/// The check of the module docs: `out` agrees with the map `f` on `b` at two random points
/// modulo a side prime (`false` also when the map is undefined at six points in a row).
pub fn verify<F>(b: &[MPoly], out: &[MPoly], f: &F) -> bool
where
    F: Fn(&Prime, &mut [u64]) -> Option<Vec<u64>>,
{
    let Some(nv) = b.first().map(MPoly::nvars) else {
        return true;
    };
    let pr = side_prime(1);
    let red: Vec<ReducedPoly> = b.iter().map(|e| ReducedPoly::new(&pr, e)).collect();
    let maxe = red.iter().map(ReducedPoly::max_exp).max().unwrap_or(0);
    let mut rng = SplitMix64(0x7e41_f1ed ^ out.len() as u64);
    let mut agreed = 0;
    for _ in 0..8 {
        let x: Vec<u64> = (0..nv).map(|_| rng.next_u64() % pr.p).collect();
        let pw = powers(&pr, &x, maxe);
        let mut a: Vec<u64> = red.iter().map(|e| e.eval(&pr, &pw)).collect();
        let Some(vals) = f(&pr, &mut a) else {
            continue;
        };
        if vals.len() != out.len()
            || vals
                .iter()
                .zip(out)
                .any(|(&y, g)| eval_mod_p(&pr, g, &x) != y)
        {
            return false;
        }
        agreed += 1;
        if agreed == 2 {
            return true;
        }
    }
    false
}
