//! Multivariate polynomials, gcd, resultants, factorization and the field Q(p1..pk):
//! textbook cases, random properties, naive oracles.

use exactlti::field::ElemDisplay;
use exactlti::field::{Field, Rational};
use exactlti::matrix::Matrix;
use exactlti::matrix::params::{charpoly_ratfunc, charpoly_zp, det_bareiss_zp};
use exactlti::mpoly::gcd::{gcd_heuristic, gcd_subresultant};
use exactlti::mpoly::resultant::{discriminant, resultant};
use exactlti::mpoly::{MPoly, factor, gcd, parse_mpoly_in};
use exactlti::ratfunc::{RatFunc, RatFuncField};
use num_bigint::BigInt;
use num_traits::{One, Zero};
use proptest::prelude::*;

const V: [&str; 3] = ["a", "b", "c"];

fn p(s: &str) -> MPoly {
    let f = parse_mpoly_in(s, &V).unwrap();
    f.prim.scale(&f.content.to_integer())
}

fn names() -> Vec<String> {
    V.iter().map(|s| s.to_string()).collect()
}

// ---------------------------------------------------------------- textbook cases

#[test]
fn textbook_gcd() {
    // Geddes–Czapor–Labahn ex. 7.1 style: common factor hidden in larger products
    let f = p("(a^2 + b^2 + c^2 - 1)*(a*b - c)^2*(a + 1)");
    let g = p("(a^2 + b^2 + c^2 - 1)*(a*b - c)*(b - 3)");
    assert_eq!(gcd(&f, &g), p("(a^2 + b^2 + c^2 - 1)*(a*b - c)"));
    assert_eq!(gcd(&p("a^4 - b^4"), &p("a^6 - b^6")), p("a^2 - b^2"));
    assert!(gcd(&p("a^2 + b^2"), &p("a + b")).is_one());
    assert_eq!(gcd(&MPoly::zero(3), &p("-2*a")), p("2*a"));
}

#[test]
fn textbook_resultant_discriminant() {
    let v = ["x", "a", "b", "c", "d"];
    let q = |s: &str| parse_mpoly_in(s, &v).unwrap().to_integer_poly().unwrap();
    assert_eq!(discriminant(&q("a*x^2 + b*x + c"), 0), q("b^2 - 4*a*c"));
    // cubic: b^2 c^2 - 4 a c^3 - 4 b^3 d - 27 a^2 d^2 + 18 a b c d
    assert_eq!(
        discriminant(&q("a*x^3 + b*x^2 + c*x + d"), 0),
        q("b^2*c^2 - 4*a*c^3 - 4*b^3*d - 27*a^2*d^2 + 18*a*b*c*d")
    );
    // Res(x^2 - a, x^2 - b) = (a - b)^2
    assert_eq!(resultant(&q("x^2 - a"), &q("x^2 - b"), 0), q("(a - b)^2"));
}

#[test]
fn textbook_factor() {
    let cases = [
        ("a^2 - b^2", 2),
        ("a^4 + 4*b^4", 2), // Sophie Germain
        ("a^3 + b^3 + c^3 - 3*a*b*c", 2),
        ("(a*b + c^2 + 1)^3*(a - b + 2*c)^2", 2),
        ("a^2 + b^2 + c^2", 1),
        ("(a^2*b + c + 3)*(a*c^2 - b + 1)*(a + b*c)*(a - 1)", 4),
        ("6*a^2*b - 6*b^3", 3),
    ];
    for (s, nf) in cases {
        let f = p(s);
        let fz = factor(&f).unwrap();
        assert_eq!(fz.expand(3), f, "{s}");
        assert_eq!(fz.factors.len(), nf, "{s}: {:?}", fz.factors);
        for (g, _) in &fz.factors {
            assert!(g.lc() > BigInt::zero());
        }
    }
    let fz = factor(&p("a^4 + 4*b^4")).unwrap();
    let shown: Vec<String> = fz
        .factors
        .iter()
        .map(|(g, _)| g.to_string_vars(&names()))
        .collect();
    assert_eq!(shown, ["a^2 - 2*a*b + 2*b^2", "a^2 + 2*a*b + 2*b^2"]);
}

