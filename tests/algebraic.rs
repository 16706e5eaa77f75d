//! Algebraic numbers, root isolation, factorization over Q and over number fields.
//!
//! Independent oracles live here: a Sturm-sequence root counter for real intervals and an
//! exact argument-principle (winding number) counter for boxes, both in rational arithmetic
//! and sharing no code with the isolation algorithms under test.

use crate::common;

use common::{Rng, iters};
use exactlti::Error;
use exactlti::algebraic::NumberField;
use exactlti::algebraic::nf_factor::norm;
use exactlti::algebraic::{AlgebraicNumber, factor_over_number_field, factor_q, roots};
use exactlti::field::{Field, Q, Rational};
use exactlti::poly::{Poly, parse_poly_q};
use exactlti::report::sections::{factor_report, roots_report};
use num_traits::{Signed, Zero};
use proptest::prelude::*;

fn p(s: &str) -> Poly<Q> {
    parse_poly_q(s).unwrap()
}
fn r(n: i64, d: i64) -> Rational {
    Rational::new(n.into(), d.into())
}

// ---------------------------------------------------------------- oracles

/// Sturm sequence of a square-free polynomial.
fn sturm(f: &Poly<Q>) -> Vec<Poly<Q>> {
    let mut s = vec![f.clone(), f.derivative()];
    while !s[s.len() - 1].is_zero() {
        let n = s.len();
        let rem = s[n - 2].rem(&s[n - 1]).neg();
        s.push(rem);
    }
    s.pop();
    s
}
fn variations_at(s: &[Poly<Q>], x: &Rational) -> usize {
    let signs: Vec<bool> = s
        .iter()
        .map(|g| g.eval(x))
        .filter(|v| !v.is_zero())
        .map(|v| v.is_positive())
        .collect();
    signs.windows(2).filter(|w| w[0] != w[1]).count()
}
/// Number of distinct real roots of the square-free `f` in `(a, b]` (Sturm).
fn sturm_count(f: &Poly<Q>, a: &Rational, b: &Rational) -> usize {
    let s = sturm(f);
    variations_at(&s, a) - variations_at(&s, b)
}

fn sqfree_part(f: &Poly<Q>) -> Poly<Q> {
    f.quo(&f.gcd(&f.derivative()))
}

/// Points of [0, 1] that separate the distinct roots of `w` in [0, 1] (Sturm bisection;
/// no returned point is a root).
fn separating_points(w: &Poly<Q>) -> Vec<Rational> {
    let one = r(1, 1);
    let zero = r(0, 1);
    let mut pts = vec![];
    if w.is_constant() {
        if !w.eval(&zero).is_zero() {
            pts.push(zero.clone());
        }
        pts.push(one);
        return pts;
    }
    let s = sturm(w);
    let count = |a: &Rational, b: &Rational| variations_at(&s, a) - variations_at(&s, b);
    let mut stack = vec![(zero.clone(), one.clone())];
    let mut cuts = vec![zero.clone(), one.clone()];
    while let Some((a, b)) = stack.pop() {
        if count(&a, &b) <= 1 {
            continue;
        }
        // a midpoint that is not a root
        let mut k = 2i64;
        let mut m = (&a + &b) / r(2, 1);
        while w.eval(&m).is_zero() {
            k += 1;
            m = &a + (&b - &a) * r(1, k);
        }
        cuts.push(m.clone());
        stack.push((a, m.clone()));
        stack.push((m, b));
    }
    cuts.sort();
    // every (cut_i, cut_{i+1}] holds <= 1 root; a root at cut_{i+1} is excluded below
    for c in cuts {
        if !w.eval(&c).is_zero() {
            pts.push(c);
        }
    }
    pts
}

