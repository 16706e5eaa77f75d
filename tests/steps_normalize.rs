//! The papers' normalisations of Jordan chains (`jordan --steps --normalize`, issue 27 item
//! 2) and `minreal --descriptor --steps`: every identity recomputed from the step data.
//!
//! * eq. 31 (`orth`): each generalized eigenvector orthogonal to its eigenvector, the chain
//!   still a chain of N spanning the same space (so A V' = V' J);
//! * `entry` / `entry:<row>`: that entry of the eigenvector is 1;
//! * `unit`: v_1 . v_1 = 1 when the root is rational, else = n (closed form V' / sqrt n);
//!   refused for a non-real eigenvalue;
//! * the minimal-realization paper's eq. 32 (A_2 with `paper` = `orth,unit`);
//! * descriptor minimal realization: Markov parameters of the finite and infinite parts, the
//!   transfer matrix of the assembled realization at points, over Q and Q(p).

use crate::common;
use crate::jcommon;
use exactlti::field::{Field, Q};
use exactlti::jordan::derivation::{Derivation, StepKind};
use exactlti::jordan::normalize::{
    Normalization, Scale, dot, normalize_chain, orthogonalize_chain,
};
use exactlti::jordan::steps::{is_chain, jordan_steps_params_with, jordan_steps_with};
use exactlti::matrix::Matrix;
use exactlti::qmat;
use exactlti::ratfunc::RatFuncField;

/// Recomputes every normalisation step of `d` (for the matrix `a` over the steps' fields)
/// and returns how many steps were checked.
fn check_normalized<K: Field>(d: &Derivation<K>, a: &Matrix<K>, how: &Normalization) -> usize {
    let mut checked = 0;
    for st in d.of_kind(StepKind::Normalization) {
        let ks = d
            .of_kind(StepKind::KernelSequence)
            .find(|s| s.part == st.part)
            .expect("its eigenvalue");
        let theta = ks.scalar("theta").unwrap();
        let nm = ks.matrix("N").unwrap();
        let k = nm.field().clone();
        // the same N as A - theta I (A lifted into the part's field when it is Q)
        if a.field().to_string() == k.to_string() {
            assert_eq!(&jcommon::shifted(a, theta), nm);
        }
        let (v, w) = (st.matrix("V").unwrap(), st.matrix("Vn").unwrap());
        let s = w.ncols();
        assert!(is_chain(nm, w), "a chain of N");
        assert_eq!(v.hstack(w).unwrap().rank(), s, "the same span");
        assert_eq!(w.rank(), s);
        let w1 = w.col(0);
        if how.orthogonal {
            for j in 1..s {
                assert!(k.is_zero(&dot(&k, &w.col(j), &w1)), "Y^T X = 0 (eq. 31)");
            }
        }
        match how.scale {
            Scale::Entry(_) => {
                let r = st.count("row").unwrap() - 1;
                assert!(k.is_one(&w1[r]), "entry {r} is 1");
            }
            Scale::Unit if st.count("refused") == Some(1) => {}
            Scale::Unit => {
                let n = st.scalar("n2").unwrap();
                let got = dot(&k, &w1, &w1);
                match st.scalar("root") {
                    Some(r) => {
                        assert!(k.is_one(&got), "unit length, exact");
                        assert_eq!(&k.mul(r, r), n);
                    }
                    None => assert_eq!(&got, n, "closed form V'/sqrt(n)"),
                }
            }
            Scale::Keep => {}
        }
        assert_eq!(st.holds, Some(true));
        checked += 1;
    }
    assert!(d.verified());
    checked
}

