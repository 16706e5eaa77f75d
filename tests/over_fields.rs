//! Every structural operation over Q, Q(sqrt 2), Q(i) and Q(p) from one generic function
//! (issue 23, "Done when"): the same generator plants a system `A = P J P^-1` (Jordan blocks
//! of eigenvalues `c + s g`, `g` the field's generator), `B`, `C` and `D` over each field,
//! and [`check_all`] asserts the identities of each operation, recomputed here:
//!
//! * Jordan form: `A T = T J` per eigenvalue in its exact field (over Q(p): `A T = T J` as
//!   rational functions), the planted block sizes, the free response;
//! * minimal realization, Kalman: Markov parameters `C A^k B` (`k < 2n`) and `D` equal,
//!   order = McMillan degree (Hankel rank);
//! * minimal realization, Jordan method: the same Markov parameters through the traces,
//!   the same order as Kalman, and the real modal system's own Markov parameters when it
//!   lies over the base field; over Q(p) (the primary blocks: restriction blocks of simple
//!   factors, the others over `E = Q(p)[t]/(g)`) the sum of the blocks' Markov parameters
//!   (`Tr_{E/F}` of the modal ones, `traced_markov`) equals the system's, order = McMillan
//!   degree, and the realization over Q(p) has the same Markov parameters;
//! * transfer matrix: `G(s) = C (sI - A)^-1 B + D` reproduces every Markov parameter;
//! * invariant zeros: the SCB route and the Smith-form oracle give the same polynomial;
//! * special coordinate basis: every identity of its construction (`Scb::check`) and its
//!   invariant zero polynomial equal to the zeros'.

use crate::common::{self, Rng};
use exactlti::field::{Field, Q, QuadraticField};
use exactlti::jordan::{EigenField, jordan_over};
use exactlti::matrix::Matrix;
use exactlti::ratfunc::RatFuncField;
use exactlti::realization::{
    JordanMethod, MinrealMethod, SystemField, mcmillan_degree, minimal, minimal_jordan,
    minimal_kalman,
};
use exactlti::structure::scb::scb;
use exactlti::structure::zeros::{invariant_zeros, invariant_zeros_smith};
use exactlti::system::StateSpace;

/// The operations whose algorithm depends on the field's Jordan decomposition.
trait JordanOps: Field {
    /// Asserts the Jordan form's identities and the planted linear blocks.
    fn check_jordan(a: &Matrix<Self>, planted: &[(Self::Elem, usize)]);
    /// Asserts the Jordan-method realization's identities (when the field has one).
    fn check_minreal_jordan(sys: &StateSpace<Self>, order: usize);
}

/// The Jordan form over a field with certified eigenvalues: `A T = T J` per eigenvalue in
/// its exact field, and the planted blocks.
fn check_jordan_eigen<F: EigenField>(a: &Matrix<F>, planted: &[(F::Elem, usize)]) {
    let k = a.field();
    let jf = jordan_over(a).unwrap();
    assert!(jf.verified);
    let mut cols = 0;
    for rc in jf.root_columns() {
        let f = &rc.field;
        let ae = a.map(f, |x| f.from_base(x));
        assert_eq!(&ae * &rc.v, &rc.v * &rc.j, "A T = T J in {f}");
        cols += rc.v.ncols();
    }
    assert_eq!(cols, a.nrows());
    for (lam, _) in planted {
        let want: usize = planted.iter().filter(|(l, _)| l == lam).map(|p| p.1).sum();
        let c = jf
            .components
            .iter()
            .find(|c| c.degree() == 1 && k.neg(&c.factor.coeff(0)) == *lam)
            .unwrap_or_else(|| panic!("no component for {}", k.fmt_elem(lam)));
        assert_eq!(c.multiplicity, want);
    }
    assert!(jf.free_response().verify(&jf));
    if k.is_real() {
        assert!(jf.real_form().unwrap().verified);
    }
}

