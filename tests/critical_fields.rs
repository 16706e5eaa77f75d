//! `critical` over $\mathbb{Q}(\sqrt 2)$ and $\mathbb{Q}(i)$ (issue 24) against an
//! independent computation: at each reported critical value $r$ the system is read again by
//! the one loader ([`System::from_text`] with the value given: $r$ itself when rational, a
//! 60-digit decimal of it otherwise) over its field $K$, and its exact characteristic
//! polynomial over $K$ must show the reported event (a zero eigenvalue: $\det A = 0$; a
//! double eigenvalue: $\mathrm{Res}(\chi, \chi') = 0$, with the number of Jordan blocks
//! $n - \operatorname{rank}(A - \lambda I)$ when $\lambda \in K$; a crossing: an eigenvalue
//! on the imaginary axis), which a nearby generic value must not show. Completeness: on a
//! grid, every change of the number of unstable eigenvalues (floats) and every sign change of
//! the discriminant (exact, over a real $K$) is bracketed by a reported value.

use exactlti::api::{Options, System, SystemVisitor};
use exactlti::field::Field;
use exactlti::io::{SystemFile, SystemFormat, TypedSystem};
use exactlti::report::display::fmt_rational;
use exactlti::rng::SplitMix64;
use exactlti::study::critical::over_k::critical_values_of_file;
use exactlti::study::{CriticalKind, CriticalValues};
use num_rational::BigRational as Rational;

fn temp_file(name: &str, text: &str) -> std::path::PathBuf {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("exactlti-crit-fields");
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

/// What the one loader's system over $K$ shows at one value.
#[derive(Debug)]
struct Facts {
    n: usize,
    det_zero: bool,
    det_abs: f64,
    disc_zero: bool,
    /// (floats) the smallest |eigenvalue| and the smallest distance of two eigenvalues
    min_abs: f64,
    min_gap: f64,
    /// (real) the sign of the discriminant, over a real field
    disc_sign: i32,
    /// number of Jordan blocks of the repeated eigenvalue when it lies in K
    blocks: Option<usize>,
    /// an eigenvalue within 1e-9 of the imaginary axis (not zero)
    on_axis: bool,
    unstable: usize,
}

struct Probe;

impl SystemVisitor for Probe {
    type Output = Facts;
    fn visit<K: Field + 'static>(self, _f: &SystemFile, t: &TypedSystem<K>) -> Facts {
        let a = &t.ss.a;
        let k = a.field().clone();
        let n = a.nrows();
        let chi = a.charpoly().unwrap();
        let det = chi.coeff(0);
        let disc = chi.resultant(&chi.derivative());
        let abs = |x: &K::Elem| {
            let (re, im) = k.approx(x).unwrap();
            (re * re + im * im).sqrt()
        };
        let (dre, dim) = k.approx(&disc).unwrap();
        let g = chi.gcd(&chi.derivative());
        let blocks = (g.degree() == Some(1)).then(|| {
            let g = g.monic();
            let lambda = k.neg(&g.coeff(0));
            let shifted = a
                .try_sub(&exactlti::matrix::Matrix::identity(k.clone(), n).scale(&lambda))
                .unwrap();
            n - shifted.rank()
        });
        let ev = exactlti::float::to_cmatrix(a)
            .unwrap()
            .eigenvalues()
            .unwrap();
        let on_axis = ev.iter().any(|z| z.re.abs() < 1e-9 && z.im.abs() > 1e-6);
        let unstable = ev.iter().filter(|z| z.re > 1e-9).count();
        Facts {
            n,
            det_zero: k.is_zero(&det),
            det_abs: abs(&det),
            disc_zero: k.is_zero(&disc),
            min_abs: ev.iter().map(|z| z.norm()).fold(f64::INFINITY, f64::min),
            min_gap: (0..ev.len())
                .flat_map(|i| (0..i).map(move |j| (i, j)))
                .map(|(i, j)| (ev[i] - ev[j]).norm())
                .fold(f64::INFINITY, f64::min),
            disc_sign: if dim.abs() > 0.0 || dre == 0.0 {
                0
            } else if dre > 0.0 {
                1
            } else {
                -1
            },
            blocks,
            on_axis,
            unstable,
        }
    }
}