/// The minimal-realization paper's eq. 29-32: A_2 with `paper` (= orth,unit). The chain of
/// -1 is the paper's (1, 0, -1, 0)/sqrt 2, (1, 0, 1, 0)/(2 sqrt 2): V' = [(1,0,-1,0),
/// (1/2, 0, 1/2, 0)] with n = 2 (closed form); the chain of 0 is e_2, e_4 (n = 1, exact).
#[test]
fn paper_eq_32_orthogonal_unit_chains() {
    let a = qmat![[0, 0, 1, 0], [0, 0, 0, 1], [-1, 0, -2, 0], [0, 0, 0, 0]];
    let how: Normalization = "paper".parse().unwrap();
    let d = jordan_steps_with(&a, &how).unwrap();
    let aq = a.map(&d.field, |x| d.field.from_rational(x));
    assert_eq!(check_normalized(&d, &aq, &how), 2);
    for st in d.of_kind(StepKind::Normalization) {
        let w = st.matrix("Vn").unwrap();
        let k = w.field().clone();
        let q = |x: &_| k.to_rational(x).unwrap();
        let col = |j: usize| w.col(j).iter().map(q).collect::<Vec<_>>();
        let ks = d
            .of_kind(StepKind::KernelSequence)
            .find(|s| s.part == st.part);
        let theta = q(ks.unwrap().scalar("theta").unwrap());
        let r = |n: i64, dd: i64| exactlti::field::Rational::new(n.into(), dd.into());
        if theta == r(-1, 1) {
            // X up to its sign, Y = X-orthogonal solution of (A + I) Y = X
            let s = col(0)[0].clone();
            assert_eq!(col(0), vec![s.clone(), r(0, 1), -s.clone(), r(0, 1)]);
            assert_eq!(col(1), vec![&s / r(2, 1), r(0, 1), &s / r(2, 1), r(0, 1)]);
            assert_eq!(q(st.scalar("n2").unwrap()), &s * &s * r(2, 1));
            assert!(st.scalar("root").is_none(), "sqrt 2 is not rational");
        } else {
            assert_eq!(theta, r(0, 1));
            assert!(st.scalar("root").is_some(), "e_2 has length 1");
        }
    }
    // the text says which case it is
    let text = exactlti::report::derivation_report(&d).to_text();
    assert!(text.contains("closed form"), "{text}");
    assert!(text.contains("Unit length, exact"), "{text}");
}

/// Property: on planted Jordan matrices (blocks up to 4, rational eigenvalues) every
/// normalisation keeps the chains and establishes its identity.
#[test]
fn planted_chains_every_normalisation() {
    let hows = ["orth", "entry", "entry:2", "unit", "orth,entry", "paper"];
    for seed in 0..common::iters(10) as u64 {
        let n = 3 + (seed as usize % 5);
        let (a, _) = jcommon::planted(n, seed);
        for h in hows {
            let how: Normalization = h.parse().unwrap();
            let d = jordan_steps_with(&a, &how).unwrap();
            let aq = a.map(&d.field, |x| d.field.from_rational(x));
            let chains: usize = d
                .of_kind(StepKind::WeyrSegre)
                .map(|s| s.counts("segre").unwrap().len())
                .sum();
            assert_eq!(check_normalized(&d, &aq, &how), chains, "seed {seed} {h}");
        }
    }
}

/// A complex pair: unit length is refused (v . v is no length there), entry 1 is exact in
/// Q(t); an isotropic eigenvector ((1, i) of a rotation) cannot be orthogonalised.
#[test]
fn complex_eigenvalues_refuse_unit_length() {
    let a = qmat![[0, 1, 0], [-1, 0, 0], [0, 0, 2]];
    for h in ["unit", "entry"] {
        let how: Normalization = h.parse().unwrap();
        let d = jordan_steps_with(&a, &how).unwrap();
        let aq = a.map(&d.field, |x| d.field.from_rational(x));
        check_normalized(&d, &aq, &how);
        let refused = d
            .of_kind(StepKind::Normalization)
            .filter(|s| s.count("refused") == Some(1))
            .count();
        assert_eq!(refused, usize::from(h == "unit"), "{h}");
    }
    // (1, i) . (1, i) = 0: a chain over it has no orthogonal normalisation
    let k = exactlti::field::QuadraticField::new(-1).unwrap();
    let i = k.gen_elem();
    let v = Matrix::from_vec(k.clone(), 2, 2, vec![k.one(), k.zero(), i, k.one()]);
    assert!(orthogonalize_chain(&v).is_err());
}

