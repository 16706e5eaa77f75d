//! Minimal realization, Kalman decomposition, descriptor conversion and Gramians.
use crate::common;
use common::systems::sliding_masses;
use common::*;
use exactlti::field::{Field, Q, Rational};
use exactlti::matrix::Matrix;
use exactlti::qmat;
use exactlti::realization::*;
use exactlti::system::{Descriptor, StateSpace};

const METHODS: [MinrealMethod; 3] = [
    MinrealMethod::Kalman,
    MinrealMethod::Rosenbrock,
    MinrealMethod::HoKalman,
];

#[test]
fn sliding_masses_mcmillan_degree_8_by_every_method() {
    let sys = sliding_masses();
    assert_eq!(mcmillan_degree(&sys), 8);
    let reference = minimal(&sys, MinrealMethod::Kalman).unwrap();
    for m in METHODS {
        let r = minimal(&sys, m).unwrap();
        assert_eq!(r.order, 8, "method {m:?}");
        assert!(r.verified, "method {m:?}");
        assert!(
            r.system.same_markov(&reference.system, 40),
            "methods agree on Markov parameters"
        );
    }
    let kd = kalman_decomposition(&sys).unwrap();
    assert_eq!(kd.dims.iter().sum::<usize>(), 20);
    assert_eq!(kd.dims[1], 8);
}

#[test]
fn minreal_examples() {
    // already minimal
    let s =
        StateSpace::new_strictly_proper(qmat![[0, 1], [-2, -3]], qmat![[0], [1]], qmat![[1, 0]])
            .unwrap();
    for m in METHODS {
        assert_eq!(minimal(&s, m).unwrap().order, 2);
    }
    // pole-zero cancellation: (s+1)/((s+1)(s+2)) -> order 1
    let s =
        StateSpace::new_strictly_proper(qmat![[0, 1], [-2, -3]], qmat![[0], [1]], qmat![[1, 1]])
            .unwrap();
    for m in METHODS {
        let r = minimal(&s, m).unwrap();
        assert_eq!(r.order, 1, "{m:?}");
        assert!(r.verified);
        assert_eq!(r.system.a.to_string(), "[[-2]]");
    }
    // no inputs / no outputs / 0 states
    let s =
        StateSpace::new_strictly_proper(qmat![[1]], Matrix::zeros(Q, 1, 0), qmat![[1]]).unwrap();
    for m in METHODS {
        assert_eq!(minimal(&s, m).unwrap().order, 0);
    }
    let s = StateSpace::new(
        Matrix::zeros(Q, 0, 0),
        Matrix::zeros(Q, 0, 1),
        Matrix::zeros(Q, 1, 0),
        qmat![[5]],
    )
    .unwrap();
    for m in METHODS {
        let r = minimal(&s, m).unwrap();
        assert_eq!(r.order, 0);
        assert!(r.verified);
    }
    // shape errors are typed
    assert!(StateSpace::new_strictly_proper(qmat![[0, 1]], qmat![[1]], qmat![[1]]).is_err());
    assert!(StateSpace::new_strictly_proper(qmat![[0]], qmat![[1], [1]], qmat![[1]]).is_err());
}

/// A random controllable+observable system of order `r` padded with uncontrollable and
/// unobservable parts and scrambled by a random similarity.
fn padded<K: Field>(k: &K, g: &Option<K::Elem>, rng: &mut Rng) -> (StateSpace<K>, usize) {
    loop {
        let r = rng.int(0, 3) as usize;
        let (m, p) = (rng.int(1, 2) as usize, rng.int(1, 2) as usize);
        let a = random_matrix(k, g, r, r, rng);
        let b = random_matrix(k, g, r, m, rng);
        let c = random_matrix(k, g, p, r, rng);
        let core = StateSpace::new_strictly_proper(a, b, c).unwrap();
        if mcmillan_degree(&core) != r {
            continue;
        }
        let (nu, no) = (rng.int(0, 2) as usize, rng.int(0, 2) as usize);
        let n = r + nu + no;
        // block triangular padding: [core, *, ; 0 uncontrollable; unobservable]
        let mut a = random_matrix(k, g, n, n, rng);
        a.set_block(0, 0, &core.a);
        for i in r..r + nu {
            for j in 0..r {
                a.set(i, j, k.zero());
            }
            for j in r + nu..n {
                a.set(i, j, k.zero());
            }
        }
        for i in 0..r + nu {
            for j in r + nu..n {
                a.set(i, j, k.zero());
            }
        }
        let mut b = Matrix::zeros(k.clone(), n, m);
        b.set_block(0, 0, &core.b);
        let rb = random_matrix(k, g, no, m, rng);
        b.set_block(r + nu, 0, &rb);
        let mut c = random_matrix(k, g, p, n, rng);
        c.set_block(0, 0, &core.c);
        for i in 0..p {
            for j in r + nu..n {
                c.set(i, j, k.zero());
            }
        }
        let sys = StateSpace::new_strictly_proper(a, b, c).unwrap();
        let t = unimodular(k, n, rng);
        return (sys.transform(&t).unwrap(), r);
    }
}

