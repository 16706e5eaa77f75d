//! Evaluation/interpolation over $\mathbb{Z}\lbrack p_0, \dots, p_{k-1}\rbrack$: polynomials
//! that are minors of a matrix $B$ over $\mathbb{Z}\lbrack p\rbrack$ (or coefficients of
//! $\det(xI - B)$), from their values modulo word primes on a grid in the parameters.
//!
//! [`interpolate_zp`] evaluates $B$ at every grid point modulo each prime, hands the image to
//! a per-point map (a Hessenberg charpoly, an elimination), interpolates every output by
//! Newton divided differences (dense, per parameter) and lifts the coefficients by the CRT.
//!
//! **Certificate.** A polynomial taking one entry from each row $i \in I$ of $B$ (a minor on
//! the rows $I$, a coefficient of $\det(xI - B_{II})$) has degree in $p_v$ at most
//! $\sum_{i \in I} \max_j \deg_{p_v} B_{ij}$ and total degree at most
//! $D = \sum_{i \in I} \max_j \operatorname{tdeg} B_{ij}$, so the lower set
//! $\{e : e_v \le d_v, |e| \le D\}$ of node indices (the box of $d_v + 1$ points per
//! parameter cut by the simplex of total degree $D$; unisolvent for the polynomials
//! supported on it, with any distinct nodes per axis) determines it. Both degree bounds are
//! lowered to the largest $\sum_i \deg B_{i\sigma(i)}$ over injective maps $\sigma$ of rows
//! to columns (the assignment bound of [`super::bounds`]: a term takes its entries at distinct
//! rows and columns), still a certificate. Degrees may be probed first ([`super::probe`]).
//! With $r_i = \sum_j \lVert B_{ij} \rVert_1$ (1-norms are submultiplicative) every integer
//! coefficient is at most $\prod_{i \in I} (1 + r_i)$ in absolute value, and enough primes are
//! taken for twice that bound: the symmetric CRT lift is exact. The nodes of axis $v$ are
//! $c_v, c_v + 1, \dots$ with a shift $c_v$ (zero, or random when the per-point map may meet
//! a point where it is undefined: it returns `None` and the prime is retried with new shifts).

use super::MPoly;
use crate::error::{Error, Result};
use crate::qkernels::modular::crt::Crt;
use crate::qkernels::prime::{Prime, nth_prime};
use crate::rng::SplitMix64;
use num_bigint::{BigInt, Sign};
use num_traits::Zero;
use std::collections::HashMap;

/// Largest interpolation grid (points per prime) accepted by [`interpolate_zp`].
pub const MAX_GRID_POINTS: usize = 1 << 20;

pub use super::bounds::{Bounds, grid_points};
use super::bounds::{box_inside, small_inverses};

fn reduce(pr: &Prime, c: &BigInt) -> u64 {
    let (s, digits) = c.to_u64_digits();
    pr.reduce_limbs(s == Sign::Minus, &digits)
}

/// The grid: exponent (node index) vectors and whether it is the simplex.
struct Grid {
    points: Vec<Vec<u32>>,
    /// The total degree of every point (the simplex only; empty for the box).
    tot: Vec<u32>,
    simplex: bool,
    sizes: Vec<usize>,
    dtot: u32,
}

fn grid(bounds: &Bounds) -> Result<Grid> {
    let nvars = bounds.dv.len();
    let sizes: Vec<usize> = bounds.dv.iter().map(|&d| d as usize + 1).collect();
    let npoints = grid_points(bounds);
    if npoints > MAX_GRID_POINTS {
        return Err(Error::Limit(
            "matrix over Q(p): interpolation grid too large".into(),
        ));
    }
    let simplex = !box_inside(bounds);
    let points = if simplex {
        lower_points(&bounds.dv, bounds.dtot)
    } else {
        (0..npoints)
            .map(|idx| {
                let mut r = idx;
                let mut e = vec![0u32; nvars];
                for v in (0..nvars).rev() {
                    e[v] = (r % sizes[v]) as u32;
                    r /= sizes[v];
                }
                e
            })
            .collect()
    };
    let tot = if simplex {
        points.iter().map(|e| e.iter().sum()).collect()
    } else {
        vec![]
    };
    Ok(Grid {
        points,
        tot,
        simplex,
        sizes,
        dtot: bounds.dtot,
    })
}

