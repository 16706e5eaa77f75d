//! `--steps` over Q(p) for `jordan --real` and `minreal --method jordan`, and plain `jordan
//! --normalize` (issue 27): every identity recomputed here from the step data.
//!
//! * real pair of a quadratic factor x^2 + c1 x + c0 over Q(p): alpha = -c1/2, w^2 = c0 -
//!   c1^2/4 (the entry w of J_c squares to it), disc = c1^2 - 4 c0 = -4 w^2, A Tc = Tc Jc in
//!   Q(p)[w], the chains v_j = p_j + q_j t give x_j = p_j + alpha q_j, y_j = w q_j; the whole
//!   A T = T J with det T != 0;
//! * the Jordan method on the sliding masses in m, k: the Markov parameters of the three
//!   stages (20 -> 16 -> 8), each as the sum over the factors of Tr_{E/F}(C J^k B), equal
//!   C A^k B;
//! * plain `jordan --normalize`: the normalised chains are chains of the same block, A T = T J
//!   still verified, T changed, closed-form unit lengths listed.

use crate::common;
use exactlti::algebraic::Ext;
use exactlti::field::ElemDisplay;
use exactlti::field::Field;
use exactlti::io::TypedAny;
use exactlti::io::symbolic::{SymbolicOptions, load_symbolic_path};
use exactlti::jordan::derivation::{Derivation, Step, StepKind};
use exactlti::jordan::normalize::{Normalization, dot, normalize_form};
use exactlti::jordan::real_steps::real_jordan_steps_qp;
use exactlti::matrix::Matrix;
use exactlti::poly::newton_power_sums;
use exactlti::qmat;
use exactlti::ratfunc::RatFuncField;
use exactlti::realization::steps::jordan_method_steps_qp;
use std::path::Path;

type E = Ext<RatFuncField>;

fn ratfunc_matrix(k: &RatFuncField, rows: &[&[&str]]) -> Matrix<RatFuncField> {
    let n = rows.len();
    let m = rows[0].len();
    Matrix::from_fn(k.clone(), n, m, |i, j| k.parse(rows[i][j]).unwrap())
}

/// The matrix over `e` (an extension of `a`'s field).
fn lift(a: &Matrix<RatFuncField>, e: &E) -> Matrix<E> {
    a.map(e, |x| e.from_base(x))
}

/// Every real-pair and real-form identity of `d` recomputed for `a`; returns the number of
/// pairs checked.
fn check_real(d: &Derivation<E>, a: &Matrix<RatFuncField>) -> usize {
    assert!(d.verified());
    let mut pairs = 0;
    for st in d.of_kind(StepKind::RealPair) {
        let (t, j) = (st.matrix("Tc").unwrap(), st.matrix("Jc").unwrap());
        let r = t.field().clone();
        assert_eq!(r.degree(), 2, "R = Q(p)[w]/(w^2 - w2)");
        let ar = lift(a, &r);
        assert_eq!(&ar * t, t * j, "A Tc = Tc Jc");
        let (re, w2, disc) = (
            st.scalar("re").unwrap(),
            st.scalar("w2").unwrap(),
            st.scalar("disc").unwrap(),
        );
        // J_c = [[alpha, w], [-w, alpha]] (+ I_2 above): w^2 is the stated w2
        let w = j.get(0, 1).clone();
        assert_eq!(&r.mul(&w, &w), w2, "w^2 = c0 - c1^2/4");
        assert_eq!(j.get(0, 0), re);
        assert_eq!(j.get(1, 0), &r.neg(&w));
        assert_eq!(disc, &r.mul(&r.from_i64(-4), w2), "c1^2 - 4 c0 = -4 w^2");
        // the factor of the part: x^2 + c1 x + c0 with alpha = -c1/2
        let ks = d
            .of_kind(StepKind::KernelSequence)
            .find(|s| s.part == st.part)
            .expect("the pair's chains");
        let g = ks.matrix("N").unwrap().field().clone();
        assert_eq!(g.degree(), 2);
        // the chain v_1 = p + q t shown gives x_1 = p + alpha q, y_1 = w q
        let chain = d
            .of_kind(StepKind::Chain)
            .find(|s| s.part == st.part)
            .unwrap();
        let v = chain.matrix("V").unwrap();
        for i in 0..v.nrows() {
            let c = &v.get(i, 0).0;
            let p = c.first().cloned().unwrap_or_else(|| a.field().zero());
            let q = c.get(1).cloned().unwrap_or_else(|| a.field().zero());
            let k = a.field();
            let alpha = r.to_base(re).unwrap();
            let x = k.add(&p, &k.mul(&alpha, &q));
            assert_eq!(t.get(i, 0), &r.from_base(&x), "x_1 = p + alpha q");
            assert_eq!(t.get(i, 1), &r.mul(&w, &r.from_base(&q)), "y_1 = w q");
        }
        pairs += 1;
    }
    if let Some(st) = d.of_kind(StepKind::RealForm).next() {
        let (t, j) = (st.matrix("T").unwrap(), st.matrix("J").unwrap());
        let f = t.field().clone();
        assert_eq!(&lift(a, &f) * t, t * j, "A T = T J");
        assert!(!f.is_zero(&t.det().unwrap()), "det T != 0");
        assert_eq!(t.ncols(), a.nrows());
    }
    pairs
}

