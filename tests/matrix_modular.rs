//! Exact matrix kernels over Q: the multi-modular path (`matrix::modular`) against the
//! fraction-free path (`qkernels::fraction_free`) and a naive rational Gauss–Jordan oracle.
//!
//! Iteration counts scale with the env var `EXACTLTI_TEST_MULTIPLIER` (default 1).

use exactlti::field::Rational;
use exactlti::matrix::over_q as oq;
use exactlti::qkernels as qk;
use exactlti::qkernels::fraction_free as ff;
use exactlti::qkernels::modular as mm;
use exactlti::rng::Lcg64;
use num_bigint::BigInt;
use num_traits::{One, Zero};

fn q(x: i64) -> Rational {
    Rational::from_integer(x.into())
}

fn qq(n: i64, d: i64) -> Rational {
    Rational::new(n.into(), d.into())
}

fn ints(xs: &[i64]) -> Vec<Rational> {
    xs.iter().map(|&x| q(x)).collect()
}

fn multiplier() -> usize {
    std::env::var("EXACTLTI_TEST_MULTIPLIER")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(1)
}

/// Fixed-seed 64-bit LCG (the same recurrence as benches/matrix.rs).
struct Lcg(Lcg64);

impl Lcg {
    fn next(&mut self) -> u64 {
        self.0.next_u31()
    }
    fn below(&mut self, k: u64) -> usize {
        (self.next() % k) as usize
    }
    fn int(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.next() % (hi - lo + 1) as u64) as i64
    }
    /// A rational with small numerator and, one time in three, a denominator up to 6.
    fn rational(&mut self) -> Rational {
        let n = self.int(-9, 9);
        if self.below(3) == 0 {
            qq(n, self.int(1, 6))
        } else {
            q(n)
        }
    }
    fn matrix(&mut self, m: usize, n: usize) -> Vec<Rational> {
        (0..m * n).map(|_| self.rational()).collect()
    }
    /// `m x n` of rank at most `k`: a product of `m x k` and `k x n` random matrices.
    fn low_rank(&mut self, m: usize, n: usize, k: usize) -> Vec<Rational> {
        let l = self.matrix(m, k);
        let r = self.matrix(k, n);
        matmul(m, k, n, &l, &r)
    }
}

fn matmul(m: usize, k: usize, n: usize, a: &[Rational], b: &[Rational]) -> Vec<Rational> {
    let mut c = vec![Rational::zero(); m * n];
    for i in 0..m {
        for l in 0..k {
            if a[i * k + l].is_zero() {
                continue;
            }
            for j in 0..n {
                c[i * n + j] += &a[i * k + l] * &b[l * n + j];
            }
        }
    }
    c
}

fn identity(n: usize) -> Vec<Rational> {
    (0..n * n)
        .map(|i| if i / n == i % n { q(1) } else { q(0) })
        .collect()
}

/// Naive Gauss–Jordan over Q: the oracle.
fn rref_naive(m: usize, n: usize, a: &[Rational]) -> (Vec<Rational>, Vec<usize>) {
    let mut a = a.to_vec();
    let mut piv = Vec::new();
    let mut r = 0;
    for c in 0..n {
        let Some(i) = (r..m).find(|&i| !a[i * n + c].is_zero()) else {
            continue;
        };
        for j in 0..n {
            a.swap(i * n + j, r * n + j);
        }
        let inv = a[r * n + c].recip();
        for j in 0..n {
            a[r * n + j] = &a[r * n + j] * &inv;
        }
        for i in 0..m {
            if i != r && !a[i * n + c].is_zero() {
                let f = a[i * n + c].clone();
                for j in 0..n {
                    let t = &f * &a[r * n + j];
                    a[i * n + j] -= t;
                }
            }
        }
        piv.push(c);
        r += 1;
        if r == m {
            break;
        }
    }
    (a, piv)
}

/// $p(A)$ by Horner, `p` low degree first.
fn poly_at_matrix(n: usize, p: &[Rational], a: &[Rational]) -> Vec<Rational> {
    let mut acc = vec![Rational::zero(); n * n];
    for c in p.iter().rev() {
        acc = matmul(n, n, n, &acc, a);
        for i in 0..n {
            acc[i * n + i] += c;
        }
    }
    acc
}

