//! Jordan decomposition: the papers' examples, properties on planted structures, errors.

use crate::common;
use crate::jcommon;

use exactlti::Error;
use exactlti::algebraic::{NfElem, NumberField};
use exactlti::field::{Field, Q, Rational};
use exactlti::jordan::{JordanForm, jordan};
use exactlti::matrix::Matrix;
use exactlti::poly::Poly;
use exactlti::qmat;
use jcommon::{planted, r, sliding_masses, yaw_plane};

fn blocks_of(jf: &JordanForm, value: &str) -> Vec<usize> {
    jf.eigenvalues
        .iter()
        .find(|e| exactlti::report::sections::eigenvalue_text(e) == value)
        .unwrap_or_else(|| panic!("no eigenvalue {value} in {:?}", values(jf)))
        .blocks
        .clone()
}

fn values(jf: &JordanForm) -> Vec<String> {
    jf.eigenvalues
        .iter()
        .map(exactlti::report::sections::eigenvalue_text)
        .collect()
}

/// Q(sqrt 2) and a + b sqrt 2.
fn qsqrt2() -> NumberField {
    NumberField::new(&Poly::from_i64s(&[-2, 0, 1]), (2f64.sqrt(), 0.0)).unwrap()
}
fn s2(a: Rational, b: Rational) -> NfElem {
    let k = qsqrt2();
    k.add(
        &k.from_rational(&a),
        &k.mul(&k.from_rational(&b), &k.generator()),
    )
}

#[test]
fn vehicle_eq_11_14_complex_pair() {
    let a = qmat![[-2, 0, 0], [0, 0, 1], [0, -2, -2]];
    let jf = jordan(&a).unwrap();
    assert!(jf.verified);
    assert_eq!(values(&jf), ["-2", "-1 + i", "-1 - i"]);
    let (j, t) = jf.single_field().expect("Q(i)");
    assert_eq!(j.field().0.var, "i");
    assert_eq!(&a.convert_to(j.field()) * &t, &t * &j);
    let rf = jf.real_form().unwrap();
    assert!(rf.exact && rf.verified);
    let (jr, tr) = rf.single_field().expect("over Q");
    assert_eq!(jr.to_string(), "[[-2, 0, 0], [0, -1, 1], [0, -1, -1]]");
    assert_eq!(&a.convert_to(jr.field()) * &tr, &tr * &jr);
    // the paper's T (eq. 14, up to the scale 0.41) is valid for the paper's J (eq. 12)
    let tp = qmat![[0, 0, 1], [-1, -1, 0], [2, 0, 0]];
    let jp = qmat![[-1, 1, 0], [-1, -1, 0], [0, 0, -2]];
    assert_eq!(&a * &tp, &tp * &jp);
}

#[test]
fn vehicle_eq_15_17_point_mass_a1_diagonalizable() {
    let a1 = qmat![[0, 0, 1, 0], [0, 0, 0, 1], [0, 0, -1, 0], [0, 0, 0, -1]];
    let jf = jordan(&a1).unwrap();
    assert!(jf.verified);
    assert_eq!(blocks_of(&jf, "0"), [1, 1]);
    assert_eq!(blocks_of(&jf, "-1"), [1, 1]);
    for e in &jf.eigenvalues {
        assert_eq!((e.algebraic_multiplicity, e.geometric_multiplicity), (2, 2));
    }
    // eq. 16-17 over Q(sqrt 2): A1 T = T J, T invertible
    let k = qsqrt2();
    let h = s2(r(0, 1), r(1, 2)); // 1/sqrt 2 = sqrt(2)/2
    let (z, o) = (k.zero(), k.one());
    let t = Matrix::from_rows(
        k.clone(),
        vec![
            vec![o.clone(), z.clone(), k.neg(&h), z.clone()],
            vec![z.clone(), o.clone(), z.clone(), k.neg(&h)],
            vec![z.clone(), z.clone(), h.clone(), z.clone()],
            vec![z.clone(), z.clone(), z.clone(), h.clone()],
        ],
    )
    .unwrap();
    let j = qmat![[0, 0, 0, 0], [0, 0, 0, 0], [0, 0, -1, 0], [0, 0, 0, -1]].convert_to(&k);
    assert_eq!(&a1.convert_to(&k) * &t, &t * &j);
    assert_eq!(t.rank(), 4);
}

