//! Shared test helpers: a deterministic generator and the three test fields.
#![allow(dead_code)]
pub mod cli;
pub mod pencils;
pub mod polys;
pub mod systems;

use exactlti::field::{Field, Q, QuadraticField, Rational};
use exactlti::matrix::Matrix;

/// The library's SplitMix64 ([`exactlti::rng::SplitMix64`]): `Rng(seed)`, `next_u64`, `int`.
pub use exactlti::rng::SplitMix64 as Rng;

/// `n / d` with `n` in `-range..=range` and `d` in `1..=3`.
pub fn rational(rng: &mut Rng, range: i64) -> Rational {
    Rational::new(rng.int(-range, range).into(), rng.int(1, 3).into())
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
    let a = k.from_rational(&rational(rng, 5));
    match gen_elem {
        Some(g) if rng.int(0, 2) == 0 => k.add(&a, &k.mul(&k.from_rational(&rational(rng, 3)), g)),
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

/// One `#[test]` per field for a generic check `$check(&k, &gen, seed, iters)`: over
/// $\mathbb{Q}$ (no generator), $\mathbb{Q}(\sqrt 2)$, $\mathbb{Q}(i)$ and $\mathbb{Q}(p)$
/// (generator `p`), seeded `$seed`, `$seed + 1`, `$seed + 2`, `$seed + 3`, with
/// `common::iters($n)` rounds (`$n_qp` over $\mathbb{Q}(p)$, whose arithmetic is slower):
/// `for_each_field!(check_linalg, 2311, 10, 5; linalg_over_q, linalg_over_q_sqrt2,
/// linalg_over_q_i, linalg_over_q_p);`
#[macro_export]
macro_rules! for_each_field {
    ($check:ident, $seed:expr, $n:expr, $n_qp:expr; $q:ident, $sqrt2:ident, $i:ident, $p:ident) => {
        $crate::for_each_number_field!($check, $seed, $n; $q, $sqrt2, $i);

        #[test]
        fn $p() {
            let k = exactlti::ratfunc::RatFuncField::new(&["p"]).unwrap();
            let g = Some(k.var(0));
            $check(&k, &g, $seed + 3, $crate::common::iters($n_qp));
        }
    };
}

/// As [`for_each_field!`] over the number fields only (Q, Q(sqrt 2), Q(i): operations that
/// need certified roots or signs, which Q(p) refuses), seeded `$seed`, `$seed + 1`,
/// `$seed + 2`.
#[macro_export]
macro_rules! for_each_number_field {
    ($check:ident, $seed:expr, $n:expr; $q:ident, $sqrt2:ident, $i:ident) => {
        #[test]
        fn $q() {
            $check(
                &$crate::common::q(),
                &None,
                $seed,
                $crate::common::iters($n),
            );
        }

        #[test]
        fn $sqrt2() {
            let (k, g) = $crate::common::qsqrt2();
            $check(&k, &g, $seed + 1, $crate::common::iters($n));
        }

        #[test]
        fn $i() {
            let (k, g) = $crate::common::qi();
            $check(&k, &g, $seed + 2, $crate::common::iters($n));
        }
    };
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

/// `a + b*sqrt(d)` (or `a + b*i`) with integer parts.
pub fn quadratic(a: i64, b: i64) -> exactlti::field::Quadratic {
    exactlti::field::Quadratic::new(
        Rational::from_integer(a.into()),
        Rational::from_integer(b.into()),
    )
}

/// A matrix over a quadratic field from `(a, b)` pairs, `a + b*sqrt(d)` each.
pub fn quadratic_matrix(k: &QuadraticField, rows: &[&[(i64, i64)]]) -> Matrix<QuadraticField> {
    Matrix::from_rows(
        k.clone(),
        rows.iter()
            .map(|r| r.iter().map(|&(a, b)| quadratic(a, b)).collect())
            .collect(),
    )
    .unwrap()
}

/// `m x n` row-major entries p/q with |p| <= `pmax` and 1 <= q <= `qmax`, a zero one time
/// in `zeros` (none for `zeros = 0`).
pub fn random_rationals(
    g: &mut Rng,
    m: usize,
    n: usize,
    pmax: i64,
    qmax: i64,
    zeros: i64,
) -> Vec<Rational> {
    (0..m * n)
        .map(|_| {
            if zeros > 0 && g.int(0, zeros - 1) == 0 {
                Rational::from_integer(0.into())
            } else {
                Rational::new(g.int(-pmax, pmax).into(), g.int(1, qmax).into())
            }
        })
        .collect()
}

/// The product of the row-major `m x k` `a` and `k x n` `b` (zero entries of `a` skipped).
pub fn matmul_q(m: usize, k: usize, n: usize, a: &[Rational], b: &[Rational]) -> Vec<Rational> {
    let mut c = vec![Rational::from_integer(0.into()); m * n];
    for i in 0..m {
        for l in 0..k {
            if a[i * k + l] != Rational::from_integer(0.into()) {
                for j in 0..n {
                    c[i * n + j] += &a[i * k + l] * &b[l * n + j];
                }
            }
        }
    }
    c
}

/// A matrix over $\mathbb{Q}(p)$ from rows of entries written as text (`"-cr/(m*u)"`).
pub fn qp_matrix(
    k: &exactlti::ratfunc::RatFuncField,
    rows: &[&[&str]],
) -> Matrix<exactlti::ratfunc::RatFuncField> {
    Matrix::from_rows(
        k.clone(),
        rows.iter()
            .map(|r| r.iter().map(|x| k.parse(x).unwrap()).collect())
            .collect(),
    )
    .unwrap()
}
