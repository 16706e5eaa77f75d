//! EoM's simple examples as model files (issue 26): the bounce-pitch model and the pendulum,
//! each against its equations of motion derived by hand (Lagrange), exactly: equal Markov
//! parameters up to the sum of the orders, hence equal transfer matrices.

use exactlti::field::{Field, Q, Rational};
use exactlti::io::{TypedAny, load_system_path};
use exactlti::matrix::Matrix;
use exactlti::ratfunc::RatFuncField;
use exactlti::system::StateSpace;
use std::path::Path;

/// $M q'' + L q' + K q = F u + F_r u'$, $y = C_q q$ as a state space with
/// $x = [q;\ q' - M^{-1}F_r u]$: $A = [0, I; -M^{-1}K, -M^{-1}L]$,
/// $B = [M^{-1}F_r;\ M^{-1}(F - L M^{-1}F_r)]$, $C = [C_q, 0]$, $D = C_q M^{-1} F_r \cdot 0$.
fn with_input_rate<K: Field>(
    m: &Matrix<K>,
    l: &Matrix<K>,
    kk: &Matrix<K>,
    f: &Matrix<K>,
    fr: &Matrix<K>,
    cq: &Matrix<K>,
) -> StateSpace<K> {
    let k = m.field().clone();
    let n = m.nrows();
    let mi = m.inverse().unwrap();
    let b1 = &mi * fr;
    let b2 = &mi * &(f - &(l * &b1));
    let top = Matrix::zeros(k.clone(), n, n).hstack(&Matrix::identity(k.clone(), n));
    let bottom = (-&(&mi * kk)).hstack(&-&(&mi * l));
    let a = top.unwrap().vstack(&bottom.unwrap()).unwrap();
    let c = cq.hstack(&Matrix::zeros(k.clone(), cq.nrows(), n)).unwrap();
    let d = Matrix::zeros(k, cq.nrows(), f.ncols());
    StateSpace::new(a, b1.vstack(&b2).unwrap(), c, d).unwrap()
}

fn q(s: &str) -> Rational {
    s.parse::<Rational>().unwrap_or_else(|_| {
        let (n, d) = s.split_once('/').unwrap();
        Rational::new(n.parse().unwrap(), d.parse().unwrap())
    })
}

/// Bounce-pitch with EoM's values: heave z and pitch theta (about y, so a point x ahead of
/// the centre of mass rises by z - x theta); suspension forces at x = a and x = -b.
#[test]
fn bounce_pitch_equals_hand_equations() {
    let l = load_system_path(Path::new("data/models/bounce-pitch.toml")).unwrap();
    let t = l.rational().expect("over Q").clone();
    let d = t.descriptor.as_ref().unwrap();
    // 12 body coordinates -> 2 positions, 2 velocities, 2 inputs
    assert_eq!(d.e.shape(), (6, 6));
    assert_eq!(t.ss.nstates(), 4);
    let (a, b) = (q("1189/1000"), q("1696/1000"));
    let (kf, kr, cf, cr) = (q("35000"), q("38000"), q("1000"), q("1200"));
    let (m, iy) = (q("16975") / q("981/100"), q("3267"));
    let qm = |rows: Vec<Vec<Rational>>| Matrix::from_rows(Q, rows).unwrap();
    let z = q("0");
    let mm = qm(vec![vec![m, z.clone()], vec![z.clone(), iy]]);
    let coupling = |kf: &Rational, kr: &Rational| {
        qm(vec![
            vec![kf + kr, -(&a * kf) + &b * kr],
            vec![-(&a * kf) + &b * kr, &a * &a * kf + &b * &b * kr],
        ])
    };
    let kk = coupling(&kf, &kr);
    let ll = coupling(&cf, &cr);
    let f = qm(vec![
        vec![kf.clone(), kr.clone()],
        vec![-(&a * &kf), &b * &kr],
    ]);
    let fr = qm(vec![
        vec![cf.clone(), cr.clone()],
        vec![-(&a * &cf), &b * &cr],
    ]);
    // z_G; the pitch sensor reads along loc1 - loc2 = -y: -(a + b) theta; z_P = z - a/2 theta
    let cq = qm(vec![
        vec![q("1"), z.clone()],
        vec![z.clone(), -(&a + &b)],
        vec![q("1"), -(&a / q("2"))],
    ]);
    let want = with_input_rate(&mm, &ll, &kk, &f, &fr, &cq);
    assert!(t.ss.same_markov(&want, 8));
    // and not the model with the pitch sensor's sign flipped (the check can fail)
    let mut flipped = cq.clone();
    flipped.set(1, 1, &a + &b);
    assert!(
        !t.ss
            .same_markov(&with_input_rate(&mm, &ll, &kk, &f, &fr, &flipped), 8)
    );
}

