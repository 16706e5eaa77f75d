//! Jordan form over QQ(p1..pk) (issue 13): the vehicle-dynamics paper's yaw-plane models in
//! symbols (eq. 24-35), random properties (A T = T J, agreement with the rational Jordan form
//! at points), and a naive oracle (block sizes from ranks of (A - theta I)^k at a point).

use exactlti::field::ElemDisplay;
use exactlti::field::{Field, Q, Rational};
use exactlti::jordan::jordan;
use exactlti::jordan::{Component, JordanForm, jordan_qp};
use exactlti::matrix::Matrix;
use exactlti::ratfunc::RatFunc;
use exactlti::ratfunc::RatFuncField;
use exactlti::report::sections::conditions_qp;

use crate::common::qp_matrix as mat;

fn q(n: i64, d: i64) -> Rational {
    Rational::new(n.into(), d.into())
}

type Form = JordanForm<RatFuncField>;

/// The component of the eigenvalue `v` in Q(p).
fn eigenvalue<'a>(jf: &'a Form, v: &RatFunc) -> Option<&'a Component<RatFuncField>> {
    let i = jf.values().iter().position(|x| x.as_ref() == Some(v))?;
    Some(&jf.components[i])
}

fn strings(jf: &Form, m: &Matrix<RatFuncField>) -> Vec<Vec<String>> {
    (0..m.nrows())
        .map(|i| {
            (0..m.ncols())
                .map(|j| jf.base().fmt_elem(m.get(i, j)))
                .collect()
        })
        .collect()
}

#[test]
fn yaw_single_wheel_eq27_35() {
    let (k, a) = crate::jcommon::yaw27();
    let jf = jordan_qp(&a).unwrap();
    assert!(jf.verified && jf.complete());
    let kk = jf.base();
    let (t, j) = jf.primary_form().unwrap();
    // eq. 29: s = -cr/(m u); the zero root in ONE 3x3 block
    assert_eq!(jf.components.len(), 2);
    let zero = eigenvalue(&jf, &kk.zero()).expect("eigenvalue 0");
    assert_eq!(zero.blocks, [3]);
    assert_eq!(zero.kernel_dims, [1, 2, 3]);
    let s = k.parse("-cr/(m*u)").unwrap();
    let se = eigenvalue(&jf, &s).expect("eigenvalue -cr/(m u)");
    assert_eq!(se.blocks, [1]);
    assert_eq!(kk.fmt_elem(&kk.neg(&se.factor.coeff(0))), "-cr/(m*u)");
    // eq. 35 exactly
    let j35 = mat(
        kk,
        &[
            &["0", "1", "0", "0"],
            &["0", "0", "1", "0"],
            &["0", "0", "0", "0"],
            &["0", "0", "0", "-cr/(m*u)"],
        ],
    );
    assert_eq!(j, j35);
    // A T = T J as rational functions (independently of the library's own flag)
    assert_eq!(jf.a.try_mul(&t).unwrap(), t.try_mul(&j).unwrap());
    assert!(!kk.is_zero(&t.det().unwrap()));
    // eq. 28: the eigenvectors are multiples of X1 = e1 and X2 = (m u/cr, 0, 1, 0)
    let t = &t;
    for i in 1..4 {
        assert!(kk.is_zero(t.get(i, 0)));
    }
    let x2_ratio = kk.div(t.get(0, 3), t.get(2, 3)).unwrap();
    assert_eq!(x2_ratio, k.parse("m*u/cr").unwrap());
    assert!(kk.is_zero(t.get(1, 3)) && kk.is_zero(t.get(3, 3)));
    // eq. 34 (the paper's normalisation) is a valid T for the same J
    let t34 = mat(
        kk,
        &[
            &["1", "0", "0", "m*u/cr"],
            &["0", "1/u", "m/cr", "0"],
            &["0", "0", "m*u/cr", "1"],
            &["0", "0", "-1/u", "0"],
        ],
    );
    assert_eq!(jf.a.try_mul(&t34).unwrap(), t34.try_mul(&j35).unwrap());
    // conditions: cr, m, u (nothing else can make the structure break)
    assert_eq!(conditions_qp(&jf), ["cr", "m", "u"]);
    let _ = strings(&jf, t);
}