fn minreal_properties<K: exactlti::realization::SystemField>(
    k: &K,
    g: &Option<K::Elem>,
    seed: u64,
) {
    let mut rng = Rng(seed);
    for _ in 0..iters(15) {
        let (sys, r) = padded(k, g, &mut rng);
        assert_eq!(mcmillan_degree(&sys), r);
        for m in METHODS {
            let res = minimal(&sys, m).unwrap();
            assert_eq!(res.order, r, "method {m:?}, A = {}", sys.a);
            assert!(res.verified, "method {m:?}, A = {}", sys.a);
        }
    }
}

#[test]
fn minreal_properties_q() {
    minreal_properties(&Q, &None, 11);
}
#[test]
fn minreal_properties_qsqrt2() {
    let (k, g) = qsqrt2();
    minreal_properties(&k, &g, 12);
}
#[test]
fn minreal_properties_qi() {
    let (k, g) = qi();
    minreal_properties(&k, &g, 13);
}

#[test]
fn descriptor_index1_and_input_as_state() {
    // x1' = -x1 + u written with an algebraic state x2 = u (input appended as a state)
    let e = qmat![[1, 0], [0, 0]];
    let a = qmat![[-1, 1], [0, -1]];
    let b = qmat![[0], [1]];
    let c = qmat![[1, 0]];
    let d = qmat![[0]];
    let sf = descriptor_to_standard(&Descriptor::new(e, a, b, c, d).unwrap()).unwrap();
    assert_eq!(sf.system.nstates(), 1);
    assert_eq!(sf.removed_infinite, 1);
    let tf = sf.system.transfer_matrix().unwrap();
    assert_eq!(tf.entries[0][0].to_string_var("s"), "(1)/(s + 1)");
}

#[test]
fn descriptor_higher_index_and_improper() {
    // index 2 chain with output of x1: N = [[0,1],[0,0]], x2 = u, x1 = x2' => improper
    let e = qmat![[0, 1], [0, 0]];
    let a = qmat![[1, 0], [0, 1]];
    let b = qmat![[0], [-1]];
    let sys = Descriptor::new(e.clone(), a.clone(), b.clone(), qmat![[1, 0]], qmat![[0]]).unwrap();
    assert!(matches!(
        descriptor_to_standard(&sys),
        Err(exactlti::Error::ImproperTransfer(_))
    ));
    // same pencil observing x2 only: proper, static gain
    let sys = Descriptor::new(e, a, b, qmat![[0, 1]], qmat![[0]]).unwrap();
    let sf = descriptor_to_standard(&sys).unwrap();
    assert_eq!(sf.system.nstates(), 0);
    assert_eq!(sf.system.d.to_string(), "[[1]]");
    // singular pencil
    let sys = Descriptor::new(
        qmat![[1, 0], [0, 0]],
        qmat![[1, 0], [0, 0]],
        qmat![[1], [0]],
        qmat![[1, 0]],
        qmat![[0]],
    )
    .unwrap();
    assert!(descriptor_to_standard(&sys).is_err());
}

#[test]
fn descriptor_with_invertible_e_matches_e_inverse() {
    let mut rng = Rng(7);
    for _ in 0..iters(10) {
        let n = rng.int(1, 4) as usize;
        let e = unimodular(&Q, n, &mut rng);
        let a = random_matrix(&Q, &None, n, n, &mut rng);
        let b = random_matrix(&Q, &None, n, 1, &mut rng);
        let c = random_matrix(&Q, &None, 1, n, &mut rng);
        let d = Matrix::zeros(Q, 1, 1);
        let sf = descriptor_to_standard(
            &Descriptor::new(e.clone(), a.clone(), b.clone(), c.clone(), d.clone()).unwrap(),
        )
        .unwrap();
        let ei = e.inverse().unwrap();
        let direct = StateSpace::new(&ei * &a, &ei * &b, c, d).unwrap();
        assert_eq!(sf.removed_infinite, 0);
        assert_eq!(
            sf.system.transfer_matrix().unwrap(),
            direct.transfer_matrix().unwrap()
        );
    }
}

