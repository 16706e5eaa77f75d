//! Issue 22, items 1, 2 and 7, by class: random regular descriptor systems (invertible `E`,
//! singular `E` of index 1, higher index proper and improper, with hidden modes and
//! non-dynamic modes; fixed seeds) and the published reproducers.
//!
//! * (1) the float frequency response on the pencil equals $C(j\omega E - A)^{-1}B + D$
//!   evaluated exactly over $\mathbb{Q}(i)$; the standard form's transfer matrix equals the
//!   descriptor's exactly, in the basis a person writes down ($E^{-1}A$, index-1 elimination);
//! * (2) `finite_dynamics` has the pencil's finite Jordan structure (staircase route);
//! * (7) `minimal_descriptor`: order at most the input's, verified, transfer matrix kept.
use exactlti::field::{Field, Q, QuadraticField, Rational};
use exactlti::matrix::Matrix;
use exactlti::pencil::pencil_structure;
use exactlti::realization::{
    StandardMethod, descriptor_to_standard, finite_dynamics, minimal_descriptor,
};
use exactlti::system::{Descriptor, StateSpace};

use crate::common::{Rng, unimodular};

/// The classes of the generator.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    Invertible,
    IndexOne,
    /// Nilpotent blocks of size >= 2 with `N B = 0` on the infinite part: proper.
    HigherProper,
    /// Any nilpotent blocks, any `B`, `C`: improper in general.
    Higher,
}

const KINDS: [Kind; 4] = [
    Kind::Invertible,
    Kind::IndexOne,
    Kind::HigherProper,
    Kind::Higher,
];

fn small(rng: &mut Rng) -> Rational {
    Rational::new(rng.int(-3, 3).into(), rng.int(1, 2).into())
}

fn rand_mat(rng: &mut Rng, r: usize, c: usize, zeros: bool) -> Matrix<Q> {
    Matrix::from_fn(Q, r, c, |_, _| {
        if zeros && rng.int(0, 3) == 0 {
            Rational::from_integer(0.into())
        } else {
            small(rng)
        }
    })
}

/// Unit upper triangular plus a random strictly upper part: invertible, harmless.
fn unit_upper(rng: &mut Rng, n: usize) -> Matrix<Q> {
    Matrix::from_fn(Q, n, n, |i, j| match i.cmp(&j) {
        std::cmp::Ordering::Equal => Rational::from_integer(rng.int(1, 3).into()),
        std::cmp::Ordering::Less => small(rng),
        _ => Rational::from_integer(0.into()),
    })
}

/// Nilpotent Jordan blocks (ones above the diagonal) of the given sizes.
fn nilpotent(sizes: &[usize]) -> Matrix<Q> {
    let n: usize = sizes.iter().sum();
    let mut m = Matrix::zeros(Q, n, n);
    let mut o = 0;
    for &k in sizes {
        for i in 0..k.saturating_sub(1) {
            m.set(o + i, o + i + 1, Rational::from_integer(1.into()));
        }
        o += k;
    }
    m
}

