//! Jordan forms in vehicle dynamics (Minaker) IN SYMBOLS, over QQ(a, b, cf, cr, Izz, m, u):
//! the general yaw-plane model eq. 24-26 (charpoly, the understeer/oversteer split), the
//! single-wheel case eq. 27 derived by substituting cf = 0, b = 0, its eigenvectors and
//! chains eq. 28-33, T and J eq. 34-35, and the closed-form response eq. 36-37 (with the
//! sign slip of eq. 36 against eq. 37a detected).
//!
//! Run: `cargo run --example vehicle_jordan_symbolic`

use exactlti::field::ElemDisplay;
use exactlti::field::{Field, Rational};
use exactlti::jordan::qp_form::integral;
use exactlti::jordan::{Component, JordanForm, jordan_qp};
use exactlti::matrix::Matrix;
use exactlti::mpoly::factor;
use exactlti::ratfunc::{RatFunc, RatFuncField};
use exactlti::report::sections::conditions_qp;

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

fn factored(k: &RatFuncField, x: &RatFunc) -> String {
    let part = |p: &exactlti::mpoly::MPoly| -> String {
        if p.is_constant() {
            return k.fmt_poly(p);
        }
        let fz = factor(p).expect("factor");
        let mut s: Vec<String> = fz
            .factors
            .iter()
            .map(|(f, e)| {
                let t = k.fmt_poly(f);
                let t = if f.len() > 1 { format!("({t})") } else { t };
                if *e > 1 { format!("{t}^{e}") } else { t }
            })
            .collect();
        if fz.content != 1.into() {
            s.insert(0, fz.content.to_string());
        }
        s.join("*")
    };
    format!("[{}] / [{}]", part(x.num()), part(x.den()))
}

