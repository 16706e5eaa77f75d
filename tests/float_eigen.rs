//! The float eigenvalue iteration converges on the matrices where the plain Francis iteration
//! cycles (issue 22 item 9: the companion matrices of x^4 + 1, x^6 + 1, x^4 + 2/3 and
//! derogatory matrices with the one eigenvalue 1/2 made `check`, `minreal --method era` and
//! `step --float` exit 2). Generators: companion matrices of x^n + c (n = 2..12), of
//! cyclotomic polynomials, permutation matrices, and Jordan matrices with repeated eigenvalues
//! in block patterns conjugated by random unimodular integer matrices. Every float spectrum is
//! matched against the exact one (the exact Jordan form over Q: eigenvalue approximations,
//! multiplicities and block sizes).

use crate::common::cli::{run, temp_file};
use crate::common::{Rng, iters, unimodular};
use exactlti::field::{Field, Q, Rational};
use exactlti::float::{eigenvalues, to_dmatrix};
use exactlti::jordan::jordan;
use exactlti::matrix::Matrix;
use num_complex::Complex;

/// The companion matrix of the monic polynomial with coefficients `c` (low degree first,
/// without the leading 1).
fn companion(c: &[Rational]) -> Matrix<Q> {
    let n = c.len();
    let mut a = Matrix::zeros(Q, n, n);
    for (i, ci) in c.iter().enumerate() {
        if i + 1 < n {
            a.set(i + 1, i, Q.one());
        }
        a.set(i, n - 1, -ci.clone());
    }
    a
}

fn rat(n: i64, d: i64) -> Rational {
    Rational::new(n.into(), d.into())
}

/// The float eigenvalues of `a` match its exact eigenvalues: each exact eigenvalue of
/// algebraic multiplicity `m` and largest Jordan block `k` has exactly `m` float eigenvalues
/// within $C (\varepsilon \lVert A\rVert)^{1/k}$ (a block of size `k` moves its eigenvalue by
/// about the `k`-th root of the perturbation). Returns the largest error.
fn matches_exact(a: &Matrix<Q>, what: &str) -> f64 {
    let af = to_dmatrix(a).unwrap();
    let ev = eigenvalues(&af).unwrap_or_else(|e| panic!("{what}: {e}\nA = {a}"));
    assert_eq!(ev.len(), a.nrows(), "{what}");
    let jf = jordan(a).unwrap();
    let norm = af.norm().max(1.0);
    let exact: Vec<(Complex<f64>, usize, usize)> = jf
        .eigenvalues
        .iter()
        .map(|e| {
            let k = e.blocks.iter().copied().max().unwrap_or(1);
            (
                Complex::new(e.approx.0, e.approx.1),
                e.algebraic_multiplicity,
                k,
            )
        })
        .collect();
    let mut count = vec![0; exact.len()];
    let mut worst: f64 = 0.0;
    for z in &ev {
        let (j, d) = exact
            .iter()
            .enumerate()
            .map(|(j, (x, _, _))| (j, (z - x).norm()))
            .min_by(|x, y| x.1.total_cmp(&y.1))
            .unwrap();
        let k = exact[j].2 as f64;
        // the unimodular conjugation inflates the condition: 1e4 eps ||A||^2 before the root
        let tol =
            10.0 * (1e4 * f64::EPSILON * norm * norm).powf(1.0 / k) * norm.powf(1.0 - 1.0 / k);
        assert!(
            d <= tol,
            "{what}: {z} is {d:e} from {} (tol {tol:e})\nA = {a}",
            exact[j].0
        );
        worst = worst.max(d / norm);
        count[j] += 1;
    }
    for (j, (x, m, _)) in exact.iter().enumerate() {
        assert_eq!(
            count[j], *m,
            "{what}: eigenvalue {x} multiplicity\nA = {a}\n{ev:?}"
        );
    }
    worst
}

/// The cyclotomic polynomial Phi_n as integer coefficients (low degree first):
/// x^n - 1 divided by Phi_d for every proper divisor d of n.
fn cyclotomic(n: usize) -> Vec<i64> {
    let mut p = vec![0i64; n + 1];
    p[0] = -1;
    p[n] = 1;
    for d in (1..n).filter(|d| n.is_multiple_of(*d)) {
        let q = cyclotomic(d);
        // exact division by the monic q
        let mut rem = p.clone();
        let mut quo = vec![0i64; rem.len() - q.len() + 1];
        for i in (0..quo.len()).rev() {
            let c = rem[i + q.len() - 1];
            quo[i] = c;
            for (j, qj) in q.iter().enumerate() {
                rem[i + j] -= c * qj;
            }
        }
        assert!(rem.iter().all(|&r| r == 0));
        p = quo;
    }
    p
}

#[test]
fn companion_of_x_n_plus_c() {
    let cs = [
        rat(1, 1),
        rat(-1, 1),
        rat(2, 3),
        rat(-2, 3),
        rat(2, 1),
        rat(1, 2),
        rat(3, 1),
    ];
    for n in 2..=12 {
        for c in &cs {
            let mut coef = vec![rat(0, 1); n];
            coef[0] = c.clone();
            matches_exact(&companion(&coef), &format!("x^{n} + {c}"));
        }
    }
}

