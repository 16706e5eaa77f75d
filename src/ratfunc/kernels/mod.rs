//! The matrix kernels of $\mathbb{Q}(p_1, \dots, p_k)$ ([`QP_KERNELS`], registered by
//! [`RatFuncField`] through [`crate::field::Field::kernels`]): evaluation/interpolation over
//! $\mathbb{Z}\lbrack p\rbrack$ ([`interp`]) instead of fraction arithmetic with a gcd per
//! operation.
//!
//! | kernel | identity computed | how |
//! |---|---|---|
//! | charpoly | $\det(xI - A)$, no conditions (a polynomial identity) | $A = B/D$ (common denominator), $\det(xI - B)$ by [`charpoly_zp`], $c_k = c'_k / D^{n-k}$ |
//! | det | $\det A$, no conditions | rows cleared ($B_i = d_i A_i$), $\det B$ interpolated, divided by $\prod d_i$; `Limit` beyond the size budget ([`budget`]) |
//! | rref, rank (null space through the RREF) | canonical RREF $R$ | below |
//! | inverse | $A^{-1} = \operatorname{adj}(B) D / \det B$ ($B = DA$ row-cleared) | [`inverse`]: $\det B$ and $\operatorname{adj} B$ interpolated together, checked, one division per entry |
//! | product | $AB$ | [`mul`]: rows of $A$ and columns of $B$ cleared, one reduction per entry |
//! | gcd in $\mathbb{Q}(p)\lbrack s\rbrack$ | monic gcd, no conditions | [`pgcd`]: coprimality at a point, else one gcd in $\mathbb{Z}\lbrack p, s\rbrack$ |
//!
//! **RREF.** Scaling row $i$ by the lcm $d_i$ of its denominators does not change the RREF.
//! At a random point modulo a word prime the elimination of `Matrix::rref` gives pivot
//! columns $P$ and pivot rows $S$ (in pivot order); on the rows $S$ the polynomials
//! $M_k$ (leading minors of $B_{S,P}$, $\Delta = M_r$) and $N = \Delta B_{S,P}^{-1} B_{S,F}$
//! (minors by Cramer's rule) are interpolated ([`interp`], certified bounds). The candidate
//! $R$ (rows $e_{P_k} + N_k / \Delta$ on $F$) is then **checked exactly**: $N_{k,j} = 0$ for
//! free $j < P_k$ (echelon shape) and $\Delta B_i = \sum_k B_{i,P_k} (\Delta e_{P_k} + N_k)$
//! for every row $i$ (row space of $B$ inside that of $R$; $\Delta \ne 0$ gives
//! $\operatorname{rank} B \ge r$, so the row spaces are equal and $R$ is the RREF). A failed
//! check (an unlucky point) retries with a new point, then leaves the generic algorithm to
//! run. Conditions recorded: the numerators of $M_k / \prod_{j \le k} d_{S_j}$, the leading
//! minors of $A$ that the generic elimination divides by. The entries $N_{kf}/\Delta$ are
//! brought to lowest terms (the only gcds). A rank or pivot pattern proved by one nonzero
//! minor at a point (full rank, pivots $0..r-1$) holds where that minor is nonzero: its
//! factors are recorded ([`minor_cond`]), or the shortcut is given up. A matrix whose rows
//! and columns split into independent blocks (a diagonal $A - \lambda I$) is reduced block by
//! block ([`blocks`]). When the interpolation grid is too large (many parameters), the
//! minors and $N$ (and the adjugate of the inverse) come from fraction-free Gauss–Jordan
//! over $\mathbb{Z}\lbrack p\rbrack$ instead ([`fraction_free`]: exact divisions, no gcd),
//! certified by the same checks.

pub(crate) mod blocks;
pub mod budget;
/// The evaluation/interpolation engine (in [`crate::mpoly`], where resultants use it too).
pub use crate::mpoly::interp;
pub(crate) mod fraction_free;
pub(crate) mod inverse;
pub(crate) mod minor_cond;
pub(crate) mod modp;
pub(crate) mod mul;
pub(crate) mod pgcd;
pub use crate::mpoly::probe;

use super::{RatFunc, RatFuncField};
use crate::error::Result;
use crate::field::KernelTable;
use crate::mpoly::MPoly;
use crate::mpoly::gcd::lcm;
use crate::qkernels::modular::charpoly::charpoly_mod_p;
use interp::{Bounds, interpolate_zp, interpolate_zp_capped};

/// The kernel table of $\mathbb{Q}(p)$.
pub struct QpKernels;

/// The one instance, returned by [`RatFuncField`]'s [`crate::field::Field::kernels`].
pub static QP_KERNELS: QpKernels = QpKernels;

/// Matrices up to this many entries keep the generic algorithms (nothing to gain).
const TINY: usize = 1;

