//! The mechanical normal form of controllable single-input systems at scale (issue 25): the
//! interleaved controller form ([`exactlti::structure::mechanical::companion`]) instead of
//! the search of eq. 15, checked as identities:
//! - random controllable single-input systems over Q (n = 2..8, fixed seed): the form is
//!   verified, $t^{-1} t = I$, $t A = \tilde A t$, $t B = e_n$, the Markov parameters agree to
//!   $2n$, and the last rows of $K$, $D_q$ are the coefficients of $\det(sI - A)$;
//! - diag(p0..p{n-1}) with B = C^T = ones over Q(p) (n = 4, 6, 8): the same identities as
//!   rational functions ($t A = \tilde A t$ column by column) and $t$ is the inverse
//!   Vandermonde row scaled by $1/\prod_{j \ne i}(p_i - p_j)$;
//! - n-mass chains in m, k, c (n = 2..4): the form exists, is verified and keeps the Markov
//!   parameters.

use crate::common::systems::{chain_qp, diag_qp};
use exactlti::field::{Field, Q};
use exactlti::matrix::Matrix;
use exactlti::rng::SplitMix64;
use exactlti::structure::mechanical::{
    DEFAULT_MAX_CANDIDATES, MechanicalForm, mechanical_normal_form_in,
};
use exactlti::system::StateSpace;

fn form_of<K: Field>(s: &StateSpace<K>) -> MechanicalForm<K> {
    let r =
        mechanical_normal_form_in(None, &s.a, &s.b, &s.c, &s.d, DEFAULT_MAX_CANDIDATES).unwrap();
    assert!(r.exists && r.verified);
    r.form.unwrap()
}

/// The identities of the interleaved form on `s` (single input, controllable).
fn assert_interleaved<K: Field>(s: &StateSpace<K>, markov: bool, tag: &str) {
    let f = form_of(s);
    let k = s.a.field().clone();
    let n = s.a.nrows();
    let h = n / 2;
    assert!((&f.t_inv * &f.t).is_identity(), "t^-1 t = I, {tag}");
    assert_eq!(
        &f.t_inv * &f.a_tilde,
        &s.a * &f.t_inv,
        "t^-1 A~ = A t^-1, {tag}"
    );
    let mut e_n = Matrix::zeros(k.clone(), n, 1);
    e_n.set(n - 1, 0, k.one());
    assert_eq!(f.b_tilde, e_n, "B~ = e_n, {tag}");
    assert_eq!(&f.t_inv * &f.b_tilde, s.b, "t^-1 B~ = B, {tag}");
    assert_eq!(&f.output * &f.t, s.c, "C~ t = C, {tag}");
    assert_eq!((f.alpha.len(), f.candidates), (0, 0), "no search, {tag}");
    // last rows of K and D_q: the coefficients a_0, a_2, ... and a_1, a_3, ... of chi
    let chi = s.a.charpoly().unwrap();
    for i in 0..h {
        assert_eq!(f.stiffness.get(h - 1, i), &chi.coeff(2 * i), "K, {tag}");
        assert_eq!(f.damping.get(h - 1, i), &chi.coeff(2 * i + 1), "D_q, {tag}");
    }
    if markov {
        let t = StateSpace::new(f.a_tilde, f.b_tilde, f.output, f.feedthrough).unwrap();
        assert_eq!(t.markov(2 * n), s.markov(2 * n), "Markov parameters, {tag}");
    }
}

#[test]
fn interleaved_form_over_q_is_a_similarity_with_the_markov_parameters() {
    let mut rng = SplitMix64(2525);
    let mut done = 0;
    for case in 0..40 {
        let n = 2 * rng.int(1, 4) as usize;
        let a = Matrix::from_fn(Q, n, n, |_, _| Q.from_i64(rng.int(-4, 4)));
        let b = Matrix::from_fn(Q, n, 1, |_, _| Q.from_i64(rng.int(-2, 2)));
        let c = Matrix::from_fn(Q, 1, n, |_, _| Q.from_i64(rng.int(-3, 3)));
        if !exactlti::realization::is_controllable(&a, &b) {
            continue;
        }
        let s = StateSpace::new(a, b, c, Matrix::zeros(Q, 1, 1)).unwrap();
        assert_interleaved(&s, true, &format!("case {case}, n = {n}"));
        done += 1;
    }
    assert!(done >= 20, "only {done} controllable cases");
}

#[test]
fn diag_mnf_is_the_interleaved_form_with_vandermonde_columns() {
    for n in [4, 6, 8] {
        let s = diag_qp(n);
        assert_interleaved(&s, n <= 6, &format!("diag{n}"));
        let f = form_of(&s);
        let k = s.a.field().clone();
        // row 0 of t is w: w_i = 1 / prod_{j != i} (p_i - p_j)
        for i in 0..n {
            let mut d = k.one();
            for j in (0..n).filter(|&j| j != i) {
                d = k.mul(&d, &k.sub(&k.var(i), &k.var(j)));
            }
            assert_eq!(k.mul(f.t.get(0, i), &d), k.one(), "w_{i}, diag{n}");
        }
    }
}

#[test]
fn chain_mnf_keeps_the_markov_parameters() {
    for n in 2..=4 {
        assert_interleaved(&chain_qp(n), true, &format!("chain{n}"));
    }
}
