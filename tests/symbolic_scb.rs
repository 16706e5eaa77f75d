//! Commands over Q(p) (issue 13): Grip & Saberi's SCB examples in symbols (sec. IV single-track
//! model, sec. V DC motor with LuGre friction), their structural bifurcations, and the CLI.
//!
//! Triad: the paper's printed matrices (errata checked: the printed ones are not similar to
//! A-hat, the corrected ones are equal to ours), an oracle (the symbolic SCB evaluated at the
//! paper's values equals the SCB computed over Q at those values), and properties (verified
//! identities, every condition irreducible and nonvanishing at the paper's values).

use crate::common::cli::run;
use exactlti::field::ElemDisplay;
use exactlti::field::{Field, Q, Rational};
use exactlti::io::TypedAny;
use exactlti::io::symbolic::{SymbolicOptions, load_symbolic_path};
use exactlti::matrix::Matrix;
use exactlti::ratfunc::{RatFunc, RatFuncField};
use exactlti::structure::bifurcation::{BranchOutcome, Limits, bifurcations, solve_linear};
use exactlti::structure::scb::{Scb, scb};
use exactlti::system::StateSpace;
use std::path::Path;

const DC: &str = "data/dc-motor-lugre.json";
const FRONT: &str = "data/scb/single-track-front.json";
const REAR: &str = "data/scb/single-track-rear.json";

fn load(path: &str) -> StateSpace<RatFuncField> {
    let l = load_symbolic_path(Path::new(path), &SymbolicOptions::default()).unwrap();
    let TypedAny::RatFunc(t) = l.system else {
        panic!("{path}: expected symbols")
    };
    t.ss
}

fn load_values(path: &str) -> StateSpace<Q> {
    let o = SymbolicOptions::from_args(Some(""), None).unwrap();
    // no symbols named on the command line and values in the file: --at with the file's values
    let _ = o;
    let text = std::fs::read_to_string(path).unwrap();
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    let at: Vec<String> = v["parameters"]
        .as_object()
        .unwrap()
        .iter()
        .map(|(k, x)| format!("{k}={}", x.as_str().unwrap()))
        .collect();
    let o = SymbolicOptions::from_args(None, Some(&at.join(","))).unwrap();
    let l = load_symbolic_path(Path::new(path), &o).unwrap();
    let TypedAny::Rational(t) = l.system else {
        panic!("{path}: expected rational values")
    };
    t.ss
}

/// The paper's parameter values in the field's variable order.
fn point(k: &RatFuncField, path: &str) -> Vec<Rational> {
    let text = std::fs::read_to_string(path).unwrap();
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    k.vars()
        .iter()
        .map(|n| exactlti::field::parse_rational(v["parameters"][n].as_str().unwrap()).unwrap())
        .collect()
}

fn mat(k: &RatFuncField, rows: &[&[&str]]) -> Matrix<RatFuncField> {
    let data: Vec<RatFunc> = rows
        .iter()
        .flat_map(|r| r.iter().map(|x| k.parse(x).unwrap()))
        .collect();
    Matrix::from_vec(k.clone(), rows.len(), rows[0].len(), data)
}

fn eval(m: &Matrix<RatFuncField>, p: &[Rational]) -> Matrix<Q> {
    let k = m.field().clone();
    m.map(&Q, |x| k.eval(x, p).expect("defined at the paper's values"))
}

fn scb_of(s: &StateSpace<RatFuncField>) -> (Scb<RatFuncField>, RatFuncField) {
    let k = s.a.field().fresh();
    let m = |x: &Matrix<RatFuncField>| x.map(&k, |e| e.clone());
    let r = scb(&m(&s.a), &m(&s.b), &m(&s.c), &m(&s.d)).unwrap();
    (r, k)
}

