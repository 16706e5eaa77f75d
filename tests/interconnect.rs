//! Interconnection (series, parallel, feedback, append) checked EXACTLY against transfer
//! matrices: the transfer matrices of the parts and of the result are computed by the
//! exact `tf` machinery and the identities $G_s = G_2 G_1$, $G_p = G_1 + G_2$,
//! $(I - \sigma G K) G_{fb} = G = G_{fb} (I - \sigma K G)$, $G_a = \mathrm{diag}(G_i)$ asserted
//! as equalities of rational matrices; over Q, Q(sqrt 2) and Q(a, k); descriptor parts;
//! a generator of random small systems (fixed seed); the classic pole-zero cancellation
//! after feedback, removed by the exact minimal realization.

use exactlti::error::Error;
use exactlti::field::{Field, Q, Quadratic, QuadraticField, Rational};
use exactlti::matrix::Matrix;
use exactlti::ratfunc::RatFuncField;
use exactlti::realization::{MinrealMethod, descriptor_transfer_matrix, minimal};
use exactlti::rng::SplitMix64;
use exactlti::system::interconnect::{
    Interconnection, Sign, append, feedback, parallel, series, static_gain, verify,
};
use exactlti::system::transfer::TransferMatrix;
use exactlti::system::{Descriptor, StateSpace};

fn q(rows: &[&[i64]]) -> Matrix<Q> {
    Matrix::from_i64_rows(rows)
}

fn ss(a: &[&[i64]], b: &[&[i64]], c: &[&[i64]], d: &[&[i64]]) -> StateSpace<Q> {
    StateSpace::new(q(a), q(b), q(c), q(d)).unwrap()
}

fn tf<K: Field>(s: &StateSpace<K>) -> TransferMatrix<K> {
    s.transfer_matrix().unwrap()
}

/// `series(g1, g2)`, with `tf = G2 G1` and the library's own check asserted.
fn check_series<K: Field>(g1: &StateSpace<K>, g2: &StateSpace<K>) -> StateSpace<K> {
    let r = series(g1, g2).unwrap();
    let k = g1.field();
    assert_eq!(tf(&r), tf(g2).try_mul(&tf(g1), k).unwrap(), "G2 G1");
    assert_eq!(r.nstates(), g1.nstates() + g2.nstates());
    assert!(verify(&Interconnection::Series(g1, g2), &r));
    r
}

fn check_parallel<K: Field>(g1: &StateSpace<K>, g2: &StateSpace<K>) -> StateSpace<K> {
    let r = parallel(g1, g2).unwrap();
    assert_eq!(tf(&r), tf(g1).try_add(&tf(g2)).unwrap(), "G1 + G2");
    assert!(verify(&Interconnection::Parallel(g1, g2), &r));
    r
}

/// `feedback(g, k, sign)`: $(I - \sigma G K) G_{fb} = G$ and $G_{fb} (I - \sigma K G) = G$.
fn check_feedback<K: Field>(g: &StateSpace<K>, kk: &StateSpace<K>, sign: Sign) -> StateSpace<K> {
    let r = feedback(g, kk, sign).unwrap();
    let f = g.field();
    let (tg, tk, tr) = (tf(g), tf(kk), tf(&r));
    let s = sign.value(f);
    let (p, m) = (g.noutputs(), g.ninputs());
    let left = TransferMatrix::identity(f, p).try_sub(&tg.try_mul(&tk, f).unwrap().scale(f, &s));
    assert_eq!(
        left.unwrap().try_mul(&tr, f).unwrap(),
        tg,
        "(I - s G K) G_fb = G"
    );
    let right = TransferMatrix::identity(f, m).try_sub(&tk.try_mul(&tg, f).unwrap().scale(f, &s));
    assert_eq!(
        tr.try_mul(&right.unwrap(), f).unwrap(),
        tg,
        "G_fb (I - s K G) = G"
    );
    assert!(verify(&Interconnection::Feedback(g, kk, sign), &r));
    r
}

fn check_append<K: Field>(parts: &[StateSpace<K>]) -> StateSpace<K> {
    let r = append(parts).unwrap();
    let tfs: Vec<_> = parts.iter().map(tf).collect();
    assert_eq!(tf(&r), TransferMatrix::block_diag(parts[0].field(), &tfs));
    assert!(verify(&Interconnection::Append(parts), &r));
    r
}

