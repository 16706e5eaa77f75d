//! `--steps` for `scb`, `zeros`, `tf` and `minreal --method rosenbrock|ho-kalman` (issue 27).
//! Every checker below recomputes the identity of each recorded step from the step's own
//! objects and the input (left null spaces, ranks, the pre-transformation, the SCB relations,
//! the pencil at a point, the resolvent at a point, Markov parameters) without calling the
//! library's step checks; each returns `Err` naming the first identity that fails, so a
//! tampered step is rejected (`tampered_*` tests). Over Q, Q(sqrt 2) and Q(m, k, c).

use crate::common;
use exactlti::field::ElemDisplay;
use exactlti::field::{Field, Q, Rational};
use exactlti::jordan::derivation::{Derivation, Method, Object, Recorder, StepKind, ratfunc_log};
use exactlti::matrix::Matrix;
use exactlti::poly::Poly;
use exactlti::realization::{
    mcmillan_degree, minimal_ho_kalman_recorded, minimal_rosenbrock_recorded,
};
use exactlti::structure::scb::{Pattern, check_pattern, scb_recorded};
use exactlti::structure::zeros::{invariant_zeros_recorded, invariant_zeros_smith};
use exactlti::system::StateSpace;

type Check = Result<(), String>;

fn ensure(ok: bool, what: &str) -> Check {
    if ok { Ok(()) } else { Err(what.to_string()) }
}

fn mat<'s, K: Field>(s: &'s exactlti::jordan::derivation::Step<K>, key: &str) -> &'s Matrix<K> {
    s.matrix(key)
        .unwrap_or_else(|| panic!("{:?} has no {key}", s.kind))
}

/// Non-pivot columns of the RREF of `m` (the paper's leading-one deletion rule).
fn non_leading<K: Field>(m: &Matrix<K>) -> Vec<usize> {
    let (_, piv) = m.rref();
    (0..m.ncols()).filter(|c| !piv.contains(c)).collect()
}

/// `s` is a basis of the left null space of `m`.
fn left_null<K: Field>(s: &Matrix<K>, m: &Matrix<K>, what: &str) -> Check {
    ensure(s.ncols() == m.nrows(), what)?;
    ensure((s * m).is_zero(), &format!("{what}: S M != 0"))?;
    ensure(s.rank() == s.nrows(), &format!("{what}: dependent rows"))?;
    ensure(
        s.nrows() == m.nrows() - m.rank(),
        &format!("{what}: not the whole left null space"),
    )
}

