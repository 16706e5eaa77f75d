//! One generic test of the Jordan decomposition (issue 23 item 2): the same planted inputs,
//! built by one generic generator, decomposed by the one code path `jordan_over` over
//! Q, Q(sqrt 2) and Q(i). Asserted: the exact identities A V = V J_t, W A = J_t W, W V = I
//! in each component field (recomputed here, not only the flag), the dimensions, the
//! planted block sizes of every planted eigenvalue, the eigenvalues as roots of the
//! characteristic polynomial, and the free response identities.

use crate::common::{self, Rng};
use exactlti::jordan::{EigenField, jordan_over};
use exactlti::matrix::Matrix;

/// Every assertion of the module docs for one matrix.
fn check<F: EigenField>(a: &Matrix<F>, planted: &[(F::Elem, usize)]) {
    let k = a.field();
    let n = a.nrows();
    let jf = jordan_over(a).unwrap();
    assert!(jf.verified, "not verified");
    let dim: usize = jf
        .components
        .iter()
        .map(|c| c.degree() * c.multiplicity)
        .sum();
    assert_eq!(dim, n);
    assert_eq!(
        jf.eigenvalues.len(),
        jf.components.iter().map(|c| c.degree()).sum::<usize>()
    );
    for c in &jf.components {
        assert!(c.verify(a));
        let (v, w, jt) = (&c.chains, &c.left_chains, c.jordan_matrix());
        let ae = c.lift(a);
        assert_eq!(&ae * v, v * &jt, "A V = V J over {}", c.field);
        assert_eq!(w * &ae, &jt * w, "W A = J W over {}", c.field);
        assert!((w * v).is_identity(), "W V = I over {}", c.field);
        assert_eq!(c.blocks.iter().sum::<usize>(), c.multiplicity);
        // the factor divides the characteristic polynomial to its multiplicity
        let mut q = jf.charpoly.clone();
        for _ in 0..c.multiplicity {
            q = q.div_exact(&c.factor).expect("the factor divides chi");
        }
    }
    // planted blocks: for each planted eigenvalue, its linear component has those sizes
    for (lam, want) in &crate::jcommon::sizes_by_eigenvalue(planted) {
        let c = jf
            .components
            .iter()
            .find(|c| c.degree() == 1 && k.neg(&c.factor.coeff(0)) == *lam)
            .unwrap_or_else(|| panic!("no component for {}", k.fmt_elem(lam)));
        assert_eq!(&c.blocks, want, "blocks of {}", k.fmt_elem(lam));
    }
    // the eigenvalues' certified numbers are roots of their minimal polynomials, which
    // divide the norm of chi: checked through the factor of each component
    for e in &jf.eigenvalues {
        let c = &jf.components[e.component];
        assert_eq!(e.algebraic_multiplicity, c.multiplicity);
        assert_eq!(e.blocks, c.blocks);
        assert!(e.minpoly.deg() >= c.degree());
    }
    let fr = jf.free_response();
    assert!(fr.verify(&jf), "free response");
}

fn run<F: EigenField>(k: &F, g: &Option<F::Elem>, seed: u64) {
    let mut rng = Rng(seed);
    for _ in 0..common::iters(6) {
        let (a, blocks, _) = crate::jcommon::planted_jordan(k, g, &mut rng, (2, 5), false);
        check(&a, &blocks);
    }
}

#[test]
fn jordan_over_q_qsqrt2_qi_from_one_generic_test() {
    run(&common::q(), &None, 23);
    let (k, g) = common::qsqrt2();
    run(&k, &g, 24);
    let (k, g) = common::qi();
    run(&k, &g, 25);
}
