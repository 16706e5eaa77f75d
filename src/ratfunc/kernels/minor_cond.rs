//! The condition of a pivot minor decided at a point: when a shortcut of the $\mathbb{Q}(p)$
//! kernels proves a rank or a pivot pattern by one nonzero minor $\det C$ ($C = B_{S,P}$, the
//! pivot rows and columns of the row-cleared $B$) at a random point, the result holds exactly
//! where $\det C / \prod_{i \in S} d_i \ne 0$; its numerator's irreducible factors are recorded
//! as conditions (where one vanishes, the rank drops or the pivots move: a change of structure).
//!
//! | size of $\det C$ | how its factors are found |
//! |---|---|
//! | certified interpolation grid $\le$ [`DENSE_GRID`] points | $\det C$ interpolated ([`super::det_zp_with`], no probe), divided by $\prod d_i$; factored by the log |
//! | larger (e.g. a Vandermonde minor: $10!$ terms) | **peeling**: candidates $f$ (the parameters, irreducible factors of the entries of $C$ of total degree $\le 3$, of differences of two entries in one row or column, of the $d_i$, and the conditions recorded so far in this computation); on a random line $x = a + t b$ modulo a word prime, $g(t) = \det C(x)$ is interpolated ($\deg g \le D$, the total-degree bound) and divided by each $f(a + t b)$ as often as it goes; when the cofactor is a constant $c_0$, the identity $\det C = c_0 \prod f^{e_f}$ is checked at two further random points (Schwartz–Zippel: wrong with probability $\le 2D/q$, $q \approx 2^{62}$) |
//! | peeling leaves a non-constant cofactor $Q$ whose grid (degrees minus the peeled ones) is $\le$ [`DENSE_GRID`] | $Q = \det C / \prod f^{e_f}$ interpolated ([`record_cofactor`]), checked at two points; the peeled factors and $Q$ recorded (a dual Krylov minor $\det(OK)$ with $\det K$ known) |
//! | peeling leaves a cofactor, probed grid ([`Bounds::probe`]) $\le$ [`DENSE_GRID`] | $\det C$ interpolated there, factored by the log |
//! | peeling leaves a cofactor, grid $\le$ [`MAX_GRID_POINTS`] | $\det C$ interpolated and recorded as **one condition, unfactored** (an 8 x 8 minor linear in 10 parameters: 43758 points) |
//!
//! When none applies (a larger grid), nothing is recorded and the caller gives the shortcut
//! up (the generic elimination then records its pivots itself).

use super::det_zp_with;
use super::interp::{Bounds, MAX_GRID_POINTS, grid_points};
use super::modp::{ReducedPoly, det_mod_p, eval_mod_p, powers};
use crate::mpoly::{MPoly, factor};
use crate::qkernels::prime::{Prime, nth_prime};
use crate::ratfunc::{RatFuncField, Reason};
use crate::rng::SplitMix64;
use std::collections::HashSet;

/// Largest grid on which $\det C$ is interpolated outright.
pub const DENSE_GRID: usize = 1 << 14;

/// Largest work (grid points times operations per point) spent on interpolating a minor
/// that is recorded unfactored.
pub const UNFACTORED_WORK: usize = 1 << 28;

/// Largest number of distinct polynomials factored for candidates.
const MAX_RAW: usize = 600;

/// Records the factors of the numerator of $\det B_{S,P} / \prod_{i \in S} d_i$ (`b` row-major
/// with `n` columns, `ds` the row denominators); `false` when they could not be found (see
/// the module docs): nothing was recorded.
pub fn record_minor(
    k: &RatFuncField,
    b: &[MPoly],
    n: usize,
    rows: &[usize],
    cols: &[usize],
    ds: &[MPoly],
) -> bool {
    let nv = k.nvars();
    let r = rows.len();
    if r == 0 {
        return true;
    }
    let c: Vec<MPoly> = rows
        .iter()
        .flat_map(|&i| cols.iter().map(move |&j| b[i * n + j].clone()))
        .collect();
    let den = rows.iter().fold(MPoly::one(nv), |acc, &i| acc.mul(&ds[i]));
    // a small certified grid: det C outright (no probe); else peeling first (a line of
    // D + 1 points: cheaper than a grid the probe made small), then the probed grid
    let cert = Bounds::of_square(nv, r, &c);
    if grid_points(&cert) <= DENSE_GRID {
        return record_det(k, r, &c, &cert, den);
    }
    let known = k.conditions().unwrap_or_default();
    match peel(r, &c, cert.dtot as usize, &den, &known) {
        Some(p) if p.complete => {
            for f in &p.out {
                k.record_because(f, Reason::ProofMinor { size: r });
            }
            return true;
        }
        Some(p) if !p.exps.is_empty() && record_cofactor(k, r, &c, &cert, &den, &p) => {
            return true;
        }
        _ => {}
    }
    let det_map = |pr: &Prime, x: &mut [u64]| Some(vec![det_mod_p(pr, r, x)]);
    let bounds = cert.probe(&c, &det_map);
    if grid_points(&bounds) <= DENSE_GRID {
        return record_det(k, r, &c, &bounds, den);
    }
    record_unfactored(k, r, &c, &bounds, &den)
}