/// Checks every SCB step of `d` against the input `(A, B, C, D)`; returns the SCB dims.
fn check_scb<K: Field>(d: &Derivation<K>, abcd: [&Matrix<K>; 4]) -> Result<[usize; 4], String> {
    let [a, b, c, dd] = abcd;
    let k = a.field().clone();
    let (n, m, p) = (a.nrows(), b.ncols(), c.nrows());
    let pre = d
        .of_kind(StepKind::ScbPreTransform)
        .next()
        .ok_or("no pre-transformation")?;
    let (u, yinv) = (mat(pre, "U"), mat(pre, "Yinv"));
    let m0 = pre.count("m0").ok_or("m0")?;
    let dh = &(yinv * dd) * u;
    let mut want = Matrix::zeros(k.clone(), p, m);
    for i in 0..m0 {
        want.set(i, i, k.one());
    }
    ensure(
        dh == want && *mat(pre, "Dh") == dh,
        "Y^-1 D U != diag(I, 0)",
    )?;
    let (bh, ch) = (b * u, yinv * c);
    let a1 = a - &(&bh.submatrix(0, n, 0, m0) * &ch.submatrix(0, m0, 0, n));
    let (b1, c1) = (bh.submatrix(0, n, m0, m), ch.submatrix(m0, p, 0, n));
    ensure(
        *mat(pre, "A1") == a1 && *mat(pre, "B1") == b1 && *mat(pre, "C1") == c1,
        "A1 != A - B0 C0",
    )?;
    // the chain of custody between the levels: C_1 = the outputs, Dbar = Bottoms B,
    // Bottoms_i = Bottoms_{i-1} + the ending rows of C_{i-1}, Cbar = (S_ib Bottoms + S_i2 C_i) A,
    // C_{i+1} = the continuing rows of Cbar
    let ss: Vec<_> = d.of_kind(StepKind::SilvermanS).collect();
    let phis: Vec<_> = d.of_kind(StepKind::SilvermanPhi).collect();
    for (lvl, s) in ss.iter().enumerate() {
        let (ci, mm, sm, bot) = (mat(s, "Ci"), mat(s, "M"), mat(s, "S"), mat(s, "Bottoms"));
        ensure(s.count("level") == Some(lvl + 1), "levels out of order")?;
        let q = bot.nrows();
        ensure(mm.nrows() == q + ci.nrows(), "M's shape")?;
        ensure(
            *mm == (bot * &b1).vstack(&(ci * &b1)).unwrap(),
            "M != [Bottoms B; C_i B]",
        )?;
        if lvl == 0 {
            ensure(ci == &c1 && q == 0, "level 1: C_1 != the outputs")?;
        } else {
            let (prev, pphi) = (ss[lvl - 1], phis.get(lvl - 1).ok_or("no phi step")?);
            let ended = mat(prev, "Ci").select_rows(prev.counts("ending").unwrap());
            ensure(
                *bot == mat(prev, "Bottoms").vstack(&ended).unwrap(),
                "Bottoms",
            )?;
            let cont = mat(pphi, "Cbar").select_rows(pphi.counts("going_on").unwrap());
            ensure(*ci == cont, "C_i != the continuing rows of Cbar")?;
        }
        left_null(sm, mm, "S_i")?;
        let s2 = sm.submatrix(0, sm.nrows(), q, sm.ncols());
        ensure(
            s.counts("ending") == Some(non_leading(&s2).as_slice()),
            "S_i1 != the deletion rule",
        )?;
        let Some(ph) = phis.get(lvl) else { continue };
        let tops = &(&sm.submatrix(0, sm.nrows(), 0, q) * bot) + &(&s2 * ci);
        let (rows, cbar, phi) = (mat(ph, "Rows"), mat(ph, "Cbar"), mat(ph, "Phi"));
        ensure(*cbar == &tops * &a1, "Cbar != (S_ib Bottoms + S_i2 C_i) A")?;
        // every row found is a combination of the output derivatives C_1 A_1^j, j < i
        let mut kry = c1.clone();
        let mut blk = c1.clone();
        for _ in 1..=lvl {
            blk = &blk * &a1;
            kry = kry.vstack(&blk).unwrap();
        }
        ensure(
            kry.vstack(rows).unwrap().rank() == kry.rank(),
            "rows found outside the output derivatives",
        )?;
        let all = rows.vstack(&tops).unwrap().vstack(bot).unwrap();
        ensure(
            rows.rank() == rows.nrows() && all.rank() == rows.nrows(),
            "rows found: dependent or missing the chains",
        )?;
        left_null(phi, &rows.vstack(cbar).unwrap(), "Phi_i")?;
        let p2 = phi.submatrix(0, phi.nrows(), rows.nrows(), phi.ncols());
        ensure(
            ph.counts("going_on") == Some(non_leading(&p2).as_slice()),
            "continuing chains != the deletion rule",
        )?;
    }
    let st = d.of_kind(StepKind::ScbStates).next().ok_or("no x_s step")?;
    let (ts, x, g3) = (mat(st, "Ts"), mat(st, "X"), mat(st, "G3"));
    let md = st.count("md").ok_or("md")?;
    let tbg = &(ts * &b1) * g3;
    ensure(
        tbg.submatrix(0, ts.nrows(), 0, md).is_zero(),
        "x_s still driven by u_d",
    )?;
    let rest = &(ts * &a1) - &(x * ts);
    ensure(
        c1.vstack(&rest).unwrap().rank() == c1.rank(),
        "x_s' depends on more than x_s and the outputs",
    )?;
    let sp = d
        .of_kind(StepKind::ScbKalmanSplit)
        .next()
        .ok_or("no split")?;
    let (bsc, ctr, pp) = (mat(sp, "Bsc"), mat(sp, "Ctr"), mat(sp, "P"));
    let na = sp.count("na").ok_or("na")?;
    let ns = x.nrows();
    ensure(
        *bsc == tbg.submatrix(0, ns, md, tbg.ncols()),
        "B_sc != the u_c columns",
    )?;
    let mut kry = bsc.clone();
    let mut blk = bsc.clone();
    for _ in 1..ns.max(1) {
        blk = x * &blk;
        kry = kry.hstack(&blk).unwrap();
    }
    ensure(&kry == ctr, "C_ctr != [B_sc, X B_sc, ...]")?;
    let pinv = pp.inverse().map_err(|_| "P singular")?;
    let xt = &(&pinv * x) * pp;
    ensure(
        xt.submatrix(0, na, na, ns).is_zero()
            && (&pinv * bsc).submatrix(0, na, 0, bsc.ncols()).is_zero(),
        "x_a reached by u_c",
    )?;
    ensure(ns - na == ctr.rank(), "n_c != rank C_ctr")?;
    let f = d.of_kind(StepKind::ScbForm).next().ok_or("no SCB")?;
    let [sa, sb, sc, sd] = ["A", "B", "C", "D"].map(|key| mat(f, key));
    let [g1, g2, g3f] = ["Gamma1", "Gamma2", "Gamma3"].map(|key| mat(f, key));
    ensure(
        g1 * sa == &a1 * g1 && g1 * sb == &bh * g3f,
        "Gamma1 A_s != A1 Gamma1",
    )?;
    ensure(
        g2 * sc == &ch * g1 && g2 * sd == &dh * g3f,
        "Gamma2 C_s != C^ Gamma1",
    )?;
    let dims: [usize; 4] = f.counts("dims").ok_or("dims")?.try_into().unwrap();
    let pat = Pattern {
        dims,
        chains: f.counts("chains").ok_or("chains")?.to_vec(),
        m0,
    };
    check_pattern(sa, sb, sc, sd, &pat).map_err(|e| e.to_string())?;
    ensure(dims[0] == na, "n_a disagrees")?;
    // T = Gamma1^-1 = [T_a; T_b; T_c; T_d]: [T_a; T_c] = P^-1 T_s, T_s - T_s^0 in row [T_b; T_d]
    let t = g1.inverse().map_err(|_| "Gamma1 singular")?;
    let [ra, rb, rc, rd] = [0, 1, 2, 3].map(|i| {
        let s0: usize = dims[..i].iter().sum();
        t.submatrix(s0, s0 + dims[i], 0, n)
    });
    ensure(
        ra.vstack(&rc).unwrap() == &pinv * ts,
        "[T_a; T_c] != P^-1 T_s",
    )?;
    let tbd = rb.vstack(&rd).unwrap();
    let ts0 = mat(st, "Ts0");
    ensure(
        (0..ts0.nrows()).all(|i| {
            let row = ts0.row(i);
            row.iter().filter(|x| k.is_one(x)).count() == 1
                && row.iter().filter(|x| !k.is_zero(x)).count() == 1
        }) && ts0.vstack(&tbd).unwrap().rank() == n,
        "T_s^0 is not unit rows completing [T_b; T_d]",
    )?;
    let diff = ts - ts0;
    ensure(
        tbd.vstack(&diff).unwrap().rank() == tbd.rank(),
        "T_s - T_s^0 not in the row space of [T_b; T_d]",
    )?;
    ensure(g3f.submatrix(m0, m, m0, m) == *g3, "Gamma_3 != diag(I, G3)")?;
    let zd = d
        .of_kind(StepKind::ZeroDynamics)
        .next()
        .ok_or("no zero dynamics")?;
    let aaa = mat(zd, "Aaa");
    ensure(
        *aaa == sa.submatrix(0, na, 0, na),
        "A_aa is not the x_a block",
    )?;
    ensure(
        zd.poly("z") == Some(&aaa.charpoly().unwrap()),
        "z != det(sI - A_aa)",
    )?;
    Ok(dims)
}