fn facts(text: &str, param: &str, value: &str) -> Facts {
    let opts = Options {
        symbolic: None,
        at: vec![(param.to_string(), value.to_string())],
    };
    System::from_text(text, SystemFormat::Json, "x.json", &opts)
        .unwrap()
        .run(Probe)
}

fn q(s: &str) -> Rational {
    exactlti::field::parse_rational(s).unwrap()
}

/// Checks every reported value of `cv` against the loader (see the module docs).
fn check_values(text: &str, param: &str, cv: &CriticalValues) {
    assert!(cv.verified, "not verified");
    let others: Vec<f64> = cv.critical.iter().map(|c| c.value.approx().0).collect();
    for c in &cv.critical {
        let r = &c.value;
        let exact = r.to_rational();
        let shown = match &exact {
            Some(x) => fmt_rational(x),
            None => r.digits(60).0,
        };
        let at = facts(text, param, &shown);
        let total: usize = c.eigenvalues_at.iter().map(|e| e.multiplicity).sum();
        assert_eq!(total, at.n, "{shown}: multiplicities add up to the order");
        for e in &c.eigenvalues_at {
            assert_eq!(e.blocks.iter().sum::<usize>(), e.multiplicity);
        }
        // a generic value nearby: r + 1/997 (when no other reported value is that close)
        let near = r.approx().0 + 1.0 / 997.0;
        let generic = others.iter().all(|o| (o - near).abs() > 1e-4);
        let s = exact.clone().unwrap_or_else(|| q(&r.digits(60).0)) + q("1/997");
        let off = facts(text, param, &fmt_rational(&s));
        match c.kind {
            CriticalKind::ZeroEigenvalue => {
                match exact {
                    Some(_) => assert!(at.det_zero, "{shown}: det != 0"),
                    None => assert!(at.min_abs < 1e-9, "{shown}: min |l| = {}", at.min_abs),
                }
                if generic {
                    assert!(!off.det_zero && off.det_abs > 1e-12);
                }
            }
            CriticalKind::DoubleEigenvalue => {
                match exact {
                    Some(_) => assert!(at.disc_zero, "{shown}: disc != 0"),
                    None => assert!(at.min_gap < 1e-6, "{shown}: eigenvalue gap {}", at.min_gap),
                }
                if generic {
                    assert!(!off.disc_zero);
                }
                // the Jordan blocks of the double eigenvalue, when it lies in K (exact r)
                if let (Some(_), Some(nb)) = (&exact, at.blocks) {
                    let rep: Vec<_> = c
                        .eigenvalues_at
                        .iter()
                        .filter(|e| e.multiplicity > 1)
                        .collect();
                    assert_eq!(rep.len(), 1, "{shown}");
                    assert_eq!(
                        rep[0].blocks.len(),
                        nb,
                        "{shown}: blocks {:?}",
                        rep[0].blocks
                    );
                }
            }
            CriticalKind::ImaginaryPair | CriticalKind::ImaginaryEigenvalue => {
                assert!(at.on_axis, "{shown}: no eigenvalue on the imaginary axis");
                if generic {
                    assert!(!off.on_axis, "{shown}: still on the axis nearby");
                }
            }
        }
    }
}