/// $\det C$ interpolated on the grid of `bounds`, the numerator of $\det C / \prod d_i$
/// recorded (factored by the log); `false` when it is zero or the grid is refused.
fn record_det(k: &RatFuncField, r: usize, c: &[MPoly], bounds: &Bounds, den: MPoly) -> bool {
    match det_zp_with(k.nvars(), r, c, bounds)
        .ok()
        .and_then(|d| k.frac(d, den))
    {
        Some(q) if !q.num().is_zero() => {
            k.record_because(q.num(), Reason::ProofMinor { size: r });
            true
        }
        _ => false,
    }
}

/// The last resort of [`record_minor`]: $\det C$ interpolated on a grid of at most
/// [`MAX_GRID_POINTS`] points (and [`UNFACTORED_WORK`] operations), the numerator of
/// $\det C / \prod d_i$ recorded as **one** condition, unfactored
/// ([`RatFuncField::record_condition_unfactored`]); `false` when the grid is larger.
fn record_unfactored(
    k: &RatFuncField,
    r: usize,
    c: &[MPoly],
    bounds: &Bounds,
    den: &MPoly,
) -> bool {
    let per_point = r * r * r + c.iter().map(MPoly::len).sum::<usize>();
    let work = grid_points(bounds).saturating_mul(per_point);
    if grid_points(bounds) > MAX_GRID_POINTS || work > UNFACTORED_WORK {
        return false;
    }
    match det_zp_with(k.nvars(), r, c, bounds)
        .ok()
        .and_then(|d| k.frac(d, den.clone()))
    {
        Some(q) if !q.num().is_zero() => {
            k.record_condition_unfactored(q.num(), Reason::ProofMinor { size: r });
            true
        }
        _ => false,
    }
}

/// The irreducible factors of `den`, of the entries of `c` of total degree at most 3 and of
/// differences of two entries in one row or column (of total degree at most 2); `None` past
/// [`MAX_RAW`]. (The
/// caller adds the conditions recorded so far: a product such as $\mathcal O \mathcal C$
/// has the factors of both.)
fn candidates(r: usize, c: &[MPoly], den: &MPoly) -> Option<Vec<MPoly>> {
    let mut raw: HashSet<MPoly> = HashSet::new();
    let mut add = |p: MPoly| {
        if !p.is_constant() {
            raw.insert(p.primitive_part());
        }
    };
    add(den.clone());
    for e in c {
        if e.total_degree() <= 3 {
            add(e.clone());
        }
    }
    let small = |e: &MPoly| e.total_degree() <= 2;
    for line in 0..r {
        for i in 0..r {
            for j in i + 1..r {
                for (x, y) in [
                    (&c[line * r + i], &c[line * r + j]),
                    (&c[i * r + line], &c[j * r + line]),
                ] {
                    if small(x) && small(y) && !(x.is_constant() && y.is_constant()) {
                        add(x.sub(y));
                    }
                }
            }
        }
    }
    if raw.len() > MAX_RAW {
        return None;
    }
    let mut out: HashSet<MPoly> = HashSet::new();
    for p in raw {
        for (g, _) in factor(&p).ok()?.factors {
            out.insert(g);
        }
    }
    let mut v: Vec<MPoly> = out.into_iter().collect();
    v.sort_by(crate::mpoly::factor::cmp_poly);
    Some(v)
}

/// What peeling found on its line.
struct Peeled {
    /// The candidates dividing $\det C$ on the line, with their multiplicities there.
    exps: Vec<(MPoly, usize)>,
    /// Those whose multiplicity exceeds that in `den` (the conditions).
    out: Vec<MPoly>,
    /// The cofactor is a constant and $\det C = c_0 \prod f^{e_f}$ held at two points.
    complete: bool,
}

