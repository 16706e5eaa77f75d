//! Jordan forms in vehicle dynamics (Minaker): eq. 11-14 (a complex pair and its real
//! 2x2 block), and the single-wheel yaw-plane model eq. 27-37 (three zero roots in ONE 3x3
//! block, s = -cr/(m u), the paper's T of eq. 34, the closed-form response eq. 37).
//!
//! Run: `cargo run --example vehicle_jordan`

use exactlti::field::{Field, Q, Rational};
use exactlti::jordan::jordan;
use exactlti::matrix::Matrix;
use exactlti::qmat;

fn r(n: i64, d: i64) -> Rational {
    Rational::new(n.into(), d.into())
}

fn main() {
    // eq. 11-14
    let a = qmat![[-2, 0, 0], [0, 0, 1], [0, -2, -2]];
    let jf = jordan(&a).expect("jordan");
    let values: Vec<String> = jf
        .eigenvalues
        .iter()
        .map(exactlti::report::sections::eigenvalue_text)
        .collect();
    assert_eq!(values, ["-2", "-1 + i", "-1 - i"]);
    let rf = jf.real_form().expect("real form");
    let (jr, tr) = rf.single_field().expect("over Q");
    println!("eq. 11-14: real J = {jr}, T = {tr}");
    assert_eq!(jr.to_string(), "[[-2, 0, 0], [0, -1, 1], [0, -1, -1]]");
    assert!(rf.verified);

    // eq. 27: m = 1500, u = 20, cr = 80000 (cf = 0, b = 0)
    let (m, u, cr) = (r(1500, 1), r(20, 1), r(80000, 1));
    let s = -(&cr / (&m * &u));
    let z = r(0, 1);
    let a = Matrix::from_rows(
        Q,
        vec![
            vec![z.clone(), u.clone(), r(-1, 1), z.clone()],
            vec![z.clone(), z.clone(), z.clone(), r(-1, 1)],
            vec![z.clone(), z.clone(), s.clone(), -&u],
            vec![z.clone(), z.clone(), z.clone(), z.clone()],
        ],
    )
    .unwrap();
    let jf = jordan(&a).expect("jordan");
    println!("{}", jf.report().to_text());
    let zero = jf
        .eigenvalues
        .iter()
        .find(|e| exactlti::report::sections::eigenvalue_text(e) == "0")
        .unwrap();
    assert_eq!(zero.blocks, [3], "three zeros in one 3x3 block");
    let se = jf
        .eigenvalues
        .iter()
        .find(|e| exactlti::report::sections::eigenvalue_text(e) == "-8/3")
        .unwrap();
    assert_eq!(se.blocks, [1]);
    assert!(jf.verified);
    let (j, t) = jf.single_field().unwrap();
    assert_eq!(&a.convert_to(j.field()) * &t, &t * &j);
    // eq. 34-35: the paper's T is valid for the same J
    let t34 = Matrix::from_rows(
        Q,
        vec![
            vec![r(1, 1), z.clone(), z.clone(), &m * &u / &cr],
            vec![z.clone(), r(1, 1) / &u, &m / &cr, z.clone()],
            vec![z.clone(), z.clone(), &m * &u / &cr, r(1, 1)],
            vec![z.clone(), z.clone(), -(r(1, 1) / &u), z.clone()],
        ],
    )
    .unwrap();
    let mut j35 = qmat![[0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 0], [0, 0, 0, 0]];
    j35.set(3, 3, s.clone());
    assert_eq!(&a * &t34, &t34 * &j35);
    println!("eq. 34 T is a valid transform for eq. 35 J");

    // eq. 37 term by term for the paper's constants (y0, psi0, v0, r0) = (1, 2, 3, 4)
    let (y0, p0, v0, r0) = (r(1, 1), r(2, 1), r(3, 1), r(4, 1));
    let x0 = Matrix::column(
        Q,
        vec![&y0 - &v0 / &s, p0.clone(), &r0 * &u / &s + &v0, r0.clone()],
    );
    let fr = jf.free_response();
    assert!(fr.verify(&jf));
    let ev0 = jf
        .eigenvalues
        .iter()
        .position(|e| exactlti::report::sections::eigenvalue_text(e) == "0")
        .unwrap();
    let evs = jf
        .eigenvalues
        .iter()
        .position(|e| exactlti::report::sections::eigenvalue_text(e) == "-8/3")
        .unwrap();
    let as_q = |v: &Matrix<exactlti::algebraic::NumberField>| -> Vec<Rational> {
        (0..4)
            .map(|i| v.field().to_rational(v.get(i, 0)).unwrap())
            .collect()
    };
    for (power, v) in fr.term_vectors(&jf, ev0, &x0) {
        let want = match power {
            0 => vec![y0.clone(), p0.clone(), &r0 * &u / &s, r0.clone()],
            1 => vec![(&p0 - &r0 / &s) * &u, -&r0, z.clone(), z.clone()],
            _ => vec![-(&r0 * &u) / r(2, 1), z.clone(), z.clone(), z.clone()],
        };
        assert_eq!(as_q(&v), want, "t^{power} e^(0 t) term");
        println!("t^{power} e^(0 t): {v}");
    }
    let (_, v) = &fr.term_vectors(&jf, evs, &x0)[0];
    assert_eq!(as_q(v), [-(&v0 / &s), z.clone(), v0.clone(), z.clone()]);
    println!("e^(s t), s = {s}: {v}");
    println!("eq. 37 reproduced term by term");
}