/// Oracle: the symbolic SCB at the paper's values is the SCB over Q of the valued system
/// (every basis choice is canonical, so the coordinates agree, not only the structure).
fn oracle(path: &str, r: &Scb<RatFuncField>, k: &RatFuncField) {
    let p = point(k, path);
    for c in k.conditions().unwrap() {
        let v = k.eval(&k.from_mpoly(c.clone()), &p).unwrap();
        assert!(
            v != Rational::from_integer(0.into()),
            "{path}: a condition vanishes at the paper's values"
        );
    }
    let q = load_values(path);
    let rq = scb(&q.a, &q.b, &q.c, &q.d).unwrap();
    assert_eq!(rq.dims, r.dims);
    assert_eq!(eval(&r.a, &p), rq.a, "{path}: symbolic SCB at the values");
    assert_eq!(eval(&r.b, &p), rq.b);
    assert_eq!(eval(&r.c, &p), rq.c);
    assert_eq!(eval(&r.gamma1, &p), rq.gamma1);
}

#[test]
fn dc_motor_symbolic_scb_is_the_papers_with_its_erratum() {
    let s = load(DC);
    let (r, k) = scb_of(&s);
    assert_eq!(k.to_string(), "QQ(J, alpha2, sigma0, sigma1)");
    assert!(r.verified && r.verify());
    assert_eq!(r.dims, [1, 0, 0, 2]);
    assert_eq!(r.chains, vec![2]);
    assert_eq!(
        k.fmt_elem(r.a.get(0, 0)),
        "-sigma0/sigma1",
        "the zero -sigma0/sigma1"
    );
    // the paper's sec. V matrix as printed: A_12 with sigma1^2 is not similar to A-hat
    let printed = mat(
        &k,
        &[
            &[
                "-sigma0/sigma1",
                "-sigma0*(sigma0*J - sigma1*alpha2)/sigma1^2",
                "0",
            ],
            &["0", "0", "1"],
            &[
                "-sigma0/J",
                "-sigma0*(sigma0*J - sigma1*alpha2)/(J*sigma1^2)",
                "(sigma0*J - sigma1*alpha2 - sigma1^2)/(J*sigma1)",
            ],
        ],
    );
    assert_ne!(printed.charpoly().unwrap(), s.a.charpoly().unwrap());
    // corrected: sigma1^3
    let mut fixed = printed.clone();
    fixed.set(
        0,
        1,
        k.parse("-sigma0*(sigma0*J - sigma1*alpha2)/sigma1^3")
            .unwrap(),
    );
    assert_eq!(fixed.charpoly().unwrap(), s.a.charpoly().unwrap());
    assert_eq!(r.a, fixed, "the paper's SCB A with entry (1, 2) corrected");
    assert_eq!(r.b, mat(&k, &[&["0"], &["0"], &["1"]]));
    assert_eq!(r.c, mat(&k, &[&["0", "1", "0"]]));
    let conds = k.conditions_strings().unwrap();
    assert!(conds.contains(&"sigma1".to_string()), "{conds:?}");
    oracle(DC, &r, &k);
}

#[test]
fn single_track_front_steering_symbolic() {
    let s = load(FRONT);
    let (r, k) = scb_of(&s);
    assert_eq!(k.nvars(), 8);
    assert!(r.verified);
    assert_eq!(r.dims, [0, 3, 0, 1]);
    assert_eq!(r.chains, vec![1]);
    assert!(r.left_invertible && !r.right_invertible);
    // the paper's A (sec. IV): same SCB pattern, same spectrum, same A_bb spectrum, A_dd, B, C
    let ap = mat(
        &k,
        &[
            &["-1/Tr", "1", "0", "Tr*lf*m/(cr*(lf + lr))"],
            &[
                "-lr*cr*(lf + lr)/(vx*Tr*J)",
                "0",
                "1",
                "lf*m/(cr*(lf + lr))",
            ],
            &["-cr*(lf + lr)/(Tr*J)", "0", "0", "1/vx"],
            &[
                "cr*(lr*cr - lf*cf)*(lf + lr)/(m*Tr^2*vx*J)",
                "0",
                "-(cf + cr)/(m*Tr)",
                "-1/Tr",
            ],
        ],
    );
    assert_eq!(ap.charpoly().unwrap(), s.a.charpoly().unwrap());
    assert_eq!(r.a.charpoly().unwrap(), s.a.charpoly().unwrap());
    let sub = |x: &Matrix<RatFuncField>| x.submatrix(0, 3, 0, 3).charpoly().unwrap();
    assert_eq!(
        sub(&r.a),
        sub(&ap),
        "A_bb: same spectrum (ours observability form)"
    );
    assert_eq!(r.a.get(3, 3), ap.get(3, 3));
    assert_eq!(r.b, mat(&k, &[&["0"], &["0"], &["0"], &["1"]]));
    assert_eq!(
        r.c,
        mat(&k, &[&["0", "0", "0", "1"], &["1", "0", "0", "0"]])
    );
    oracle(FRONT, &r, &k);
}