/// The cofactor $Q = \det C / \prod f^{e_f}$ left by peeling, interpolated on its own grid:
/// degrees those of `cert` minus the peeled ones (a dual Krylov minor $\det(O K) = \det O
/// \det K$ with $\det K$ recorded before: half the degree, an eighth of the grid), coefficients
/// bounded by Gelfond's inequality ($\lVert Q \rVert_\infty \le 2^{\sum_v d_v}
/// \prod_v (d_v + 1) \lVert \det C \rVert_\infty$ for a factor of a polynomial of partial
/// degrees $d_v$); the values at a grid point are $\det C(x) / \prod f(x)^{e_f}$. Checked:
/// $\det C = Q \prod f^{e_f}$ at two random points modulo a side prime (the multiplicities
/// came from one line: Monte Carlo as the peeling). Recorded: the peeled conditions and the
/// numerator of $Q / \prod d_i$ (factored by the log). `false` when the grid exceeds
/// [`DENSE_GRID`] or the check fails: nothing recorded.
fn record_cofactor(
    k: &RatFuncField,
    r: usize,
    c: &[MPoly],
    cert: &Bounds,
    den: &MPoly,
    p: &Peeled,
) -> bool {
    let nv = k.nvars();
    let mut dv = cert.dv.clone();
    let mut dtot = cert.dtot;
    for (f, e) in &p.exps {
        let e = *e as u32;
        for (v, d) in dv.iter_mut().enumerate() {
            *d = d.saturating_sub(f.deg(v) * e);
        }
        dtot = dtot.saturating_sub(f.total_degree() * e);
    }
    let growth: u64 = cert.dv.iter().map(|&d| u64::from(d)).sum();
    let coef = cert
        .dv
        .iter()
        .fold(&cert.coef << growth, |acc, &d| acc * (d + 1));
    let bounds = Bounds {
        dv,
        dtot,
        coef,
        certified: None,
    };
    if grid_points(&bounds) > DENSE_GRID {
        return false;
    }
    let es: Vec<u64> = p.exps.iter().map(|(_, e)| *e as u64).collect();
    let mut b = c.to_vec();
    b.extend(p.exps.iter().map(|(f, _)| f.clone()));
    let map = |pr: &Prime, x: &mut [u64]| -> Option<Vec<u64>> {
        let (m, fs) = x.split_at_mut(r * r);
        let prod = fs
            .iter()
            .zip(&es)
            .fold(1u64, |acc, (&y, &e)| pr.mul(acc, pr.pow(y, e)));
        Some(vec![pr.mul(det_mod_p(pr, r, m), pr.inv(prod)?)])
    };
    let Ok(Some(mut out)) = super::interp::interpolate_zp(nv, &b, &bounds, 1, true, map) else {
        return false;
    };
    let q = out.pop().expect("one output");
    let pr = super::probe::side_prime(2);
    let mut rng = SplitMix64(0xc0fa_c702);
    for _ in 0..2 {
        let x: Vec<u64> = (0..nv).map(|_| rng.next_u64() % pr.p).collect();
        let mut m: Vec<u64> = c.iter().map(|f| eval_mod_p(&pr, f, &x)).collect();
        let rhs = p.exps.iter().fold(eval_mod_p(&pr, &q, &x), |acc, (f, e)| {
            pr.mul(acc, pr.pow(eval_mod_p(&pr, f, &x), *e as u64))
        });
        if det_mod_p(&pr, r, &mut m) != rhs {
            return false;
        }
    }
    let Some(qd) = k.frac(q, den.clone()) else {
        return false;
    };
    for f in &p.out {
        k.record_because(f, Reason::ProofMinor { size: r });
    }
    if !qd.num().is_constant() {
        k.record_because(qd.num(), Reason::ProofMinor { size: r });
    }
    true
}

/// The peeling of the module docs: the candidates dividing $\det C$ and whether they leave a
/// constant cofactor (checked); `None` on an unlucky line or a failed check.
fn peel(r: usize, c: &[MPoly], dtot: usize, den: &MPoly, known: &[MPoly]) -> Option<Peeled> {
    // the conditions recorded so far and the factors of `den` first (cheap), the entries'
    // factors only when those leave a cofactor
    let mut first: Vec<MPoly> = known.to_vec();
    // the parameters themselves (a Krylov matrix of a chain: det = k^90 / m^110, whose
    // entries of small degree are all constants)
    for v in 0..den.nvars() {
        let x = MPoly::var(den.nvars(), v);
        if !first.contains(&x) {
            first.push(x);
        }
    }
    if !den.is_constant() {
        for (g, _) in factor(den).ok()?.factors {
            if !first.contains(&g) {
                first.push(g);
            }
        }
    }
    let with_first = peel_with(r, c, dtot, den, &first);
    if with_first.as_ref().is_some_and(|p| p.complete) {
        return with_first;
    }
    let Some(mut cands) = candidates(r, c, den) else {
        return with_first;
    };
    for f in first {
        if !cands.contains(&f) {
            cands.push(f);
        }
    }
    peel_with(r, c, dtot, den, &cands).or(with_first)
}

