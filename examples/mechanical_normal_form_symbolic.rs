//! The mechanical normal form paper, App. B, in symbols over QQ(w1, w2): the system of
//! eq. 18, the singular T of eq. 19 (X = [e1, e3]: a zero row for every w1, w2), T = I for
//! X = [e1, e2], and the normal form found by the library's search, verified as rational
//! functions, with the conditions it assumes.
//!
//! Run: `cargo run --example mechanical_normal_form_symbolic`

use exactlti::field::ElemDisplay;
use exactlti::field::Field;
use exactlti::matrix::Matrix;
use exactlti::ratfunc::RatFuncField;
use exactlti::structure::mechanical::transform::transformation_from_x;
use exactlti::structure::mechanical::{DEFAULT_MAX_CANDIDATES, mechanical_normal_form_in};

fn mat(k: &RatFuncField, rows: &[&[&str]]) -> Matrix<RatFuncField> {
    Matrix::from_rows(
        k.clone(),
        rows.iter()
            .map(|r| r.iter().map(|s| k.parse(s).expect("entry")).collect())
            .collect(),
    )
    .expect("rectangular")
}

fn show(k: &RatFuncField, m: &Matrix<RatFuncField>) -> String {
    let rows: Vec<String> = (0..m.nrows())
        .map(|i| {
            let r: Vec<String> = m.row(i).iter().map(|x| k.fmt_elem(x)).collect();
            format!("    [{}]", r.join(", "))
        })
        .collect();
    rows.join("\n")
}

fn main() -> exactlti::Result<()> {
    let k = RatFuncField::new(&["w1", "w2"])?;
    let a = mat(
        &k,
        &[
            &["0", "0", "1", "0"],
            &["0", "0", "0", "1"],
            &["-w1^2", "0", "0", "0"],
            &["0", "-w2^2", "0", "0"],
        ],
    );
    let b = mat(&k, &[&["0"], &["0"], &["0"], &["1"]]);
    let c = mat(&k, &[&["1", "0", "0", "0"]]);
    let d = mat(&k, &[&["0"]]);
    println!("eq. 18: A =\n{}\nB = [0, 0, 0, 1]^T", show(&k, &a));
    let x = mat(&k, &[&["1", "0"], &["0", "0"], &["0", "1"], &["0", "0"]]);
    let t19 = transformation_from_x(&a, &x)?;
    let det = t19.det()?;
    println!(
        "eq. 19: X = [e1, e3]: [X, A^T X] =\n{}\n  det T = {} identically in w1, w2: singular",
        show(&k, &t19.transpose()),
        k.fmt_elem(&det)
    );
    assert!(k.is_zero(&det));
    let x = mat(&k, &[&["1", "0"], &["0", "1"], &["0", "0"], &["0", "0"]]);
    let t = transformation_from_x(&a, &x)?;
    println!("  X = [e1, e2]: T = I: {}", t.is_identity());
    assert!(t.is_identity());
    let k = k.fresh();
    let re = |m: &Matrix<RatFuncField>| {
        Matrix::from_vec(k.clone(), m.nrows(), m.ncols(), m.as_slice().to_vec())
    };
    let m = mechanical_normal_form_in(
        None,
        &re(&a),
        &re(&b),
        &re(&c),
        &re(&d),
        DEFAULT_MAX_CANDIDATES,
    )?;
    assert!(m.exists && m.verified);
    let f = m.form.as_ref().expect("exists");
    println!(
        "normal form over {k} (search: {} candidate(s)):\n  stiffness K =\n{}\n  damping D =\n{}\n  T =\n{}",
        f.candidates,
        show(&k, &f.stiffness),
        show(&k, &f.damping),
        show(&k, &f.t)
    );
    k.record_condition(f.t.det()?.num());
    println!(
        "  verified (similarity and Markov parameters as rational functions): {}\n  conditions: {:?}",
        m.verified,
        k.conditions_strings()?
    );
    Ok(())
}