/// Exact number of roots of the square-free `f` inside the closed box (argument principle
/// by quadrant counting); `None` when a root lies on the boundary.
fn winding_count(
    f: &Poly<Q>,
    re: (&Rational, &Rational),
    im: (&Rational, &Rational),
) -> Option<i64> {
    let (a, b) = re;
    let (c, d) = im;
    // edges as u0 + u1 t, t in [0, 1], counter-clockwise
    let edges = [
        ((a.clone(), c.clone()), (b - a, r(0, 1))),
        ((b.clone(), c.clone()), (r(0, 1), d - c)),
        ((b.clone(), d.clone()), (a - b, r(0, 1))),
        ((a.clone(), d.clone()), (r(0, 1), c - d)),
    ];
    let mut quads = vec![];
    for ((u0r, u0i), (u1r, u1i)) in edges {
        // f(u0 + u1 t) = U(t) + i V(t) by Horner over pairs
        let xr = Poly::new(Q, vec![u0r, u1r]);
        let xi = Poly::new(Q, vec![u0i, u1i]);
        let (mut ur, mut ui) = (Poly::zero(Q), Poly::zero(Q));
        for co in f.coeffs().iter().rev() {
            let nr = ur
                .mul(&xr)
                .sub(&ui.mul(&xi))
                .add(&Poly::constant(Q, co.clone()));
            let ni = ur.mul(&xi).add(&ui.mul(&xr));
            ur = nr;
            ui = ni;
        }
        let g = ur.gcd(&ui);
        if !g.is_constant() {
            // a common root on [0, 1] would be a root of f on the boundary
            let gs = sqfree_part(&g);
            let z0 = r(0, 1);
            if gs.eval(&z0).is_zero() || sturm_count(&gs, &z0, &r(1, 1)) > 0 {
                return None;
            }
        }
        let w = sqfree_part(&ur.mul(&ui));
        for t in separating_points(&w) {
            let (u, v) = (ur.eval(&t), ui.eval(&t));
            let q = match (u.is_positive(), v.is_positive()) {
                (true, true) => 0,
                (false, true) => 1,
                (false, false) => 2,
                (true, false) => 3,
            };
            quads.push(q);
        }
    }
    let mut turns = 0i64;
    for i in 0..quads.len() {
        let dq = (quads[(i + 1) % quads.len()] - quads[i] + 4) % 4;
        turns += match dq {
            0 => 0,
            1 => 1,
            3 => -1,
            _ => return None,
        };
    }
    Some(turns / 4)
}

/// Checks that the isolating region of `x` holds exactly one root of its minimal polynomial,
/// by the oracles above.
fn check_isolation(x: &AlgebraicNumber) {
    let m = x.minpoly();
    if let Some(q) = x.to_rational() {
        assert!(m.eval(&q).is_zero());
        return;
    }
    let ((r0, r1), (i0, i1)) = x.bounding_box();
    if x.is_real() {
        assert!(r0 < r1);
        assert!(!m.eval(&r0).is_zero() && !m.eval(&r1).is_zero());
        assert_eq!(sturm_count(m, &r0, &r1), 1, "interval of {x}");
        // and the sign changes across it
        assert_ne!(m.eval(&r0).is_positive(), m.eval(&r1).is_positive());
    } else {
        assert_eq!(
            winding_count(m, (&r0, &r1), (&i0, &i1)),
            Some(1),
            "box of {x}"
        );
    }
}

fn eval_c(f: &Poly<Q>, z: (f64, f64)) -> ((f64, f64), f64) {
    let (mut a, mut b) = (0.0, 0.0);
    let mut scale = 0.0;
    let mz = (z.0 * z.0 + z.1 * z.1).sqrt();
    for (i, c) in f.coeffs().iter().enumerate().rev() {
        let cf = exactlti::field::rational_to_f64(c);
        let na = a * z.0 - b * z.1 + cf;
        let nb = a * z.1 + b * z.0;
        a = na;
        b = nb;
        scale += cf.abs() * mz.powi(i as i32);
    }
    ((a, b), scale)
}

// ---------------------------------------------------------------- examples

#[test]
fn factor_q_examples() {
    let (lc, fs) = factor_q(&p("3*x^4 - 3")).unwrap();
    assert_eq!(lc, r(3, 1));
    let shown: Vec<String> = fs.iter().map(|(f, e)| format!("{f}^{e}")).collect();
    assert_eq!(shown, ["x - 1^1", "x + 1^1", "x^2 + 1^1"]);
    let (_, fs) = factor_q(&p("((s^2+1)*(s^2+2)*(s^2+3)*(s^4+4*s^2+1))^2")).unwrap();
    let shown: Vec<String> = fs.iter().map(|(f, e)| format!("{f}:{e}")).collect();
    assert_eq!(
        shown,
        ["x^2 + 1:2", "x^2 + 2:2", "x^2 + 3:2", "x^4 + 4*x^2 + 1:2"]
    );
    assert!(matches!(factor_q(&Poly::zero(Q)), Err(Error::Invalid(_))));
    assert_eq!(factor_q(&p("7/2")).unwrap(), (r(7, 2), vec![]));
}

