//! Gain and phase margins over Q(sqrt d) and Q(i) (issue 28 item 3): the one computation of
//! `system::margins` on loops whose crossings are known by hand (the exact gain margins
//! sqrt 2, 4 sqrt 2 at w = sqrt 2 and at w = sqrt 3, 2 and 8 sqrt 3 / 9 over Q(i)), random
//! loops over Q(sqrt 2) and Q(i) against a float scan of G(jw) (every reported crossing is
//! one, none is missed), the rational loops unchanged when read over a quadratic field, and
//! the CLI on a file with sqrt(2).

use crate::common::cli::{run, temp_file};
use exactlti::algebraic::AlgebraicNumber;
use exactlti::field::{Q, Quadratic, QuadraticField, Rational};
use exactlti::poly::Poly;
use exactlti::rng::SplitMix64;
use exactlti::system::margins::{Margins, margins_tf};
use num_complex::Complex64;

fn qf(d: i64) -> QuadraticField {
    QuadraticField::new(d).unwrap()
}

/// `a + b sqrt d` with integer parts.
fn el(a: i64, b: i64) -> Quadratic {
    Quadratic::new(
        Rational::from_integer(a.into()),
        Rational::from_integer(b.into()),
    )
}

/// A polynomial over the field from `(a, b)` parts, constant term first.
fn poly(k: &QuadraticField, cs: &[(i64, i64)]) -> Poly<QuadraticField> {
    Poly::new(k.clone(), cs.iter().map(|&(a, b)| el(a, b)).collect())
}

fn minpoly_is(x: &AlgebraicNumber, cs: &[Rational]) {
    assert_eq!(x.minpoly(), &Poly::new(Q, cs.to_vec()), "{x:?}");
}

fn r(n: i64, d: i64) -> Rational {
    Rational::new(n.into(), d.into())
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * (1.0 + b.abs())
}

/// G(jw) in floats from the field's own embedding.
fn g_jw(
    k: &QuadraticField,
    num: &Poly<QuadraticField>,
    den: &Poly<QuadraticField>,
    w: f64,
) -> Complex64 {
    let ev = |p: &Poly<QuadraticField>| {
        p.coeffs()
            .iter()
            .rev()
            .fold(Complex64::new(0.0, 0.0), |acc, c| {
                let (re, im) = QuadraticField::approx(k, c);
                acc * Complex64::new(0.0, w) + Complex64::new(re, im)
            })
    };
    ev(num) / ev(den)
}

#[test]
fn real_quadratic_loops_by_hand() {
    let k = qf(2);
    // sqrt2 / (s (s+1)^2): w_pc = 1 (rational), gain margin 2 / sqrt 2 = sqrt 2
    let m = margins_tf(
        &poly(&k, &[(0, 1)]),
        &poly(&k, &[(0, 0), (1, 0), (2, 0), (1, 0)]),
    )
    .unwrap();
    assert!(m.verified);
    let gm = m.gain_margin().unwrap();
    assert_eq!(gm.w.to_rational(), Some(r(1, 1)));
    minpoly_is(&gm.gain_margin, &[r(-2, 1), r(0, 1), r(1, 1)]);
    assert!(close(gm.gain_margin.approx().0, 2f64.sqrt(), 1e-12));
    // 1 / (s (s + sqrt2)^2): w_pc = sqrt 2 (a root over Q(sqrt 2), sqrt 2 in Q(w)),
    // |G| = 1 / (sqrt2 * 4): gain margin 4 sqrt 2, a root of x^2 - 32
    let den = poly(&k, &[(0, 0), (2, 0), (0, 2), (1, 0)]); // s^3 + 2 sqrt2 s^2 + 2 s
    let m = margins_tf(&poly(&k, &[(1, 0)]), &den).unwrap();
    assert!(m.verified);
    let gm = m.gain_margin().unwrap();
    minpoly_is(&gm.w, &[r(-2, 1), r(0, 1), r(1, 1)]);
    minpoly_is(&gm.gain_margin, &[r(-32, 1), r(0, 1), r(1, 1)]);
    assert!(gm.gain_margin.approx().0 > 0.0);
    // sqrt2 / (s+1)^3: w_pc = sqrt 3 (sqrt 2 not in Q(w)), |G| = sqrt2 / 8: gain margin
    // 4 sqrt 2, the positive root of x^2 - 32
    let den = poly(&k, &[(1, 0), (3, 0), (3, 0), (1, 0)]);
    let m = margins_tf(&poly(&k, &[(0, 1)]), &den).unwrap();
    assert!(m.verified);
    let gm = m.gain_margin().unwrap();
    minpoly_is(&gm.w, &[r(-3, 1), r(0, 1), r(1, 1)]);
    minpoly_is(&gm.gain_margin, &[r(-32, 1), r(0, 1), r(1, 1)]);
    assert!(close(gm.gain_margin.approx().0, 32f64.sqrt(), 1e-12));
    // its gain crossover: |G| = 1 at (1 + w^2)^3 = 2, w^2 = 2^(1/3) - 1
    let pm = m.phase_margin().unwrap();
    let w = (2f64.powf(1.0 / 3.0) - 1.0).sqrt();
    assert!(close(pm.w.approx().0, w, 1e-12));
    assert!(close(
        pm.phase_margin_deg,
        180.0 - 3.0 * w.atan().to_degrees(),
        1e-9
    ));
}

