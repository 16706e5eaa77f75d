//! `Field::elem_value` (src/field/value.rs): every element's value names the element. For
//! random elements (fixed seed) of Q, Q(sqrt 2), Q(i), a cubic number field and Q(a, b), the
//! element rebuilt from its value in its field equals the element.

use exactlti::algebraic::NumberField;
use exactlti::field::{ElemValue, Field, Q, QuadraticField, Rational};
use exactlti::mpoly::{MPoly, pack};
use exactlti::poly::Poly;
use exactlti::ratfunc::RatFuncField;
use exactlti::rng::SplitMix64;

fn rat(g: &mut SplitMix64) -> Rational {
    Rational::new(g.int(-9, 9).into(), g.int(1, 5).into())
}

fn rational(v: &ElemValue) -> Rational {
    match v {
        ElemValue::Rational(r) => r.clone(),
        other => panic!("not rational: {other:?}"),
    }
}

#[test]
fn rationals_and_quadratic_elements_are_their_parts() {
    let mut g = SplitMix64(23);
    for d in [2i64, -1, 5] {
        let k = QuadraticField::new(d).unwrap();
        for _ in 0..50 {
            let x = k.add(
                &k.from_rational(&rat(&mut g)),
                &k.mul(&k.from_rational(&rat(&mut g)), &k.gen_elem()),
            );
            let Some(ElemValue::Quadratic { a, b, d: dd }) = k.elem_value(&x) else {
                panic!("a quadratic value")
            };
            assert_eq!(dd, d.into());
            let back = k.add(
                &k.from_rational(&a),
                &k.mul(&k.from_rational(&b), &k.gen_elem()),
            );
            assert_eq!(back, x);
        }
    }
    let q = rat(&mut g);
    assert_eq!(Q.elem_value(&q), Some(ElemValue::Rational(q)));
}

#[test]
fn number_field_elements_are_polynomials_in_the_marked_root() {
    let m = Poly::new(
        Q,
        [-2, 0, 0, 1]
            .iter()
            .map(|&c| Rational::from_integer(c.into()))
            .collect(),
    );
    let k = NumberField::new(&m, (1.26, 0.0)).unwrap();
    let mut g = SplitMix64(7);
    for _ in 0..50 {
        let x = k.from_coeffs((0..3).map(|_| rat(&mut g)).collect());
        let Some(ElemValue::Ext { coeffs, generator }) = k.elem_value(&x) else {
            panic!("an extension value")
        };
        let back = k.from_coeffs(coeffs.iter().map(rational).collect());
        assert_eq!(back, x);
        let modulus: Vec<Rational> = generator.modulus.iter().map(rational).collect();
        assert_eq!(modulus, m.coeffs());
        assert_eq!(generator.root, (1.26, 0.0));
    }
}

#[test]
fn rational_functions_are_their_terms() {
    let k = RatFuncField::new(&["a", "b"]).unwrap();
    let mut g = SplitMix64(11);
    let rebuild = |t: &[(Vec<u32>, num_bigint::BigInt)]| {
        MPoly::from_terms(2, t.iter().map(|(e, c)| (pack(2, e), c.clone())).collect())
    };
    for _ in 0..40 {
        let mut x = k.zero();
        for _ in 0..3 {
            let mono = k.mul(
                &k.from_rational(&rat(&mut g)),
                &k.mul(&k.var(0), &k.var(g.int(0, 1) as usize)),
            );
            x = k.add(&x, &mono);
        }
        let den = k.add(&k.var(1), &k.from_rational(&rat(&mut g)));
        let x = k.div(&x, &den).unwrap_or(x);
        let Some(ElemValue::RatFunc { vars, num, den }) = k.elem_value(&x) else {
            panic!("a rational-function value")
        };
        assert_eq!(vars, ["a", "b"]);
        assert_eq!(k.frac(rebuild(&num), rebuild(&den)), Some(x));
    }
}
