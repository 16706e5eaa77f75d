//! Real forms over a real K = Q(sqrt d) and the free response over K: the real Jordan form
//! with each pair in its real field (by default when small, with `--expand` always), the real
//! modal Jordan-method realization (Markov parameters of the real system itself), and
//! e^{At} through the Jordan form over K.

use super::{jordan_matrix, mat, planted, q, run, temp_file};
use exactlti::field::{Field, QuadraticField};
use exactlti::jordan::RealJordanForm;
use exactlti::jordan::fields::pair_field;
use exactlti::jordan::jordan_over as jordan_over_k;
use exactlti::matrix::Matrix;
use exactlti::realization::{MinrealMethod, RealModalBlock, minimal, minimal_jordan};
use exactlti::system::StateSpace;

/// For each pair of `a`: A T = T J exactly in its real field F, T = [Re v, Im v] from the
/// complex chains, J = [[Re, Im], [-Im, Re]] of the complex block. Returns the pair count.
fn real_identity(a: &Matrix<QuadraticField>) -> usize {
    let jf = jordan_over_k(a).unwrap();
    let mut pairs = 0;
    let k = a.field();
    for rc in jf.root_columns() {
        let (v, jj) = (&rc.v, &rc.j);
        let e = &jf.eigenvalues[rc.eigenvalue];
        if e.approx.1 <= 0.0 {
            continue;
        }
        let g = &jf.components[e.component].factor;
        let pf = pair_field(g, e.approx, "c", true).unwrap().unwrap();
        let f = pf.field.clone();
        let (n, m) = (v.nrows(), v.ncols());
        let t = Matrix::from_fn(f.clone(), n, 2 * m, |r, c| {
            let (x, y) = pf.re_im(k, v.get(r, c / 2));
            if c % 2 == 0 { x } else { y }
        });
        let j = Matrix::from_fn(f.clone(), 2 * m, 2 * m, |r, c| {
            let (re, im) = pf.re_im(k, jj.get(r / 2, c / 2));
            match (r % 2, c % 2) {
                (0, 0) | (1, 1) => re,
                (0, 1) => im,
                _ => f.neg(&im),
            }
        });
        assert_eq!(&pf.matrix(a) * &t, &t * &j, "A = {a}");
        pairs += 1;
    }
    pairs
}

/// The exact texts of the real form's `J` (made by the report).
fn j_texts(rf: &RealJordanForm<QuadraticField>) -> Vec<Vec<String>> {
    rf.j_t_out().0.exact
}

/// Some pair is written in the compact form.
fn compact(rf: &RealJordanForm<QuadraticField>) -> bool {
    rf.blocks.iter().any(|b| b.is_compact())
}

/// The lines of a legend key of the real form's report (`fields`, `symbols`, ...).
pub(super) fn legend(rf: &RealJordanForm<QuadraticField>, key: &str) -> Vec<String> {
    match rf.report().get(key) {
        Some(exactlti::report::Value::List(xs)) => xs
            .iter()
            .map(|x| match x {
                exactlti::report::Value::Str(s) => s.clone(),
                other => format!("{other:?}"),
            })
            .collect(),
        _ => vec![],
    }
}

/// sqrt(d) +- i twice in a 2-block, and -1 + sqrt(d), planted over Q(sqrt d).
pub(super) fn pair_block_matrix(k: &QuadraticField) -> Matrix<QuadraticField> {
    let mut j = Matrix::zeros(k.clone(), 5, 5);
    for off in [0, 2] {
        j.set(off, off, q(0, 1));
        j.set(off + 1, off + 1, q(0, 1));
        j.set(off, off + 1, q(1, 0));
        j.set(off + 1, off, q(-1, 0));
    }
    j.set(0, 2, k.one());
    j.set(1, 3, k.one());
    j.set(4, 4, q(-1, 1));
    planted(k, &j, &[(1, 0), (0, 1), (-1, 1), (2, 0)])
}

