//! ERA on state-space systems (issue 17): the Hankel size grows until the numerical rank is
//! stable, the state matrix is time-scaled so fast modes do not swamp slow ones, and the
//! order agrees with the exact McMillan degree on the paper examples.

use crate::common;

use exactlti::field::Q;
use exactlti::float::{HANKEL_ENTRY_LIMIT, Tol, Truth, era_system, markov_parameters, to_dmatrix};
use exactlti::matrix::Matrix;
use exactlti::realization::mcmillan_degree;
use exactlti::system::StateSpace;
use nalgebra::DMatrix;

fn float_sys(s: &StateSpace<Q>) -> [DMatrix<f64>; 4] {
    [
        to_dmatrix(&s.a).unwrap(),
        to_dmatrix(&s.b).unwrap(),
        to_dmatrix(&s.c).unwrap(),
        to_dmatrix(&s.d).unwrap(),
    ]
}

/// An exact decimal such as "-0.85035641456978".
fn q(s: &str) -> exactlti::field::Rational {
    let (neg, t) = s.strip_prefix('-').map_or((false, s), |t| (true, t));
    let (int, frac) = t.split_once('.').unwrap_or((t, ""));
    let digits: exactlti::field::Rational = format!("{int}{frac}0").parse().unwrap();
    let den: exactlti::field::Rational = format!("1{}0", "0".repeat(frac.len())).parse().unwrap();
    let v = &digits / &den;
    if neg { -v } else { v }
}

fn mat(rows: &[&[&str]]) -> Matrix<Q> {
    Matrix::from_rows(
        Q,
        rows.iter()
            .map(|r| r.iter().map(|x| q(x)).collect())
            .collect(),
    )
    .unwrap()
}

/// ERA order equals the exact McMillan degree, and its Markov parameters match.
fn assert_era_order(s: &StateSpace<Q>, what: &str) {
    let exact = mcmillan_degree(s);
    let [a, b, c, d] = float_sys(s);
    let r = era_system(&a, &b, &c, &d, None, &Tol::default()).unwrap();
    assert_eq!(r.realization.order, exact, "{what}: ranks {:?}", r.ranks);
    assert!(r.stabilised, "{what}");
    // Markov parameters of the ERA realization against the original's (relative)
    let k = 2 * exact + 2;
    let h0 = markov_parameters(&a, &b, &c, &d, k).unwrap();
    let e = &r.realization;
    let h1 = markov_parameters(&e.a, &e.b, &e.c, &e.d, k).unwrap();
    let scale = h0.iter().map(|x| x.amax()).fold(0.0, f64::max);
    for (i, (x, y)) in h0.iter().zip(&h1).enumerate() {
        assert!(
            (x - y).amax() <= 1e-6 * scale,
            "{what}: Markov parameter {i}: {x} vs {y}"
        );
    }
}

#[test]
fn sliding_masses_order_8() {
    assert_era_order(&common::systems::sliding_masses(), "sliding masses");
}

#[test]
fn damped_quarter_car_order_4() {
    // states [zs, zu, zs', zu'], input road displacement, output body acceleration and
    // suspension travel; ms = 300, mu = 40, ks = 16000, cs = 1000, kt = 190000
    let (ms, mu, ks, cs, kt) = (q("300"), q("40"), q("16000"), q("1000"), q("190000"));
    let z = q("0");
    let one = q("1");
    let a = Matrix::from_rows(
        Q,
        vec![
            vec![z.clone(), z.clone(), one.clone(), z.clone()],
            vec![z.clone(), z.clone(), z.clone(), one.clone()],
            vec![-&ks / &ms, &ks / &ms, -&cs / &ms, &cs / &ms],
            vec![&ks / &mu, -(&ks + &kt) / &mu, &cs / &mu, -&cs / &mu],
        ],
    )
    .unwrap();
    let b = Matrix::from_rows(
        Q,
        vec![
            vec![z.clone()],
            vec![z.clone()],
            vec![z.clone()],
            vec![&kt / &mu],
        ],
    )
    .unwrap();
    let c = Matrix::from_rows(
        Q,
        vec![
            vec![-&ks / &ms, &ks / &ms, -&cs / &ms, &cs / &ms],
            vec![one.clone(), -&one, z.clone(), z.clone()],
        ],
    )
    .unwrap();
    let s = StateSpace::new_strictly_proper(a, b, c).unwrap();
    assert_eq!(mcmillan_degree(&s), 4);
    assert_era_order(&s, "quarter car");
}