#[test]
fn vehicle_entries_display() {
    // the vehicle-dynamics paper writes its entries in m, u, c_r
    let k = RatFuncField::new(&["cr", "m", "u"]).unwrap();
    let a = k.parse("-cr/(m*u)").unwrap();
    assert_eq!(k.fmt_elem(&a), "-cr/(m*u)");
    assert_eq!(k.latex_elem(&a), "-\\frac{\\mathit{cr}}{m u}");
    let b = k.parse("(m*u^2 - 3*cr)/(m*u)").unwrap();
    assert_eq!(k.fmt_elem(&b), "(m*u^2 - 3*cr)/(m*u)");
    let c = k.parse("(m + u)^2/(m^2 - u^2)").unwrap();
    assert_eq!(k.fmt_elem(&c), "(m + u)/(m - u)");
    assert_eq!(
        k.eval(
            &c,
            &[
                Rational::one(),
                Rational::from_integer(3.into()),
                Rational::one()
            ]
        ),
        Some(Rational::from_integer(2.into()))
    );
}

#[test]
fn rref_over_params_reports_conditions() {
    let k = RatFuncField::new(&["a", "b"]).unwrap();
    let rows = [
        ["a", "b", "1"],
        ["1", "a", "b"],
        ["a + 1", "a + b", "b + 1"],
    ];
    let m = Matrix::from_rows(
        k.clone(),
        rows.iter()
            .map(|r| r.iter().map(|s| k.parse(s).unwrap()).collect())
            .collect(),
    )
    .unwrap();
    // row 3 = row 1 + row 2: rank 2 for generic a, b
    let (r, piv) = m.rref();
    assert_eq!(piv, vec![0, 1]);
    assert_eq!(m.rank(), 2);
    // R is the RREF: it has the same row space (every row of m is a combination)
    let ns = m.nullspace();
    assert_eq!(ns.ncols(), 1);
    let prod = &m * &ns;
    assert!(prod.is_zero());
    assert!(r.get(2, 2).clone() == k.zero());
    let conds = k.conditions_strings().unwrap();
    // pivots: a, then (a^2 - b)/a: conditions a and a^2 - b
    assert_eq!(conds, ["a", "a^2 - b"]);
}

// ---------------------------------------------------------------- random properties

fn poly_strategy(maxdeg: u32, maxterms: usize) -> impl Strategy<Value = MPoly> {
    proptest::collection::vec(
        (0..=maxdeg, 0..=maxdeg, 0..=maxdeg, -9i64..=9),
        1..=maxterms,
    )
    .prop_map(|ts| {
        let t: Vec<(u128, BigInt)> = ts
            .into_iter()
            .map(|(x, y, z, c)| (exactlti::mpoly::pack(3, &[x, y, z]), BigInt::from(c)))
            .collect();
        MPoly::from_terms(3, t)
    })
}

