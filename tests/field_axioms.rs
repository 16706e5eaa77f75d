//! Field axioms as properties over a cubic number field Q(cbrt 2) and ComplexField over it,
//! the invariants (`is_valid`), the optional approximation, and exact field equality.

use exactlti::algebraic::NumberField;
use exactlti::field::{ComplexField, ComplexPair, Field, Rational};
use exactlti::poly::Poly;
use proptest::prelude::*;

/// Q(cbrt 2) with a root approximation at f64 precision (the approximation of elements is
/// only as good as the stored root).
fn cubic() -> NumberField {
    NumberField::new(&Poly::from_i64s(&[-2, 0, 0, 1]), (2f64.cbrt(), 0.0)).unwrap()
}

fn q(n: i64, d: i64) -> Rational {
    Rational::new(n.into(), d.into())
}

fn nf_elem(k: &NumberField, c: &[(i64, i64)]) -> <NumberField as Field>::Elem {
    k.from_coeffs(c.iter().map(|&(n, d)| q(n, d)).collect())
}

fn coeffs() -> impl Strategy<Value = Vec<(i64, i64)>> {
    prop::collection::vec((-9i64..=9, 1i64..=5), 0..=4)
}

/// The axioms for one triple; `valid` checks the representation invariant of results.
fn axioms<K: Field>(
    k: &K,
    a: &K::Elem,
    b: &K::Elem,
    c: &K::Elem,
    valid: impl Fn(&K::Elem) -> bool,
) {
    let (z, o) = (k.zero(), k.one());
    assert_eq!(k.add(a, b), k.add(b, a));
    assert_eq!(k.mul(a, b), k.mul(b, a));
    assert_eq!(k.add(&k.add(a, b), c), k.add(a, &k.add(b, c)));
    assert_eq!(k.mul(&k.mul(a, b), c), k.mul(a, &k.mul(b, c)));
    assert_eq!(k.mul(a, &k.add(b, c)), k.add(&k.mul(a, b), &k.mul(a, c)));
    assert_eq!(k.add(a, &z), *a);
    assert_eq!(k.mul(a, &o), *a);
    assert!(k.is_zero(&k.add(a, &k.neg(a))));
    assert_eq!(k.sub(a, b), k.add(a, &k.neg(b)));
    for x in [k.add(a, b), k.mul(a, b), k.sub(a, c), k.neg(a)] {
        assert!(valid(&x), "non-canonical result {x:?}");
    }
    match k.inv(a) {
        None => assert!(k.is_zero(a)),
        Some(ai) => {
            assert!(!k.is_zero(a));
            assert!(valid(&ai));
            assert!(k.is_one(&k.mul(a, &ai)));
            assert_eq!(k.div(b, a), Some(k.mul(b, &ai)));
        }
    }
    // the approximation is a ring homomorphism up to round-off
    let (ar, ai) = k.approx(a).expect("embedded field");
    let (br, bi) = k.approx(b).expect("embedded field");
    let (pr, pi) = k.approx(&k.mul(a, b)).expect("embedded field");
    let scale = 1.0 + ar.hypot(ai) * br.hypot(bi);
    assert!((pr - (ar * br - ai * bi)).abs() <= 1e-9 * scale);
    assert!((pi - (ar * bi + ai * br)).abs() <= 1e-9 * scale);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn cubic_number_field_axioms(a in coeffs(), b in coeffs(), c in coeffs()) {
        let k = cubic();
        prop_assert!(k.is_valid());
        let (a, b, c) = (nf_elem(&k, &a), nf_elem(&k, &b), nf_elem(&k, &c));
        axioms(&k, &a, &b, &c, |x| k.is_valid_elem(x));
        // t^3 = 2 in the field
        let t = k.generator();
        prop_assert_eq!(k.mul(&k.mul(&t, &t), &t), k.from_i64(2));
    }

    #[test]
    fn complex_over_cubic_axioms(
        a in coeffs(), b in coeffs(), c in coeffs(), d in coeffs(), e in coeffs(), f in coeffs()
    ) {
        let base = cubic();
        let k = ComplexField::new(base.clone());
        let pair = |x: &[(i64, i64)], y: &[(i64, i64)]| ComplexPair {
            re: nf_elem(&base, x),
            im: nf_elem(&base, y),
        };
        let (x, y, z) = (pair(&a, &b), pair(&c, &d), pair(&e, &f));
        axioms(&k, &x, &y, &z, |w| base.is_valid_elem(&w.re) && base.is_valid_elem(&w.im));
        // i^2 = -1
        prop_assert_eq!(k.mul(&k.i(), &k.i()), k.from_i64(-1));
    }
}

/// Equality of number fields is exact: the same marked root through different
/// approximations is the same field; a conjugate root is a different field.
#[test]
fn number_field_equality_is_exact() {
    let m = Poly::from_i64s(&[-2, 0, 0, 1]);
    let a = NumberField::new(&m, (1.2599, 0.0)).unwrap();
    let b = NumberField::new(&m, (1.26, 0.001)).unwrap();
    assert_eq!(a, b);
    // the complex roots of x^3 - 2: -0.63 +- 1.09 i
    let c = NumberField::new(&m, (-0.63, 1.09)).unwrap();
    let cbar = NumberField::new(&m, (-0.63, -1.09)).unwrap();
    assert_ne!(a, c);
    assert_ne!(c, cbar);
    assert_eq!(c, NumberField::new(&m, (-0.6, 1.1)).unwrap());
    // a different modulus is a different field, even with a close root
    let d = NumberField::new(&Poly::from_i64s(&[-3, 0, 0, 1]), (1.2599, 0.0)).unwrap();
    assert_ne!(a, d);
    assert_eq!(a.marked_root_index(), b.marked_root_index());
    assert_ne!(a.marked_root_index(), c.marked_root_index());
}