#[test]
fn gramians_and_hurwitz() {
    let s =
        StateSpace::new_strictly_proper(qmat![[-1, 0], [0, -2]], qmat![[1], [1]], qmat![[1, 1]])
            .unwrap();
    let g = gramians(&s).unwrap();
    // A Wc + Wc A^T = -B B^T
    let lhs = &(&s.a * &g.wc) + &(&g.wc * &s.a.transpose());
    assert_eq!(lhs, -&(&s.b * &s.b.transpose()));
    assert_eq!(g.wc.to_string(), "[[1/2, 1/3], [1/3, 1/4]]");
    let lhs = &(&s.a.transpose() * &g.wo) + &(&g.wo * &s.a);
    assert_eq!(lhs, -&(&s.c.transpose() * &s.c));
    let unstable =
        StateSpace::new_strictly_proper(qmat![[0, 1], [-2, 1]], qmat![[0], [1]], qmat![[1, 0]])
            .unwrap();
    assert!(matches!(
        gramians(&unstable),
        Err(exactlti::Error::Unstable(_))
    ));
    use exactlti::poly::Poly;
    assert!(is_hurwitz(&Poly::from_i64s(&[2, 3, 1])));
    assert!(!is_hurwitz(&Poly::from_i64s(&[1, 0, 1])));
    assert!(!is_hurwitz(&Poly::from_i64s(&[6, 11, 6, -1])));
    // s^3 + s^2 + 2 s + 24 has roots with positive real part
    assert!(!is_hurwitz(&Poly::from_i64s(&[24, 2, 1, 1])));
    assert!(is_hurwitz(&Poly::from_i64s(&[6, 11, 6, 1])));
}

#[test]
fn transfer_matrix_examples() {
    let s = StateSpace::new(
        qmat![[0, 1], [-2, -3]],
        qmat![[0], [1]],
        qmat![[1, 1]],
        qmat![[2]],
    )
    .unwrap();
    let tf = s.transfer_matrix().unwrap();
    // (s+1)/((s+1)(s+2)) + 2 = (2 s + 5)/(s + 2)
    assert_eq!(tf.entries[0][0].to_string_var("s"), "(2*s + 5)/(s + 2)");
    let _ = Rational::from_integer(1.into());
    // D, C B, C A B, ... are the Laurent coefficients of G at infinity
    assert!(tf.matches_markov(&s));
    let other = StateSpace::new(
        qmat![[0, 1], [-2, -3]],
        qmat![[0], [1]],
        qmat![[1, 2]],
        qmat![[2]],
    )
    .unwrap();
    assert!(!tf.matches_markov(&other));
    assert!(other.transfer_matrix().unwrap().matches_markov(&other));
}

#[test]
fn modal_table_sliding_masses_matches_paper_tab1() {
    let sys = sliding_masses();
    let t = modal_table(&sys.a).unwrap();
    assert_eq!(t.modes.len(), 5);
    // Tab. 1: natural frequencies in Hz (10 significant digits)
    let want = [
        8.2384660790e-2,
        1.5915494309e-1,
        2.2507907904e-1,
        2.7566444771e-1,
        3.0746373983e-1,
    ];
    let mut got: Vec<f64> = t.modes.iter().map(|m| m.frequency_hz).collect();
    got.sort_by(|a, b| a.partial_cmp(b).unwrap());
    for (g, w) in got.iter().zip(want) {
        assert!((g - w).abs() < 1e-10 * w, "{g} vs {w}");
    }
    for m in &t.modes {
        assert_eq!(m.multiplicity, 2);
        assert_eq!(m.damping_ratio, Some(0.0));
        assert_eq!(m.time_constant_s, None);
    }
    // a damped pair: s^2 + 2 s + 2 -> wn^2 = 2, zeta = sqrt(2)/2, tau = 1
    let t = modal_table(&qmat![[0, 1], [-2, -2]]).unwrap();
    assert_eq!(t.modes.len(), 1);
    let ex: std::collections::HashMap<_, _> = t.modes[0].exact_texts().into_iter().collect();
    assert_eq!(ex["natural_frequency_squared"], "2");
    assert_eq!(ex["damping_ratio"], "sqrt(2)/2");
    assert_eq!(ex["time_constant_s"], "1");
    assert!((t.modes[0].damping_ratio.unwrap() - 0.5f64.sqrt()).abs() < 1e-15);
    assert_eq!(t.modes[0].eigenvalue.value_string(), "-1 + i");
}

