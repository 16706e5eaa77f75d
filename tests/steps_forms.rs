//! `--steps` for `mnf`, `standard` (descriptor systems) and `jordan --real` (issue 27).
//! Each checker recomputes the identities of the recorded steps from the step's own objects
//! and the input (eq. 15 for T_0 and every direction, the member T(alpha), the similarity and
//! the second-order model; U E V and its zero pattern, the elimination, the transfer matrix
//! at points; A T_c = T_c J_c), returning `Err` naming the first identity that fails, so
//! tampered steps are rejected. The papers' intermediate results are asserted where they
//! give them: the mechanical-normal-form paper's App. B (eq. 18: U_B2, T = I for a system
//! already in normal form) and the vehicle paper's eq. 11-14 (the real block and T up to
//! its unit-length normalisation).

use crate::common;
use crate::common::cli::{json_of as json, step_names};
use exactlti::algebraic::NumberField;
use exactlti::field::ElemDisplay;
use exactlti::field::{Field, Q};
use exactlti::jordan::derivation::{
    Derivation, Method, Object, Recorder, Step, StepKind, ratfunc_log,
};
use exactlti::matrix::Matrix;
use exactlti::qmat;
use exactlti::ratfunc::RatFuncField;
use exactlti::realization::{descriptor_to_standard_recorded, eval_transfer};
use exactlti::structure::mechanical::{DEFAULT_MAX_CANDIDATES, mechanical_normal_form_recorded};
use exactlti::system::Descriptor;

type Check = Result<(), String>;

fn ensure(ok: bool, what: &str) -> Check {
    if ok { Ok(()) } else { Err(what.to_string()) }
}

fn mat<'s, K: Field>(s: &'s Step<K>, key: &str) -> Result<&'s Matrix<K>, String> {
    s.matrix(key).ok_or(format!("{:?} has no {key}", s.kind))
}

fn one<K: Field>(d: &Derivation<K>, kind: StepKind) -> Result<&Step<K>, String> {
    d.of_kind(kind).next().ok_or(format!("no {kind:?} step"))
}

/// `[0; I_p]` (n x p).
fn target<K: Field>(k: &K, n: usize, p: usize) -> Matrix<K> {
    Matrix::from_fn(k.clone(), n, p, |i, j| {
        if i == n - p + j { k.one() } else { k.zero() }
    })
}