/// The pendulum over Q(r): lateral motion y and rotation theta about x; the string's
/// lower end moves by y - r theta and the string (tension m g) pulls it back with
/// m g (y - r theta) / l; the weight acting r below the string end adds m g r theta:
/// m y'' + (m g / l)(y - r theta) = Y,
/// Ix theta'' - (m g r / l)(y - r theta) + m g r theta = 0.
#[test]
fn pendulum_equals_hand_equations_over_q_r() {
    let l = load_system_path(Path::new("data/models/pendulum.toml")).unwrap();
    let TypedAny::RatFunc(t) = &l.system else {
        panic!("r is a symbol")
    };
    let k: RatFuncField = t.ss.a.field().clone();
    assert_eq!(k.to_string(), "QQ(r)");
    let p = |s: &str| k.parse(s).unwrap();
    let rows = |r: Vec<Vec<&str>>| {
        Matrix::from_rows(
            k.clone(),
            r.into_iter()
                .map(|row| row.into_iter().map(p).collect())
                .collect(),
        )
        .unwrap()
    };
    let (mg, lg) = ("(10*9807/1000)", "(1/2)");
    let mm = rows(vec![vec!["10", "0"], vec!["0", "11/2 - 10*r^2"]]);
    let kk = rows(vec![
        vec![&format!("{mg}/{lg}"), &format!("-{mg}*r/{lg}")],
        vec![&format!("-{mg}*r/{lg}"), &format!("{mg}*r^2/{lg} + {mg}*r")],
    ]);
    let zero = Matrix::zeros(k.clone(), 2, 2);
    let f = rows(vec![vec!["1"], vec!["0"]]);
    let fr = Matrix::zeros(k.clone(), 2, 1);
    let cq = rows(vec![vec![&format!("{mg}/({lg} + r)"), "0"]]);
    let want = with_input_rate(&mm, &zero, &kk, &f, &fr, &cq);
    assert_eq!(t.ss.nstates(), 4);
    assert!(t.ss.same_markov(&want, 8));
    let g = t.ss.transfer_matrix().unwrap();
    assert_eq!(g.to_strings(), want.transfer_matrix().unwrap().to_strings());
}

/// An acceleration sensor (`order = 3`) on the spring-mass-damper: y = x'' = f - c x' - k x,
/// so G(s) = s^2 / (s^2 + s/5 + 1) with feedthrough 1; the appended algebraic state is
/// eliminated and the states keep the descriptor's names.
#[test]
fn acceleration_sensor_reads_the_second_derivative() {
    let json = r#"{"name": "smd", "parameters": {"m": 1, "c": 0.2, "k": 1},
      "bodies": [{"name": "block", "mass": "m", "location": [0, 0, 0]}],
      "flex_points": [{"name": "spring", "bodies": ["block", "ground"], "location": [0, 0, 0],
                       "forces": 1, "axis": [0, 0, 1], "stiffness": "k", "damping": "c"}],
      "rigid_points": [{"name": "slider", "bodies": ["block", "ground"], "location": [0, 0, 0],
                        "forces": 2, "moments": 3, "axis": [0, 0, 1]}],
      "actuators": [{"name": "f", "bodies": ["block", "ground"], "locations": [[0, 0, 0], [0, 0, -0.1]]}],
      "sensors": [{"name": "a", "order": 3, "bodies": ["block", "ground"], "locations": [[0, 0, 0], [0, 0, -0.1]]}]}"#;
    let l =
        exactlti::io::load_system_str(json, exactlti::io::SystemFormat::Json, "a.json").unwrap();
    let t = l.rational().unwrap();
    assert_eq!(t.descriptor.as_ref().unwrap().e.shape(), (4, 4));
    let qm = |rows: Vec<Vec<&str>>| {
        Matrix::from_rows(
            Q,
            rows.into_iter()
                .map(|r| r.into_iter().map(q).collect())
                .collect(),
        )
        .unwrap()
    };
    let want = StateSpace::new(
        qm(vec![vec!["0", "1"], vec!["-1", "-1/5"]]),
        qm(vec![vec!["0"], vec!["1"]]),
        qm(vec![vec!["-1", "-1/5"]]),
        qm(vec![vec!["1"]]),
    )
    .unwrap();
    assert!(t.ss.same_markov(&want, 6));
    let names = l
        .file
        .signals
        .states
        .clone()
        .expect("the descriptor's own states");
    assert_eq!(names, ["block.z", "v.block.z"]);
    // order 4 is refused with its key
    let bad = json.replace("\"order\": 3", "\"order\": 4");
    let e = exactlti::io::load_system_str(&bad, exactlti::io::SystemFormat::Json, "a.json")
        .unwrap_err()
        .to_string();
    assert!(e.contains("sensors[1].order"), "{e}");
}

