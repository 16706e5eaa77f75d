//! Linear multibody models (issue 26): model files assembled exactly into descriptor
//! systems, checked against the papers (minimal-realizations sec. 4.1 and 4.3 Tables 7-8,
//! Jordan-forms eq. 24-26) and against hand-built second-order systems.

use exactlti::field::{Field, Q, Rational};
use exactlti::io::model_file::{ModelAny, read_model_str};
use exactlti::io::symbolic::SymbolicOptions;
use exactlti::io::{SystemFormat, TypedAny, TypedSystem, load_system_path, load_system_str};
use exactlti::matrix::Matrix;
use exactlti::multibody::{assemble, chain};
use exactlti::ratfunc::RatFuncField;
use exactlti::realization::{
    MinrealMethod, descriptor_to_standard, mcmillan_degree, minimal, modal_table,
};
use exactlti::rng::SplitMix64;
use exactlti::system::StateSpace;
use std::path::Path;

fn rational(path: &str) -> TypedSystem<Q> {
    let l = load_system_path(Path::new(path)).unwrap_or_else(|e| panic!("{path}: {e}"));
    l.rational().expect("a model over Q").clone()
}

fn q(s: &str) -> Rational {
    s.parse::<Rational>().unwrap_or_else(|_| {
        let (n, d) = s.split_once('/').unwrap();
        Rational::new(n.parse().unwrap(), d.parse().unwrap())
    })
}

fn qm(rows: &[&[&str]]) -> Matrix<Q> {
    let r: Vec<Vec<Rational>> = rows
        .iter()
        .map(|r| r.iter().map(|x| q(x)).collect())
        .collect();
    Matrix::from_rows(Q, r).unwrap()
}

/// Sec. 4.3: 11x11 descriptor with 3 infinite eigenvalues, standard order 8, McMillan
/// degree 7; Table 7's eigenvalues to all their 11 printed digits, Table 8's modes.
#[test]
fn quarter_car_a_arm_pushrod_tables_7_8() {
    let t = rational("data/models/quarter-car-a-arm-pushrod.toml");
    let d = t.descriptor.as_ref().expect("a descriptor system");
    assert_eq!(d.e.shape(), (11, 11));
    assert_eq!(d.e.rank(), 8);
    assert_eq!(t.ss.nstates(), 8, "3 infinite eigenvalues removed");
    assert_eq!(mcmillan_degree(&t.ss), 7);
    for m in [MinrealMethod::Kalman, MinrealMethod::Rosenbrock] {
        let r = minimal(&t.ss, m).unwrap();
        assert_eq!(r.system.nstates(), 7, "{m:?}");
        assert!(r.verified, "{m:?}");
        assert!(r.system.same_markov(&t.ss, 16), "{m:?}");
    }
    // Table 7 (real, imaginary), 11 significant digits as printed
    let table7 = [
        (-2.7124597711, 78.900865886),
        (-67.987473020, 0.0),
        (-17.032008218, 0.0),
        (-0.87165056701, 7.7487824748),
        (-44.916900938, 0.0),
        (0.0, 0.0),
    ];
    let modes = modal_table(&t.ss.a).unwrap().modes;
    assert_eq!(
        modes
            .iter()
            .map(|m| m.multiplicity * if m.paired { 2 } else { 1 })
            .sum::<usize>(),
        8
    );
    for (re, im) in table7 {
        let m = modes
            .iter()
            .find(|m| (m.approx.0 - re).abs() < 1e-6 && (m.approx.1.abs() - im).abs() < 1e-6)
            .unwrap_or_else(|| panic!("no eigenvalue near {re} + {im}i in {modes:?}"));
        let tol = |x: f64| 6e-11 * x.abs().max(1e-30);
        assert!((m.approx.0 - re).abs() <= tol(re), "{re}: {:?}", m.approx);
        assert!(
            (m.approx.1.abs() - im).abs() <= tol(im),
            "{im}: {:?}",
            m.approx
        );
    }
    // Table 8: frequency (Hz), damping ratio, time constant (s), period (s) of the pairs;
    // the time constants of the real modes
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-9 * b.abs();
    let hop = modes.iter().find(|m| m.approx.1.abs() > 70.0).unwrap();
    assert!(close(hop.frequency_hz, 12.564881160));
    assert!(close(hop.damping_ratio.unwrap(), 3.4357776649e-2));
    assert!(close(hop.time_constant_s.unwrap(), 3.6866906218e-1));
    assert!(close(hop.period_s.unwrap(), 7.9633920827e-2));
    let heave = modes
        .iter()
        .find(|m| (m.approx.1.abs() - 7.75).abs() < 0.1)
        .unwrap();
    assert!(close(heave.frequency_hz, 1.2410351444));
    assert!(close(heave.damping_ratio.unwrap(), 1.1178369687e-1));
    assert!(close(heave.time_constant_s.unwrap(), 1.1472487231));
    assert!(close(heave.period_s.unwrap(), 8.1086097430e-1));
    for tau in [1.4708591974e-2, 5.8712982475e-2, 2.2263334716e-2] {
        assert!(
            modes
                .iter()
                .any(|m| m.time_constant_s.is_some_and(|x| close(x, tau))),
            "{tau}"
        );
    }
    // the rigid-body mode (wheel angle) is not observable: the minimal realization drops 0
    let cp = minimal(&t.ss, MinrealMethod::Kalman)
        .unwrap()
        .system
        .a
        .charpoly()
        .unwrap();
    assert!(!Q.is_zero(&cp.coeff(0)), "0 is no pole of G");
}

