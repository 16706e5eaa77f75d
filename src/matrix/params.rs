//! Matrices over $\mathbb{Q}(p_1, \dots, p_k)$ and $\mathbb{Z}\lbrack p\rbrack$: characteristic
//! polynomial by evaluation and interpolation, fraction-free (Bareiss) determinant.
//!
//! | entry point | computes | algorithm |
//! |---|---|---|
//! | [`charpoly_ratfunc`] | $\det(xI - A)$ over $\mathbb{Q}(p)$ | clear denominators ($A = B / D$, $B$ over $\mathbb{Z}\lbrack p\rbrack$), [`charpoly_zp`], $c_k = c'_k / D^{n-k}$ |
//! | [`charpoly_zp`] | $\det(xI - B)$ over $\mathbb{Z}\lbrack p\rbrack$ | multi-modular: per word prime, evaluate $B$ on a grid in the parameters, Hessenberg charpoly mod $p$ ([`crate::qkernels::modular::charpoly`]), dense Newton interpolation per parameter, CRT |
//! | [`rref_params`] | canonical RREF over $\mathbb{Q}(p)$, conditions recorded | fraction-free Gauss–Jordan over $\mathbb{Z}\lbrack p\rbrack$ |
//! | [`det_bareiss_zp`] | $\det B$ over $\mathbb{Z}\lbrack p\rbrack$ | Bareiss fraction-free elimination, exact multivariate divisions |
//!
//! **Certificate of [`charpoly_zp`].** The degree of every coefficient in $p_v$ is at most
//! $\sum_i \max_j \deg_{p_v} B_{ij}$ and its total degree at most
//! $D = \sum_i \max_j \operatorname{tdeg} B_{ij}$ (a minor takes one entry per row), so the
//! box grid of that many plus one points per parameter, or the simplex grid
//! $\{e : |e| \le D\}$ (unisolvent for total degree $D$; the smaller one is used: 165 instead
//! of 729 points for an 8x8 linear in 3 parameters) determines it. The coefficient of $x^{n-k}$ is a sum of
//! principal minors; with $r_i = \sum_j \lVert B_{ij} \rVert_1$ (1-norms of the entries, which are
//! submultiplicative) every integer coefficient is at most $\prod_i (1 + r_i)$ in absolute
//! value, and enough primes are taken for twice that bound: the symmetric CRT lift is exact.
//! Over $\mathbb{Q}(p)$ no condition arises: nothing is divided by a non-constant except the
//! field's own denominators.

use super::Matrix;
use crate::error::{Error, Result};
use crate::field::Field;
use crate::mpoly::MPoly;
use crate::mpoly::gcd::lcm;
use crate::poly::Poly;
use crate::qkernels::modular::charpoly::charpoly_mod_p;
use crate::qkernels::modular::crt::Crt;
use crate::qkernels::prime::{Prime, nth_prime};
use crate::ratfunc::RatFuncField;
use num_bigint::{BigInt, Sign};
use num_traits::{One, Signed, ToPrimitive, Zero};
use std::collections::HashMap;

/// Largest interpolation grid (points per prime) accepted by [`charpoly_zp`].
pub const MAX_GRID_POINTS: usize = 1 << 20;

/// $\det(xI - A)$ for a square matrix over $\mathbb{Q}(p)$ (low degree first, monic).
///
/// # Errors
/// `NotSquare`; `Limit` when the interpolation grid would exceed [`MAX_GRID_POINTS`].
pub fn charpoly_ratfunc(a: &Matrix<RatFuncField>) -> Result<Poly<RatFuncField>> {
    let k = a.field().clone();
    let (n, m) = a.shape();
    if n != m {
        return Err(Error::NotSquare {
            op: "charpoly",
            nrows: n,
            ncols: m,
        });
    }
    let nv = k.nvars();
    let (b, d) = clear_denominators(a);
    let c = charpoly_zp(nv, n, &b)?;
    let mut out = Vec::with_capacity(n + 1);
    let mut dpow = MPoly::one(nv);
    for kk in (0..=n).rev() {
        out.push(k.frac(c[kk].clone(), dpow.clone()).expect("nonzero"));
        if kk > 0 {
            dpow = dpow.mul(&d);
        }
    }
    out.reverse();
    Ok(Poly::new(k, out))
}

/// 1-norm of a polynomial's coefficient vector.
fn norm1(f: &MPoly) -> BigInt {
    f.terms().iter().map(|t| t.1.abs()).sum()
}