/// The Jordan-method realization over a field with a Jordan decomposition.
fn check_minreal_jordan_eigen<F: EigenField>(sys: &StateSpace<F>, order: usize) {
    let r = minimal_jordan(sys).unwrap();
    assert!(r.verified);
    assert_eq!(r.order(), order);
    assert_eq!(r.mcmillan_degree, order);
    if let Some(rs) = r.real_to_base() {
        let n = sys.nstates();
        assert!(rs.same_markov(sys, 2 * n + 2));
        assert_eq!(rs.nstates(), order);
    }
}

/// The Jordan-method realization through the front door ([`minimal`] with
/// [`MinrealMethod::Jordan`]) over every field: verified, order = McMillan degree, the same
/// Markov parameters and `D`; over Q(p) the primary blocks' Markov parameters add up to the
/// system's (the modal blocks' through `Tr_{E/F}`, the restriction blocks' as the rows and
/// columns of the realization they occupy).
fn check_minreal_jordan_any<K: SystemField>(sys: &StateSpace<K>, order: usize) {
    let n = sys.nstates();
    let r = minimal(sys, MinrealMethod::Jordan).unwrap();
    assert!(r.verified);
    assert_eq!(r.order, order, "order = McMillan degree");
    assert_eq!(r.system.nstates(), order);
    assert!(r.system.same_markov(sys, 2 * n + 2));
    assert_eq!(r.system.d, sys.d);
    let Some(JordanMethod::Primary(pm)) = &r.jordan else {
        return;
    };
    assert!(pm.verified);
    assert_eq!(pm.mcmillan_degree, order);
    assert_eq!(pm.stages[2], order);
    assert_eq!(pm.stages[0], n);
    let (p, m, f) = (sys.noutputs(), sys.ninputs(), sys.a.field().clone());
    let kmax = 2 * n;
    let modal: Vec<_> = pm
        .blocks
        .iter()
        .filter(|b| !b.is_restriction())
        .map(|b| (&b.modal[0], &b.modal[1], &b.modal[2]))
        .collect();
    let mut got = crate::jcommon::traced_markov(&modal, p, m, &f, kmax);
    let mut covered = 0;
    for b in &pm.blocks {
        covered += b.order;
        if !b.is_restriction() {
            continue;
        }
        let idx: Vec<usize> = (b.offset..b.offset + b.order).collect();
        let part = StateSpace::new(
            pm.system.a.select_rows(&idx).select_cols(&idx),
            pm.system.b.select_rows(&idx),
            pm.system.c.select_cols(&idx),
            sys.d.clone(),
        )
        .unwrap();
        for (g, h) in got.iter_mut().zip(part.markov(kmax)) {
            *g = &*g + &h;
        }
    }
    assert_eq!(covered, order, "the blocks cover the realization");
    for (k, (g, w)) in got.iter().zip(sys.markov(kmax)).enumerate() {
        assert_eq!(g, &w, "sum over the primary blocks of C A^{k} B");
    }
}

impl JordanOps for Q {
    fn check_jordan(a: &Matrix<Q>, planted: &[(Self::Elem, usize)]) {
        check_jordan_eigen(a, planted)
    }
    fn check_minreal_jordan(sys: &StateSpace<Q>, order: usize) {
        check_minreal_jordan_eigen(sys, order);
        check_minreal_jordan_any(sys, order)
    }
}

impl JordanOps for QuadraticField {
    fn check_jordan(a: &Matrix<Self>, planted: &[(Self::Elem, usize)]) {
        check_jordan_eigen(a, planted)
    }
    fn check_minreal_jordan(sys: &StateSpace<Self>, order: usize) {
        check_minreal_jordan_eigen(sys, order);
        check_minreal_jordan_any(sys, order)
    }
}