/// Over Q(p): the vehicle paper's yaw plane (eq. 27, a chain of length 3 at 0) made
/// orthogonal and with its first entry 1; the constants are rational functions.
#[test]
fn symbolic_chains_normalised() {
    let (_, a) = jcommon::yaw27();
    for h in ["orth", "orth,entry", "unit"] {
        let how: Normalization = h.parse().unwrap();
        let d = jordan_steps_params_with(&a, &how).unwrap();
        let a2 = Matrix::from_vec(d.field.clone(), 4, 4, a.as_slice().to_vec());
        assert_eq!(check_normalized(&d, &a2, &how), 2, "{h}");
        // A T = T J with the normalised T
        let sim = d.of_kind(StepKind::Similarity).next().unwrap();
        let (t, j) = (sim.matrix("T").unwrap(), sim.matrix("J").unwrap());
        assert_eq!(&a2 * t, t * j, "{h}");
        let top3 = d
            .of_kind(StepKind::Normalization)
            .find(|s| s.count("top") == Some(3))
            .unwrap();
        if h.starts_with("orth") {
            assert_eq!(top3.matrix("b").unwrap().ncols(), 2, "b_1, b_2");
        }
    }
}

/// The chain's own algebra: orthogonalising a chain of a nilpotent block keeps v_1.
#[test]
fn orthogonalize_keeps_the_eigenvector() {
    let n = qmat![[0, 1, 0], [0, 0, 1], [0, 0, 0]];
    let v = qmat![[1, 3, 2], [0, 1, 3], [0, 0, 1]];
    assert!(is_chain(&n, &v));
    let (w, b) = orthogonalize_chain(&v).unwrap();
    assert_eq!(b.len(), 2);
    assert_eq!(w.col(0), v.col(0));
    assert!(is_chain(&n, &w));
    let c = normalize_chain(&v, &"entry:1".parse().unwrap(), true).unwrap();
    assert!(Q.is_one(&c.v.col(0)[0]));
    // bad lists are refused with the reason
    for bad in ["", "unit,entry", "entry:0", "norm"] {
        assert!(bad.parse::<Normalization>().is_err(), "{bad}");
    }
}

fn json(args: &[&str]) -> serde_json::Value {
    common::cli::json_of(args)
}

/// The command line: `jordan --steps --normalize paper` on the vehicle paper's model; bad
/// lists and `--normalize` without `--steps` over Q(p) exit 2 with the reason.
#[test]
fn cli_normalize() {
    let f = common::cli::temp_file(
        "normalize",
        "a2.json",
        r#"{"A": [[0, 0, 1, 0], [0, 0, 0, 1], [-1, 0, -2, 0], [0, 0, 0, 0]]}"#,
    );
    let p = f.to_str().unwrap();
    let j = json(&[
        "jordan",
        p,
        "--steps",
        "--normalize",
        "paper",
        "--format",
        "json",
    ]);
    assert_eq!(j["verified"], true);
    let norm: Vec<_> = j["steps"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|s| s["step"] == "normalization")
        .collect();
    assert_eq!(norm.len(), 2);
    for (args, want) in [
        (
            vec!["jordan", p, "--steps", "--normalize", "bogus"],
            "bogus",
        ),
        (
            vec!["jordan", p, "--real", "--steps", "--normalize", "unit"],
            "--real",
        ),
    ] {
        let (code, _, err) = common::cli::run(&args);
        assert_eq!(code, 2, "{args:?}");
        assert!(err.contains(want), "{err}");
    }
    // plain --normalize answers over Q(p) too (was refused: "add --steps"); A T = T J
    // re-checked (tests/steps_modes_fields.rs asserts it on the matrices)
    let sym = common::cli::run_json(&[
        "jordan",
        "data/sliding-masses-symbolic.json",
        "--normalize",
        "unit",
    ]);
    assert_eq!(sym["verified"], true);
    // every factor of the sliding masses' chi is s^2 + c k/m (degree 2): primary blocks, kept
    assert!(
        sym["normalize_note"]
            .as_str()
            .unwrap()
            .contains("primary block")
    );
    let (code, out, _) = common::cli::run(&[
        "jordan",
        p,
        "--steps",
        "--normalize",
        "orth,entry",
        "--format",
        "latex",
        "--standalone",
    ]);
    assert_eq!(code, 0);
    assert!(out.contains("V'"), "{out}");
}

