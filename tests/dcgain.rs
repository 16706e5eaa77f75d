//! `dc_gain`: $G(0) = D - C A^{-1} B$ per channel, infinite exactly where the reduced
//! transfer-matrix entry has a pole at 0; examples, random systems (fixed seed) against the
//! transfer matrix, and the command line.

use crate::common::cli::run;
use exactlti::field::{Field, Q, Rational};
use exactlti::matrix::Matrix;
use exactlti::rng::SplitMix64;
use exactlti::system::StateSpace;
use exactlti::system::dcgain::dc_gain;

fn q(rows: &[&[i64]]) -> Matrix<Q> {
    Matrix::from_i64_rows(rows)
}

fn r(n: i64, d: i64) -> Option<Rational> {
    Some(Rational::new(n.into(), d.into()))
}

#[test]
fn examples_finite_infinite_and_mixed_channels() {
    // 1/((s+1)(s+2)): 1/2
    let p = StateSpace::new(
        q(&[&[0, 1], &[-2, -3]]),
        q(&[&[0], &[1]]),
        q(&[&[1, 0]]),
        q(&[&[0]]),
    )
    .unwrap();
    let g = dc_gain(&p).unwrap();
    assert_eq!(g.entries, vec![vec![r(1, 2)]]);
    assert_eq!(
        g.matrix,
        Some(q(&[&[1]]).scale(&Rational::new(1.into(), 2.into())))
    );
    assert!(g.verified);
    // an integrator channel is infinite, the others finite (A singular)
    let m = StateSpace::new(
        q(&[&[0, 0], &[0, -2]]),
        q(&[&[1, 0], &[0, 1]]),
        q(&[&[1, 0], &[0, 1], &[1, 1]]),
        q(&[&[0, 0], &[0, 0], &[0, 1]]),
    )
    .unwrap();
    let g = dc_gain(&m).unwrap();
    assert_eq!(g.matrix, None);
    assert_eq!(
        g.entries,
        vec![
            vec![None, r(0, 1)],
            vec![r(0, 1), r(1, 2)],
            vec![None, r(3, 2)]
        ]
    );
    // a pole at 0 that cancels (unobservable integrator): finite
    let c = StateSpace::new(
        q(&[&[0, 0], &[0, -1]]),
        q(&[&[1], &[1]]),
        q(&[&[0, 1]]),
        q(&[&[0]]),
    )
    .unwrap();
    assert_eq!(dc_gain(&c).unwrap().entries, vec![vec![r(1, 1)]]);
}

#[test]
fn random_systems_agree_with_the_transfer_matrix_at_zero() {
    let mut rng = SplitMix64(0xdc_2026);
    let (mut singular, mut regular) = (0, 0);
    for _ in 0..60 {
        let (n, m, p) = (
            rng.int(1, 3) as usize,
            rng.int(1, 2) as usize,
            rng.int(1, 2) as usize,
        );
        let mut mat = |r: usize, c: usize, lo: i64, hi: i64| {
            let v = (0..r * c)
                .map(|_| Rational::from_integer(rng.int(lo, hi).into()))
                .collect();
            Matrix::from_vec(Q, r, c, v)
        };
        let s = StateSpace::new(
            mat(n, n, -2, 2),
            mat(n, m, -2, 2),
            mat(p, n, -2, 2),
            mat(p, m, -1, 1),
        )
        .unwrap();
        let g = dc_gain(&s).unwrap();
        assert!(g.verified);
        let tf = s.transfer_matrix().unwrap();
        for (i, row) in tf.entries.iter().enumerate() {
            for (j, f) in row.iter().enumerate() {
                let den0 = f.den.coeff(0);
                match &g.entries[i][j] {
                    None => assert!(Q.is_zero(&den0), "infinite only at a pole at 0"),
                    Some(x) => assert_eq!(Q.mul(x, &den0), f.num.coeff(0)),
                }
            }
        }
        match s.a.inverse() {
            Ok(ai) => {
                regular += 1;
                assert_eq!(g.matrix, Some(&s.d - &(&(&s.c * &ai) * &s.b)));
            }
            Err(_) => singular += 1,
        }
    }
    assert!(
        singular > 0 && regular > 0,
        "both cases drawn: {singular} {regular}"
    );
}

#[test]
fn command_line() {
    let (code, out, err) = run(&[
        "dcgain",
        "tests/data/interconnect/plant.json",
        "--format",
        "json",
    ]);
    assert_eq!(code, 0, "{err}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["dc_gain"], serde_json::json!([["1/2"]]));
    assert_eq!(j["verified"], true);
    let (code, out, _) = run(&[
        "dcgain",
        "tests/data/interconnect/pi.json",
        "--format",
        "json",
    ]);
    assert_eq!(code, 0);
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(
        (j["dc_gain"][0][0].as_str(), j["finite"].as_bool()),
        (Some("inf"), Some(false))
    );
    let (code, out, _) = run(&[
        "dcgain",
        "tests/data/interconnect/plant_sym.json",
        "--format",
        "json",
    ]);
    assert_eq!(code, 0);
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["dc_gain"], serde_json::json!([["1/a"]]));
    assert_eq!(j["conditions"], serde_json::json!(["a"]));
    let (code, _, err) = run(&["dcgain", "tests/data/no-such-file.json"]);
    assert_eq!((code, err.trim_end().lines().count()), (2, 1));
}