#[test]
fn vehicle_eq_18_23_point_mass_a2_two_blocks() {
    let a2 = qmat![[0, 0, 1, 0], [0, 0, 0, 1], [-1, 0, -2, 0], [0, 0, 0, 0]];
    let jf = jordan(&a2).unwrap();
    assert!(jf.verified);
    assert_eq!(blocks_of(&jf, "0"), [2]);
    assert_eq!(blocks_of(&jf, "-1"), [2]);
    for e in &jf.eigenvalues {
        assert_eq!((e.algebraic_multiplicity, e.geometric_multiplicity), (2, 1));
    }
    let (j, t) = jf.single_field().unwrap();
    assert_eq!(&a2.convert_to(j.field()) * &t, &t * &j);
    // eq. 22 (1/2sqrt2 = sqrt(2)/4) is one valid transform for eq. 23
    let k = qsqrt2();
    let h = s2(r(0, 1), r(1, 2));
    let q = s2(r(0, 1), r(1, 4));
    let (z, o) = (k.zero(), k.one());
    let t22 = Matrix::from_rows(
        k.clone(),
        vec![
            vec![z.clone(), z.clone(), h.clone(), q.clone()],
            vec![o.clone(), z.clone(), z.clone(), z.clone()],
            vec![z.clone(), z.clone(), k.neg(&h), q.clone()],
            vec![z.clone(), o.clone(), z.clone(), z.clone()],
        ],
    )
    .unwrap();
    let j23 = qmat![[0, 1, 0, 0], [0, 0, 0, 0], [0, 0, -1, 1], [0, 0, 0, -1]].convert_to(&k);
    assert_eq!(&a2.convert_to(&k) * &t22, &t22 * &j23);
    assert_eq!(t22.rank(), 4);
    // our J has the same structure as eq. 23
    let mut got = jf
        .eigenvalues
        .iter()
        .map(|e| e.blocks.clone())
        .collect::<Vec<_>>();
    got.sort();
    assert_eq!(got, [vec![2], vec![2]]);
}

#[test]
fn vehicle_eq_24_26_yaw_plane_understeer() {
    let a = yaw_plane(
        r(1500, 1),
        r(2500, 1),
        r(6, 5),
        r(7, 5),
        r(80000, 1),
        r(80000, 1),
        r(20, 1),
    );
    let jf = jordan(&a).unwrap();
    assert!(jf.verified);
    let zero = jf
        .eigenvalues
        .iter()
        .find(|e| exactlti::report::sections::eigenvalue_text(e) == "0")
        .unwrap();
    assert_eq!(zero.algebraic_multiplicity, 2);
    let pair: Vec<_> = jf
        .eigenvalues
        .iter()
        .filter(|e| e.approx.1 != 0.0)
        .collect();
    assert_eq!(pair.len(), 2, "understeer: a complex pair");
    assert!(
        pair.iter()
            .all(|e| e.approx.0 < 0.0 && e.minpoly.deg() == 2)
    );
    let rf = jf.real_form().unwrap();
    assert!(rf.exact && rf.verified, "{:?}", rf.notes);
}

/// The vehicle paper's single-wheel yaw plane (eq. 27 with m = 1500, u = 20, cr = 80000,
/// the front axle absent): `(m, u, cr)`, `A` and its Jordan form.
fn single_wheel() -> ((Rational, Rational, Rational), Matrix<Q>, JordanForm) {
    let (m, u, cr) = (r(1500, 1), r(20, 1), r(80000, 1));
    let a = yaw_plane(
        m.clone(),
        r(2500, 1),
        r(6, 5),
        r(0, 1),
        r(0, 1),
        cr.clone(),
        u.clone(),
    );
    let jf = jordan(&a).unwrap();
    ((m, u, cr), a, jf)
}

