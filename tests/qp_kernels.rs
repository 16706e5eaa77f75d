//! The matrix kernels of Q(p) (evaluation/interpolation, registered on the field) against the
//! generic algorithms, with their identities checked: A A^-1 = I and det against Berkowitz
//! (so A adj(A) = det(A) I), the charpoly against the Q charpoly of the substituted matrix at
//! random rational points, A N = 0 with rank + nullity = n; no conditions for charpoly and
//! det; scale cases (diag(p0..p9), n-mass chains) with exact orders and transfer functions.

use crate::common::systems::diag_qp;
use exactlti::field::{Field, Q, Rational};
use exactlti::matrix::Matrix;
use exactlti::ratfunc::{RatFunc, RatFuncField};
use exactlti::rng::SplitMix64;

/// A random entry: zero, a small polynomial, or a small polynomial over `c + p0`.
fn entry(k: &RatFuncField, rng: &mut SplitMix64) -> RatFunc {
    let vars = k.vars().to_vec();
    let poly = |rng: &mut SplitMix64, terms: usize| {
        let mut s = format!("{}", rng.int(-3, 3));
        for _ in 0..terms {
            let v = &vars[rng.int(0, vars.len() as i64 - 1) as usize];
            s += &format!(" + {}*{v}^{}", rng.int(-3, 3), rng.int(1, 2));
        }
        s
    };
    match rng.int(0, 9) {
        0..=1 => k.zero(),
        2..=7 => k.parse(&poly(rng, 2)).unwrap(),
        _ => {
            let num = poly(rng, 1);
            let den = format!("{} + {}", rng.int(1, 3), vars[0]);
            k.parse(&format!("({num})/({den})")).unwrap()
        }
    }
}

/// A random `m x n` matrix; one time in three of rank at most 1 or 2 (a product of factors).
fn random_matrix(
    k: &RatFuncField,
    rng: &mut SplitMix64,
    m: usize,
    n: usize,
) -> Matrix<RatFuncField> {
    let full = |rng: &mut SplitMix64, m: usize, n: usize| {
        Matrix::from_fn(k.clone(), m, n, |_, _| entry(k, rng))
    };
    if rng.int(0, 2) == 0 {
        let r = rng.int(1, 2) as usize;
        &full(rng, m, r) * &full(rng, r, n)
    } else {
        full(rng, m, n)
    }
}

fn fields() -> Vec<RatFuncField> {
    vec![
        RatFuncField::new(&["a", "b"]).unwrap(),
        RatFuncField::new(&["a", "b", "c"]).unwrap(),
    ]
}

/// The rational point `point`, substituted into every entry; `None` at a pole.
fn at(a: &Matrix<RatFuncField>, point: &[Rational]) -> Option<Matrix<Q>> {
    let k = a.field();
    let data: Option<Vec<Rational>> = a.as_slice().iter().map(|x| k.eval(x, point)).collect();
    Some(Matrix::from_vec(Q, a.nrows(), a.ncols(), data?))
}

#[test]
fn kernels_agree_with_the_generic_algorithms() {
    let mut rng = SplitMix64(2025);
    for k in fields() {
        for case in 0..24 {
            let (m, n) = (rng.int(1, 4) as usize, rng.int(1, 4) as usize);
            let a = random_matrix(&k, &mut rng, m, n);
            let (r, piv) = a.rref();
            let (rg, pg) = a.rref_gauss_jordan();
            assert_eq!((&r, &piv), (&rg, &pg), "rref, case {case}: {a}");
            assert_eq!(a.rank(), piv.len(), "rank, case {case}: {a}");
            let ns = a.nullspace();
            assert_eq!(ns.ncols() + piv.len(), n, "nullity, case {case}");
            assert!((&a * &ns).is_zero(), "A N = 0, case {case}: {a}");
            if m == n {
                let cp = a.charpoly().unwrap();
                assert_eq!(cp, a.charpoly_berkowitz().unwrap(), "charpoly, case {case}");
                let det = a.det().unwrap();
                let c0 = cp.coeff(0);
                let sign = if n % 2 == 0 { k.one() } else { k.neg(&k.one()) };
                assert_eq!(
                    det,
                    k.mul(&sign, &c0),
                    "det = (-1)^n charpoly(0), case {case}"
                );
                match a.inverse() {
                    Ok(inv) => {
                        assert!(!k.is_zero(&det));
                        assert!((&a * &inv).is_identity(), "A A^-1 = I, case {case}");
                        let adj = inv.scale(&det);
                        assert_eq!(&a * &adj, Matrix::identity(k.clone(), n).scale(&det));
                    }
                    Err(_) => assert!(k.is_zero(&det), "singular exactly when det = 0"),
                }
            }
        }
    }
}