fn recorded_scb<K: Field>(abcd: [&Matrix<K>; 4]) -> Derivation<K> {
    let [a, b, c, d] = abcd;
    let mut rec = Recorder::new(Method::Scb, a.field().clone());
    let s = scb_recorded(a, b, c, d, Some(&mut rec)).unwrap();
    let der = rec.finish();
    assert_eq!(
        der.of_kind(StepKind::ScbForm)
            .next()
            .unwrap()
            .counts("dims"),
        Some(&s.dims[..])
    );
    der
}

/// A random system over `k` (generator element `g`) with `[B; D]` of full column rank and
/// `[C, D]` of full row rank, or `None`.
fn random_system<K: Field>(k: &K, g: &Option<K::Elem>, seed: u64) -> Option<[Matrix<K>; 4]> {
    let mut rng = common::Rng(seed);
    let n = 2 + (seed as usize % 5);
    let m = 1 + (seed as usize / 5) % 3;
    let p = 1 + (seed as usize / 15) % 3;
    let a = common::random_matrix(k, g, n, n, &mut rng);
    let b = common::random_matrix(k, g, n, m, &mut rng);
    let c = common::random_matrix(k, g, p, n, &mut rng);
    let d = if seed.is_multiple_of(3) {
        common::random_matrix(k, g, p, m, &mut rng)
    } else {
        Matrix::zeros(k.clone(), p, m)
    };
    let ok = b.vstack(&d).unwrap().rank() == m && c.hstack(&d).unwrap().rank() == p;
    ok.then_some([a, b, c, d])
}