fn reduce(pr: &Prime, c: &BigInt) -> u64 {
    let (s, digits) = c.to_u64_digits();
    pr.reduce_limbs(s == Sign::Minus, &digits)
}

/// $\det(xI - B)$ for a square `n x n` matrix over $\mathbb{Z}\lbrack p_0..p_{k-1}\rbrack$
/// (row-major, `nvars` variables), low degree first, monic. See the module docs.
///
/// # Errors
/// `Limit` when the grid exceeds [`MAX_GRID_POINTS`].
pub fn charpoly_zp(nvars: usize, n: usize, b: &[MPoly]) -> Result<Vec<MPoly>> {
    assert_eq!(b.len(), n * n);
    // degree bounds (per parameter and total), coefficient bound
    let mut dv = vec![0u32; nvars];
    let mut dtot = 0u32;
    let mut bound = BigInt::one();
    for i in 0..n {
        let mut rowmax = vec![0u32; nvars];
        let mut rowtot = 0u32;
        let mut r = BigInt::zero();
        for j in 0..n {
            let e = &b[i * n + j];
            for (v, d) in e.degrees().into_iter().enumerate() {
                rowmax[v] = rowmax[v].max(d);
            }
            rowtot = rowtot.max(e.total_degree());
            r += norm1(e);
        }
        for v in 0..nvars {
            dv[v] += rowmax[v];
        }
        dtot += rowtot;
        bound *= r + 1u32;
    }
    // interpolation grid: the box prod (d_v + 1) or the simplex |e| <= D, whichever is smaller
    let sizes: Vec<usize> = dv.iter().map(|&d| d as usize + 1).collect();
    let nbox = sizes
        .iter()
        .try_fold(1usize, |acc, &s| acc.checked_mul(s))
        .unwrap_or(usize::MAX);
    let nsimplex = binomial(dtot as usize + nvars, nvars);
    let use_simplex = nsimplex < nbox;
    if nbox.min(nsimplex) > MAX_GRID_POINTS {
        return Err(Error::Limit(
            "charpoly over Z[p]: interpolation grid too large".into(),
        ));
    }
    let points: Vec<Vec<u32>> = if use_simplex {
        simplex_points(nvars, dtot)
    } else {
        (0..nbox)
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
    let npts = points.len();
    let bits = bound.bits() + 2;
    let nprimes = (bits / 61 + 1) as usize;
    let primes: Vec<Prime> = (0..nprimes).map(nth_prime).collect();
    // entries as (exponent vectors, coefficients)
    let entries: Vec<Vec<(Vec<u32>, &BigInt)>> = b
        .iter()
        .map(|e| e.terms().iter().map(|(m, c)| (e.exps(*m), c)).collect())
        .collect();
    let maxd = dv.iter().copied().max().unwrap_or(0) as usize;
    let maxs = (dtot as usize + 1).max(sizes.iter().copied().max().unwrap_or(1));
    // per prime: coefficient k at point index
    let mut images: Vec<Vec<Vec<u64>>> = Vec::with_capacity(nprimes);
    for pr in &primes {
        let red: Vec<Vec<(Vec<u32>, u64)>> = entries
            .iter()
            .map(|e| e.iter().map(|(x, c)| (x.clone(), reduce(pr, c))).collect())
            .collect();
        let mut vals = vec![vec![0u64; npts]; n + 1];
        let mut a = vec![0u64; n * n];
        // powers t^e for t < maxs, e <= deg
        let pw: Vec<Vec<u64>> = (0..maxs)
            .map(|t| {
                let mut v = vec![1u64; maxd + 1];
                for e in 1..=maxd {
                    v[e] = pr.mul(v[e - 1], t as u64 % pr.p);
                }
                v
            })
            .collect();
        for (idx, point) in points.iter().enumerate() {
            for (slot, e) in a.iter_mut().zip(&red) {
                let mut s = 0u64;
                for (x, c) in e {
                    let mut t = *c;
                    for v in 0..nvars {
                        if x[v] > 0 {
                            t = pr.mul(t, pw[point[v] as usize][x[v] as usize]);
                        }
                    }
                    s = pr.add(s, t);
                }
                *slot = s;
            }
            let cp = charpoly_mod_p(pr, n, &mut a);
            for (k, c) in cp.into_iter().enumerate() {
                vals[k][idx] = c;
            }
        }
        if use_simplex {
            let index: HashMap<Vec<u32>, usize> = points
                .iter()
                .enumerate()
                .map(|(i, p)| (p.clone(), i))
                .collect();
            let invs = small_inverses(pr, dtot as usize + 1);
            for v in vals.iter_mut() {
                let map: HashMap<Vec<u32>, u64> = points
                    .iter()
                    .zip(v.iter())
                    .map(|(p, x)| (p.clone(), *x))
                    .collect();
                let coeffs = interpolate_simplex(pr, nvars, dtot, &map, &invs);
                v.iter_mut().for_each(|x| *x = 0);
                for (e, c) in coeffs {
                    v[index[&e]] = c;
                }
            }
        } else {
            for v in vals.iter_mut() {
                interpolate_tensor(pr, v, &sizes);
            }
        }
        images.push(vals);
    }
    let crt = Crt::new(&primes);
    let mut out = Vec::with_capacity(n + 1);
    for k in 0..=n {
        let mut terms = Vec::new();
        for (idx, e) in points.iter().enumerate() {
            let c = crt.lift(|j| images[j][k][idx]);
            if !c.is_zero() {
                terms.push((crate::mpoly::pack(nvars, e), c));
            }
        }
        out.push(MPoly::from_terms(nvars, terms));
    }
    Ok(out)
}

fn binomial(n: usize, k: usize) -> usize {
    let mut r: usize = 1;
    for i in 0..k {
        r = match r.checked_mul(n - i) {
            Some(x) => x / (i + 1),
            None => return usize::MAX,
        };
    }
    r
}

/// All exponent vectors of `k` entries with sum at most `d`.
fn simplex_points(k: usize, d: u32) -> Vec<Vec<u32>> {
    if k == 0 {
        return vec![Vec::new()];
    }
    let mut out = Vec::new();
    for head in simplex_points(k - 1, d) {
        let used: u32 = head.iter().sum();
        for last in 0..=d - used {
            let mut e = head.clone();
            e.push(last);
            out.push(e);
        }
    }
    out
}

fn small_inverses(pr: &Prime, m: usize) -> Vec<u64> {
    (0..=m)
        .map(|j| {
            if j == 0 {
                0
            } else {
                pr.inv(j as u64).expect("small")
            }
        })
        .collect()
}

/// Interpolation of a polynomial of total degree at most `d` in `k` variables from its values
/// on the simplex grid $\{e : |e| \le d\}$ (unisolvent): Newton divided differences in the last
/// variable on each line (the $l$-th one has total degree at most $d - l$ in the others, known
/// on the smaller simplex), recursion, then the Newton basis
/// $\prod_{m < l} (x - m)$ expanded into monomials.
fn interpolate_simplex(
    pr: &Prime,
    k: usize,
    d: u32,
    vals: &HashMap<Vec<u32>, u64>,
    invs: &[u64],
) -> HashMap<Vec<u32>, u64> {
    if k == 0 {
        return vals.clone();
    }
    let mut w: Vec<HashMap<Vec<u32>, u64>> = vec![HashMap::new(); d as usize + 1];
    let mut key = Vec::with_capacity(k);
    for p in simplex_points(k - 1, d) {
        let m = (d - p.iter().sum::<u32>()) as usize;
        let mut y: Vec<u64> = (0..=m)
            .map(|c| {
                key.clear();
                key.extend_from_slice(&p);
                key.push(c as u32);
                vals[&key]
            })
            .collect();
        for j in 1..=m {
            for i in (j..=m).rev() {
                y[i] = pr.mul(pr.sub(y[i], y[i - 1]), invs[j]);
            }
        }
        for (l, yl) in y.into_iter().enumerate() {
            w[l].insert(p.clone(), yl);
        }
    }
    let mut out: HashMap<Vec<u32>, u64> = HashMap::new();
    let mut newton = vec![1u64]; // prod_{m < l} (x - m), low degree first
    for (l, wl) in w.iter().enumerate() {
        let g = interpolate_simplex(pr, k - 1, d - l as u32, wl, invs);
        for (e, c) in g {
            if c == 0 {
                continue;
            }
            for (j, nj) in newton.iter().enumerate() {
                if *nj == 0 {
                    continue;
                }
                let mut key = e.clone();
                key.push(j as u32);
                let slot = out.entry(key).or_insert(0);
                *slot = pr.add(*slot, pr.mul(c, *nj));
            }
        }
        // newton *= (x - l)
        let nl = pr.neg(l as u64 % pr.p);
        let mut next = vec![0u64; newton.len() + 1];
        for (j, nj) in newton.iter().enumerate() {
            next[j + 1] = pr.add(next[j + 1], *nj);
            next[j] = pr.add(next[j], pr.mul(*nj, nl));
        }
        newton = next;
    }
    out
}

/// Replaces values on the grid $\{0..s_0-1\} \times \dots$ (last axis fastest) by the
/// coefficients of the interpolating polynomial (same layout, exponent = index).
fn interpolate_tensor(pr: &Prime, v: &mut [u64], sizes: &[usize]) {
    let total = v.len();
    let mut stride = 1;
    for ax in (0..sizes.len()).rev() {
        let s = sizes[ax];
        if s > 1 {
            let invs: Vec<u64> = (0..s)
                .map(|j| {
                    if j == 0 {
                        0
                    } else {
                        pr.inv(j as u64).expect("small")
                    }
                })
                .collect();
            let block = stride * s;
            let mut line = vec![0u64; s];
            for base in (0..total).step_by(block) {
                for off in 0..stride {
                    for (t, l) in line.iter_mut().enumerate() {
                        *l = v[base + off + t * stride];
                    }
                    interpolate_line(pr, &mut line, &invs);
                    for (t, l) in line.iter().enumerate() {
                        v[base + off + t * stride] = *l;
                    }
                }
            }
        }
        stride *= s;
    }
}

/// Newton interpolation at the points $0, 1, \dots, m-1$, then conversion to monomials.
fn interpolate_line(pr: &Prime, c: &mut [u64], invs: &[u64]) {
    let m = c.len();
    for j in 1..m {
        for i in (j..m).rev() {
            c[i] = pr.mul(pr.sub(c[i], c[i - 1]), invs[j]);
        }
    }
    // p = c[m-1]; p = p*(x - i) + c[i]
    let mut p = vec![0u64; m];
    p[0] = c[m - 1];
    for (deg, i) in (0..m - 1).rev().enumerate() {
        // multiply by (x - i)
        let ni = pr.neg(i as u64 % pr.p);
        for k in (0..=deg + 1).rev() {
            let hi = if k > 0 { p[k - 1] } else { 0 };
            let lo = if k <= deg { pr.mul(p[k], ni) } else { 0 };
            p[k] = pr.add(hi, lo);
        }
        p[0] = pr.add(p[0], c[i]);
    }
    c.copy_from_slice(&p);
}

/// $\det B$ over $\mathbb{Z}\lbrack p\rbrack$ by Bareiss's fraction-free elimination (every
/// division exact; row swaps change the sign).
pub fn det_bareiss_zp(nvars: usize, n: usize, b: &[MPoly]) -> MPoly {
    assert_eq!(b.len(), n * n);
    if n == 0 {
        return MPoly::one(nvars);
    }
    let mut a = b.to_vec();
    let mut prev = MPoly::one(nvars);
    let mut neg = false;
    for k in 0..n {
        let Some(p) = (k..n).find(|&i| !a[i * n + k].is_zero()) else {
            return MPoly::zero(nvars);
        };
        if p != k {
            for j in 0..n {
                a.swap(p * n + j, k * n + j);
            }
            neg = !neg;
        }
        for i in k + 1..n {
            for j in k + 1..n {
                let t = a[k * n + k]
                    .mul(&a[i * n + j])
                    .sub(&a[i * n + k].mul(&a[k * n + j]));
                a[i * n + j] = t.div_exact(&prev).expect("Bareiss division is exact");
            }
            a[i * n + k] = MPoly::zero(nvars);
        }
        prev = a[k * n + k].clone();
    }
    let d = a[n * n - 1].clone();
    if neg { d.neg() } else { d }
}

/// Canonical RREF and pivot columns of an `m x n` matrix over $\mathbb{Q}(p)$ by
/// fraction-free Gauss–Jordan elimination over $\mathbb{Z}\lbrack p\rbrack$ (each row first
/// multiplied by the lcm of its denominators, which does not change the RREF; every division
/// $(\pi a_{ij} - f a_{rj}) / \pi_{\text{prev}}$ is exact). The result equals
/// [`Matrix::rref`]; the conditions recorded in the field are the numerators of the leading
/// minors $M_r$ used as pivots (the generic pivots are $M_r / M_{r-1}$), so the RREF holds
/// wherever none of them vanishes.
pub fn rref_params(a: &Matrix<RatFuncField>) -> (Matrix<RatFuncField>, Vec<usize>) {
    let k = a.field().clone();
    let nv = k.nvars();
    let (m, n) = a.shape();
    let mut e: Vec<MPoly> = Vec::with_capacity(m * n);
    let mut scale: Vec<MPoly> = Vec::with_capacity(m);
    for i in 0..m {
        let row = a.row(i);
        let mut d = MPoly::one(nv);
        for x in row {
            if !x.den().is_one() {
                d = lcm(&d, x.den());
            }
        }
        for x in row {
            e.push(if x.den() == &d {
                x.num().clone()
            } else {
                x.num().mul(&d.div_exact(x.den()).expect("lcm"))
            });
        }
        scale.push(d);
    }
    let mut pivots = Vec::new();
    let mut den = MPoly::one(nv);
    let mut sprod = MPoly::one(nv);
    let mut r = 0;
    for c in 0..n {
        if r == m {
            break;
        }
        let Some(i) = (r..m).find(|&i| !e[i * n + c].is_zero()) else {
            continue;
        };
        if i != r {
            for j in 0..n {
                e.swap(i * n + j, r * n + j);
            }
            scale.swap(i, r);
        }
        let piv = e[r * n + c].clone();
        // the leading minor M_r(A) = piv / (product of the row scalings)
        sprod = sprod.mul(&scale[r]);
        if let Some(minor) = k.frac(piv.clone(), sprod.clone()) {
            k.record_condition(minor.num());
        }
        for i in 0..m {
            if i == r {
                continue;
            }
            let f = e[i * n + c].clone();
            for j in 0..n {
                let t = if f.is_zero() {
                    piv.mul(&e[i * n + j])
                } else {
                    piv.mul(&e[i * n + j]).sub(&f.mul(&e[r * n + j]))
                };
                e[i * n + j] = if den.is_one() {
                    t
                } else {
                    t.div_exact(&den).expect("fraction-free division is exact")
                };
            }
        }
        den = piv;
        pivots.push(c);
        r += 1;
    }
    let out: Vec<_> = e
        .into_iter()
        .enumerate()
        .map(|(idx, x)| {
            if idx >= r * n || x.is_zero() {
                k.zero()
            } else {
                k.frac(x, den.clone()).expect("nonzero pivot")
            }
        })
        .collect();
    (Matrix::from_vec(k, m, n, out), pivots)
}

/// The matrix of numerators times the common denominator: $A = B / D$ with $B$ over
/// $\mathbb{Z}\lbrack p\rbrack$; returns `(B, D)`.
pub fn clear_denominators(a: &Matrix<RatFuncField>) -> (Vec<MPoly>, MPoly) {
    let nv = a.field().nvars();
    let mut d = MPoly::one(nv);
    for e in a.as_slice() {
        if !e.den().is_one() {
            d = lcm(&d, e.den());
        }
    }
    let b = a
        .as_slice()
        .iter()
        .map(|e| {
            if e.den() == &d {
                e.num().clone()
            } else {
                e.num().mul(&d.div_exact(e.den()).expect("lcm"))
            }
        })
        .collect();
    (b, d)
}

/// A small-integer check used by tests: the value of a polynomial entry at a point.
pub fn eval_entry_i64(f: &MPoly, point: &[i64]) -> Option<i64> {
    f.eval_all(&point.iter().map(|&x| BigInt::from(x)).collect::<Vec<_>>())
        .to_i64()
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn small() {
        let k = RatFuncField::new(&["a", "b"]).unwrap();
        let rows = [["a", "1"], ["b", "a + b"]];
        let m = Matrix::from_rows(
            k.clone(),
            rows.iter()
                .map(|r| r.iter().map(|s| k.parse(s).unwrap()).collect())
                .collect(),
        )
        .unwrap();
        let c = charpoly_ratfunc(&m).unwrap();
        let g = m.charpoly_berkowitz().unwrap();
        assert_eq!(c, g);
        let (b, _) = clear_denominators(&m);
        let det = det_bareiss_zp(2, 2, &b);
        assert_eq!(k.from_mpoly(det), m.det().unwrap());
        assert_eq!(rref_params(&m), m.rref());
    }
}