#[test]
fn charpoly_commutes_with_substitution() {
    let mut rng = SplitMix64(7);
    for k in fields() {
        for _ in 0..12 {
            let n = rng.int(2, 5) as usize;
            let a = random_matrix(&k, &mut rng, n, n);
            let cp = a.charpoly().unwrap();
            for _ in 0..3 {
                let point: Vec<Rational> = (0..k.nvars())
                    .map(|_| Rational::new(rng.int(-9, 9).into(), rng.int(1, 5).into()))
                    .collect();
                let Some(aq) = at(&a, &point) else { continue };
                let want = aq.charpoly().unwrap();
                let got: Vec<Rational> = cp
                    .coeffs()
                    .iter()
                    .map(|c| k.eval(c, &point).expect("no pole where A has none"))
                    .collect();
                assert_eq!(got, want.coeffs().to_vec());
            }
        }
    }
}

#[test]
fn charpoly_and_det_carry_no_conditions() {
    let k = RatFuncField::new(&["a", "b", "c"]).unwrap();
    let mut rng = SplitMix64(11);
    for _ in 0..6 {
        let a = random_matrix(&k, &mut rng, 4, 4);
        let k2 = k.fresh();
        let a = a.map(&k2, |x| x.clone());
        a.charpoly().unwrap();
        a.det().unwrap();
        assert!(k2.conditions().unwrap().is_empty(), "{a}");
    }
}

/// A dense `n x n` matrix with entries linear in a, b, c (the bench and anchor shape).
fn dense_linear(k: &RatFuncField, n: usize, seed: u64) -> Matrix<RatFuncField> {
    let mut rng = SplitMix64(seed);
    Matrix::from_fn(k.clone(), n, n, |_, _| {
        let t = format!(
            "{} + {}*a + {}*b + {}*c",
            rng.int(-5, 5),
            rng.int(-5, 5),
            rng.int(-5, 5),
            rng.int(-5, 5)
        );
        k.parse(&t).unwrap()
    })
}

#[test]
fn dense_8x8_in_three_parameters() {
    let k = RatFuncField::new(&["a", "b", "c"]).unwrap();
    let a = dense_linear(&k, 8, 1);
    let cp = a.charpoly().unwrap();
    assert_eq!(cp.degree(), Some(8));
    // every coefficient is a polynomial of total degree at most 8 - k
    for (i, c) in cp.coeffs().iter().enumerate() {
        assert!(c.den().is_one() && c.num().total_degree() as usize <= 8 - i);
    }
    let det = a.det().unwrap();
    assert_eq!(det.num().total_degree(), 8);
    let point = [
        Rational::from_integer(2.into()),
        Rational::from_integer((-1).into()),
        Rational::new(1.into(), 3.into()),
    ];
    let aq = at(&a, &point).unwrap();
    assert_eq!(k.eval(&det, &point).unwrap(), aq.det().unwrap());
    let (r, piv) = a.rref();
    assert_eq!(piv, (0..8).collect::<Vec<_>>());
    assert!(r.is_identity());
    let inv = a.inverse().unwrap();
    assert!((&a * &inv).is_identity());
}