/// Jordan-forms paper eq. 24-26: the yaw-plane model in symbols has exactly the transfer
/// matrix of (A, B) with the outputs y, psi, v, r.
#[test]
fn yaw_plane_symbolic_equals_eq_24_26() {
    let l = load_system_path(Path::new("data/models/yaw-plane.toml")).unwrap();
    let TypedAny::RatFunc(t) = &l.system else {
        panic!("expected Q(p)")
    };
    let k: RatFuncField = t.ss.a.field().clone();
    assert_eq!(k.to_string(), "QQ(Izz, a, b, cf, cr, m, u)");
    let p = |s: &str| k.parse(s).unwrap();
    let a = Matrix::from_rows(
        k.clone(),
        vec![
            vec![p("0"), p("u"), p("-1"), p("0")],
            vec![p("0"), p("0"), p("0"), p("-1")],
            vec![
                p("0"),
                p("0"),
                p("-(cf + cr)/(m*u)"),
                p("-(a*cf - b*cr)/(m*u) - u"),
            ],
            vec![
                p("0"),
                p("0"),
                p("-(a*cf - b*cr)/(Izz*u)"),
                p("-(a^2*cf + b^2*cr)/(Izz*u)"),
            ],
        ],
    )
    .unwrap();
    let b = Matrix::from_rows(
        k.clone(),
        vec![
            vec![p("0")],
            vec![p("0")],
            vec![p("cf/m")],
            vec![p("a*cf/Izz")],
        ],
    )
    .unwrap();
    let paper = StateSpace::new(
        a,
        b,
        Matrix::identity(k.clone(), 4),
        Matrix::zeros(k.clone(), 4, 1),
    )
    .unwrap();
    assert_eq!(t.ss.nstates(), 4);
    // equal Markov parameters up to 2n = 8 determine equal transfer matrices (both order 4)
    assert!(t.ss.same_markov(&paper, 8));
    let g = t.ss.transfer_matrix().unwrap();
    let gp = paper.transfer_matrix().unwrap();
    assert_eq!(g.to_strings(), gp.to_strings());
    assert!(g.matches_markov(&paper));
}