/// A random regular descriptor system of the class `kind` with `n` states: in Weierstrass
/// coordinates $E_0 = \mathrm{diag}(E_f, N)$, $A_0 = \mathrm{diag}(A_f, I)$ (index 1: $N = 0$
/// with a coupling $A_{12}$, $A_{21}$), then $E = PE_0Q$, $A = PA_0Q$, $B = PB_0$, $C = C_0Q$
/// with unimodular $P$, $Q$ (identity half the time for index 1: a block-diagonal $E$).
fn random_descriptor(kind: Kind, n: usize, m: usize, p: usize, rng: &mut Rng) -> Descriptor<Q> {
    let ni = match kind {
        Kind::Invertible => 0,
        _ => rng.int(1, (n / 2).max(1) as i64) as usize,
    };
    let nf = n - ni;
    let mut sizes = vec![];
    if matches!(kind, Kind::Higher | Kind::HigherProper) {
        let mut left = ni;
        while left > 0 {
            let k = (rng.int(1, 3) as usize).min(left);
            sizes.push(k);
            left -= k;
        }
    } else {
        sizes = vec![1; ni];
    }
    let ef = unit_upper(rng, nf);
    let e0 = Matrix::block_diag(Q, &[ef, nilpotent(&sizes)]);
    let mut a0 = rand_mat(rng, n, n, true);
    for i in nf..n {
        for j in 0..n {
            let v = if i == j { 1 } else { 0 };
            if kind != Kind::IndexOne || j >= nf {
                a0.set(i, j, Rational::from_integer(v.into()));
            }
        }
        if kind != Kind::IndexOne {
            for j in 0..nf {
                a0.set(j, i, Rational::from_integer(0.into()));
            }
        }
    }
    let mut b0 = rand_mat(rng, n, m, true);
    if kind == Kind::HigherProper {
        // N B = 0: only the first row of each nilpotent block is excited
        let mut o = nf;
        for &k in &sizes {
            for i in 1..k {
                for j in 0..m {
                    b0.set(o + i, j, Rational::from_integer(0.into()));
                }
            }
            o += k;
        }
    }
    let c0 = rand_mat(rng, p, n, true);
    let d = rand_mat(rng, p, m, true);
    let (pm, qm) = if kind == Kind::IndexOne && rng.int(0, 1) == 0 {
        (Matrix::identity(Q, n), Matrix::identity(Q, n))
    } else {
        (unimodular(&Q, n, rng), unimodular(&Q, n, rng))
    };
    Descriptor::new(
        &(&pm * &e0) * &qm,
        &(&pm * &a0) * &qm,
        &pm * &b0,
        &c0 * &qm,
        d,
    )
    .unwrap()
}

/// $C(s_0E - A)^{-1}B + D$ over any field, or `None` at an eigenvalue (the oracle: a plain
/// inverse, independent of every conversion under test).
fn eval<K: Field>(s: &Descriptor<K>, s0: &K::Elem) -> Option<Matrix<K>> {
    let x = (&s.e.scale(s0) - &s.a).inverse().ok()?;
    Some(&(&(&s.c * &x) * &s.b) + &s.d)
}

/// Equal transfer matrices: the entries of $G_1 - G_2$ have numerator degree at most
/// $n_1 + n_2$ over the common denominator, so $n_1 + n_2 + 1$ agreeing points prove it.
fn same_tf(s1: &Descriptor<Q>, s2: &Descriptor<Q>) -> bool {
    let need = s1.nstates() + s2.nstates() + 1;
    let (mut agree, mut t) = (0, 0i64);
    while agree < need {
        t += 1;
        assert!(t < 200, "too many poles hit");
        let s0 = Rational::new((3 * t - 100).into(), 11.into());
        let (Some(g1), Some(g2)) = (eval(s1, &s0), eval(s2, &s0)) else {
            continue;
        };
        if g1 != g2 {
            return false;
        }
        agree += 1;
    }
    true
}

fn as_descriptor(s: &StateSpace<Q>) -> Descriptor<Q> {
    Descriptor::new(
        Matrix::identity(Q, s.nstates()),
        s.a.clone(),
        s.b.clone(),
        s.c.clone(),
        s.d.clone(),
    )
    .unwrap()
}

/// The fixed-seed sample of the class: `count` systems of each kind, 2..=7 states.
fn sample(seed: u64, count: usize) -> Vec<(Kind, Descriptor<Q>)> {
    let mut rng = Rng(seed);
    let mut out = vec![];
    for i in 0..count {
        for kind in KINDS {
            let n = 2 + (i % 6);
            let (m, p) = (rng.int(1, 2) as usize, rng.int(1, 2) as usize);
            out.push((kind, random_descriptor(kind, n, m, p, &mut rng)));
        }
    }
    out
}

fn to_c(m: &Matrix<Q>) -> nalgebra::DMatrix<num_complex::Complex<f64>> {
    let a = m.to_approx();
    nalgebra::DMatrix::from_fn(m.nrows(), m.ncols(), |i, j| {
        num_complex::Complex::new(a[i][j], 0.0)
    })
}