/// A damped oscillator beside a real eigenvalue, and (x^2 + k)^2 in one Jordan block per
/// root: the real pair blocks with I_2 above the diagonal.
#[test]
fn real_pairs_over_qp() {
    let k = RatFuncField::new(&["k", "c", "a"]).unwrap();
    let a = ratfunc_matrix(
        &k,
        &[&["0", "1", "0"], &["-k", "-c", "0"], &["0", "0", "a"]],
    );
    let d = real_jordan_steps_qp(&a).unwrap();
    assert_eq!(check_real(&d, &a), 1);
    assert_eq!(d.of_kind(StepKind::RealForm).count(), 1);
    // the discriminant c^2 - 4k is a condition of the factorization
    let conds: Vec<String> = d
        .assumptions()
        .iter()
        .map(|x| d.field.fmt_elem(x))
        .collect();
    assert!(conds.iter().any(|c| c.contains("c^2")), "{conds:?}");
    let b = ratfunc_matrix(
        &k,
        &[
            &["0", "1", "1", "0"],
            &["-k", "0", "0", "1"],
            &["0", "0", "0", "1"],
            &["0", "0", "-k", "0"],
        ],
    );
    let d = real_jordan_steps_qp(&b).unwrap();
    assert_eq!(check_real(&d, &b), 1);
    let st = d.of_kind(StepKind::RealPair).next().unwrap();
    let j = st.matrix("Jc").unwrap();
    let r = j.field().clone();
    assert!(r.is_one(j.get(0, 2)) && r.is_one(j.get(1, 3)), "I_2 above");
    // a cubic factor has no real form with one square root: refused
    let c = ratfunc_matrix(&k, &[&["0", "0", "k"], &["1", "0", "0"], &["0", "1", "0"]]);
    assert!(real_jordan_steps_qp(&c).is_err());
}

/// The yaw plane model (a descriptor file in seven symbols) on the command line: the
/// standard form's steps, then the real pair; every identity holds.
#[test]
fn real_steps_yaw_plane_cli() {
    let j = common::cli::run_json(&["jordan", "data/models/yaw-plane.toml", "--real", "--steps"]);
    assert_eq!(j["verified"], true);
    let steps = j["steps"].as_array().unwrap();
    let kinds: Vec<&str> = steps.iter().map(|s| s["step"].as_str().unwrap()).collect();
    for want in [
        "standard_form",
        "charpoly",
        "chain",
        "real_pair",
        "real_form",
    ] {
        assert!(kinds.contains(&want), "{kinds:?}");
    }
    for s in steps {
        if s.get("holds").is_some() {
            assert_eq!(s["holds"], true, "{}", s["step"]);
        }
    }
    let pair = steps.iter().find(|s| s["step"] == "real_pair").unwrap();
    assert!(pair["w2"].as_str().unwrap().contains("Izz"));
    assert!(pair["sentence"].as_str().unwrap().contains("< 0"));
    assert!(j["conditions"].as_array().unwrap().len() > 3);
}

/// The `(J, B, C)` matrices named `names` of each step (`nonempty`: the steps whose `J` has
/// rows only).
fn stage_parts<'a>(
    steps: impl Iterator<Item = &'a Step<E>>,
    names: [&str; 3],
    nonempty: bool,
) -> Vec<(&'a Matrix<E>, &'a Matrix<E>, &'a Matrix<E>)> {
    steps
        .filter(|s| !nonempty || s.matrix(names[0]).unwrap().nrows() > 0)
        .map(|s| {
            let m = |name: &str| s.matrix(name).unwrap();
            (m(names[0]), m(names[1]), m(names[2]))
        })
        .collect()
}