/// `minreal --descriptor --steps` over Q: an improper file (G = s - 1 with a hidden mode,
/// 4 -> 2) and a proper one; every step holds and the last step's realization has the
/// order the command reports.
#[test]
fn descriptor_minimal_steps() {
    for (file, order) in [
        ("tests/data/improper_s.json", 2),
        ("data/models/quarter-car-2mass.toml", 4),
    ] {
        let j = json(&[
            "minreal",
            file,
            "--descriptor",
            "--steps",
            "--format",
            "json",
        ]);
        assert_eq!(j["verified"], true, "{file}");
        let names: Vec<_> = j["steps"]
            .as_array()
            .unwrap()
            .iter()
            .map(|s| s["step"].as_str().unwrap().to_string())
            .collect();
        assert_eq!(
            names,
            [
                "fitting_split",
                "finite_part",
                "infinite_part",
                "nondynamic_modes",
                "minimal_descriptor"
            ]
        );
        let last = j["steps"].as_array().unwrap().last().unwrap().clone();
        assert_eq!(last["orders"][2], order, "{file}");
        let plain = json(&["minreal", file, "--descriptor", "--format", "json"]);
        assert_eq!(plain["verified"], true);
        assert_eq!(plain["order"], order, "{file}");
    }
}

/// The library path, over Q and Q(p): each step's identity recomputed (Markov parameters of
/// the finite and infinite parts, the same transfer matrix at points).
#[test]
fn descriptor_minimal_steps_identities_over_q_and_qp() {
    use exactlti::jordan::derivation::Recorder;
    use exactlti::jordan::derivation::{Method, ratfunc_log};
    use exactlti::realization::minimal_descriptor_recorded;
    use exactlti::system::Descriptor;
    fn check<K: Field>(d: &Derivation<K>, sys: &Descriptor<K>) {
        assert!(d.verified());
        let fin = d.of_kind(StepKind::DescriptorFinite).next().unwrap();
        let m = |s: &exactlti::jordan::derivation::Step<K>, k: &str| s.matrix(k).unwrap().clone();
        let markov =
            |a: &Matrix<K>, b: &Matrix<K>, c: &Matrix<K>, j: u32| c * &(&a.pow(j).unwrap() * b);
        for j in 0..6 {
            assert_eq!(
                markov(&m(fin, "Af"), &m(fin, "Bf"), &m(fin, "Cf"), j),
                markov(&m(fin, "Am"), &m(fin, "Bm"), &m(fin, "Cm"), j)
            );
        }
        let inf = d.of_kind(StepKind::DescriptorInfinite).next().unwrap();
        for j in 0..6 {
            assert_eq!(
                markov(&m(inf, "N"), &m(inf, "Binf"), &m(inf, "Cinf"), j),
                markov(&m(inf, "Nr"), &m(inf, "Br"), &m(inf, "Cr"), j)
            );
        }
        let last = d.of_kind(StepKind::DescriptorMinimalForm).next().unwrap();
        let out = Descriptor::new(
            m(last, "E"),
            m(last, "A"),
            m(last, "B"),
            m(last, "C"),
            m(last, "D"),
        )
        .unwrap();
        let k = sys.a.field().clone();
        for t in 2..6 {
            let s0 = k.from_i64(t * 3 + 1);
            assert_eq!(
                exactlti::realization::eval_transfer(sys, &s0),
                exactlti::realization::eval_transfer(&out, &s0),
                "G(s0)"
            );
        }
    }
    let e = qmat![[0, 1, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, 1]];
    let a = qmat![[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, -3]];
    let (b, c, dd) = (qmat![[0], [-1], [1], [1]], qmat![[1, 0, 1, 0]], qmat![[0]]);
    let sys = Descriptor::new(e, a, b, c, dd).unwrap();
    let mut rec = Recorder::new(Method::DescriptorMinimal, Q);
    minimal_descriptor_recorded(&sys, Some(&mut rec)).unwrap();
    check(&rec.finish(), &sys);
    // over Q(k): E x' = A x + B u with a parameter in the finite and the infinite part
    let k = RatFuncField::new(&["k"]).unwrap();
    let mk = |rows: &[&[&str]]| crate::common::qp_matrix(&k, rows);
    let sys = Descriptor::new(
        mk(&[&["0", "1", "0"], &["0", "0", "0"], &["0", "0", "1"]]),
        mk(&[&["1", "0", "0"], &["0", "1", "0"], &["0", "0", "-k"]]),
        mk(&[&["0"], &["-1"], &["k"]]),
        mk(&[&["k", "0", "1"]]),
        mk(&[&["0"]]),
    )
    .unwrap();
    let mut rec = Recorder::with_log(Method::DescriptorMinimal, k.clone(), ratfunc_log(&k));
    minimal_descriptor_recorded(&sys, Some(&mut rec)).unwrap();
    check(&rec.finish(), &sys);
}