/// (1) float `freqresp_descriptor` against the exact value over Q(i), relative 1e-9.
#[test]
fn freqresp_on_the_pencil_matches_exact_complex_evaluation() {
    let k = QuadraticField::gaussian();
    let i = k.gen_elem();
    let mut checked = 0;
    for (kind, s) in sample(0x22_01, crate::common::iters(12)) {
        let sk = Descriptor::new(
            s.e.convert_to(&k),
            s.a.convert_to(&k),
            s.b.convert_to(&k),
            s.c.convert_to(&k),
            s.d.convert_to(&k),
        )
        .unwrap();
        let wq = [(1, 3), (5, 2), (7, 1)];
        let ws = wq.map(|(n, d)| Rational::new(n.into(), d.into()));
        let hz: Vec<f64> = wq
            .iter()
            .map(|&(n, d)| n as f64 / d as f64 / (2.0 * std::f64::consts::PI))
            .collect();
        let [e, a, b, c, d] = [&s.e, &s.a, &s.b, &s.c, &s.d].map(to_c);
        let Ok(fr) = exactlti::float::freqresp_descriptor(&e, [&a, &b, &c, &d], &hz) else {
            continue;
        };
        for (w, g) in ws.iter().zip(&fr) {
            let s0 = k.mul(&k.from_rational(w), &i);
            let Some(exact) = eval(&sk, &s0) else {
                continue;
            };
            let ex = exact.to_approx_complex();
            let scale = ex
                .iter()
                .flatten()
                .map(|(re, im)| re.hypot(*im))
                .fold(1e-300f64, f64::max);
            for r in 0..g.nrows() {
                for col in 0..g.ncols() {
                    let (re, im) = ex[r][col];
                    let err = (g[(r, col)] - num_complex::Complex::new(re, im)).norm();
                    assert!(err <= 1e-9 * scale, "{kind:?} w = {w}: {err} vs {scale}");
                }
            }
            checked += 1;
        }
    }
    assert!(checked > 60, "{checked}");
}

/// (1) the standard form's transfer matrix equals the descriptor's, exactly; `E^-1 A` when
/// `E` is invertible; index 1 eliminates; improper systems are refused.
#[test]
fn standard_form_keeps_the_transfer_matrix_in_a_recognisable_basis() {
    let mut proper = 0;
    for (kind, s) in sample(0x22_02, crate::common::iters(10)) {
        let f = match descriptor_to_standard(&s) {
            Ok(f) => f,
            Err(exactlti::Error::ImproperTransfer(_)) => {
                assert_eq!(kind, Kind::Higher, "{s:?}");
                continue;
            }
            Err(e) => panic!("{kind:?}: {e}"),
        };
        proper += 1;
        assert!(f.verified, "{kind:?}");
        assert!(same_tf(&s, &as_descriptor(&f.system)), "{kind:?}: {s:?}");
        let n_f = s.nstates() - f.removed_infinite;
        assert_eq!(f.system.nstates(), n_f);
        match kind {
            Kind::Invertible => {
                let ei = s.e.inverse().unwrap();
                assert_eq!(f.method, StandardMethod::Invertible);
                assert_eq!(f.system.a, &ei * &s.a);
                assert_eq!(f.system.b, &ei * &s.b);
                assert_eq!((&f.system.c, &f.system.d), (&s.c, &s.d));
            }
            Kind::IndexOne => assert_eq!(f.method, StandardMethod::IndexOne),
            _ => {}
        }
    }
    assert!(proper > 30, "{proper}");
}