#[test]
fn single_track_rear_steering_symbolic_with_the_papers_sign_slip() {
    let s = load(REAR);
    let (r, k) = scb_of(&s);
    assert!(r.verified);
    assert_eq!(r.dims, [1, 0, 0, 3]);
    assert_eq!(r.chains, vec![1, 2]);
    assert!(r.left_invertible && r.right_invertible);
    assert!(r.a_aa().is_zero(), "A_aa = 0: the zero at the origin");
    let printed = mat(
        &k,
        &[
            &["0", "1", "-vx", "0"],
            &[
                "-(cf + cr)/(m*Tr*vx)",
                "-1/Tr",
                "(lr*cr - lf*cf)/(m*Tr*vx)",
                "0",
            ],
            &["0", "0", "0", "1"],
            &[
                "(lr*cr - lf*cf)/(J*Tr*vx)",
                "0",
                "(lf^2*cf + lr^2*cr)/(J*Tr*vx)",
                "-1/Tr",
            ],
        ],
    );
    assert_ne!(printed.charpoly().unwrap(), s.a.charpoly().unwrap());
    let mut fixed = printed.clone();
    fixed.set(3, 2, k.parse("-(lf^2*cf + lr^2*cr)/(J*Tr*vx)").unwrap());
    assert_eq!(r.a, fixed, "the paper's A with entry (4, 3) negated");
    assert_eq!(
        r.b,
        mat(&k, &[&["0", "0"], &["1", "0"], &["0", "0"], &["0", "1"]])
    );
    assert_eq!(
        r.c,
        mat(&k, &[&["0", "1", "0", "0"], &["0", "0", "1", "0"]])
    );
    oracle(REAR, &r, &k);
}

#[test]
fn dc_motor_bifurcation_sigma1_zero_found_without_being_told() {
    let s = load(DC);
    let f = |s: &StateSpace<RatFuncField>| {
        scb(&s.a, &s.b, &s.c, &s.d).map(|r| (r.dims, r.chains, r.verified))
    };
    let t = bifurcations(&s, &f, Limits::default()).unwrap();
    assert_eq!(t.result.0, [1, 0, 0, 2]);
    let b = t
        .branches
        .iter()
        .find(|b| exactlti::report::sections::branch_equation(s.a.field(), b) == "sigma1 = 0")
        .expect("a branch sigma1 = 0");
    let BranchOutcome::Explored(n) = &b.outcome else {
        panic!("sigma1 = 0 not explored: {:?}", b.outcome)
    };
    assert_eq!(
        n.result.0,
        [0, 0, 0, 3],
        "one integrator chain of length three"
    );
    assert_eq!(n.result.1, vec![3]);
    assert!(n.result.2);
    // the branch system is the file's with sigma1 = 0
    let k = s.a.field();
    assert!(k.is_zero(n.system.b.get(1, 0)));
    // every explored branch is the generic system with the substitution made: its result
    // equals the SCB over Q at a point of the branch (oracle at sigma1 = 0)
    let p = [
        Rational::new(23.into(), 10000.into()),
        Rational::new(176.into(), 1000.into()),
        Rational::from_integer(260.into()),
        Rational::from_integer(0.into()),
    ];
    let q = StateSpace {
        a: eval(&s.a, &p),
        b: eval(&s.b, &p),
        c: eval(&s.c, &p),
        d: eval(&s.d, &p),
    };
    assert_eq!(scb(&q.a, &q.b, &q.c, &q.d).unwrap().dims, [0, 0, 0, 3]);
}