/// The MNF steps of `(A, B, C)` (no descriptor), every identity recomputed.
fn check_mnf<K: Field>(d: &Derivation<K>, abc: [&Matrix<K>; 3]) -> Check {
    let [a, b, c] = abc;
    let k = a.field().clone();
    let n = a.nrows();
    let h = n / 2;
    let b1 = match d.of_kind(StepKind::MnfCompression).next() {
        Some(s) => {
            ensure(mat(s, "B1")? * mat(s, "R")? == *b, "B1 R = B")?;
            mat(s, "B1")?.clone()
        }
        None => b.clone(),
    };
    let p = b1.ncols();
    let ex = one(d, StepKind::MnfExistence)?;
    if let Some(u) = ex.matrix("UB2t") {
        ensure((u * &b1).is_zero(), "U_B2^T B = 0")?;
        ensure(u.rank() == n - p && u.nrows() == n - p, "U_B2^T rows")?;
        if let Some(kk) = ex.matrix("K") {
            ensure(*kk == &(u * a) * &b1, "K = U_B2^T A B")?;
            ensure(ex.count("rank_k") == Some(kk.rank()), "rank K")?;
        }
    }
    if ex.count("exists") != Some(1) {
        return ensure(d.of_kind(StepKind::MnfForm).next().is_none(), "no form");
    }
    let eq = one(d, StepKind::MnfEquation)?;
    let sat = |t: &Matrix<K>, rhs: &Matrix<K>| {
        let ta = t * a;
        ta.submatrix(0, h, 0, n) == t.submatrix(h, n, 0, n) && t * &b1 == *rhs
    };
    let t0 = mat(eq, "T0")?;
    ensure(sat(t0, &target(&k, n, p)), "eq. 15 for T0")?;
    let s = eq.count("s").ok_or("s")?;
    ensure(eq.count("rank_L") == Some(n * n - s), "rank L = n^2 - s")?;
    let zero = Matrix::zeros(k.clone(), n, p);
    let dirs: Vec<Matrix<K>> = match eq.matrix("Tk") {
        Some(side) => (0..s)
            .map(|i| side.submatrix(0, n, i * n, i * n + n))
            .collect(),
        None => vec![],
    };
    for t in &dirs {
        ensure(sat(t, &zero), "eq. 15 (homogeneous) for T_k")?;
    }
    if let Some(l) = eq.matrix("L") {
        // L vec(T0) = [0; vec([0; I_p])] (column-stacking vec)
        let v = Matrix::from_fn(k.clone(), n * n, 1, |i, _| t0.get(i % n, i / n).clone());
        let want = Matrix::zeros(k.clone(), h * n, 1)
            .vstack(&Matrix::from_fn(k.clone(), n * p, 1, |i, _| {
                target(&k, n, p).get(i % n, i / n).clone()
            }))
            .unwrap();
        ensure(l * &v == want, "L vec(T0) = R")?;
        ensure(l.rank() == n * n - s, "rank L")?;
    }
    let se = one(d, StepKind::MnfSearch)?;
    let t = mat(se, "T")?;
    if se.count("t_equals_i") == Some(1) {
        ensure(
            t.is_identity() && sat(t, &target(&k, n, p)),
            "T = I solves eq. 15",
        )?;
    } else if !dirs.is_empty() {
        let alpha = mat(se, "alpha")?;
        let mut want = t0.clone();
        for (i, dk) in dirs.iter().enumerate() {
            want = &want + &dk.scale(alpha.get(0, i));
        }
        ensure(*t == want, "T = T0 + sum alpha_k T_k")?;
    }
    ensure(!k.is_zero(&t.det().unwrap()), "det T != 0")?;
    let fm = one(d, StepKind::MnfForm)?;
    let (at, bt, ct) = (mat(fm, "At")?, mat(fm, "Bt")?, mat(fm, "Ct")?);
    ensure(at * t == t * a, "At T = T A")?;
    ensure(*bt == t * b, "Bt = T B")?;
    ensure(ct * t == *c, "Ct T = C")?;
    let (kq, dq) = (mat(fm, "Kq")?, mat(fm, "Dq")?);
    ensure(*kq == -&at.submatrix(h, n, 0, h), "K = -At_21")?;
    ensure(*dq == -&at.submatrix(h, n, h, n), "D = -At_22")?;
    ensure(mat(fm, "Mq")?.is_identity(), "M = I")?;
    ensure(
        *mat(fm, "W")? == bt.submatrix(h, n, 0, b.ncols()),
        "Bt = [0; W]",
    )?;
    ensure(at.submatrix(0, h, h, n).is_identity(), "At_12 = I")?;
    ensure(at.submatrix(0, h, 0, h).is_zero(), "At_11 = 0")
}

fn mnf_steps<K: Field>(abcd: [&Matrix<K>; 4], rec: &mut Recorder<'_, K>) {
    mechanical_normal_form_recorded(None, abcd, DEFAULT_MAX_CANDIDATES, Some(rec)).unwrap();
}

/// The library's doc example, S^-1 [[0, 1], [-4, -1]] S with S = [[0, 1], [1, 1]] (B = e1,
/// C = e1^T, D = 0): `(A, B, C)` and its MNF steps.
fn scrambled_oscillator_steps() -> ([Matrix<Q>; 3], Derivation<Q>) {
    let (a, b, c, d) = (
        qmat![[-2, -6], [1, 1]],
        qmat![[1], [0]],
        qmat![[1, 0]],
        qmat![[0]],
    );
    let mut rec = Recorder::new(Method::Mnf, Q);
    mnf_steps([&a, &b, &c, &d], &mut rec);
    ([a, b, c], rec.finish())
}

#[test]
fn mnf_steps_scrambled_oscillator_over_q() {
    let ([a, b, c], der) = scrambled_oscillator_steps();
    assert!(der.verified());
    check_mnf(&der, [&a, &b, &c]).unwrap();
    let fm = one(&der, StepKind::MnfForm).unwrap();
    assert_eq!(fm.matrix("Kq").unwrap(), &qmat![[4]]);
    assert_eq!(fm.matrix("Dq").unwrap(), &qmat![[1]]);
    let se = one(&der, StepKind::MnfSearch).unwrap();
    assert_eq!(se.count("t_equals_i"), Some(0));
}