#[test]
fn gaussian_loops_by_hand() {
    let k = QuadraticField::gaussian();
    // -i / (s+1)^2: G(j) = -i / (2 j) = -1/2: w_pc = 1, gain margin 2; G(0) = -i is not real
    let m = margins_tf(&poly(&k, &[(0, -1)]), &poly(&k, &[(1, 0), (2, 0), (1, 0)])).unwrap();
    assert!(m.verified);
    assert_eq!(m.phase_crossings.len(), 1);
    let gm = m.gain_margin().unwrap();
    assert_eq!(gm.w.to_rational(), Some(r(1, 1)));
    assert_eq!(gm.gain_margin.to_rational(), Some(r(2, 1)));
    // -i / (s+1)^3: -90 - 3 atan w = -180 at w = 1/sqrt 3, |G| = (3/4)^(3/2):
    // gain margin 8 sqrt3 / 9, a root of x^2 - 64/27
    let den = poly(&k, &[(1, 0), (3, 0), (3, 0), (1, 0)]);
    let m = margins_tf(&poly(&k, &[(0, -1)]), &den).unwrap();
    assert!(m.verified);
    let gm = m.gain_margin().unwrap();
    minpoly_is(&gm.w, &[r(-1, 3), r(0, 1), r(1, 1)]);
    minpoly_is(&gm.gain_margin, &[r(-64, 27), r(0, 1), r(1, 1)]);
    assert!(close(
        gm.gain_margin.approx().0,
        8.0 * 3f64.sqrt() / 9.0,
        1e-12
    ));
}

/// A rational loop read over Q(sqrt 2) or Q(i) has the margins it has over Q.
#[test]
fn rational_loops_agree_over_every_field() {
    let mut rng = SplitMix64(0x0028_3a26);
    for _ in 0..crate::common::iters(12) {
        let dn = rng.int(1, 4) as usize;
        let cs = |rng: &mut SplitMix64, n: usize| -> Vec<i64> {
            let mut v: Vec<i64> = (0..=n).map(|_| rng.int(-3, 6)).collect();
            if v[n] == 0 {
                v[n] = 1;
            }
            v
        };
        let nn = rng.int(0, dn as i64) as usize;
        let (nq, dq) = (cs(&mut rng, nn), cs(&mut rng, dn));
        let mq = margins_tf(&Poly::<Q>::from_i64s(&nq), &Poly::<Q>::from_i64s(&dq)).unwrap();
        for k in [qf(2), QuadraticField::gaussian()] {
            let lift = |v: &[i64]| poly(&k, &v.iter().map(|&a| (a, 0)).collect::<Vec<_>>());
            let mk: Margins<QuadraticField> = margins_tf(&lift(&nq), &lift(&dq)).unwrap();
            assert!(mk.verified);
            let ws =
                |m: &[AlgebraicNumber]| m.iter().map(|w| w.minpoly().clone()).collect::<Vec<_>>();
            let pq: Vec<_> = mq.phase_crossings.iter().map(|c| c.w.clone()).collect();
            let pk: Vec<_> = mk.phase_crossings.iter().map(|c| c.w.clone()).collect();
            assert_eq!(ws(&pq), ws(&pk), "{nq:?} / {dq:?}");
            for (a, b) in mq.phase_crossings.iter().zip(&mk.phase_crossings) {
                assert_eq!(a.gain_margin.minpoly(), b.gain_margin.minpoly());
                assert!(close(
                    a.gain_margin.approx().0,
                    b.gain_margin.approx().0,
                    1e-12
                ));
            }
            assert_eq!(mq.gain_crossings.len(), mk.gain_crossings.len());
            assert_eq!(mq.gm_index, mk.gm_index);
            assert_eq!(mq.pm_index, mk.pm_index);
        }
    }
}