#[test]
fn scb_steps_identities_over_q_and_sqrt2() {
    let (k2, g2) = common::qsqrt2();
    let mut checked = 0;
    for seed in 0..common::iters(40) as u64 {
        if let Some(s) = random_system(&Q, &None, seed) {
            let abcd = [&s[0], &s[1], &s[2], &s[3]];
            let d = recorded_scb(abcd);
            assert!(d.verified(), "seed {seed}");
            check_scb(&d, abcd).unwrap_or_else(|e| panic!("seed {seed}: {e}"));
            checked += 1;
        }
        if seed.is_multiple_of(4)
            && let Some(s) = random_system(&k2, &g2, seed)
        {
            let abcd = [&s[0], &s[1], &s[2], &s[3]];
            check_scb(&recorded_scb(abcd), abcd).unwrap_or_else(|e| panic!("sqrt2 {seed}: {e}"));
        }
    }
    assert!(checked >= 20, "{checked}");
}

#[test]
fn scb_steps_double_integrator_chain() {
    // one chain of length 2: level 1 continues, level 2 ends
    let a = exactlti::qmat![[0, 1], [0, 0]];
    let (b, c, d) = (
        exactlti::qmat![[0], [1]],
        exactlti::qmat![[1, 0]],
        exactlti::qmat![[0]],
    );
    let der = recorded_scb([&a, &b, &c, &d]);
    let s: Vec<_> = der.of_kind(StepKind::SilvermanS).collect();
    assert_eq!(s.len(), 2);
    assert_eq!(s[0].counts("ending"), Some(&[][..]));
    assert_eq!(s[1].counts("ending"), Some(&[0usize][..]));
    assert_eq!(check_scb(&der, [&a, &b, &c, &d]), Ok([0, 0, 0, 2]));
}

#[test]
fn scb_and_zeros_steps_over_qp_with_conditions() {
    let sys = common::systems::chain_qp(2);
    let k = sys.field().fresh();
    let mv =
        |m: &Matrix<_>| Matrix::from_vec(k.clone(), m.nrows(), m.ncols(), m.as_slice().to_vec());
    let (a, b, c, d) = (mv(&sys.a), mv(&sys.b), mv(&sys.c), mv(&sys.d));
    let mut rec = Recorder::with_log(Method::Scb, k.clone(), ratfunc_log(&k));
    scb_recorded(&a, &b, &c, &d, Some(&mut rec)).unwrap();
    let der = rec.finish();
    assert!(der.verified());
    // force on mass 1, position of mass 2: G = (c s + k) / (...), relative degree 3, one zero
    assert_eq!(check_scb(&der, [&a, &b, &c, &d]), Ok([1, 0, 0, 3]));
    let z = der
        .of_kind(StepKind::ZeroDynamics)
        .next()
        .unwrap()
        .poly("z")
        .unwrap();
    assert_eq!(z.to_string_var("s"), "s + k/c");
    let conds: Vec<String> = der.assumptions().iter().map(|x| k.fmt_elem(x)).collect();
    assert!(conds.iter().any(|c| c == "m" || c == "k"), "{conds:?}");
    let dz = recorded_zeros([&a, &b, &c, &d]);
    check_zeros(&dz, [&a, &b, &c, &d]).unwrap();
}

#[test]
fn tampered_scb_steps_are_rejected() {
    // an unobservable mode (state 5), so that the output derivatives do not span the space
    let s = [
        exactlti::qmat![
            [0, 1, 0, 0, 0],
            [0, 0, 1, 0, 0],
            [1, 2, 3, 1, 0],
            [1, 0, 0, -1, 0],
            [1, 1, 0, 0, -2]
        ],
        exactlti::qmat![[0, 0], [0, 1], [1, 0], [0, 0], [1, 1]],
        exactlti::qmat![[1, 0, 0, 0, 0], [0, 0, 0, 1, 0]],
        exactlti::qmat![[0, 0], [0, 0]],
    ];
    let abcd = [&s[0], &s[1], &s[2], &s[3]];
    let d = recorded_scb(abcd);
    check_scb(&d, abcd).unwrap();
    let mut tampered = 0;
    for (i, st) in d.steps.iter().enumerate() {
        for (j, (key, o)) in st.objects.iter().enumerate() {
            let Object::Matrix(m) = o else { continue };
            if m.nrows() == 0 || m.ncols() == 0 {
                continue;
            }
            let mut bad = d.clone();
            let mut mm = m.clone();
            if *key == "Rows" {
                // the rows found are checked through their span (in the output derivatives,
                // containing the chains' tops and bottoms): move row 0 out of the output
                // derivatives' span (the observability rows)
                let n = m.ncols();
                let obs = exactlti::realization::observability_matrix(&s[0], &s[2]);
                let Some(e) = (0..n)
                    .map(|j| Matrix::from_fn(Q, 1, n, |_, c| Q.from_i64(i64::from(c == j))))
                    .find(|e| obs.vstack(e).unwrap().rank() > obs.rank())
                else {
                    continue;
                };
                for c in 0..n {
                    mm.set(0, c, Q.add(mm.get(0, c), e.get(0, c)));
                }
            } else {
                let v = Q.add(mm.get(0, 0), &Rational::from_integer(1.into()));
                mm.set(0, 0, v);
            }
            bad.steps[i].objects[j].1 = Object::Matrix(mm);
            assert!(
                check_scb(&bad, abcd).is_err(),
                "step {i} {:?} {key}",
                st.kind
            );
            tampered += 1;
        }
    }
    assert!(tampered >= 15, "{tampered}");
}

