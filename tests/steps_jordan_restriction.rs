//! `minreal --method jordan --steps` over Q(p) on the command's path (issue 27): a simple
//! irreducible factor g of degree d >= 2 is derived by its restriction, not by chains over
//! E = Q(p)[t]/(g). Every identity is recomputed here from the step data:
//!
//! * restriction step: A u = u A_g, P u = I_d, P A = A_g P (u = P = I when d = n), the part
//!   is (A_g, P B, C u) with PB = P B and Cu = C u recomputed, `excited` = [P B != 0],
//!   `observed` = [C u != 0];
//! * stages: stage s is the sum of the parts of that stage (modal data / kept modes /
//!   compacted blocks of the chained factors, each traced from E to Q(p); the restriction
//!   parts, kept ones only after stage 0): its Markov parameters equal C A^k B for k < 2n
//!   (exactly, as rational functions), its order is the stage's count;
//! * the last stage's order = the McMillan degree, and the Stages step's (Ar, Br, Cr, Dr) is
//!   the command's realization (`minimal_jordan_qp`, same matrices) with C_r A_r^k B_r =
//!   C A^k B.

use crate::common::{self, Rng, unimodular};
use exactlti::algebraic::Ext;
use exactlti::field::Field;
use exactlti::io::TypedAny;
use exactlti::io::symbolic::{SymbolicOptions, load_symbolic_path};
use exactlti::jordan::derivation::{Derivation, Step, StepKind};
use exactlti::matrix::Matrix;
use exactlti::ratfunc::RatFuncField;
use exactlti::realization::steps::jordan_method_steps_qp;
use exactlti::realization::{mcmillan_degree, minimal_jordan_qp};
use exactlti::system::StateSpace;
use std::path::Path;

type F = RatFuncField;
type E = Ext<RatFuncField>;
type Part<'a> = (&'a Matrix<E>, &'a Matrix<E>, &'a Matrix<E>);

fn load(f: &str) -> StateSpace<F> {
    let opts = SymbolicOptions::from_args(Some(""), None).unwrap();
    let l = load_symbolic_path(Path::new(f), &opts).unwrap();
    let TypedAny::RatFunc(t) = l.system else {
        panic!("expected QQ(p) for {f}")
    };
    t.ss
}

/// `m` over the derivation's field (elements of Q(p) as constants).
fn lift(m: &Matrix<F>, e: &E) -> Matrix<E> {
    m.map(e, |x| e.from_base(x))
}

/// `m` back over Q(p) (a matrix over the degree-one extension).
fn down(m: &Matrix<E>) -> Matrix<F> {
    let f = m.field().base().clone();
    assert_eq!(m.field().degree(), 1);
    Matrix::from_fn(f.clone(), m.nrows(), m.ncols(), |i, j| {
        m.get(i, j).0.first().cloned().unwrap_or_else(|| f.zero())
    })
}

fn triple<'a>(s: &'a Step<E>, names: [&str; 3]) -> Part<'a> {
    let m = |k: &str| s.matrix(k).unwrap_or_else(|| panic!("{k} in {:?}", s.kind));
    (m(names[0]), m(names[1]), m(names[2]))
}

/// The restriction identities of one step (module docs); returns whether it is kept.
fn check_restriction(s: &Step<E>, sys: &StateSpace<F>) -> bool {
    let e = s.matrix("Ag").unwrap().field().clone();
    let (a, b, c) = (lift(&sys.a, &e), lift(&sys.b, &e), lift(&sys.c, &e));
    let ag = s.matrix("Ag").unwrap();
    let d = ag.nrows();
    assert_eq!(s.count("deg"), Some(d));
    assert_eq!(s.poly("g").unwrap().deg(), d);
    let n = sys.nstates();
    let id = |k| Matrix::identity(e.clone(), k);
    let (u, p) = match (s.matrix("u"), s.matrix("P")) {
        (Some(u), Some(p)) => (u.clone(), p.clone()),
        (None, None) => {
            assert_eq!(d, n, "u = P = I only for deg g = n");
            (id(n), id(n))
        }
        _ => panic!("u and P come together"),
    };
    assert!(d >= 2, "a restriction is for a factor of degree >= 2");
    assert_eq!(&a * &u, &u * ag, "A u = u A_g");
    assert_eq!(&p * &u, id(d), "P u = I");
    assert_eq!(&p * &a, ag * &p, "P A = A_g P");
    // g(A_g) = 0: A_g is the restriction to ker g(A)
    let g = s.poly("g").unwrap();
    assert!(ag.eval_poly(g).unwrap().is_zero(), "g(A_g) = 0");
    let (pb, cu) = (s.matrix("PB").unwrap(), s.matrix("Cu").unwrap());
    assert_eq!(pb, &(&p * &b));
    assert_eq!(cu, &(&c * &u));
    let excited = s.count("excited") == Some(1);
    let observed = s.count("observed") == Some(1);
    assert_eq!(excited, !pb.is_zero());
    assert_eq!(observed, !cu.is_zero());
    excited && observed
}