/// $\det(xI - B)$ for a square `n x n` matrix over $\mathbb{Z}\lbrack p\rbrack$ (row-major,
/// `nvars` variables), low degree first, monic (see [`interp`]).
///
/// # Errors
/// `Limit` when the grid exceeds [`interp::MAX_GRID_POINTS`].
pub fn charpoly_zp(nvars: usize, n: usize, b: &[MPoly]) -> Result<Vec<MPoly>> {
    assert_eq!(b.len(), n * n);
    let map = |pr: &crate::qkernels::prime::Prime, a: &mut [u64]| Some(charpoly_mod_p(pr, n, a));
    let bounds = Bounds::of_square(nvars, n, b).probe(b, &map);
    let out = interpolate_zp_capped(nvars, b, &bounds, &charpoly_caps(n, b), false, map)?;
    Ok(out.expect("the charpoly map is defined at every point"))
}

/// Total-degree bounds of the coefficients of $\det(xI - B)$, low degree first: the
/// coefficient of $x^k$ is a sum of principal minors of size $n - k$, each term a product
/// of entries from $n - k$ distinct rows (and columns), so its degree is at most the sum of
/// the $n - k$ largest row (column) maxima of the total degrees.
fn charpoly_caps(n: usize, b: &[MPoly]) -> Vec<u32> {
    let largest_sums = |deg: &dyn Fn(usize, usize) -> u32| -> Vec<u32> {
        let mut m: Vec<u32> = (0..n)
            .map(|i| (0..n).map(|j| deg(i, j)).max().unwrap_or(0))
            .collect();
        m.sort_unstable_by(|x, y| y.cmp(x));
        let mut acc = vec![0u32];
        for d in m {
            acc.push(acc.last().copied().unwrap_or(0).saturating_add(d));
        }
        acc
    };
    let tdeg: Vec<u32> = b.iter().map(MPoly::total_degree).collect();
    let rows = largest_sums(&|i, j| tdeg[i * n + j]);
    let cols = largest_sums(&|i, j| tdeg[j * n + i]);
    (0..=n).map(|k| rows[n - k].min(cols[n - k])).collect()
}

/// $\det B$ for a square `n x n` matrix over $\mathbb{Z}\lbrack p\rbrack$ (see [`interp`]).
///
/// # Errors
/// `Limit` when the grid exceeds [`interp::MAX_GRID_POINTS`].
pub fn det_zp(nvars: usize, n: usize, b: &[MPoly]) -> Result<MPoly> {
    let map =
        |pr: &crate::qkernels::prime::Prime, a: &mut [u64]| Some(vec![modp::det_mod_p(pr, n, a)]);
    det_zp_with(nvars, n, b, &Bounds::of_square(nvars, n, b).probe(b, &map))
}

/// [`det_zp`] on the grid of `bounds` (the caller's certified or probed bounds of
/// [`Bounds::of_square`]; no second probe).
///
/// # Errors
/// As [`det_zp`].
pub fn det_zp_with(nvars: usize, n: usize, b: &[MPoly], bounds: &Bounds) -> Result<MPoly> {
    assert_eq!(b.len(), n * n);
    let map =
        |pr: &crate::qkernels::prime::Prime, a: &mut [u64]| Some(vec![modp::det_mod_p(pr, n, a)]);
    let out = interpolate_zp(nvars, b, bounds, 1, false, map)?;
    Ok(out
        .expect("the det map is defined at every point")
        .pop()
        .expect("one output"))
}

/// $A = B / D$ with $B$ over $\mathbb{Z}\lbrack p\rbrack$ and $D$ the lcm of all
/// denominators; returns `(B, D)`.
pub fn clear_common(nvars: usize, a: &[RatFunc]) -> (Vec<MPoly>, MPoly) {
    let mut d = MPoly::one(nvars);
    for e in a {
        if !e.den().is_one() {
            d = lcm(&d, e.den());
        }
    }
    (a.iter().map(|e| times(e, &d)).collect(), d)
}

/// Row `i` times the lcm $d_i$ of its denominators; returns the polynomial rows and the $d_i$.
pub fn clear_rows(nvars: usize, m: usize, n: usize, a: &[RatFunc]) -> (Vec<MPoly>, Vec<MPoly>) {
    let mut b = Vec::with_capacity(m * n);
    let mut ds = Vec::with_capacity(m);
    for i in 0..m {
        let row = &a[i * n..(i + 1) * n];
        let mut d = MPoly::one(nvars);
        for e in row {
            if !e.den().is_one() {
                d = lcm(&d, e.den());
            }
        }
        b.extend(row.iter().map(|e| times(e, &d)));
        ds.push(d);
    }
    (b, ds)
}

