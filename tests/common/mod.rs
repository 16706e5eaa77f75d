//! Shared test helpers: a deterministic generator and the three test fields.
#![allow(dead_code)]
pub mod pencils;
pub mod systems;

use exactlti::field::{Field, Q, QuadraticField, Rational};
use exactlti::matrix::Matrix;

/// SplitMix64: a tiny deterministic generator (fixed seeds, no external crate).
pub struct Rng(pub u64);

impl Rng {
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E3779B97F4A7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58476D1CE4E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D049BB133111EB);
        z ^ (z >> 31)
    }
    /// Uniform integer in `lo..=hi`.
    pub fn int(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.next_u64() % ((hi - lo + 1) as u64)) as i64
    }
    pub fn rational(&mut self, range: i64) -> Rational {
        Rational::new(self.int(-range, range).into(), self.int(1, 3).into())
    }
}

/// Iteration count scaled by `EXACTLTI_TEST_MULTIPLIER` (FLINT style).
pub fn iters(base: usize) -> usize {
    let m: usize = std::env::var("EXACTLTI_TEST_MULTIPLIER")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(1);
    base * m
}

/// A random element of `k`: rational, or `a + b*g` for the field generator `g` given.
pub fn elem<K: Field>(k: &K, gen_elem: &Option<K::Elem>, rng: &mut Rng) -> K::Elem {
    let a = k.from_rational(&rng.rational(5));
    match gen_elem {
        Some(g) if rng.int(0, 2) == 0 => k.add(&a, &k.mul(&k.from_rational(&rng.rational(3)), g)),
        _ => a,
    }
}

pub fn random_matrix<K: Field>(
    k: &K,
    g: &Option<K::Elem>,
    m: usize,
    n: usize,
    rng: &mut Rng,
) -> Matrix<K> {
    Matrix::from_fn(k.clone(), m, n, |_, _| {
        if rng.int(0, 3) == 0 {
            k.zero()
        } else {
            elem(k, g, rng)
        }
    })
}

/// A random unimodular-ish integer matrix (product of elementary operations): invertible.
pub fn unimodular<K: Field>(k: &K, n: usize, rng: &mut Rng) -> Matrix<K> {
    let mut t = Matrix::identity(k.clone(), n);
    if n < 2 {
        return t;
    }
    for _ in 0..3 * n {
        let i = rng.int(0, n as i64 - 1) as usize;
        let j = rng.int(0, n as i64 - 1) as usize;
        if i == j {
            continue;
        }
        let f = k.from_i64(rng.int(-2, 2));
        for c in 0..n {
            let v = k.add(t.get(i, c), &k.mul(&f, t.get(j, c)));
            t.set(i, c, v);
        }
    }
    t
}

pub fn q() -> Q {
    Q
}
pub fn qsqrt2() -> (QuadraticField, Option<<QuadraticField as Field>::Elem>) {
    let k = QuadraticField::new(2).unwrap();
    let g = k.gen_elem();
    (k, Some(g))
}
pub fn qi() -> (QuadraticField, Option<<QuadraticField as Field>::Elem>) {
    let k = QuadraticField::gaussian();
    let g = k.gen_elem();
    (k, Some(g))
}