/// The companion matrix of x^3 - sqrt 2: a pair whose real field has degree 12.
fn cubic(k: &QuadraticField) -> Matrix<QuadraticField> {
    mat(
        k,
        &[
            &[(0, 0), (0, 0), (0, 1)],
            &[(1, 0), (0, 0), (0, 0)],
            &[(0, 0), (1, 0), (0, 0)],
        ],
    )
}

#[test]
fn real_jordan_form_over_k_expands_small_pairs() {
    for d in [2, 3] {
        let k = QuadraticField::new(d).unwrap();
        let a = pair_block_matrix(&k);
        let rf = jordan_over_k(&a).unwrap().real_form().unwrap();
        assert!(rf.verified && !compact(&rf), "d = {d}: {rf:?}");
        // J: -1 + sqrt(d), then the 2-block of sqrt(d) +- i in Q(sqrt d)
        let s = format!("sqrt({d})");
        let j = j_texts(&rf);
        assert_eq!(j[0][0], format!("-1 + {s}"));
        assert_eq!(j[1][1..], [s.as_str(), "1", "1", "0"]);
        assert_eq!(j[2][1..], ["-1", s.as_str(), "0", "1"]);
        assert_eq!(j[4][3..], ["-1", s.as_str()]);
        assert_eq!(real_identity(&a), 1);
    }
    // a large real field: compact by default, expanded on request (like --expand over Q)
    let k = QuadraticField::new(2).unwrap();
    let a = cubic(&k);
    let jf = jordan_over_k(&a).unwrap();
    let rf = jf.real_form().unwrap();
    // no real field, only the definition of the real root's symbol (issue 22 item 6)
    assert!(rf.verified && compact(&rf), "{rf:?}");
    let fields = legend(&rf, "fields");
    assert_eq!(fields.len(), 1, "{fields:?}");
    assert!(
        fields[0].contains(
            " = root of x^6 - 2 near 1.122462048 (over QQ(sqrt(2)): root of x^3 - sqrt(2))"
        ),
        "{fields:?}"
    );
    let rf = jf.real_form_with(true).unwrap();
    assert!(rf.verified && !compact(&rf), "{rf:?}");
    let fields = legend(&rf, "fields");
    assert!(
        fields[0].starts_with("r1 = root of x^6 - 2 near 1.12")
            && fields[1].starts_with("c2 = root of x^12"),
        "{fields:?}"
    );
    assert_eq!(real_identity(&a), 1);
    // x^5 - x^4 - sqrt(2) x + 1: K(theta) of degree 10 over Q, beyond the expansion bound:
    // compact with a note, at once
    let a = mat(
        &k,
        &[
            &[(0, 0), (0, 0), (0, 0), (0, 0), (-1, 0)],
            &[(1, 0), (0, 0), (0, 0), (0, 0), (0, 1)],
            &[(0, 0), (1, 0), (0, 0), (0, 0), (0, 0)],
            &[(0, 0), (0, 0), (1, 0), (0, 0), (0, 0)],
            &[(0, 0), (0, 0), (0, 0), (1, 0), (1, 0)],
        ],
    );
    let rf = jordan_over_k(&a).unwrap().real_form_with(true).unwrap();
    assert!(rf.verified && compact(&rf), "{rf:?}");
    let notes = rf.note_lines();
    assert!(notes.iter().all(|n| n.contains("degree 10")) && !notes.is_empty());
    // Q(i) with a non-real entry: no real form, expanded or not
    let a = mat(&QuadraticField::gaussian(), &[&[(0, 1)]]);
    assert!(jordan_over_k(&a).unwrap().real_form_with(true).is_err());
}

