//! `--steps` (issue 27): the derivations of `jordan` and `minreal` (Kalman, Jordan method) as
//! data. Every test asserts the identities of the recorded steps by recomputing them from the
//! input (ranks, chains, Markov parameters), over Q and over Q(p); the vehicle paper's
//! yaw-plane example (eq. 27-35) and the minimal-realization paper's 20 -> 16 -> 8.

use crate::common;
use crate::jcommon;
use exactlti::field::ElemDisplay;
use exactlti::field::{Field, Q, Rational};
use exactlti::jordan::derivation::{Derivation, Object, StepKind, ratfunc_log};
use exactlti::jordan::steps::{is_chain, jordan_steps, jordan_steps_params, weyr_segre};
use exactlti::matrix::Matrix;
use exactlti::poly::Poly;
use exactlti::ratfunc::RatFuncField;
use exactlti::realization::steps::{jordan_method_steps, kalman_steps};
use exactlti::realization::{mcmillan_degree, observability_matrix};
use exactlti::system::StateSpace;

/// Checks every Jordan step of `d` (for the input `a_of(part)` over the part's field) against
/// recomputed values; returns the block sizes per part.
fn check_jordan<K: Field + 'static>(d: &Derivation<K>, a: &Matrix<K>) -> Vec<Vec<usize>> {
    assert!(d.verified(), "a step failed");
    let chi = d.of_kind(StepKind::CharPoly).next().expect("charpoly");
    let Some(Object::Poly(p)) = chi.get("chi") else {
        panic!("chi")
    };
    assert!(a.eval_poly(p).unwrap().is_zero(), "Cayley-Hamilton");
    let mut all_blocks = vec![];
    for ks in d.of_kind(StepKind::KernelSequence) {
        let n_mat = ks.matrix("N").unwrap();
        let theta = ks.scalar("theta").unwrap();
        let lifted = a.map(n_mat.field(), |x| x.clone());
        assert_eq!(n_mat, &jcommon::shifted(&lifted, theta), "N = A - theta I");
        let ranks = ks.counts("ranks").unwrap();
        let dims = ks.counts("dims").unwrap();
        let mut pw = n_mat.clone();
        for (i, &r) in ranks.iter().enumerate() {
            assert_eq!(pw.rank(), r, "rank N^{} recomputed", i + 1);
            assert_eq!(dims[i], n_mat.nrows() - r);
            pw = &pw * n_mat;
        }
        assert_eq!(*dims.last().unwrap(), ks.count("m").unwrap());
        let part = ks.part;
        let ws = d
            .of_kind(StepKind::WeyrSegre)
            .find(|s| s.part == part)
            .unwrap();
        let (w, s) = weyr_segre(dims);
        assert_eq!(ws.counts("weyr").unwrap(), w.as_slice());
        assert_eq!(ws.counts("segre").unwrap(), s.as_slice());
        // each chain: N v_1 = 0, N v_j = v_{j-1}, recomputed column by column
        let mut lengths = vec![];
        for ch in d.of_kind(StepKind::Chain).filter(|s| s.part == part) {
            let v = ch.matrix("V").unwrap();
            let nv = n_mat * v;
            let n = v.nrows();
            assert!(nv.submatrix(0, n, 0, 1).is_zero(), "N v_1 = 0");
            assert!(!v.submatrix(0, n, 0, 1).is_zero(), "v_1 != 0");
            for j in 1..v.ncols() {
                assert_eq!(nv.submatrix(0, n, j, j + 1), v.submatrix(0, n, j - 1, j));
            }
            lengths.push(v.ncols());
        }
        assert_eq!(lengths, s, "chains = Segre characteristic");
        let ec = d
            .of_kind(StepKind::EigenCheck)
            .find(|s| s.part == part)
            .unwrap();
        let (v, j) = (ec.matrix("V").unwrap(), ec.matrix("J").unwrap());
        assert_eq!(&lifted * v, v * j, "A V = V J");
        assert_eq!(v.rank(), v.ncols());
        all_blocks.push(lengths);
    }
    all_blocks
}

