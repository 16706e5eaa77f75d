//! Parameter studies on the classes of inputs of issue 22 (items 3, 4, 8), each from a
//! generator with a fixed seed, beside the reproducers:
//!
//! * a swept parameter the file does not have: `sweep`/`critical` exit 2 with one line
//!   naming the file, the key and the parameters the file has;
//! * singular-E families $E = P\,\mathrm{diag}(I_r, N)\,Q$, $A(v) = P\,\mathrm{diag}(J_0 +
//!   vJ_1, I)\,Q$ (rows scaled by $(v - d)/(v - c)$: a pole at $c$, a singular pencil at
//!   $d$): the sweep gives the $r$ finite eigenvalues (those of $J(v)$, computed
//!   independently), a note at $c$ and $d$; `critical` certifies and classifies;
//! * second-order families $M q'' + v L_1 q' + (K_0 + vK_1) q$ ($L(0) = 0$: every
//!   eigenvalue paired at $v = 0$) and first-order families $S(D + (v - c)B)S^{-1}$ with
//!   the planted spectrum $\{\pm wi, \pm a\}$ at $v = c$ inside the range or at either end:
//!   `critical` is verified and finds the imaginary pair exactly when the float spectrum
//!   has one.

use crate::common::Rng;
use crate::common::cli::{run, temp_file};
use exactlti::field::{Q, Rational};
use exactlti::matrix::Matrix;
use exactlti::study::{
    CriticalKind, ParamFamily, PointStatus, SingularReason, charpoly_xv, critical_values, sweep,
    sweep_values,
};
use num_complex::Complex;

fn q(s: &str) -> Rational {
    exactlti::field::parse_rational(s).expect("rational")
}

fn qi(x: i64) -> Rational {
    Rational::from_integer(x.into())
}

fn random_int_matrix(rng: &mut Rng, r: usize, c: usize, range: i64) -> Matrix<Q> {
    Matrix::from_fn(Q, r, c, |_, _| qi(rng.int(-range, range)))
}

/// A random unimodular integer matrix $L U$ (unit triangular factors, entries in -1..=1).
fn unimodular(rng: &mut Rng, n: usize) -> Matrix<Q> {
    let l = Matrix::from_fn(Q, n, n, |i, j| match i.cmp(&j) {
        std::cmp::Ordering::Equal => qi(1),
        std::cmp::Ordering::Greater => qi(rng.int(-1, 1)),
        std::cmp::Ordering::Less => qi(0),
    });
    let u = Matrix::from_fn(Q, n, n, |i, j| match i.cmp(&j) {
        std::cmp::Ordering::Equal => qi(1),
        std::cmp::Ordering::Less => qi(rng.int(-1, 1)),
        std::cmp::Ordering::Greater => qi(0),
    });
    &l * &u
}

fn block_diag(a: &Matrix<Q>, b: &Matrix<Q>) -> Matrix<Q> {
    let (n1, n2) = (a.nrows(), b.nrows());
    let mut m = Matrix::zeros(Q, n1 + n2, n1 + n2);
    m.set_block(0, 0, a);
    m.set_block(n1, n1, b);
    m
}

/// `(c0) + (c1)*v`, each row times `scale[i]` (an expression, or empty).
fn lin_json(c0: &Matrix<Q>, c1: &Matrix<Q>, scale: &[String]) -> String {
    let rows: Vec<String> = (0..c0.nrows())
        .map(|i| {
            let cells: Vec<String> = (0..c0.ncols())
                .map(|j| {
                    let e = format!("({}) + ({})*v", c0.get(i, j), c1.get(i, j));
                    if scale[i].is_empty() {
                        format!("\"{e}\"")
                    } else {
                        format!("\"({e})*{}\"", scale[i])
                    }
                })
                .collect();
            format!("[{}]", cells.join(", "))
        })
        .collect();
    format!("[{}]", rows.join(", "))
}

fn float_matrix(m: &Matrix<Q>) -> nalgebra::DMatrix<f64> {
    nalgebra::DMatrix::from_fn(m.nrows(), m.ncols(), |i, j| {
        exactlti::field::rational_to_f64(m.get(i, j))
    })
}