fn recorded_zeros<K: Field>(abcd: [&Matrix<K>; 4]) -> Derivation<K> {
    let [a, b, c, d] = abcd;
    let mut rec = Recorder::new(Method::Zeros, a.field().clone());
    invariant_zeros_recorded(a, b, c, d, Some(&mut rec)).unwrap();
    rec.finish()
}

/// Checks the zeros steps: compression, pencil, the SCB of the compressed system, normal rank,
/// and the result against the polynomial diagonal form (the independent oracle).
fn check_zeros<K: Field>(d: &Derivation<K>, abcd: [&Matrix<K>; 4]) -> Check {
    let [a, b, c, dd] = abcd;
    let k = a.field().clone();
    let n = a.nrows();
    let cp = d
        .of_kind(StepKind::ZerosCompress)
        .next()
        .ok_or("no compression")?;
    let (cols, rows) = (cp.counts("cols").unwrap(), cp.counts("rows").unwrap());
    let bd = b.vstack(dd).unwrap();
    let cd = c.hstack(dd).unwrap();
    ensure(cols == bd.pivots().as_slice(), "cols != pivots of [B; D]")?;
    ensure(
        rows == cd.transpose().pivots().as_slice(),
        "rows != pivots of [C, D]",
    )?;
    ensure(
        bd.select_cols(cols).rank() == bd.rank(),
        "kept columns lose rank",
    )?;
    let pe = d
        .of_kind(StepKind::SystemPencil)
        .next()
        .ok_or("no pencil")?;
    let (p0, e) = (mat(pe, "P0"), mat(pe, "E"));
    let top = a.hstack(b).unwrap();
    ensure(*p0 == top.vstack(&cd).unwrap(), "P0 != [A B; C D]")?;
    ensure(
        (0..e.nrows()).all(|i| {
            (0..e.ncols()).all(|j| *e.get(i, j) == if i == j && i < n { k.one() } else { k.zero() })
        }),
        "E != diag(I, 0)",
    )?;
    let (bc, dc) = (b.select_cols(cols), dd.select_cols(cols).select_rows(rows));
    let cc = c.select_rows(rows);
    check_scb(d, [a, &bc, &cc, &dc])?;
    let nr = d
        .of_kind(StepKind::NormalRank)
        .next()
        .ok_or("no normal rank")?;
    let s0 = nr.scalar("s0").ok_or("s0")?;
    let z = nr.poly("z").ok_or("z")?;
    let ps0 = p0.try_sub(&e.scale(s0)).unwrap();
    ensure(*mat(nr, "Ps0") == ps0, "P(s0) != P0 - s0 E")?;
    ensure(!k.is_zero(&z.eval(s0)), "z(s0) = 0")?;
    ensure(
        nr.count("rank") == Some(ps0.rank()),
        "rank P(s0) recomputed differs",
    )?;
    let zd = d
        .of_kind(StepKind::ZeroDynamics)
        .next()
        .ok_or("no zero dynamics")?;
    ensure(
        zd.poly("z").map(|p| p.monic()).as_ref() == Some(z),
        "z != monic det(sI - A_aa)",
    )?;
    let oracle = invariant_zeros_smith(a, b, c, dd).unwrap();
    ensure(oracle.polynomial == *z, "z != the Smith-form oracle")?;
    ensure(
        Some(oracle.normal_rank) == nr.count("rank"),
        "normal rank != the oracle",
    )
}

#[test]
fn zeros_steps_identities_including_redundant_inputs() {
    let mut checked = 0;
    for seed in 0..common::iters(30) as u64 {
        let mut rng = common::Rng(seed + 7);
        let n = 2 + (seed as usize % 4);
        let (m, p) = (1 + seed as usize % 3, 1 + (seed as usize / 3) % 3);
        let a = common::random_matrix(&Q, &None, n, n, &mut rng);
        let mut b = common::random_matrix(&Q, &None, n, m, &mut rng);
        if seed.is_multiple_of(2) {
            // a redundant input: the compression step removes it
            b = b
                .hstack(&b.select_cols(&[0]).scale(&Rational::from_integer(2.into())))
                .unwrap();
        }
        let c = common::random_matrix(&Q, &None, p, n, &mut rng);
        let d = Matrix::zeros(Q, p, b.ncols());
        let abcd = [&a, &b, &c, &d];
        let der = recorded_zeros(abcd);
        assert!(der.verified(), "seed {seed}");
        check_zeros(&der, abcd).unwrap_or_else(|e| panic!("seed {seed}: {e}"));
        checked += 1;
    }
    assert!(checked > 0);
}