#[test]
fn mnf_steps_paper_appendix_b_in_symbols() {
    // eq. 18: A already in normal form over QQ(w1, w2), B = e4
    let k = RatFuncField::new(&["w1", "w2"]).unwrap();
    let m = |rows: &[&[&str]]| common::qp_matrix(&k, rows);
    let a = m(&[
        &["0", "0", "1", "0"],
        &["0", "0", "0", "1"],
        &["-w1^2", "0", "0", "0"],
        &["0", "-w2^2", "0", "0"],
    ]);
    let b = m(&[&["0"], &["0"], &["0"], &["1"]]);
    let c = m(&[&["1", "0", "0", "0"]]);
    let d = m(&[&["0"]]);
    let mut rec = Recorder::with_log(Method::Mnf, k.clone(), ratfunc_log(&k));
    mnf_steps([&a, &b, &c, &d], &mut rec);
    let der = rec.finish();
    assert!(der.verified());
    check_mnf(&der, [&a, &b, &c]).unwrap();
    // eq. 18: U_B2 = [e1, e2, e3] (its transpose recorded), K = U_B2^T A B = e2
    let ex = one(&der, StepKind::MnfExistence).unwrap();
    assert_eq!(
        ex.matrix("UB2t").unwrap(),
        &m(&[
            &["1", "0", "0", "0"],
            &["0", "1", "0", "0"],
            &["0", "0", "1", "0"]
        ])
    );
    assert_eq!(ex.matrix("K").unwrap(), &m(&[&["0"], &["1"], &["0"]]));
    // the system is in normal form: T = I without search (issue 27 item 2), K = diag(w^2)
    let se = one(&der, StepKind::MnfSearch).unwrap();
    assert_eq!(se.count("t_equals_i"), Some(1));
    assert!(se.matrix("T").unwrap().is_identity());
    let fm = one(&der, StepKind::MnfForm).unwrap();
    assert_eq!(
        fm.matrix("Kq").unwrap(),
        &m(&[&["w1^2", "0"], &["0", "w2^2"]])
    );
    assert!(fm.matrix("Dq").unwrap().is_zero());
    // eq. 15 has (n/2)(n - 2p) = 4 free directions
    assert_eq!(
        one(&der, StepKind::MnfEquation).unwrap().count("s"),
        Some(4)
    );
}

#[test]
fn mnf_steps_dependent_inputs_and_no_form() {
    // B = [b, 2b]: compression B = B1 R
    let a = qmat![[0, 0, 1, 0], [0, 0, 0, 1], [-2, 1, 0, 0], [1, -2, 0, 0]];
    let b = qmat![[0, 0], [0, 0], [1, 2], [0, 0]];
    let (c, d) = (qmat![[1, 0, 0, 0]], qmat![[0, 0]]);
    let mut rec = Recorder::new(Method::Mnf, Q);
    mnf_steps([&a, &b, &c, &d], &mut rec);
    let der = rec.finish();
    assert!(der.verified());
    assert_eq!(der.of_kind(StepKind::MnfCompression).count(), 1);
    check_mnf(&der, [&a, &b, &c]).unwrap();
    // diag(2, 2) (+) rotation, B = e4: two uncontrollable modes at 2, one free coordinate
    let a = qmat![[2, 0, 0, 0], [0, 2, 0, 0], [0, 0, 0, 1], [0, 0, -1, 0]];
    let b = qmat![[0], [0], [0], [1]];
    let (c, d) = (qmat![[1, 0, 0, 0]], qmat![[0]]);
    let mut rec = Recorder::new(Method::Mnf, Q);
    mnf_steps([&a, &b, &c, &d], &mut rec);
    let der = rec.finish();
    assert!(der.verified(), "no form is not a failed identity");
    let ex = one(&der, StepKind::MnfExistence).unwrap();
    assert_eq!((ex.count("exists"), ex.count("geo")), (Some(0), Some(2)));
    check_mnf(&der, [&a, &b, &c]).unwrap();
}