#[test]
fn planted_jordan_steps_identities() {
    for seed in 0..common::iters(12) as u64 {
        let n = 3 + (seed as usize % 5);
        let (a, blocks) = jcommon::planted(n, seed);
        let d = jordan_steps(&a).unwrap();
        let aq = a.map(&d.field, |x| d.field.from_rational(x));
        let got = check_jordan(&d, &aq);
        // the planted blocks per eigenvalue, largest first
        let ks: Vec<_> = d.of_kind(StepKind::KernelSequence).collect();
        for (ks, got_blocks) in ks.iter().zip(&got) {
            let theta = ks.scalar("theta").unwrap();
            let theta_q = ks.matrix("N").unwrap().field().to_rational(theta).unwrap();
            let mut want: Vec<usize> = blocks
                .iter()
                .filter(|(l, _)| *l == theta_q)
                .map(|(_, s)| *s)
                .collect();
            want.sort_unstable_by(|x, y| y.cmp(x));
            assert_eq!(got_blocks, &want, "seed {seed}");
        }
        let sim = d.of_kind(StepKind::Similarity).next().unwrap();
        assert_eq!(sim.count("n"), Some(n));
        assert_eq!(sim.counts("dims").unwrap().iter().sum::<usize>(), n);
    }
}

#[test]
fn irrational_eigenvalues_worked_once_per_factor() {
    // chi = (x^2 + 1)^2 with one 2-block per root, worked in Q[t]/(t^2 + 1)
    let a = jcommon::companion_pair_chain(&[1, 0, 1], 3);
    let d = jordan_steps(&a).unwrap();
    let blocks = check_jordan(&d, &a.map(&d.field, |x| d.field.from_rational(x)));
    assert_eq!(blocks, vec![vec![2]]);
    let ks: Vec<_> = d.of_kind(StepKind::KernelSequence).collect();
    assert!(
        ks.iter()
            .any(|s| s.matrix("N").unwrap().field().degree() == 2)
    );
}

#[test]
fn a_broken_chain_is_detected() {
    let a = jcommon::yaw_plane(
        Rational::from_integer(1500.into()),
        Rational::from_integer(2000.into()),
        Rational::from_integer(0.into()),
        Rational::from_integer(0.into()),
        Rational::from_integer(0.into()),
        Rational::from_integer(80000.into()),
        Rational::from_integer(20.into()),
    );
    let d = jordan_steps(&a).unwrap();
    let ch = d
        .of_kind(StepKind::Chain)
        .find(|s| s.count("top") == Some(3))
        .unwrap();
    let ks = d.of_kind(StepKind::KernelSequence).next().unwrap();
    let n_mat = ks.matrix("N").unwrap();
    let v = ch.matrix("V").unwrap();
    assert!(is_chain(n_mat, v));
    let mut bad = v.clone();
    let k = bad.field().clone();
    let x = k.add(bad.get(1, 2), &k.one());
    bad.set(1, 2, x);
    assert!(!is_chain(n_mat, &bad));
    assert!(!is_chain(n_mat, &Matrix::zeros(k, 4, 1)));
}

