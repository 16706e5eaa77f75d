//! Symbolic models at scale (issue 25, item 4), as identities rather than timings (speed
//! lives in `benches/qp_matrix.rs`):
//! - block-split RREF over Q(p) (rows and columns in independent blocks, permuted) equals
//!   the generic Gauss–Jordan RREF, with rank + nullity = n and A N = 0;
//! - diag(p0..p{n-1}): the Jordan form is diagonal with A T = T J, one condition p_i - p_j
//!   per pair;
//! - n-mass chains in m, k, c (n = 2..6): the Kalman minimal realization has the Markov
//!   parameters of the chain, the transfer function commutes with substitution at random
//!   rational points (against C (s0 I - A)^-1 B over Q), the SCB is verified with dims
//!   summing to 2n, x_a of the n - 1 zeros at -k/c and one chain of relative degree n + 1.

use crate::common::systems::diag_qp;
use exactlti::field::{Field, Q, Rational};
use exactlti::matrix::Matrix;
use exactlti::ratfunc::{RatFunc, RatFuncField};
use exactlti::realization::{MinrealMethod, minimal};
use exactlti::rng::SplitMix64;
use exactlti::system::StateSpace;

pub(crate) fn at(a: &Matrix<RatFuncField>, point: &[Rational]) -> Matrix<Q> {
    let k = a.field();
    let data: Vec<Rational> = a
        .as_slice()
        .iter()
        .map(|x| k.eval(x, point).expect("no pole at the point"))
        .collect();
    Matrix::from_vec(Q, a.nrows(), a.ncols(), data)
}

/// A random small polynomial or ratio in the field's variables (never zero).
pub(crate) fn entry(k: &RatFuncField, rng: &mut SplitMix64) -> RatFunc {
    let vars = k.vars().to_vec();
    let v = |rng: &mut SplitMix64| vars[rng.int(0, vars.len() as i64 - 1) as usize].clone();
    let s = match rng.int(0, 3) {
        0 => format!("{}", rng.int(1, 4)),
        1 => format!("{} + {}*{}", rng.int(1, 3), rng.int(1, 3), v(rng)),
        2 => format!("{} - {}", v(rng), v(rng)),
        _ => format!(
            "({}*{})/({} + {})",
            rng.int(1, 3),
            v(rng),
            rng.int(1, 3),
            v(rng)
        ),
    };
    let e = k.parse(&s).unwrap();
    if k.is_zero(&e) { k.one() } else { e }
}

/// A block-diagonal matrix (blocks of rank up to full, some rank-deficient), rows and
/// columns permuted, with a few zero rows and columns.
pub(crate) fn blocky(k: &RatFuncField, rng: &mut SplitMix64) -> Matrix<RatFuncField> {
    let nb = rng.int(2, 4) as usize;
    let mut blocks = Vec::new();
    let (mut m, mut n) = (0, 0);
    for _ in 0..nb {
        let (bm, bn) = (rng.int(1, 3) as usize, rng.int(1, 3) as usize);
        let mut b = Matrix::from_fn(k.clone(), bm, bn, |_, _| entry(k, rng));
        if rng.int(0, 2) == 0 && bm > 1 {
            // a rank-deficient block: last row = first row
            for j in 0..bn {
                let x = b.get(0, j).clone();
                b.set(bm - 1, j, x);
            }
        }
        blocks.push((m, n, b));
        m += bm;
        n += bn;
    }
    let (m, n) = (m + rng.int(0, 1) as usize, n + rng.int(0, 1) as usize);
    let mut a = Matrix::zeros(k.clone(), m, n);
    for (r0, c0, b) in &blocks {
        for i in 0..b.nrows() {
            for j in 0..b.ncols() {
                a.set(r0 + i, c0 + j, b.get(i, j).clone());
            }
        }
    }
    let perm = |rng: &mut SplitMix64, len: usize| {
        let mut p: Vec<usize> = (0..len).collect();
        for i in (1..len).rev() {
            p.swap(i, rng.int(0, i as i64) as usize);
        }
        p
    };
    let (pr, pc) = (perm(rng, m), perm(rng, n));
    Matrix::from_fn(k.clone(), m, n, |i, j| a.get(pr[i], pc[j]).clone())
}