fn sylvester_resultant_oracle(f: &MPoly, g: &MPoly, x: usize) -> MPoly {
    let n = f.nvars();
    let (fc, gc) = (f.to_univariate(x), g.to_univariate(x));
    let (df, dg) = (fc.len() - 1, gc.len() - 1);
    let s = df + dg;
    let mut m = vec![MPoly::zero(n); s * s];
    for i in 0..dg {
        for (j, c) in fc.iter().rev().enumerate() {
            m[i * s + i + j] = c.clone();
        }
    }
    for i in 0..df {
        for (j, c) in gc.iter().rev().enumerate() {
            m[(dg + i) * s + i + j] = c.clone();
        }
    }
    det_bareiss_zp(n, s, &m)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn gcd_of_multiples(f in poly_strategy(2, 4), g in poly_strategy(2, 3), h in poly_strategy(2, 3)) {
        prop_assume!(!f.is_zero() && !g.is_zero() && !h.is_zero());
        let lhs = gcd(&f.mul(&g), &f.mul(&h));
        let rhs = f.mul(&gcd(&g, &h)).abs_lc();
        prop_assert_eq!(&lhs, &rhs);
        // oracle: subresultant path and the heuristic (when it answers) agree
        prop_assert_eq!(gcd_subresultant(&f.mul(&g), &f.mul(&h)), lhs.clone());
        if let Some(hh) = gcd_heuristic(&f.mul(&g), &f.mul(&h)) {
            prop_assert_eq!(hh, lhs);
        }
    }

    #[test]
    fn factor_round_trip(f in poly_strategy(2, 3), g in poly_strategy(2, 3), e in 1u32..3) {
        prop_assume!(!f.is_zero() && !g.is_zero());
        let h = f.pow(e).mul(&g);
        let fz = factor(&h).unwrap();
        prop_assert_eq!(fz.expand(3), h.clone());
        for (q, _) in &fz.factors {
            prop_assert!(h.div_exact(q).is_some());
            prop_assert!(!q.is_constant());
        }
        // every factor of f appears with multiplicity at least e
        for (q, k) in factor(&f).unwrap().factors {
            let m = fz.factors.iter().find(|(r, _)| *r == q).map(|x| x.1).unwrap_or(0);
            prop_assert!(m >= k * e as usize);
        }
    }

    #[test]
    fn resultant_matches_sylvester(f in poly_strategy(2, 4), g in poly_strategy(2, 4)) {
        prop_assume!(f.deg(0) >= 1 && g.deg(0) >= 1);
        prop_assert_eq!(resultant(&f, &g, 0), sylvester_resultant_oracle(&f, &g, 0));
    }

    #[test]
    fn field_axioms(a in poly_strategy(1, 3), b in poly_strategy(1, 3), c in poly_strategy(1, 3), d in poly_strategy(1, 3)) {
        let k = RatFuncField::new(&V).unwrap();
        prop_assume!(!b.is_zero() && !d.is_zero());
        let x = k.frac(a.clone(), b.clone()).unwrap();
        let y = k.frac(c.clone(), d.clone()).unwrap();
        let z = k.frac(b.add(&c), d.add(&MPoly::one(3))).unwrap_or_else(|| k.one());
        prop_assert_eq!(k.add(&k.add(&x, &y), &z), k.add(&x, &k.add(&y, &z)));
        prop_assert_eq!(k.mul(&x, &k.add(&y, &z)), k.add(&k.mul(&x, &y), &k.mul(&x, &z)));
        prop_assert_eq!(k.mul(&k.mul(&x, &y), &z), k.mul(&x, &k.mul(&y, &z)));
        prop_assert!(k.is_zero(&k.sub(&x, &x)));
        if !k.is_zero(&x) {
            prop_assert!(k.is_one(&k.mul(&x, &k.inv(&x).unwrap())));
        }
        // canonical form: cross-multiplication equality is structural equality
        let x2 = k.frac(a.mul(&c.add(&MPoly::one(3))), b.mul(&c.add(&MPoly::one(3))));
        if let Some(x2) = x2 { prop_assert_eq!(x2, x.clone()); }
        // display parses back to the same element
        let back: RatFunc = k.parse(&k.fmt_elem(&x)).unwrap();
        prop_assert_eq!(back, x);
    }

    #[test]
    fn fraction_free_rref_matches_gauss_jordan(es in proptest::collection::vec((-2i64..=2, -1i64..=1, -1i64..=1, 0i64..=2), 12)) {
        let k = RatFuncField::new(&["a", "b"]).unwrap();
        let entries: Vec<RatFunc> = es.iter().map(|(c, x, y, d)| {
            k.parse(&format!("({c} + {x}*a + {y}*b)/(a + {d})")).unwrap()
        }).collect();
        // rank-deficient half the time: row 2 = row 0 + row 1
        let mut rows: Vec<Vec<RatFunc>> = entries.chunks(4).map(|r| r.to_vec()).collect();
        if es[0].3 == 0 {
            rows[2] = (0..4).map(|j| k.add(&rows[0][j], &rows[1][j])).collect();
        }
        let m = Matrix::from_rows(k.clone(), rows).unwrap();
        let (r1, p1) = exactlti::matrix::params::rref_params(&m);
        let (r2, p2) = m.rref_gauss_jordan();
        prop_assert_eq!(p1, p2);
        prop_assert_eq!(r1, r2);
    }

    #[test]
    fn charpoly_interpolation_matches_berkowitz(es in proptest::collection::vec((-3i64..=3, -2i64..=2, -2i64..=2), 9)) {
        let k = RatFuncField::new(&["a", "b"]).unwrap();
        let entries: Vec<RatFunc> = es.iter().map(|(c, x, y)| {
            let t = format!("{c} + {x}*a + {y}*b");
            k.parse(&t).unwrap()
        }).collect();
        let m = Matrix::from_vec(k.clone(), 3, 3, entries.clone());
        let fast = charpoly_ratfunc(&m).unwrap();
        prop_assert_eq!(fast.clone(), m.charpoly_berkowitz().unwrap());
        let nums: Vec<MPoly> = entries.iter().map(|e| e.num().clone()).collect();
        let cz = charpoly_zp(2, 3, &nums).unwrap();
        prop_assert_eq!(k.from_mpoly(cz[0].clone()), fast.coeff(0));
    }
}