/// 1/(s+1), (s+2)/(s+3) and a 2x2 system.
fn g_first_order() -> StateSpace<Q> {
    ss(&[&[-1]], &[&[1]], &[&[1]], &[&[0]])
}
fn g_lead() -> StateSpace<Q> {
    // (s+2)/(s+3) = 1 - 1/(s+3)
    ss(&[&[-3]], &[&[1]], &[&[-1]], &[&[1]])
}
fn g_mimo() -> StateSpace<Q> {
    ss(
        &[&[0, 1, 0], &[-2, -3, 0], &[0, 0, -4]],
        &[&[0, 0], &[1, 0], &[0, 1]],
        &[&[1, 0, 1], &[0, 1, 0]],
        &[&[0, 1], &[0, 0]],
    )
}

// ---- examples ----

#[test]
fn series_siso_is_the_product() {
    let r = check_series(&g_first_order(), &g_lead());
    // states [x1; x2]: A = [[A1, 0], [B2 C1, A2]]
    assert_eq!(r.a, q(&[&[-1, 0], &[1, -3]]));
    assert_eq!(tf(&r).to_strings(), vec![vec!["(s + 2)/(s^2 + 4*s + 3)"]]);
}

#[test]
fn series_mimo_order_matters() {
    let g = g_mimo();
    let k = ss(&[&[-1]], &[&[1, 1]], &[&[1], &[2]], &[&[1, 0], &[0, 0]]);
    let gk = check_series(&k, &g);
    let kg = check_series(&g, &k);
    assert_ne!(tf(&gk), tf(&kg), "G K and K G differ for these 2x2 systems");
}

#[test]
fn parallel_and_append() {
    check_parallel(&g_first_order(), &g_lead());
    check_parallel(&g_mimo(), &g_mimo());
    let r = check_append(&[g_first_order(), g_mimo(), static_gain(q(&[&[5]]))]);
    assert_eq!((r.noutputs(), r.ninputs(), r.nstates()), (4, 4, 4));
}

#[test]
fn feedback_negative_and_positive_siso() {
    let g = g_first_order();
    let one = static_gain(q(&[&[1]]));
    let neg = check_feedback(&g, &one, Sign::Negative);
    assert_eq!(tf(&neg).to_strings(), vec![vec!["(1)/(s + 2)"]]);
    let pos = check_feedback(&g, &one, Sign::Positive);
    assert_eq!(tf(&pos).to_strings(), vec![vec!["(1)/(s)"]]);
    // a dynamic controller in the feedback path, with feedthrough on both sides
    let r = check_feedback(&g_lead(), &g_lead(), Sign::Negative);
    assert_eq!(r.nstates(), 2);
}

#[test]
fn feedback_mimo_with_a_system_and_a_gain() {
    let g = g_mimo();
    let k = ss(&[&[-1]], &[&[1, 1]], &[&[1], &[2]], &[&[1, 0], &[0, 2]]);
    check_feedback(&g, &k, Sign::Negative);
    check_feedback(&g, &k, Sign::Positive);
    check_feedback(&g, &static_gain(q(&[&[1, 2], &[3, 4]])), Sign::Negative);
}

#[test]
fn edge_shapes_static_systems() {
    // no states anywhere: D-only algebra, D = D1 (I - s D2 D1)^-1
    let g = static_gain(q(&[&[2]]));
    let r = check_feedback(&g, &static_gain(q(&[&[3]])), Sign::Negative);
    assert_eq!(r.nstates(), 0);
    assert_eq!(r.d.get(0, 0), &Rational::new(2.into(), 7.into()));
    check_series(&g, &g_first_order());
    check_parallel(&g, &g_first_order());
    check_append(&[g]);
}

#[test]
fn ill_posed_feedback_is_refused() {
    // G = 1, K = 1, positive: I - D2 D1 = 0
    let one = static_gain(q(&[&[1]]));
    let e = feedback(&one, &one, Sign::Positive).unwrap_err();
    assert!(matches!(e, Error::IllPosed(_)), "{e}");
    // negative feedback with D_G = 1, D_K = -1: I + D1 D2 = 0, also with states
    let g = ss(&[&[-1]], &[&[1]], &[&[1]], &[&[1]]);
    let k = ss(&[&[-2]], &[&[1]], &[&[1]], &[&[-1]]);
    assert!(matches!(
        feedback(&g, &k, Sign::Negative),
        Err(Error::IllPosed(_))
    ));
    assert!(feedback(&g, &k, Sign::Positive).is_ok());
}