#[test]
fn value_strings() {
    let cases = [
        ("x^2 - x - 1", vec!["1/2 - sqrt(5)/2", "1/2 + sqrt(5)/2"]),
        ("x^2 + 2*x + 2", vec!["-1 - i", "-1 + i"]),
        ("2*x^2 + 1", vec!["-sqrt(2)*i/2", "sqrt(2)*i/2"]),
        ("x + 2", vec!["-2"]),
        ("4*x - 3", vec!["3/4"]),
        ("x^2 - 8", vec!["-2*sqrt(2)", "2*sqrt(2)"]),
        ("x^2 - 2*x + 5", vec!["1 - 2*i", "1 + 2*i"]),
    ];
    for (s, want) in cases {
        let rs = AlgebraicNumber::roots_of_irreducible(&p(s)).unwrap();
        let got: Vec<String> = rs.iter().map(|x| x.value_string()).collect();
        assert_eq!(got, want, "{s}");
        for x in &rs {
            check_isolation(x);
        }
    }
    // the biquadratic case: the nested radicals of the Jordan form (one display per number)
    let rs = AlgebraicNumber::roots_of_irreducible(&p("x^4 + 4*x^2 + 1")).unwrap();
    let got: Vec<String> = rs.iter().map(|x| x.value_string()).collect();
    assert_eq!(
        got,
        [
            "-i*sqrt(2 + sqrt(3))",
            "-i*sqrt(2 - sqrt(3))",
            "i*sqrt(2 - sqrt(3))",
            "i*sqrt(2 + sqrt(3))",
        ]
    );
    let rs = AlgebraicNumber::roots_of_irreducible(&p("x^4 + 2")).unwrap();
    assert!(rs[0].value_string().starts_with("root of x^4 + 2 near "));
    let rs = AlgebraicNumber::roots_of_irreducible(&p("x^3 - 2")).unwrap();
    assert_eq!(rs[0].value_string(), "root of x^3 - 2 near 1.259921050");
    assert_eq!(
        rs[1].value_string(),
        "root of x^3 - 2 near -0.6299605249 - 1.091123636*i"
    );
    assert!(matches!(
        AlgebraicNumber::roots_of_irreducible(&p("x^2 - 1")),
        Err(Error::NotIrreducible(_))
    ));
    assert!(AlgebraicNumber::roots_of_irreducible(&p("3")).is_err());
}

#[test]
fn sliding_mass_roots() {
    let f = p("((s^2+1)*(s^2+2)*(s^2+3)*(s^4+4*s^2+1))^2");
    let rs = roots(&f).unwrap();
    assert_eq!(rs.len(), 10);
    assert_eq!(rs.iter().map(|(_, e)| e).sum::<usize>(), 20);
    assert!(
        rs.iter()
            .all(|(x, e)| *e == 2 && !x.is_real() && x.is_pure_imaginary())
    );
    let mut ims: Vec<f64> = rs.iter().map(|(x, _)| x.approx().1).collect();
    let want = [
        -(3f64.sqrt()),
        -(2.0 + 3f64.sqrt()).sqrt(),
        -(2f64.sqrt()),
        -1.0,
        -(2.0 - 3f64.sqrt()).sqrt(),
    ];
    let mut want: Vec<f64> = want
        .iter()
        .chain(want.iter().map(|w| -w).collect::<Vec<_>>().iter())
        .copied()
        .collect();
    want.sort_by(|a, b| a.partial_cmp(b).unwrap());
    ims.sort_by(|a, b| a.partial_cmp(b).unwrap());
    for (a, b) in ims.iter().zip(&want) {
        assert!((a - b).abs() < 1e-14, "{a} vs {b}");
    }
    let shown: Vec<String> = rs.iter().map(|(x, _)| x.value_string()).collect();
    for s in [
        "i",
        "-i",
        "sqrt(2)*i",
        "-sqrt(2)*i",
        "sqrt(3)*i",
        "-sqrt(3)*i",
    ] {
        assert!(shown.contains(&s.to_string()), "{s} in {shown:?}");
    }
    // sorted by (re, im): all re = 0, so by imaginary part
    for w in rs.windows(2) {
        assert!(w[0].0.approx().1 < w[1].0.approx().1);
    }
    for (x, _) in &rs {
        check_isolation(x);
    }
}