fn check_square(n: usize, a: &[Rational], ctx: &str) {
    let det = mm::det_modular(n, a);
    assert_eq!(det, ff::det_bareiss(n, a), "det {ctx}");
    assert_eq!(det, oq::det_q(n, a), "det dispatch {ctx}");
    let cp = mm::charpoly_modular(n, a);
    assert_eq!(cp, ff::charpoly_berkowitz(n, a), "charpoly {ctx}");
    assert_eq!(cp.len(), n + 1, "charpoly length {ctx}");
    assert!(cp[n].is_one(), "charpoly monic {ctx}");
    let c0 = if n.is_multiple_of(2) {
        det.clone()
    } else {
        -det.clone()
    };
    assert_eq!(cp[0], c0, "charpoly constant term is (-1)^n det {ctx}");
    assert!(
        poly_at_matrix(n, &cp, a).iter().all(|x| x.is_zero()),
        "Cayley-Hamilton {ctx}"
    );
    let inv = mm::inverse_modular(n, a);
    assert_eq!(inv, ff::inverse_bareiss(n, a), "inverse {ctx}");
    assert_eq!(inv.is_none(), det.is_zero(), "singular iff det = 0 {ctx}");
    if let Some(inv) = inv {
        assert_eq!(matmul(n, n, n, a, &inv), identity(n), "A A^-1 {ctx}");
        assert_eq!(matmul(n, n, n, &inv, a), identity(n), "A^-1 A {ctx}");
    }
}

fn check_rect(m: usize, n: usize, a: &[Rational], ctx: &str) {
    let (r, piv) = mm::rref_modular(m, n, a);
    assert_eq!((r.clone(), piv.clone()), rref_naive(m, n, a), "rref {ctx}");
    assert_eq!(
        (r.clone(), piv.clone()),
        ff::rref_bareiss(m, n, a),
        "rref bareiss {ctx}"
    );
    assert_eq!(
        (r.clone(), piv.clone()),
        oq::rref_q(m, n, a),
        "rref dispatch {ctx}"
    );
    // RREF is idempotent and canonical
    assert_eq!(
        mm::rref_modular(m, n, &r),
        (r.clone(), piv.clone()),
        "idempotent {ctx}"
    );
    let rank = piv.len();
    assert_eq!(mm::rank_modular(m, n, a), rank, "rank {ctx}");
    assert_eq!(ff::rank_bareiss(m, n, a), rank, "rank bareiss {ctx}");
    assert_eq!(oq::rank_q(m, n, a), rank, "rank dispatch {ctx}");
    let ns = mm::nullspace_modular(m, n, a);
    assert_eq!(ns, oq::nullspace_q(m, n, a), "nullspace dispatch {ctx}");
    assert_eq!(ns.len() + rank, n, "rank + nullity {ctx}");
    for v in &ns {
        assert!(
            matmul(m, n, 1, a, v).iter().all(|x| x.is_zero()),
            "A v = 0 {ctx}, v = {v:?}"
        );
    }
}

#[test]
fn examples_empty_and_1x1() {
    // 0 x 0
    assert_eq!(oq::det_q(0, &[]), q(1));
    assert_eq!(mm::det_modular(0, &[]), q(1));
    assert_eq!(oq::charpoly_q(0, &[]), vec![q(1)]);
    assert_eq!(mm::charpoly_modular(0, &[]), vec![q(1)]);
    assert_eq!(oq::inverse_q(0, &[]), Some(vec![]));
    assert_eq!(mm::inverse_modular(0, &[]), Some(vec![]));
    assert_eq!(oq::rank_q(0, 0, &[]), 0);
    assert_eq!(mm::rref_modular(0, 0, &[]), (vec![], vec![]));
    // 0 x n and n x 0
    for (m, n) in [(0, 3), (3, 0)] {
        assert_eq!(oq::rank_q(m, n, &[]), 0);
        assert_eq!(mm::rank_modular(m, n, &[]), 0);
        assert_eq!(oq::rref_q(m, n, &[]), (vec![], vec![]));
        assert_eq!(mm::rref_modular(m, n, &[]), (vec![], vec![]));
        let ns = mm::nullspace_modular(m, n, &[]);
        assert_eq!(ns, oq::nullspace_q(m, n, &[]));
        assert_eq!(ns.len(), n);
        for (f, v) in ns.iter().enumerate() {
            assert_eq!(v, &(0..n).map(|j| q((j == f) as i64)).collect::<Vec<_>>());
        }
    }
    // 1 x 1
    for a in [qq(-5, 3), q(7), q(0)] {
        let s = [a.clone()];
        check_square(1, &s, &format!("[{a}]"));
        check_rect(1, 1, &s, &format!("[{a}]"));
        assert_eq!(oq::charpoly_q(1, &s), vec![-a.clone(), q(1)]);
    }
    assert_eq!(oq::inverse_q(1, &[qq(-5, 3)]), Some(vec![qq(-3, 5)]));
    assert_eq!(mm::inverse_modular(1, &[q(0)]), None);
}

