//! Brown's modular multivariate gcd (`mpoly::brown`): textbook and adversarial cases (unlucky
//! evaluation points, unlucky primes, large coefficients), random properties
//! (gcd(f g, f h) = f gcd(g, h) up to units, cofactors exact), and the subresultant PRS as
//! the naive oracle.

use exactlti::mpoly::brown::gcd_brown;
use exactlti::mpoly::gcd::gcd_subresultant;
use exactlti::mpoly::{MPoly, gcd, parse_mpoly_in};
use num_bigint::BigInt;
use proptest::prelude::*;

const V: [&str; 4] = ["x", "a", "b", "c"];

fn p(s: &str) -> MPoly {
    let f = parse_mpoly_in(s, &V).unwrap();
    f.prim.scale(&f.content.to_integer())
}

/// `gcd_brown` of the primitive parts, checked against the oracle and by exact cofactors.
fn check(f: &MPoly, g: &MPoly, want: &MPoly) {
    let h = gcd_brown(&f.primitive_part(), &g.primitive_part()).expect("Brown answers");
    assert_eq!(&h, &want.primitive_part().abs_lc());
    let (cf, cg) = (f.div_exact(&h).unwrap(), g.div_exact(&h).unwrap());
    assert_eq!(cf.mul(&h), *f);
    assert_eq!(cg.mul(&h), *g);
    assert_eq!(
        gcd_subresultant(&f.primitive_part(), &g.primitive_part()),
        h
    );
}

#[test]
fn textbook_cases() {
    // Geddes–Czapor–Labahn ch. 7 style: a common factor hidden in larger products
    let f = p("a*b + c^2 + 1");
    check(
        &f.pow(3).mul(&p("a - b + 2*c").pow(2)),
        &f.pow(2).mul(&p("a + b + c").pow(3)),
        &f.pow(2),
    );
    // coprime inputs
    check(&p("x^2 + a*b - 1"), &p("x*a + c^3 + 2"), &MPoly::one(4));
    // gcd free of the main variable (content in x)
    check(&p("(a + b)*(x^2 + 1)"), &p("(a + b)*(x + c)"), &p("a + b"));
    // gcd in the last variable only
    check(
        &p("(c^2 + 3)*(x - a)"),
        &p("(c^2 + 3)*(x + b)"),
        &p("c^2 + 3"),
    );
}

#[test]
fn unlucky_evaluation_point() {
    // at b = 2 (the first point tried) both become (x + 2)^2 times something: the image
    // gcd is too large there and must be discarded
    let f = p("(x + b)*(x + 2)*(a + 1)");
    let g = p("(x + b)^2*(a - 1)");
    check(&f, &g, &p("x + b"));
    let f = p("(x + b*c)*(x + 2*c)");
    let g = p("(x + b*c)*(x + b^2*c - 2*c)");
    check(&f, &g, &p("x + b*c"));
}

#[test]
fn unlucky_primes_and_large_coefficients() {
    // leading coefficients divisible by the first primes below 2^31 and coefficients of
    // ~200 bits: several primes, some skipped
    let big = BigInt::parse_bytes(
        b"1606938044258990275541962092341162602522202993782792835301376",
        10,
    )
    .unwrap();
    let q = BigInt::from(2147483647i64) * BigInt::from(2147483629i64);
    let h = p("x^3*a + b*c - 5")
        .scale(&BigInt::from(1))
        .add(&MPoly::constant(4, big.clone()));
    let u = p("x*b + 1")
        .scale(&q)
        .add(&MPoly::constant(4, BigInt::from(7)));
    let w = p("x^2 - c").scale(&q).add(&p("a"));
    check(&h.mul(&u), &h.mul(&w), &h);
    check(&h.pow(2).mul(&u), &h.mul(&w).mul(&u), &h.mul(&u));
}