#[test]
fn vehicle_eq_27_35_single_wheel_three_zeros_one_block() {
    let ((m, u, cr), a, jf) = single_wheel();
    assert!(jf.verified);
    assert_eq!(blocks_of(&jf, "0"), [3]);
    let s = -(&cr / (&m * &u));
    assert_eq!(s, r(-8, 3));
    assert_eq!(blocks_of(&jf, "-8/3"), [1]);
    // the paper's T (eq. 34) is valid for J (eq. 35)
    let t34 = Matrix::from_rows(
        Q,
        vec![
            vec![r(1, 1), r(0, 1), r(0, 1), &m * &u / &cr],
            vec![r(0, 1), r(1, 1) / &u, &m / &cr, r(0, 1)],
            vec![r(0, 1), r(0, 1), &m * &u / &cr, r(1, 1)],
            vec![r(0, 1), r(0, 1), -(r(1, 1) / &u), r(0, 1)],
        ],
    )
    .unwrap();
    let mut j35 = qmat![[0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 0], [0, 0, 0, 0]];
    j35.set(3, 3, s.clone());
    assert_eq!(&a * &t34, &t34 * &j35);
    assert_eq!(t34.rank(), 4);
    // ours: A T = T J exactly, over Q
    let (j, t) = jf.single_field().unwrap();
    assert_eq!(j.field().degree(), 1);
    assert_eq!(&a.convert_to(j.field()) * &t, &t * &j);
}

#[test]
fn vehicle_eq_36_37_free_response_term_by_term() {
    let ((m, u, cr), _, jf) = single_wheel();
    let fr = jf.free_response();
    assert!(fr.verify(&jf));
    let s = -(&cr / (&m * &u));
    // paper constants (y0, psi0, v0, r0) and the initial state they mean (eq. 37 at t = 0)
    for (y0, p0, v0, r0) in [
        (1, 0, 0, 0),
        (0, 1, 0, 0),
        (0, 0, 1, 0),
        (0, 0, 0, 1),
        (3, -2, 5, 7),
    ] {
        let (y0, p0, v0, r0) = (r(y0, 1), r(p0, 1), r(v0, 1), r(r0, 1));
        let x0 = Matrix::column(
            Q,
            vec![&y0 - &v0 / &s, p0.clone(), &r0 * &u / &s + &v0, r0.clone()],
        );
        let ev_zero = jf
            .eigenvalues
            .iter()
            .position(|e| exactlti::report::sections::eigenvalue_text(e) == "0")
            .unwrap();
        let ev_s = jf
            .eigenvalues
            .iter()
            .position(|e| exactlti::report::sections::eigenvalue_text(e) == "-8/3")
            .unwrap();
        let get = |ev: usize, power: usize| -> Vec<Rational> {
            let tv = fr.term_vectors(&jf, ev, &x0);
            let v = tv.iter().find(|(p, _)| *p == power).map(|(_, v)| v.clone());
            match v {
                Some(v) => (0..4)
                    .map(|i| v.field().to_rational(v.get(i, 0)).unwrap())
                    .collect(),
                None => vec![r(0, 1); 4],
            }
        };
        let z = r(0, 1);
        // e^{0t}: (y0, psi0, r0 u / s, r0)
        assert_eq!(
            get(ev_zero, 0),
            [y0.clone(), p0.clone(), &r0 * &u / &s, r0.clone()]
        );
        // t e^{0t}: ((psi0 - r0/s) u, -r0, 0, 0)
        assert_eq!(
            get(ev_zero, 1),
            [(&p0 - &r0 / &s) * &u, -&r0, z.clone(), z.clone()]
        );
        // t^2 e^{0t}: (-r0 u / 2, 0, 0, 0)
        assert_eq!(
            get(ev_zero, 2),
            [-(&r0 * &u) / r(2, 1), z.clone(), z.clone(), z.clone()]
        );
        // e^{st}: (-v0/s, 0, v0, 0)
        assert_eq!(
            get(ev_s, 0),
            [-(&v0 / &s), z.clone(), v0.clone(), z.clone()]
        );
        assert!(get(ev_zero, 3).iter().all(|c| *c == z));
    }
}

