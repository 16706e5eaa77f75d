//! n-mass chains with symbolic m, k, c (issue 25, item 4), as identities (speed lives in
//! `scripts/anchors/qp_matrix.py`; the 10-mass rows are in its scale table):
//! - `tf`: the transfer function's Laurent coefficients at infinity are the Markov
//!   parameters C A^k B of the chain ([`TransferMatrix::matches_markov`]), its numerator is
//!   (c s + k)^(n-1) / m^n up to the constant of the denominator's normalisation;
//! - `zeros`: the invariant-zero polynomial is (s + k/c)^(n-1);
//! - `minreal` (Kalman, Rosenbrock, Ho–Kalman): order 2n, the Markov parameters of the chain;
//! - `scb`: verified, block dimensions summing to 2n, x_a of dimension n - 1;
//! - `jordan` (the components over Q(m, k, c)): A T = T J per component, the factors' degrees
//!   times multiplicities sum to 2n, one block per eigenvalue (distinct modes), and the monic
//!   factors multiply back to the characteristic polynomial.
//!
//! Every command runs n = 2..10 (`cargo test`, test profile) except the heaviest, which are
//! `#[ignore]`d with their reason and run by
//! `cargo test --release --test all scale_chain:: -- --include-ignored`.

use crate::common::systems::chain_qp;
use exactlti::field::Field;
use exactlti::jordan::over_qp::components_qp;
use exactlti::poly::Poly;
use exactlti::realization::{MinrealMethod, minimal};
use exactlti::structure::zeros::invariant_zeros;

#[test]
fn chain_tf_matches_the_markov_parameters() {
    for n in 2..=10 {
        let s = chain_qp(n);
        let g = s.transfer_matrix().unwrap();
        assert!(g.matches_markov(&s), "n = {n}");
        let f = &g.entries[0][0];
        assert_eq!(f.den.degree(), Some(2 * n), "n = {n}");
        // numerator (c s + k)^(n-1) times a constant of Q(m, k, c)
        let k = s.a.field().clone();
        let cs_k = Poly::new(k.clone(), vec![k.var(1), k.var(2)]);
        let mut want = Poly::new(k.clone(), vec![k.one()]);
        for _ in 1..n {
            want = want.mul(&cs_k);
        }
        let lc = k.div(&f.num.lc(), &want.lc()).unwrap();
        assert_eq!(f.num, want.scale(&lc), "n = {n}");
    }
}

#[test]
fn chain_zeros_are_minus_k_over_c() {
    for n in 2..=10 {
        let s = chain_qp(n);
        let z = invariant_zeros(&s.a, &s.b, &s.c, &s.d).unwrap();
        let k = s.a.field().clone();
        // (s + k/c)^(n-1)
        let root = Poly::new(
            k.clone(),
            vec![k.div(&k.var(1), &k.var(2)).unwrap(), k.one()],
        );
        let mut want = Poly::new(k.clone(), vec![k.one()]);
        for _ in 1..n {
            want = want.mul(&root);
        }
        assert_eq!(z.polynomial, want, "n = {n}");
    }
}

#[test]
fn chain_minreal_keeps_the_markov_parameters() {
    for (method, nmax) in [
        (MinrealMethod::Kalman, 10),
        (MinrealMethod::Rosenbrock, 10),
        (MinrealMethod::HoKalman, 10),
    ] {
        for n in 2..=nmax {
            let s = chain_qp(n);
            let r = minimal(&s, method).unwrap();
            assert_eq!(r.order, 2 * n, "{method:?} n = {n}");
            assert!(r.verified, "{method:?} n = {n}");
            assert_eq!(
                s.markov(4 * n),
                r.system.markov(4 * n),
                "{method:?} n = {n}"
            );
        }
    }
}

#[test]
fn chain_scb_blocks() {
    for n in 2..=10 {
        let s = chain_qp(n);
        let r = exactlti::structure::scb::scb(&s.a, &s.b, &s.c, &s.d).unwrap();
        assert!(r.verified, "n = {n}");
        assert_eq!(r.dims.iter().sum::<usize>(), 2 * n, "n = {n}");
        assert_eq!(r.dims[0], n - 1, "n = {n}");
        assert_eq!(r.chains, vec![n + 1], "n = {n}");
    }
}

/// The Jordan components of the n-mass chain over Q(m, k, c) (see the module docs).
fn check_chain_jordan(n: usize) {
    let s = chain_qp(n);
    let (cp, comps) = components_qp(&s.a).unwrap();
    let total: usize = comps.iter().map(|c| c.degree() * c.multiplicity).sum();
    assert_eq!(total, 2 * n, "n = {n}");
    for c in &comps {
        assert!(c.verify(&s.a), "n = {n}: A T = T J");
        assert_eq!(c.blocks, vec![1; c.multiplicity], "n = {n}: distinct modes");
    }
    let k = s.a.field().clone();
    let mut prod = Poly::new(k.clone(), vec![k.one()]);
    for f in &cp.factors {
        for _ in 0..f.multiplicity {
            prod = prod.mul(&f.monic);
        }
    }
    assert_eq!(prod, cp.charpoly, "n = {n}");
}

#[test]
fn chain_jordan_components() {
    for n in 2..=6 {
        check_chain_jordan(n);
    }
}

/// n = 7..10: 4-5 s each in a release build (factoring the discriminants recorded as
/// conditions), minutes in the test profile.
#[test]
#[ignore = "slow in the test profile: run with --release -- --include-ignored"]
fn chain_jordan_components_up_to_ten() {
    for n in 7..=10 {
        check_chain_jordan(n);
    }
}