/// The `nout` polynomials whose values at each point are `f(prime, B(point))` (see the
/// module docs); `Ok(None)` when `f` kept failing (`None`) on three shifted grids of a prime.
/// With probed bounds ([`Bounds::probe`]) the result is accepted after
/// [`super::probe::verify`], else the certified bounds run.
///
/// # Errors
/// `Limit` when the grid exceeds [`MAX_GRID_POINTS`] points or [`MAX_VALUES`] residues.
pub fn interpolate_zp<F>(
    nvars: usize,
    b: &[MPoly],
    bounds: &Bounds,
    nout: usize,
    shifted: bool,
    f: F,
) -> Result<Option<Vec<MPoly>>>
where
    F: Fn(&Prime, &mut [u64]) -> Option<Vec<u64>>,
{
    interpolate_zp_capped(nvars, b, bounds, &vec![u32::MAX; nout], shifted, f)
}

/// [`interpolate_zp`] with a certified total-degree bound per output (`caps[k]` for output
/// `k`; `caps.len()` outputs): on the simplex grid an output of total degree at most
/// `caps[k] < D` is interpolated on the lower set $\{e : e_v \le d_v, |e| \le$ `caps[k]`$\}$
/// only (the coefficients of $\det(xI - B)$: degree $n - k$ for the coefficient of $x^k$ of
/// a matrix linear in $p$, one third of the work of the full grid for each of them).
///
/// # Errors
/// As [`interpolate_zp`].
pub fn interpolate_zp_capped<F>(
    nvars: usize,
    b: &[MPoly],
    bounds: &Bounds,
    caps: &[u32],
    shifted: bool,
    f: F,
) -> Result<Option<Vec<MPoly>>>
where
    F: Fn(&Prime, &mut [u64]) -> Option<Vec<u64>>,
{
    if let Some(cert) = &bounds.certified {
        if let Ok(Some(out)) = interpolate_on(nvars, b, bounds, caps, shifted, &f)
            && super::probe::verify(b, &out, &f)
        {
            return Ok(Some(out));
        }
        return interpolate_on(nvars, b, cert, caps, shifted, &f);
    }
    interpolate_on(nvars, b, bounds, caps, shifted, &f)
}

/// Largest number of residues (grid points times outputs) one prime may hold (64 MB).
pub const MAX_VALUES: usize = 1 << 23;

/// [`interpolate_zp`] on the grid of `bounds` as they are.
fn interpolate_on<F>(
    nvars: usize,
    b: &[MPoly],
    bounds: &Bounds,
    caps: &[u32],
    shifted: bool,
    f: &F,
) -> Result<Option<Vec<MPoly>>>
where
    F: Fn(&Prime, &mut [u64]) -> Option<Vec<u64>>,
{
    let nout = caps.len();
    if grid_points(bounds).saturating_mul(nout.max(1)) > MAX_VALUES {
        return Err(Error::Limit(
            "matrix over Q(p): interpolation needs more than 64 MB per prime".into(),
        ));
    }
    let g = grid(bounds)?;
    let nprimes = ((bounds.coef.bits() + 2) / 61 + 1) as usize;
    let primes: Vec<Prime> = (0..nprimes).map(nth_prime).collect();
    let ev = Evaluator::new(b);
    let mut rng = SplitMix64(0x5eed ^ (nvars as u64));
    let mut images: Vec<Vec<Vec<u64>>> = Vec::with_capacity(nprimes);
    // the lines of the simplex, once for every prime
    let lines = if g.simplex {
        lower_set_lines(&g.points, nvars)
    } else {
        vec![]
    };
    for pr in &primes {
        let mut done = None;
        for attempt in 0..3 {
            let shifts: Vec<u64> = (0..nvars)
                .map(|_| {
                    if shifted || attempt > 0 {
                        rng.next_u64() % pr.p
                    } else {
                        0
                    }
                })
                .collect();
            if let Some(v) = images_mod_p(pr, (&g, &lines), &ev, &shifts, caps, f) {
                done = Some(v);
                break;
            }
        }
        let Some(v) = done else {
            return Ok(None);
        };
        images.push(v);
    }
    let packed: Vec<u128> = g
        .points
        .iter()
        .map(|e| crate::mpoly::pack(nvars, e))
        .collect();
    let crt = (nprimes > 1).then(|| Crt::new(&primes));
    let mut out = Vec::with_capacity(nout);
    for k in 0..nout {
        let mut terms = Vec::new();
        for (idx, &m) in packed.iter().enumerate() {
            let c = match &crt {
                Some(crt) => crt.lift(|j| images[j][k][idx]),
                None => symmetric(primes[0].p, images[0][k][idx]),
            };
            if !c.is_zero() {
                terms.push((m, c));
            }
        }
        out.push(MPoly::from_terms(nvars, terms));
    }
    Ok(Some(out))
}

