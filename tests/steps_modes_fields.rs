//! Issue 27: mode contributions (minimal-realizations paper eq. 33) and the free response
//! generic over the field — Q(sqrt 2), Q(i), Q(p) — with `--steps` over Q(p); `jordan
//! --normalize` over Q(p) without `--steps`. Every identity is recomputed here: the
//! projectors sum to I, the parts' Markov parameters add up to C A^k B, the residues' traces
//! are C_p B_p, each weight is tr(C W C^H) with its Lyapunov equation, sum g_0 = x0, and
//! after normalising A T = T J with det T != 0.

use crate::common::cli::{run, temp_file};
use crate::common::{Rng, qi, qsqrt2, random_matrix, unimodular};
use exactlti::field::{ElemDisplay, Field, Q, QuadraticField, Rational};
use exactlti::jordan::derivation::{Derivation, Object, StepKind};
use exactlti::jordan::normalize::{Normalization, dot, normalize_form_qp};
use exactlti::jordan::{jordan_over, jordan_qp};
use exactlti::matrix::Matrix;
use exactlti::ratfunc::RatFuncField;
use exactlti::realization::contribution::{
    Contributions, Weight, contributions, contributions_in, contributions_qp,
};
use exactlti::realization::contribution_steps::{contributions_steps_qp, response_steps_qp};
use exactlti::realization::lyapunov;
use exactlti::system::StateSpace;

fn rf(k: &RatFuncField, rows: &[&[&str]]) -> Matrix<RatFuncField> {
    Matrix::from_fn(k.clone(), rows.len(), rows[0].len(), |i, j| {
        k.parse(rows[i][j]).unwrap()
    })
}

/// The identities of a contributions result, recomputed: sum_p V_p R_p = I, R_p V_p = I,
/// A V_p = V_p A_p, the parts' Markov parameters add up to C A^k B (k < 2n).
fn check_modes<F: Field>(ss: &StateSpace<F>, c: &Contributions<F>) {
    let k = ss.field();
    let n = ss.nstates();
    let mut sum = Matrix::zeros(k.clone(), n, n);
    let kmax = 2 * n;
    let mut markov: Vec<Matrix<F>> = (0..kmax)
        .map(|_| Matrix::zeros(k.clone(), ss.noutputs(), ss.ninputs()))
        .collect();
    for m in &c.modes {
        let (v, r) = (&m.basis, &m.rows);
        assert!((r * v).is_identity());
        assert_eq!(&ss.a * v, v * &m.part.a);
        sum = &sum + &(v * r);
        for (acc, h) in markov.iter_mut().zip(m.part.markov(kmax)) {
            *acc = &*acc + &h;
        }
    }
    assert!(sum.is_identity(), "the projectors sum to I");
    assert_eq!(markov, ss.markov(kmax), "the parts add up to G");
    assert!(c.verified);
}

/// The rational value of a Q(p) matrix at `p0`.
fn at(k: &RatFuncField, m: &Matrix<RatFuncField>, p0: &[Rational]) -> Matrix<Q> {
    Matrix::from_fn(Q, m.nrows(), m.ncols(), |i, j| {
        k.eval(m.get(i, j), p0).unwrap()
    })
}

fn r(n: i64) -> Rational {
    Rational::from_integer(n.into())
}