#[test]
fn yaw_plane_single_wheel_reproduces_the_paper() {
    let (k, a) = jcommon::yaw27();
    let d = jordan_steps_params(&a).unwrap();
    let blocks = check_jordan(&d, &a);
    assert_eq!(
        blocks,
        vec![vec![3], vec![1]],
        "a 3-block at 0, s = -cr/(m u)"
    );
    let p = |s: &str| k.parse(s).unwrap();
    let ks: Vec<_> = d.of_kind(StepKind::KernelSequence).collect();
    assert_eq!(ks[0].scalar("theta"), Some(&k.zero()));
    assert_eq!(ks[0].counts("dims"), Some(&[1usize, 2, 3][..]));
    assert_eq!(ks[1].scalar("theta"), Some(&p("-cr/(m*u)")), "eq. 29");
    let chain = |top| {
        d.of_kind(StepKind::Chain)
            .find(|s| s.count("top") == Some(top))
            .unwrap()
            .matrix("V")
            .unwrap()
            .clone()
    };
    let v = chain(3);
    let x1 = v.col(0);
    // eq. 28: X1 along e1; eq. 30: Y1 = (x1, x2, 0, 0); eq. 32: Z1 = (x3, x4, -x5 m u^2/cr, x5)
    assert!(x1[1..].iter().all(|x| k.is_zero(x)) && !k.is_zero(&x1[0]));
    assert!(k.is_zero(v.get(2, 1)) && k.is_zero(v.get(3, 1)));
    let want = k.mul(&k.neg(v.get(3, 2)), &p("m*u^2/cr"));
    assert_eq!(v.get(2, 2), &want, "eq. 32");
    // eq. 28: X2 along (m u / cr, 0, 1, 0)
    let x2 = chain(1).col(0);
    let ratio = k.div(&x2[0], &x2[2]).unwrap();
    assert_eq!(ratio, p("m*u/cr"));
    assert!(k.is_zero(&x2[1]) && k.is_zero(&x2[3]));
    // the paper's own T (eq. 34) and J (eq. 35) satisfy A T = T J
    let mk = |rows: &[[&str; 4]]| {
        Matrix::from_rows(
            k.clone(),
            rows.iter()
                .map(|r| r.iter().map(|s| p(s)).collect())
                .collect(),
        )
        .unwrap()
    };
    let t34 = mk(&[
        ["1", "0", "0", "m*u/cr"],
        ["0", "1/u", "m/cr", "0"],
        ["0", "0", "m*u/cr", "1"],
        ["0", "0", "-1/u", "0"],
    ]);
    let j35 = mk(&[
        ["0", "1", "0", "0"],
        ["0", "0", "1", "0"],
        ["0", "0", "0", "0"],
        ["0", "0", "0", "-cr/(m*u)"],
    ]);
    assert_eq!(&a * &t34, &t34 * &j35);
    let sim = d.of_kind(StepKind::Similarity).next().unwrap();
    let (t, j) = (sim.matrix("T").unwrap(), sim.matrix("J").unwrap());
    assert_eq!(j.map(&k, |x| x.clone()), j35, "J of eq. 35");
    // the chains built top-down are the paper's choice (eq. 33): T is eq. 34 exactly
    assert_eq!(t.map(&k, |x| x.clone()), t34, "T of eq. 34");
    assert_eq!(&a.map(t.field(), |x| x.clone()) * t, t * j);
    // the conditions: cr, m, u nonzero (and nothing else)
    let conds: Vec<String> = d.assumptions().iter().map(|x| k.fmt_elem(x)).collect();
    for c in ["cr", "m", "u"] {
        assert!(conds.iter().any(|x| x == c), "{conds:?}");
    }
    // at the data file's point the rational derivation has the same structure
    let aq = Matrix::from_fn(Q, 4, 4, |i, jj| {
        let pt = [
            Rational::from_integer(80000.into()),
            Rational::from_integer(1500.into()),
            Rational::from_integer(20.into()),
        ];
        k.eval(a.get(i, jj), &pt).unwrap()
    });
    let dq = jordan_steps(&aq).unwrap();
    let bq = check_jordan(&dq, &aq.map(&dq.field, |x| dq.field.from_rational(x)));
    assert_eq!(bq, blocks);
}

#[test]
fn symbolic_irreducible_quadratic_gives_a_primary_block() {
    let k = RatFuncField::new(&["w"]).unwrap();
    let p = |s: &str| k.parse(s).unwrap();
    let a = Matrix::from_rows(
        k.clone(),
        vec![
            vec![p("0"), p("1"), p("0")],
            vec![p("-w^2"), p("0"), p("0")],
            vec![p("0"), p("0"), p("w")],
        ],
    )
    .unwrap();
    let d = jordan_steps_params(&a).unwrap();
    assert!(d.verified());
    let pb = d.of_kind(StepKind::PrimaryBlock).next().unwrap();
    let (b, m) = (pb.matrix("B").unwrap(), pb.matrix("M").unwrap());
    assert_eq!(&a.map(b.field(), |x| x.clone()) * b, b * m, "A B = B M");
    let Some(Object::Poly(f)) = pb.get("f") else {
        panic!()
    };
    assert!(a.map(f.field(), |x| x.clone()).eval_poly(f).unwrap().rank() == 1);
    assert_eq!(pb.counts("segre"), Some(&[1usize][..]));
}