#[test]
fn examples_values() {
    let a = ints(&[1, 2, 3, 4]);
    assert_eq!(mm::det_modular(2, &a), q(-2));
    assert_eq!(mm::charpoly_modular(2, &a), ints(&[-2, -5, 1]));
    assert_eq!(
        mm::inverse_modular(2, &a),
        Some(vec![q(-2), q(1), qq(3, 2), qq(-1, 2)])
    );
    let a = ints(&[1, 2, 3, 2, 4, 6]);
    assert_eq!(
        mm::rref_modular(2, 3, &a),
        (ints(&[1, 2, 3, 0, 0, 0]), vec![0])
    );
    assert_eq!(
        mm::nullspace_modular(2, 3, &a),
        vec![ints(&[-2, 1, 0]), ints(&[-3, 0, 1])]
    );
    // rational entries with denominators: rows (1/2, 1/3) and (1/4, 1/6) are parallel
    let a = vec![qq(1, 2), qq(1, 3), qq(1, 4), qq(1, 6)];
    assert_eq!(mm::rank_modular(2, 2, &a), 1);
    assert_eq!(
        mm::rref_modular(2, 2, &a),
        (vec![q(1), qq(2, 3), q(0), q(0)], vec![0])
    );
    assert_eq!(mm::det_modular(2, &a), q(0));
    let a = vec![qq(1, 2), qq(1, 3), qq(1, 5), qq(1, 7)];
    // det = 1/14 - 1/15 = 1/210; charpoly x^2 - (1/2 + 1/7) x + 1/210
    assert_eq!(mm::det_modular(2, &a), qq(1, 210));
    assert_eq!(
        mm::charpoly_modular(2, &a),
        vec![qq(1, 210), qq(-9, 14), q(1)]
    );
    check_square(2, &a, "2x2 rational");
}

#[test]
fn properties_paths_agree_small() {
    let mut g = Lcg(Lcg64(1));
    for it in 0..60 * multiplier() {
        let (m, n) = (g.below(8), g.below(8));
        let a = if g.below(2) == 0 {
            g.matrix(m, n)
        } else {
            let k = g.below(4);
            g.low_rank(m, n, k)
        };
        check_rect(m, n, &a, &format!("it {it}: {m}x{n} A = {a:?}"));
        let n = g.below(7);
        let a = if g.below(3) == 0 {
            let k = g.below(n.max(1) as u64);
            g.low_rank(n, n, k)
        } else {
            g.matrix(n, n)
        };
        check_square(n, &a, &format!("it {it}: {n}x{n} A = {a:?}"));
    }
}

#[test]
fn properties_medium_dispatch_to_modular() {
    // sizes above the fraction-free thresholds: the *_q entry points take the modular path
    let mut g = Lcg(Lcg64(7));
    for it in 0..3 * multiplier() {
        let (m, n, k) = (12 + g.below(6), 14 + g.below(6), 3 + g.below(6));
        let a = g.low_rank(m, n, k);
        let ctx = format!("it {it}: {m}x{n} rank <= {k}");
        check_rect(m, n, &a, &ctx);
        assert!(oq::rank_q(m, n, &a) <= k, "{ctx}");
        let n = 9 + g.below(4);
        let a = g.matrix(n, n);
        check_square(n, &a, &format!("it {it}: {n}x{n} A = {a:?}"));
    }
}

#[test]
fn thin_products_have_the_planted_rank() {
    let mut g = Lcg(Lcg64(11));
    for k in [0usize, 1, 5, 10] {
        // a generic product of 30 x k and k x 40 integer matrices has rank k
        let l: Vec<Rational> = (0..30 * k).map(|_| q(g.int(-9, 9))).collect();
        let r: Vec<Rational> = (0..k * 40).map(|_| q(g.int(-9, 9))).collect();
        let a = matmul(30, k, 40, &l, &r);
        let rank = oq::rank_q(30, 40, &a);
        assert_eq!(rank, oq::rank_q(k, 40, &r).min(oq::rank_q(30, k, &l)));
        assert_eq!(rank, k, "generic rank k = {k}");
        check_rect(30, 40, &a, &format!("rank {k}"));
    }
}

#[test]
fn unlucky_primes_are_discarded() {
    // the first prime of the sequence divides entries and minors
    let p = BigInt::from(qk::prime::nth_prime(0).p);
    let pq = Rational::from_integer(p.clone());
    let a = vec![pq.clone(), q(0), q(0), q(1)];
    assert_eq!(mm::rank_modular(2, 2, &a), 2);
    assert_eq!(mm::det_modular(2, &a), pq);
    assert_eq!(
        mm::inverse_modular(2, &a),
        Some(vec![pq.recip(), q(0), q(0), q(1)])
    );
    // pivot profile changes modulo p: [[1, 1, 0], [1, 1 + p, 1]]
    let a = vec![q(1), q(1), q(0), q(1), q(1) + &pq, q(1)];
    let (r, piv) = mm::rref_modular(2, 3, &a);
    assert_eq!(piv, vec![0, 1]);
    assert_eq!((r, piv), rref_naive(2, 3, &a));
    // several early primes at once: det = p0 p1 p2
    let ps: Vec<Rational> = (0..3)
        .map(|i| Rational::from_integer(qk::prime::nth_prime(i).p.into()))
        .collect();
    let a = vec![
        ps[0].clone(),
        q(0),
        q(0),
        q(0),
        ps[1].clone(),
        q(0),
        q(0),
        q(0),
        ps[2].clone(),
    ];
    check_square(3, &a, "diag(p0, p1, p2)");
    check_rect(3, 3, &a, "diag(p0, p1, p2)");
}