#[test]
fn general_yaw_plane_eq24_26_charpoly_and_discriminant() {
    let k = RatFuncField::new(&["a", "b", "cf", "cr", "Izz", "m", "u"]).unwrap();
    let a = mat(
        &k,
        &[
            &["0", "u", "-1", "0"],
            &["0", "0", "0", "-1"],
            &["0", "0", "-(cf + cr)/(m*u)", "-(a*cf - b*cr)/(m*u) - u"],
            &[
                "0",
                "0",
                "-(a*cf - b*cr)/(Izz*u)",
                "-(a^2*cf + b^2*cr)/(Izz*u)",
            ],
        ],
    );
    let jf = jordan_qp(&a).unwrap();
    assert!(jf.verified);
    assert!(
        !jf.complete(),
        "the nonzero pair is a root pair of a quadratic"
    );
    let kk = jf.base();
    let zero = eigenvalue(&jf, &kk.zero()).expect("0");
    // two zeros (lateral offset, heading) in one 2x2 block
    assert_eq!(zero.blocks, [2]);
    let quad = jf.components.iter().find(|c| c.degree() == 2).unwrap();
    assert_eq!(quad.blocks, [1]);
    // the quadratic: s^2 + tr s + det with the textbook coefficients
    let tr = k
        .parse("(cf + cr)/(m*u) + (a^2*cf + b^2*cr)/(Izz*u)")
        .unwrap();
    let det = k
        .parse("(cf*cr*(a + b)^2)/(m*Izz*u^2) - (a*cf - b*cr)/Izz")
        .unwrap();
    assert_eq!(
        quad.factor.coeffs(),
        &[det.clone(), tr.clone(), k.one()][..]
    );
    // the understeer/oversteer split: the discriminant tr^2 - 4 det is a condition
    let disc = k.sub(&k.mul(&tr, &tr), &k.mul(&k.from_i64(4), &det));
    let want: Vec<_> = exactlti::mpoly::factor(disc.num())
        .unwrap()
        .factors
        .into_iter()
        .map(|(f, _)| f)
        .collect();
    for f in &want {
        assert!(
            jf.conditions.iter().any(|c| c.num() == f),
            "discriminant factor missing"
        );
    }
}