#[test]
fn companion_of_cyclotomic_polynomials() {
    for n in 1..=36 {
        let p = cyclotomic(n);
        if p.len() - 1 > 12 {
            continue;
        }
        let coef: Vec<Rational> = p[..p.len() - 1].iter().map(|&x| rat(x, 1)).collect();
        matches_exact(&companion(&coef), &format!("Phi_{n}"));
    }
    assert_eq!(cyclotomic(12), [1, 0, -1, 0, 1]);
}

#[test]
fn permutation_matrices() {
    let mut rng = Rng(22_09);
    for case in 0..iters(40) {
        let n = 2 + case % 11;
        let mut perm: Vec<usize> = (0..n).collect();
        for i in (1..n).rev() {
            perm.swap(i, rng.int(0, i as i64) as usize);
        }
        let mut a = Matrix::zeros(Q, n, n);
        for (i, &p) in perm.iter().enumerate() {
            a.set(p, i, Q.one());
        }
        matches_exact(&a, &format!("permutation {perm:?}"));
    }
}

/// A Jordan matrix with the given eigenvalues and block sizes.
fn jordan_matrix(blocks: &[(Rational, usize)]) -> Matrix<Q> {
    let n = blocks.iter().map(|b| b.1).sum();
    crate::jcommon::jordan_blocks(&Q, blocks, n)
}

#[test]
fn derogatory_matrices_with_repeated_eigenvalues() {
    let patterns: [&[usize]; 8] = [
        &[2, 2, 1, 1],
        &[2, 2, 1, 1, 1, 1],
        &[1, 1, 1, 1],
        &[2, 2, 2],
        &[3, 1],
        &[2, 1],
        &[3, 3, 1],
        &[1, 1, 1, 1, 1, 1, 1, 1],
    ];
    let values = [rat(1, 2), rat(-1, 3), rat(2, 1), rat(0, 1)];
    let mut rng = Rng(22_091);
    for case in 0..iters(32) {
        let pat = patterns[case % patterns.len()];
        let x = &values[(case / patterns.len()) % values.len()];
        let mut blocks: Vec<(Rational, usize)> = pat.iter().map(|&s| (x.clone(), s)).collect();
        if case % 3 == 1 {
            // a second repeated eigenvalue beside the first
            blocks.push((x + rat(1, 1), 2));
            blocks.push((x + rat(1, 1), 1));
        }
        let j = jordan_matrix(&blocks);
        let n = j.nrows();
        let s = unimodular(&Q, n, &mut rng);
        let a = &(&s * &j) * &s.inverse().unwrap();
        matches_exact(&a, &format!("blocks {blocks:?}"));
    }
}

#[test]
fn reproducers_exit_0_on_the_command_line() {
    let comp = |c: &str, n: usize| {
        let mut rows = vec![vec!["0".to_string(); n]; n];
        for (i, row) in rows.iter_mut().enumerate().skip(1) {
            row[i - 1] = "1".into();
        }
        rows[0][n - 1] = format!("-({c})");
        rows
    };
    let ones = |n: usize| -> String {
        let b: Vec<String> = (0..n).map(|i| format!("[{}]", i % 2 + 1)).collect();
        format!("[{}]", b.join(", "))
    };
    let cases = [
        ("x4p1", comp("1", 4)),
        ("x6p1", comp("1", 6)),
        ("x4p23", comp("2/3", 4)),
    ];
    let mut files = vec![];
    for (name, rows) in cases {
        let n = rows.len();
        let c: Vec<String> = (0..n).map(|i| format!("{}", i + 1)).collect();
        let text = format!(
            r#"{{"A": {}, "B": {}, "C": [[{}]]}}"#,
            serde_json::to_string(&rows).unwrap(),
            ones(n),
            c.join(", ")
        );
        files.push(temp_file("float_eigen", &format!("{name}.json"), &text));
    }
    // one eigenvalue 1/2 with blocks 2, 2, 1, 1 under a unimodular similarity
    let j = jordan_matrix(&[
        (rat(1, 2), 2),
        (rat(1, 2), 2),
        (rat(1, 2), 1),
        (rat(1, 2), 1),
    ]);
    let s = unimodular(&Q, 6, &mut Rng(7));
    let a = &(&s * &j) * &s.inverse().unwrap();
    let rows: Vec<Vec<String>> = (0..6)
        .map(|r| (0..6).map(|c| a.get(r, c).to_string()).collect())
        .collect();
    let text = format!(
        r#"{{"A": {}, "B": {}, "C": [[1, 0, 2, 0, 1, 1]]}}"#,
        serde_json::to_string(&rows).unwrap(),
        ones(6)
    );
    files.push(temp_file("float_eigen", "half.json", &text));
    for f in &files {
        let p = f.to_str().unwrap();
        for args in [
            vec!["check", p],
            vec!["minreal", "--method", "era", p],
            vec!["step", "--float", "--points", "20", p],
        ] {
            let (code, out, err) = run(&args);
            assert_eq!(code, 0, "{args:?}: {err}\n{out}");
        }
    }
}
