//! The eigenvalue list of a Jordan form as values, one generic test over Q, Q(sqrt 2), Q(i)
//! and Q(p) (issue 23 item 2): `JordanField::jordan_form` on planted matrices
//! `A = P J P^-1` (linear blocks `c + s g`, `g` the field's generator or the parameter, and
//! on some seeds a coupled pair of companion blocks of `x^2 + 3 + g`, irreducible over each
//! field). Asserted from `JordanForm::eigenvalues` alone (not the components' flags):
//! * the multiplicities sum to `n` (`count`: `mu`, or `d mu` for the roots of a factor);
//! * geometric multiplicity = number of blocks, algebraic = their sum;
//! * every eigenvalue's blocks match the ranks of its powers: for a root `theta` in the field
//!   or in the component field `E = F[t]/(g)`, `rank (A - theta I)^k = n - sum_b min(b, k)`;
//!   for the roots of a factor `g` of degree `d` over Q(p) (a primary block), exactly in
//!   Q(p): `rank g(A)^k = n - d sum_b min(b, k)`;
//! * a factor's minimal polynomial over the field divides `chi_A` to its multiplicity;
//! * the planted eigenvalues and their block sizes are found;
//! * the typed answers about the real embedding: exact over the number fields, a constant
//!   element of Q(p) has a decided sign, a non-constant one and a pair over Q(p) are
//!   `NotInSymbols`.

use crate::common::Rng;
use exactlti::field::{ElemDisplay, Field};
use exactlti::jordan::{Decided, EigenValue, JordanField};
use exactlti::matrix::Matrix;
use exactlti::poly::Poly;

/// `n - sum_b min(b, k)` for `k = 1..=max block + 1`, times `d` roots.
fn want_ranks(n: usize, d: usize, blocks: &[usize]) -> Vec<usize> {
    let top = blocks.iter().copied().max().unwrap_or(0) + 1;
    (1..=top)
        .map(|k| n - d * blocks.iter().map(|&b| b.min(k)).sum::<usize>())
        .collect()
}

/// The ranks of `m^k`, `k = 1..=len`.
fn ranks<K: Field>(m: &Matrix<K>, len: usize) -> Vec<usize> {
    let mut p = m.clone();
    let mut out = vec![p.rank()];
    for _ in 1..len {
        p = &p * m;
        out.push(p.rank());
    }
    out
}

/// Every assertion of the module docs for one planted matrix.
fn check<F: JordanField>(a: &Matrix<F>, planted: &[(F::Elem, usize)], pair: bool) {
    let n = a.nrows();
    let jf = F::jordan_form(a).unwrap();
    let k = jf.base().clone();
    assert!(jf.verified, "not verified");
    let total: usize = jf.eigenvalues.iter().map(|e| e.count()).sum();
    assert_eq!(total, n, "multiplicities sum to n");
    let a = &jf.a;
    for e in &jf.eigenvalues {
        assert_eq!(e.geometric_multiplicity, e.blocks.len());
        assert_eq!(e.blocks.iter().sum::<usize>(), e.algebraic_multiplicity);
        assert!(e.blocks.windows(2).all(|w| w[0] >= w[1]), "largest first");
        let c = &jf.components[e.component];
        let want = want_ranks(n, 1, &e.blocks);
        match e.value() {
            EigenValue::RootOf(g) => {
                // exactly in Q(p): the primary block of the factor g (its roots' minimal
                // polynomial over the field) through rank g(A)^k
                let d = g.deg();
                assert!(d >= 2);
                let ga = a.eval_poly(g).unwrap();
                assert_eq!(ranks(&ga, want.len()), want_ranks(n, d, &e.blocks));
                divides_chi(&jf.charpoly, g, e.algebraic_multiplicity);
                assert_eq!(e.is_real(), Decided::NotInSymbols);
                assert_eq!(e.re_sign(&k).unwrap(), Decided::NotInSymbols);
            }
            EigenValue::InField(x) => {
                let shifted = a.try_sub(&Matrix::identity(k.clone(), n).scale(x)).unwrap();
                assert_eq!(ranks(&shifted, want.len()), want);
                let lin = Poly::new(k.clone(), vec![k.neg(x), k.one()]);
                divides_chi(&jf.charpoly, &lin, e.algebraic_multiplicity);
                assert_eq!(e.is_real(), Decided::Exactly(true));
                let sign = e.re_sign(&k).unwrap();
                match k.to_rational(x) {
                    Some(q) => assert_eq!(
                        sign,
                        Decided::Exactly(q.cmp(&exactlti::field::Rational::from_integer(0.into())))
                    ),
                    None => assert_eq!(sign, Decided::NotInSymbols),
                }
            }
            EigenValue::Number(z) => {
                // the root theta = t of E = F[t]/(g), the component field marked at it
                let ef = &c.field;
                let shifted = c
                    .lift(a)
                    .try_sub(&Matrix::identity(ef.clone(), n).scale(&ef.generator()))
                    .unwrap();
                assert_eq!(ranks(&shifted, want.len()), want);
                divides_chi(&jf.charpoly, &c.factor, e.algebraic_multiplicity);
                assert!(z.minpoly.deg() >= c.degree());
                assert_eq!(e.is_real(), Decided::Exactly(z.number.is_real()));
                assert!(matches!(e.re_sign(&k).unwrap(), Decided::Exactly(_)));
            }
        }
    }
    // the planted eigenvalues with their block sizes
    for (lam, want) in &crate::jcommon::sizes_by_eigenvalue(planted) {
        let found = jf.eigenvalues.iter().find(|e| match e.value() {
            EigenValue::InField(x) => x == lam,
            _ => {
                let c = &jf.components[e.component];
                c.degree() == 1 && k.neg(&c.factor.coeff(0)) == *lam
            }
        });
        let e = found.unwrap_or_else(|| panic!("no eigenvalue {}", k.fmt_elem(lam)));
        assert_eq!(&e.blocks, want, "blocks of {}", k.fmt_elem(lam));
    }
    // the planted pair: the roots of a quadratic factor with one block of size 2 each
    if pair {
        assert!(
            jf.eigenvalues
                .iter()
                .any(|e| jf.components[e.component].degree() == 2 && e.blocks == [2]),
            "the pair of x^2 + 3 + g"
        );
    }
}