#[test]
fn tampered_mnf_steps_are_rejected() {
    let ([a, b, c], der) = scrambled_oscillator_steps();
    let mut rejected = 0;
    for (i, st) in der.steps.iter().enumerate() {
        for (j, (_, o)) in st.objects.iter().enumerate() {
            let Object::Matrix(m) = o else { continue };
            if m.nrows() == 0 || m.ncols() == 0 {
                continue;
            }
            let mut bad = der.clone();
            let Object::Matrix(mm) = &mut bad.steps[i].objects[j].1 else {
                unreachable!()
            };
            let x = Q.add(mm.get(0, 0), &Q.one());
            mm.set(0, 0, x);
            if check_mnf(&bad, [&a, &b, &c]).is_err() {
                rejected += 1;
            }
        }
    }
    // every matrix that enters an identity (K, T0, Tk, L, T, At, Bt, Ct, Kq, Dq; not alpha
    // alone, which T rejects, nor the identity matrix M)
    assert!(rejected >= 9, "{rejected}");
}

/// The standard-form steps of `sys`, every identity recomputed.
fn check_standard<K: Field>(d: &Derivation<K>, sys: &Descriptor<K>) -> Check {
    let k = sys.a.field().clone();
    let n = sys.nstates();
    let cs = one(d, StepKind::DescriptorCompress)?;
    let (u, v, uev) = (mat(cs, "U")?, mat(cs, "V")?, mat(cs, "UEV")?);
    ensure(*uev == &(u * &sys.e) * v, "UEV = U E V")?;
    ensure(*mat(cs, "UAV")? == &(u * &sys.a) * v, "UAV")?;
    let r = cs.count("r").ok_or("r")?;
    ensure(r == sys.e.rank(), "r = rank E")?;
    ensure(
        uev.submatrix(0, r, r, n).is_zero() && uev.submatrix(r, n, 0, n).is_zero(),
        "UEV = diag(E11, 0)",
    )?;
    ensure(uev.submatrix(0, r, 0, r).rank() == r, "E11 invertible")?;
    let fm = one(d, StepKind::StandardForm)?;
    let (a_s, b_s, c_s, d_s) = (
        mat(fm, "As")?,
        mat(fm, "Bs")?,
        mat(fm, "Cs")?,
        mat(fm, "Ds")?,
    );
    if let Some(w) = fm.matrix("W") {
        let v1 = mat(fm, "V1")?;
        let ev1 = &sys.e * v1;
        ensure((&sys.e * w).is_zero(), "E W = 0")?;
        ensure(&ev1 * a_s == &sys.a * v1, "E V1 As = A V1")?;
        ensure(&ev1 * b_s == &(&sys.a * w) + &sys.b, "E V1 Bs = A W + B")?;
        ensure(&sys.c * v1 == *c_s, "C V1 = Cs")?;
        ensure(&(&sys.c * w) + &sys.d == *d_s, "C W + D = Ds")?;
    }
    if let Some(f) = d.of_kind(StepKind::DescriptorFitting).next() {
        let gn = mat(f, "GN")?;
        ensure(
            gn.nrows() == 0 || gn.pow(gn.nrows() as u32).unwrap().is_zero(),
            "GN nilpotent",
        )?;
        ensure(*mat(f, "Af")? == *a_s, "As = Af")?;
    }
    ensure(fm.count("removed") == Some(n - a_s.nrows()), "removed")?;
    // the transfer matrices agree at points (enough: degrees are at most 2n)
    let std = Descriptor::new(
        Matrix::identity(k.clone(), a_s.nrows()),
        a_s.clone(),
        b_s.clone(),
        c_s.clone(),
        d_s.clone(),
    )
    .unwrap();
    for t in 0..(2 * n + 3) as i64 {
        let s0 = k.from_rational(&exactlti::field::Rational::new(
            (3 * t + 1).into(),
            5.into(),
        ));
        if let (Some(g1), Some(g2)) = (eval_transfer(sys, &s0), eval_transfer(&std, &s0)) {
            ensure(g1 == g2, "C (sE - A)^-1 B + D = Cs (sI - As)^-1 Bs + Ds")?;
        }
    }
    Ok(())
}

fn standard_steps<K: Field>(sys: &Descriptor<K>) -> Derivation<K> {
    let mut rec = Recorder::new(Method::Standard, sys.a.field().clone());
    descriptor_to_standard_recorded(sys, Some(&mut rec)).unwrap();
    rec.finish()
}