/// Index 1 with a block-diagonal `E`: the kept states are the file's own differential
/// states (V1 selects them) and the formulas are the hand elimination.
#[test]
fn index_one_hand_elimination() {
    use exactlti::qmat;
    // x1' = -x1 + x2, 0 = x1 - 2 x2 + u, y = x2: x2 = (x1 + u)/2
    let s = Descriptor::new(
        qmat![[1, 0], [0, 0]],
        qmat![[-1, 1], [1, -2]],
        qmat![[0], [1]],
        qmat![[0, 1]],
        qmat![[0]],
    )
    .unwrap();
    let f = descriptor_to_standard(&s).unwrap();
    assert_eq!(f.method, StandardMethod::IndexOne);
    let h = |n: i64, d: i64| Rational::new(n.into(), d.into());
    assert_eq!(f.system.a.get(0, 0), &h(-1, 2));
    assert_eq!(f.system.b.get(0, 0), &h(1, 2));
    assert_eq!(f.system.c.get(0, 0), &h(1, 2));
    assert_eq!(f.system.d.get(0, 0), &h(1, 2));
    // x = V1 z: x1 = z, x2 = z / 2 (when u = 0)
    assert_eq!((f.v1.get(0, 0), f.v1.get(1, 0)), (&h(1, 1), &h(1, 2)));
    assert!(f.verified);
}

/// The issue's reproducer: E = diag(2, 1) gives E^-1 B = [0, 1], C = [1, 0].
#[test]
fn e_diag_2_1_reproducer() {
    use exactlti::qmat;
    let s = Descriptor::new(
        qmat![[2, 0], [0, 1]],
        qmat![[0, 1], [-1, -1]],
        qmat![[0], [1]],
        qmat![[1, 0]],
        qmat![[0]],
    )
    .unwrap();
    let f = descriptor_to_standard(&s).unwrap();
    assert_eq!(f.system.b, qmat![[0], [1]]);
    assert_eq!(f.system.c, qmat![[1, 0]]);
    assert_eq!(f.v1, Matrix::identity(Q, 2));
    assert!(f.verified);
}

/// (2) the finite dynamics carry the pencil's finite Jordan structure (staircase route).
#[test]
fn finite_dynamics_have_the_pencils_finite_jordan_structure() {
    for (kind, s) in sample(0x22_03, crate::common::iters(4)) {
        let (af, _) = finite_dynamics(&s).unwrap();
        let ps = pencil_structure(&s.a, &s.e).unwrap();
        assert!(ps.verified);
        let jf = exactlti::jordan::jordan(&af).unwrap();
        assert!(jf.verified);
        let key = |j: &exactlti::jordan::JordanForm| {
            let mut v: Vec<(String, Vec<usize>)> = j
                .eigenvalues
                .iter()
                .map(|e| (e.minpoly.to_string(), e.blocks.clone()))
                .collect();
            v.sort();
            v
        };
        assert_eq!(key(&jf), key(&ps.finite), "{kind:?}");
        assert_eq!(af.nrows(), ps.structure.finite_order());
    }
}

/// (7) minimal descriptor realizations: order <= input's, verified, transfer matrix kept,
/// never above the irreducible order (340 systems as in the issue).
#[test]
fn minimal_descriptor_order_never_exceeds_the_input() {
    let mut reduced = 0;
    for (kind, s) in sample(0x22_07, crate::common::iters(85)) {
        let m = minimal_descriptor(&s).unwrap();
        assert!(
            m.order <= s.nstates(),
            "{kind:?}: {} > {}",
            m.order,
            s.nstates()
        );
        assert!(m.order <= m.irreducible_order && m.irreducible_order <= s.nstates());
        assert!(m.verified, "{kind:?}: {s:?}");
        assert!(same_tf(&s, &m.system), "{kind:?}");
        // minimal again: nothing left to remove
        assert_eq!(minimal_descriptor(&m.system).unwrap().order, m.order);
        reduced += usize::from(m.order < s.nstates());
    }
    assert!(reduced > 50, "{reduced}");
}