/// Checks the Kalman steps against recomputed ranks, subspaces and Markov parameters.
fn check_kalman<K: Field>(d: &Derivation<K>, sys: &StateSpace<K>) -> usize {
    assert!(d.verified());
    let n = sys.nstates();
    let c = d.of_kind(StepKind::Controllability).next().unwrap();
    let ctrb = c.matrix("Ctrb").unwrap();
    assert_eq!(ctrb.rank(), c.count("rank").unwrap());
    let r = d
        .of_kind(StepKind::ControllableSubspace)
        .next()
        .unwrap()
        .matrix("R")
        .unwrap();
    assert_eq!(
        r.hstack(ctrb).unwrap().rank(),
        r.ncols(),
        "span R = im Ctrb"
    );
    assert_eq!(r.rank(), r.ncols());
    let o = d.of_kind(StepKind::Observability).next().unwrap();
    assert_eq!(
        o.matrix("Obsv").unwrap(),
        &observability_matrix(&sys.a, &sys.c)
    );
    let nn = d
        .of_kind(StepKind::UnobservableSubspace)
        .next()
        .unwrap()
        .matrix("Nobs")
        .unwrap();
    assert!((o.matrix("Obsv").unwrap() * nn).is_zero());
    assert_eq!(nn.ncols(), n - o.count("rank").unwrap());
    let t = d
        .of_kind(StepKind::KalmanBasis)
        .next()
        .unwrap()
        .matrix("T")
        .unwrap();
    let kf = d.of_kind(StepKind::KalmanForm).next().unwrap();
    let at = kf.matrix("At").unwrap();
    assert_eq!(&sys.a * t, t * at);
    let mp = d.of_kind(StepKind::MinimalPart).next().unwrap();
    let min = StateSpace::new(
        mp.matrix("Am").unwrap().clone(),
        mp.matrix("Bm").unwrap().clone(),
        mp.matrix("Cm").unwrap().clone(),
        sys.d.clone(),
    )
    .unwrap();
    let order = mp.count("order").unwrap();
    assert_eq!(min.nstates(), order);
    assert_eq!(sys.markov(n + order + 1), min.markov(n + order + 1));
    assert_eq!(order, mcmillan_degree(sys));
    order
}

#[test]
fn planted_kalman_steps_identities() {
    for seed in 0..common::iters(6) as u64 {
        let n = 4 + 2 * (seed as usize % 3);
        let pl = common::systems::planted(n, seed);
        let d = kalman_steps(&pl.sys, None).unwrap();
        assert_eq!(check_kalman(&d, &pl.sys), pl.order, "seed {seed}");
    }
}

#[test]
fn kalman_steps_over_qp_with_conditions() {
    let (k, a) = jcommon::yaw27();
    let p = |s: &str| k.parse(s).unwrap();
    let k2 = k.fresh();
    let mv = |m: &Matrix<RatFuncField>| m.map(&k2, |x| x.clone());
    let b = Matrix::from_rows(
        k.clone(),
        vec![vec![p("0")], vec![p("0")], vec![p("1/m")], vec![p("0")]],
    )
    .unwrap();
    let c = Matrix::from_rows(k.clone(), vec![vec![p("1"), p("0"), p("0"), p("0")]]).unwrap();
    let d0 = Matrix::zeros(k.clone(), 1, 1);
    let sys = StateSpace::new(mv(&a), mv(&b), mv(&c), mv(&d0)).unwrap();
    let d = kalman_steps(&sys, Some(ratfunc_log(&k2))).unwrap();
    assert_eq!(check_kalman(&d, &sys), 2);
    assert!(
        !d.assumptions().is_empty(),
        "pivots divided by are recorded"
    );
}