/// The symmetric representative in $(-p/2, p/2\rbrack$ of a residue (one prime: the CRT
/// lift without big-integer arithmetic).
fn symmetric(p: u64, r: u64) -> BigInt {
    if r > p / 2 {
        BigInt::from(-((p - r) as i64))
    } else {
        BigInt::from(r)
    }
}

/// The entries of `B` as sums of coefficients times shared monomials: at a point every
/// distinct monomial is evaluated once, every entry is one dot product.
struct Evaluator<'a> {
    /// Distinct exponent vectors of all entries.
    monos: Vec<Vec<u32>>,
    /// Per entry: (monomial index, integer coefficient).
    terms: Vec<Vec<(usize, &'a BigInt)>>,
    /// Largest exponent of any variable.
    maxd: usize,
}

impl<'a> Evaluator<'a> {
    fn new(b: &'a [MPoly]) -> Self {
        let mut index: HashMap<u128, usize> = HashMap::new();
        let mut monos = Vec::new();
        let mut maxd = 0usize;
        let terms = b
            .iter()
            .map(|e| {
                e.terms()
                    .iter()
                    .map(|(m, c)| {
                        let j = *index.entry(*m).or_insert_with(|| {
                            let x = e.exps(*m);
                            maxd = maxd.max(x.iter().copied().max().unwrap_or(0) as usize);
                            monos.push(x);
                            monos.len() - 1
                        });
                        (j, c)
                    })
                    .collect()
            })
            .collect();
        Evaluator { monos, terms, maxd }
    }
}

/// Per prime: the coefficients (indexed like the grid points) of every output.
fn images_mod_p<F>(
    pr: &Prime,
    (g, lines): (&Grid, &[Vec<Vec<usize>>]),
    ev: &Evaluator,
    shifts: &[u64],
    caps: &[u32],
    f: &F,
) -> Option<Vec<Vec<u64>>>
where
    F: Fn(&Prime, &mut [u64]) -> Option<Vec<u64>>,
{
    let nout = caps.len();
    // each coefficient with its Shoup quotient: one entry is a dot product of fixed
    // coefficients with the monomials' values at the point
    let red: Vec<Vec<(usize, u64, u64)>> = ev
        .terms
        .iter()
        .map(|e| {
            e.iter()
                .map(|&(j, c)| {
                    let r = reduce(pr, c);
                    (j, r, pr.shoup(r))
                })
                .collect()
        })
        .collect();
    let maxs = (g.dtot as usize + 1).max(g.sizes.iter().copied().max().unwrap_or(1));
    // pw[v][t][e] = (shift_v + t)^e
    let pw: Vec<Vec<Vec<u64>>> = shifts
        .iter()
        .map(|&c| {
            (0..maxs)
                .map(|t| {
                    let x = pr.add(c, t as u64 % pr.p);
                    let mut v = vec![1u64; ev.maxd + 1];
                    for e in 1..=ev.maxd {
                        v[e] = pr.mul(v[e - 1], x);
                    }
                    v
                })
                .collect()
        })
        .collect();
    let npts = g.points.len();
    let mut vals = vec![vec![0u64; npts]; nout];
    let mut a = vec![0u64; red.len()];
    let mut mv = vec![0u64; ev.monos.len()];
    for (idx, point) in g.points.iter().enumerate() {
        for (slot, x) in mv.iter_mut().zip(&ev.monos) {
            let mut t = 1u64;
            for (v, &e) in x.iter().enumerate() {
                if e > 0 {
                    let y = pw[v][point[v] as usize][e as usize];
                    t = if t == 1 { y } else { pr.mul(t, y) };
                }
            }
            *slot = t;
        }
        for (slot, e) in a.iter_mut().zip(&red) {
            *slot = e
                .iter()
                .fold(0u64, |s, &(j, c, cs)| pr.add(s, pr.mul_shoup(c, cs, mv[j])));
        }
        let out = f(pr, &mut a)?;
        for (k, c) in out.into_iter().enumerate() {
            vals[k][idx] = c;
        }
    }
    if g.simplex {
        let invs = small_inverses(pr, g.dtot as usize + 1);
        let mut buf = Vec::new();
        for (v, &cap) in vals.iter_mut().zip(caps) {
            if cap < g.dtot {
                // the sub-lower-set |e| <= cap (see interpolate_lower_set); the coefficients
                // outside it are zero
                interpolate_lower_set(pr, v, (lines, &g.tot, cap), &invs, shifts, &mut buf);
                for (x, &t) in v.iter_mut().zip(&g.tot) {
                    if t > cap {
                        *x = 0;
                    }
                }
            } else {
                interpolate_lower_set(pr, v, (lines, &g.tot, u32::MAX), &invs, shifts, &mut buf);
            }
        }
    } else {
        for v in vals.iter_mut() {
            interpolate_tensor(pr, v, &g.sizes, shifts);
        }
    }
    Some(vals)
}