#[test]
fn staged_gcd_keeps_integer_content() {
    let f = p("x*a + b");
    assert_eq!(
        gcd(
            &f.scale(&BigInt::from(12)),
            &f.mul(&p("x - c")).scale(&BigInt::from(-18))
        ),
        f.scale(&BigInt::from(6))
    );
}

fn poly4(maxdeg: u32, maxterms: usize) -> impl Strategy<Value = MPoly> {
    proptest::collection::vec(
        (0..=maxdeg, 0..=maxdeg, 0..=maxdeg, 0..=maxdeg, -20i64..=20),
        1..=maxterms,
    )
    .prop_map(|ts| {
        let t: Vec<(u128, BigInt)> = ts
            .into_iter()
            .map(|(x, y, z, w, c)| (exactlti::mpoly::pack(4, &[x, y, z, w]), BigInt::from(c)))
            .collect();
        MPoly::from_terms(4, t)
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(40))]

    /// gcd(f g, f h) = f gcd(g, h) up to units; Brown agrees with the subresultant oracle
    /// and its cofactors are exact.
    #[test]
    fn gcd_of_multiples(f in poly4(2, 4), g in poly4(2, 3), h in poly4(2, 3)) {
        prop_assume!(!f.is_zero() && !g.is_zero() && !h.is_zero());
        let (fg, fh) = (f.mul(&g), f.mul(&h));
        let lhs = gcd(&fg, &fh);
        prop_assert_eq!(&lhs, &f.mul(&gcd(&g, &h)).abs_lc());
        prop_assert!(fg.div_exact(&lhs).is_some() && fh.div_exact(&lhs).is_some());
        let (pfg, pfh) = (fg.primitive_part(), fh.primitive_part());
        if !pfg.is_constant() && !pfh.is_constant() {
            let b = gcd_brown(&pfg, &pfh);
            prop_assert!(b.is_some());
            let b = b.unwrap();
            prop_assert_eq!(&b, &gcd_subresultant(&pfg, &pfh));
            prop_assert_eq!(pfg.div_exact(&b).unwrap().mul(&b), pfg);
        }
    }
}

#[test]
fn gcd_with_a_monomial_factor_in_both() {
    // regression (proptest seed): f = x (x a b + c^2), g = x - c^2, h = x; the heuristic's
    // cofactor route once returned a proper divisor of the content (a c^2 for a b c^2)
    let f = p("x^2*a*b + x*c^2");
    let (g, h) = (p("x - c^2"), p("x"));
    let (fg, fh) = (f.mul(&g), f.mul(&h));
    assert_eq!(gcd(&fg, &fh), f);
    check(&fg, &fh, &f);
    let r = p("x^2*a^2*b^2*c^2 + x*a*b*c^4");
    assert_eq!(exactlti::mpoly::gcd::content_in(&r, 0), p("a*b*c^2"));
    let (m1, m2) = (p("a*b*c^4"), p("a^2*b^2*c^2"));
    assert_eq!(gcd(&m1, &m2), p("a*b*c^2"));
    assert_eq!(gcd(&m2, &m1), p("a*b*c^2"));
    assert_eq!(gcd(&p("961*a*b"), &p("a^2*b^2")), p("a*b"));
}

#[test]
fn cofactor_route_and_variable_order() {
    // gcd with ~100-bit coefficients, small cofactors: the cofactor image lifts from one
    // prime and the gcd follows by exact division
    let big = BigInt::parse_bytes(b"1267650600228229401496703205653", 10).unwrap();
    let h = p("x^3*a + b*c^2 - 5*x").scale(&big).add(&p("a^2*c - 7"));
    check(&h.mul(&p("x - 2*b + 1")), &h.mul(&p("x^2 + a*x - 3")), &h);
    // the largest degree in the last variable (the dense order puts it first)
    let h = p("c^9 + a*c^4 - b + x");
    check(&h.mul(&p("c^3 - a")), &h.mul(&p("c^2 + x*b")), &h);
    // one input divides the other
    let h = p("(x + a*b)^2*(c - 1)");
    check(&h.mul(&p("x*c + 2")), &h, &h);
}