/// Every eigenvalue of `got` within `tol * (1 + |z|)` of a distinct one of `want`.
fn same_spectrum(got: &[Complex<f64>], want: &[Complex<f64>], tol: f64) -> bool {
    if got.len() != want.len() {
        return false;
    }
    let mut used = vec![false; want.len()];
    got.iter().all(|z| {
        let best = (0..want.len())
            .filter(|&j| !used[j])
            .min_by(|&i, &j| (want[i] - z).norm().total_cmp(&(want[j] - z).norm()));
        match best {
            Some(j) if (want[j] - z).norm() <= tol * (1.0 + z.norm()) => {
                used[j] = true;
                true
            }
            _ => false,
        }
    })
}

// ---------------------------------------------------------------- item 3: unknown name

const NAMES: [&str; 8] = ["a", "b", "m", "k", "c1", "u", "zeta", "omega2"];

#[test]
fn a_parameter_the_file_lacks_is_refused_naming_the_ones_it_has() {
    let mut rng = Rng(0x5eed_0003);
    for case in 0..crate::common::iters(12) {
        let npar = rng.int(0, 3) as usize;
        let mut have: Vec<&str> = vec![];
        while have.len() < npar {
            let n = NAMES[rng.int(0, NAMES.len() as i64 - 1) as usize];
            if !have.contains(&n) {
                have.push(n);
            }
        }
        let params: Vec<String> = have
            .iter()
            .map(|n| format!("\"{n}\": {}", rng.int(1, 9)))
            .collect();
        let x = have.first().copied().unwrap_or("1");
        let body = if case % 2 == 0 {
            format!("\"A\": [[\"{x}\", 1], [-2, -3]]")
        } else {
            format!("\"M\": [[1]], \"L\": [[\"{x}\"]], \"K\": [[2]]")
        };
        let text = format!("{{\"parameters\": {{{}}}, {body}}}", params.join(", "));
        let missing = ["v", "w", "speed", "A"][case % 4];
        let file = temp_file("study-classes", &format!("named{case}.json"), &text);
        let f = file.to_str().unwrap();
        // the library refuses too, with the same message
        let err = ParamFamily::from_file(&file, missing)
            .unwrap_err()
            .to_string();
        for cmd in ["sweep", "critical"] {
            let (code, out, err_cli) =
                run(&[cmd, f, "--param", missing, "--from", "0", "--to", "1"]);
            assert_eq!(code, 2, "{cmd} {text}: {out}{err_cli}");
            assert!(out.is_empty(), "{out}");
            assert_eq!(err_cli.trim().lines().count(), 1, "{err_cli}");
            for must in [f, "key parameters", missing] {
                assert!(err_cli.contains(must), "{err_cli} lacks {must}");
            }
            for n in &have {
                assert!(err_cli.contains(&format!(" {n}")), "{err_cli} lacks {n}");
            }
            if have.is_empty() {
                assert!(err_cli.contains("no parameters"), "{err_cli}");
            }
            assert!(err.contains("key parameters"), "{err}");
        }
        // a parameter the file has is accepted
        if let Some(n) = have.first() {
            assert!(ParamFamily::from_file(&file, n).is_ok(), "{text}");
            let (code, _, e) = run(&["sweep", f, "--param", n, "--from", "0", "--to", "1"]);
            assert_eq!(code, 0, "{text}: {e}");
        }
    }
    // the reproducer: a file without parameters
    let (code, _, e) = run(&[
        "critical",
        "tests/data/improper_s.json",
        "--param",
        "v",
        "--from",
        "-1",
        "--to",
        "1",
    ]);
    assert_eq!(code, 2, "{e}");
    assert!(
        e.contains("improper_s.json") && e.contains("no parameters"),
        "{e}"
    );
}

// ------------------------------------------------------- item 4: singular-E families

/// A singular-E family with $r$ finite eigenvalues $\lambda(J_0 + vJ_1)$, a pole at `c`
/// and a singular pencil at `d` (rows scaled), and its file text.
struct Descriptor {
    n: usize,
    r: usize,
    j0: Matrix<Q>,
    j1: Matrix<Q>,
    text: String,
}

