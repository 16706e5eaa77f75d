//! Gain and phase margins (`system::margins`): hand values (python-control's `margin` on
//! the same systems gives the same numbers, `scripts/anchors/margins.py`), edge shapes
//! (integrator, unstable, no crossover, Nyquist curve on the real axis, |G| = 1 everywhere),
//! random loops against a dense float scan of G(jw), and the exact identities.

use crate::common::cli::{run, temp_file};
use exactlti::algebraic::{AlgebraicNumber, NumberField};
use exactlti::field::{Field, Q, Rational};
use exactlti::poly::Poly;
use exactlti::rng::SplitMix64;
use exactlti::system::margins::algebra::split_imaginary_axis;
use exactlti::system::margins::{Margins, eval_jw, margins_tf};

fn p(cs: &[i64]) -> Poly<Q> {
    Poly::from_i64s(cs)
}

fn rat(n: i64, d: i64) -> Rational {
    Rational::new(n.into(), d.into())
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * (1.0 + b.abs())
}

#[test]
fn type_one_third_order_loop_by_hand() {
    // G = 1/(s (s+1)^2): I = w^3 - w, so w_pc = 1 with G(j) = -1/2: gain margin 2;
    // |D|^2 = w^2 (w^2+1)^2 = 1 at w^3 + w - 1 = 0 (w_gc = 0.6823), cos PM = 2 w^2
    let m = margins_tf(&p(&[1]), &p(&[0, 1, 2, 1])).unwrap();
    assert!(m.verified);
    let gm = m.gain_margin().unwrap();
    assert_eq!(gm.w.to_rational(), Some(rat(1, 1)));
    assert_eq!(gm.gain_margin.to_rational(), Some(rat(2, 1)));
    let pm = m.phase_margin().unwrap();
    assert_eq!(pm.w.minpoly(), &p(&[-1, 1, 0, 1]));
    assert!(close(pm.w.approx().0, 0.682_327_803_828_019_3, 1e-14));
    assert!(close(pm.phase_margin_deg, 21.386_389_751_875_04, 1e-9));
    // cos PM = 2 w^2 is a root of x^3 - 4 x^2 + 4x ... : check the value and the identity
    let w = pm.w.approx().0;
    assert!(close(pm.cos_phase_margin.approx().0, 2.0 * w * w, 1e-14));
    assert!(close(
        pm.cos_phase_margin.approx().0,
        pm.phase_margin_deg.to_radians().cos(),
        1e-12
    ));
}

#[test]
fn third_order_with_irrational_phase_crossover() {
    // G = 1/(s^3 + 2 s^2 + 3 s + 4): I = w^3 - 3w, w_pc = sqrt(3), G(j sqrt 3) = -1/2
    let m = margins_tf(&p(&[1]), &p(&[4, 3, 2, 1])).unwrap();
    assert!(m.verified);
    let gm = m.gain_margin().unwrap();
    assert_eq!(gm.w.minpoly(), &p(&[-3, 0, 1]));
    assert_eq!(gm.w.value_string(), "sqrt(3)");
    assert_eq!(gm.gain_margin.to_rational(), Some(rat(2, 1)));
    // |G(0)| = 1/4 and |G| falls: no gain crossover, infinite phase margin
    assert!(m.phase_margin().is_none() && m.gain_crossings.is_empty());
    // with gain 8: |G(0)| = 2, the gain margin is 1/4 (unstable closed loop), the phase
    // margin negative
    let m = margins_tf(&p(&[8]), &p(&[4, 3, 2, 1])).unwrap();
    assert_eq!(
        m.gain_margin().unwrap().gain_margin.to_rational(),
        Some(rat(1, 4))
    );
    assert!(m.phase_margin().unwrap().phase_margin_deg < 0.0);
}