#[test]
fn huge_entries() {
    let mut g = Lcg(Lcg64(5));
    let big = Rational::from_integer(BigInt::one() << 150u32);
    for it in 0..2 * multiplier() {
        let n = 4 + g.below(8);
        let a: Vec<Rational> = g
            .matrix(n, n)
            .into_iter()
            .map(|x| if g.below(4) == 0 { &x * &big + q(1) } else { x })
            .collect();
        let ctx = format!("it {it}: {n}x{n} with 150-bit entries");
        check_square(n, &a, &ctx);
        check_rect(n, n, &a, &ctx);
    }
}

#[test]
fn similarity_invariance() {
    let mut g = Lcg(Lcg64(13));
    for it in 0..4 * multiplier() {
        let n = 2 + g.below(10);
        let a = g.matrix(n, n);
        // T unit upper triangular: invertible, T^-1 exact
        let t: Vec<Rational> = (0..n * n)
            .map(|i| match (i / n).cmp(&(i % n)) {
                std::cmp::Ordering::Equal => q(1),
                std::cmp::Ordering::Less => q(g.int(-3, 3)),
                _ => q(0),
            })
            .collect();
        let ti = oq::inverse_q(n, &t).expect("unit triangular");
        let b = matmul(n, n, n, &matmul(n, n, n, &ti, &a), &t);
        let ctx = format!("it {it}: n = {n}");
        assert_eq!(oq::charpoly_q(n, &a), oq::charpoly_q(n, &b), "{ctx}");
        assert_eq!(oq::rank_q(n, n, &a), oq::rank_q(n, n, &b), "{ctx}");
        assert_eq!(oq::det_q(n, &a), oq::det_q(n, &b), "{ctx}");
    }
}

/// The class of `rref-def` (issue 29): fractions p/q with |p|, q up to 10^6, rows that are
/// combinations of others placed anywhere, zero rows and zero or repeated columns. The
/// pivot-block path (`modular::pivot_solve`) must give the RREF of the naive elimination,
/// and its certificate must refuse an unlucky prime (the reconstruction path answers).
#[test]
fn properties_rank_deficient_fractions() {
    let mut g = Lcg(Lcg64(29));
    for it in 0..4 * multiplier() {
        let (m, n) = (9 + g.below(6), 9 + g.below(6));
        let mut a: Vec<Rational> = (0..m * n)
            .map(|_| qq(g.int(-1_000_000, 1_000_000), g.int(1, 1_000_000)))
            .collect();
        for _ in 0..1 + g.below(3) {
            // row t = c0 row s0 + c1 row s1
            let (t, s0, s1) = (g.below(m as u64), g.below(m as u64), g.below(m as u64));
            let (c0, c1) = (g.rational(), g.rational());
            for j in 0..n {
                a[t * n + j] = &c0 * &a[s0 * n + j] + &c1 * &a[s1 * n + j];
            }
        }
        match g.below(3) {
            0 => (0..m).for_each(|i| a[i * n + g.below(n as u64)] = q(0)),
            1 => {
                let (c, d) = (g.below(n as u64), g.below(n as u64));
                (0..m).for_each(|i| a[i * n + d] = a[i * n + c].clone());
            }
            _ => {}
        }
        let ctx = format!("it {it}: {m}x{n} A = {a:?}");
        check_rect(m, n, &a, &ctx);
        if let Some(res) = mm::pivot_solve::rref_pivot_solve(m, n, &a) {
            assert_eq!(res.pivots, rref_naive(m, n, &a).1, "pivots {ctx}");
        }
    }
    // pivot profile later modulo the first prime: [[1, 1, 0], [1, 1 + p, 1]] has pivots
    // 0, 2 there and 0, 1 over Q; the certificate refuses the block solve
    let p = Rational::from_integer(BigInt::from(qk::prime::nth_prime(0).p));
    let a = vec![q(1), q(1), q(0), q(1), q(1) + &p, q(1)];
    assert!(mm::pivot_solve::rref_pivot_solve(2, 3, &a).is_none());
    check_rect(2, 3, &a, "unlucky pivots");
}
