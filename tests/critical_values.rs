//! Critical values hold values (issue 23 item 4): at a double eigenvalue the factor of
//! $P(x, v_0)$ is a polynomial over $\mathbb{Q}(v_0)$ (or $K(v_0)$) and, when linear, its
//! root is an exact algebraic number; text, JSON and LaTeX are rendered from them.

use exactlti::algebraic::AlgebraicNumber;
use exactlti::field::{Field, Q, QuadraticField, Rational};
use exactlti::poly::Poly;
use exactlti::study::critical::over_k::critical_values_of_file;
use exactlti::study::critical::{EigenvalueAt, FactorAt};
use exactlti::study::{CriticalKind, CriticalValues, ParamFamily, critical_values};
use std::path::{Path, PathBuf};

fn q(n: i64, d: i64) -> Rational {
    Rational::new(n.into(), d.into())
}

fn write(name: &str, text: &str) -> PathBuf {
    crate::common::cli::temp_file("critical-values", name, text)
}

const YAW: &str = r#"{"parameters": {"m": 1500, "J": 2500, "lf": 1.2, "lr": 1.4, "cf": 80000,
 "cr": 80000, "v": null},
 "A": [["-(cf+cr)/(m*v)", "(cr*lr-cf*lf)/(m*v) - v"],
       ["(cr*lr-cf*lf)/(J*v)", "-(cf*lf^2+cr*lr^2)/(J*v)"]],
 "B": [["cf/m"], ["cf*lf/J"]], "C": [[0, 1]], "D": [[0]]}"#;

/// The one repeated eigenvalue at the only double-eigenvalue critical value (and that value).
fn double(cv: &CriticalValues) -> (&AlgebraicNumber, &EigenvalueAt) {
    let ds: Vec<_> = cv
        .critical
        .iter()
        .filter(|c| c.kind == CriticalKind::DoubleEigenvalue)
        .collect();
    assert_eq!(ds.len(), 1, "{:?}", cv.critical);
    let reps: Vec<_> = ds[0]
        .eigenvalues_at
        .iter()
        .filter(|e| e.multiplicity == 2)
        .collect();
    assert_eq!(reps.len(), 1);
    (&ds[0].value, reps[0])
}

/// The root of $x^2 - c$ with the sign of `positive`.
fn sqrt_root(c: &Rational, positive: bool) -> AlgebraicNumber {
    let p = Poly::new(Q, vec![-c.clone(), q(0, 1), q(1, 1)]);
    let mut r = AlgebraicNumber::roots_of_irreducible(&p).unwrap();
    if positive {
        r.pop().unwrap()
    } else {
        r.remove(0)
    }
}

/// $x - \lambda$ over $\mathbb{Q}(v_0)$ divides $P(x, v_0)$ twice.
fn factor_divides_twice(cv: &CriticalValues, v0: &AlgebraicNumber, e: &EigenvalueAt) {
    let Some(FactorAt::Q(f)) = &e.factor else {
        panic!("a factor over Q(v0): {:?}", e.factor)
    };
    assert_eq!(f.deg(), 1);
    let k = v0.to_number_field();
    let pk = cv.charpoly.at_nf(&k);
    assert!(
        pk.rem(&f.mul(f)).is_zero(),
        "(x - lambda)^2 divides P(x, v0)"
    );
}

#[test]
fn yaw_plane_double_eigenvalue_is_exact() {
    let file = write("yaw.json", YAW);
    let fam = ParamFamily::from_file(&file, "v").unwrap();
    let cv = critical_values(&fam, &q(1, 1), &q(80, 1)).unwrap();
    assert!(cv.verified);
    // v0 = 2 sqrt(610)/15, lambda = -404 sqrt(610)/305 (lambda^2 = 404^2 * 610 / 305^2)
    assert_eq!(cv.critical.len(), 1);
    let (v0, e) = double(&cv);
    assert_eq!(v0, &sqrt_root(&q(488, 45), true));
    assert_eq!(e.blocks, [2]);
    let want = sqrt_root(&(q(404 * 404 * 610, 1) / q(305 * 305, 1)), false);
    assert_eq!(e.value.as_ref(), Some(&want));
    assert_eq!(want.value_string(), "-404*sqrt(610)/305");
    factor_divides_twice(&cv, v0, e);
}

fn cli(file: &Path, format: &str) -> String {
    let file = file.to_str().unwrap();
    let args = [
        "critical", file, "--param", "v", "--from", "1", "--to", "80",
    ];
    let (code, out, err) = crate::common::cli::run(&[&args[..], &["--format", format]].concat());
    assert_eq!(code, 0, "{err}");
    out
}