/// Random matrices with a planted structure: A = S J S^-1 with symbolic S and J; the
/// result's blocks match J, and at rational points A(p0) T(p0) = T(p0) J(p0) and the
/// rational Jordan form has the same blocks wherever no condition vanishes.
#[test]
fn planted_structures_random_points() {
    let k = RatFuncField::new(&["p", "q"]).unwrap();
    let cases: &[(&[&[&str]], &[usize])] = &[
        (
            &[&["p", "1", "0"], &["0", "p", "0"], &["0", "0", "q"]],
            &[2, 1],
        ),
        (
            &[&["p", "1", "0"], &["0", "p", "1"], &["0", "0", "p"]],
            &[3],
        ),
        (
            &[&["p+q", "0", "0"], &["0", "p+q", "0"], &["0", "0", "p*q"]],
            &[1, 1, 1],
        ),
    ];
    let s = mat(&k, &[&["1", "p", "0"], &["q", "1", "1"], &["0", "1", "2"]]);
    let si = s.inverse().unwrap();
    let mut seed = 12345u64;
    for (rows, want_blocks) in cases {
        let j0 = mat(&k, rows);
        let a = s.try_mul(&j0).unwrap().try_mul(&si).unwrap();
        let jf = jordan_qp(&a).unwrap();
        assert!(jf.verified && jf.complete());
        let mut blocks: Vec<usize> = jf
            .components
            .iter()
            .flat_map(|c| c.blocks.iter().copied())
            .collect();
        blocks.sort_unstable_by(|x, y| y.cmp(x));
        assert_eq!(&blocks, want_blocks);
        for _ in 0..4 {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            let p0 = [
                q(
                    ((seed >> 33) % 19) as i64 - 9,
                    1 + ((seed >> 20) % 3) as i64,
                ),
                q(((seed >> 40) % 17) as i64 - 8, 1),
            ];
            if jf.conditions_vanish_at(&p0) {
                continue;
            }
            let (ap, tp, jp) = jf.at(&p0).expect("no pole off the conditions");
            assert_eq!(ap.try_mul(&tp).unwrap(), tp.try_mul(&jp).unwrap());
            assert_ne!(tp.det().unwrap(), Rational::from_integer(0.into()));
            // naive oracle: the rational Jordan form at the point has the same blocks
            let jq = jordan(&ap).unwrap();
            let mut bq: Vec<usize> = jq
                .components
                .iter()
                .flat_map(|c| c.blocks.clone())
                .collect();
            bq.sort_unstable_by(|x, y| y.cmp(x));
            assert_eq!(&bq, want_blocks, "at {p0:?}");
        }
    }
    let _ = Q;
}

#[test]
fn cubic_factor_blocks_from_ranks() {
    // companion of x^3 - p twice (a 2-block per root would need a nilpotent coupling):
    // A = [[C, I], [0, C]] has blocks [2] for each root of x^3 - p
    let k = RatFuncField::new(&["p"]).unwrap();
    let c: &[&str] = &["0", "0", "p", "1", "0", "0", "0", "1", "0"];
    let a = Matrix::from_fn(k.clone(), 6, 6, |i, j| {
        if i < 3 && j < 3 {
            k.parse(c[i * 3 + j]).unwrap()
        } else if i >= 3 && j >= 3 {
            k.parse(c[(i - 3) * 3 + j - 3]).unwrap()
        } else if i < 3 && j == i + 3 {
            k.one()
        } else {
            k.zero()
        }
    });
    let jf = jordan_qp(&a).unwrap();
    assert!(jf.verified && !jf.complete());
    assert_eq!(jf.components.len(), 1);
    let e = &jf.components[0];
    assert_eq!((e.degree(), e.multiplicity), (3, 2));
    assert_eq!(e.blocks, [2]);
    // dim ker f(A)^k over Q(p) = 3 dim ker (A - t I)^k over E
    let dims: Vec<usize> = e.kernel_dims.iter().map(|d| 3 * d).collect();
    assert_eq!(dims, [3, 6]);
    // the discriminant of x^3 - p is -27 p^2: the condition p
    assert!(conditions_qp(&jf).contains(&"p".to_string()));
}