/// The sliding masses in m, k (paper sec. 4.1): 20 -> 16 -> 8, the Markov parameters of
/// every stage (the modal data, the kept modes, the compacted blocks) equal C A^k B.
#[test]
fn jordan_method_stages_over_qp() {
    let opts = SymbolicOptions::from_args(Some(""), None).unwrap();
    let l = load_symbolic_path(Path::new("data/sliding-masses-symbolic.json"), &opts).unwrap();
    let TypedAny::RatFunc(t) = &l.system else {
        panic!("expected QQ(k, m)")
    };
    let d = jordan_method_steps_qp(&t.ss).unwrap();
    assert!(d.verified());
    let st = d.of_kind(StepKind::Stages).next().unwrap();
    assert_eq!(st.counts("stages").unwrap(), &[20, 16, 8]);
    assert_eq!(st.count("mcmillan"), Some(8));
    let kmax = 28;
    // the system in the derivation's parameters' field
    let want = t.ss.markov(kmax);
    let stage0 = stage_parts(d.of_kind(StepKind::ModalData), ["J", "WB", "CV"], false);
    let stage1 = stage_parts(d.of_kind(StepKind::DropModes), ["Jk", "Bk", "Ck"], true);
    let stage2 = stage_parts(d.of_kind(StepKind::Compaction), ["J", "B", "C"], true);
    let order = |parts: &[(&Matrix<E>, &Matrix<E>, &Matrix<E>)]| -> usize {
        parts
            .iter()
            .map(|(j, _, _)| j.nrows() * j.field().degree())
            .sum()
    };
    assert_eq!(
        [order(&stage0), order(&stage1), order(&stage2)],
        [20, 16, 8]
    );
    for stage in [&stage0, &stage1, &stage2] {
        let got = {
            let (p, m) = (stage[0].2.nrows(), stage[0].1.ncols());
            let f = stage[0].0.field().base().clone();
            crate::jcommon::traced_markov(stage, p, m, &f, kmax)
        };
        for (g, w) in got.iter().zip(&want) {
            assert_eq!(g.as_slice(), w.as_slice(), "C A^k B at every stage");
        }
    }
    // each step lists what it assumes: k and m nonzero
    let conds: Vec<String> = d
        .assumptions()
        .iter()
        .map(|x| d.field.fmt_elem(x))
        .collect();
    assert!(
        conds.contains(&"k".to_string()) && conds.contains(&"m".to_string()),
        "{conds:?}"
    );
}

/// `minreal --method jordan --steps` over Q(p) on the command line (text, JSON, LaTeX).
#[test]
fn jordan_method_steps_cli() {
    let f = "data/sliding-masses-symbolic.json";
    let j = common::cli::run_json(&["minreal", f, "--method", "jordan", "--steps"]);
    assert_eq!(j["verified"], true);
    assert_eq!(j["field"], "QQ(k, m)");
    let st = j["steps"].as_array().unwrap().last().unwrap();
    assert_eq!(st["stages"], serde_json::json!([20, 16, 8]));
    for fmt in ["text", "latex"] {
        let (code, out, err) = common::cli::run(&[
            "minreal", f, "--method", "jordan", "--steps", "--format", fmt,
        ]);
        assert_eq!(code, 0, "{err}");
        assert!(out.contains("16"), "{out}");
    }
}