#[test]
fn yaw_plane_factor_reads_as_a_polynomial() {
    let file = write("yaw-cli.json", YAW);
    let text = cli(&file, "text");
    // was `factor: x - -(3232*t)/(976/3)`
    assert!(text.contains("factor: x + 606/61*t"), "{text}");
    assert!(text.contains("eigenvalue: -404*sqrt(610)/305"), "{text}");
    assert!(!text.contains("- -") && !text.contains("/("), "{text}");
    let j: serde_json::Value = serde_json::from_str(&cli(&file, "json")).unwrap();
    let e = &j["critical_values"][0]["eigenvalues_at"][0];
    assert_eq!(e["factor"], "x + 606/61*t");
    assert_eq!(e["eigenvalue"], "-404*sqrt(610)/305");
    assert_eq!(e["blocks"], serde_json::json!([2]));
    let tex = cli(&file, "latex");
    assert!(tex.contains("$x + \\frac{606}{61} t$"), "{tex}");
    assert!(tex.contains("$-\\frac{404 \\sqrt{610}}{305}$"), "{tex}");
}

/// A small deterministic generator (fixed seed).
struct Lcg(u64);
impl Lcg {
    fn next(&mut self, n: u64) -> i64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        ((self.0 >> 33) % n) as i64
    }
}

/// The class $A(v) = [[v, 1], [-k, m v]]$ ($k > 0$ not a square, $m \ne \pm 1$): the
/// discriminant $v^2 (1 - m)^2 - 4k$ vanishes at $v_0 = 2\sqrt k/|1 - m|$, where the
/// eigenvalue $\lambda = v_0 (1 + m)/2$ is double with one block; $\lambda^2 = k (1 + m)^2 /
/// (1 - m)^2$.
#[test]
fn double_eigenvalues_of_a_class_are_exact() {
    let mut g = Lcg(23);
    let mut seen = 0;
    while seen < 10 {
        let k = 2 + g.next(40);
        if (1..=7).any(|s| s * s == k) {
            continue;
        }
        let m = q(g.next(13) - 6, 1 + g.next(4));
        if m == q(1, 1) || m == q(-1, 1) {
            continue;
        }
        seen += 1;
        let text = format!(
            r#"{{"parameters": {{"v": null}}, "A": [["v", 1], [{}, "({m})*v"]],
               "B": [[0], [1]], "C": [[1, 0]], "D": [[0]]}}"#,
            -k
        );
        let file = write(&format!("class{seen}.json"), &text);
        let fam = ParamFamily::from_file(&file, "v").unwrap();
        let cv = critical_values(&fam, &q(1, 100), &q(1000, 1)).unwrap();
        let one_m = q(1, 1) - &m;
        let one_p = q(1, 1) + &m;
        let v0 = sqrt_root(&(q(4 * k, 1) / (&one_m * &one_m)), true);
        let (got, e) = double(&cv);
        assert_eq!(got, &v0, "k = {k}, m = {m}");
        assert_eq!(e.blocks, [2], "k = {k}, m = {m}");
        let want = sqrt_root(
            &(q(k, 1) * &one_p * &one_p / (&one_m * &one_m)),
            one_p > q(0, 1),
        );
        assert_eq!(e.value.as_ref(), Some(&want), "k = {k}, m = {m}");
        factor_divides_twice(&cv, got, e);
    }
}

/// Over $\mathbb{Q}(\sqrt 2)$: $A(v) = [[v, 1], [-\sqrt 2, 3 v]]$, $v_0 = 2^{1/4}$ (degree 2
/// over $K$, 4 over $\mathbb{Q}$), $\lambda = 2 v_0 = 2^{5/4}$, a root of $x^4 - 32$.
#[test]
fn a_double_eigenvalue_over_q_sqrt_2() {
    let text = r#"{"parameters": {"v": null}, "A": [["v", 1], ["-sqrt(2)", "3*v"]],
        "B": [[0], [1]], "C": [[1, 0]], "D": [[0]]}"#;
    let file = write("sqrt2.json", text);
    let k = QuadraticField::new(2).unwrap();
    let cv = critical_values_of_file(&file, "v", &[], &k, &q(0, 1), &q(10, 1)).unwrap();
    let (_, e) = double(&cv);
    let Some(FactorAt::K(f)) = &e.factor else {
        panic!("a factor over K(v0): {:?}", e.factor)
    };
    assert_eq!(f.deg(), 1);
    let v = e.value.as_ref().expect("a linear factor has its value");
    assert_eq!(
        v.minpoly(),
        &Poly::new(Q, vec![q(-32, 1), q(0, 1), q(0, 1), q(0, 1), q(1, 1)])
    );
    assert!((v.approx().0 - 2f64.powf(1.25)).abs() < 1e-12 && v.approx().1 == 0.0);
    // lambda = 2 t in K(t): the factor is x - 2 t
    let e_field = f.field();
    assert!(e_field.is_zero(&e_field.add(
        &f.coeff(0),
        &e_field.add(&e_field.generator(), &e_field.generator())
    )));
}