#[test]
fn sliding_masses_ten_pairs_diagonalizable() {
    let a = sliding_masses();
    let jf = jordan(&a).unwrap();
    assert!(jf.verified);
    assert_eq!(jf.eigenvalues.len(), 10);
    let mut ims: Vec<f64> = jf.eigenvalues.iter().map(|e| e.approx.1).collect();
    ims.sort_by(f64::total_cmp);
    let mut want: Vec<f64> = (1..=5)
        .flat_map(|k| {
            let w = (2.0 - 2.0 * (k as f64 * std::f64::consts::PI / 6.0).cos()).sqrt();
            [w, -w]
        })
        .collect();
    want.sort_by(f64::total_cmp);
    for (g, w) in ims.iter().zip(&want) {
        assert!((g - w).abs() < 1e-12, "{g} vs {w}");
    }
    for e in &jf.eigenvalues {
        assert!(e.approx.0 == 0.0, "purely imaginary, exactly");
        assert_eq!(
            e.blocks,
            [1, 1],
            "{}",
            exactlti::report::sections::eigenvalue_text(e)
        );
        assert_eq!((e.algebraic_multiplicity, e.geometric_multiplicity), (2, 2));
    }
    let vals = values(&jf);
    for v in [
        "i*sqrt(2 - sqrt(3))",
        "-i*sqrt(2 + sqrt(3))",
        "i",
        "sqrt(2)*i",
        "-sqrt(3)*i",
    ] {
        assert!(vals.contains(&v.to_string()), "{v} not in {vals:?}");
    }
    let rf = jf.real_form().unwrap();
    assert!(rf.exact && rf.verified, "{:?}", rf.notes);
    let fr = jf.free_response();
    assert!(fr.verify(&jf));
}

#[test]
fn minimal_realization_paper_sec_3_2_examples() {
    // eq. 25-27 of the minimal-realization paper are the vehicle paper's eq. 11-14; the
    // point-mass A2 (eq. 29-32) has two 2x2 blocks
    let a = qmat![[-2, 0, 0], [0, 0, 1], [0, -2, -2]];
    let rf = jordan(&a).unwrap().real_form().unwrap();
    let (j, _) = rf.single_field().unwrap();
    assert!(j.to_string().contains("[0, -1, 1], [0, -1, -1]"));
    let a2 = qmat![[0, 0, 1, 0], [0, 0, 0, 1], [-1, 0, -2, 0], [0, 0, 0, 0]];
    let jf = jordan(&a2).unwrap();
    assert!(jf.eigenvalues.iter().all(|e| e.blocks == [2]));
}

#[test]
fn planted_structures_properties() {
    for seed in 0..common::iters(6) as u64 {
        let n = 3 + (seed as usize % 6);
        let (a, blocks) = planted(n, seed + 11);
        let jf = jordan(&a).unwrap();
        assert!(jf.verified, "A = {a}");
        for e in &jf.eigenvalues {
            let lam = Q.to_rational(&-e.minpoly.coeff(0)).unwrap();
            let mut want: Vec<usize> = blocks
                .iter()
                .filter(|(l, _)| *l == lam)
                .map(|(_, k)| *k)
                .collect();
            want.sort_by(|x, y| y.cmp(x));
            assert_eq!(e.blocks, want, "A = {a}");
        }
        let (j, t) = jf.single_field().unwrap();
        assert_eq!(&a.convert_to(j.field()) * &t, &t * &j, "A = {a}");
        assert!(jf.free_response().verify(&jf));
        // deterministic
        assert_eq!(jordan(&a).unwrap(), jf);
    }
}

#[test]
fn irrational_cases_are_exact_and_explicit() {
    // companion of x^3 - 2: one real cube root and a complex pair with Re != 0
    let a = qmat![[0, 1, 0], [0, 0, 1], [2, 0, 0]];
    let jf = jordan(&a).unwrap();
    assert!(jf.verified);
    assert!(jf.single_field().is_none());
    let rep = jf.report().to_json();
    assert!(!rep["T"][0][0].as_str().unwrap().is_empty());
    assert_eq!(rep["verified"], true);
    let rf = jf.real_form().unwrap();
    assert!(
        rf.exact && rf.verified && rf.notes.is_empty(),
        "{:?}",
        rf.notes
    );
    // golden ratio: Q(sqrt 5)
    let g = qmat![[1, 1], [1, 0]];
    let jf = jordan(&g).unwrap();
    assert!(
        values(&jf).contains(&"1/2 + sqrt(5)/2".to_string()),
        "{:?}",
        values(&jf)
    );
    assert!(jf.single_field().is_some() && jf.verified);
}

