//! A transfer matrix realized AS WRITTEN (issue 28 item 4: `tf()` keeps what the user wrote,
//! `minreal` cancels): `det(sI - A)` is the product of the column denominators (the written
//! ones, lcm per column), the Markov parameters equal those of the matrix in lowest terms and
//! of its minimal realization exactly, and the Kalman minimal realization of the as-written
//! system has the McMillan degree. Examples incl. edge shapes, a generator of written
//! fractions with planted common factors (fixed seed), the file key `realize` on the CLI.

use crate::common::cli::run;
use exactlti::field::{Field, Q, Quadratic, QuadraticField, Rational};
use exactlti::io::transfer_written::parse_written_fraction;
use exactlti::poly::Poly;
use exactlti::realization::{
    WrittenTransfer, minimal_kalman, realize_as_written, realize_transfer,
};
use exactlti::rng::SplitMix64;
use exactlti::system::StateSpace;

fn written(rows: &[&[&str]]) -> WrittenTransfer<Q> {
    WrittenTransfer {
        entries: rows
            .iter()
            .map(|r| {
                r.iter()
                    .map(|t| parse_written_fraction(t, &[]).unwrap())
                    .collect()
            })
            .collect(),
    }
}

fn markov<K: Field>(s: &StateSpace<K>, count: usize) -> Vec<exactlti::matrix::Matrix<K>> {
    let mut out = vec![s.d.clone()];
    let mut akb = s.b.clone();
    for _ in 1..count {
        out.push(&s.c * &akb);
        akb = &s.a * &akb;
    }
    out
}

/// Every identity of an as-written realization, `order` = states expected.
fn check(w: &WrittenTransfer<Q>, order: usize) -> StateSpace<Q> {
    let r = realize_as_written(w).unwrap();
    assert!(r.verified, "{w:?}");
    let s = &r.system;
    assert_eq!(s.nstates(), order, "{w:?}");
    let det = r
        .column_denominators
        .iter()
        .fold(Poly::one(Q), |a, d| a.mul(d));
    assert_eq!(s.a.charpoly().unwrap(), det);
    // the column denominators are the lcm of the written ones: every written denominator
    // divides its column's, and their product has the written roots with multiplicity
    for row in &w.entries {
        for (j, (_, d)) in row.iter().enumerate() {
            assert!(r.column_denominators[j].rem(d).is_zero());
        }
    }
    let g = w.reduced();
    assert!(g.matches_markov(s));
    let min = realize_transfer(&g).unwrap();
    let ms = min.state_space.unwrap();
    let k = 2 * (s.nstates() + ms.nstates()) + 2;
    assert_eq!(markov(s, k), markov(&ms, k));
    let cancelled = minimal_kalman(s).unwrap();
    assert_eq!(cancelled.order, min.mcmillan_degree);
    s.clone()
}

#[test]
fn siso_keeps_the_written_denominator() {
    // python-control: tf([1, 1], [1, 3, 2]).poles() = [-2, -1]; minreal cancels to 1 state
    let s = check(&written(&[&["(s+1)/((s+1)*(s+2))"]]), 2);
    assert_eq!(s.a.charpoly().unwrap(), Poly::from_i64s(&[2, 3, 1]));
    check(&written(&[&["(s+1)/(s^2+3*s+2)"]]), 2);
    // sums keep both denominators (python-control's arithmetic): 1/(s+1) + 1/(s+1)
    let s = check(&written(&[&["1/(s+1) + 1/(s+1)"]]), 2);
    assert_eq!(s.a.charpoly().unwrap(), Poly::from_i64s(&[1, 2, 1]));
    // biproper with a common factor: D = 2, two states
    let s = check(&written(&[&["(2*s+2)*(s+3)/((s+1)*(s+2))"]]), 2);
    assert_eq!(s.d.get(0, 0), &Rational::from_integer(2.into()));
    // a pole at 0 written twice and cancelled once: s/s^2
    check(&written(&[&["s/s^2"]]), 2);
    // a zero entry with a written denominator keeps it (python-control does too)
    check(&written(&[&["0/(s+3)"]]), 1);
}

#[test]
fn edge_shapes() {
    // constants only: no state, D = G
    let s = check(&written(&[&["3/2", "0"], &["-1", "0.25"]]), 0);
    assert_eq!(s.d.get(1, 1), &Rational::new(1.into(), 4.into()));
    // 1 x 3 and 3 x 1
    check(&written(&[&["1/(s+1)", "1/(s+2)", "1/(s+1)^2"]]), 4);
    check(
        &written(&[&["1/(s+1)"], &["1/(s+1)^2"], &["(s+2)/(s+2)"]]),
        3,
    );
    // a column of shared denominators: lcm, not the product (python-control's common
    // denominator per input): [[1/(s+1), 1/(s+2)], [2/(s+1), 1/(s+1)]] has 1 + 2 states
    check(
        &written(&[&["1/(s+1)", "1/(s+2)"], &["2/(s+1)", "1/(s+1)"]]),
        3,
    );
    // refusals: improper, ragged, empty, zero denominator
    assert!(realize_as_written(&written(&[&["s^2/(s+1)"]])).is_err());
    let mut w = written(&[&["1/(s+1)", "1"], &["1"]]);
    assert!(realize_as_written(&w).is_err());
    w.entries.clear();
    assert!(realize_as_written(&w).is_err());
    let z = WrittenTransfer {
        entries: vec![vec![(Poly::one(Q), Poly::zero(Q))]],
    };
    assert!(realize_as_written(&z).is_err());
}