/// The two-mass quarter car against its second-order equations.
#[test]
fn quarter_car_two_mass_matches_second_order() {
    let t = rational("data/models/quarter-car-2mass.toml");
    assert_eq!(t.descriptor.as_ref().unwrap().e.shape(), (5, 5));
    let (mu, ms, ks, kt, cs) = ("50", "500", "18000", "180000", "1500");
    let m = qm(&[&[mu, "0"], &["0", ms]]);
    let kk = qm(&[&["198000", "-18000"], &["-18000", ks]]);
    let l = qm(&[&[cs, "-1500"], &["-1500", cs]]);
    let f = qm(&[&[kt], &["0"]]);
    // outputs on [x_u, x_s, x_u', x_s']: x_s, x_s - x_u, x_u - z0
    let c = qm(&[
        &["0", "1", "0", "0"],
        &["-1", "1", "0", "0"],
        &["1", "0", "0", "0"],
    ]);
    let d = qm(&[&["0"], &["0"], &["-1"]]);
    let want = StateSpace::from_second_order(&m, &l, &kk, &f, Some(&c), Some(&d)).unwrap();
    assert!(t.ss.same_markov(&want, 10));
    assert_eq!(mcmillan_degree(&t.ss), 4);
}

/// EoM's spring-mass-damper: G(s) = 1/(m s^2 + c s + k) with c = 0.2 read exactly.
#[test]
fn spring_mass_damper() {
    let t = rational("data/models/spring-mass-damper.toml");
    let want = StateSpace::from_second_order(
        &qm(&[&["1"]]),
        &qm(&[&["1/5"]]),
        &qm(&[&["1"]]),
        &qm(&[&["1"]]),
        None,
        None,
    )
    .unwrap();
    assert!(t.ss.same_markov(&want, 6));
}

/// Sec. 4.1: the sliding masses model gives the system file's transfer function; 20 -> 8.
#[test]
fn sliding_masses_model_equals_system_file() {
    let t = rational("data/models/sliding-masses.toml");
    let file = rational("data/sliding-masses.json");
    assert_eq!(t.descriptor.as_ref().unwrap().e.shape(), (21, 21));
    assert_eq!(t.ss.nstates(), 20);
    assert!(t.ss.same_markov(&file.ss, 40));
    assert_eq!(mcmillan_degree(&t.ss), 8);
}

/// A chain of n bodies: descriptor 2n + 1, standard 2n, and the second-order equations
/// (tridiagonal stiffness and damping) for every n up to 8.
#[test]
fn chain_properties() {
    for n in 1..=8 {
        let a = assemble(&chain(&Q, n)).unwrap();
        let d = &a.descriptor;
        assert_eq!(d.e.shape(), (2 * n + 1, 2 * n + 1), "n = {n}");
        let sf = descriptor_to_standard(d).unwrap();
        assert!(sf.verified, "n = {n}");
        let ss = sf.system;
        let mut k = Matrix::zeros(Q, n, n);
        for i in 0..n {
            k.set(i, i, Q.from_i64(if i + 1 < n { 2 } else { 1 }));
            if i + 1 < n {
                k.set(i, i + 1, Q.from_i64(-1));
                k.set(i + 1, i, Q.from_i64(-1));
            }
        }
        let mut f = Matrix::zeros(Q, n, 1);
        f.set(n - 1, 0, Q.one());
        let mut c = Matrix::zeros(Q, 1, 2 * n);
        c.set(0, n - 1, Q.one());
        let want =
            StateSpace::from_second_order(&Matrix::identity(Q, n), &k, &k, &f, Some(&c), None)
                .unwrap();
        assert!(ss.same_markov(&want, 4 * n), "n = {n}");
        // the assembly's mass/stiffness restricted to the x coordinates are M and K
        let xs: Vec<usize> = (0..n).map(|i| 6 * i).collect();
        assert_eq!(a.stiffness.select_rows(&xs).select_cols(&xs), k, "n = {n}");
    }
}