#[test]
fn block_split_rref_equals_the_generic_rref() {
    let k = RatFuncField::new(&["a", "b", "c"]).unwrap();
    let mut rng = SplitMix64(25);
    for case in 0..30 {
        let a = blocky(&k, &mut rng);
        let (r, piv) = a.rref();
        let (rg, pg) = a.rref_gauss_jordan();
        assert_eq!((&r, &piv), (&rg, &pg), "case {case}: {a}");
        assert_eq!(a.rank(), piv.len(), "rank, case {case}");
        let ns = a.nullspace();
        assert_eq!(ns.ncols() + piv.len(), a.ncols(), "nullity, case {case}");
        assert!((&a * &ns).is_zero(), "A N = 0, case {case}");
    }
}

#[test]
fn diag_jordan_is_diagonal_with_pairwise_conditions() {
    let n = 6;
    let s = diag_qp(n);
    let k = s.a.field().clone();
    k.clear_conditions();
    let j = exactlti::jordan::jordan_qp(&s.a).unwrap();
    assert!(j.verified && j.complete());
    let (t, jj) = j.primary_form().unwrap();
    assert_eq!(&s.a * &t, &t * &jj, "A T = T J");
    assert_eq!(j.components.len(), n);
    for c in &j.components {
        assert_eq!(c.blocks, vec![1]);
    }
    let conditions: Vec<_> = j.conditions.iter().map(|c| c.num().clone()).collect();
    for a in 0..n {
        for b in a + 1..n {
            let d = k.parse(&format!("p{a} - p{b}")).unwrap();
            let f = d.num().primitive_part();
            let f = if conditions.contains(&f) { f } else { f.neg() };
            assert!(conditions.contains(&f), "p{a} - p{b} in {:?}", conditions);
        }
    }
}

#[test]
fn chains_minreal_keeps_the_markov_parameters() {
    for n in 2..=5 {
        let s = crate::common::systems::chain_qp(n);
        let r = minimal(&s, MinrealMethod::Kalman).unwrap();
        assert_eq!(r.order, 2 * n, "n = {n}");
        assert!(r.verified);
        assert_eq!(s.markov(4 * n), r.system.markov(4 * n), "n = {n}");
        assert_eq!(r.system.d, s.d);
    }
}

#[test]
fn chains_transfer_function_commutes_with_substitution() {
    let mut rng = SplitMix64(2);
    for n in 2..=6 {
        let s = crate::common::systems::chain_qp(n);
        let k = s.a.field().clone();
        let g = s.transfer_matrix().unwrap();
        let (num, den) = (&g.entries[0][0].num, &g.entries[0][0].den);
        for _ in 0..2 {
            let point: Vec<Rational> = (0..3)
                .map(|_| Rational::new(rng.int(1, 9).into(), rng.int(1, 4).into()))
                .collect();
            let sq = StateSpace::new(
                at(&s.a, &point),
                at(&s.b, &point),
                at(&s.c, &point),
                at(&s.d, &point),
            )
            .unwrap();
            // G(s0) = C (s0 I - A)^-1 B at a rational s0, against num(s0) / den(s0)
            let s0 = Rational::new(rng.int(10, 40).into(), 3.into());
            let ev = |p: &exactlti::poly::Poly<RatFuncField>| {
                p.coeffs().iter().rev().fold(Q.zero(), |acc, c| {
                    Q.add(&Q.mul(&acc, &s0), &k.eval(c, &point).unwrap())
                })
            };
            let si_a = &Matrix::identity(Q, 2 * n).scale(&s0) - &sq.a;
            let x = si_a.inverse().unwrap();
            let direct = &(&sq.c * &x) * &sq.b;
            let ratio = Q.div(&ev(num), &ev(den)).unwrap();
            assert_eq!(direct.get(0, 0), &ratio, "n = {n}");
        }
    }
}

#[test]
fn chains_scb_identities() {
    for n in 2..=4 {
        let s = crate::common::systems::chain_qp(n);
        let g = s.transfer_matrix().unwrap();
        let nz = g.entries[0][0].num.degree().unwrap();
        // G = (c s + k)^(n-1) / (m^n det(...)): n - 1 zeros at -k/c
        assert_eq!(nz, n - 1, "n = {n}");
        let r = exactlti::structure::scb::scb(&s.a, &s.b, &s.c, &s.d).unwrap();
        assert!(r.verified, "n = {n}");
        assert_eq!(r.dims.iter().sum::<usize>(), 2 * n, "n = {n}");
        // SISO, invertible: x_a carries the zeros, one chain of the relative degree
        assert_eq!(r.dims[0], nz, "n = {n}");
        assert_eq!(r.chains, vec![2 * n - nz], "n = {n}");
        assert!(r.left_invertible && r.right_invertible);
    }
}