#[test]
fn report_keys_follow_the_contract() {
    let a = qmat![[0, 0, 1, 0], [0, 0, 0, 1], [-1, 0, -2, 0], [0, 0, 0, 0]];
    let js = jordan(&a).unwrap().report().to_json();
    for key in ["eigenvalues", "J", "T", "J_approx", "T_approx", "verified"] {
        assert!(js.get(key).is_some(), "missing {key}: {js}");
    }
    let e = &js["eigenvalues"][0];
    for key in [
        "minpoly",
        "value",
        "approx",
        "algebraic_multiplicity",
        "geometric_multiplicity",
        "blocks",
    ] {
        assert!(e.get(key).is_some(), "missing {key}: {e}");
    }
    let rj = jordan(&qmat![[-2, 0, 0], [0, 0, 1], [0, -2, -2]])
        .unwrap()
        .real_form()
        .unwrap()
        .report()
        .to_json();
    assert_eq!(rj["verified"], true);
    assert_eq!(rj["J"][1][2], "1");
}

#[test]
fn bad_input_and_edge_shapes() {
    let ns = Matrix::<Q>::zeros(Q, 2, 3);
    assert!(matches!(jordan(&ns), Err(Error::NotSquare { .. })));
    let empty = Matrix::<Q>::zeros(Q, 0, 0);
    let jf = jordan(&empty).unwrap();
    assert!(jf.verified && jf.eigenvalues.is_empty());
    let one = qmat![[5]];
    let jf = jordan(&one).unwrap();
    assert_eq!(values(&jf), ["5"]);
}

/// Every block of the real form exact, verified in its own field, the pair blocks of the
/// papers' shape, and the whole real `T` invertible (its approximation well conditioned).
fn check_real_form_exact(a: &Matrix<Q>) -> exactlti::jordan::RealJordanForm {
    let jf = jordan(a).unwrap();
    assert!(jf.verified, "A = {a}");
    let rf = jf.real_form_expanded().unwrap();
    assert!(
        rf.exact && rf.verified && rf.notes.is_empty(),
        "{:?}",
        rf.notes
    );
    let n = a.nrows();
    let mut cols = 0;
    for b in &rf.blocks {
        let (f, t, j) = b.exact_entries().unwrap();
        assert_eq!(f.root_approx().1, 0.0, "a real field");
        assert_eq!(&a.convert_to(f) * t, t * j, "A T = T J in {f}");
        let e = &jf.eigenvalues[b.eigenvalue];
        if b.pair {
            // [[a, b], [-b, a]] with the eigenvalue's parts, I2 coupling
            let m = j.nrows();
            for d in (0..m).step_by(2) {
                assert_eq!(j.get(d, d), j.get(d + 1, d + 1));
                assert_eq!(*j.get(d + 1, d), f.neg(j.get(d, d + 1)));
                if d + 2 < m && j.get(d, d + 2) != &f.zero() {
                    assert!(f.is_one(j.get(d, d + 2)) && f.is_one(j.get(d + 1, d + 3)));
                }
            }
            let (re, _) = f.approx(j.get(0, 0));
            let (im, _) = f.approx(j.get(0, 1));
            assert!((re - e.approx.0).abs() < 1e-9 && (im - e.approx.1).abs() < 1e-9);
            assert!(e.approx.1 > 0.0);
        }
        cols += t.ncols();
    }
    assert_eq!(cols, n);
    let t_all = rf
        .single_field()
        .map(|(_, t)| t.to_approx())
        .unwrap_or_else(|| {
            let (_, to) = rf.j_t_out();
            to.approx
                .iter()
                .map(|row| row.iter().map(|z| z.0).collect())
                .collect()
        });
    let tm = nalgebra::DMatrix::from_fn(n, n, |i, j| t_all[i][j]);
    let sv = tm.singular_values();
    assert!(sv.min() > 1e-8 * sv.max(), "real T singular: {sv}");
    rf
}