/// Every identity of the derivation (module docs); returns (stages, restriction steps, kept).
fn check_derivation(sys: &StateSpace<F>) -> ([usize; 3], usize, usize) {
    let d: Derivation<E> = jordan_method_steps_qp(sys).unwrap();
    assert!(d.verified(), "every step's identity holds");
    let n = sys.nstates();
    let f = sys.a.field().clone();
    let (p, m) = (sys.noutputs(), sys.ninputs());
    let mut stages: [Vec<Part<'_>>; 3] = [vec![], vec![], vec![]];
    let (mut restricted, mut kept) = (0, 0);
    for s in d.of_kind(StepKind::Restriction) {
        restricted += 1;
        let part = triple(s, ["Ag", "PB", "Cu"]);
        stages[0].push(part);
        if check_restriction(s, sys) {
            kept += 1;
            stages[1].push(part);
            stages[2].push(part);
        }
    }
    let chained = |kind, names| {
        d.of_kind(kind)
            .map(move |s| triple(s, names))
            .filter(|t| t.0.nrows() > 0)
    };
    stages[0].extend(chained(StepKind::ModalData, ["J", "WB", "CV"]));
    stages[1].extend(chained(StepKind::DropModes, ["Jk", "Bk", "Ck"]));
    stages[2].extend(chained(StepKind::Compaction, ["J", "B", "C"]));
    let st = d.of_kind(StepKind::Stages).next().unwrap();
    let counts = st.counts("stages").unwrap();
    let kmax = 2 * n;
    let want = sys.markov(kmax);
    for (i, parts) in stages.iter().enumerate() {
        let order: usize = parts
            .iter()
            .map(|(j, _, _)| j.nrows() * j.field().degree())
            .sum();
        assert_eq!(order, counts[i], "stage {i}: its order");
        let got = crate::jcommon::traced_markov(parts, p, m, &f, kmax);
        for (k, (g, w)) in got.iter().zip(&want).enumerate() {
            assert_eq!(g.as_slice(), w.as_slice(), "stage {i}: C A^{k} B");
        }
    }
    assert_eq!(counts[0], n);
    let mcm = mcmillan_degree(sys);
    assert_eq!(counts[2], mcm, "order = McMillan degree");
    assert_eq!(st.count("mcmillan"), Some(mcm));
    // the realization of the last step is the command's
    let ar = ["Ar", "Br", "Cr", "Dr"].map(|k| down(st.matrix(k).unwrap()));
    let cmd = minimal_jordan_qp(sys).unwrap().system;
    for (x, y) in ar.iter().zip([&cmd.a, &cmd.b, &cmd.c, &cmd.d]) {
        assert_eq!(x.as_slice(), y.as_slice(), "the command's realization");
    }
    let [a, b, c, dd] = ar;
    let r = StateSpace::new(a, b, c, dd).unwrap();
    assert_eq!(r.nstates(), mcm);
    for (g, w) in r.markov(kmax).iter().zip(&want) {
        assert_eq!(g.as_slice(), w.as_slice(), "C_r A_r^k B_r = C A^k B");
    }
    assert_eq!(r.d.as_slice(), sys.d.as_slice());
    ([counts[0], counts[1], counts[2]], restricted, kept)
}

/// The yaw plane in 7 symbols (eigenvalue 0 in a Jordan block of 2, a simple quadratic
/// factor: its restriction to ker g(A), 2 states of 4) and the single-track models in 8
/// symbols (an irreducible quartic: the whole system is the restriction, u = P = I).
#[test]
fn yaw_plane_and_single_track_by_restriction() {
    assert_eq!(
        check_derivation(&load("data/models/yaw-plane.toml")),
        ([4, 4, 4], 1, 1)
    );
    assert_eq!(
        check_derivation(&load("data/scb/single-track-front.json")),
        ([4, 4, 4], 1, 1)
    );
    // the single wheel: every eigenvalue in Q(cr, m, u), no restriction
    assert_eq!(
        check_derivation(&load("data/yaw-plane-single-wheel.json")),
        ([4, 2, 2], 0, 0)
    );
}

/// A = U diag(J_2(a), x^2 + a, x^2 - x + 2a, x^2 + a) U^-1 (U unimodular; x^2 + a twice, so
/// chains over E for it, the other quadratic simple: a restriction), random B, C with zero
/// rows/columns so that parts drop (generator, fixed seed).
#[test]
fn planted_simple_factors_by_restriction() {
    let mut rng = Rng(2711);
    let k = RatFuncField::new(&["a"]).unwrap();
    let blocks: [(&[&str], usize); 4] = [
        (&["a", "1", "0", "a"], 2),
        (&["0", "-a", "1", "0"], 2),
        (&["0", "-2*a", "1", "1"], 2),
        (&["0", "-a", "1", "0"], 2),
    ];
    let n = 8;
    let mut j = Matrix::zeros(k.clone(), n, n);
    let mut off = 0;
    for (entries, s) in blocks {
        for r in 0..s {
            for c in 0..s {
                j.set(off + r, off + c, k.parse(entries[r * s + c]).unwrap());
            }
        }
        off += s;
    }
    let mut kinds = std::collections::BTreeSet::new();
    for case in 0..common::iters(4) {
        let u = unimodular(&k, n, &mut rng);
        let ui = u.inverse().unwrap();
        let a = u.try_mul(&j).unwrap().try_mul(&ui).unwrap();
        // case 1: the simple pair (states 4, 5) not excited; case 2: not observed
        let pick = |rng: &mut Rng| k.from_i64(rng.int(-1, 1));
        let b0 = Matrix::from_fn(k.clone(), n, 1, |i, _| {
            if case % 3 == 1 && (4..6).contains(&i) {
                k.zero()
            } else {
                pick(&mut rng)
            }
        });
        let c0 = Matrix::from_fn(k.clone(), 2, n, |_, c| {
            if case % 3 == 2 && (4..6).contains(&c) {
                k.zero()
            } else {
                k.from_i64(c as i64 % 3 - 1)
            }
        });
        let sys = StateSpace::new(
            a,
            u.try_mul(&b0).unwrap(),
            c0.try_mul(&ui).unwrap(),
            Matrix::zeros(k.clone(), 2, 1),
        )
        .unwrap();
        let (stages, restricted, kept) = check_derivation(&sys);
        assert_eq!(restricted, 1, "one simple factor of degree >= 2");
        assert_eq!(stages[0], n);
        if case % 3 != 0 {
            assert_eq!(kept, 0, "case {case}: the simple pair is dropped");
        }
        kinds.insert(kept);
    }
    assert!(kinds.contains(&0), "a dropped restriction was generated");
}

/// On the command line: JSON names the restriction step, the LaTeX document has it.
#[test]
fn restriction_steps_cli() {
    let f = "data/scb/single-track-rear.json";
    let j = common::cli::run_json(&["minreal", f, "--method", "jordan", "--steps"]);
    assert_eq!(j["verified"], true);
    let steps = j["steps"].as_array().unwrap();
    let r = steps.iter().find(|s| s["step"] == "restriction").unwrap();
    assert_eq!(r["holds"], true);
    assert_eq!(r["deg"], 4);
    let last = steps.last().unwrap();
    assert_eq!(last["step"], "stages");
    assert_eq!(last["stages"], serde_json::json!([4, 4, 4]));
    let (code, out, err) = common::cli::run(&[
        "minreal",
        f,
        "--method",
        "jordan",
        "--steps",
        "--format",
        "latex",
        "--standalone",
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(
        out.contains("\\texttt{restriction}") && out.contains("A_g"),
        "{out}"
    );
}