#[test]
fn real_modal_realization_over_real_k() {
    for d in [2, 3] {
        let k = QuadraticField::new(d).unwrap();
        let a = pair_block_matrix(&k);
        for (b, c) in [
            (
                vec![(0, 0), (0, 0), (0, 0), (1, 0), (1, 1)],
                vec![(1, 0), (0, 1), (0, 0), (0, 0), (1, 0)],
            ),
            (
                vec![(1, 0), (0, 0), (0, 1), (0, 0), (0, 0)],
                vec![(0, 0), (1, 0), (0, 0), (0, 0), (0, 0)],
            ),
        ] {
            let bm = Matrix::from_fn(k.clone(), 5, 1, |i, _| q(b[i].0, b[i].1));
            let cm = Matrix::from_fn(k.clone(), 1, 5, |_, i| q(c[i].0, c[i].1));
            let sys = StateSpace::new_strictly_proper(a.clone(), bm, cm).unwrap();
            let r = minimal_jordan(&sys).unwrap();
            let kal = minimal(&sys, MinrealMethod::Kalman).unwrap();
            assert!(r.verified, "d = {d}");
            let real = r.real.as_ref().unwrap();
            assert!(
                real.iter()
                    .all(|b| !matches!(b, RealModalBlock::Compact(_)))
            );
            // the real system itself: same Markov parameters, minimal order
            let rs = r.real_to_base().unwrap();
            assert_eq!(rs.markov(10), sys.markov(10), "d = {d}");
            assert_eq!(rs.nstates(), kal.order);
            assert_eq!(rs.nstates(), r.mcmillan_degree);
            // each pair block [[a, b], [-b, a]], b != 0
            for blk in real {
                if let RealModalBlock::Pair { a, pair, .. } = blk {
                    let field = &pair.field;
                    assert_eq!(a.get(0, 0), a.get(1, 1));
                    assert_eq!(*a.get(0, 1), field.neg(a.get(1, 0)));
                    assert!(!field.is_zero(a.get(0, 1)));
                }
            }
        }
    }
    // pairs of a rational quadratic factor, written with their radical: 1 +- sqrt(2) i (real
    // system over K: its own Markov parameters) and +- sqrt(3) i (imaginary parts in
    // sqrt(3) K, not in K)
    let k = QuadraticField::new(2).unwrap();
    for (a, want) in [
        (
            mat(&k, &[&[(1, 0), (0, 1)], &[(0, -1), (1, 0)]]),
            [["1", "sqrt(2)"], ["-sqrt(2)", "1"]],
        ),
        (
            mat(&k, &[&[(0, 0), (-3, 0)], &[(1, 0), (0, 0)]]),
            [["0", "sqrt(3)"], ["-sqrt(3)", "0"]],
        ),
    ] {
        let bm = Matrix::from_fn(k.clone(), 2, 1, |i, _| q(1, i as i64));
        let cm = Matrix::from_fn(k.clone(), 1, 2, |_, i| q(1 - i as i64, 1));
        let sys = StateSpace::new_strictly_proper(a, bm, cm).unwrap();
        let r = minimal_jordan(&sys).unwrap();
        assert!(r.verified);
        let real = r.real.as_ref().unwrap();
        assert!(matches!(real[0], RealModalBlock::Radical(_)));
        match r.real_to_base() {
            Some(rs) => {
                assert_eq!(want[0][1], "sqrt(2)");
                assert_eq!(rs.markov(6), sys.markov(6));
            }
            None => assert_eq!(want[0][1], "sqrt(3)"),
        }
        let rep = r.report();
        let Some(exactlti::report::Value::Matrix(am)) = rep.get("A") else {
            panic!("A")
        };
        assert_eq!(am.exact, want);
    }
    // -1 +- 2i (f = -1): plain rational parts, no `sqrt(1)`
    let a = mat(
        &k,
        &[
            &[(-1, 0), (2, 0), (0, 0)],
            &[(-2, 0), (-1, 0), (0, 0)],
            &[(0, 0), (0, 0), (0, 1)],
        ],
    );
    let bm = Matrix::from_fn(k.clone(), 3, 1, |_, _| k.one());
    let sys = StateSpace::new_strictly_proper(a.clone(), bm.clone(), bm.transpose()).unwrap();
    let r = minimal_jordan(&sys).unwrap();
    let rs = r.real_to_base().unwrap();
    assert!(r.verified && rs.markov(8) == sys.markov(8));
    let rep = r.report().to_text();
    assert!(
        rep.contains("-1   2 ]") && !rep.contains("sqrt(1)"),
        "{rep}"
    );
    let rf = jordan_over_k(&a).unwrap().real_form().unwrap();
    let j = j_texts(&rf);
    assert!(j.iter().flatten().all(|x| !x.contains("sqrt(1)")), "{j:?}");
    // a large real field: the compact form, still verified on the complex side
    let k = QuadraticField::new(2).unwrap();
    let one = Matrix::from_fn(k.clone(), 3, 1, |i, _| q((i == 0) as i64, 0));
    let sys = StateSpace::new_strictly_proper(cubic(&k), one.clone(), one.transpose()).unwrap();
    let r = minimal_jordan(&sys).unwrap();
    assert!(r.verified && r.real_to_base().is_none());
    assert!(
        r.real
            .as_ref()
            .unwrap()
            .iter()
            .any(|b| matches!(b, RealModalBlock::Compact(_)))
    );
    // Q(i): the complex modal form only
    let k = QuadraticField::gaussian();
    let a = mat(&k, &[&[(0, 1), (1, 0)], &[(0, 0), (-1, 0)]]);
    let sys = StateSpace::new_strictly_proper(
        a,
        one.select_rows(&[0, 1]).map(&k, |x| x.clone()),
        Matrix::from_fn(k.clone(), 1, 2, |_, _| k.one()),
    )
    .unwrap();
    let r = minimal_jordan(&sys).unwrap();
    assert!(r.verified && r.real.is_none());
}