#[test]
fn jordan_method_sliding_masses_20_16_8() {
    let sys = sliding_masses();
    let r = minimal_jordan(&sys).unwrap();
    assert_eq!(
        r.stages,
        [20, 16, 8],
        "drop the four modes at +/- i sqrt 2, then compact"
    );
    assert!(r.verified);
    assert_eq!(r.mcmillan_degree, 8);
    // sparse real Jordan pattern: 4 blocks [[0, w], [-w, 0]] with 4 distinct magnitudes
    let real = r.real.as_ref().unwrap();
    assert_eq!(real.len(), 4);
    let mut mags = vec![];
    for b in real {
        let (f, [a, _, _]) = b.exact_entries().unwrap();
        assert_eq!(a.nrows(), 2);
        assert!(f.is_zero(a.get(0, 0)) && f.is_zero(a.get(1, 1)));
        assert_eq!(f.neg(a.get(0, 1)), *a.get(1, 0));
        mags.push(f.approx(a.get(0, 1)).0.abs());
    }
    mags.sort_by(|a, b| a.partial_cmp(b).unwrap());
    let want = [
        0.5176380902050415,
        1.0,
        1.7320508075688772,
        1.9318516525781366,
    ];
    for (g, w) in mags.iter().zip(want) {
        assert!((g - w).abs() < 1e-12, "{g} vs {w}");
    }
}

#[test]
fn jordan_method_agrees_with_kalman_on_rational_and_quadratic_modes() {
    // real, repeated and complex-quadratic modes, with a non-trivial Jordan block
    let a = qmat![
        [-1, 1, 0, 0, 0],
        [0, -1, 0, 0, 0],
        [0, 0, -1, 0, 0],
        [0, 0, 0, 0, 1],
        [0, 0, 0, -2, -2]
    ];
    let b = qmat![[0, 1], [1, 0], [1, 1], [0, 0], [1, 0]];
    let c = qmat![[1, 0, 1, 1, 0], [0, 1, 0, 0, 1]];
    let mut rng = Rng(5);
    let t = unimodular(&Q, 5, &mut rng);
    let sys = StateSpace::new_strictly_proper(a, b, c)
        .unwrap()
        .transform(&t)
        .unwrap();
    let r = minimal_jordan(&sys).unwrap();
    assert!(r.verified);
    assert_eq!(r.order(), mcmillan_degree(&sys));
    let rs = r
        .real_to_base()
        .expect("all modes rational or Q(i) pairs with rational parts");
    assert!(rs.same_markov(&sys, 2 * 5));
    // a cubic factor with complex roots (x^3 - 2): exact real blocks over Q(Re, Im) on
    // request (degree 6), by default the compact pair (Re/Im of entries of Q(theta))
    let cubic = StateSpace::new_strictly_proper(
        qmat![[0, 1, 0], [0, 0, 1], [2, 0, 0]],
        qmat![[0], [0], [1]],
        qmat![[1, 0, 0]],
    )
    .unwrap();
    let r = exactlti::realization::minimal_jordan_with(&cubic, true).unwrap();
    assert!(r.verified);
    assert_eq!(r.order(), 3);
    let real = r.real.as_ref().unwrap();
    assert_eq!(
        real.len(),
        2,
        "one real root block and one complex pair block"
    );
    assert_eq!(real[1].exact_entries().unwrap().1[0].nrows(), 2);
    let c = minimal_jordan(&cubic).unwrap();
    let real = c.real.as_ref().unwrap();
    assert!(c.verified && c.order() == 3);
    let RealModalBlock::Compact(blk) = &real[1] else {
        panic!("the cubic's pair is compact by default")
    };
    assert_eq!((real[1].order(), blk.a.nrows()), (2, 1));
}

#[test]
fn pbh_agrees_with_kalman_rank_tests() {
    let mut rng = Rng(21);
    for _ in 0..iters(20) {
        let (sys, _) = padded(&Q, &None, &mut rng);
        assert_eq!(
            pbh_controllable(&sys.a, &sys.b).unwrap(),
            is_controllable(&sys.a, &sys.b),
            "A = {}",
            sys.a
        );
        assert_eq!(
            pbh_observable(&sys.a, &sys.c).unwrap(),
            is_observable(&sys.a, &sys.c),
            "A = {}",
            sys.a
        );
    }
    let s = sliding_masses();
    assert!(!pbh_controllable(&s.a, &s.b).unwrap());
    assert!(!pbh_observable(&s.a, &s.c).unwrap());
}

#[test]
fn number_field_matrices_at_jordan_sizes() {
    // rref and null space of the 20x20 sliding-mass A - t I over Q[t]/(t^4 + 4 t^2 + 1)
    use exactlti::algebraic::NumberField;
    use exactlti::poly::Poly;
    let s = sliding_masses();
    let k = NumberField::new(&Poly::from_i64s(&[1, 0, 4, 0, 1]), (0.0, 0.5176380902)).unwrap();
    let mut m = s.a.convert_to(&k);
    let t = k.generator();
    for i in 0..20 {
        let v = k.sub(m.get(i, i), &t);
        m.set(i, i, v);
    }
    let ns = m.nullspace();
    assert_eq!(ns.ncols(), 2, "each eigenvalue is double and non-defective");
    assert!((&m * &ns).is_zero());
    let (r, piv) = m.rref();
    assert_eq!(piv.len(), 18);
    assert_eq!(r.rref().0, r);
}