#[test]
fn edge_shapes() {
    // integrator 1/s: no phase crossover, w_gc = 1 with PM 90 (cos PM = 0 exactly)
    let m = margins_tf(&p(&[1]), &p(&[0, 1])).unwrap();
    assert!(m.gain_margin().is_none());
    let pm = m.phase_margin().unwrap();
    assert_eq!(pm.w.to_rational(), Some(rat(1, 1)));
    assert_eq!(pm.cos_phase_margin.to_rational(), Some(rat(0, 1)));
    assert!(close(pm.phase_margin_deg, 90.0, 1e-12));
    // unstable 2/(s - 1): G(0) = -2 counts as a phase crossing at w = 0 (python-control's
    // convention), gain margin 1/2; w_gc = sqrt(3), G = -1/2 - sqrt(3)/2 j, PM = 60
    let m = margins_tf(&p(&[2]), &p(&[-1, 1])).unwrap();
    let gm = m.gain_margin().unwrap();
    assert_eq!(gm.w.to_rational(), Some(rat(0, 1)));
    assert_eq!(gm.gain_margin.to_rational(), Some(rat(1, 2)));
    let pm = m.phase_margin().unwrap();
    assert_eq!(pm.w.value_string(), "sqrt(3)");
    assert_eq!(pm.cos_phase_margin.to_rational(), Some(rat(1, 2)));
    assert!(close(pm.phase_margin_deg, 60.0, 1e-12));
    // no crossover at all: 1/(s + 1)
    let m = margins_tf(&p(&[1]), &p(&[1, 1])).unwrap();
    assert!(m.gain_margin().is_none() && m.phase_margin().is_none());
    assert!(m.verified && !m.real_everywhere && !m.unit_gain_everywhere);
    // poles on the axis: 1/(s^2 + 1) is real on the whole axis (no phase crossover counted),
    // |G| = 1 at w = sqrt(2) where G = -1: PM = 0
    let m = margins_tf(&p(&[1]), &p(&[1, 0, 1])).unwrap();
    assert!(m.real_everywhere && m.gain_margin().is_none());
    let pm = m.phase_margin().unwrap();
    assert_eq!(pm.w.value_string(), "sqrt(2)");
    assert_eq!(pm.cos_phase_margin.to_rational(), Some(rat(1, 1)));
    assert!(pm.phase_margin_deg.abs() < 1e-9);
    // all-pass (1 - s)/(1 + s): |G| = 1 everywhere, -180 degrees only as w -> inf
    let m = margins_tf(&p(&[1, -1]), &p(&[1, 1])).unwrap();
    assert!(m.unit_gain_everywhere && m.phase_margin().is_none() && m.gain_margin().is_none());
    // ((1 - s)/(1 + s))^2: G(j) = (-j)^2 = -1, a phase crossing at w = 1 with gain margin 1
    let m = margins_tf(&p(&[1, -2, 1]), &p(&[1, 2, 1])).unwrap();
    assert!(m.unit_gain_everywhere && m.phase_margin().is_none());
    let gm = m.gain_margin().unwrap();
    assert_eq!(gm.w.to_rational(), Some(rat(1, 1)));
    assert_eq!(gm.gain_margin.to_rational(), Some(rat(1, 1)));
    // a zero on the axis is no crossing: s^2 + 1 over (s + 1)^3
    let m = margins_tf(&p(&[1, 0, 1]), &p(&[1, 3, 3, 1])).unwrap();
    assert!(m.verified);
    for c in &m.phase_crossings {
        assert!((c.w.approx().0 - 1.0).abs() > 1e-6);
    }
    // a constant: nothing crosses
    let m = margins_tf(&p(&[-3]), &p(&[1])).unwrap();
    assert!(m.real_everywhere && m.gain_margin().is_none() && m.phase_margin().is_none());
    assert!(margins_tf(&p(&[1]), &Poly::zero(Q)).is_err());
}

/// The exact identities: each crossing's minimal polynomial divides its defining polynomial,
/// the gain margin g satisfies g P(w) + |D(w)|^2 = 0 and cos PM |D|^2 + P = 0 in Q(w).
fn identities(num: &Poly<Q>, den: &Poly<Q>, m: &Margins) {
    let (nr, ni) = split_imaginary_axis(num);
    let (dr, di) = split_imaginary_axis(den);
    let pp = nr.mul(&dr).add(&ni.mul(&di));
    let d2 = dr.mul(&dr).add(&di.mul(&di));
    let value_in = |x: &AlgebraicNumber, w: &AlgebraicNumber, a: &Poly<Q>, b: &Poly<Q>| {
        // x b(w) + a(w) == 0 where x is given by its minimal polynomial: evaluate the minimal
        // polynomial of x at -a/b in Q(w)
        let k = NumberField::new_unchecked(w.minpoly(), w.approx());
        let v = k.neg(&k.mul(&k.from_poly(a), &k.inv(&k.from_poly(b)).unwrap()));
        let mut acc = k.zero();
        for c in x.minpoly().coeffs().iter().rev() {
            acc = k.add(&k.mul(&acc, &v), &k.from_base(c));
        }
        assert!(k.is_zero(&acc));
        let approx = k.approx(&v).0;
        assert!(
            close(approx, x.approx().0, 1e-9),
            "{approx} vs {}",
            x.approx().0
        );
    };
    for c in &m.phase_crossings {
        assert!(m.imag_poly.rem(c.w.minpoly()).is_zero());
        value_in(&c.gain_margin, &c.w, &d2, &pp);
    }
    for c in &m.gain_crossings {
        assert!(m.magnitude_poly.rem(c.w.minpoly()).is_zero());
        value_in(&c.cos_phase_margin, &c.w, &pp, &d2);
    }
}