#[test]
fn tampered_zeros_steps_are_rejected() {
    // G(s) = (s + 2) / (s^2 + 3 s + 1)
    let (a, b) = (exactlti::qmat![[0, 1], [-1, -3]], exactlti::qmat![[0], [1]]);
    let (c, d) = (exactlti::qmat![[2, 1]], exactlti::qmat![[0]]);
    let abcd = [&a, &b, &c, &d];
    let der = recorded_zeros(abcd);
    check_zeros(&der, abcd).unwrap();
    let nr = der.of_kind(StepKind::NormalRank).next().unwrap();
    assert_eq!(nr.poly("z").unwrap().to_string(), "x + 2");
    assert_eq!(nr.count("rank"), Some(3));
    for key in ["z", "rank", "s0"] {
        let mut bad = der.clone();
        let i = bad
            .steps
            .iter()
            .position(|s| s.kind == StepKind::NormalRank)
            .unwrap();
        let o = &mut bad.steps[i]
            .objects
            .iter_mut()
            .find(|(k, _)| *k == key)
            .unwrap()
            .1;
        *o = match o {
            Object::Poly(_) => Object::Poly(Poly::new(
                Q,
                vec![
                    Rational::from_integer(3.into()),
                    Rational::from_integer(1.into()),
                ],
            )),
            Object::Count(r) => Object::Count(*r - 1),
            _ => Object::Scalar(Rational::from_integer((-2).into())),
        };
        assert!(check_zeros(&bad, abcd).is_err(), "{key}");
    }
}

/// Checks the transfer-matrix steps: chi, the Markov parameters, the numerators at points
/// (the resolvent solved independently) and the entries by cross-multiplication.
fn check_tf<K: Field>(d: &Derivation<K>, s: &StateSpace<K>) -> Check {
    let k = s.field().clone();
    let n = s.nstates();
    let (p, m) = (s.noutputs(), s.ninputs());
    let cp = d.of_kind(StepKind::CharPoly).next().ok_or("no chi")?;
    let chi = cp.poly("chi").ok_or("chi")?;
    ensure(*chi == s.a.charpoly().unwrap(), "chi != det(sI - A)")?;
    let mk = d.of_kind(StepKind::Markov).next().ok_or("no Markov")?;
    let h = mat(mk, "H");
    let mut ab = s.b.clone();
    for j in 0..n {
        ensure(
            h.submatrix(0, p, j * m, (j + 1) * m) == &s.c * &ab,
            "h_j != C A^j B",
        )?;
        ab = &s.a * &ab;
    }
    let nu = d
        .of_kind(StepKind::Numerators)
        .next()
        .ok_or("no numerators")?;
    let num = nu.polys("N").ok_or("N")?;
    let mut tried = 0;
    for x in -3..=3i64 {
        let x = k.from_i64(x);
        if k.is_zero(&chi.eval(&x)) || n == 0 {
            continue;
        }
        let r = Matrix::identity(k.clone(), n)
            .scale(&x)
            .try_sub(&s.a)
            .unwrap();
        let (sol, _) = r.solve(&s.b).unwrap().ok_or("singular")?;
        let g = (&s.c * &sol).scale(&chi.eval(&x));
        for (i, ni) in num.iter().enumerate().take(p * m) {
            ensure(
                ni.eval(&x) == *g.get(i / m, i % m),
                "N(s0) != chi C (s0 I - A)^-1 B",
            )?;
        }
        tried += 1;
    }
    ensure(n == 0 || tried > 0, "no point")?;
    let en = d
        .of_kind(StepKind::TransferEntries)
        .next()
        .ok_or("no entries")?;
    let (nums, dens) = (en.polys("num").ok_or("num")?, en.polys("den").ok_or("den")?);
    for i in 0..p * m {
        let full = num[i].add(&chi.scale(s.d.get(i / m, i % m)));
        ensure(
            nums[i].mul(chi) == dens[i].mul(&full),
            "G_ij chi != N_ij + D_ij chi",
        )?;
        ensure(k.is_one(&dens[i].lc()), "denominator not monic")?;
        ensure(
            nums[i].gcd(&dens[i]).deg() == 0 || nums[i].is_zero(),
            "not in lowest terms",
        )?;
    }
    Ok(())
}

fn recorded_tf<K: Field>(s: &StateSpace<K>) -> Derivation<K> {
    let mut rec = Recorder::new(Method::Transfer, s.field().clone());
    s.transfer_matrix_recorded(Some(&mut rec)).unwrap();
    rec.finish()
}