#[test]
fn solve_linear_picks_a_parameter_and_substitution_is_exact() {
    let k = RatFuncField::new(&["cr", "m", "u"]).unwrap();
    // cr*(a) - m*u^2 = 0 solved for cr: cr = m*u^2
    let c = k.parse("cr - m*u^2").unwrap();
    let s = solve_linear(&k, c.num()).unwrap();
    assert_eq!(k.vars()[s.var], "cr");
    assert_eq!(k.fmt_elem(&s.value), "m*u^2");
    let x = k.parse("1/(cr - m*u^2 + 1) + cr").unwrap();
    let y = exactlti::structure::bifurcation::substitute(&k, &x, s.var, &s.value).unwrap();
    assert_eq!(y, k.parse("1 + m*u^2").unwrap());
    // a pole on the branch: no value
    let z = k.parse("1/(cr - m*u^2)").unwrap();
    assert!(exactlti::structure::bifurcation::substitute(&k, &z, s.var, &s.value).is_none());
    // not linear in any parameter
    let q = k.parse("cr^2 + m^2").unwrap();
    assert!(solve_linear(&k, q.num()).is_none());
}

#[test]
fn zero_polynomial_factors_over_qp() {
    let k = RatFuncField::new(&["a", "b"]).unwrap();
    // (s + a)(s^2 + b/a) over Q(a, b)
    let p = exactlti::poly::Poly::new(
        k.clone(),
        vec![
            k.parse("b").unwrap(),
            k.parse("b/a").unwrap(),
            k.parse("a").unwrap(),
            k.one(),
        ],
    );
    let fs = exactlti::structure::factor_qp::factor_over_qp(&p).unwrap();
    let mut shown: Vec<String> = fs
        .iter()
        .map(|(g, e)| format!("{}^{e}", g.to_string_var("s")))
        .collect();
    shown.sort();
    assert_eq!(fs.len(), 2, "{shown:?}");
    assert!(fs.iter().all(|(g, _)| g.deg() == 1 || g.deg() == 2));
}

fn json(args: &[&str]) -> serde_json::Value {
    crate::common::cli::run_json(args)
}

#[test]
fn cli_commands_over_qp() {
    let v = json(&["scb", DC]);
    assert_eq!(v["field"], "QQ(J, alpha2, sigma0, sigma1)");
    assert_eq!(v["verified"], true);
    assert_eq!(v["dims"]["a"], 1);
    assert_eq!(v["minimum_phase"], "depends on parameters");
    assert!(
        v["conditions"]
            .as_array()
            .unwrap()
            .iter()
            .any(|c| c == "sigma1")
    );
    assert_eq!(v["zero_factors"][0]["root"], "-sigma0/sigma1");
    let v = json(&["zeros", DC]);
    assert_eq!(v["zero_factors"][0]["root"], "-sigma0/sigma1");
    for m in ["kalman", "rosenbrock", "ho-kalman"] {
        let v = json(&["minreal", REAR, "--method", m]);
        assert_eq!(v["verified"], true, "{m}");
        assert_eq!(v["order"], 4, "{m}");
    }
    let v = json(&["tf", DC]);
    assert_eq!(v["verified"], true);
    assert_eq!(v["mcmillan_degree"], 3);
    let v = json(&["ctrb", FRONT]);
    assert_eq!(v["controllable_order"], 4);
    let v = json(&["obsv", FRONT]);
    assert_eq!(v["observable_order"], 4);
    let v = json(&["analyze", DC]);
    assert_eq!(v["field"], "QQ(J, alpha2, sigma0, sigma1)");
    assert_eq!(v["verified"], true);
    assert_eq!(v["structure"]["minimum_phase"], "depends on parameters");
    assert_eq!(v["jordan"]["verified"], true);
    assert_eq!(v["jordan"]["eigenvalues"][0]["value"], "0");
    // modes over Q(p): the factors of the characteristic polynomial as formulas
    let v = json(&["modes", DC]);
    assert_eq!(v["verified"], true);
    assert_eq!(v["modes"].as_array().map(Vec::len), Some(2), "{v}");
    assert_eq!(v["modes"][0]["pole"], "0");
    assert_eq!(v["modes"][1]["omega_n_squared"], "sigma0/J");
    // values for every symbol: the ordinary command
    let v = json(&["scb", DC, "--at", "sigma1=0"]);
    assert_eq!(v["dims"]["d"], 3);
}