fn singular_e_family(rng: &mut Rng, c: &str, d: &str) -> Descriptor {
    let n = rng.int(2, 5) as usize;
    let r = rng.int(0, n as i64 - 1) as usize;
    let (j0, j1) = (
        random_int_matrix(rng, r, r, 3),
        random_int_matrix(rng, r, r, 2),
    );
    let k = n - r;
    let nil = Matrix::from_fn(
        Q,
        k,
        k,
        |i, j| {
            if j > i { qi(rng.int(0, 1)) } else { qi(0) }
        },
    );
    let (p, qq) = (unimodular(rng, n), unimodular(rng, n));
    let e = &(&p * &block_diag(&Matrix::identity(Q, r), &nil)) * &qq;
    let a0 = &(&p * &block_diag(&j0, &Matrix::identity(Q, k))) * &qq;
    let a1 = &(&p * &block_diag(&j1, &Matrix::zeros(Q, k, k))) * &qq;
    let (rc, rd) = (
        rng.int(0, n as i64 - 1) as usize,
        rng.int(0, n as i64 - 1) as usize,
    );
    let scale: Vec<String> = (0..n)
        .map(|i| match (i == rc, i == rd) {
            (true, true) => format!("(v - ({d}))/(v - ({c}))"),
            (true, false) => format!("1/(v - ({c}))"),
            (false, true) => format!("(v - ({d}))"),
            _ => String::new(),
        })
        .collect();
    let zero = Matrix::zeros(Q, n, n);
    let text = format!(
        "{{\"name\": \"singular E, r = {r}\", \"parameters\": {{\"v\": 0}}, \"E\": {}, \"A\": {}}}",
        lin_json(&e, &zero, &scale),
        lin_json(&a0, &a1, &scale)
    );
    Descriptor { n, r, j0, j1, text }
}

impl Descriptor {
    fn j_at(&self, v: &Rational) -> Matrix<Q> {
        &self.j0 + &self.j1.scale(v)
    }
}

#[test]
fn sweep_of_singular_e_families_gives_the_finite_eigenvalues_and_notes() {
    let mut rng = Rng(0x5eed_0004);
    // values -2, -1.5, ..., 2: the pole at c = -1, the singular pencil at d = 3/2
    let vals = sweep_values(-2.0, 2.0, 9);
    for case in 0..crate::common::iters(30) {
        let g = singular_e_family(&mut rng, "-1", "3/2");
        let file = temp_file("study-classes", &format!("sing{case}.json"), &g.text);
        let fam = ParamFamily::from_file(&file, "v").unwrap();
        // exact: P(x, v0) is the characteristic polynomial of J(v0), of degree r
        let p = charpoly_xv(&fam).unwrap();
        assert_eq!(p.deg_x(), g.r, "{}", g.text);
        let v0 = q("1/3");
        assert_eq!(p.at(&v0).monic(), g.j_at(&v0).charpoly().unwrap());
        let af = fam.state_matrix_q(&v0).unwrap();
        assert_eq!(af.charpoly().unwrap(), g.j_at(&v0).charpoly().unwrap());
        let sw = sweep(&fam, &vals, None).unwrap();
        for (i, v) in vals.iter().enumerate() {
            let (ev, st) = (&sw.eigenvalues[i], sw.status[i]);
            if *v == -1.0 {
                assert_eq!((st, ev.len()), (PointStatus::Pole, 0), "{}", g.text);
            } else if *v == 1.5 {
                assert_eq!(
                    (st, ev.len()),
                    (PointStatus::SingularPencil, 0),
                    "{}",
                    g.text
                );
            } else {
                assert_eq!(
                    st,
                    PointStatus::Descriptor {
                        infinite: g.n - g.r
                    },
                    "v = {v}: {}",
                    g.text
                );
                let j = g.j_at(&Rational::from_float(*v).unwrap());
                let want = exactlti::float::eigenvalues(&float_matrix(&j)).unwrap();
                assert!(
                    same_spectrum(ev, &want, 1e-5),
                    "v = {v}: {ev:?} vs {want:?}\n{}",
                    g.text
                );
            }
        }
        if case < 4 {
            // the command line says the same
            let f = file.to_str().unwrap();
            let (code, out, e) = run(&[
                "sweep", f, "--param", "v", "--from", "-2", "--to", "2", "--points", "9",
                "--format", "json",
            ]);
            assert_eq!(code, 0, "{e}");
            let j: serde_json::Value = serde_json::from_str(&out).unwrap();
            let notes = j["notes"].as_array().unwrap();
            let reasons: Vec<&str> = notes
                .iter()
                .map(|x| x["reason"].as_str().unwrap())
                .collect();
            assert_eq!(reasons, ["pole", "singular_pencil"], "{out}");
            assert_eq!(notes[0]["index"], 2);
            assert_eq!(j["infinite_eigenvalues"][0], (g.n - g.r) as i64);
            assert_eq!(j["eigenvalues_approx"][0].as_array().unwrap().len(), g.r);
            let (code, text, _) = run(&[
                "sweep", f, "--param", "v", "--from", "-2", "--to", "2", "--points", "9",
            ]);
            assert_eq!(code, 0);
            assert!(
                text.contains("has a pole") && text.contains("singular pencil"),
                "{text}"
            );
        }
    }
}