/// The published examples of DescriptorSystems.jl's `test_ordred.jl` (gminreal / gir).
#[test]
fn published_minimal_and_irreducible_orders() {
    use exactlti::qmat;
    let shift = |n: usize, k: usize| {
        Matrix::from_fn(Q, n, n, |i, j| {
            Rational::from_integer(i64::from(j == i + k).into())
        })
    };
    // De Teran, Dopico, Mackey (ELA 2009), G = [[s^2, s], [s, 1]]: minimal 3, irreducible 4
    let dtdm = Descriptor::new(
        shift(6, 2),
        Matrix::identity(Q, 6),
        qmat![[0, 0], [0, 0], [0, 1], [1, 0], [1, 0], [0, 0]],
        qmat![[-1, 0, 0, 0, 0, 0], [0, -1, 0, 0, 0, 0]],
        qmat![[0, 0], [0, 1]],
    )
    .unwrap();
    // Van Dooren, Dewilde (LAA 1983): minimal 3, irreducible 4
    let vdd = Descriptor::new(
        shift(9, 3),
        Matrix::identity(Q, 9),
        qmat![
            [0, 0, 0],
            [0, 0, 0],
            [0, 0, 0],
            [1, 3, 0],
            [1, 4, 2],
            [0, -1, -2],
            [1, 4, 2],
            [0, 0, 0],
            [1, 4, 2]
        ],
        qmat![
            [-1, 0, 0, 0, 0, 0, 0, 0, 0],
            [0, -1, 0, 0, 0, 0, 0, 0, 0],
            [0, 0, -1, 0, 0, 0, 0, 0, 0]
        ],
        qmat![[1, 2, -2], [0, -1, -2], [0, 0, 0]],
    )
    .unwrap();
    for (s, name) in [(&dtdm, "DTDM"), (&vdd, "VDD")] {
        let m = minimal_descriptor(s).unwrap();
        assert!(m.verified, "{name}");
        assert_eq!((m.order, m.irreducible_order), (3, 4), "{name}");
        assert!(same_tf(s, &m.system), "{name}");
    }
}

/// The CLI on the reproducers: `standard`, `freqresp`, `jordan`, `tf`, `minreal --descriptor`.
mod cli {
    use crate::common::cli::{run, temp_file};
    use serde_json::{Value, json};

    fn json_of(args: &[&str]) -> (i32, Value, String) {
        let (code, out, err) = run(args);
        (code, serde_json::from_str(&out).unwrap_or(Value::Null), err)
    }