#[test]
fn real_form_exact_cube_root_of_two() {
    let a = jcommon::companion(&[-2, 0, 0, 1]);
    let rf = check_real_form_exact(&a);
    let jf = jordan(&a).unwrap();
    // certified approximations
    let real = jf.eigenvalues.iter().find(|e| e.approx.1 == 0.0).unwrap();
    assert!((real.approx.0 - 2f64.cbrt()).abs() <= 4.0 * f64::EPSILON);
    let up = jf.eigenvalues.iter().find(|e| e.approx.1 > 0.0).unwrap();
    assert!((up.approx.0 + 2f64.cbrt() / 2.0).abs() < 1e-15);
    assert!((up.approx.1 - 2f64.cbrt() * 3f64.sqrt() / 2.0).abs() < 1e-15);
    assert_eq!(up.number.minpoly().to_string(), "x^3 - 2");
    // Q(Re, Im) = Q(cbrt 2, sqrt 3) has degree 6
    let pair = rf.blocks.iter().find(|b| b.pair).unwrap();
    assert_eq!(pair.exact_entries().unwrap().0.degree(), 6);
    let rep = rf.report().to_json();
    assert_eq!(rep["exact"], true);
    assert_eq!(rep["verified"], true);
    assert!(rep["parts"][0].as_str().unwrap().starts_with("r"), "{rep}");
    assert!(rep["fields"].as_array().unwrap().len() >= 2, "{rep}");
    assert!(!rep["J"][1][1].as_str().unwrap().starts_with('~'));
}

#[test]
fn real_form_exact_cube_root_chain_of_length_two() {
    let a = jcommon::companion_pair_chain(&[-2, 0, 0, 1], 7);
    let jf = jordan(&a).unwrap();
    assert!(jf.verified);
    assert_eq!(jf.charpoly.to_string(), "x^6 - 4*x^3 + 4");
    for e in &jf.eigenvalues {
        assert_eq!(
            e.blocks,
            [2],
            "{}",
            exactlti::report::sections::eigenvalue_text(e)
        );
    }
    let rf = check_real_form_exact(&a);
    let pair = rf.blocks.iter().find(|b| b.pair).unwrap();
    let (f, _, j) = pair.exact_entries().unwrap();
    assert_eq!(j.nrows(), 4, "one 4x4 block: a 2x2 complex block pair");
    assert!(f.is_one(j.get(0, 2)) && f.is_one(j.get(1, 3)) && f.is_zero(j.get(0, 3)));
}

#[test]
fn real_form_exact_quartic_two_complex_pairs() {
    let a = jcommon::companion(&[1, 1, 0, 0, 1]);
    let rf = check_real_form_exact(&a);
    assert_eq!(rf.blocks.len(), 2);
    assert!(rf.blocks.iter().all(|b| b.pair));
    // purely imaginary factor with a quadratic real field: x^4 + 6 x^2 + 1, roots
    // +-i (sqrt 2 +- 1)
    let rf = check_real_form_exact(&jcommon::companion(&[1, 0, 6, 0, 1]));
    let (j, _) = rf.single_field().expect("all in Q(sqrt 2)");
    assert!(j.to_string().contains("sqrt(2)"), "{j}");
}

#[test]
fn real_form_exact_random_complex_factors() {
    let mut rng = common::Rng(2024);
    let mut done = 0;
    while done < common::iters(4) {
        let deg = [3, 3, 4][rng.int(0, 2) as usize];
        let mut p: Vec<i64> = (0..deg).map(|_| rng.int(-3, 3)).collect();
        p.push(1);
        let poly = Poly::from_i64s(&p);
        if !exactlti::algebraic::is_irreducible_q(&poly) {
            continue;
        }
        let a = jcommon::companion(&p);
        let jf = jordan(&a).unwrap();
        if jf.eigenvalues.iter().all(|e| e.approx.1 == 0.0) {
            continue;
        }
        // the certified approximations are roots to f64 accuracy
        for e in &jf.eigenvalues {
            let z = num_complex::Complex64::new(e.approx.0, e.approx.1);
            let v = p
                .iter()
                .rev()
                .fold(num_complex::Complex64::new(0.0, 0.0), |acc, &c| {
                    acc * z + c as f64
                });
            assert!(v.norm() < 1e-9 * (1.0 + z.norm()).powi(deg), "{p:?}: {z}");
        }
        check_real_form_exact(&a);
        done += 1;
    }
}