#[test]
fn critical_of_singular_e_families_is_verified_and_classifies_the_points() {
    let mut rng = Rng(0x5eed_0084);
    for case in 0..crate::common::iters(24) {
        let g = singular_e_family(&mut rng, "-1", "1/2");
        let file = temp_file("study-classes", &format!("crit{case}.json"), &g.text);
        let fam = ParamFamily::from_file(&file, "v").unwrap();
        let cv = critical_values(&fam, &q("-2"), &q("2")).unwrap();
        assert!(cv.verified, "{}", g.text);
        let sing: Vec<(String, SingularReason)> = cv
            .singular
            .iter()
            .map(|a| a.to_string())
            .zip(cv.singular_reasons.iter().copied())
            .filter(|(s, _)| s == "-1" || s == "1/2")
            .collect();
        assert_eq!(
            sing,
            [
                ("-1".to_string(), SingularReason::Pole),
                ("1/2".to_string(), SingularReason::SingularPencil)
            ],
            "{}",
            g.text
        );
        // the counts in each interval are those of J at the sample point
        for iv in &cv.intervals {
            let j = g.j_at(&iv.sample);
            let ev = exactlti::float::eigenvalues(&float_matrix(&j)).unwrap();
            if ev.iter().any(|z| z.re.abs() < 1e-9) {
                continue;
            }
            let unstable = ev.iter().filter(|z| z.re > 0.0).count();
            assert_eq!(iv.counts.unstable(), unstable, "{}", g.text);
            assert_eq!(iv.stable, unstable == 0);
        }
        // every critical value: its kind holds for the eigenvalues of J there
        for c in &cv.critical {
            let got = c
                .eigenvalues_at
                .iter()
                .map(|e| e.multiplicity)
                .sum::<usize>();
            assert_eq!(got, g.r, "{:?} at {}: {}", c.kind, c.value, g.text);
        }
        if case < 3 {
            let (code, out, e) = run(&[
                "critical",
                file.to_str().unwrap(),
                "--param",
                "v",
                "--from",
                "-2",
                "--to",
                "2",
                "--format",
                "json",
            ]);
            assert_eq!(code, 0, "{e}");
            let j: serde_json::Value = serde_json::from_str(&out).unwrap();
            let reasons: Vec<&str> = j["singular_values"]
                .as_array()
                .unwrap()
                .iter()
                .map(|x| x["reason"].as_str().unwrap())
                .collect();
            assert!(reasons.contains(&"pole") && reasons.contains(&"singular_pencil"));
        }
    }
}

// ------------------------------------------- item 8: coincident and boundary pairs

/// Does the float spectrum of the exact matrix `a` hold a purely imaginary pair?
fn has_imaginary_pair(a: &Matrix<Q>) -> Option<bool> {
    let ev = exactlti::float::eigenvalues(&float_matrix(a)).ok()?;
    let scale = ev.iter().map(|z| z.norm()).fold(1.0, f64::max);
    let near = |x: f64| x.abs() < 1e-9 * scale;
    if ev.iter().any(|z| !near(z.re) && z.re.abs() < 1e-5 * scale) {
        return None; // too close to call in floating point
    }
    // a zero eigenvalue in a Jordan block scatters by sqrt(eps): not a pair
    Some(ev.iter().any(|z| near(z.re) && z.im.abs() > 1e-6 * scale))
}