/// JSON and TOML model files with the same keys give the same system; symbols by `null`.
#[test]
fn json_and_toml_agree_and_null_is_a_symbol() {
    let toml = std::fs::read_to_string("data/models/spring-mass-damper.toml").unwrap();
    let json = r#"{"name": "smd", "parameters": {"m": 1, "c": 0.2, "k": 1},
      "bodies": [{"name": "block", "mass": "m", "location": [0, 0, 0]}],
      "flex_points": [{"name": "spring", "bodies": ["block", "ground"], "location": [0, 0, 0],
                       "forces": 1, "axis": [0, 0, 1], "stiffness": "k", "damping": "c"}],
      "rigid_points": [{"name": "slider", "bodies": ["block", "ground"], "location": [0, 0, 0],
                        "forces": 2, "moments": 3, "axis": [0, 0, 1]}],
      "actuators": [{"name": "f", "bodies": ["block", "ground"], "locations": [[0, 0, 0], [0, 0, -0.1]]}],
      "sensors": [{"name": "z", "bodies": ["block", "ground"], "locations": [[0, 0, 0], [0, 0, -0.1]]}]}"#;
    let a = load_system_str(&toml, SystemFormat::Toml, "smd.toml").unwrap();
    let b = load_system_str(json, SystemFormat::Json, "smd.json").unwrap();
    assert!(
        a.rational()
            .unwrap()
            .ss
            .same_markov(&b.rational().unwrap().ss, 4)
    );
    let sym = json.replace("\"c\": 0.2", "\"c\": null");
    let m = read_model_str(
        &sym,
        SystemFormat::Json,
        "smd.json",
        &SymbolicOptions::default(),
    )
    .unwrap();
    let ModelAny::RatFunc(m) = m else {
        panic!("c is a symbol")
    };
    assert_eq!(m.field.to_string(), "QQ(c)");
    let asm = assemble(&m).unwrap();
    assert_eq!(asm.descriptor.e.shape(), (3, 3));
}

/// Bad model files: one line naming the file and key, never a panic.
#[test]
fn bad_models_name_the_key() {
    let base = std::fs::read_to_string("data/models/quarter-car-2mass.toml").unwrap();
    let cases = [
        (
            base.replace(
                "bodies = [\"sprung\", \"unsprung\"]",
                "bodies = [\"sprung\", \"wheel\"]",
            ),
            "flex_points[2].bodies: unknown body 'wheel'",
        ),
        (
            base.replace("mass = \"ms\"", "mass = \"ms\"\nmas = 1"),
            "bodies[2].mas: unknown key",
        ),
        (
            base.replace(
                "forces = 1\naxis = [0, 0, 1]\nstiffness = \"kt\"",
                "forces = 1\nstiffness = \"kt\"",
            ),
            "flex_points[1].axis: missing",
        ),
        (
            base.replace("gain = \"kt\"", "gain = \"kq\""),
            "actuators[1].gain: unknown",
        ),
        (
            base.replace(
                "locations = [[0.05, 0, 0.3], [0.05, 0, 0]]",
                "locations = [[0.05, 0, 0.3], [0.06, 0, 0]]",
            ),
            "z0: the distance between the two locations must be a rational number",
        ),
    ];
    for (text, want) in cases {
        let e = load_system_str(&text, SystemFormat::Toml, "qc.toml")
            .unwrap_err()
            .to_string();
        assert!(e.starts_with("qc.toml") && e.contains(want), "{e}");
        assert!(!e.contains('\n'), "{e}");
    }
}

/// The class of damaged model files (a line dropped or a value garbled, fixed seed): every
/// one loads or fails with a one-line error, none panics.
#[test]
fn damaged_models_never_panic() {
    let base = std::fs::read_to_string("data/models/quarter-car-2mass.toml").unwrap();
    let lines: Vec<&str> = base.lines().collect();
    let mut rng = SplitMix64(26);
    for _ in 0..200 {
        let i = (rng.next_u64() % lines.len() as u64) as usize;
        let mut l = lines.clone();
        let garbled;
        match rng.next_u64() % 3 {
            0 => {
                l.remove(i);
            }
            1 => {
                garbled = l[i].replace('0', "-1").replace('"', "");
                l[i] = &garbled;
            }
            _ => {
                garbled = l[i].replace("1", "0");
                l[i] = &garbled;
            }
        }
        let text = l.join("\n");
        if let Err(e) = load_system_str(&text, SystemFormat::Toml, "x.toml") {
            assert!(!e.to_string().contains('\n'), "{e}");
        }
    }
}