#[test]
fn shape_mismatches_are_typed_errors() {
    let g = g_mimo();
    let siso = g_first_order();
    assert!(matches!(series(&siso, &g), Err(Error::Shape { .. })));
    assert!(matches!(parallel(&siso, &g), Err(Error::Shape { .. })));
    assert!(matches!(
        feedback(&g, &static_gain(q(&[&[1, 2]])), Sign::Negative),
        Err(Error::Shape { .. })
    ));
    assert!(matches!(
        append::<Q, StateSpace<Q>>(&[]),
        Err(Error::Invalid(_))
    ));
}

#[test]
fn verify_rejects_a_wrong_result() {
    let (g, k) = (g_mimo(), static_gain(q(&[&[1, 0], &[0, 1]])));
    let mut r = feedback(&g, &k, Sign::Negative).unwrap();
    assert!(verify(
        &Interconnection::Feedback(&g, &k, Sign::Negative),
        &r
    ));
    assert!(!verify(
        &Interconnection::Feedback(&g, &k, Sign::Positive),
        &r
    ));
    let x = r.a.get(0, 0).clone();
    r.a.set(0, 0, Q.add(&x, &Q.one()));
    assert!(!verify(
        &Interconnection::Feedback(&g, &k, Sign::Negative),
        &r
    ));
}

// ---- the classic cancellation: minreal after feedback drops the order ----

#[test]
fn cancellation_after_feedback_minreal_drops_order() {
    // plant 1/((s+1)(s+2)), PI controller 10 (s+1)/s cancels the plant pole at -1:
    // L = 10/(s(s+2)) realized with 3 states, T = L/(1+L) = 10/(s^2 + 2 s + 10)
    let plant = ss(&[&[0, 1], &[-2, -3]], &[&[0], &[1]], &[&[1, 0]], &[&[0]]);
    let pi = ss(&[&[0]], &[&[1]], &[&[10]], &[&[10]]);
    let l = check_series(&plant, &pi);
    let t = check_feedback(&l, &static_gain(q(&[&[1]])), Sign::Negative);
    assert_eq!(t.nstates(), 3);
    assert_eq!(tf(&t).to_strings(), vec![vec!["(10)/(s^2 + 2*s + 10)"]]);
    for method in [
        MinrealMethod::Kalman,
        MinrealMethod::Rosenbrock,
        MinrealMethod::HoKalman,
    ] {
        let m = minimal(&t, method).unwrap();
        assert!(m.verified);
        assert_eq!(m.order, 2, "{method:?}: the cancelled pole at -1 is gone");
        assert_eq!(tf(&m.system), tf(&t));
    }
}

// ---- other fields ----

#[test]
fn over_q_sqrt2() {
    let k = QuadraticField::new(2).unwrap();
    let sqrt2 = Quadratic::new(
        Rational::from_integer(0.into()),
        Rational::from_integer(1.into()),
    );
    let sys = StateSpace::new(
        g_mimo().a.convert_to(&k),
        g_mimo().b.convert_to(&k),
        g_mimo().c.convert_to(&k),
        g_mimo().d.convert_to(&k),
    )
    .unwrap();
    let gain = Matrix::from_rows(
        k.clone(),
        vec![vec![sqrt2.clone(), k.zero()], vec![k.one(), sqrt2]],
    )
    .unwrap();
    check_feedback(&sys, &static_gain(gain), Sign::Negative);
    check_series(&sys, &sys);
}

#[test]
fn over_q_of_parameters_closed_loop_formula() {
    let k = RatFuncField::new(&["a", "k"]).unwrap();
    let e = |t: &str| k.parse(t).unwrap();
    let m = |rows: Vec<Vec<&str>>| {
        Matrix::from_rows(
            k.clone(),
            rows.into_iter()
                .map(|r| r.into_iter().map(e).collect())
                .collect(),
        )
        .unwrap()
    };
    // G = 1/(s + a), K = k: T = 1/(s + a + k); G2 = 1/(s - k) in series
    let g = StateSpace::new(
        m(vec![vec!["-a"]]),
        m(vec![vec!["1"]]),
        m(vec![vec!["1"]]),
        m(vec![vec!["0"]]),
    )
    .unwrap();
    let gain = static_gain(m(vec![vec!["k"]]));
    let t = check_feedback(&g, &gain, Sign::Negative);
    assert_eq!(t.a.get(0, 0), &e("-a - k"));
    let g2 = StateSpace::new(
        m(vec![vec!["k"]]),
        m(vec![vec!["1"]]),
        m(vec![vec!["a"]]),
        m(vec![vec!["1"]]),
    )
    .unwrap();
    check_series(&g, &g2);
    check_parallel(&g, &g2);
    check_feedback(&g, &g2, Sign::Positive);
    check_append(&[g, g2]);
}