#[test]
fn free_response_over_k_is_verified() {
    let seed = [(1, 1), (-2, 0), (0, 1), (3, -1), (1, 0), (-1, 2)];
    for d in [-1, 2, 3] {
        let k = QuadraticField::new(d).unwrap();
        let j = jordan_matrix(&k, &[(q(1, 1), 3), (q(1, 1), 1), (q(-2, 0), 2)]);
        let a = planted(&k, &j, &seed);
        let jf = jordan_over_k(&a).unwrap();
        let fr = jf.free_response();
        assert!(fr.verify(&jf), "d = {d}");
        // every eigenvalue lies in K: x(0) = sum G_0 = I and A G_k = theta G_k + (k+1) G_(k+1)
        // over K, term by term
        let mut sum0 = Matrix::zeros(k.clone(), 6, 6);
        for ev in 0..jf.eigenvalues.len() {
            let terms = fr.terms_of(&jf, ev);
            let to_k = |g: &Matrix<exactlti::algebraic::Ext<QuadraticField>>| {
                let f = g.field().clone();
                g.map(&k, |x| f.to_base(x).unwrap())
            };
            let theta = if exactlti::report::sections::eigenvalue_text(&jf.eigenvalues[ev])
                .starts_with("-2")
            {
                q(-2, 0)
            } else {
                q(1, 1)
            };
            for (p, g) in &terms {
                let g = to_k(g);
                if *p == 0 {
                    sum0 = &sum0 + &g;
                }
                let next = terms
                    .iter()
                    .find(|(p2, _)| *p2 == p + 1)
                    .map(|(_, g2)| to_k(g2).scale(&k.from_i64(*p as i64 + 1)))
                    .unwrap_or_else(|| Matrix::zeros(k.clone(), 6, 6));
                assert_eq!(&a * &g, &g.scale(&theta) + &next, "d = {d}, power {p}");
            }
            // the 3-block gives t^2 terms
            assert_eq!(terms.len(), if theta == q(1, 1) { 3 } else { 2 });
        }
        assert!(sum0.is_identity(), "d = {d}");
    }
    // pairs (a component of degree 2 over K) and a tampered term
    let k = QuadraticField::new(2).unwrap();
    let jf = jordan_over_k(&pair_block_matrix(&k)).unwrap();
    let mut fr = jf.free_response();
    assert!(fr.verify(&jf));
    let e = fr.terms[0].coeff.field().clone();
    let x = e.add(fr.terms[0].coeff.get(0, 0), &e.one());
    fr.terms[0].coeff.set(0, 0, x);
    assert!(!fr.verify(&jf));
    // 0 x 0: no terms, e^{At} = I trivially
    let jf = jordan_over_k(&Matrix::zeros(k.clone(), 0, 0)).unwrap();
    let fr = jf.free_response();
    assert!(fr.terms.is_empty() && fr.verify(&jf));
}

