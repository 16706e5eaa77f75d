//! Planted Kronecker structures: block diagonal canonical pencils scrambled by random
//! unimodular integer row and column operations (shared by tests and `benches/pencil.rs`).
#![allow(dead_code)]

use exactlti::field::{Q, Rational};
use exactlti::matrix::Matrix;

/// The library's SplitMix64 (same stream as `tests/common::Rng`).
pub use exactlti::rng::SplitMix64 as PencilRng;

/// The planted canonical structure.
#[derive(Clone, Debug, Default)]
pub struct Planted {
    /// Right indices, left indices, infinite block sizes (each ascending).
    pub eps: Vec<usize>,
    pub eta: Vec<usize>,
    pub inf: Vec<usize>,
    /// Finite Jordan blocks `(eigenvalue, size)` with rational eigenvalues, and companion
    /// blocks of monic integer polynomials (coefficients low degree first, without the 1).
    pub jordan: Vec<(i64, usize)>,
    pub companions: Vec<Vec<i64>>,
}

fn q(n: i64) -> Rational {
    Rational::from_integer(n.into())
}

impl Planted {
    /// Canonical `(A, E)`: blocks placed along the diagonal.
    pub fn canonical(&self) -> (Matrix<Q>, Matrix<Q>) {
        let mut blocks: Vec<(Matrix<Q>, Matrix<Q>)> = Vec::new();
        for &k in &self.eps {
            // L_k: k x (k+1), A = [0 I], E = [I 0]
            let a = Matrix::from_fn(Q, k, k + 1, |i, j| q((j == i + 1) as i64));
            let e = Matrix::from_fn(Q, k, k + 1, |i, j| q((j == i) as i64));
            blocks.push((a, e));
        }
        for &k in &self.eta {
            let a = Matrix::from_fn(Q, k + 1, k, |i, j| q((i == j + 1) as i64));
            let e = Matrix::from_fn(Q, k + 1, k, |i, j| q((i == j) as i64));
            blocks.push((a, e));
        }
        for &k in &self.inf {
            let a = Matrix::identity(Q, k);
            let e = Matrix::from_fn(Q, k, k, |i, j| q((j == i + 1) as i64));
            blocks.push((a, e));
        }
        for &(l, k) in &self.jordan {
            let a = Matrix::from_fn(
                Q,
                k,
                k,
                |i, j| {
                    if i == j { q(l) } else { q((j == i + 1) as i64) }
                },
            );
            blocks.push((a, Matrix::identity(Q, k)));
        }
        for c in &self.companions {
            let k = c.len();
            let a = Matrix::from_fn(Q, k, k, |i, j| {
                if i + 1 == k {
                    q(-c[j])
                } else {
                    q((j == i + 1) as i64)
                }
            });
            blocks.push((a, Matrix::identity(Q, k)));
        }
        let m: usize = blocks.iter().map(|b| b.0.nrows()).sum();
        let n: usize = blocks.iter().map(|b| b.0.ncols()).sum();
        let mut a = Matrix::zeros(Q, m, n);
        let mut e = Matrix::zeros(Q, m, n);
        let (mut r, mut c) = (0, 0);
        for (ba, be) in &blocks {
            a.set_block(r, c, ba);
            e.set_block(r, c, be);
            r += ba.nrows();
            c += ba.ncols();
        }
        (a, e)
    }
    /// `P (A - sE) Q` with random unimodular integer `P`, `Q` (`ops` elementary operations
    /// each, multipliers in -2..=2).
    pub fn scrambled(&self, seed: u64, ops: usize) -> (Matrix<Q>, Matrix<Q>) {
        let (a, e) = self.canonical();
        let mut rng = PencilRng(seed);
        let p = unimodular(a.nrows(), ops, &mut rng);
        let qm = unimodular(a.ncols(), ops, &mut rng);
        (&(&p * &a) * &qm, &(&p * &e) * &qm)
    }
    /// A random structure with roughly `size` columns.
    pub fn random(rng: &mut PencilRng, size: usize) -> Planted {
        let mut p = Planted::default();
        let mut cols = 0;
        while cols < size {
            match rng.int(0, 4) {
                0 => {
                    let k = rng.int(0, 3) as usize;
                    p.eps.push(k);
                    cols += k + 1;
                }
                1 => {
                    let k = rng.int(0, 3) as usize;
                    p.eta.push(k);
                    cols += k;
                }
                2 => {
                    let k = rng.int(1, 3) as usize;
                    p.inf.push(k);
                    cols += k;
                }
                3 => {
                    let k = rng.int(1, 3) as usize;
                    p.jordan.push((rng.int(-2, 2), k));
                    cols += k;
                }
                _ => {
                    // x^2 - c with c not a square: irreducible over Q
                    let c = [2, 3, 5, -1, -2, -3][rng.int(0, 5) as usize];
                    p.companions.push(vec![-c, 0]);
                    cols += 2;
                }
            }
        }
        p.eps.sort();
        p.eta.sort();
        p.inf.sort();
        p
    }
}

/// Product of `ops` random elementary integer operations: determinant 1.
pub fn unimodular(n: usize, ops: usize, rng: &mut PencilRng) -> Matrix<Q> {
    let mut t = Matrix::identity(Q, n);
    if n < 2 {
        return t;
    }
    for _ in 0..ops {
        let i = rng.int(0, n as i64 - 1) as usize;
        let j = rng.int(0, n as i64 - 1) as usize;
        if i == j {
            continue;
        }
        let f = q(rng.int(-2, 2));
        for c in 0..n {
            let v = t.get(i, c) + &(&f * t.get(j, c));
            t.set(i, c, v);
        }
    }
    t
}

/// A planted (A, B): Brunovsky chains of lengths `kappa` with random integer state
/// feedback, an uncontrollable block `a_u` coupled into the controllable part, scrambled by
/// a unimodular similarity: `(T A T^-1, T B)`. Returns (A, B).
pub fn planted_ctrb(
    kappa: &[usize],
    a_u: &Matrix<Q>,
    seed: u64,
    ops: usize,
) -> (Matrix<Q>, Matrix<Q>) {
    let mut rng = PencilRng(seed);
    let nc: usize = kappa.iter().sum();
    let nu = a_u.nrows();
    let n = nc + nu;
    let m = kappa.len();
    let mut a = Matrix::zeros(Q, n, n);
    let mut b = Matrix::zeros(Q, n, m);
    let mut off = 0;
    for (j, &k) in kappa.iter().enumerate() {
        for i in 0..k.saturating_sub(1) {
            a.set(off + i, off + i + 1, q(1));
        }
        if k > 0 {
            b.set(off + k - 1, j, q(1));
            // feedback row: the last state of the chain gets random dependence
            for c in 0..n {
                if c < nc || rng.int(0, 1) == 0 {
                    let v = a.get(off + k - 1, c) + &q(rng.int(-2, 2));
                    a.set(off + k - 1, c, v);
                }
            }
        }
        off += k;
    }
    a.set_block(nc, nc, a_u);
    let t = unimodular(n, ops, &mut rng);
    let ti = t.inverse().unwrap();
    (&(&t * &a) * &ti, &t * &b)
}