/// [`peel`] with the candidates `cands`.
fn peel_with(r: usize, c: &[MPoly], dtot: usize, den: &MPoly, cands: &[MPoly]) -> Option<Peeled> {
    let nv = den.nvars();
    let pr = nth_prime(60);
    let mut rng = SplitMix64(0x9ee1_c0d5);
    let rand_pt = |rng: &mut SplitMix64| -> Vec<u64> {
        (0..nv).map(|_| rng.next_u64() % pr.p).collect::<Vec<u64>>()
    };
    let a = rand_pt(&mut rng);
    let dir = rand_pt(&mut rng);
    let on_line =
        |t: u64| -> Vec<u64> { (0..nv).map(|v| pr.add(a[v], pr.mul(t, dir[v]))).collect() };
    // the entries reduced once (evaluated at dtot + 3 points)
    let red: Vec<ReducedPoly> = c.iter().map(|f| ReducedPoly::new(&pr, f)).collect();
    let maxe = red.iter().map(ReducedPoly::max_exp).max().unwrap_or(0);
    let det_at = |x: &[u64]| -> u64 {
        let pw = powers(&pr, x, maxe);
        let mut m: Vec<u64> = red.iter().map(|f| f.eval(&pr, &pw)).collect();
        det_mod_p(&pr, r, &mut m)
    };
    let restrict = |vals: &dyn Fn(&[u64]) -> u64, deg: usize| -> Vec<u64> {
        let ys: Vec<u64> = (0..=deg as u64).map(|t| vals(&on_line(t))).collect();
        let mut g = newton_monomial(&pr, &ys);
        trim(&mut g);
        g
    };
    let mut g = restrict(&det_at, dtot);
    if g.is_empty() {
        return None;
    }
    let mut out = Vec::new();
    let mut exps = Vec::new();
    for f in cands {
        let fl = restrict(
            &|x: &[u64]| eval_mod_p(&pr, f, x),
            f.total_degree() as usize,
        );
        if fl.len() < 2 {
            return None; // constant on the line: an unlucky line
        }
        let mut e = 0usize;
        while let Some(q) = div_exact(&pr, &g, &fl) {
            g = q;
            e += 1;
        }
        if e == 0 {
            continue;
        }
        exps.push((f, e));
        let mut in_den = 0usize;
        let mut d = den.clone();
        while let Some(q) = d.div_exact(f) {
            d = q;
            in_den += 1;
        }
        if e > in_den {
            out.push(f.clone());
        }
    }
    if g.len() != 1 {
        return Some(Peeled {
            exps: exps.into_iter().map(|(f, e)| (f.clone(), e)).collect(),
            out,
            complete: false,
        });
    }
    for _ in 0..2 {
        let x = rand_pt(&mut rng);
        let rhs = exps.iter().fold(g[0], |acc, (f, e)| {
            pr.mul(acc, pr.pow(eval_mod_p(&pr, f, &x), *e as u64))
        });
        if det_at(&x) != rhs {
            return None;
        }
    }
    Some(Peeled {
        exps: exps.into_iter().map(|(f, e)| (f.clone(), e)).collect(),
        out,
        complete: true,
    })
}

/// Drops trailing zero coefficients.
fn trim(g: &mut Vec<u64>) {
    while g.last() == Some(&0) {
        g.pop();
    }
}