fn run(args: &[&str]) -> (i32, String, String) {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_exactlti"))
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn cli_jordan_over_qp_and_at() {
    let yaw = "data/yaw-plane-single-wheel.json";
    let (code, out, err) = run(&["jordan", yaw, "--symbolic", "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["field"], "QQ(cr, m, u)");
    assert_eq!(j["verified"], true);
    assert_eq!(j["eigenvalues"][0]["value"], "0");
    assert_eq!(j["eigenvalues"][0]["blocks"], serde_json::json!([3]));
    assert_eq!(j["eigenvalues"][1]["value"], "-cr/(m*u)");
    assert_eq!(j["J"][3][3], "-cr/(m*u)");
    assert_eq!(j["J"][0][1], "1");
    assert_eq!(j["conditions"], serde_json::json!(["cr", "m", "u"]));
    assert!(!out.contains("approx"));
    // partly symbolic: cr and u valued, m a symbol
    let (code, out, _) = run(&["jordan", yaw, "--symbolic", "m", "--format", "json"]);
    assert_eq!(code, 0);
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["eigenvalues"][1]["value"], "-4000/m");
    // --at: every symbol valued -> the ordinary rational path
    let (code, out, _) = run(&[
        "jordan",
        yaw,
        "--symbolic",
        "--at",
        "m=1500, u=20, cr=80000",
        "--format",
        "json",
    ]);
    assert_eq!(code, 0);
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["verified"], true);
    assert!(out.contains("-8/3"));
    // --real over QQ(p): every eigenvalue of the yaw plane lies in QQ(p), so the real form is
    // the Jordan form (verified); a factor of degree 4 (sliding masses) is refused with its
    // reason in one line
    let (code, out, _) = run(&["jordan", yaw, "--symbolic", "--real", "--format", "json"]);
    assert_eq!(code, 0);
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["verified"], true);
    let sliding = "data/sliding-masses-symbolic.json";
    let (code, _, err) = run(&["jordan", sliding, "--real"]);
    assert_eq!(code, 2);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("degree 4"), "{err}");
}

/// The mechanical-normal-form paper, App. B (eq. 18-19) over QQ(w1, w2).
fn app_b() -> (RatFuncField, [Matrix<RatFuncField>; 4]) {
    let k = RatFuncField::new(&["w1", "w2"]).unwrap();
    let a = mat(
        &k,
        &[
            &["0", "0", "1", "0"],
            &["0", "0", "0", "1"],
            &["-w1^2", "0", "0", "0"],
            &["0", "-w2^2", "0", "0"],
        ],
    );
    let b = mat(&k, &[&["0"], &["0"], &["0"], &["1"]]);
    let c = mat(&k, &[&["1", "0", "0", "0"]]);
    let d = mat(&k, &[&["0"]]);
    (k, [a, b, c, d])
}