#[test]
fn tf_steps_identities_and_tampering() {
    let (k2, g2) = common::qsqrt2();
    for seed in 0..common::iters(20) as u64 {
        if let Some([a, b, c, d]) = random_system(&Q, &None, seed) {
            let s = StateSpace::new(a, b, c, d).unwrap();
            let der = recorded_tf(&s);
            assert!(der.verified(), "seed {seed}");
            check_tf(&der, &s).unwrap_or_else(|e| panic!("seed {seed}: {e}"));
            // a tampered numerator coefficient or Markov parameter is rejected
            let mut bad = der.clone();
            let i = bad
                .steps
                .iter()
                .position(|s| s.kind == StepKind::Numerators)
                .unwrap();
            if let Object::Polys(ps) = &mut bad.steps[i].objects[0].1 {
                ps[0] = ps[0].add(&Poly::one(Q));
            }
            assert!(check_tf(&bad, &s).is_err());
        }
        if let Some([a, b, c, d]) = random_system(&k2, &g2, seed + 100) {
            let s = StateSpace::new(a, b, c, d).unwrap();
            check_tf(&recorded_tf(&s), &s).unwrap();
        }
    }
    let s = common::systems::chain_qp(2);
    let der = recorded_tf(&s);
    assert!(der.verified());
    check_tf(&der, &s).unwrap();
}

/// Checks the Rosenbrock steps: each staircase's similarity and zero pattern, the minimal
/// part's Markov parameters and order.
fn check_minimal_part<K: Field>(d: &Derivation<K>, s: &StateSpace<K>) -> Check {
    let mp = d
        .of_kind(StepKind::MinimalPart)
        .next()
        .ok_or("no minimal part")?;
    let min = StateSpace::new(
        mat(mp, "Am").clone(),
        mat(mp, "Bm").clone(),
        mat(mp, "Cm").clone(),
        s.d.clone(),
    )
    .map_err(|e| e.to_string())?;
    let kk = 2 * s.nstates() + 2;
    ensure(s.markov(kk) == min.markov(kk), "Markov parameters differ")?;
    ensure(
        min.nstates() == mcmillan_degree(s),
        "order != McMillan degree",
    )
}

fn check_staircase<K: Field>(
    st: &exactlti::jordan::derivation::Step<K>,
    s: &StateSpace<K>,
) -> Check {
    let (t, at, bt, ct) = (mat(st, "T"), mat(st, "At"), mat(st, "Bt"), mat(st, "Ct"));
    let n = s.nstates();
    let u = n - st.count("k").ok_or("k")?;
    ensure(
        &s.a * t == t * at && s.b == t * bt && *ct == &s.c * t,
        "not a similarity",
    )?;
    ensure(t.rank() == n, "T singular")?;
    ensure(
        at.submatrix(0, u, u, n).is_zero() && bt.submatrix(0, u, 0, bt.ncols()).is_zero(),
        "pattern",
    )
}

#[test]
fn rosenbrock_and_ho_kalman_steps_on_planted_systems() {
    for seed in 0..common::iters(6) as u64 {
        let pl = common::systems::planted(4 + 2 * (seed as usize % 3), seed);
        let s = &pl.sys;
        let mut rec = Recorder::new(Method::Rosenbrock, Q);
        minimal_rosenbrock_recorded(s, Some(&mut rec)).unwrap();
        let d = rec.finish();
        assert!(d.verified(), "seed {seed}");
        let st: Vec<_> = d.of_kind(StepKind::Staircase).collect();
        assert_eq!(st.len(), 2);
        check_staircase(st[0], s).unwrap();
        check_minimal_part(&d, s).unwrap();
        // the dual staircase on the controllable part
        let k = st[0].count("k").unwrap();
        let n = s.nstates();
        let (at, bt, ct) = (mat(st[0], "At"), mat(st[0], "Bt"), mat(st[0], "Ct"));
        let ctrl = StateSpace::new(
            at.submatrix(n - k, n, n - k, n),
            bt.submatrix(n - k, n, 0, bt.ncols()),
            ct.submatrix(0, ct.nrows(), n - k, n),
            s.d.clone(),
        )
        .unwrap();
        check_staircase(st[1], &ctrl.dual()).unwrap();
        assert_eq!(mcmillan_degree(s), pl.order);

        let mut rec = Recorder::new(Method::HoKalman, Q);
        minimal_ho_kalman_recorded(s, Some(&mut rec)).unwrap();
        let d = rec.finish();
        assert!(d.verified());
        let h = d.of_kind(StepKind::Hankel).next().unwrap();
        let h0 = exactlti::realization::hankel_matrix(s, n, n, 0);
        assert_eq!(mat(h, "H"), &h0);
        assert_eq!(h.count("rank"), Some(h0.rank()));
        let f = d.of_kind(StepKind::HankelFactor).next().unwrap();
        assert_eq!(mat(f, "L") * mat(f, "R"), h0);
        assert_eq!(
            mat(f, "H1"),
            &exactlti::realization::hankel_matrix(s, n, n, 1)
        );
        check_minimal_part(&d, s).unwrap();
        let mut bad = d.clone();
        let i = bad
            .steps
            .iter()
            .position(|s| s.kind == StepKind::MinimalPart)
            .unwrap();
        bad.steps[i].objects[0].1 =
            Object::Matrix(mat(f, "Am").scale(&Rational::from_integer(2.into())));
        assert!(check_minimal_part(&bad, s).is_err() || mat(f, "Am").is_zero());
    }
}

