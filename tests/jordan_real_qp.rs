//! The real form of a quadratic factor's pair (`jordan::real_quadratic`), one generic test over
//! Q and Q(p): A T = T J_real exactly in F(w), w^2 = c - b^2/4, the pair complex where
//! b^2 - 4c < 0, T of full rank; `jordan --real` over Q(p) (real_form_qp) and its refusal of
//! factors of degree >= 3.

use crate::common::{Rng, unimodular};
use exactlti::field::{Field, Q};
use exactlti::jordan::over_qp::real_form_qp;
use exactlti::jordan::primary::Component;
use exactlti::jordan::real_quadratic::quadratic_real;
use exactlti::matrix::Matrix;
use exactlti::ratfunc::RatFuncField;

/// A = U diag(blocks(C, s), C, theta) U^-1 with C the companion matrix of x^2 + b x + c:
/// one Jordan block of size `s` of the pair, one of size 1, and an eigenvalue `theta`.
fn planted<F: Field>(
    k: &F,
    b: &F::Elem,
    c: &F::Elem,
    theta: &F::Elem,
    s: usize,
    rng: &mut Rng,
) -> Matrix<F> {
    let n = 2 * s + 3;
    let mut j = Matrix::zeros(k.clone(), n, n);
    for blk in 0..=s {
        let off = 2 * blk;
        j.set(off, off + 1, k.neg(c));
        j.set(off + 1, off, k.one());
        j.set(off + 1, off + 1, k.neg(b));
        if blk + 1 < s {
            j.set(off, off + 2, k.one());
            j.set(off + 1, off + 3, k.one());
        }
    }
    j.set(n - 1, n - 1, theta.clone());
    let u = unimodular(k, n, rng);
    u.try_mul(&j)
        .unwrap()
        .try_mul(&u.inverse().unwrap())
        .unwrap()
}

/// Every identity of the real form of each quadratic component, recomputed here.
fn check<F: Field>(a: &Matrix<F>, comps: &[Component<F>]) -> usize {
    let k = a.field();
    let mut pairs = 0;
    for comp in comps {
        let Some(r) = quadratic_real(a, comp, "w") else {
            assert_ne!(comp.degree(), 2);
            continue;
        };
        pairs += 1;
        assert!(r.verified);
        let g = comp.factor.monic();
        let (b, c) = (g.coeff(1), g.coeff(0));
        assert_eq!(
            r.discriminant,
            k.sub(&k.mul(&b, &b), &k.mul(&k.from_i64(4), &c))
        );
        assert_eq!(k.mul(&r.re, &k.from_i64(-2)), b);
        assert_eq!(k.mul(&r.im_squared, &k.from_i64(-4)), r.discriminant);
        let f = &r.field;
        let w = f.generator();
        assert_eq!(f.mul(&w, &w), f.from_base(&r.im_squared));
        let ar = a.map(f, |x| f.from_base(x));
        assert_eq!(ar.try_mul(&r.t).unwrap(), r.t.try_mul(&r.j).unwrap());
        // T has full column rank 2 m (w^2 - omega^2 irreducible here: R is a field)
        assert_eq!(r.t.rank(), 2 * comp.multiplicity);
        // J_real: [[re, w], [-w, re]] on the diagonal
        assert_eq!(r.j.get(0, 0), &f.from_base(&r.re));
        assert_eq!(r.j.get(0, 1), &w);
        assert_eq!(r.j.get(1, 0), &f.neg(&w));
    }
    pairs
}

#[test]
fn quadratic_pairs_over_q_and_qp() {
    let mut rng = Rng(2325);
    for s in 1..=2 {
        // over Q: x^2 + 2x + 5 (discriminant -16 < 0)
        let a = planted(
            &Q,
            &Q.from_i64(2),
            &Q.from_i64(5),
            &Q.from_i64(-3),
            s,
            &mut rng,
        );
        let jf = exactlti::jordan::jordan(&a).unwrap();
        assert_eq!(check(&a, &jf.components), 1);
        // over Q(a): x^2 + a x + 1 (discriminant a^2 - 4: complex where |a| < 2)
        let k = RatFuncField::new(&["a"]).unwrap();
        let aa = planted(
            &k,
            &k.var(0),
            &k.one(),
            &k.parse("a+1").unwrap(),
            s,
            &mut rng,
        );
        let rf = real_form_qp(&aa).unwrap();
        assert!(rf.verified);
        assert_eq!(check(&rf.a, &rf.components), 1);
        let pair = rf.pairs.iter().flatten().next().unwrap();
        assert_eq!(pair.discriminant, k.parse("a^2-4").unwrap());
        assert_eq!(pair.im_squared, k.parse("1-a^2/4").unwrap());
        // the blocks of the pair: s and 1
        let comp = rf.components.iter().find(|c| c.degree() == 2).unwrap();
        let mut want = vec![s, 1];
        want.sort_unstable_by(|x, y| y.cmp(x));
        assert_eq!(comp.blocks, want);
    }
}

#[test]
fn real_form_over_qp_refuses_a_cubic_factor_with_the_reason() {
    let k = RatFuncField::new(&["a"]).unwrap();
    // companion of x^3 - a: irreducible over Q(a)
    let z = k.zero();
    let a = Matrix::from_rows(
        k.clone(),
        vec![
            vec![z.clone(), z.clone(), k.var(0)],
            vec![k.one(), z.clone(), z.clone()],
            vec![z.clone(), k.one(), z.clone()],
        ],
    )
    .unwrap();
    let err = real_form_qp(&a).unwrap_err().to_string();
    assert!(err.contains("degree 3"), "{err}");
}