/// Plain `jordan --normalize` (no --steps): every chain of the Jordan form normalised, the
/// identities checked again; over Q the eigenvector (1, 1) of [[1, 1], [0, 2]] has
/// v . v = 2, listed as a closed-form unit length.
#[test]
fn plain_normalize() {
    // a 3-block of eigenvalue 1 and a simple eigenvalue 2
    let a = qmat![[2, 1, 0, 1], [0, 1, 1, 0], [0, 0, 1, 1], [0, 0, 0, 1]];
    let plain = exactlti::jordan::jordan(&a).unwrap();
    for how in ["orth", "entry", "entry:2", "unit", "paper", "orth,entry"] {
        let how: Normalization = how.parse().unwrap();
        let mut jf = plain.clone();
        let closed = normalize_form(&mut jf, &how).unwrap();
        assert!(jf.verified);
        for (c, p) in jf.components.iter().zip(&plain.components) {
            assert!(c.verify(&a), "A V' = V' J, W' A = J W', W' V' = I");
            assert_eq!(c.blocks, p.blocks, "J unchanged");
            let e = c.field.clone();
            let v = &c.chains;
            let v1 = v.col(0);
            if how.orthogonal {
                for j in 1..v.ncols() {
                    assert!(e.is_zero(&dot(&e, &v.col(j), &v1)), "v_j . v_1 = 0");
                }
            }
        }
        if how.scale == exactlti::jordan::normalize::Scale::Unit {
            for cu in &closed {
                let c = &jf.components[cu.component];
                let v1 = c.chains.col(cu.first);
                assert_eq!(dot(&c.field, &v1, &v1), cu.n);
            }
        }
    }
    let f = common::cli::temp_file("plain_normalize", "a.json", r#"{"A": [[1, 1], [0, 2]]}"#);
    let p = f.to_str().unwrap();
    let plain = common::cli::run_json(&["jordan", p]);
    let j = common::cli::run_json(&["jordan", p, "--normalize", "entry:2"]);
    assert_eq!(j["verified"], true);
    assert_eq!(j["J"], plain["J"]);
    let u = common::cli::run_json(&["jordan", p, "--normalize", "unit"]);
    assert_eq!(u["verified"], true);
    let notes = u["unit_lengths"].as_array().unwrap();
    assert!(notes[0].as_str().unwrap().contains("n = 2"), "{notes:?}");
    for fmt in ["text", "latex"] {
        let (code, out, err) =
            common::cli::run(&["jordan", p, "--normalize", "orth,entry", "--format", fmt]);
        assert_eq!(code, 0, "{err}");
        assert!(out.contains("normali"), "{out}");
    }
    // an eigenvector whose entry 2 is made 1: T's column of eigenvalue 2 is (1, 1)
    let t = &j["T"];
    let col: Vec<&str> = (0..2).map(|i| t[i][0].as_str().unwrap()).collect();
    assert_eq!(col, ["1", "1"]);
}

/// The trace over Q of each entry of a matrix over a number field Q[t]/(p).
fn trace_q(m: &Matrix<exactlti::algebraic::NumberField>) -> Matrix<exactlti::field::Q> {
    use exactlti::field::{Q, Rational};
    let e = m.field().clone();
    let ps = newton_power_sums(e.modulus(), e.degree());
    m.map(&Q, |x| {
        x.0.iter()
            .zip(&ps)
            .fold(Rational::from_integer(0.into()), |acc, (a, b)| acc + a * b)
    })
}

/// `contributions --steps` on random stable-ish systems (fixed seed) and the sliding masses:
/// every identity recomputed from the steps (projectors idempotent and summing to I, A V =
/// V A_p, the residues' traces C_p B_p, the Lyapunov identity of each weight, the parts'
/// Markov parameters summing to C A^k B, the truncation's C B = C_K B_K + E_0).
#[test]
fn contributions_steps_identities() {
    use crate::response_modal::random_system;
    use exactlti::field::Q;
    use exactlti::realization::contribution_steps::contributions_steps;
    let mut rng = exactlti::rng::SplitMix64(27_027);
    let mut systems = vec![crate::common::systems::sliding_masses()];
    for case in 0..8 {
        let n = 2 + case % 4;
        let (a, b, c) = random_system(&mut rng, n);
        let d = Matrix::zeros(Q, c.nrows(), b.ncols());
        systems.push(exactlti::system::StateSpace::new(a, b, c, d).unwrap());
    }
    for ss in &systems {
        let n = ss.nstates();
        let d = contributions_steps(ss, Some(1)).unwrap();
        assert!(d.verified());
        let lq = |m: &Matrix<exactlti::algebraic::NumberField>| trace_q(m);
        let mut sum = Matrix::zeros(Q, n, n);
        let mut markov = vec![Matrix::zeros(Q, ss.noutputs(), ss.ninputs()); 2 * n];
        for st in d.of_kind(StepKind::SpectralProjector) {
            let m = |k: &str| lq(st.matrix(k).unwrap());
            let (p, v, r, ap, bp, cp) = (m("P"), m("V"), m("R"), m("Ap"), m("Bp"), m("Cp"));
            assert_eq!(&v * &r, p);
            assert_eq!(&p * &p, p, "P^2 = P");
            assert!((&r * &v).is_identity(), "R V = I");
            assert_eq!(&ss.a * &v, &v * &ap, "A V = V A_p");
            assert_eq!(bp, &r * &ss.b);
            assert_eq!(cp, &ss.c * &v);
            sum = &sum + &p;
            let mut akb = bp.clone();
            for h in markov.iter_mut() {
                *h = &*h + &(&cp * &akb);
                akb = &ap * &akb;
            }
            let res = d
                .of_kind(StepKind::ModeResidues)
                .find(|s| s.part == st.part)
                .unwrap();
            let h = res.matrix("H").unwrap();
            let h0 = h.submatrix(0, h.nrows(), 0, ss.ninputs());
            assert_eq!(
                trace_q(&h0),
                &cp * &bp,
                "sum over conjugates of H_0 = C_p B_p"
            );
            let w = d
                .of_kind(StepKind::ModeWeight)
                .find(|s| s.part == st.part)
                .unwrap();
            if let Some(wm) = w.matrix("W") {
                let wq = lq(wm);
                let bbt = &bp * &bp.transpose();
                assert!((&(&(&ap * &wq) + &(&wq * &ap.transpose())) + &bbt).is_zero());
            }
        }
        assert!(sum.is_identity(), "sum P_p = I");
        assert_eq!(markov, ss.markov(2 * n), "the parts add up to G");
        let t = d.of_kind(StepKind::TruncationError).next().unwrap();
        let m = |k: &str| lq(t.matrix(k).unwrap());
        assert_eq!(&ss.c * &ss.b, &(&m("Ck") * &m("Bk")) + &m("M0"));
    }
}

/// `response --steps` from x0: A g_k = theta g_k + (k+1) g_(k+1) per factor, the traces of
/// g_0 sum to x0; on the command line (JSON, LaTeX) and refused with symbols in x0.
#[test]
fn response_steps_identities() {
    use crate::response_modal::random_system;
    use exactlti::field::{Q, Rational};
    use exactlti::realization::contribution_steps::response_steps;
    let mut rng = exactlti::rng::SplitMix64(27_028);
    for case in 0..10 {
        let n = 2 + case % 5;
        let (a, _, _) = random_system(&mut rng, n);
        let x0 = Matrix::from_fn(Q, n, 1, |i, _| {
            Rational::from_integer((i as i64 - 1).into())
        });
        let d = response_steps(&a, &x0).unwrap();
        assert!(d.verified());
        let mut sum0 = Matrix::zeros(Q, n, 1);
        for st in d.of_kind(StepKind::FreeTerms) {
            let g = st.matrix("g").unwrap();
            let e = g.field().clone();
            let theta = st.scalar("theta").unwrap();
            let ae = a.map(&e, |x| e.from_rational(x));
            for k in 0..g.ncols() {
                let gk = g.submatrix(0, n, k, k + 1);
                let next = if k + 1 < g.ncols() {
                    g.submatrix(0, n, k + 1, k + 2)
                        .scale(&e.from_i64(k as i64 + 1))
                } else {
                    Matrix::zeros(e.clone(), n, 1)
                };
                assert_eq!(&ae * &gk, &gk.scale(theta) + &next, "case {case}");
            }
            sum0 = &sum0 + &trace_q(&g.submatrix(0, n, 0, 1));
        }
        assert_eq!(sum0, x0, "x(0) = x0");
    }
    let f = "data/sliding-masses.json";
    let x0 = vec!["0"; 20].join(",").replacen('0', "1", 1);
    let j = common::cli::run_json(&["response", f, "--x0", &x0, "--steps"]);
    assert_eq!(j["verified"], true);
    let c = common::cli::run_json(&["contributions", f, "--keep", "2", "--steps"]);
    assert_eq!(c["verified"], true);
    assert!(
        c["steps"]
            .as_array()
            .unwrap()
            .iter()
            .any(|s| s["step"] == "truncation")
    );
    let (code, out, err) = common::cli::run(&[
        "contributions",
        f,
        "--steps",
        "--format",
        "latex",
        "--standalone",
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("holds exactly"));
    let (code, _, err) = common::cli::run(&[
        "response",
        "tests/data/mnf_appendix_b.json",
        "--x0",
        "1,0,0,0",
        "--steps",
        "--format",
        "json",
    ]);
    // generic over the field now (was refused "over QQ"): every identity holds
    assert_eq!(code, 0, "{err}");
}