/// All exponent vectors $e$ with $e_v \le d_v$ and $|e| \le D$ (a lower set).
fn lower_points(dv: &[u32], d: u32) -> Vec<Vec<u32>> {
    let Some((&last, head)) = dv.split_last() else {
        return vec![Vec::new()];
    };
    let mut out = Vec::new();
    for h in lower_points(head, d) {
        let used: u32 = h.iter().sum();
        for e in 0..=last.min(d - used) {
            let mut x = h.clone();
            x.push(e);
            out.push(x);
        }
    }
    out
}

/// For each axis $v$, the lines of a lower set of exponent vectors along $v$: the point
/// indices with $e_v = 0, 1, \dots$ and the other coordinates fixed, for every start point
/// with $e_v = 0$.
fn lower_set_lines(points: &[Vec<u32>], nvars: usize) -> Vec<Vec<Vec<usize>>> {
    let index: HashMap<&[u32], usize> = points
        .iter()
        .enumerate()
        .map(|(i, p)| (p.as_slice(), i))
        .collect();
    (0..nvars)
        .map(|v| {
            let mut lines = Vec::new();
            for (i, p) in points.iter().enumerate() {
                if p[v] != 0 {
                    continue;
                }
                let mut line = vec![i];
                let mut key = p.clone();
                loop {
                    key[v] += 1;
                    match index.get(key.as_slice()) {
                        Some(&j) => line.push(j),
                        None => break,
                    }
                }
                if line.len() > 1 {
                    lines.push(line);
                }
            }
            lines
        })
        .collect()
}