#[test]
fn bicycle_at_8_mps_order_4() {
    // Meijaard et al. benchmark: M q'' + v C1 q' + (g K0 + v^2 K2) q = f, v = 8
    let m = mat(&[
        &["80.81722", "2.31941332208709"],
        &["2.31941332208709", "0.29784188199686"],
    ]);
    let c1 = mat(&[
        &["0", "33.86641391492494"],
        &["-0.85035641456978", "1.68540397397560"],
    ]);
    let k0 = mat(&[
        &["-80.95", "-2.59951685249872"],
        &["-2.59951685249872", "-0.80329488458618"],
    ]);
    let k2 = mat(&[&["0", "76.59734589573222"], &["0", "2.65431523794604"]]);
    let (g, v) = (q("9.81"), q("8"));
    let minv = m.inverse().unwrap();
    let stiff = &k0.scale(&g) + &k2.scale(&(&v * &v));
    let damp = c1.scale(&v);
    let mut a = Matrix::zeros(Q, 4, 4);
    a.set_block(0, 2, &Matrix::identity(Q, 2));
    a.set_block(2, 0, &-&(&minv * &stiff));
    a.set_block(2, 2, &-&(&minv * &damp));
    let mut b = Matrix::zeros(Q, 4, 2);
    b.set_block(2, 0, &minv);
    let mut c = Matrix::zeros(Q, 2, 4);
    c.set_block(0, 0, &Matrix::identity(Q, 2));
    let s = StateSpace::new_strictly_proper(a, b, c).unwrap();
    assert_era_order(&s, "bicycle 8 m/s");
}

#[test]
fn fixed_hankel_size_is_used() {
    let s = common::systems::sliding_masses();
    let [a, b, c, d] = float_sys(&s);
    let r = era_system(&a, &b, &c, &d, Some(12), &Tol::default()).unwrap();
    assert_eq!(r.ranks, vec![(12, 8), (13, 8), (14, 8)]);
    assert_eq!(r.realization.hankel_blocks, (12, 12));
    assert!(r.stabilised);
    assert_eq!(r.realization.truth, Truth::True);
    // a Hankel matrix too small to show the degree (rank 4 of 8) is never True
    let r = era_system(&a, &b, &c, &d, Some(5), &Tol::default()).unwrap();
    assert_eq!(r.realization.order, 4);
    assert!(!r.stabilised);
    assert_ne!(r.realization.truth, Truth::True);
}

#[test]
fn wide_systems_are_sized_by_need_and_refused_beyond_the_limit() {
    // A = [-1], B = 1 x 20000 ones, C = 200 x 1 ones: the 12.8 GB case of the issue
    let a = DMatrix::from_element(1, 1, -1.0);
    let b = DMatrix::from_element(1, 20000, 1.0);
    let c = DMatrix::from_element(200, 1, 1.0);
    let d = DMatrix::zeros(200, 20000);
    match era_system(&a, &b, &c, &d, None, &Tol::default()) {
        Err(exactlti::Error::Limit(msg)) => assert!(msg.contains("Hankel"), "{msg}"),
        other => panic!("expected a Limit error, got {:?}", other.map(|r| r.ranks)),
    }
    // a wide system within the limit: 2 x 3000 inputs, order 1 through the transposed SVD
    let b = DMatrix::from_element(1, 3000, 1.0);
    let c = DMatrix::from_element(2, 1, 1.0);
    let d = DMatrix::zeros(2, 3000);
    const { assert!(2 * 3 * 3000 * 3 <= HANKEL_ENTRY_LIMIT) };
    let r = era_system(&a, &b, &c, &d, None, &Tol::default()).unwrap();
    assert_eq!(r.realization.order, 1);
    assert!((r.realization.a[(0, 0)] + 1.0).abs() < 1e-12);
}

/// Found by the fuzzer: an entry 1e300 in the yaw-plane A.
#[rustfmt::skip]
fn huge_yaw_a() -> DMatrix<f64> {
    DMatrix::from_row_slice(4, 4, &[
        0.0, 20.0, -1.0, 0.0,
        0.0, 0.0, 1e300, -1.0,
        0.0, 0.0, -80000.0 / 30000.0, -20.0,
        0.0, 0.0, 0.0, 0.0,
    ])
}

#[test]
fn huge_entries_do_not_hang() {
    let a = huge_yaw_a();
    let b = DMatrix::from_row_slice(4, 1, &[0.0, 0.0, 1.0 / 1500.0, 0.0]);
    let c = DMatrix::from_row_slice(1, 4, &[1.0, 0.0, 0.0, 0.0]);
    let d = DMatrix::zeros(1, 1);
    let r = era_system(&a, &b, &c, &d, None, &Tol::default());
    if let Ok(r) = r {
        assert_ne!(r.realization.truth, Truth::True, "{:?}", r.ranks);
    }
}

#[test]
fn huge_entries_eigenvalues_do_not_hang() {
    let a = huge_yaw_a();
    let _ = exactlti::float::eigenvalues(&a);
}