#[test]
fn cli_bifurcations_dc_motor() {
    let v = json(&["bifurcations", DC, "--of", "scb"]);
    assert_eq!(v["generic"]["dims"]["a"], 1);
    let bs = v["branches"].as_array().unwrap();
    let b = bs
        .iter()
        .find(|b| b["condition"] == "sigma1 = 0")
        .expect("sigma1 = 0 branch");
    assert_eq!(b["outcome"], "explored");
    assert_eq!(b["changed"], true);
    assert_eq!(b["dims"]["d"], 3);
    assert_eq!(b["chains"], serde_json::json!([3]));
    assert!(
        b["branches"].is_array(),
        "depth 2: the branch has its own branches"
    );
    let (code, _, err) = run(&["bifurcations", "tests/data/mass_spring.json"]);
    assert_eq!(code, 2, "{err}");
    for of in ["minreal", "zeros", "ctrb"] {
        let v = json(&["bifurcations", DC, "--of", of, "--depth", "1"]);
        assert_eq!(v["verified"], true, "{of}");
    }
}

#[test]
fn cli_bifurcations_jordan_yaw_plane() {
    // vehicle-dynamics paper eq. 27: generically 0 (one 3x3 block) and -cr/(m u); at cr = 0
    // A^2 = 0 with rank 2: two 2x2 blocks at 0
    let v = json(&[
        "bifurcations",
        "data/yaw-plane-single-wheel.json",
        "--symbolic",
        "--of",
        "jordan",
    ]);
    let g = &v["generic"]["eigenvalues"];
    assert_eq!(g[0]["blocks"], serde_json::json!([3]));
    assert_eq!(g[1]["value"], "-cr/(m*u)");
    let b = v["branches"]
        .as_array()
        .unwrap()
        .iter()
        .find(|b| b["condition"] == "cr = 0")
        .expect("cr = 0");
    assert_eq!(b["changed"], true);
    assert_eq!(b["eigenvalues"][0]["blocks"], serde_json::json!([2, 2]));
    let m = v["branches"]
        .as_array()
        .unwrap()
        .iter()
        .find(|b| b["condition"] == "m = 0")
        .expect("m = 0");
    assert_eq!(
        m["outcome"], "undefined",
        "1/m: the system has a pole there"
    );
}

/// A tiny deterministic generator (no dependency).
struct Lcg(u64);
impl Lcg {
    fn next(&mut self, n: i64) -> i64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((self.0 >> 33) % (2 * n as u64 + 1)) as i64 - n
    }
}