#[test]
fn sliding_masses_jordan_method_20_16_8() {
    let sys = common::systems::sliding_masses();
    let d = jordan_method_steps(&sys).unwrap();
    assert!(d.verified());
    let st = d.of_kind(StepKind::Stages).next().unwrap();
    assert_eq!(st.counts("stages"), Some(&[20usize, 16, 8][..]));
    assert_eq!(st.count("mcmillan"), Some(8));
    // the four modes at +-i sqrt 2 are neither excited nor observed (paper sec. 4.1)
    let dropped: Vec<_> = d
        .of_kind(StepKind::DropModes)
        .filter(|s| s.counts("kept").unwrap().is_empty())
        .collect();
    assert_eq!(dropped.len(), 1);
    let s = dropped[0];
    assert_eq!(s.count("deg"), Some(2));
    assert_eq!(s.counts("not_excited"), Some(&[0usize, 1][..]));
    assert_eq!(s.counts("not_observed"), Some(&[0usize, 1][..]));
    let modal = d
        .of_kind(StepKind::ModalData)
        .find(|m| m.part == s.part)
        .unwrap();
    let j = modal.matrix("J").unwrap();
    let f = j.field();
    let theta2 = f.mul(
        modal.scalar("theta").unwrap(),
        modal.scalar("theta").unwrap(),
    );
    assert_eq!(
        f.to_rational(&theta2),
        Some(Rational::from_integer((-2).into()))
    );
    check_markov_recombination(&d);
}

/// Per eigenvalue: the full modal block, the kept states and the compacted block have the
/// same Markov parameters (recomputed), and the orders add up to the stages.
fn check_markov_recombination(d: &Derivation<exactlti::algebraic::NumberField>) {
    let (mut s1, mut s2) = (0, 0);
    for md in d.of_kind(StepKind::ModalData) {
        let part = md.part;
        let deg = md.count("deg").unwrap();
        let full = StateSpace::new_strictly_proper(
            md.matrix("J").unwrap().clone(),
            md.matrix("WB").unwrap().clone(),
            md.matrix("CV").unwrap().clone(),
        )
        .unwrap();
        let dm = d
            .of_kind(StepKind::DropModes)
            .find(|s| s.part == part)
            .unwrap();
        let kept = StateSpace::new_strictly_proper(
            dm.matrix("Jk").unwrap().clone(),
            dm.matrix("Bk").unwrap().clone(),
            dm.matrix("Ck").unwrap().clone(),
        )
        .unwrap();
        let kk = full.nstates() * 2 + 2;
        assert_eq!(full.markov(kk), kept.markov(kk));
        s1 += kept.nstates() * deg;
        if let Some(cp) = d.of_kind(StepKind::Compaction).find(|s| s.part == part) {
            let comp = StateSpace::new_strictly_proper(
                cp.matrix("J").unwrap().clone(),
                cp.matrix("B").unwrap().clone(),
                cp.matrix("C").unwrap().clone(),
            )
            .unwrap();
            assert_eq!(full.markov(kk), comp.markov(kk));
            s2 += comp.nstates() * deg;
        }
    }
    let st = d
        .of_kind(StepKind::Stages)
        .next()
        .unwrap()
        .counts("stages")
        .unwrap();
    assert_eq!((st[1], st[2]), (s1, s2));
}

#[test]
fn planted_jordan_method_steps_recombine() {
    // repeated modes: the planted Jordan matrices with random B, C
    for seed in 0..common::iters(6) as u64 {
        let n = 4 + (seed as usize % 4);
        let (a, _) = jcommon::planted(n, seed + 100);
        let mut rng = exactlti::rng::SplitMix64(seed);
        let b = Matrix::from_fn(Q, n, 1, |_, _| {
            Rational::from_integer(rng.int(-1, 1).into())
        });
        let c = Matrix::from_fn(Q, 2, n, |_, _| {
            Rational::from_integer(rng.int(-1, 1).into())
        });
        let sys = StateSpace::new_strictly_proper(a, b, c).unwrap();
        let d = jordan_method_steps(&sys).unwrap();
        assert!(d.verified(), "seed {seed}");
        check_markov_recombination(&d);
        let st = d.of_kind(StepKind::Stages).next().unwrap();
        assert_eq!(st.counts("stages").unwrap()[2], mcmillan_degree(&sys));
    }
}