/// A damped oscillator in (c, k) and a first-order lag in a: the weights are rational
/// functions (undecided stability), equal at stable points to the exact H2^2 over Q.
#[test]
fn contributions_over_qp_are_rational_functions_equal_to_h2_where_stable() {
    let k = RatFuncField::new(&["a", "c", "k"]).unwrap();
    let a = rf(
        &k,
        &[&["0", "1", "0"], &["-k", "-c", "1"], &["0", "0", "-a"]],
    );
    let b = rf(&k, &[&["0"], &["1"], &["1"]]);
    let cm = rf(&k, &[&["1", "0", "1"]]);
    let d = rf(&k, &[&["0"]]);
    let ss = StateSpace::new(a, b, cm, d).unwrap();
    let c = contributions_qp(&ss).unwrap();
    let kk = c.jordan.base().clone();
    let ss2 = StateSpace::new(
        Matrix::from_vec(kk.clone(), 3, 3, ss.a.as_slice().to_vec()),
        Matrix::from_vec(kk.clone(), 3, 1, ss.b.as_slice().to_vec()),
        Matrix::from_vec(kk.clone(), 1, 3, ss.c.as_slice().to_vec()),
        Matrix::from_vec(kk.clone(), 1, 1, ss.d.as_slice().to_vec()),
    )
    .unwrap();
    check_modes(&ss2, &c);
    assert_eq!(c.modes.len(), 2);
    assert!(!c.ranked, "weights in symbols are not ranked");
    assert!(c.truncate(1).is_err(), "no K heaviest in symbols");
    // at stable points the rational functions are the exact H2^2 over Q
    // points where s^2 + c s + k stays irreducible over Q (one mode there too) and -a is
    // not one of its roots
    for p0 in [
        [r(3), r(1), r(2)],
        [r(5), Rational::new(1.into(), 2.into()), r(7)],
    ] {
        let sq = StateSpace::new(
            at(&kk, &ss2.a, &p0),
            at(&kk, &ss2.b, &p0),
            at(&kk, &ss2.c, &p0),
            at(&kk, &ss2.d, &p0),
        )
        .unwrap();
        let cq = contributions(&sq).unwrap();
        for m in &c.modes {
            let Weight::H2SquaredWhereStable(h) = &m.weight else {
                panic!("a weight in symbols: {:?}", m.weight)
            };
            let hv = kk
                .eval(h, &p0)
                .unwrap_or_else(|| panic!("{} at {p0:?}", kk.fmt_elem(h)));
            // the same factor at the point: its part's order and H2^2
            let deg = c.jordan.components[m.component].degree();
            let found = cq
                .modes
                .iter()
                .any(|mq| mq.part.nstates() == deg && mq.weight == Weight::H2Squared(hv.clone()));
            assert!(found, "h2^2 at {p0:?}: {hv} not among {:?}", cq.modes);
            // and the Lyapunov identity of the part, as rational functions
            let w = lyapunov(&m.part.a, &(&m.part.b * &m.part.b.transpose())).unwrap();
            let cwc = &(&m.part.c * &w) * &m.part.c.transpose();
            assert_eq!(cwc.get(0, 0), h);
        }
    }
}

/// `contributions --steps` over Q(p): every step's identity holds, and recomputed from the
/// step data: the projectors sum to I, each residue H_0's trace is C_p B_p.
#[test]
fn contributions_steps_over_qp_hold() {
    let k = RatFuncField::new(&["m", "k"]).unwrap();
    let a = rf(
        &k,
        &[
            &["0", "1", "0", "0"],
            &["-2*k/m", "-1", "k/m", "0"],
            &["0", "0", "0", "1"],
            &["k/m", "0", "-2*k/m", "-1"],
        ],
    );
    let b = rf(&k, &[&["0"], &["1/m"], &["0"], &["0"]]);
    let cm = rf(&k, &[&["0", "0", "1", "0"]]);
    let d = rf(&k, &[&["0"]]);
    let ss = StateSpace::new(a, b, cm, d).unwrap();
    let der = contributions_steps_qp(&ss, None).unwrap();
    assert!(der.verified(), "every identity holds");
    let e = der.field.clone();
    let mut sum = Matrix::zeros(e.clone(), 4, 4);
    for st in der
        .steps
        .iter()
        .filter(|s| s.kind == StepKind::SpectralProjector)
    {
        let p = st.matrix("P").unwrap();
        assert_eq!(&(p * p), p, "P^2 = P");
        sum = &sum + p;
    }
    assert!(sum.is_identity());
    let weights = der
        .steps
        .iter()
        .filter(|s| s.kind == StepKind::ModeWeight)
        .count();
    assert_eq!(weights, 2);
    let ranking = der.of_kind(StepKind::ModeRanking).next().unwrap();
    assert_eq!(ranking.count("unranked"), Some(1));
    // the conditions are the last step's assumptions
    assert!(!der.steps.last().unwrap().assumes.is_empty());
}