// ---- descriptor parts: E = diag(E1, E2) ----

#[test]
fn descriptor_series_with_an_improper_part() {
    // G1 = s + 1 (improper, E singular), G2 = 1/(s+2)^2: G2 G1 = (s+1)/(s+2)^2
    let g1 = Descriptor::new(
        q(&[&[0, 1], &[0, 0]]),
        q(&[&[1, 0], &[0, 1]]),
        q(&[&[0], &[-1]]),
        q(&[&[1, 1]]),
        q(&[&[0]]),
    )
    .unwrap();
    let g2s = ss(&[&[0, 1], &[-4, -4]], &[&[0], &[1]], &[&[1, 0]], &[&[0]]);
    let g2 = Descriptor::from_standard(&g2s);
    let t1 = descriptor_transfer_matrix(&g1).unwrap();
    assert_eq!(t1.to_strings(), vec![vec!["s + 1"]]);
    let r = series(&g1, &g2).unwrap();
    let tr = descriptor_transfer_matrix(&r).unwrap();
    assert_eq!(tr, tf(&g2s).try_mul(&t1, &Q).unwrap());
    assert_eq!(tr.to_strings(), vec![vec!["(s + 1)/(s^2 + 4*s + 4)"]]);
    assert!(verify(&Interconnection::Series(&g1, &g2), &r));
    let mut wrong = r.clone();
    wrong.d.set(0, 0, Q.one());
    assert!(
        !verify(&Interconnection::Series(&g1, &g2), &wrong),
        "the points check fails too"
    );
    let p = parallel(&g1, &g2).unwrap();
    assert_eq!(
        descriptor_transfer_matrix(&p).unwrap(),
        t1.try_add(&tf(&g2s)).unwrap()
    );
    let one = Descriptor::from_standard(&static_gain(q(&[&[1]])));
    let fb = feedback(&g2, &one, Sign::Negative).unwrap();
    assert!(verify(
        &Interconnection::Feedback(&g2, &one, Sign::Negative),
        &fb
    ));
}

// ---- properties: random small systems (fixed seed) ----

fn random_ss(rng: &mut SplitMix64, p: usize, m: usize) -> StateSpace<Q> {
    let n = rng.int(0, 3) as usize;
    let mut mat = |r: usize, c: usize, lo: i64, hi: i64| {
        let v: Vec<Rational> = (0..r * c)
            .map(|_| Rational::from_integer(rng.int(lo, hi).into()))
            .collect();
        Matrix::from_vec(Q, r, c, v)
    };
    let a = mat(n, n, -3, 3);
    let b = mat(n, m, -2, 2);
    let c = mat(p, n, -2, 2);
    let d = mat(p, m, -1, 1);
    StateSpace::new(a, b, c, d).unwrap()
}

#[test]
fn random_systems_satisfy_the_transfer_identities() {
    let mut rng = SplitMix64(0x1c0_2026);
    let mut ill_posed = 0;
    for _ in 0..40 {
        let (p, m, r) = (
            rng.int(1, 2) as usize,
            rng.int(1, 2) as usize,
            rng.int(1, 2) as usize,
        );
        let g1 = random_ss(&mut rng, r, m);
        let g2 = random_ss(&mut rng, p, r);
        let s12 = check_series(&g1, &g2);
        // the check by values (descriptor path) agrees with the one on Markov parameters
        let (d1, d2) = (
            Descriptor::from_standard(&g1),
            Descriptor::from_standard(&g2),
        );
        let ds = Descriptor::from_standard(&s12);
        assert!(verify(&Interconnection::Series(&d1, &d2), &ds));
        let g3 = random_ss(&mut rng, r, m);
        check_parallel(&g1, &g3);
        check_append(&[g1.clone(), g2.clone()]);
        let k = random_ss(&mut rng, m, r);
        for sign in [Sign::Negative, Sign::Positive] {
            // I - s D_K D_G singular <=> ill-posed
            let f = &Matrix::identity(Q, m) - &(&k.d * &g1.d).scale(&sign.value(&Q));
            match feedback(&g1, &k, sign) {
                Err(Error::IllPosed(_)) => {
                    assert!(f.inverse().is_err());
                    ill_posed += 1;
                }
                Err(e) => panic!("{e}"),
                Ok(_) => {
                    assert!(f.inverse().is_ok());
                    check_feedback(&g1, &k, sign);
                }
            }
        }
    }
    assert!(ill_posed > 0, "the generator reaches ill-posed loops");
}