/// The coefficients (low degree first) of the polynomial taking the values `ys` at
/// $t = 0, 1, \dots$ (Newton divided differences, then the change to monomials).
fn newton_monomial(pr: &Prime, ys: &[u64]) -> Vec<u64> {
    let m = ys.len();
    let mut c = ys.to_vec();
    for j in 1..m {
        let inv = pr.inv(j as u64 % pr.p).expect("small nonzero");
        for i in (j..m).rev() {
            c[i] = pr.mul(pr.sub(c[i], c[i - 1]), inv);
        }
    }
    // Horner: p(t) = c0 + t (c1 + (t - 1)(c2 + ...))
    let mut out = vec![0u64; m];
    for i in (0..m).rev() {
        // out = out * (t - i) + c[i]
        let shift = pr.neg(i as u64 % pr.p);
        let mut next = vec![0u64; m];
        for d in 0..m {
            if out[d] == 0 {
                continue;
            }
            if d + 1 < m {
                next[d + 1] = pr.add(next[d + 1], out[d]);
            }
            next[d] = pr.add(next[d], pr.mul(out[d], shift));
        }
        next[0] = pr.add(next[0], c[i]);
        out = next;
    }
    out
}

/// `g / f` modulo the prime when `f` divides `g` (both trimmed, `f` non-constant).
fn div_exact(pr: &Prime, g: &[u64], f: &[u64]) -> Option<Vec<u64>> {
    if g.len() < f.len() {
        return None;
    }
    let mut rem = g.to_vec();
    let df = f.len() - 1;
    let inv = pr.inv(f[df])?;
    let mut q = vec![0u64; g.len() - df];
    for i in (0..q.len()).rev() {
        let co = pr.mul(rem[i + df], inv);
        q[i] = co;
        if co != 0 {
            for (j, &fj) in f.iter().enumerate() {
                rem[i + j] = pr.sub(rem[i + j], pr.mul(co, fj));
            }
        }
    }
    rem[..df].iter().all(|&x| x == 0).then_some(q)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn newton_and_division_mod_p() {
        let pr = nth_prime(60);
        // (t + 2)(t - 3) = t^2 - t - 6
        let ys: Vec<u64> = (0..4u64)
            .map(|t| pr.mul(pr.add(t, 2), pr.sub(t, 3)))
            .collect();
        let mut g = newton_monomial(&pr, &ys);
        trim(&mut g);
        assert_eq!(g, vec![pr.neg(6), pr.neg(1), 1]);
        assert_eq!(div_exact(&pr, &g, &[2, 1]), Some(vec![pr.neg(3), 1]));
        assert_eq!(div_exact(&pr, &g, &[1, 1]), None);
    }

    /// The Vandermonde minor in 8 variables (8! terms, never expanded): its 28 factors
    /// $p_i - p_j$ are recorded.
    #[test]
    fn vandermonde_by_peeling() {
        let n = 8;
        let names: Vec<String> = (0..n).map(|i| format!("p{i}")).collect();
        let k = RatFuncField::new(&names).unwrap();
        let b: Vec<MPoly> = (0..n)
            .flat_map(|i| {
                let k = k.clone();
                (0..n).map(move |j| k.var(i).num().pow(j as u32))
            })
            .collect();
        let ds = vec![MPoly::one(n); n];
        let all: Vec<usize> = (0..n).collect();
        assert!(record_minor(&k, &b, n, &all, &all, &ds));
        let conds = k.conditions_strings().unwrap();
        assert_eq!(conds.len(), n * (n - 1) / 2);
        assert!(conds.contains(&"p0 - p1".to_string()), "{conds:?}");
        // a minor with a factor that is no candidate: the cofactor left by peeling is
        // interpolated on its own grid ([`record_cofactor`]) and recorded; the conditions
        // multiply back to det C up to a constant (at two points modulo a prime)
        let k2 = k.fresh();
        let mut b2 = b.clone();
        b2[0] = k.parse("p0^3 + p1*p2 + 7").unwrap().num().clone();
        assert!(record_minor(&k2, &b2, n, &all, &all, &ds));
        let conds = k2.conditions().unwrap();
        assert!(conds.len() > (n - 1) * (n - 2) / 2, "{conds:?}");
        let pr = nth_prime(3);
        let mut rng = SplitMix64(0x7e57);
        let ratios: Vec<u64> = (0..2)
            .map(|_| {
                let x: Vec<u64> = (0..n).map(|_| rng.next_u64() % pr.p).collect();
                let mut m: Vec<u64> = b2.iter().map(|f| eval_mod_p(&pr, f, &x)).collect();
                let d = det_mod_p(&pr, n, &mut m);
                let prod = conds
                    .iter()
                    .fold(1u64, |acc, f| pr.mul(acc, eval_mod_p(&pr, f, &x)));
                pr.mul(d, pr.inv(prod).unwrap())
            })
            .collect();
        assert_eq!(ratios[0], ratios[1], "{:?}", k2.conditions_strings());
    }
}