/// The audit of issue 27's Done-when: `minreal --method rosenbrock|ho-kalman --steps` over
/// Q(p) (the chain of masses with symbols m, k, c): every step holds, the minimal part's
/// Markov parameters are the system's (recomputed), its order is the McMillan degree, and
/// the conditions assumed are recorded.
#[test]
fn rosenbrock_and_ho_kalman_steps_over_qp() {
    use exactlti::jordan::derivation::{Method, Recorder, ratfunc_log};
    use exactlti::realization::{
        mcmillan_degree, minimal_ho_kalman_recorded, minimal_rosenbrock_recorded,
    };
    use exactlti::system::StateSpace;
    let sys = common::systems::chain_qp(2);
    let k = sys.field().fresh();
    let mv =
        |m: &Matrix<_>| Matrix::from_vec(k.clone(), m.nrows(), m.ncols(), m.as_slice().to_vec());
    let s = StateSpace::new(mv(&sys.a), mv(&sys.b), mv(&sys.c), mv(&sys.d)).unwrap();
    for method in [Method::Rosenbrock, Method::HoKalman] {
        let mut rec = Recorder::with_log(method, k.clone(), ratfunc_log(&k));
        if method == Method::Rosenbrock {
            minimal_rosenbrock_recorded(&s, Some(&mut rec)).unwrap();
        } else {
            minimal_ho_kalman_recorded(&s, Some(&mut rec)).unwrap();
        }
        let d = rec.finish();
        assert!(d.verified(), "{method:?}");
        let mp = d
            .of_kind(StepKind::MinimalPart)
            .next()
            .or_else(|| d.of_kind(StepKind::HankelFactor).next())
            .unwrap();
        let m = |key: &str| mp.matrix(key).unwrap().clone();
        let min = StateSpace::new(m("Am"), m("Bm"), m("Cm"), s.d.clone()).unwrap();
        let n = s.nstates() + min.nstates();
        assert_eq!(s.markov(n), min.markov(n), "{method:?}");
        assert_eq!(min.nstates(), mcmillan_degree(&s), "{method:?}");
        if method == Method::Rosenbrock {
            let st = d.of_kind(StepKind::Staircase).next().unwrap();
            let t = st.matrix("T").unwrap();
            assert_eq!(&s.a * t, t * st.matrix("At").unwrap(), "A T = T At");
        }
    }
}