#[test]
fn quadratic_input_rational_entries_or_explicit_unsupported() {
    use exactlti::field::QuadraticField;
    use exactlti::jordan::jordan_quadratic;
    let k = QuadraticField::new(3).unwrap();
    let a = qmat![[-2, 0, 0], [0, 0, 1], [0, -2, -2]];
    let ak = Matrix::from_fn(k.clone(), 3, 3, |i, j| k.from_rational(a.get(i, j)));
    assert_eq!(jordan_quadratic(&ak).unwrap(), jordan(&a).unwrap());
    let mut bk = ak.clone();
    bk.set(0, 0, k.gen_elem());
    match jordan_quadratic(&bk) {
        Err(Error::Unsupported(m)) => assert!(m.contains("not rational"), "{m}"),
        other => panic!("expected Unsupported, got {other:?}"),
    }
    let ns = Matrix::zeros(k.clone(), 2, 3);
    assert!(matches!(
        jordan_quadratic(&ns),
        Err(Error::NotSquare { .. })
    ));
}

/// `--expand` is bounded: the pair of a sextic (x^6 - x + 1, real field of degree up to 30,
/// 16 s to build) stays in the compact exact form with a note naming the bound, and the
/// form is still exact and verified; a quintic (real field of degree 20) is expanded.
#[test]
fn real_form_expand_stops_at_the_eigenvalue_degree_bound() {
    use exactlti::jordan::real::EXPAND_MAX_EIGENVALUE_DEGREE;
    assert_eq!(EXPAND_MAX_EIGENVALUE_DEGREE, 5);
    let companion = |last: [i64; 2], n: usize| {
        let mut a = Matrix::zeros(Q, n, n);
        for i in 0..n - 1 {
            a.set(i, i + 1, Rational::from_integer(1.into()));
        }
        a.set(n - 1, 0, Rational::from_integer(last[0].into()));
        a.set(n - 1, 1, Rational::from_integer(last[1].into()));
        a
    };
    let sextic = jordan(&companion([-1, 1], 6)).unwrap();
    let rf = sextic.real_form_expanded().unwrap();
    assert!(rf.verified, "{:?}", rf.notes);
    let pairs: Vec<_> = rf.blocks.iter().filter(|b| b.pair).collect();
    assert_eq!(pairs.len(), 3);
    assert!(
        pairs
            .iter()
            .all(|b| b.compact().is_some() && b.exact_entries().is_none())
    );
    let notes = rf.note_lines();
    assert_eq!(notes.len(), 3, "{notes:?}");
    assert!(notes[0].contains("degree 6") && notes[0].contains("up to 30"));
    let quintic = jordan(&companion([1, 1], 5)).unwrap();
    let rf = quintic.real_form_expanded().unwrap();
    assert!(
        rf.exact && rf.verified && rf.notes.is_empty(),
        "{:?}",
        rf.notes
    );
    assert!(
        rf.blocks
            .iter()
            .filter(|b| b.pair)
            .all(|b| b.exact_entries().is_some())
    );
}

/// The free response report carries its check (`verified`: A G_k = θ G_k + (k+1) G_{k+1}
/// and the traces of G_0 sum to I), as over K; a tampered term is reported unverified, and
/// `analyze` prints the section's `verified` for an everyday model with complex pairs.
#[test]
fn free_response_report_is_verified_and_a_tampered_term_is_not() {
    use exactlti::report::Value;
    let a = qmat![[0, 1, 0], [-2, -1, 1], [0, 0, -3]];
    let jf = jordan(&a).unwrap();
    let fr = jf.free_response();
    let rep = fr.report(&jf);
    assert_eq!(rep.get("verified"), Some(&Value::Bool(true)));
    let mut bad = fr.clone();
    let c = &mut bad.terms[0].coeff;
    let one = c.field().one();
    let x = c.field().add(c.get(0, 0), &one);
    c.set(0, 0, x);
    assert_eq!(bad.report(&jf).get("verified"), Some(&Value::Bool(false)));
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_exactlti"))
        .args([
            "analyze",
            "tests/data/everyday/quarter_car.json",
            "--format",
            "json",
        ])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let out = String::from_utf8(out.stdout).unwrap();
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["jordan"]["free_response"]["verified"], true);
}