/// Completeness on a grid of `m` rationals in `[a, b]`.
fn check_grid(text: &str, param: &str, cv: &CriticalValues, a: i64, b: i64, m: i64, real: bool) {
    let crossings: Vec<f64> = cv
        .critical
        .iter()
        .filter(|c| c.kind != CriticalKind::DoubleEigenvalue)
        .map(|c| c.value.approx().0)
        .chain(cv.singular.iter().map(|s| s.approx().0))
        .collect();
    let doubles: Vec<f64> = cv
        .critical
        .iter()
        .filter(|c| c.kind == CriticalKind::DoubleEigenvalue)
        .map(|c| c.value.approx().0)
        .chain(cv.singular.iter().map(|s| s.approx().0))
        .collect();
    let pts: Vec<Rational> = (0..=m)
        .map(|j| q(&format!("{}/{}", a * m + j * (b - a), m)) + q("1/7919"))
        .collect();
    let fs: Vec<Facts> = pts
        .iter()
        .map(|p| facts(text, param, &fmt_rational(p)))
        .collect();
    let x = |p: &Rational| exactlti::field::rational_to_f64(p);
    for (w, f) in pts.windows(2).zip(fs.windows(2)) {
        let (lo, hi) = (x(&w[0]), x(&w[1]));
        let inside = |v: &[f64]| v.iter().any(|c| *c >= lo - 1e-12 && *c <= hi + 1e-12);
        if f[0].unstable != f[1].unstable {
            assert!(
                inside(&crossings),
                "unstable count changes in [{lo}, {hi}] unreported"
            );
        }
        if real && f[0].disc_sign * f[1].disc_sign < 0 {
            assert!(
                inside(&doubles),
                "discriminant changes sign in [{lo}, {hi}] unreported"
            );
        }
    }
    // the intervals' counts against the floats at their samples
    for iv in &cv.intervals {
        let f = facts(text, param, &fmt_rational(&iv.sample));
        let reported = if real {
            iv.counts.unstable()
        } else {
            iv.counts.unstable() / 2
        };
        assert_eq!(reported, f.unstable, "interval sample {}", iv.sample);
        assert_eq!(iv.stable, f.unstable == 0 && !f.on_axis && f.min_abs > 1e-9);
    }
}

fn crit(text: &str, name: &str, param: &str, a: &str, b: &str) -> CriticalValues {
    let p = temp_file(name, text);
    let sys = System::open(&p, &Options::default()).unwrap();
    let exactlti::io::Ground::Quadratic(k) = sys.ground().clone() else {
        panic!("not over a quadratic field");
    };
    critical_values_of_file(&p, param, &[], &k, &q(a), &q(b)).unwrap()
}

fn summary(cv: &CriticalValues) -> Vec<(String, &'static str, String)> {
    cv.critical
        .iter()
        .map(|c| {
            (
                c.value.value_string(),
                c.kind.name(),
                c.minpoly_over_field.as_ref().unwrap().to_string(),
            )
        })
        .collect()
}

#[test]
fn parity_files_over_sqrt2_and_i() {
    let sqrt2 = r#"{"parameters": {"c": "3"}, "A": [[0, 1, 0], [-2, "-c*sqrt(2)", 0], [0, 0, -1]], "B": [[0], [1], [1]], "C": [[1, 0, 0]]}"#;
    let cv = crit(sqrt2, "s.json", "c", "0", "4");
    // x^2 + c sqrt2 x + 2: pair +-i sqrt2 at 0, double at c = 2; -1 double at c = 3/sqrt 2,
    // a value in K, not in Q (minimal polynomial x^2 - 9/2 over Q, x - 3 sqrt2/2 over K)
    assert_eq!(
        summary(&cv),
        [
            ("0".into(), "imaginary_pair", "x".into()),
            ("2".into(), "double_eigenvalue", "x - 2".into()),
            (
                "3*sqrt(2)/2".into(),
                "double_eigenvalue",
                "x - 3*sqrt(2)/2".into()
            ),
        ]
    );
    assert_eq!(cv.critical[2].value.minpoly().to_string(), "x^2 - 9/2");
    // at 2 one block [2] (a companion matrix), at 3/sqrt2 two blocks [1, 1] (-1 decoupled)
    let rep = |i: usize| {
        cv.critical[i]
            .eigenvalues_at
            .iter()
            .find(|e| e.multiplicity == 2)
            .unwrap()
            .blocks
            .clone()
    };
    assert_eq!((rep(1), rep(2)), (vec![2], vec![1, 1]));
    check_values(sqrt2, "c", &cv);
    check_grid(sqrt2, "c", &cv, 0, 4, 200, true);
    // over Q(i) with the coupling i: at c = 3 the double eigenvalue -1 has ONE block (over
    // Q, with 0 in place of i, two)
    let qi = r#"{"parameters": {"c": "3"}, "A": [[0, 1, 0], [-2, "-c", "i"], [0, 0, -1]], "B": [[0], [1], [1]], "C": [[1, 0, 0]]}"#;
    let cv = crit(qi, "i.json", "c", "0", "4");
    assert_eq!(
        summary(&cv),
        [
            ("0".into(), "imaginary_eigenvalue", "x".into()),
            ("2*sqrt(2)".into(), "double_eigenvalue", "x^2 - 8".into()),
            ("3".into(), "double_eigenvalue", "x - 3".into()),
        ]
    );
    let blocks = cv.critical[2]
        .eigenvalues_at
        .iter()
        .find(|e| e.multiplicity == 2)
        .unwrap();
    assert_eq!(blocks.blocks, vec![2]);
    check_values(qi, "c", &cv);
    check_grid(qi, "c", &cv, 0, 4, 200, false);
}