fn random_system(k: &RatFuncField, g: &mut Lcg, n: usize) -> StateSpace<RatFuncField> {
    let vars = k.vars().to_vec();
    let mut entry = |sparse: bool| {
        if sparse && g.next(2) != 0 {
            return k.zero();
        }
        let (c0, c1) = (g.next(2), g.next(1));
        let v = &vars[g.next(1).unsigned_abs() as usize % vars.len()];
        k.parse(&format!("{c0} + {c1}*{v}")).unwrap()
    };
    let mut m = |r: usize, c: usize, sparse: bool| {
        let data = (0..r * c).map(|_| entry(sparse)).collect();
        Matrix::from_vec(k.clone(), r, c, data)
    };
    StateSpace {
        a: m(n, n, true),
        b: m(n, 1, true),
        c: m(1, n, true),
        d: Matrix::zeros(k.clone(), 1, 1),
    }
}

/// Property: at a point where no condition vanishes, the symbolic SCB evaluates to the SCB
/// over Q (same dims and the same matrices); and every explored bifurcation branch, at a
/// point of the branch, has the dims of the SCB over Q there.
#[test]
fn random_symbolic_scb_agrees_with_rational_scb_at_points() {
    let k = RatFuncField::new(&["a", "b"]).unwrap();
    let mut g = Lcg(7);
    let mut checked = 0;
    for _ in 0..25 {
        let s = random_system(&k, &mut g, 3);
        let f = |s: &StateSpace<RatFuncField>| scb(&s.a, &s.b, &s.c, &s.d).map(|r| r.dims);
        let Ok(t) = bifurcations(
            &s,
            &f,
            Limits {
                depth: 1,
                max_nodes: 50,
            },
        ) else {
            continue; // [B; D] or [C, D] rank-deficient: not an SCB input
        };
        let (r, kk) = scb_of(&s);
        let p = [
            Rational::new(7.into(), 3.into()),
            Rational::new((-5).into(), 2.into()),
        ];
        let ok = kk.conditions().unwrap().iter().all(|c| {
            kk.eval(&kk.from_mpoly(c.clone()), &p)
                .is_some_and(|v| v != Rational::from_integer(0.into()))
        });
        let defined = |m: &Matrix<RatFuncField>| {
            (0..m.nrows()).all(|i| (0..m.ncols()).all(|j| k.eval(m.get(i, j), &p).is_some()))
        };
        if !ok || !defined(&s.a) {
            continue;
        }
        let q = StateSpace {
            a: eval(&s.a, &p),
            b: eval(&s.b, &p),
            c: eval(&s.c, &p),
            d: eval(&s.d, &p),
        };
        let rq = scb(&q.a, &q.b, &q.c, &q.d).unwrap();
        assert_eq!(rq.dims, r.dims);
        assert_eq!(eval(&r.a, &p), rq.a);
        assert_eq!(t.result, r.dims);
        checked += 1;
        for b in &t.branches {
            let BranchOutcome::Explored(n) = &b.outcome else {
                continue;
            };
            // a point on the branch: the solved parameter is already substituted; the other
            // gets a value where the branch's conditions are nonzero
            for v in [3i64, -4, 11] {
                let pt = [
                    Rational::from_integer(v.into()),
                    Rational::from_integer((v + 5).into()),
                ];
                let nz = n.conditions.iter().all(|c| {
                    k.eval(&k.from_mpoly(c.clone()), &pt)
                        .is_some_and(|x| x != Rational::from_integer(0.into()))
                });
                let sys = &n.system;
                let all_def = [&sys.a, &sys.b, &sys.c].iter().all(|m| {
                    (0..m.nrows())
                        .all(|i| (0..m.ncols()).all(|j| k.eval(m.get(i, j), &pt).is_some()))
                });
                if !nz || !all_def {
                    continue;
                }
                let q = StateSpace {
                    a: eval(&sys.a, &pt),
                    b: eval(&sys.b, &pt),
                    c: eval(&sys.c, &pt),
                    d: eval(&sys.d, &pt),
                };
                let rq = scb(&q.a, &q.b, &q.c, &q.d).unwrap();
                assert_eq!(rq.dims, n.result, "branch {:?}", b.equation);
                break;
            }
        }
    }
    assert!(checked >= 5, "only {checked} random systems checked");
}
