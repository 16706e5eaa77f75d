//! Bicycle benchmark (Meijaard et al. 2007) as the EoM-like 7x7 descriptor system of the
//! minimal-realizations paper, sec. 4.2: 7 -> 6 (standard form) -> 4 (minimal).
use exactlti::field::{Field, Q, Rational, parse_rational, rational_to_f64};
use exactlti::matrix::Matrix;
use exactlti::realization::{MinrealMethod, descriptor_to_standard, mcmillan_degree, minimal};
use exactlti::system::Descriptor;

fn data() -> serde_json::Value {
    serde_json::from_str(include_str!("../data/bicycle-benchmark.json")).unwrap()
}

fn mat2(v: &serde_json::Value) -> Matrix<Q> {
    Matrix::from_fn(Q, 2, 2, |i, j| {
        parse_rational(v[i][j].as_str().unwrap()).unwrap()
    })
}

fn q(s: &str) -> Rational {
    parse_rational(s).unwrap()
}

/// States: roll, steer, roll rate, steer rate, yaw, lateral position, steer torque (the input
/// appended as a state, E row zero: 0 = -x7 + u).
pub fn bicycle_descriptor(v: &str) -> Descriptor<Q> {
    let d = data();
    let (m, c1, k0, k2) = (
        mat2(&d["M"]),
        mat2(&d["C1"]),
        mat2(&d["K0"]),
        mat2(&d["K2"]),
    );
    let g = q(d["g"].as_str().unwrap());
    let v = q(v);
    let kin = &d["kinematics"];
    let (w, c, cl) = (
        q(kin["w"].as_str().unwrap()),
        q(kin["c"].as_str().unwrap()),
        q(kin["cos_lambda"].as_str().unwrap()),
    );
    let stiff = &k0.scale(&g) + &k2.scale(&(&v * &v));
    let damp = c1.scale(&v);
    let mut e = Matrix::identity(Q, 7);
    e.set_block(2, 2, &m);
    e.set(6, 6, Q.zero());
    let mut a = Matrix::zeros(Q, 7, 7);
    a.set(0, 2, Q.one());
    a.set(1, 3, Q.one());
    a.set_block(2, 0, &-&stiff);
    a.set_block(2, 2, &-&damp);
    a.set(3, 6, Q.one()); // steer torque acts on the steer equation
    a.set(4, 1, &v * &cl / &w); // yaw rate = (v delta + c delta') cos(lambda) / w
    a.set(4, 3, &c * &cl / &w);
    a.set(5, 4, v.clone()); // lateral velocity = v psi
    a.set(6, 6, -Q.one());
    let mut b = Matrix::zeros(Q, 7, 1);
    b.set(6, 0, Q.one());
    let mut cm = Matrix::zeros(Q, 2, 7);
    cm.set(0, 0, Q.one());
    cm.set(1, 1, Q.one());
    Descriptor::new(e, a, b, cm, Matrix::zeros(Q, 2, 1)).unwrap()
}

#[test]
fn bicycle_7_to_6_to_4_at_2_and_8_mps() {
    for v in ["2", "8"] {
        let desc = bicycle_descriptor(v);
        let sf = descriptor_to_standard(&desc).unwrap();
        assert_eq!(sf.system.nstates(), 6, "v = {v}");
        assert_eq!(sf.removed_infinite, 1);
        assert!(sf.verified);
        assert_eq!(mcmillan_degree(&sf.system), 4);
        for m in [
            MinrealMethod::Kalman,
            MinrealMethod::Rosenbrock,
            MinrealMethod::HoKalman,
        ] {
            let r = minimal(&sf.system, m).unwrap();
            assert_eq!(r.order, 4, "v = {v}, {m:?}");
            assert!(r.verified);
        }
    }
}

#[test]
fn bicycle_eigenvalues_at_2_mps_match_paper_eq_51() {
    let sf = descriptor_to_standard(&bicycle_descriptor("2")).unwrap();
    let r = minimal(&sf.system, MinrealMethod::Kalman).unwrap();
    let p = r.system.a.charpoly().unwrap();
    // certified real roots by exact sign changes: -8.674 and -3.072 (to 3 decimals)
    for (lo, hi) in [("-8.6745", "-8.6735"), ("-3.0725", "-3.0715")] {
        let (a, b) = (p.eval(&q(lo)), p.eval(&q(hi)));
        assert!(
            &a * &b < Rational::from_integer(0.into()),
            "root in [{lo}, {hi}]"
        );
    }
    // the complex pair from trace and determinant: re = (tr - r1 - r2)/2, |lambda|^2 = det/(r1 r2)
    let tr = rational_to_f64(&(0..4).fold(Q.zero(), |s, i| s + r.system.a.get(i, i)));
    let det = rational_to_f64(&r.system.a.det().unwrap());
    let (r1, r2) = (-8.674_f64, -3.072_f64);
    let re = (tr - r1 - r2) / 2.0;
    let im = (det / (r1 * r2) - re * re).sqrt();
    assert!((re - 2.682).abs() < 2e-3, "re = {re}");
    assert!((im - 1.681).abs() < 2e-3, "im = {im}");
}