    const E2: &str = r#"{"E": [[2, 0], [0, 1]], "A": [[0, 1], [-1, -1]], "B": [[0], [1]],
        "C": [[1, 0]], "D": [[0]]}"#;
    const DTDM: &str = r#"{"E": [[0,0,1,0,0,0],[0,0,0,1,0,0],[0,0,0,0,1,0],[0,0,0,0,0,1],
        [0,0,0,0,0,0],[0,0,0,0,0,0]],
        "A": [[1,0,0,0,0,0],[0,1,0,0,0,0],[0,0,1,0,0,0],[0,0,0,1,0,0],[0,0,0,0,1,0],[0,0,0,0,0,1]],
        "B": [[0,0],[0,0],[0,1],[1,0],[1,0],[0,0]], "C": [[-1,0,0,0,0,0],[0,-1,0,0,0,0]],
        "D": [[0,0],[0,1]]}"#;

    #[test]
    fn standard_of_e_diag_2_1_is_e_inverse_a() {
        let p = temp_file("descr", "e2.json", E2);
        let (code, v, err) = json_of(&["standard", p.to_str().unwrap(), "--format", "json"]);
        assert_eq!(code, 0, "{err}");
        assert_eq!(v["B"], json!([["0"], ["1"]]));
        assert_eq!(v["C"], json!([["1", "0"]]));
        assert_eq!(v["A"], json!([["0", "1/2"], ["-1", "-1"]]));
        assert_eq!(v["verified"], json!(true));
    }

    /// G(s) = 1 / (2 s^2 + 2 s + 1) against the CLI's frequency response.
    #[test]
    fn freqresp_of_a_descriptor_file_is_the_pencils() {
        let p = temp_file("descr", "e2f.json", E2);
        let args = ["freqresp", p.to_str().unwrap(), "--format", "json"];
        let (code, v, err) = json_of(&[&args[..], &["--from", "0.01", "--to", "10"]].concat());
        assert_eq!(code, 0, "{err}");
        let fs = v["frequencies_hz"].as_array().unwrap();
        for (k, f) in fs.iter().enumerate() {
            let w = 2.0 * std::f64::consts::PI * f.as_f64().unwrap();
            let den = num_complex::Complex::new(1.0 - 2.0 * w * w, 2.0 * w);
            let g = num_complex::Complex::new(1.0, 0.0) / den;
            let z = &v["response"][k][0][0];
            let got = num_complex::Complex::new(z[0].as_f64().unwrap(), z[1].as_f64().unwrap());
            assert!(
                (got - g).norm() <= 1e-12 * g.norm(),
                "f = {f}: {got} vs {g}"
            );
        }
    }

    #[test]
    fn jordan_of_a_descriptor_file_is_the_pencils() {
        let p = temp_file("descr", "e2j.json", E2);
        let (code, v, err) = json_of(&["jordan", p.to_str().unwrap(), "--format", "json"]);
        assert_eq!(code, 0, "{err}");
        // E^-1 A, not A (whose charpoly is x^2 + x + 1)
        assert_eq!(v["charpoly"], json!("x^2 + x + 1/2"));
        assert_eq!(v["infinite_blocks"], json!([]));
        let p = temp_file("descr", "dtdm.json", DTDM);
        let (code, v, err) = json_of(&["jordan", p.to_str().unwrap(), "--format", "json"]);
        assert_eq!(code, 0, "{err}");
        assert_eq!(
            (&v["n"], &v["infinite_blocks"]),
            (&json!(0), &json!([3, 3]))
        );
        // improper and singular pencils: the finite part, or a refusal with the reason
        let (code, v, err) = json_of(&["jordan", "tests/data/improper_s.json", "--format", "json"]);
        assert_eq!(code, 0, "{err}");
        assert_eq!(
            (&v["n"], &v["infinite_blocks"]),
            (&json!(1), &json!([1, 2]))
        );
        let sing =
            r#"{"E": [[1, 0], [0, 0]], "A": [[1, 0], [0, 0]], "B": [[1], [0]], "C": [[1, 0]]}"#;
        let p = temp_file("descr", "sing.json", sing);
        let (code, _, err) = run(&["jordan", p.to_str().unwrap()]);
        assert_eq!(code, 2, "{err}");
        assert!(
            err.contains("singular") && err.lines().count() == 1,
            "{err}"
        );
    }

    #[test]
    fn tf_and_minreal_of_the_published_example_exit_0() {
        let p = temp_file("descr", "dtdm2.json", DTDM);
        let (code, v, err) = json_of(&[
            "minreal",
            "--descriptor",
            p.to_str().unwrap(),
            "--format",
            "json",
        ]);
        assert_eq!(code, 0, "{err}");
        assert_eq!(
            (&v["order"], &v["irreducible_order"]),
            (&json!(3), &json!(4))
        );
        let (code, v, err) = json_of(&["tf", p.to_str().unwrap(), "--format", "json"]);
        assert_eq!(code, 0, "{err}");
        assert_eq!(v["verified"], json!(true));
    }
}

/// The bicycle (index 1, the input appended as an algebraic state): the standard form keeps
/// the file's six differential states and B = E11^-1 e4 (the old split gave entries ~9e9).
#[test]
fn bicycle_standard_form_is_the_hand_elimination() {
    for v in ["2", "8"] {
        let desc = crate::bicycle::bicycle_descriptor(v);
        let f = descriptor_to_standard(&desc).unwrap();
        assert_eq!(f.method, StandardMethod::IndexOne);
        assert!(f.verified);
        let mut e4 = Matrix::zeros(Q, 6, 1);
        e4.set(3, 0, Rational::from_integer(1.into()));
        let e11 = desc.e.submatrix(0, 6, 0, 6);
        assert_eq!(f.system.b, &e11.inverse().unwrap() * &e4);
        assert_eq!(
            f.system.a,
            &e11.inverse().unwrap() * &desc.a.submatrix(0, 6, 0, 6)
        );
        assert_eq!(f.v1.submatrix(0, 6, 0, 6), Matrix::identity(Q, 6));
        assert!(f.v1.submatrix(6, 7, 0, 6).is_zero());
    }
}