fn descriptors() -> Vec<(Descriptor<Q>, usize)> {
    vec![
        // E invertible (not diagonal)
        (
            Descriptor::new(
                qmat![[1, 1], [0, 2]],
                qmat![[0, 1], [-1, -1]],
                qmat![[0], [1]],
                qmat![[1, 0]],
                qmat![[0]],
            )
            .unwrap(),
            0,
        ),
        // index 1: x2 algebraic, 0 = x1 - 2 x2 + u
        (
            Descriptor::new(
                qmat![[1, 0], [0, 0]],
                qmat![[-1, 1], [1, -2]],
                qmat![[0], [1]],
                qmat![[1, 1]],
                qmat![[0]],
            )
            .unwrap(),
            1,
        ),
        // index 2, proper: E = diag(1, N), the output sees z_b = -u only
        (
            Descriptor::new(
                qmat![[1, 0, 0], [0, 0, 1], [0, 0, 0]],
                qmat![[-1, 0, 0], [0, 1, 0], [0, 0, 1]],
                qmat![[1], [0], [1]],
                qmat![[1, 0, 1]],
                qmat![[0]],
            )
            .unwrap(),
            2,
        ),
    ]
}

#[test]
fn standard_steps_every_route_over_q() {
    for (sys, route) in descriptors() {
        let der = standard_steps(&sys);
        assert!(der.verified(), "route {route}");
        check_standard(&der, &sys).unwrap_or_else(|e| panic!("route {route}: {e}"));
        let fm = one(&der, StepKind::StandardForm).unwrap();
        assert_eq!(fm.count("route"), Some(route));
        assert_eq!(
            der.of_kind(StepKind::DescriptorEliminate).count(),
            usize::from(route == 1)
        );
        assert_eq!(
            der.of_kind(StepKind::DescriptorFitting).count(),
            usize::from(route == 2)
        );
    }
}

#[test]
fn tampered_standard_steps_are_rejected() {
    for (sys, route) in descriptors() {
        let der = standard_steps(&sys);
        let mut rejected = 0;
        let mut total = 0;
        for (i, st) in der.steps.iter().enumerate() {
            for (j, (key, o)) in st.objects.iter().enumerate() {
                let Object::Matrix(m) = o else { continue };
                if m.nrows() == 0
                    || m.ncols() == 0
                    || [
                        "E", "Er", "Ar", "Br", "Cr", "Dr", "X", "V2", "Bf", "GB", "V1",
                    ]
                    .contains(key)
                {
                    continue;
                }
                total += 1;
                let mut bad = der.clone();
                let Object::Matrix(mm) = &mut bad.steps[i].objects[j].1 else {
                    unreachable!()
                };
                let x = Q.add(mm.get(0, 0), &Q.one());
                mm.set(0, 0, x);
                if check_standard(&bad, &sys).is_err() {
                    rejected += 1;
                }
            }
        }
        assert_eq!(rejected, total, "route {route}");
    }
}

#[test]
fn standard_steps_over_qp() {
    // m x'' + c x' + k x = u with the velocity as an algebraic state: index 1
    let k = RatFuncField::new(&["m", "c", "k"]).unwrap();
    let m = |rows: &[&[&str]]| common::qp_matrix(&k, rows);
    let sys = Descriptor::new(
        m(&[&["1", "0", "0"], &["0", "m", "0"], &["0", "0", "0"]]),
        m(&[&["0", "0", "1"], &["-k", "-c", "0"], &["0", "1", "-1"]]),
        m(&[&["0"], &["1"], &["0"]]),
        m(&[&["1", "0", "0"]]),
        m(&[&["0"]]),
    )
    .unwrap();
    let mut rec = Recorder::with_log(Method::Standard, k.clone(), ratfunc_log(&k));
    descriptor_to_standard_recorded(&sys, Some(&mut rec)).unwrap();
    let der = rec.finish();
    assert!(der.verified());
    check_standard(&der, &sys).unwrap();
    let a_s = one(&der, StepKind::StandardForm)
        .unwrap()
        .matrix("As")
        .unwrap();
    assert_eq!(a_s, &m(&[&["0", "1"], &["-k/m", "-c/m"]]));
    let conds: Vec<String> = der.assumptions().iter().map(|x| k.fmt_elem(x)).collect();
    assert!(conds.contains(&"m".to_string()), "{conds:?}");
}

