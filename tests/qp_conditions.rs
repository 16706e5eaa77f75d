//! Conditions over Q(p) that mean something (issue 25 item 3) and the commands added over
//! Q(p) (item 2): a rank or pivot pattern proved by one minor at a point records that
//! minor's factors (diag(p0..p5): minimal order 6 exactly where every p_i - p_j != 0; a
//! generator of matrices P diag(f) Q whose rank drops on the hypersurfaces f_i = 0 records
//! every f_i); a zero at s = 0 for every parameter value is not minimum phase; `modes` as
//! formulas; `sweep`/`critical` along a parameter written `null`.

use crate::common::cli::{run, temp_file};
use crate::common::systems::diag_qp;
use exactlti::field::Field;
use exactlti::matrix::Matrix;
use exactlti::ratfunc::RatFuncField;
use exactlti::rng::SplitMix64;

#[test]
fn diag_minreal_states_where_the_order_drops() {
    for n in [4, 6] {
        let s = diag_qp(n);
        let k = s.a.field().clone();
        k.clear_conditions();
        let r = exactlti::realization::minimal(&s, exactlti::realization::MinrealMethod::Kalman)
            .unwrap();
        assert_eq!(r.order, n);
        assert!(r.verified);
        let conds = k.conditions_strings().unwrap();
        for i in 0..n {
            for j in i + 1..n {
                let d = format!("p{i} - p{j}");
                assert!(conds.contains(&d), "n = {n}: {d} missing from {conds:?}");
            }
        }
    }
}

/// `P diag(f_1..f_r, 0..) Q` with unimodular integer `P`, `Q` (products of elementary
/// matrices) and random linear `f_i` in a, b, c: rank r exactly off the hypersurfaces
/// f_i = 0, so the rank must come with every f_i among its conditions.
#[test]
fn rank_records_where_it_drops() {
    let k = RatFuncField::new(&["a", "b", "c"]).unwrap();
    let mut rng = SplitMix64(25);
    for _ in 0..12 {
        let n = rng.int(2, 5) as usize;
        let r = rng.int(1, n as i64) as usize;
        let fs: Vec<String> = (0..r)
            .map(|_| {
                format!(
                    "{} + {}*a + {}*b + {}*c",
                    rng.int(-4, 4),
                    rng.int(1, 4),
                    rng.int(-4, 4),
                    rng.int(-4, 4)
                )
            })
            .collect();
        let mid = Matrix::from_fn(k.clone(), n, n, |i, j| {
            if i == j && i < r {
                k.parse(&fs[i]).unwrap()
            } else {
                k.zero()
            }
        });
        let unimodular = |rng: &mut SplitMix64| {
            let mut u = Matrix::identity(k.clone(), n);
            for _ in 0..2 * n {
                let (i, j) = (
                    rng.int(0, n as i64 - 1) as usize,
                    rng.int(0, n as i64 - 1) as usize,
                );
                if i != j {
                    let mut e = Matrix::identity(k.clone(), n);
                    e.set(i, j, k.from_i64(rng.int(-2, 2)));
                    u = &u * &e;
                }
            }
            u
        };
        let m = &(&unimodular(&mut rng) * &mid) * &unimodular(&mut rng);
        let k2 = k.fresh();
        let m = m.map(&k2, |x| x.clone());
        assert_eq!(m.rank(), r, "{fs:?}");
        let conds = k2.conditions().unwrap();
        for f in &fs {
            let p = k2.parse(f).unwrap().num().primitive_part();
            let p = if conds.contains(&p) { p } else { p.neg() };
            assert!(
                conds.contains(&p),
                "{f} missing from {:?}",
                k2.conditions_strings()
            );
        }
    }
}

#[test]
fn zero_at_the_origin_is_not_minimum_phase() {
    for cmd in ["scb", "zeros"] {
        let (code, out, err) = run(&[
            cmd,
            "data/scb/single-track-rear.json",
            "--symbolic",
            "--format",
            "json",
        ]);
        assert_eq!(code, 0, "{err}");
        let v: serde_json::Value = serde_json::from_str(&out).unwrap();
        assert_eq!(
            v["minimum_phase"],
            serde_json::Value::Bool(false),
            "{cmd}: {out}"
        );
    }
}

#[test]
fn modes_as_formulas() {
    let f = temp_file(
        "qp_conditions",
        "msd.json",
        r#"{"parameters": {"m": null, "k": null, "c": null},
            "A": [[0, 1], ["-k/m", "-c/m"]], "B": [[0], ["1/m"]], "C": [[1, 0]], "D": [[0]]}"#,
    );
    let (code, out, err) = run(&["modes", f.to_str().unwrap(), "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let m = &v["modes"][0];
    assert_eq!(m["omega_n_squared"], "k/m", "{out}");
    assert_eq!(m["two_zeta_omega_n"], "c/m", "{out}");
    assert_eq!(m["zeta_squared"], "c^2/(4*k*m)", "{out}");
}

#[test]
fn sweep_and_critical_along_a_null_parameter() {
    let f = temp_file(
        "qp_conditions",
        "sweep.json",
        r#"{"parameters": {"v": null, "k": "2"},
            "A": [[0, 1], ["-k", "-v"]], "B": [[0], [1]], "C": [[1, 0]], "D": [[0]]}"#,
    );
    let p = f.to_str().unwrap();
    let (code, _, err) = run(&[
        "sweep", p, "--param", "v", "--from", "0", "--to", "1", "--points", "3",
    ]);
    assert_eq!(code, 0, "{err}");
    let (code, out, err) = run(&["critical", p, "--param", "v", "--from", "-1", "--to", "1"]);
    assert_eq!(code, 0, "{err}");
    assert!(!out.is_empty());
    // another symbol without a value: refused, naming it
    let g = temp_file(
        "qp_conditions",
        "sweep2.json",
        r#"{"parameters": {"v": null, "k": null},
            "A": [[0, 1], ["-k", "-v"]], "B": [[0], [1]], "C": [[1, 0]], "D": [[0]]}"#,
    );
    let (code, _, err) = run(&[
        "sweep",
        g.to_str().unwrap(),
        "--param",
        "v",
        "--from",
        "0",
        "--to",
        "1",
    ]);
    assert_eq!(code, 2);
    assert!(err.contains("k without one"), "{err}");
}