/// The descriptor-level loader (`tf`, `pencil`) names the channels of a model file by its
/// actuators and sensors.
#[test]
fn model_channels_are_named() {
    let l = exactlti::io::load_descriptor::load_descriptor_path(Path::new(
        "data/models/quarter-car-a-arm-pushrod.toml",
    ))
    .unwrap();
    assert_eq!(l.signals.inputs.as_deref(), Some(&["z_g".to_string()][..]));
    assert_eq!(
        l.signals.outputs.clone().unwrap(),
        ["chassis motion", "suspension travel", "tire compression"]
    );
}

/// The benchmark bicycle (Table 2) from its bodies, joints and rolling contacts: at every
/// speed its finite nonzero eigenvalues are those of Meijaard et al.'s
/// M q'' + v C1 q' + (g K0 + v^2 K2) q = f (data/bicycle-benchmark.json, 14 decimals), and
/// the McMillan degree is 4 (paper sec. 4.2).
#[test]
fn bicycle_matches_the_benchmark_eigenvalues() {
    use exactlti::io::symbolic::SymbolicOptions;
    let text = std::fs::read_to_string("data/models/bicycle.toml").unwrap();
    let bench: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string("data/bicycle-benchmark.json").unwrap())
            .unwrap();
    let mat = |key: &str| -> nalgebra::DMatrix<f64> {
        let rows = bench[key].as_array().unwrap();
        nalgebra::DMatrix::from_fn(2, 2, |i, j| {
            rows[i][j].as_str().unwrap().parse::<f64>().unwrap()
        })
    };
    let (m, c1, k0, k2) = (mat("M"), mat("C1"), mat("K0"), mat("K2"));
    for v in [2i64, 5, 8] {
        let opts = SymbolicOptions {
            symbolic: None,
            at: vec![("u".into(), v.to_string())],
        };
        let l = exactlti::io::load_model_str(
            &text,
            exactlti::io::SystemFormat::Toml,
            "bicycle.toml",
            &opts,
        )
        .unwrap();
        let t = l.rational().unwrap();
        let vf = v as f64;
        let mi = m.clone().try_inverse().unwrap();
        let kk = &k0 * 9.81 + &k2 * (vf * vf);
        let mut a = nalgebra::DMatrix::zeros(4, 4);
        a.view_mut((0, 2), (2, 2))
            .copy_from(&nalgebra::DMatrix::identity(2, 2));
        a.view_mut((2, 0), (2, 2)).copy_from(&(-(&mi * kk)));
        a.view_mut((2, 2), (2, 2)).copy_from(&(-(&mi * (&c1 * vf))));
        let want = exactlti::float::eigenvalues(&a).unwrap();
        let ours =
            exactlti::float::eigenvalues(&exactlti::float::to_dmatrix(&t.ss.a).unwrap()).unwrap();
        for w in &want {
            let best = ours
                .iter()
                .map(|z| (z - w).norm())
                .fold(f64::INFINITY, f64::min);
            assert!(
                best < 1e-8 * w.norm().max(1.0),
                "v = {v}: {w} not in {ours:?}"
            );
        }
        assert_eq!(exactlti::realization::mcmillan_degree(&t.ss), 4, "v = {v}");
    }
}