#[test]
fn ordering_and_equality() {
    let sq2 = AlgebraicNumber::roots_of_irreducible(&p("x^2 - 2")).unwrap()[1].clone();
    let q = |a, b| AlgebraicNumber::from_rational(&r(a, b));
    assert!(sq2 < q(99, 70));
    assert!(sq2 > q(141421356, 100000000));
    assert!(sq2 < q(141421357, 100000000));
    assert!(sq2 > q(1393, 985)); // continued-fraction convergent just below
    assert!(q(3, 4) < q(4, 5));
    assert_eq!(q(3, 4), q(6, 8));
    let again = AlgebraicNumber::roots_of_irreducible(&p("2*x^2 - 4")).unwrap();
    assert_eq!(again[1], sq2);
    assert_ne!(again[0], sq2);
    assert!(again[0] < sq2);
    let sq3 = AlgebraicNumber::roots_of_irreducible(&p("x^2 - 3")).unwrap()[1].clone();
    assert!(sq2 < sq3);
    let i = AlgebraicNumber::roots_of_irreducible(&p("x^2 + 1")).unwrap();
    assert_eq!(i[0].partial_cmp(&i[1]), None);
    assert_eq!(i[1].conj(), i[0]);
    assert_eq!(i[1].conj().conj(), i[1]);
}

#[test]
fn digits_examples() {
    let sq2 = AlgebraicNumber::roots_of_irreducible(&p("x^2 - 2")).unwrap()[1].clone();
    assert_eq!(sq2.digits(30).0, "1.41421356237309504880168872421");
    let rs = AlgebraicNumber::roots_of_irreducible(&p("x^4 + 4*x^2 + 1")).unwrap();
    assert_eq!(
        rs[3].digits(20),
        ("0".into(), "1.9318516525781365735".into())
    );
    let c = AlgebraicNumber::roots_of_irreducible(&p("x^3 - 2")).unwrap();
    assert_eq!(
        c[2].digits(15),
        ("-0.629960524947437".into(), "1.09112363597172".into())
    );
    assert_eq!(
        AlgebraicNumber::from_rational(&r(-2, 3)).digits(5),
        ("-0.66667".into(), "0".into())
    );
}

#[test]
fn re_im_conj_identities() {
    for s in ["x^3 - 2", "x^4 + x + 1", "x^2 + 2*x + 2", "x^4 + 4*x^2 + 1"] {
        for z in AlgebraicNumber::roots_of_irreducible(&p(s)).unwrap() {
            let re = z.try_re().unwrap();
            let im = z.try_im().unwrap();
            assert!(re.is_real() && im.is_real());
            let (zr, zi) = z.approx();
            let (a, _) = re.approx();
            let (b, _) = im.approx();
            assert!(
                (zr - a).abs() < 1e-13 && (zi - b).abs() < 1e-13,
                "{z}: {a} {b}"
            );
            // minimal polynomials vanish at the approximations (relative to their scale)
            for x in [&re, &im] {
                let ((v, _), sc) = eval_c(x.minpoly(), x.approx());
                assert!(v.abs() <= 1e-10 * sc.max(1.0));
                check_isolation(x);
            }
            // exact: conj has the same minimal polynomial, conj(conj z) = z, re(conj) = re
            let zc = z.conj();
            assert_eq!(zc.minpoly(), z.minpoly());
            assert_eq!(zc.conj(), z);
            assert_eq!(zc.try_re().unwrap(), re);
            if !z.is_real() {
                assert_ne!(zc, z);
                assert_eq!(zc.try_im().unwrap(), im.neg());
            }
        }
    }
    // exact minimal polynomials of parts of cube roots of 2: re = -2^(1/3)/2
    let c = AlgebraicNumber::roots_of_irreducible(&p("x^3 - 2")).unwrap();
    assert_eq!(c[1].re().unwrap().minpoly().to_string(), "x^3 + 1/4");
    assert_eq!(c[2].im().unwrap().minpoly().to_string(), "x^6 - 27/16");
}

