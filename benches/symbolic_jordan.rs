//! Jordan form over QQ(p) (issue 13): wall-clock timings (release build, std::time).
//!
//! `cargo bench --bench symbolic_jordan` prints `name: best ms (median ms, reps)` per case and
//! writes the inputs to `target/symbolic-jordan-bench-cases.txt` (tab-separated: name,
//! variables, n, entries separated by `;`) so `scripts/anchors/symbolic_jordan.py` times
//! SymPy's `Matrix.jordan_form` on the same symbolic matrices.
//!
//! Cases: the single-wheel yaw-plane model of the vehicle-dynamics paper (eq. 27, QQ(cr, m,
//! u): a 3x3 block at 0 and -cr/(m u); goal <= 50 ms), the general yaw-plane model (eq. 25,
//! seven parameters: a 2x2 block at 0 and an irreducible quadratic), and a planted 5x5
//! S J S^-1 over QQ(p, q) with blocks [2, 1] at p and [2] at q.

#[path = "common.rs"]
mod common;

use exactlti::field::{ElemDisplay, Field};
use exactlti::jordan::jordan_qp;
use exactlti::matrix::Matrix;
use exactlti::ratfunc::RatFuncField;
use std::fmt::Write as _;

fn mat(k: &RatFuncField, rows: &[&[&str]]) -> Matrix<RatFuncField> {
    Matrix::from_rows(
        k.clone(),
        rows.iter()
            .map(|r| r.iter().map(|s| k.parse(s).unwrap()).collect())
            .collect(),
    )
    .unwrap()
}

fn main() {
    let mut cases = String::new();
    let mut add = |name: &str, k: &RatFuncField, a: &Matrix<RatFuncField>| {
        let n = a.nrows();
        let ents: Vec<String> = a.as_slice().iter().map(|x| k.fmt_elem(x)).collect();
        let _ = writeln!(
            cases,
            "{name}\t{}\t{n}\t{}",
            k.vars().join(","),
            ents.join(";")
        );
    };
    let k3 = RatFuncField::new(&["cr", "m", "u"]).unwrap();
    let yaw27 = mat(
        &k3,
        &[
            &["0", "u", "-1", "0"],
            &["0", "0", "0", "-1"],
            &["0", "0", "-cr/(m*u)", "-u"],
            &["0", "0", "0", "0"],
        ],
    );
    add("yaw plane single wheel eq. 27 (3 params)", &k3, &yaw27);
    let k7 = RatFuncField::new(&["a", "b", "cf", "cr", "Izz", "m", "u"]).unwrap();
    let yaw25 = mat(
        &k7,
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
    add("yaw plane general eq. 25 (7 params)", &k7, &yaw25);
    let k2 = RatFuncField::new(&["p", "q"]).unwrap();
    let j = mat(
        &k2,
        &[
            &["p", "1", "0", "0", "0"],
            &["0", "p", "0", "0", "0"],
            &["0", "0", "p", "0", "0"],
            &["0", "0", "0", "q", "1"],
            &["0", "0", "0", "0", "q"],
        ],
    );
    let s = Matrix::from_fn(k2.clone(), 5, 5, |i, jj| {
        if i == jj {
            k2.one()
        } else if jj == i + 1 {
            k2.var(i % 2)
        } else if i == jj + 2 {
            k2.from_i64(1)
        } else {
            k2.zero()
        }
    });
    let planted = s
        .try_mul(&j)
        .unwrap()
        .try_mul(&s.inverse().unwrap())
        .unwrap();
    add("planted 5x5 S J S^-1 over QQ(p, q)", &k2, &planted);
    for (name, a) in [
        ("yaw plane single wheel eq. 27 (3 params)", &yaw27),
        ("yaw plane general eq. 25 (7 params)", &yaw25),
        ("planted 5x5 S J S^-1 over QQ(p, q)", &planted),
    ] {
        if !common::selected(name) {
            continue;
        }
        let jf = jordan_qp(a).unwrap();
        assert!(jf.verified);
        common::bench(name, 5, 1500.0, || jordan_qp(a).unwrap());
        let (t, _) = jf.primary_form().unwrap();
        let size: usize = t
            .as_slice()
            .iter()
            .map(|x| jf.base().fmt_elem(x).len())
            .sum();
        println!(
            "  (T: {size} characters; {} conditions)",
            jf.conditions.len()
        );
    }
    let target = std::env::var("CARGO_TARGET_DIR").unwrap_or_else(|_| "target".into());
    let _ = std::fs::write(
        std::path::Path::new(&target).join("symbolic-jordan-bench-cases.txt"),
        cases,
    );
}