/// |B| = |Bt| (the minimal-realization paper after eq. 36) on a repeated real mode: two
/// copies of -1 (SISO) compact to one; the step scales Bt, Ct with a^2 = |B|^2 / |Bt|^2,
/// exact when a is rational (B = (3, 4): |B| = 5) and in closed form otherwise (B = (1, 2)).
#[test]
fn compaction_matches_the_input_norm() {
    use exactlti::realization::steps::jordan_method_steps;
    use exactlti::system::StateSpace;
    let mut exact_seen = [false, false];
    for (b1, b2) in [(3, 4), (1, 2)] {
        let a = qmat![[-1, 0], [0, -1]];
        let s = StateSpace::new(a, qmat![[b1], [b2]], qmat![[5, 7]], qmat![[0]]).unwrap();
        let d = jordan_method_steps(&s).unwrap();
        assert!(d.verified());
        let nm = d.of_kind(StepKind::NormMatch).next().expect("a norm step");
        let k = nm.matrix("Bt").unwrap().field().clone();
        let dropped = d.of_kind(StepKind::DropModes).next().unwrap();
        let (bk, ck) = (dropped.matrix("Bk").unwrap(), dropped.matrix("Ck").unwrap());
        let (bt, ct) = (nm.matrix("Bt").unwrap(), nm.matrix("Ct").unwrap());
        let sq = |m: &Matrix<_>| dot(&k, m.as_slice(), m.as_slice());
        // C B is the only Markov parameter shape here (J = -1 I): Ct Bt = C B
        assert_eq!(ct * bt, ck * bk);
        assert_eq!(nm.scalar("nB"), Some(&sq(bk)));
        assert_eq!(
            k.mul(nm.scalar("a2").unwrap(), nm.scalar("nBt").unwrap()),
            sq(bk)
        );
        let exact = nm.scalar("a").is_some();
        if exact {
            assert_eq!(sq(bt), sq(bk), "|Bt| = |B|");
        }
        exact_seen[usize::from(exact)] = true;
    }
    assert_eq!(exact_seen, [true, true], "both cases met");
}

/// T = I when the system is already in mechanical normal form, over Q (the Q(p) case is
/// the paper's App. B in `tests/steps_forms.rs`): A = [0, I; -K, -D], B = [0; I]; the search
/// step takes T = I, which solves eq. 15, and the form's K and D are read back.
#[test]
fn mnf_of_a_normal_form_is_the_identity_over_q() {
    use exactlti::jordan::derivation::{Method, Recorder};
    use exactlti::structure::mechanical::{
        DEFAULT_MAX_CANDIDATES, mechanical_normal_form_recorded,
    };
    let a = qmat![[0, 0, 1, 0], [0, 0, 0, 1], [-2, 1, -3, 0], [1, -2, 0, -1]];
    let b = qmat![[0], [0], [1], [0]];
    let b = b.hstack(&qmat![[0], [0], [0], [1]]).unwrap();
    let c = qmat![[1, 0, 0, 0]];
    let d = qmat![[0, 0]];
    let mut rec = Recorder::new(Method::Mnf, Q);
    mechanical_normal_form_recorded(
        None,
        [&a, &b, &c, &d],
        DEFAULT_MAX_CANDIDATES,
        Some(&mut rec),
    )
    .unwrap();
    let der = rec.finish();
    assert!(der.verified());
    let se = der.of_kind(StepKind::MnfSearch).next().unwrap();
    assert_eq!(se.count("t_equals_i"), Some(1));
    let t = se.matrix("T").unwrap();
    assert!(t.is_identity());
    // T = I solves eq. 15: T A = A has the normal form's rows [0 I] on top, T B = B = [0; I]
    assert_eq!(
        &(t * &a).submatrix(0, 2, 0, 4),
        &qmat![[0, 0, 1, 0], [0, 0, 0, 1]]
    );
    let fm = der.of_kind(StepKind::MnfForm).next().unwrap();
    assert_eq!(fm.matrix("Kq").unwrap(), &qmat![[2, -1], [-1, 2]]);
    assert_eq!(fm.matrix("Dq").unwrap(), &qmat![[3, 0], [0, 1]]);
}