/// `g^mu` divides `chi`.
fn divides_chi<F: Field>(chi: &Poly<F>, g: &Poly<F>, mu: usize) {
    let mut q = chi.clone();
    for _ in 0..mu {
        q = q
            .div_exact(g)
            .expect("the minimal polynomial divides chi_A");
    }
}

fn run<F: JordanField>(k: &F, g: &Option<F::Elem>, seed: u64, iters: usize) {
    let mut rng = Rng(seed);
    for _ in 0..iters {
        let (a, blocks, pair) = crate::jcommon::planted_jordan(k, g, &mut rng, (1, 4), true);
        check(&a, &blocks, pair);
    }
}

crate::for_each_field!(run, 2300, 6, 4; over_q, over_qsqrt2, over_qi, over_qp);

/// A constant eigenvalue in Q(p) has a decided sign; a pair over Q(p) whose realness depends
/// on the parameter is not decided in symbols (never a guess from sample points).
#[test]
fn signs_over_qp_are_typed() {
    let k = exactlti::ratfunc::RatFuncField::new(&["p"]).unwrap();
    let e = |s: &str| k.parse(s).unwrap();
    // diag(-1, p) and the companion matrix of x^2 + p (complex for p > 0, real for p < 0)
    let mut a = Matrix::zeros(k.clone(), 4, 4);
    a.set(0, 0, e("-1"));
    a.set(1, 1, e("p"));
    a.set(2, 3, e("1"));
    a.set(3, 2, e("-p"));
    let jf = exactlti::jordan::jordan_qp(&a).unwrap();
    assert!(jf.verified);
    let kk = jf.base().clone();
    let mut seen = 0;
    for ev in &jf.eigenvalues {
        match ev.value() {
            EigenValue::InField(x) if kk.to_rational(x).is_some() => {
                assert_eq!(kk.fmt_elem(x), "-1");
                assert_eq!(
                    ev.re_sign(&kk).unwrap(),
                    Decided::Exactly(std::cmp::Ordering::Less)
                );
                seen += 1;
            }
            EigenValue::InField(_) => {
                assert_eq!(ev.re_sign(&kk).unwrap(), Decided::NotInSymbols);
                seen += 10;
            }
            EigenValue::RootOf(g) => {
                assert_eq!(g.deg(), 2);
                assert_eq!(ev.is_real(), Decided::NotInSymbols);
                assert_eq!(ev.count(), 2);
                seen += 100;
            }
            EigenValue::Number(_) => panic!("no certified numbers over Q(p)"),
        }
    }
    assert_eq!(seen, 111);
}