#[test]
fn random_loops_against_a_float_scan() {
    let mut rng = SplitMix64(0x006d_a791_2026);
    let (mut with_pc, mut with_gc) = (0, 0);
    for _ in 0..crate::common::iters(25) {
        let dn = rng.int(1, 4) as usize;
        let nn = rng.int(0, dn as i64) as usize;
        let mut coeffs = |n: usize, lead: bool| {
            let mut v: Vec<i64> = (0..=n).map(|_| rng.int(-4, 6)).collect();
            if lead && v[n] == 0 {
                v[n] = 1;
            }
            v
        };
        let num = p(&coeffs(nn, true));
        let den = p(&coeffs(dn, true));
        if num.is_zero() {
            continue;
        }
        let g = num.gcd(&den);
        let (num, den) = (num.quo(&g), den.quo(&g));
        let m = margins_tf(&num, &den).unwrap();
        assert!(m.verified);
        identities(&num, &den, &m);
        // every reported crossing is one in floats
        for c in &m.phase_crossings {
            let z = eval_jw(&num, &den, c.w.approx().0);
            assert!(z.re < 0.0 && z.im.abs() <= 1e-7 * z.norm(), "{z}");
            assert!(close(c.gain_margin.approx().0 * z.norm(), 1.0, 1e-9));
        }
        for c in &m.gain_crossings {
            assert!(close(eval_jw(&num, &den, c.w.approx().0).norm(), 1.0, 1e-9));
        }
        // and no crossing is missed: a sign change of Im G (Re G < 0) or of |G| - 1 on a
        // dense grid lies within a reported one
        let grid: Vec<f64> = (0..4000)
            .map(|k| 10f64.powf(-3.0 + 6.0 * k as f64 / 3999.0))
            .collect();
        for win in grid.windows(2) {
            let (a, b) = (eval_jw(&num, &den, win[0]), eval_jw(&num, &den, win[1]));
            if !(a.norm().is_finite() && b.norm().is_finite()) {
                continue;
            }
            let inside = |w: &AlgebraicNumber| {
                let x = w.approx().0;
                x >= win[0] * (1.0 - 1e-9) && x <= win[1] * (1.0 + 1e-9)
            };
            if a.im * b.im < 0.0 && a.re < 0.0 && b.re < 0.0 && !m.real_everywhere {
                assert!(
                    m.phase_crossings.iter().any(|c| inside(&c.w)),
                    "{num} / {den}"
                );
            }
            if (a.norm() - 1.0) * (b.norm() - 1.0) < 0.0 {
                assert!(
                    m.gain_crossings.iter().any(|c| inside(&c.w)),
                    "{num} / {den}"
                );
            }
        }
        with_pc += usize::from(!m.phase_crossings.is_empty());
        with_gc += usize::from(!m.gain_crossings.is_empty());
    }
    assert!(with_pc > 0 && with_gc > 0, "{with_pc} {with_gc}");
}

#[test]
fn command_line() {
    let f = temp_file(
        "margins",
        "loop.json",
        r#"{"G": [["1/(s^3 + 2*s^2 + s)"]]}"#,
    );
    let (code, out, err) = run(&["margin", f.to_str().unwrap(), "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["gain_margin"], "2");
    assert_eq!(j["phase_crossover_frequency"], "1");
    assert_eq!(j["gain_crossover_frequency_minpoly"], "x^3 + x - 1");
    assert!(close(
        j["phase_margin_deg"].as_f64().unwrap(),
        21.386_389_751_875_04,
        1e-9
    ));
    assert_eq!(j["verified"], true);
    let (code, out, _) = run(&["margin", f.to_str().unwrap()]);
    assert_eq!(code, 0);
    assert!(out.lines().all(|l| l.chars().count() <= 200));
    // no crossover: stated as infinite
    let f = temp_file("margins", "lag.json", r#"{"G": [["1/(s + 1)"]]}"#);
    let (code, out, _) = run(&["margin", f.to_str().unwrap(), "--format", "json"]);
    assert_eq!(code, 0);
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(
        (j["gain_margin"].as_str(), j["phase_margin_deg"].as_str()),
        (Some("inf"), Some("inf"))
    );
    // MIMO is refused with one line, exit 2; a file over Q(sqrt 2) has its margins (issue 28:
    // it was refused; tests/margins_fields.rs has the crossings over Q(sqrt d) and Q(i))
    let f = temp_file(
        "margins",
        "mimo.json",
        r#"{"A": [[-1]], "B": [[1, 1]], "C": [[1]]}"#,
    );
    let (code, _, err) = run(&["margin", f.to_str().unwrap()]);
    assert_eq!((code, err.trim_end().lines().count()), (2, 1), "{err}");
    assert!(err.contains("SISO"));
    let f = temp_file(
        "margins",
        "k.json",
        r#"{"A": [["-sqrt(2)"]], "B": [[1]], "C": [[1]]}"#,
    );
    let (code, out, err) = run(&["margin", f.to_str().unwrap(), "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    // 1/(s + sqrt 2): |G(jw)| = 1/sqrt(w^2 + 2) < 1 and the phase stays above -90: no crossing
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(
        (j["gain_margin"].as_str(), j["phase_margin_deg"].as_str()),
        (Some("inf"), Some("inf"))
    );
    assert_eq!(j["verified"], true);
}
