//! The per-point maps of the $\mathbb{Q}(p)$ kernels, over $\mathbb{Z}/p$: determinant,
//! generic row/column profile, and the normalised solve $X = C_P^{-1} C$ with the leading
//! minors of $C_P$.

use crate::mpoly::MPoly;
use crate::qkernels::prime::Prime;
use num_bigint::Sign;

/// $\det A$ of the `n x n` row-major `a` (destroyed): the kernel of the multi-modular
/// determinant over $\mathbb{Q}$.
pub use crate::qkernels::modular::det::det_mod_p;

/// Gauss–Jordan with the generic rule of `Matrix::rref` (the first row at or below the
/// current one with a nonzero entry in the column, swapped up): the pivot columns and the
/// original indices of the pivot rows, in pivot order.
pub fn profile_mod_p(pr: &Prime, m: usize, n: usize, a: &mut [u64]) -> (Vec<usize>, Vec<usize>) {
    let mut rows: Vec<usize> = (0..m).collect();
    let mut piv = Vec::new();
    let mut r = 0;
    for c in 0..n {
        if r == m {
            break;
        }
        let Some(p) = (r..m).find(|&i| a[i * n + c] != 0) else {
            continue;
        };
        if p != r {
            for j in 0..n {
                a.swap(p * n + j, r * n + j);
            }
            rows.swap(p, r);
        }
        let inv = pr.inv(a[r * n + c]).expect("nonzero pivot");
        for i in r + 1..m {
            let f = a[i * n + c];
            if f == 0 {
                continue;
            }
            let f = pr.mul(f, inv);
            for j in c..n {
                let t = pr.mul(f, a[r * n + j]);
                a[i * n + j] = pr.sub(a[i * n + j], t);
            }
        }
        piv.push(c);
        r += 1;
    }
    rows.truncate(r);
    (piv, rows)
}

/// For the `r x n` row-major `c` (destroyed) and pivot columns `piv` (`r` of them): the
/// leading minors $M_1, \dots, M_r$ of $C_P$ (no row exchanges) followed by the entries of
/// $\Delta X_{:,F}$, $X = C_P^{-1} C$, $\Delta = M_r$, row by row over the non-pivot columns
/// `free`. `None` when a leading minor vanishes at this point.
pub fn minors_and_solve_mod_p(
    pr: &Prime,
    n: usize,
    c: &mut [u64],
    piv: &[usize],
    free: &[usize],
) -> Option<Vec<u64>> {
    let r = piv.len();
    let mut out = Vec::with_capacity(r + r * free.len());
    let mut m = 1u64;
    for (k, &pc) in piv.iter().enumerate() {
        let pv = c[k * n + pc];
        if pv == 0 {
            return None;
        }
        m = pr.mul(m, pv);
        out.push(m);
        let inv = pr.inv(pv).expect("nonzero");
        for j in 0..n {
            c[k * n + j] = pr.mul(c[k * n + j], inv);
        }
        for i in 0..r {
            if i == k {
                continue;
            }
            let f = c[i * n + pc];
            if f == 0 {
                continue;
            }
            for j in 0..n {
                let t = pr.mul(f, c[k * n + j]);
                c[i * n + j] = pr.sub(c[i * n + j], t);
            }
        }
    }
    for k in 0..r {
        for &f in free {
            out.push(pr.mul(m, c[k * n + f]));
        }
    }
    Some(out)
}

/// $f(x)$ modulo the prime.
pub fn eval_mod_p(pr: &Prime, f: &MPoly, point: &[u64]) -> u64 {
    let mut s = 0u64;
    for (m, c) in f.terms() {
        let (sg, digits) = c.to_u64_digits();
        let mut t = pr.reduce_limbs(sg == Sign::Minus, &digits);
        for (v, &x) in point.iter().enumerate() {
            let e = f.exp(*m, v);
            if e > 0 {
                t = pr.mul(t, pr.pow(x, u64::from(e)));
            }
        }
        s = pr.add(s, t);
    }
    s
}

/// A polynomial reduced modulo a prime once (coefficients as residues, exponent vectors
/// unpacked), for evaluation at many points ([`ReducedPoly::eval`]).
pub struct ReducedPoly {
    terms: Vec<(u64, Vec<u32>)>,
}

impl ReducedPoly {
    pub fn new(pr: &Prime, f: &MPoly) -> Self {
        let terms = f
            .terms()
            .iter()
            .map(|(m, c)| {
                let (sg, digits) = c.to_u64_digits();
                (pr.reduce_limbs(sg == Sign::Minus, &digits), f.exps(*m))
            })
            .collect();
        ReducedPoly { terms }
    }
    /// Largest exponent of any variable.
    pub fn max_exp(&self) -> u32 {
        self.terms
            .iter()
            .flat_map(|(_, e)| e.iter().copied())
            .max()
            .unwrap_or(0)
    }
    /// $f(x)$ with `pw[v][e]` $= x_v^e$ (see [`powers`]).
    pub fn eval(&self, pr: &Prime, pw: &[Vec<u64>]) -> u64 {
        let mut s = 0u64;
        for (c, e) in &self.terms {
            let mut t = *c;
            for (v, &ev) in e.iter().enumerate() {
                if ev > 0 {
                    t = pr.mul(t, pw[v][ev as usize]);
                }
            }
            s = pr.add(s, t);
        }
        s
    }
}

/// `pw[v][e]` $= x_v^e$ for $e \le$ `maxe`.
pub fn powers(pr: &Prime, point: &[u64], maxe: u32) -> Vec<Vec<u64>> {
    point
        .iter()
        .map(|&x| {
            let mut v = vec![1u64; maxe as usize + 1];
            for e in 1..v.len() {
                v[e] = pr.mul(v[e - 1], x);
            }
            v
        })
        .collect()
}