fn main() {
    // ---- eq. 24-26: the general yaw-plane model
    let k = RatFuncField::new(&["a", "b", "cf", "cr", "Izz", "m", "u"]).expect("field");
    let a25 = mat(
        &k,
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
    println!("eq. 25: A over {k} =\n{}", show(&k, &a25));
    let jf = jordan_qp(&a25).expect("jordan");
    let kk = jf.base();
    println!("eq. 10: det(sI - A) = {}", kk_charpoly(&jf));
    let quad = jf
        .components
        .iter()
        .find(|e| e.degree() == 2)
        .expect("a quadratic factor");
    let c = quad.factor.coeffs();
    let (det, tr) = (c[0].clone(), c[1].clone());
    println!("  = s^2 (s^2 + tr s + det) with");
    println!("    tr  = {}", kk.fmt_elem(&tr));
    println!("    det = {}", factored(kk, &det));
    let zero = eigenvalue(&jf, &kk.zero()).expect("0");
    println!(
        "  the repeated zero (rigid-body modes: lateral offset, heading): blocks {:?}",
        zero.blocks
    );
    assert_eq!(zero.blocks, [2]);
    let disc = kk.sub(&kk.mul(&tr, &tr), &kk.mul(&kk.from_i64(4), &det));
    println!(
        "  discriminant tr^2 - 4 det = {}\n  > 0: two distinct real roots; < 0: a complex pair (oscillatory); \
         = 0: double root",
        factored(kk, &disc)
    );
    // understeer/oversteer: det * m Izz u^2 = cf cr (a+b)^2 + m u^2 (b cr - a cf)
    let scaled = kk.mul(&det, &kk.parse("m*Izz*u^2").expect("p"));
    println!(
        "  det * m*Izz*u^2 = {}: with b*cr - a*cf > 0 (understeer) det > 0 at every speed \
         (stable); with b*cr - a*cf < 0 (oversteer) det = 0 at the critical speed \
         u^2 = cf*cr*(a + b)^2/(m*(a*cf - b*cr)), a positive real root beyond it",
        kk.fmt_elem(&scaled)
    );
    assert_eq!(
        scaled,
        kk.parse("cf*cr*(a + b)^2 + m*u^2*(b*cr - a*cf)")
            .expect("p")
    );
    println!("  conditions (assumed nonzero): {:?}", conditions_qp(&jf));
    for (f, _) in factor(disc.num()).expect("f").factors {
        assert!(
            jf.conditions.iter().any(|c| c.num() == &f),
            "the discriminant is a condition"
        );
    }
    assert!(jf.verified);

    // ---- eq. 27: single wheel, cf = 0, b = 0 (substituted into eq. 25)
    let zero_q = Rational::from_integer(0.into());
    let sub = |x: &RatFunc| -> RatFunc {
        let x = kk.substitute(x, 2, &zero_q).expect("cf = 0");
        kk.substitute(&x, 1, &zero_q).expect("b = 0")
    };
    let a27_general = Matrix::from_vec(kk.clone(), 4, 4, jf.a.as_slice().iter().map(sub).collect());
    let k3 = RatFuncField::new(&["cr", "m", "u"]).expect("field");
    let a27 = mat(
        &k3,
        &[
            &["0", "u", "-1", "0"],
            &["0", "0", "0", "-1"],
            &["0", "0", "-cr/(m*u)", "-u"],
            &["0", "0", "0", "0"],
        ],
    );
    assert_eq!(show(kk, &a27_general), show(&k3, &a27));
    println!(
        "\neq. 27 (cf = 0, b = 0 in eq. 25): A =\n{}",
        show(&k3, &a27)
    );
    let jf = jordan_qp(&a27).expect("jordan");
    let k3 = jf.base().clone();
    let (t, j) = jf.primary_form().expect("T, J");
    println!("eq. 10: det(sI - A) = {}", kk_charpoly(&jf));
    let s = k3.parse("-cr/(m*u)").expect("s");
    let zero = eigenvalue(&jf, &k3.zero()).expect("0");
    let se = eigenvalue(&jf, &s).expect("s");
    println!(
        "eq. 29: eigenvalues 0 (algebraic multiplicity {}, geometric {}, blocks {:?}) and s = {}",
        zero.multiplicity,
        zero.geometric_multiplicity(),
        zero.blocks,
        k3.fmt_elem(&s)
    );
    assert_eq!(
        (zero.blocks.as_slice(), se.blocks.as_slice()),
        (&[3][..], &[1][..])
    );
    let t = &t;
    let col = |j: usize| -> Vec<String> { (0..4).map(|i| k3.fmt_elem(t.get(i, j))).collect() };
    println!(
        "eq. 28: X1 = {:?} (s = 0), X2 = {:?} (s = -cr/(m u))",
        col(0),
        col(3)
    );
    println!(
        "eq. 30-33: the chain of 0: A Y1 = X1, A Z1 = Y1: Y1 = {:?}, Z1 = {:?}",
        col(1),
        col(2)
    );
    // the paper's eq. 21/31 read [I s - A] Y = X, i.e. -A Y = X at s = 0; its chosen vectors
    // (eq. 33) satisfy A Y = X (the convention of J with +1 on the superdiagonal)
    let y33 = mat(&k3, &[&["0"], &["1/u"], &["0"], &["0"]]);
    let z33 = mat(&k3, &[&["0"], &["m/cr"], &["m*u/cr"], &["-1/u"]]);
    let x1 = mat(&k3, &[&["1"], &["0"], &["0"], &["0"]]);
    let ay = jf.a.try_mul(&y33).expect("mul");
    let az = jf.a.try_mul(&z33).expect("mul");
    println!(
        "  paper's eq. 33: A Y1 = X1: {}, A Z1 = Y1: {} (so eq. 21/31 hold with A - sI, not sI - A: \
         a sign convention, no effect on J)",
        ay == x1,
        az == y33
    );
    assert!(ay == x1 && az == y33);
    println!("eq. 34-35: T =\n{}\nJ =\n{}", show(&k3, t), show(&k3, &j));
    let t34 = mat(
        &k3,
        &[
            &["1", "0", "0", "m*u/cr"],
            &["0", "1/u", "m/cr", "0"],
            &["0", "0", "m*u/cr", "1"],
            &["0", "0", "-1/u", "0"],
        ],
    );
    assert!(jf.verified);
    assert_eq!(jf.a.try_mul(&t34).expect("m"), t34.try_mul(&j).expect("m"));
    // the paper's T = our T * C with C commuting with J (the normalisation freedom)
    let cmat = t.inverse().expect("T invertible").try_mul(&t34).expect("m");
    assert_eq!(j.try_mul(&cmat).expect("m"), cmat.try_mul(&j).expect("m"));
    println!(
        "  A T = T J holds as rational functions (verified = {}); the paper's T of eq. 34 is valid \
         for the same J and equals T C with C J = J C:\nC =\n{}",
        jf.verified,
        show(&k3, &cmat)
    );
    println!("  conditions (assumed nonzero): {:?}", conditions_qp(&jf));

    // ---- eq. 36-37: the closed-form response in symbols
    let k7 = RatFuncField::new(&["cr", "m", "u", "y0", "psi0", "v0", "r0"]).expect("field");
    let a7 = Matrix::from_vec(
        k7.clone(),
        4,
        4,
        a27.as_slice()
            .iter()
            .map(|x| k7.parse(&k3.fmt_elem(x)).expect("same entry"))
            .collect(),
    );
    let jf7 = jordan_qp(&a7).expect("jordan");
    let k7 = jf7.base().clone();
    let p = |s: &str| k7.parse(s).expect("p");
    // eq. 37 at t = 0: x0 = (y0 - v0/s, psi0, r0 u/s + v0, r0), s = -cr/(m u)
    let x0 = [
        p("y0 + v0*m*u/cr"),
        p("psi0"),
        p("v0 - r0*m*u^2/cr"),
        p("r0"),
    ];
    let fr = param_response(&jf7, &x0);
    println!(
        "\neq. 36-37: x(t) = sum over eigenvalues e^(theta t) sum_k t^k g_k (verified: x(0) = x0, x' = A x):"
    );
    let names = ["y", "psi", "v", "r"];
    for (theta, gs) in &fr {
        for (kk_, g) in gs.iter().enumerate() {
            let v: Vec<String> = g.iter().map(|x| k7.fmt_elem(x)).collect();
            println!(
                "  e^({}) t^{kk_}: {:?}",
                if k7.is_zero(theta) {
                    "0".to_string()
                } else {
                    format!("{} t", k7.fmt_elem(theta))
                },
                v
            );
        }
    }
    // eq. 37 term by term: y(t) = y0 + (psi0 - r0/s) u t - r0 u t^2/2 - (v0/s) e^{st}
    let zero_terms = &fr.iter().find(|(th, _)| k7.is_zero(th)).expect("0").1;
    let s_terms = &fr.iter().find(|(th, _)| !k7.is_zero(th)).expect("s").1;
    let want37: [(&str, &[&str]); 4] = [
        ("37a", &["y0", "(psi0 + r0*m*u/cr)*u", "-r0*u/2"]),
        ("37b", &["psi0", "-r0", "0"]),
        ("37c", &["-r0*m*u^2/cr", "0", "0"]),
        ("37d", &["r0", "0", "0"]),
    ];
    for (row, (eq, want)) in want37.iter().enumerate() {
        for (kk_, w) in want.iter().enumerate() {
            assert_eq!(zero_terms[kk_][row], p(w), "eq. {eq}, t^{kk_}");
        }
        println!("  eq. {eq} ({}): polynomial part matches", names[row]);
    }
    assert_eq!(s_terms[0][0], p("v0*m*u/cr"), "eq. 37a: -(v0/s) e^(st)");
    assert_eq!(s_terms[0][2], p("v0"), "eq. 37c: v0 e^(st)");
    // eq. 36 as printed: (r0 u / 2) e1 t^2
    let eq36_t2 = p("r0*u/2");
    let derived = &zero_terms[2][0];
    if *derived != eq36_t2 {
        println!(
            "  eq. 36 has +r0 u/2 * e1 * t^2; the derivation (and eq. 37a) give {} t^2: \
             a sign slip in eq. 36 (its t^2 term must be -r0 u/2)",
            k7.fmt_elem(derived)
        );
    }
    assert_eq!(*derived, k7.neg(&eq36_t2));
}

type Form = JordanForm<RatFuncField>;

/// The component of the eigenvalue `v` in Q(p).
fn eigenvalue<'a>(jf: &'a Form, v: &RatFunc) -> Option<&'a Component<RatFuncField>> {
    let i = jf.values().iter().position(|x| x.as_ref() == Some(v))?;
    Some(&jf.components[i])
}