/// `response --steps` over Q(p): A g_k = theta g_k + (k+1) g_(k+1) (each step), sum g_0 = x0.
#[test]
fn response_steps_over_qp_hold() {
    let k = RatFuncField::new(&["a", "u"]).unwrap();
    let a = rf(
        &k,
        &[&["-a", "1", "0"], &["0", "-a", "0"], &["0", "u", "-2*a"]],
    );
    let x0 = rf(&k, &[&["1"], &["u"], &["a - 1"]]);
    let der: Derivation<_> = response_steps_qp(&a, &x0).unwrap();
    assert!(der.verified());
    let free = der.of_kind(StepKind::FreeTerms).count();
    assert_eq!(free, 2, "two eigenvalues, -a (double) and -2a");
    let last = der.of_kind(StepKind::InitialState).next().unwrap();
    assert_eq!(last.holds, Some(true));
    // sum of the g_0 (every factor linear: no trace needed) is x0
    let mut sum: Option<Matrix<_>> = None;
    for st in der.of_kind(StepKind::FreeTerms) {
        let g = st.matrix("g").unwrap();
        let e = g.field().clone();
        let g0 = g.submatrix(0, 3, 0, 1);
        let g0 = g0.map(&der.field, |x| {
            der.field.from_base(&e.to_base(x).expect("linear factor"))
        });
        sum = Some(match sum {
            None => g0,
            Some(s) => &s + &g0,
        });
    }
    let Some(Object::Matrix(x)) = last.get("x0") else {
        panic!("x0")
    };
    assert_eq!(&sum.unwrap(), x);
}

/// Over Q(sqrt 2) and Q(i): random stable-or-not systems behind a random similarity; every
/// identity recomputed; over Q(i) the weight of 1/(s - (-1 + i)) is |1|^2 / (2 * 1) = 1/2
/// (the conjugate transpose: with the plain transpose W would not be real).
#[test]
fn contributions_over_quadratic_fields() {
    for (field, g) in [qsqrt2(), qi()] {
        let mut rng = Rng(27_031);
        for case in 0..6 {
            let n = 2 + case % 3;
            let diag = Matrix::from_fn(field.clone(), n, n, |i, j| {
                if i == j {
                    field.from_i64(-(i as i64) - 1)
                } else if j == i + 1 && case % 2 == 0 {
                    g.clone().unwrap()
                } else {
                    field.zero()
                }
            });
            let t = unimodular(&field, n, &mut rng);
            let ti = t.inverse().unwrap();
            let a = &(&t * &diag) * &ti;
            let b = random_matrix(&field, &g, n, 1, &mut rng);
            let c = random_matrix(&field, &g, 1, n, &mut rng);
            let ss = StateSpace::new(a, b, c, Matrix::zeros(field.clone(), 1, 1)).unwrap();
            let jf = jordan_over(&ss.a).unwrap();
            let cs = contributions_in(&ss, jf).unwrap();
            check_modes(&ss, &cs);
            assert!(cs.ranked);
            for m in &cs.modes {
                assert!(
                    matches!(m.weight, Weight::H2Squared(_) | Weight::Zero),
                    "eigenvalues -1, -2, ...: stable ({:?})",
                    m.weight
                );
            }
            // keeping all: no error; keeping none: the error's C B is C B
            let all = cs.truncate(cs.modes.len()).unwrap();
            assert!(all.verified && all.error_markov0.is_zero());
            let none = cs.truncate(0).unwrap();
            assert_eq!(none.error_markov0, &ss.c * &ss.b);
        }
    }
    let (k, i) = qi();
    let i = i.unwrap();
    let lam = k.add(&k.from_i64(-1), &i);
    let one = |x| Matrix::from_vec(k.clone(), 1, 1, vec![x]);
    let ss = StateSpace::new(one(lam), one(k.one()), one(k.one()), one(k.zero())).unwrap();
    let cs = contributions_in(&ss, jordan_over(&ss.a).unwrap()).unwrap();
    assert_eq!(
        cs.modes[0].weight,
        Weight::H2Squared(k.from_rational(&Rational::new(1.into(), 2.into())))
    );
    // an unstable mode over Q(sqrt 2): -1 + sqrt 2 > 0
    let (k2, s2) = qsqrt2();
    let lam = k2.add(&k2.from_i64(-1), &s2.unwrap());
    let one = |x| Matrix::from_vec(k2.clone(), 1, 1, vec![x]);
    let ss = StateSpace::new(one(lam), one(k2.one()), one(k2.one()), one(k2.zero())).unwrap();
    let cs = contributions_in(&ss, jordan_over(&ss.a).unwrap()).unwrap();
    assert_eq!(cs.modes[0].weight, Weight::Infinite);
}

