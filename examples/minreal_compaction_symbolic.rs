//! The minimal-realization paper's compaction rule (sec. 3.3, eq. 33-36) in symbols, over
//! QQ(a11, a12, a22, b1..b4, c1..c4, lam): a repeated 2x2 mode M with geometric = algebraic
//! multiplicity (eq. 34) is compacted to one copy (eq. 35).
//!
//! Steps: the Jordan structure of eq. 34 over QQ(p) (the quadratic factor of M, twice, blocks
//! [1, 1]); the controllability rank 2 (so the minimal order is 2); eq. 36 read literally,
//! [b5; b6][c5 c6] = P := [b1; b2][c1 c2] + [b3; b4][c3 c4], needs rank P = 1, i.e. det P = 0:
//! it holds when the rows of B are co-linear (the paper's MIMO remark), not in general; the
//! exact general rule: any rank-one R = [b5; b6][c5 c6] with trace(R) = trace(P) and
//! trace(M R) = trace(M P) (the transfer function is trace((sI - M)^-1 P)); checked by equal
//! Markov parameters C A^k B, k < 6, as rational functions.
//!
//! Run: `cargo run --example minreal_compaction_symbolic`

use exactlti::field::ElemDisplay;
use exactlti::field::Field;
use exactlti::jordan::jordan_qp;
use exactlti::jordan::qp_form::integral;
use exactlti::matrix::Matrix;
use exactlti::matrix::params::rref_params;
use exactlti::mpoly::factor;
use exactlti::ratfunc::{RatFunc, RatFuncField};

fn mat(k: &RatFuncField, rows: &[&[&str]]) -> Matrix<RatFuncField> {
    Matrix::from_rows(
        k.clone(),
        rows.iter()
            .map(|r| r.iter().map(|s| k.parse(s).expect("entry")).collect())
            .collect(),
    )
    .expect("rectangular")
}

/// Markov parameters C A^k B, k < count (SISO: scalars).
fn markov(
    a: &Matrix<RatFuncField>,
    b: &Matrix<RatFuncField>,
    c: &Matrix<RatFuncField>,
    count: usize,
) -> Vec<RatFunc> {
    let mut v = b.clone();
    let mut out = vec![];
    for _ in 0..count {
        out.push(c.try_mul(&v).expect("shapes").get(0, 0).clone());
        v = a.try_mul(&v).expect("shapes");
    }
    out
}

fn trace(k: &RatFuncField, m: &Matrix<RatFuncField>) -> RatFunc {
    (0..m.nrows()).fold(k.zero(), |s, i| k.add(&s, m.get(i, i)))
}

fn main() {
    let vars = [
        "a11", "a12", "a22", "b1", "b2", "b3", "b4", "c1", "c2", "c3", "c4", "lam",
    ];
    let k = RatFuncField::new(&vars).expect("field");
    let mm = mat(&k, &[&["a11", "a12"], &["-a12", "a22"]]);
    let a = Matrix::block_diag(k.clone(), &[mm.clone(), mm.clone()]);
    let b = mat(&k, &[&["b1"], &["b2"], &["b3"], &["b4"]]);
    let c = mat(&k, &[&["c1", "c2", "c3", "c4"]]);
    println!("eq. 34: A = diag(M, M), M = [[a11, a12], [-a12, a22]], B = [b1..b4]^T, C = [c1..c4]");
    let jf = jordan_qp(&a).expect("jordan");
    let mut names = vars.iter().map(|v| v.to_string()).collect::<Vec<_>>();
    names.push("s".into());
    for e in &jf.components {
        println!(
            "  eigenvalues: roots of {} = 0, algebraic multiplicity {}, blocks {:?} per root",
            integral(&e.factor).to_string_vars(&names),
            e.multiplicity,
            e.blocks
        );
    }
    let e = &jf.components[0];
    assert_eq!((e.degree(), e.multiplicity), (2, 2));
    assert_eq!(e.blocks, [1, 1], "geometric = algebraic multiplicity");
    assert!(jf.verified);
    // controllability matrix rank
    let mut ctrb = b.clone();
    let mut v = b.clone();
    for _ in 1..4 {
        v = a.try_mul(&v).expect("m");
        ctrb = ctrb.hstack(&v).expect("h");
    }
    let (_, piv) = rref_params(&ctrb);
    println!(
        "  rank [B, AB, A^2 B, A^3 B] = {} (generically): minimal order 2",
        piv.len()
    );
    assert_eq!(piv.len(), 2);

    // eq. 36 literally
    let b12 = b.submatrix(0, 2, 0, 1);
    let b34 = b.submatrix(2, 4, 0, 1);
    let c12 = c.submatrix(0, 1, 0, 2);
    let c34 = c.submatrix(0, 1, 2, 4);
    let p = b12
        .try_mul(&c12)
        .expect("m")
        .try_add(&b34.try_mul(&c34).expect("m"))
        .expect("a");
    let det_p = p.det().expect("det");
    let fz = factor(det_p.num()).expect("factor");
    let fs: Vec<String> = fz
        .factors
        .iter()
        .map(|(f, _)| format!("({})", k.fmt_poly(f)))
        .collect();
    println!(
        "eq. 36: P = b12 c12 + b34 c34 has det P = {}{}: a rank-one [b5; b6][c5 c6] = P exists only where it vanishes",
        if fz.content < 0.into() { "-" } else { "" },
        fs.join("*")
    );
    assert_eq!(fz.factors.len(), 2);
    // co-linear rows of B (b34 = lam b12): eq. 36 holds with b56 = b12, c56 = c12 + lam c34
    let lam = k.parse("lam").expect("p");
    let bl = mat(&k, &[&["b1"], &["b2"], &["lam*b1"], &["lam*b2"]]);
    let c56 = c12.try_add(&c34.scale(&lam)).expect("a");
    let eq36 = markov(&a, &bl, &c, 6) == markov(&mm, &b12, &c56, 6);
    println!(
        "  co-linear rows (b3, b4) = lam (b1, b2): eq. 36 with b56 = (b1, b2), c56 = c12 + lam c34 reproduces C A^k B, k < 6: {eq36}"
    );
    assert!(eq36);

    // the exact general rule
    let tp = trace(&k, &p);
    let tmp = trace(&k, &mm.try_mul(&p).expect("m"));
    let c5 = tp.clone();
    let c6 = k
        .div(
            &k.sub(&k.mul(&k.parse("a11").expect("p"), &tp), &tmp),
            &k.parse("a12").expect("p"),
        )
        .expect("a12 != 0");
    let b56 = mat(&k, &[&["1"], &["0"]]);
    let c56 = Matrix::from_vec(k.clone(), 1, 2, vec![c5, c6]);
    let ok = markov(&a, &b, &c, 6) == markov(&mm, &b56, &c56, 6);
    println!(
        "  general rule: b56 = (1, 0), c5 = trace P = {}, c6 = (a11 trace P - trace(M P))/a12 = {}\n  \
         C A^k B = c56 M^k b56 for k < 6 (so equal transfer functions, orders 4 and 2): {ok}",
        k.fmt_elem(c56.get(0, 0)),
        k.fmt_elem(c56.get(0, 1))
    );
    assert!(ok);
    println!("  conditions: a12 (assumed nonzero; M is not a multiple of I)");
}