/// The real Jordan steps of `a`: every expanded pair satisfies A T_c = T_c J_c with the
/// blocks [[a, b], [-b, a]] (I_2 coupling) and the whole T is a real Jordan basis.
fn check_real(d: &Derivation<NumberField>, a: &Matrix<Q>) -> Check {
    for st in d.of_kind(StepKind::RealPair) {
        let (Some(tc), Some(jc)) = (st.matrix("Tc"), st.matrix("Jc")) else {
            ensure(st.count("compact") == Some(1), "a compact pair")?;
            continue;
        };
        let f = tc.field().clone();
        let af = a.map(&f, |x| f.from_rational(x));
        ensure(&af * tc == tc * jc, "A Tc = Tc Jc")?;
        for q in (0..jc.nrows()).step_by(2) {
            ensure(
                jc.get(q, q) == jc.get(q + 1, q + 1)
                    && *jc.get(q + 1, q) == f.neg(jc.get(q, q + 1)),
                "[[a, b], [-b, a]]",
            )?;
        }
        ensure(tc.rank() == tc.ncols(), "independent real columns")?;
    }
    let last = d.steps.last().ok_or("empty")?;
    ensure(last.kind == StepKind::RealForm, "the real T last")?;
    if let (Some(t), Some(j)) = (last.matrix("T"), last.matrix("J")) {
        let f = t.field().clone();
        ensure(&a.map(&f, |x| f.from_rational(x)) * t == t * j, "A T = T J")?;
        ensure(t.rank() == a.nrows(), "T invertible")?;
    }
    Ok(())
}

#[test]
fn real_jordan_steps_vehicle_paper_eq_11_to_14() {
    let a = qmat![[-2, 0, 0], [0, 0, 1], [0, -2, -2]];
    let der = exactlti::jordan::real_steps::real_jordan_steps(&a, false).unwrap();
    assert_eq!(der.method, Method::RealJordan);
    assert!(der.verified());
    check_real(&der, &a).unwrap();
    let pair = one(&der, StepKind::RealPair).unwrap();
    let (tc, jc) = (pair.matrix("Tc").unwrap(), pair.matrix("Jc").unwrap());
    // eq. 12: the block [[-1, 1], [-1, -1]]
    let f = jc.field().clone();
    let want: Vec<i64> = vec![-1, 1, -1, -1];
    for (i, w) in want.iter().enumerate() {
        assert_eq!(*jc.get(i / 2, i % 2), f.from_i64(*w));
    }
    // eq. 13-14: the paper's eigenvector w = (0, -0.41 - 0.41i, 0.82) is c v for ours, v =
    // Re v + i Im v, with |w| = 1 (unit length): w_k v_l = w_l v_k and |w| = 1 to 2 digits
    let ap = tc.to_approx();
    let v: Vec<(f64, f64)> = ap.iter().map(|r| (r[0], r[1])).collect();
    let w = [(0.0, 0.0), (-0.41, -0.41), (0.82, 0.0)];
    let mul = |x: (f64, f64), y: (f64, f64)| (x.0 * y.0 - x.1 * y.1, x.0 * y.1 + x.1 * y.0);
    for (kk, l) in [(1, 2), (0, 1), (0, 2)] {
        let (p, q) = (mul(w[kk], v[l]), mul(w[l], v[kk]));
        let scale = v.iter().map(|z| z.0.abs() + z.1.abs()).fold(0.0, f64::max);
        assert!(
            (p.0 - q.0).abs() < 0.02 * scale && (p.1 - q.1).abs() < 0.02 * scale,
            "{v:?}"
        );
    }
    let norm: f64 = w.iter().map(|z| z.0 * z.0 + z.1 * z.1).sum::<f64>();
    assert!((norm - 1.0).abs() < 0.01);
}