#[test]
fn number_field_factorization_examples() {
    // s^4 + 4 s^2 + 1 over Q(sqrt 3): (x^2 + 2 - t)(x^2 + 2 + t)
    let k = NumberField::new(&p("t^2 - 3"), (1.732, 0.0)).unwrap();
    let f = p("x^4 + 4*x^2 + 1").map(&k, |c| k.from_rational(c));
    let fs = factor_over_number_field(&f).unwrap();
    assert_eq!(fs.len(), 2);
    assert!(fs.iter().all(|(g, e)| g.deg() == 2 && *e == 1));
    let prod = fs.iter().fold(Poly::one(k.clone()), |a, (g, _)| a.mul(g));
    assert_eq!(prod, f);
    // x^2 + 1 over Q(i)
    let ki = NumberField::new(&p("t^2 + 1"), (0.0, 1.0)).unwrap();
    let g = p("x^2 + 1").map(&ki, |c| ki.from_rational(c));
    let gs = factor_over_number_field(&g).unwrap();
    let shown: Vec<String> = gs.iter().map(|(h, _)| h.to_string()).collect();
    assert_eq!(shown, ["x + t", "x - t"]);
    // x^3 - 2 over Q(cbrt 2): linear times irreducible quadratic; squared input
    let kc = NumberField::new(&p("t^3 - 2"), (1.26, 0.0)).unwrap();
    let h = p("(x^3 - 2)^2").map(&kc, |c| kc.from_rational(c));
    let hs = factor_over_number_field(&h).unwrap();
    let shown: Vec<String> = hs.iter().map(|(h, e)| format!("{h}:{e}")).collect();
    assert_eq!(shown, ["x - t:2", "x^2 + t*x + t^2:2"]);
    // x^2 - 2 stays irreducible over Q(i)
    let q2 = p("x^2 - 2").map(&ki, |c| ki.from_rational(c));
    assert_eq!(factor_over_number_field(&q2).unwrap().len(), 1);
    // reducible moduli are rejected
    assert!(matches!(
        NumberField::new(&p("t^4 + 2*t^2 + 1"), (0.0, 1.0)),
        Err(Error::NotIrreducible(_))
    ));
    assert!(NumberField::new(&p("t^4 + 4*t^2 + 1"), (0.0, 0.5)).is_ok());
    // to_number_field marks the root
    let z = AlgebraicNumber::roots_of_irreducible(&p("x^2 - 3")).unwrap()[1].to_number_field();
    assert!((z.root_approx().0 - 3f64.sqrt()).abs() < 1e-15);
}

#[test]
fn reports() {
    let rep = factor_report(&p("2*x^3 - 2*x")).unwrap();
    let j = rep.to_json();
    assert_eq!(j["content"], "2");
    assert_eq!(j["factors"][0]["poly"], "x - 1");
    assert_eq!(j["factors"][2]["multiplicity"], 1);
    let rep = roots_report(&p("(x^2 + 1)^2*(x - 1/2)"), 12).unwrap();
    let j = rep.to_json();
    assert_eq!(j["roots"][0]["value"], "1/2");
    assert_eq!(j["roots"][1]["value"], "-i");
    assert_eq!(j["roots"][2]["multiplicity"], 2);
    assert_eq!(j["roots"][2]["minpoly"], "x^2 + 1");
    assert_eq!(j["roots"][2]["approx"][1].as_f64(), Some(1.0));
    assert_eq!(j["roots"][2]["digits"][1], "1.00000000000");
}

// ---------------------------------------------------------------- properties

fn random_poly(rng: &mut Rng, deg: usize, c: i64) -> Poly<Q> {
    let mut v: Vec<i64> = (0..=deg).map(|_| rng.int(-c, c)).collect();
    if v[deg] == 0 {
        v[deg] = 1;
    }
    Poly::from_i64s(&v)
}