/// Random loops with irrational coefficients: every reported crossing is one in floats (G
/// real negative with |G| gm = 1; |G| = 1), and a float scan finds no other.
#[test]
fn random_quadratic_loops_against_a_float_scan() {
    let mut rng = SplitMix64(0x0028_5eed);
    for k in [qf(2), qf(3), QuadraticField::gaussian(), qf(-3)] {
        for _ in 0..crate::common::iters(8) {
            let dn = rng.int(1, 3) as usize;
            let mut cs = |n: usize| -> Vec<(i64, i64)> {
                let mut v: Vec<(i64, i64)> =
                    (0..=n).map(|_| (rng.int(-2, 4), rng.int(-1, 1))).collect();
                v[n] = (1, 0);
                v
            };
            let den = poly(&k, &cs(dn));
            let nn = cs(0);
            let num = poly(&k, &[(nn[0].0.max(1), nn[0].1)]);
            let m = margins_tf(&num, &den).unwrap();
            assert!(m.verified, "{num:?} / {den:?}");
            for c in &m.phase_crossings {
                let z = g_jw(&k, &num, &den, c.w.approx().0);
                assert!(z.re < 0.0 && z.im.abs() <= 1e-7 * z.norm(), "{z}");
                assert!(close(c.gain_margin.approx().0 * z.norm(), 1.0, 1e-9));
            }
            for c in &m.gain_crossings {
                let z = g_jw(&k, &num, &den, c.w.approx().0);
                assert!(close(z.norm(), 1.0, 1e-9), "{z}");
                assert!(close(c.cos_phase_margin.approx().0, -z.re, 1e-9));
            }
            // the scan: a sign change of Im G with Re G < 0, or of |G| - 1, near a reported w
            let grid: Vec<f64> = (0..3000)
                .map(|i| 10f64.powf(-2.0 + 4.0 * i as f64 / 2999.0))
                .collect();
            for win in grid.windows(2) {
                let (a, b) = (g_jw(&k, &num, &den, win[0]), g_jw(&k, &num, &den, win[1]));
                if !(a.norm().is_finite() && b.norm().is_finite()) {
                    continue;
                }
                let near = |ws: Vec<f64>| {
                    ws.iter()
                        .any(|&x| x >= win[0] * 0.999 && x <= win[1] * 1.001)
                };
                if a.im.signum() != b.im.signum() && a.re < -1e-6 && b.re < -1e-6 {
                    assert!(
                        near(m.phase_crossings.iter().map(|c| c.w.approx().0).collect()),
                        "{win:?}"
                    );
                }
                if (a.norm() - 1.0).signum() != (b.norm() - 1.0).signum() {
                    assert!(
                        near(m.gain_crossings.iter().map(|c| c.w.approx().0).collect()),
                        "{win:?}"
                    );
                }
            }
        }
    }
}

#[test]
fn cli_margin_over_q_sqrt2() {
    // sqrt2 / (s+1)^3 in companion form
    let f = temp_file(
        "margins_fields",
        "margin_sqrt2.json",
        r#"{"A": [[0, 1, 0], [0, 0, 1], [-1, -3, -3]], "B": [[0], [0], [1]], "C": [["sqrt(2)", 0, 0]]}"#,
    );
    let f = f.to_string_lossy().into_owned();
    let (code, out, err) = run(&["margin", &f, "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["verified"], true, "{v}");
    let text = v.to_string();
    assert!(text.contains("x^2 - 32"), "{v}");
    assert!(text.contains("x^2 - 3"), "{v}");
}