#[test]
fn undamped_point_of_second_order_families_is_certified() {
    let mut rng = Rng(0x5eed_0008);
    let mut with_pair = 0;
    for case in 0..crate::common::iters(36) {
        let n = rng.int(1, 3) as usize;
        let m = Matrix::from_fn(Q, n, n, |i, j| {
            if i == j {
                qi(rng.int(1, 3))
            } else {
                qi(rng.int(-1, 1))
            }
        });
        let (l1, k0, k1) = (
            random_int_matrix(&mut rng, n, n, 3),
            random_int_matrix(&mut rng, n, n, 4),
            random_int_matrix(&mut rng, n, n, 2),
        );
        let zero = Matrix::zeros(Q, n, n);
        let none = vec![String::new(); n];
        let text = format!(
            "{{\"parameters\": {{\"v\": 1}}, \"M\": {}, \"L\": {}, \"K\": {}}}",
            lin_json(&m, &zero, &none),
            lin_json(&zero, &l1, &none),
            lin_json(&k0, &k1, &none)
        );
        let file = temp_file("study-classes", &format!("second{case}.json"), &text);
        let fam = ParamFamily::from_file(&file, "v").unwrap();
        let (from, to) = [("0", "2"), ("-3", "0"), ("-1", "1")][case % 3];
        let cv = critical_values(&fam, &q(from), &q(to)).unwrap();
        assert!(cv.verified, "{text} on [{from}, {to}]");
        assert!(cv.critical.iter().all(|c| c.certified), "{text}");
        // (a singular M can make v = 0 a point where an eigenvalue goes to infinity)
        if cv.persistent.contains(&CriticalKind::ImaginaryPair)
            || cv.singular.iter().any(|s| s.to_string() == "0")
        {
            continue;
        }
        let at0 = cv
            .critical
            .iter()
            .any(|c| c.kind == CriticalKind::ImaginaryPair && c.value.to_string() == "0");
        let rejected0 = cv.rejected.iter().any(|(r, _)| r.to_string() == "0");
        assert!(at0 != rejected0, "v = 0 decided once: {text}");
        if let Some(want) = has_imaginary_pair(&fam.state_matrix_q(&qi(0)).unwrap()) {
            assert_eq!(at0, want, "{text}");
            with_pair += usize::from(want);
        }
        if case < 3 {
            let (code, _, e) = run(&[
                "critical",
                file.to_str().unwrap(),
                "--param",
                "v",
                "--from",
                from,
                "--to",
                to,
            ]);
            assert_eq!(code, 0, "{text}: {e}");
        }
    }
    assert!(
        with_pair >= 10,
        "the class exercises imaginary pairs ({with_pair})"
    );
}

#[test]
fn planted_imaginary_pair_beside_a_real_pair_is_certified_inside_and_at_the_ends() {
    let mut rng = Rng(0x5eed_0088);
    for case in 0..crate::common::iters(18) {
        let (w, a) = (rng.int(1, 3), rng.int(1, 3));
        let extra = rng.int(0, 1) as usize;
        let n = 4 + extra;
        let mut d = Matrix::zeros(Q, n, n);
        d.set(0, 1, qi(w));
        d.set(1, 0, qi(-w));
        d.set(2, 3, qi(a));
        d.set(3, 2, qi(a));
        if extra == 1 {
            d.set(4, 4, qi(-rng.int(1, 4)));
        }
        let s = unimodular(&mut rng, n);
        let si = s.inverse().unwrap();
        let b = random_int_matrix(&mut rng, n, n, 2);
        let c = Rational::new(rng.int(-3, 3).into(), rng.int(1, 2).into());
        // A(v) = S (D + (v - c) B) S^-1 = (S D S^-1 - c S B S^-1) + v S B S^-1
        let a1 = &(&s * &b) * &si;
        let a0 = &(&(&s * &d) * &si) - &a1.scale(&c);
        let text = format!(
            "{{\"parameters\": {{\"v\": 0}}, \"A\": {}}}",
            lin_json(&a0, &a1, &vec![String::new(); n])
        );
        let file = temp_file("study-classes", &format!("planted{case}.json"), &text);
        let fam = ParamFamily::from_file(&file, "v").unwrap();
        let one = qi(1);
        let (from, to) = match case % 3 {
            0 => (&c - &one, &c + &one),
            1 => (c.clone(), &c + &one),
            _ => (&c - &one, c.clone()),
        };
        let cv = critical_values(&fam, &from, &to).unwrap();
        assert!(cv.verified, "{text} on [{from}, {to}]");
        let at_c: Vec<_> = cv
            .critical
            .iter()
            .filter(|x| x.value.to_rational() == Some(c.clone()))
            .collect();
        let pair = at_c
            .iter()
            .find(|x| x.kind == CriticalKind::ImaginaryPair)
            .unwrap_or_else(|| panic!("no imaginary pair at {c}: {text}"));
        assert!(pair.certified);
        assert!((pair.omega.unwrap() - w as f64).abs() < 1e-9, "{text}");
        let reals = pair
            .eigenvalues_at
            .iter()
            .filter(|e| e.approx.1 == 0.0 && (e.approx.0.abs() - a as f64).abs() < 1e-9)
            .count();
        assert_eq!(reals, 2, "the real pair +-{a}: {text}");
        if case < 3 {
            let (code, _, e) = run(&[
                "critical",
                file.to_str().unwrap(),
                "--param",
                "v",
                "--from",
                &from.to_string(),
                "--to",
                &to.to_string(),
            ]);
            assert_eq!(code, 0, "{text}: {e}");
        }
    }
}

