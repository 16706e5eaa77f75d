//! Dense n x n matrices over Q(a, b[, c]) with entries `c0 + c1 a + c2 b (+ c3 c)` (the
//! files of `scripts/qp_scale.py`, coefficients in -5..5, fixed seeds), as identities
//! (speed lives in `scripts/anchors/qp_matrix.py`):
//! - the characteristic polynomial and the determinant commute with substitution: at random
//!   rational points they equal those of the evaluated matrix over Q;
//! - the RREF at a point where no recorded condition vanishes equals the RREF of the
//!   evaluated matrix (a full-rank square matrix: the identity; a wide one [A | A e]: the
//!   pivots and the free column);
//! - matrices whose certified interpolation grid is large but whose results are small
//!   (A = T D T^-1 with D = diag of parameters, T unimodular with parameter entries): the
//!   probed degrees give charpoly = prod (x - p_i) and det = prod p_i exactly.
//!
//! Debug builds run n = 4..7 (q = 2, 3); n = 8..10 are in the release anchor run
//! (`python3 scripts/anchors/qp_matrix.py --dense-table`).

use crate::qp_scale::at;
use exactlti::field::{Field, Q, Rational};
use exactlti::matrix::Matrix;
use exactlti::poly::Poly;
use exactlti::ratfunc::RatFuncField;
use exactlti::rng::SplitMix64;

/// The dense test matrix: n x n over Q(a, b[, c]), entries linear in the q parameters.
fn dense(n: usize, q: usize, seed: u64) -> Matrix<RatFuncField> {
    let names = ["a", "b", "c"];
    let k = RatFuncField::new(&names[..q]).unwrap();
    let mut rng = SplitMix64(seed);
    Matrix::from_fn(k.clone(), n, n, |_, _| {
        let mut e = k.from_i64(rng.int(-5, 5));
        for v in 0..q {
            let c = k.from_i64(rng.int(-5, 5));
            e = k.add(&e, &k.mul(&c, &k.var(v)));
        }
        e
    })
}

/// Every dense case: `(n, q, A)` for n = 4..7 and q = 2, 3 parameters, A = [`dense`] seeded
/// by `(n, q)`.
fn dense_cases() -> impl Iterator<Item = (usize, usize, Matrix<RatFuncField>)> {
    (4..=7).flat_map(|n| {
        [2, 3]
            .into_iter()
            .map(move |q| (n, q, dense(n, q, 1000 + 10 * n as u64 + q as u64)))
    })
}

fn point(q: usize, rng: &mut SplitMix64) -> Vec<Rational> {
    (0..q)
        .map(|_| Rational::new(rng.int(-30, 30).into(), rng.int(1, 7).into()))
        .collect()
}

fn eval_poly(p: &Poly<RatFuncField>, x: &[Rational]) -> Vec<Rational> {
    let k = p.field();
    p.coeffs()
        .iter()
        .map(|c| k.eval(c, x).expect("polynomial coefficients"))
        .collect()
}

#[test]
fn dense_charpoly_and_det_commute_with_substitution() {
    let mut rng = SplitMix64(25);
    for (n, q, a) in dense_cases() {
        let chi = a.charpoly().unwrap();
        let det = a.det().unwrap();
        assert_eq!(chi.degree(), Some(n));
        for _ in 0..3 {
            let x = point(q, &mut rng);
            let aq = at(&a, &x);
            let want = aq.charpoly().unwrap();
            assert_eq!(
                eval_poly(&chi, &x),
                want.coeffs().to_vec(),
                "n = {n}, q = {q}"
            );
            assert_eq!(
                a.field().eval(&det, &x).unwrap(),
                aq.det().unwrap(),
                "n = {n}, q = {q}"
            );
        }
    }
}

#[test]
fn dense_rref_commutes_with_substitution_off_the_conditions() {
    let mut rng = SplitMix64(52);
    for (n, q, a) in dense_cases() {
        let k = a.field().fresh();
        let a = Matrix::from_vec(k.clone(), n, n, a.as_slice().to_vec());
        // [A | A e]: rank n, pivots 0..n-1, the free column is the row sums
        let ones = Matrix::from_fn(k.clone(), n, 1, |_, _| k.one());
        let wide = a.hstack(&a.try_mul(&ones).unwrap()).unwrap();
        let (r, piv) = wide.rref();
        assert_eq!(piv, (0..n).collect::<Vec<_>>(), "n = {n}, q = {q}");
        let conds = k.conditions().unwrap();
        let mut checked = 0;
        while checked < 2 {
            let x = point(q, &mut rng);
            if conds
                .iter()
                .any(|c| Q.is_zero(&k.eval(&k.from_mpoly(c.clone()), &x).unwrap()))
            {
                continue;
            }
            let (rq, pq) = at(&wide, &x).rref();
            assert_eq!(pq, piv);
            assert_eq!(at(&r, &x), rq, "n = {n}, q = {q}");
            checked += 1;
        }
    }
}

/// A = T D T^-1 over Q(p0..p{n-1}): D = diag(p), T = L U with unit triangular L, U whose
/// entries are parameters (det T = 1), so A's entries have large degrees while its
/// charpoly is prod (x - p_i).
fn similar_diag(n: usize) -> (RatFuncField, Matrix<RatFuncField>) {
    let names: Vec<String> = (0..n).map(|i| format!("p{i}")).collect();
    let k = RatFuncField::new(&names).unwrap();
    let l = Matrix::from_fn(k.clone(), n, n, |i, j| match i.cmp(&j) {
        std::cmp::Ordering::Equal => k.one(),
        std::cmp::Ordering::Greater => k.var((i + j) % n),
        std::cmp::Ordering::Less => k.zero(),
    });
    let u = Matrix::from_fn(k.clone(), n, n, |i, j| match i.cmp(&j) {
        std::cmp::Ordering::Equal => k.one(),
        std::cmp::Ordering::Less => k.from_i64((i + 2 * j) as i64 % 3 - 1),
        std::cmp::Ordering::Greater => k.zero(),
    });
    let t = l.try_mul(&u).unwrap();
    let d = Matrix::diagonal(k.clone(), &(0..n).map(|i| k.var(i)).collect::<Vec<_>>());
    let a = t
        .try_mul(&d)
        .unwrap()
        .try_mul(&t.inverse().unwrap())
        .unwrap();
    (k, a)
}

#[test]
fn probed_degrees_give_the_small_charpoly_of_a_similar_diagonal() {
    for n in [4, 5] {
        let (k, a) = similar_diag(n);
        let chi = a.charpoly().unwrap();
        let mut want = Poly::new(k.clone(), vec![k.one()]);
        let mut det = k.one();
        for i in 0..n {
            want = want.mul(&Poly::new(k.clone(), vec![k.neg(&k.var(i)), k.one()]));
            det = k.mul(&det, &k.var(i));
        }
        assert_eq!(chi, want, "n = {n}");
        assert_eq!(a.det().unwrap(), det, "n = {n}");
        // and at a point, as over Q
        let x: Vec<Rational> = (0..n as i64)
            .map(|i| Rational::from_integer((2 * i + 3).into()))
            .collect();
        assert_eq!(
            eval_poly(&chi, &x),
            at(&a, &x).charpoly().unwrap().coeffs().to_vec()
        );
    }
}