impl JordanOps for RatFuncField {
    /// Over Q(p) the generic Jordan form (`jordan::jordan_qp`): `A T = T J` recomputed on
    /// its primary form.
    fn check_jordan(a: &Matrix<Self>, planted: &[(Self::Elem, usize)]) {
        let jf = exactlti::jordan::jordan_qp(a).unwrap();
        assert!(jf.verified);
        let (t, j) = jf.primary_form().unwrap();
        assert_eq!(&jf.a * &t, &t * &j, "A T = T J over Q(p)");
        assert!(t.inverse().is_ok());
        let dim: usize = jf
            .components
            .iter()
            .map(|c| c.degree() * c.multiplicity)
            .sum();
        assert_eq!(dim, a.nrows());
        let values = jf.values();
        for (lam, _) in planted {
            let want: usize = planted.iter().filter(|(l, _)| l == lam).map(|p| p.1).sum();
            let i = values
                .iter()
                .position(|v| v.as_ref() == Some(lam))
                .expect("a planted eigenvalue in Q(p)");
            assert_eq!(jf.components[i].multiplicity, want);
        }
    }
    fn check_minreal_jordan(sys: &StateSpace<Self>, order: usize) {
        check_minreal_jordan_any(sys, order)
    }
}

/// `A = P J P^-1` (blocks of `c + s g`, `c` in -2..=2, `s` in {0, 1}), `B`, `C` with one
/// column / row, `D` a constant; returns the system and the planted blocks.
fn planted<F: Field>(
    k: &F,
    g: &Option<F::Elem>,
    rng: &mut Rng,
) -> (StateSpace<F>, Vec<(F::Elem, usize)>) {
    let mut blocks = vec![];
    let mut n = 0;
    let want = rng.int(2, 4) as usize;
    while n < want {
        let m = [1, 1, 2][rng.int(0, 2) as usize].min(want - n);
        let mut lam = k.from_i64(rng.int(-2, 2));
        if let Some(g) = g
            && rng.int(0, 1) == 1
        {
            lam = k.add(&lam, g);
        }
        blocks.push((lam, m));
        n += m;
    }
    let j = crate::jcommon::jordan_blocks(k, &blocks, n);
    let p = common::unimodular(k, n, rng);
    let a = &(&p * &j) * &p.inverse().unwrap();
    let nonzero = |rng: &mut Rng| {
        let x = common::elem(k, g, rng);
        if k.is_zero(&x) { k.one() } else { x }
    };
    let b = Matrix::from_fn(k.clone(), n, 1, |_, _| nonzero(rng));
    let c = Matrix::from_fn(k.clone(), 1, n, |_, _| nonzero(rng));
    let d = Matrix::from_fn(k.clone(), 1, 1, |_, _| k.from_i64(rng.int(0, 1)));
    (StateSpace::new(a, b, c, d).unwrap(), blocks)
}

/// Every operation of the module docs on planted systems over `k`.
fn check_all<F: JordanOps>(k: &F, g: &Option<F::Elem>, seed: u64, cases: usize) {
    let mut rng = Rng(seed);
    for _ in 0..cases {
        let (sys, blocks) = planted(k, g, &mut rng);
        let n = sys.nstates();
        // Jordan form
        F::check_jordan(&sys.a, &blocks);
        // minimal realization (Kalman): Markov parameters, D and the McMillan degree
        let mcm = mcmillan_degree(&sys);
        let kal = minimal_kalman(&sys).unwrap();
        assert!(kal.verified);
        assert_eq!(kal.order, mcm);
        assert!(kal.system.same_markov(&sys, 2 * n + 2));
        assert_eq!(kal.system.d, sys.d);
        // minimal realization (Jordan method)
        F::check_minreal_jordan(&sys, mcm);
        // transfer matrix
        let tf = sys.transfer_matrix().unwrap();
        assert!(tf.matches_markov(&sys));
        // invariant zeros: the SCB route against the Smith-form oracle
        let z = invariant_zeros(&sys.a, &sys.b, &sys.c, &sys.d).unwrap();
        let zs = invariant_zeros_smith(&sys.a, &sys.b, &sys.c, &sys.d).unwrap();
        assert_eq!(z.polynomial, zs.polynomial);
        assert_eq!(z.normal_rank, zs.normal_rank);
        // special coordinate basis
        let s = scb(&sys.a, &sys.b, &sys.c, &sys.d).unwrap();
        s.check().unwrap();
        assert_eq!(s.invariant_zero_polynomial().monic(), z.polynomial);
    }
}

crate::for_each_field!(check_all, 2301, 6, 3; every_operation_over_q, every_operation_over_q_sqrt2,
    every_operation_over_q_i, every_operation_over_q_p);