/// Generic over the field: $\mathbb{Q}(\sqrt 2)$ with a written common factor $s - \sqrt 2$.
#[test]
fn over_a_quadratic_field() {
    let k = QuadraticField::new(2).unwrap();
    let r = |a: i64, b: i64| {
        Quadratic::new(
            Rational::from_integer(a.into()),
            Rational::from_integer(b.into()),
        )
    };
    let p = |cs: Vec<Quadratic>| Poly::new(k.clone(), cs);
    let f = p(vec![r(0, -1), r(1, 0)]); // s - sqrt2
    let num = f.mul(&p(vec![r(1, 0)]));
    let den = f.mul(&p(vec![r(3, 0), r(1, 0)])); // (s - sqrt2)(s + 3)
    let w = WrittenTransfer {
        entries: vec![vec![
            (num, den.clone()),
            (p(vec![r(0, 1)]), p(vec![r(1, 1), r(1, 0)])),
        ]],
    };
    let s = realize_as_written(&w).unwrap();
    assert!(s.verified);
    assert_eq!(s.system.nstates(), 3);
    assert_eq!(
        s.system.a.charpoly().unwrap(),
        den.monic().mul(&p(vec![r(1, 1), r(1, 0)]))
    );
    assert_eq!(minimal_kalman(&s.system).unwrap().order, 2);
    let _ = k.one();
}

/// A random proper written entry: $f \cdot n / (f \cdot d)$ with a planted common factor
/// $f$ (sometimes 1), small integer coefficients.
fn random_entry(rng: &mut SplitMix64) -> String {
    let poly = |rng: &mut SplitMix64, deg: i64, monic: bool| -> String {
        let mut terms = vec![];
        for k in 0..=deg {
            let c = if k == deg && monic { 1 } else { rng.int(-3, 3) };
            terms.push(format!("({c})*s^{k}"));
        }
        format!("({})", terms.join("+"))
    };
    let dd = rng.int(0, 2);
    let dn = rng.int(0, dd);
    let df = rng.int(0, 1);
    let f = poly(rng, df, true);
    format!("{f}*{}/({f}*{})", poly(rng, dn, false), poly(rng, dd, true))
}

#[test]
fn random_written_matrices_keep_every_denominator() {
    let mut rng = SplitMix64(0x28a5_2026);
    for _ in 0..60 {
        let (p, m) = (rng.int(1, 3) as usize, rng.int(1, 3) as usize);
        let texts: Vec<Vec<String>> = (0..p)
            .map(|_| (0..m).map(|_| random_entry(&mut rng)).collect())
            .collect();
        let rows: Vec<Vec<&str>> = texts
            .iter()
            .map(|r| r.iter().map(|s| s.as_str()).collect())
            .collect();
        let refs: Vec<&[&str]> = rows.iter().map(|r| r.as_slice()).collect();
        let w = written(&refs);
        let order = (0..m)
            .map(|j| {
                w.entries
                    .iter()
                    .fold(Poly::one(Q), |acc, row| {
                        let g = acc.gcd(&row[j].1);
                        acc.mul(&row[j].1.div_exact(&g).unwrap())
                    })
                    .deg()
            })
            .sum();
        check(&w, order);
    }
}

/// The CLI: a `G` file is realized minimally (the documented default); `realize =
/// "as_written"` keeps the written denominators; `minreal` cancels them again.
#[test]
fn file_key_realize() {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("as_written");
    std::fs::create_dir_all(&dir).unwrap();
    let write = |name: &str, text: &str| {
        let p = dir.join(name);
        std::fs::write(&p, text).unwrap();
        p.to_string_lossy().into_owned()
    };
    let min = write("min.json", r#"{"G": [["(s+1)/((s+1)*(s+2))"]]}"#);
    let kept = write(
        "kept.json",
        r#"{"G": [["(s+1)/((s+1)*(s+2))"]], "realize": "as_written"}"#,
    );
    let json = |args: &[&str]| -> serde_json::Value {
        let (code, out, err) = run(args);
        assert_eq!(code, 0, "{args:?}: {err}");
        serde_json::from_str(&out).unwrap()
    };
    let n = |v: &serde_json::Value| v["A"].as_array().map(|a| a.len());
    let m1 = json(&["minreal", &min, "--format", "json"]);
    let m2 = json(&["minreal", &kept, "--format", "json"]);
    assert_eq!(m1["order"], 1, "{m1}");
    assert_eq!(m2["order"], 1, "{m2}");
    assert_eq!(m2["original_order"], 2, "{m2}");
    let _ = n;
    let bad = write("bad.json", r#"{"G": [["1/(s+1)"]], "realize": "both"}"#);
    let (code, _, err) = run(&["minreal", &bad]);
    assert_eq!(code, 2);
    assert!(
        err.contains("realize") && err.contains("as_written"),
        "{err}"
    );
    let lone = write(
        "lone.json",
        r#"{"A": [[1]], "B": [[1]], "C": [[1]], "realize": "as_written"}"#,
    );
    let (code, _, err) = run(&["minreal", &lone]);
    assert_eq!(code, 2);
    assert!(err.contains("key realize"), "{err}");
    let improper = write(
        "imp.json",
        r#"{"G": [["s^2/(s+1)"]], "realize": "as_written"}"#,
    );
    let (code, _, err) = run(&["tf", &improper]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("improper"), "{err}");
}