/// Interpolation on a lower set of exponent vectors (here $\{e : e_v \le d_v, |e| \le D\}$,
/// node $e_v$ of axis $v$ at $c_v + e_v$): the Newton coefficients by divided differences
/// along every axis in turn (on a lower set the Newton basis $\prod_v \prod_{t < e_v}
/// (x_v - c_v - t)$ is triangular axis by axis), then the change to monomials along every
/// axis in turn. Values in, coefficients out (at the index of their exponent vector).
///
/// With a cap $c$ (`tot[i]` the total degree of point `i`) only the sub-lower-set
/// $|e| \le c$ is used: each line cut to its points of total degree at most $c$ (a prefix,
/// the total degree grows by one along a line). Divided differences of a prefix are the
/// prefix of the line's, and for a polynomial supported on the sub-lower-set the Newton
/// (and monomial) coefficients outside it are zero at every stage, so the values inside are
/// those of the whole computation; the caller sets the ones outside to zero.
fn interpolate_lower_set(
    pr: &Prime,
    vals: &mut [u64],
    (lines, tot, cap): (&[Vec<Vec<usize>>], &[u32], u32),
    invs: &[u64],
    shifts: &[u64],
    buf: &mut Vec<u64>,
) {
    let cut = |line: &'_ [usize]| -> usize {
        if cap == u32::MAX {
            return line.len();
        }
        let t0 = tot[line[0]];
        if t0 > cap {
            0
        } else {
            line.len().min((cap - t0) as usize + 1)
        }
    };
    for axis in lines {
        for line in axis {
            let line = &line[..cut(line)];
            if line.len() < 2 {
                continue;
            }
            buf.clear();
            buf.extend(line.iter().map(|&i| vals[i]));
            let m = buf.len();
            for j in 1..m {
                for i in (j..m).rev() {
                    buf[i] = pr.mul(pr.sub(buf[i], buf[i - 1]), invs[j]);
                }
            }
            for (&i, &x) in line.iter().zip(buf.iter()) {
                vals[i] = x;
            }
        }
    }
    let mut scratch = Vec::new();
    for (v, axis) in lines.iter().enumerate() {
        for line in axis {
            let line = &line[..cut(line)];
            if line.len() < 2 {
                continue;
            }
            buf.clear();
            buf.extend(line.iter().map(|&i| vals[i]));
            newton_to_monomial_in(pr, buf, shifts[v], &mut scratch);
            for (&i, &x) in line.iter().zip(buf.iter()) {
                vals[i] = x;
            }
        }
    }
}

/// Newton coefficients at the nodes $c, c + 1, \dots$ to monomial coefficients, in place.
fn newton_to_monomial(pr: &Prime, c: &mut [u64], shift: u64) {
    newton_to_monomial_in(pr, c, shift, &mut Vec::new());
}

/// [`newton_to_monomial`] with a scratch buffer (no allocation per line).
fn newton_to_monomial_in(pr: &Prime, c: &mut [u64], shift: u64, p: &mut Vec<u64>) {
    let m = c.len();
    // p = c[m-1]; p = p*(x - c - i) + c[i]
    p.clear();
    p.resize(m, 0);
    p[0] = c[m - 1];
    for (deg, i) in (0..m - 1).rev().enumerate() {
        let ni = pr.neg(pr.add(shift, i as u64 % pr.p));
        for k in (0..=deg + 1).rev() {
            let hi = if k > 0 { p[k - 1] } else { 0 };
            let lo = if k <= deg { pr.mul(p[k], ni) } else { 0 };
            p[k] = pr.add(hi, lo);
        }
        p[0] = pr.add(p[0], c[i]);
    }
    c.copy_from_slice(p);
}

/// Replaces values on the grid $\{0..s_0-1\} \times \dots$ (last axis fastest; node $t$ of
/// axis $v$ is $c_v + t$) by the coefficients of the interpolating polynomial (same layout,
/// exponent = index).
fn interpolate_tensor(pr: &Prime, v: &mut [u64], sizes: &[usize], shifts: &[u64]) {
    let total = v.len();
    let mut stride = 1;
    for ax in (0..sizes.len()).rev() {
        let s = sizes[ax];
        if s > 1 {
            let invs = small_inverses(pr, s);
            let block = stride * s;
            let mut line = vec![0u64; s];
            for base in (0..total).step_by(block) {
                for off in 0..stride {
                    for (t, l) in line.iter_mut().enumerate() {
                        *l = v[base + off + t * stride];
                    }
                    interpolate_line(pr, &mut line, &invs, shifts[ax]);
                    for (t, l) in line.iter().enumerate() {
                        v[base + off + t * stride] = *l;
                    }
                }
            }
        }
        stride *= s;
    }
}

/// Newton interpolation at the nodes $c, c + 1, \dots, c + m - 1$, then conversion to
/// monomials.
fn interpolate_line(pr: &Prime, c: &mut [u64], invs: &[u64], shift: u64) {
    let m = c.len();
    for j in 1..m {
        for i in (j..m).rev() {
            c[i] = pr.mul(pr.sub(c[i], c[i - 1]), invs[j]);
        }
    }
    newton_to_monomial(pr, c, shift);
}