#[test]
fn reproducers_of_issue_22() {
    // A0 + (v - 1) A1 with the spectrum {+-2i, +-1} at v = 1, range [1, 2]
    let text = r#"{"parameters": {"v": 1}, "A": [
        ["(v-1)*1", "2+(v-1)*2", "(v-1)*(-1)", "(v-1)*3"],
        ["-2", "(v-1)*1", "(v-1)*2", "(v-1)*(-1)"],
        ["(v-1)*1", "(v-1)*1", "(v-1)*(-2)", "1+(v-1)*1"],
        ["(v-1)*3", "(v-1)*(-1)", "1", "(v-1)*2"]]}"#;
    let file = temp_file("study-classes", "coincident.json", text);
    let (code, out, e) = run(&[
        "critical",
        file.to_str().unwrap(),
        "--param",
        "v",
        "--from",
        "1",
        "--to",
        "2",
        "--format",
        "json",
    ]);
    assert_eq!(code, 0, "{e}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    let first = &j["critical_values"][0];
    assert_eq!(
        (first["value"].as_str(), first["kind"].as_str()),
        (Some("1"), Some("imaginary_pair"))
    );
    assert_eq!(first["certified"], true);
    assert_eq!(j["verified"], true);
    // M q'' + v L1 q' + K q on [0, 2]: at v = 0 the pairs +-1.0589 and +-1.7667i
    let text = r#"{"parameters": {"v": 1}, "M": [[1, 0], [0, 2]],
        "L": [["v", "2*v"], ["-v", "v"]], "K": [[3, 1], [1, -2]]}"#;
    let file = temp_file("study-classes", "undamped.json", text);
    let (code, out, e) = run(&[
        "critical",
        file.to_str().unwrap(),
        "--param",
        "v",
        "--from",
        "0",
        "--to",
        "2",
        "--format",
        "json",
    ]);
    assert_eq!(code, 0, "{e}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["critical_values"][0]["kind"], "imaginary_pair");
    assert_eq!(j["critical_values"][0]["certified"], true);
    // improper_s.json with the parameter in A: singular E, critical and sweep answer
    let text = r#"{"parameters": {"v": 1},
        "E": [[0, 1, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, 1]],
        "A": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, "-3*v"]]}"#;
    let file = temp_file("study-classes", "improper_v.json", text);
    let f = file.to_str().unwrap();
    let (code, out, e) = run(&[
        "critical", f, "--param", "v", "--from", "-1", "--to", "1", "--format", "json",
    ]);
    assert_eq!(code, 0, "{e}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["critical_values"][0]["value"], "0");
    assert_eq!(j["critical_values"][0]["kind"], "zero_eigenvalue");
    let (code, out, e) = run(&[
        "sweep", f, "--param", "v", "--from", "1", "--to", "2", "--points", "2", "--format", "json",
    ]);
    assert_eq!(code, 0, "{e}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    // one finite eigenvalue -3v, three infinite
    assert_eq!(j["infinite_eigenvalues"][1], 3);
    let ev = j["eigenvalues_approx"][1][0][0].as_f64().unwrap();
    assert!((ev + 6.0).abs() < 1e-12, "{out}");
}