#[test]
fn roots_properties_fixed_seed() {
    let mut rng = Rng(7);
    // the exact winding-number oracle is slow in debug builds: small degrees here, the
    // proptest below covers degree <= 9 numerically
    for _ in 0..iters(12) {
        let d = rng.int(1, 4) as usize;
        let a = random_poly(&mut rng, d, 9);
        // also products with repeated factors
        let f = if d <= 2 && rng.int(0, 1) == 0 {
            a.mul(&random_poly(&mut rng, 2, 3)).mul(&a)
        } else {
            a
        };
        let rs = roots(&f).unwrap();
        assert_eq!(rs.iter().map(|(_, e)| e).sum::<usize>(), f.deg());
        for (x, e) in &rs {
            check_isolation(x);
            // multiplicity e: x is a root of f^(e-1) ... exactly: minpoly^e divides f
            assert!(f.div_exact(&x.minpoly().pow(*e as u32)).is_some());
            assert!(f.div_exact(&x.minpoly().pow(*e as u32 + 1)).is_none());
        }
        // pairwise distinct, sorted reals
        for i in 0..rs.len() {
            for j in i + 1..rs.len() {
                assert_ne!(rs[i].0, rs[j].0);
            }
        }
        let reals: Vec<&AlgebraicNumber> =
            rs.iter().map(|(x, _)| x).filter(|x| x.is_real()).collect();
        for w in reals.windows(2) {
            assert!(w[0] < w[1]);
        }
    }
}

#[test]
fn nf_factor_properties_fixed_seed() {
    let fields = [
        NumberField::new(&p("t^2 - 2"), (1.414, 0.0)).unwrap(),
        NumberField::new(&p("t^2 + 1"), (0.0, 1.0)).unwrap(),
        NumberField::new(&p("t^3 - 2"), (1.26, 0.0)).unwrap(),
    ];
    let mut rng = Rng(11);
    for it in 0..iters(6) {
        let k = &fields[it % fields.len()];
        let t = k.generator();
        let rnd = |rng: &mut Rng, d: usize| {
            let cs: Vec<_> = (0..=d)
                .map(|i| {
                    if i == d {
                        k.one()
                    } else {
                        k.add(
                            &k.from_i64(rng.int(-3, 3)),
                            &k.mul(&k.from_i64(rng.int(-2, 2)), &t),
                        )
                    }
                })
                .collect();
            Poly::new(k.clone(), cs)
        };
        let (da, db) = (rng.int(1, 2) as usize, rng.int(1, 2) as usize);
        let a = rnd(&mut rng, da);
        let b = rnd(&mut rng, db);
        let f = a.mul(&b).mul(&a);
        let fs = factor_over_number_field(&f).unwrap();
        let prod = fs.iter().fold(Poly::one(k.clone()), |acc, (g, e)| {
            acc.mul(&g.pow(*e as u32))
        });
        assert_eq!(prod, f.monic());
        for (g, _) in &fs {
            // irreducible over K  =>  its norm is a power of one irreducible over Q
            let (_, nf) = factor_q(&norm(g)).unwrap();
            assert_eq!(nf.len(), 1, "factor {g} of {f}");
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, .. ProptestConfig::default() })]

    #[test]
    fn random_integer_polys_roots(cs in proptest::collection::vec(-30i64..30, 2..10)) {
        let f = Poly::from_i64s(&cs);
        prop_assume!(f.deg() >= 1);
        let rs = roots(&f).unwrap();
        prop_assert_eq!(rs.iter().map(|(_, e)| e).sum::<usize>(), f.deg());
        for (x, _) in &rs {
            let ((a, b), sc) = eval_c(&f, x.approx());
            prop_assert!((a * a + b * b).sqrt() <= 1e-9 * sc.max(1.0), "{} at {:?}", f, x.approx());
        }
    }

    #[test]
    fn parser_never_panics(s in "[0-9xy+\\-*/^(). e]{0,24}") {
        let _ = parse_poly_q(&s);
    }

    #[test]
    fn parser_never_panics_any_text(s in "\\PC{0,32}") {
        let _ = parse_poly_q(&s);
    }
}