#[test]
fn charpoly_factors_multiply_back() {
    let a = jcommon::sliding_masses();
    let d = jordan_steps(&a).unwrap();
    let f = d.of_kind(StepKind::Factorization).next().unwrap();
    let Some(Object::Factors(fs)) = f.get("factors") else {
        panic!()
    };
    let k = d.field.clone();
    let prod = fs.iter().fold(Poly::one(k.clone()), |acc, (p, e)| {
        acc.mul(&p.pow(*e as u32))
    });
    let chi = a.charpoly().unwrap().map(&k, |x| k.from_rational(x));
    assert_eq!(prod, chi);
    check_jordan(&d, &a.map(&k, |x| k.from_rational(x)));
}

fn json(args: &[&str]) -> serde_json::Value {
    common::cli::json_of(args)
}

#[test]
fn cli_steps_json_text_latex() {
    let f = "data/yaw-plane-single-wheel.json";
    let j = json(&["jordan", f, "--steps", "--format", "json"]);
    assert_eq!(j["verified"], true);
    let steps = j["steps"].as_array().unwrap();
    assert_eq!(steps[0]["step"], "charpoly");
    let ks = steps
        .iter()
        .find(|s| s["step"] == "kernel_sequence")
        .unwrap();
    assert_eq!(ks["dims"], serde_json::json!([1, 2, 3]));
    assert!(
        steps
            .iter()
            .all(|s| s.get("holds").is_none_or(|h| h == true))
    );
    // over Q(p): the conditions of each step
    let j = json(&["jordan", f, "--steps", "--symbolic", "--format", "json"]);
    let conds: Vec<&str> = j["conditions"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c.as_str().unwrap())
        .collect();
    assert!(
        conds.contains(&"cr != 0") && conds.contains(&"u != 0"),
        "{conds:?}"
    );
    let j = json(&[
        "minreal",
        "data/sliding-masses.json",
        "--method",
        "jordan",
        "--steps",
        "--format",
        "json",
    ]);
    let st = j["steps"].as_array().unwrap().last().unwrap().clone();
    assert_eq!(st["stages"], serde_json::json!([20, 16, 8]));
    let (code, out, _) = common::cli::run(&["minreal", f, "--steps"]);
    assert_eq!(code, 0);
    assert!(
        out.contains("step 7. The controllable and observable part"),
        "{out}"
    );
    let (code, out, _) =
        common::cli::run(&["jordan", f, "--steps", "--format", "latex", "--standalone"]);
    assert_eq!(code, 0);
    assert!(out.starts_with("\\documentclass[11pt,a4paper]{article}"));
    assert!(out.contains("\\end{document}") && out.contains("holds exactly"));
}

#[test]
fn cli_steps_refusals_are_one_line_exit_2() {
    let f = "data/yaw-plane-single-wheel.json";
    // `mnf` and `jordan --real` have steps now (tests/steps_forms.rs); over Q(p) `jordan
    // --real --steps` answers as the command itself does (tests/steps_qp_forms.rs)
    let (code, out, err) = common::cli::run(&["jordan", f, "--real", "--steps", "--symbolic"]);
    assert_eq!(code, 0, "{err}");
    assert!(
        out.contains("real_form") && out.contains("verified: true"),
        "{out}"
    );
    for args in [
        vec!["standard", f, "--steps"],
        vec!["minreal", f, "--method", "era", "--steps"],
        vec!["jordan", "tests/data/sqrt2.toml", "--steps"],
        vec!["jordan", "tests/data/no-such-file.json", "--steps"],
    ] {
        let (code, out, err) = common::cli::run(&args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(out.is_empty());
        assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    }
}