#[test]
fn tampered_real_jordan_steps_are_rejected() {
    let a = qmat![[-2, 0, 0], [0, 0, 1], [0, -2, -2]];
    let der = exactlti::jordan::real_steps::real_jordan_steps(&a, false).unwrap();
    let mut rejected = 0;
    for (i, st) in der.steps.iter().enumerate() {
        if !matches!(st.kind, StepKind::RealPair | StepKind::RealForm) {
            continue;
        }
        for (j, (_, o)) in st.objects.iter().enumerate() {
            let Object::Matrix(m) = o else { continue };
            let f = m.field().clone();
            let mut bad = der.clone();
            let Object::Matrix(mm) = &mut bad.steps[i].objects[j].1 else {
                unreachable!()
            };
            // the last row's first entry: (0, 0) of T scales the eigenvector of -2 (still a
            // Jordan basis)
            let r = mm.nrows() - 1;
            let x = f.add(mm.get(r, 0), &f.one());
            mm.set(r, 0, x);
            if check_real(&bad, &a).is_err() {
                rejected += 1;
            }
        }
    }
    // T_c, J_c of the pair and the whole T, J
    assert_eq!(rejected, 4);
}

#[test]
fn cli_steps_for_mnf_standard_real_and_descriptor_files() {
    let j = json(&[
        "mnf",
        "tests/data/mnf_appendix_b.json",
        "--steps",
        "--format",
        "json",
    ]);
    assert_eq!(j["verified"], true);
    assert_eq!(
        step_names(&j),
        [
            "existence",
            "equation_15",
            "invertible_member",
            "normal_form"
        ]
    );
    assert!(j["field"].as_str().unwrap().contains("w1"));
    let j = json(&[
        "jordan",
        "tests/data/vehicle_eq11.json",
        "--real",
        "--steps",
        "--format",
        "json",
    ]);
    assert_eq!(j["verified"], true);
    assert!(step_names(&j).contains(&"real_pair".to_string()));
    let model = "data/models/spring-mass-damper.toml";
    let j = json(&["standard", model, "--steps", "--format", "json"]);
    assert_eq!(j["verified"], true);
    let names = step_names(&j);
    assert_eq!(names.first().map(String::as_str), Some("compress_e"));
    assert_eq!(names.last().map(String::as_str), Some("standard_form"));
    // a descriptor file through its standard form: the standard steps, then the command's
    for (cmd, last) in [
        ("tf", "entries"),
        ("mnf", "normal_form"),
        ("scb", "zero_dynamics"),
    ] {
        let j = json(&[cmd, model, "--steps", "--format", "json"]);
        assert_eq!(j["verified"], true, "{cmd}");
        let names = step_names(&j);
        assert_eq!(names[0], "compress_e", "{cmd}");
        assert!(names.contains(&"standard_form".to_string()));
        assert_eq!(
            names.last().map(String::as_str),
            Some(last),
            "{cmd}: {names:?}"
        );
    }
    let j = json(&["jordan", model, "--steps", "--format", "json"]);
    assert_eq!(step_names(&j)[0], "compress_e");
    let (code, out, _) = common::cli::run(&["mnf", "tests/data/mnf_appendix_b.json", "--steps"]);
    assert_eq!(code, 0);
    assert!(
        out.contains("already in mechanical normal form: T = I"),
        "{out}"
    );
    let (code, out, _) = common::cli::run(&[
        "standard",
        model,
        "--steps",
        "--format",
        "latex",
        "--standalone",
    ]);
    assert_eq!(code, 0);
    assert!(
        out.starts_with("\\documentclass[11pt,a4paper]{article}") && out.contains("holds exactly")
    );
}

#[test]
fn cli_steps_refusals_for_forms_are_one_line_exit_2() {
    // `jordan --real --steps` over Q(w1, w2) answers now: two pairs, each with its identity
    let j = common::cli::run_json(&[
        "jordan",
        "tests/data/mnf_appendix_b.json",
        "--real",
        "--steps",
    ]);
    assert_eq!(j["verified"], true);
    let pairs: Vec<_> = j["steps"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|s| s["step"] == "real_pair")
        .collect();
    assert_eq!(pairs.len(), 2);
    assert!(pairs.iter().all(|s| s["holds"] == true));
    // `zeros` and `jordan --real` of a descriptor file have steps now
    // (tests/steps_descriptor.rs)
    let args = ["standard", "data/yaw-plane-single-wheel.json", "--steps"];
    let (code, out, err) = common::cli::run(&args);
    assert_eq!(code, 2, "{args:?}: {err}");
    assert!(out.is_empty());
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
}