/// `jordan --normalize` over Q(p) without --steps: entry 1 and orthogonal chains, A T = T J
/// and det T != 0 after normalising; the CLI answers (was refused).
#[test]
fn normalize_over_qp_keeps_a_t_equals_t_j() {
    let k = RatFuncField::new(&["a", "b"]).unwrap();
    // a Jordan block of a (size 2), an eigenvalue b, a quadratic factor s^2 + a (primary block)
    let j = rf(
        &k,
        &[
            &["a", "1", "0", "0", "0"],
            &["0", "a", "0", "0", "0"],
            &["0", "0", "b", "0", "0"],
            &["0", "0", "0", "0", "1"],
            &["0", "0", "0", "-a", "0"],
        ],
    );
    let t = rf(
        &k,
        &[
            &["1", "b", "0", "1", "0"],
            &["0", "1", "a", "0", "0"],
            &["0", "0", "1", "0", "1"],
            &["0", "0", "0", "1", "b"],
            &["0", "0", "0", "0", "1"],
        ],
    );
    let a = &(&t * &j) * &t.inverse().unwrap();
    for how in ["entry", "orth", "orth,entry:2", "unit"] {
        let how: Normalization = how.parse().unwrap();
        let mut jf = jordan_qp(&a).unwrap();
        normalize_form_qp(&mut jf, &how).unwrap();
        assert!(jf.verified, "{how:?}");
        let (tt, jj) = jf.primary_form().unwrap();
        assert_eq!(
            &jf.a * &tt,
            &tt * &jj,
            "A T = T J after normalising ({how:?})"
        );
        assert!(!jf.base().is_zero(&tt.det().unwrap()));
        for comp in jf.components.iter().filter(|c| c.degree() == 1) {
            let e = &comp.field;
            let mut off = 0;
            for &s in &comp.blocks {
                let v1 = comp.chains.col(off);
                if how.orthogonal {
                    for jx in 1..s {
                        assert!(e.is_zero(&dot(e, &comp.chains.col(off + jx), &v1)));
                    }
                }
                if matches!(how.scale, exactlti::jordan::normalize::Scale::Entry(_)) {
                    assert!(v1.iter().any(|x| e.is_one(x)), "an entry 1");
                }
                off += s;
            }
        }
    }
    let f = temp_file(
        "steps_modes_fields",
        "sym.json",
        r#"{"A": [["a", 1, 0], [0, "a", 0], [0, 0, "b"]], "B": [[0], [1], [1]], "C": [[1, 0, 1]], "D": [[0]], "symbols": ["a", "b"]}"#,
    );
    let p = f.to_str().unwrap();
    let (code, out, err) = run(&["jordan", p, "--normalize", "orth,entry", "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["verified"], true);
    assert!(v["normalize"].as_str().unwrap().contains("orthogonal"));
    let (code, out, err) = run(&["contributions", p, "--steps", "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("\"holds\": true"));
    let (code, _, err) = run(&["contributions", p, "--keep", "1"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("rational functions"), "{err}");
    let (code, _, err) = run(&[
        "response", p, "--x0", "1, a, 0", "--steps", "--format", "latex",
    ]);
    assert_eq!(code, 0, "{err}");
    let _ = QuadraticField::new(3);
}