#[test]
fn mnf_appendix_b_in_symbols() {
    use exactlti::structure::mechanical::{
        DEFAULT_MAX_CANDIDATES, mechanical_normal_form_in, transform::transformation_from_x,
    };
    let (k, [a, b, c, d]) = app_b();
    // eq. 19: X = [e1, e3] gives T = [X, A^T X]^T with a zero row: singular for all w1, w2
    let x = mat(&k, &[&["1", "0"], &["0", "0"], &["0", "1"], &["0", "0"]]);
    let t19 = transformation_from_x(&a, &x).unwrap();
    assert!(k.is_zero(&t19.det().unwrap()));
    // the paper prints [X, A^T X] (eq. 19); transformation_from_x returns its transpose
    let eq19 = mat(
        &k,
        &[
            &["1", "0", "0", "-w1^2"],
            &["0", "0", "0", "0"],
            &["0", "1", "1", "0"],
            &["0", "0", "0", "0"],
        ],
    );
    assert_eq!(t19.transpose(), eq19);
    // X = [e1, e2] gives T = I
    let x = mat(&k, &[&["1", "0"], &["0", "1"], &["0", "0"], &["0", "0"]]);
    assert!(transformation_from_x(&a, &x).unwrap().is_identity());
    // the normal form in symbols: exists, verified as rational functions, same charpoly
    let m = mechanical_normal_form_in(None, &a, &b, &c, &d, DEFAULT_MAX_CANDIDATES).unwrap();
    assert!(m.exists && m.verified);
    let f = m.form.unwrap();
    assert_eq!(
        f.a_tilde.charpoly().unwrap(),
        a.charpoly().unwrap(),
        "similar matrices"
    );
    // naive oracle: at w1 = 2, w2 = 3 the rational normal form exists too
    let at = |m: &Matrix<RatFuncField>| {
        Matrix::from_vec(
            Q,
            m.nrows(),
            m.ncols(),
            m.as_slice()
                .iter()
                .map(|x| k.eval(x, &[q(2, 1), q(3, 1)]).unwrap())
                .collect(),
        )
    };
    let r =
        exactlti::structure::mechanical::mechanical_normal_form(&at(&a), &at(&b), &at(&c), &at(&d))
            .unwrap();
    assert!(r.exists && r.verified);
    // CLI
    let (code, out, err) = run(&["mnf", "tests/data/mnf_appendix_b.json", "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["field"], "QQ(w1, w2)");
    assert_eq!(j["exists"], true);
    assert_eq!(j["verified"], true);
    assert!(j["conditions"].is_array() && j["existence_checks"].is_array());
    assert!(!out.contains("approx"));
}

/// The minimal-realization paper's compaction (sec. 3.3, eq. 34-36) in symbols: eq. 36 holds
/// only where det P = 0 (co-linear rows of B or columns of C); the general exact rule
/// (trace conditions) reproduces every Markov parameter.
#[test]
fn compaction_rule_eq34_36() {
    use exactlti::matrix::params::rref_params;
    let k = RatFuncField::new(&[
        "a11", "a12", "a22", "b1", "b2", "b3", "b4", "c1", "c2", "c3", "c4",
    ])
    .unwrap();
    let mm = mat(&k, &[&["a11", "a12"], &["-a12", "a22"]]);
    let a = Matrix::block_diag(k.clone(), &[mm.clone(), mm.clone()]);
    let b = mat(&k, &[&["b1"], &["b2"], &["b3"], &["b4"]]);
    let c = mat(&k, &[&["c1", "c2", "c3", "c4"]]);
    let jf = jordan_qp(&a).unwrap();
    assert!(jf.verified);
    assert_eq!(jf.components.len(), 1);
    assert_eq!(jf.components[0].blocks, [1, 1]);
    let markov = |a: &Matrix<RatFuncField>, b: &Matrix<RatFuncField>, c: &Matrix<RatFuncField>| {
        let mut v = b.clone();
        (0..6)
            .map(|_| {
                let x = c.try_mul(&v).unwrap().get(0, 0).clone();
                v = a.try_mul(&v).unwrap();
                x
            })
            .collect::<Vec<_>>()
    };
    let mut ctrb = b.clone();
    let mut v = b.clone();
    for _ in 1..4 {
        v = a.try_mul(&v).unwrap();
        ctrb = ctrb.hstack(&v).unwrap();
    }
    assert_eq!(rref_params(&ctrb).1.len(), 2);
    let p = b
        .submatrix(0, 2, 0, 1)
        .try_mul(&c.submatrix(0, 1, 0, 2))
        .unwrap()
        .try_add(
            &b.submatrix(2, 4, 0, 1)
                .try_mul(&c.submatrix(0, 1, 2, 4))
                .unwrap(),
        )
        .unwrap();
    let det = p.det().unwrap();
    let want = k.parse("(b1*b4 - b2*b3)*(c1*c4 - c2*c3)").unwrap();
    assert!(
        det == want || det == k.neg(&want),
        "det P = {}",
        k.fmt_elem(&det)
    );
    let tr = |m: &Matrix<RatFuncField>| k.add(m.get(0, 0), m.get(1, 1));
    let tp = tr(&p);
    let c6 = k
        .div(
            &k.sub(
                &k.mul(&k.parse("a11").unwrap(), &tp),
                &tr(&mm.try_mul(&p).unwrap()),
            ),
            &k.parse("a12").unwrap(),
        )
        .unwrap();
    let c56 = Matrix::from_vec(k.clone(), 1, 2, vec![tp, c6]);
    let b56 = mat(&k, &[&["1"], &["0"]]);
    assert_eq!(markov(&a, &b, &c), markov(&mm, &b56, &c56));
    // a wrong compaction (just the first copy) differs
    assert_ne!(
        markov(&a, &b, &c),
        markov(&mm, &b.submatrix(0, 2, 0, 1), &c.submatrix(0, 1, 0, 2))
    );
}