#[test]
fn descriptor_file_has_the_critical_values_of_its_finite_part() {
    let std = r#"{"parameters": {"c": "3"}, "A": [[0, 1, 0], [-2, "-c*sqrt(2)", 0], [0, 0, -1]]}"#;
    let desc = r#"{"parameters": {"c": "3"}, "A": [[0, 1, 0, 0], [-2, "-c*sqrt(2)", 0, 0], [0, 0, -1, 0], [1, 0, 0, -1]], "B": [[0], [1], [1], [0]], "C": [[0, 0, 0, 1]], "D": [[0]], "E": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 0]]}"#;
    let a = crit(std, "std.json", "c", "-4", "4");
    let b = crit(desc, "desc.json", "c", "-4", "4");
    assert_eq!(summary(&a), summary(&b));
    assert!(b.verified);
}

#[test]
fn persistent_zero_eigenvalue_over_sqrt2() {
    // a rigid-body mode (0 for every c) beside x^2 + c sqrt2 x + 2
    let text = r#"{"parameters": {"c": "1"}, "A": [[0, 0, 0], [0, 0, 1], [0, -2, "-c*sqrt(2)"]]}"#;
    let cv = crit(text, "z.json", "c", "-3", "3");
    assert!(cv.persistent.contains(&CriticalKind::ZeroEigenvalue));
    assert_eq!(
        summary(&cv),
        [
            ("-2".into(), "double_eigenvalue", "x + 2".into()),
            ("0".into(), "imaginary_pair", "x".into()),
            ("2".into(), "double_eigenvalue", "x - 2".into()),
        ]
    );
    assert!(
        cv.intervals
            .iter()
            .all(|iv| iv.counts.zero == 1 && !iv.stable)
    );
    check_values(text, "c", &cv);
    check_grid(text, "c", &cv, -3, 3, 60, true);
}

/// A random entry `a + b*unit` with small integers.
fn entry(rng: &mut SplitMix64, unit: &str) -> String {
    format!("({} + {}*{unit})", rng.int(-3, 3), rng.int(-2, 2))
}

#[test]
fn random_families_over_sqrt2_and_i_agree_with_the_loader() {
    let mut rng = SplitMix64(24);
    let mut reported = 0;
    for case in 0..12 {
        let (unit, real) = if case % 2 == 0 {
            ("sqrt(2)", true)
        } else {
            ("i", false)
        };
        let rows: Vec<String> = (0..3)
            .map(|_| {
                let cells: Vec<String> = (0..3)
                    .map(|_| {
                        let a0 = entry(&mut rng, unit);
                        if rng.int(0, 2) == 0 {
                            format!("\"{a0} + c*{}\"", rng.int(-2, 2))
                        } else {
                            format!("\"{a0}\"")
                        }
                    })
                    .collect();
                format!("[{}]", cells.join(", "))
            })
            .collect();
        // make sure the parameter is used
        let text = format!(
            r#"{{"parameters": {{"c": "1"}}, "A": [{}], "B": [[1], [0], ["c"]], "C": [[1, 0, 0]]}}"#,
            rows.join(", ")
        )
        .replacen("\"]", " + c\"]", 1);
        let cv = crit(&text, &format!("r{case}.json"), "c", "-3", "3");
        reported += cv.critical.len();
        check_values(&text, "c", &cv);
        check_grid(&text, "c", &cv, -3, 3, 120, real);
    }
    assert!(
        reported >= 6,
        "the generator produced too few critical values ({reported})"
    );
}