/// Terms of the free response from `x0` (every eigenvalue in Q(p)): per eigenvalue its value
/// and g_0, g_1, ..., checked exactly (x(0) = x0, x' = A x).
fn param_response(jf: &Form, x0: &[RatFunc]) -> Vec<(RatFunc, Vec<Vec<RatFunc>>)> {
    let k = jf.base();
    let x0m = Matrix::column(k.clone(), x0.to_vec());
    let fr = jf.free_response().from_state(&x0m);
    assert!(
        fr.verify(jf, &x0m),
        "the closed form solves x' = A x from x0"
    );
    let values = jf.values();
    let mut out: Vec<(RatFunc, Vec<Vec<RatFunc>>)> = vec![];
    for (ci, power, g) in &fr.terms {
        let e = g.field();
        let g: Vec<RatFunc> = g
            .as_slice()
            .iter()
            .map(|x| e.to_base(x).expect("in Q(p)"))
            .collect();
        let theta = values[*ci].clone().expect("complete");
        match out.last_mut() {
            Some((th, gs)) if *power > 0 && *th == theta => gs.push(g),
            _ => out.push((theta, vec![g])),
        }
    }
    out
}

fn kk_charpoly(jf: &Form) -> String {
    let mut names = jf.base().vars().to_vec();
    names.push("s".into());
    let f: Vec<String> = jf
        .components
        .iter()
        .map(|e| {
            let big = integral(&e.factor);
            let t = big.to_string_vars(&names);
            let t = if big.len() > 1 { format!("({t})") } else { t };
            if e.multiplicity > 1 {
                format!("{t}^{}", e.multiplicity)
            } else {
                t
            }
        })
        .collect();
    format!("{} (up to the content in the parameters)", f.join(" * "))
}