/// `e * d` for a multiple `d` of the denominator of `e`.
fn times(e: &RatFunc, d: &MPoly) -> MPoly {
    if e.num().is_zero() {
        MPoly::zero(d.nvars())
    } else if e.den() == d {
        e.num().clone()
    } else {
        e.num().mul(&d.div_exact(e.den()).expect("lcm"))
    }
}

/// $\det(xI - A)$ over $\mathbb{Q}(p)$, low degree first (no conditions).
///
/// # Errors
/// `Limit` as [`charpoly_zp`].
pub fn charpoly_qp(k: &RatFuncField, n: usize, a: &[RatFunc]) -> Result<Vec<RatFunc>> {
    let nv = k.nvars();
    let (b, d) = clear_common(nv, a);
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
    Ok(out)
}

/// $\det A$ over $\mathbb{Q}(p)$ (no conditions): rows cleared, $\det$ over
/// $\mathbb{Z}\lbrack p\rbrack$ ([`det_zp`]). The table's entry point checks the size budget
/// first ([`budget::det_budget`]).
///
/// # Errors
/// `Limit` as [`det_zp`].
fn det_cleared(k: &RatFuncField, n: usize, a: &[RatFunc]) -> Result<RatFunc> {
    let nv = k.nvars();
    let (b, ds) = clear_rows(nv, n, n, a);
    let det = det_zp(nv, n, &b)?;
    let den = ds.iter().fold(MPoly::one(nv), |acc, d| acc.mul(d));
    Ok(k.frac(det, den).expect("nonzero"))
}

mod rref;
pub use pgcd::poly_gcd_qp;
pub use rref::{rank_qp, rref_qp};

impl KernelTable<RatFuncField> for QpKernels {
    fn charpoly(&self, k: &RatFuncField, n: usize, a: &[RatFunc]) -> Option<Result<Vec<RatFunc>>> {
        if n * n <= TINY || k.nvars() == 0 {
            return None;
        }
        match charpoly_qp(k, n, a) {
            Err(crate::error::Error::Limit(_)) => None,
            r => Some(r),
        }
    }
    /// Beyond the size budget `Limit` ([`budget::det_budget`]: no fallback expands it); a
    /// `Limit` of the interpolation itself leaves the generic elimination to run.
    fn det(&self, k: &RatFuncField, n: usize, a: &[RatFunc]) -> Option<Result<RatFunc>> {
        if n * n <= TINY || k.nvars() == 0 {
            return None;
        }
        if let Err(e) = budget::det_budget(k.nvars(), n, n, a) {
            return Some(Err(e));
        }
        match det_cleared(k, n, a) {
            Err(crate::error::Error::Limit(_)) => None,
            r => Some(r),
        }
    }
    fn rref(
        &self,
        k: &RatFuncField,
        m: usize,
        n: usize,
        a: &[RatFunc],
    ) -> Option<(Vec<RatFunc>, Vec<usize>)> {
        if m * n <= TINY || k.nvars() == 0 {
            return None;
        }
        rref_qp(k, m, n, a)
    }
    fn rank(&self, k: &RatFuncField, m: usize, n: usize, a: &[RatFunc]) -> Option<usize> {
        if m * n <= TINY || k.nvars() == 0 {
            return None;
        }
        rank_qp(k, m, n, a)
    }
    fn rank_lower_bound(
        &self,
        k: &RatFuncField,
        m: usize,
        n: usize,
        a: &[RatFunc],
    ) -> Option<usize> {
        (k.nvars() > 0).then(|| rref::rank_at_point(k, m, n, a))
    }
    fn pivots(&self, k: &RatFuncField, m: usize, n: usize, a: &[RatFunc]) -> Option<Vec<usize>> {
        if m * n <= TINY || k.nvars() == 0 {
            return None;
        }
        rref::pivots_qp(k, m, n, a)
    }
    fn inverse(&self, k: &RatFuncField, n: usize, a: &[RatFunc]) -> Option<Option<Vec<RatFunc>>> {
        if n * n <= TINY || k.nvars() == 0 {
            return None;
        }
        inverse::inverse_qp(k, n, a)
    }
    fn mul(
        &self,
        k: &RatFuncField,
        dims: (usize, usize, usize),
        a: &[RatFunc],
        b: &[RatFunc],
    ) -> Option<Vec<RatFunc>> {
        if k.nvars() == 0 {
            return None;
        }
        mul::mul_qp(k, dims, a, b)
    }
    fn poly_gcd(&self, k: &RatFuncField, f: &[RatFunc], g: &[RatFunc]) -> Option<Vec<RatFunc>> {
        if k.nvars() == 0 {
            return None;
        }
        poly_gcd_qp(k, f, g)
    }
}

/// A fixed word prime for the profile points (distinct from the interpolation primes; no
/// list of 41 primes at a cold start).
fn profile_prime(attempt: usize) -> crate::qkernels::prime::Prime {
    probe::side_prime(attempt)
}