fn json(args: &[&str]) -> serde_json::Value {
    common::cli::json_of(args)
}

#[test]
fn cli_steps_for_scb_zeros_tf_minreal() {
    let f = "data/yaw-plane-single-wheel.json";
    for (args, first) in [
        (vec!["scb", f], "pre_transformation"),
        (vec!["zeros", f], "compress"),
        (vec!["tf", f], "charpoly"),
        (vec!["minreal", f, "--method", "rosenbrock"], "staircase"),
        (vec!["minreal", f, "--method", "ho-kalman"], "hankel"),
    ] {
        for sym in [false, true] {
            let mut a = args.clone();
            a.extend(["--steps", "--format", "json"]);
            if sym {
                a.push("--symbolic");
            }
            let j = json(&a);
            assert_eq!(j["verified"], true, "{a:?}");
            let steps = j["steps"].as_array().unwrap();
            assert_eq!(steps[0]["step"], first, "{a:?}");
            assert!(
                steps
                    .iter()
                    .all(|s| s.get("holds").is_none_or(|h| h == true))
            );
            if sym && matches!(args[0], "scb" | "zeros") {
                assert_eq!(j["conditions"], serde_json::json!(["u != 0"]), "{a:?}");
            }
        }
    }
    let (code, out, _) =
        common::cli::run(&["zeros", f, "--steps", "--format", "latex", "--standalone"]);
    assert_eq!(code, 0);
    assert!(out.starts_with("\\documentclass[11pt,a4paper]{article}"));
    assert!(out.contains("holds exactly") && !out.contains("FAILS"));
    let (code, out, _) = common::cli::run(&["scb", "tests/data/sqrt2.toml", "--steps"]);
    assert_eq!(code, 0, "{out}");
    assert!(out.contains("special coordinate basis"), "{out}");
}

/// Rosenbrock and Ho-Kalman steps over Q(m, k, c) (the chain of two masses): the staircase's
/// similarity and zero pattern, the Hankel factorization and the minimal part's Markov
/// parameters recomputed, with the conditions recorded (issue 27 Done-when over Q(p)).
#[test]
fn rosenbrock_and_ho_kalman_steps_over_qp() {
    use exactlti::jordan::derivation::ratfunc_log;
    let s0 = common::systems::chain_qp(2);
    let k = s0.field().fresh();
    let m = |x: &Matrix<exactlti::ratfunc::RatFuncField>| {
        Matrix::from_vec(k.clone(), x.nrows(), x.ncols(), x.as_slice().to_vec())
    };
    let s = StateSpace::new(m(&s0.a), m(&s0.b), m(&s0.c), m(&s0.d)).unwrap();
    let n = s.nstates();
    let mut rec = Recorder::with_log(Method::Rosenbrock, k.clone(), ratfunc_log(&k));
    minimal_rosenbrock_recorded(&s, Some(&mut rec)).unwrap();
    let d = rec.finish();
    assert!(d.verified());
    let st: Vec<_> = d.of_kind(StepKind::Staircase).collect();
    assert!(!st.is_empty());
    check_staircase(st[0], &s).unwrap();
    check_minimal_part(&d, &s).unwrap();
    let mut rec = Recorder::with_log(Method::HoKalman, k.clone(), ratfunc_log(&k));
    minimal_ho_kalman_recorded(&s, Some(&mut rec)).unwrap();
    let d = rec.finish();
    assert!(d.verified());
    let h = d.of_kind(StepKind::Hankel).next().unwrap();
    let h0 = exactlti::realization::hankel_matrix(&s, n, n, 0);
    assert_eq!(mat(h, "H"), &h0);
    let f = d.of_kind(StepKind::HankelFactor).next().unwrap();
    assert_eq!(mat(f, "L") * mat(f, "R"), h0);
    check_minimal_part(&d, &s).unwrap();
}