// ---------------------------------------------------------------- scale cases

#[test]
fn diag_p0_to_p9_transfer_function_and_minimal_order() {
    let s = diag_qp(10);
    // G = sum 1/(s - p_i) = chi'(s) / chi(s), chi = prod (s - p_i), in lowest terms
    let g = s.transfer_matrix().unwrap();
    let chi = s.a.charpoly().unwrap();
    assert_eq!(g.entries[0][0].den, chi);
    assert_eq!(g.entries[0][0].num, chi.derivative());
    let r =
        exactlti::realization::minimal(&s, exactlti::realization::MinrealMethod::Kalman).unwrap();
    assert_eq!(r.order, 10);
    assert!(r.verified);
}

#[test]
fn mass_chains_transfer_functions_and_minimal_orders() {
    let mut rng = SplitMix64(3);
    for n in 2..=10 {
        let s = crate::common::systems::chain_qp(n);
        let g = s.transfer_matrix().unwrap();
        let (num, den) = (&g.entries[0][0].num, &g.entries[0][0].den);
        assert_eq!(den.degree(), Some(2 * n), "no cancellation, n = {n}");
        // against the transfer function over Q at a random point
        let k = s.a.field().clone();
        let point: Vec<Rational> = (0..3)
            .map(|_| Rational::new(rng.int(1, 9).into(), rng.int(1, 4).into()))
            .collect();
        let sq = exactlti::system::StateSpace::new(
            at(&s.a, &point).unwrap(),
            at(&s.b, &point).unwrap(),
            at(&s.c, &point).unwrap(),
            at(&s.d, &point).unwrap(),
        )
        .unwrap();
        let gq = sq.transfer_matrix().unwrap();
        let ev = |p: &exactlti::poly::Poly<RatFuncField>| -> Vec<Rational> {
            p.coeffs()
                .iter()
                .map(|c| k.eval(c, &point).unwrap())
                .collect()
        };
        assert_eq!(ev(num), gq.entries[0][0].num.coeffs().to_vec(), "n = {n}");
        assert_eq!(ev(den), gq.entries[0][0].den.coeffs().to_vec(), "n = {n}");
        if n <= 6 || n == 10 {
            let r =
                exactlti::realization::minimal(&s, exactlti::realization::MinrealMethod::Kalman)
                    .unwrap();
            assert_eq!(r.order, 2 * n, "n = {n}");
            assert!(r.verified);
        }
    }
}

/// `generic_rank_at_least` over Q(p): `true` only when the generic rank (the rank the
/// recording kernel proves) reaches `r`, and it records no condition; rank-deficient
/// products (rank <= l) never pass at r = l + 1.
#[test]
fn generic_rank_at_least_is_the_rank_and_records_nothing() {
    let k = RatFuncField::new(&["a", "b", "c"]).unwrap();
    let mut rng = SplitMix64(20261126);
    for case in 0..8 {
        let (n, l) = (4 + case % 2, 1 + case % 3);
        let low = &random_matrix(&k, &mut rng, n, l) * &random_matrix(&k, &mut rng, l, n);
        let full = random_matrix(&k, &mut rng, n, n);
        for a in [low, full] {
            let k2 = k.fresh();
            let a = a.map(&k2, |x| x.clone());
            let probe = a.generic_rank_at_least(a.nrows());
            let fast: Vec<bool> = (0..=n + 1).map(|r| a.generic_rank_at_least(r)).collect();
            assert!(k2.conditions().unwrap().is_empty(), "{a}");
            let rank = a.rank();
            assert_eq!(probe, rank == n, "{a}");
            for (r, &f) in fast.iter().enumerate() {
                // true proves rank >= r; at this point and prime it is never short here
                assert_eq!(f, r <= rank, "r = {r}, rank = {rank}: {a}");
            }
        }
    }
}