#[test]
fn cli_real_forms_and_free_response_over_k() {
    let ps = temp_file(
        "ps.json",
        r#"{"A": [["sqrt(2)", "1", "0"], ["-1", "sqrt(2)", "0"], ["0", "0", "-1"]], "B": [[1], [0], [1]], "C": [[1, "sqrt(2)", 1]]}"#,
    );
    let cub = temp_file(
        "cub.json",
        r#"{"A": [[0, 0, "sqrt(2)"], [1, 0, 0], [0, 1, 0]], "B": [[1], [0], [0]], "C": [[0, 0, 1]]}"#,
    );
    let qi = temp_file(
        "qi2.json",
        r#"{"A": [["i", 1], [0, "-i"]], "B": [[1], [1]], "C": [[1, 0]]}"#,
    );
    let (ps, cub, qi) = (
        ps.to_str().unwrap(),
        cub.to_str().unwrap(),
        qi.to_str().unwrap(),
    );
    let json = |args: &[&str]| -> serde_json::Value {
        let (code, out, err) = run(args);
        assert_eq!(code, 0, "{args:?}: {err}");
        serde_json::from_str(&out).unwrap()
    };
    let j = json(&["minreal", "--method", "jordan", ps, "--format", "json"]);
    assert_eq!(j["verified"], true);
    assert!(
        j["presentation"]
            .as_str()
            .unwrap()
            .starts_with("real modal form")
    );
    assert_eq!(j["A"][1], serde_json::json!(["0", "sqrt(2)", "1"]));
    assert_eq!(j["A"][2], serde_json::json!(["0", "-1", "sqrt(2)"]));
    assert_eq!(j["symbols"], serde_json::json!([]));
    let j = json(&["minreal", "--method", "jordan", qi, "--format", "json"]);
    assert!(
        j["presentation"]
            .as_str()
            .unwrap()
            .starts_with("complex modal form")
    );
    // jordan --real: compact by default for the degree-12 field, expanded with --expand
    let j = json(&["jordan", "--real", cub, "--format", "json"]);
    assert!(j["presentation"].as_str().unwrap().starts_with("compact"));
    let j = json(&["jordan", "--real", "--expand", cub, "--format", "json"]);
    assert_eq!(
        (j["verified"].clone(), j["exact"].clone()),
        (true.into(), true.into())
    );
    assert!(
        j.get("presentation").is_none() && j["fields"].is_array(),
        "{j}"
    );
    let (code, _, err) = run(&["jordan", "--real", "--expand", qi]);
    assert_eq!(code, 2);
    assert_eq!(err.lines().count(), 1, "{err}");
    // analyze: the free response over K, with its check
    for f in [ps, qi] {
        let j = json(&["analyze", f, "--format", "json"]);
        let fr = &j["jordan"]["free_response"];
        assert_eq!(fr["verified"], true, "{fr}");
        let terms = fr["terms"].as_array().unwrap();
        assert_eq!(terms.len(), 3 - (f == qi) as usize, "{fr}");
        assert!(terms.iter().all(|t| t["G"].is_array() && t["power"] == 0));
    }
}
