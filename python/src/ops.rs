//! The exact operations on a system over its (numeric) ground field, as plain output data.

use crate::out::*;
use crate::values::{Grid, elem, part, values_of, zero};
use crate::{FResult, Fail};
use exactlti::field::Field;
use exactlti::io::TypedSystem as Typed;
use exactlti::jordan::{EigenField, JordanForm, RealEntries, RealJordanForm};
use exactlti::matrix::Matrix;
use exactlti::realization::{self, MinrealMethod};
use exactlti::system::StateSpace;
use exactlti::system::discrete::stability::Domain;

pub(crate) fn typed_system<K: Field>(t: &Typed<K>) -> Out {
    let s = &t.ss;
    Out::Dict(vec![
        ("A", mat(&s.a)),
        ("B", mat(&s.b)),
        ("C", mat(&s.c)),
        ("D", mat(&s.d)),
        (
            "E",
            t.descriptor
                .as_ref()
                .map(|d| mat(&d.e))
                .unwrap_or(Out::None),
        ),
        (
            "descriptor_A",
            t.descriptor
                .as_ref()
                .map(|d| mat(&d.a))
                .unwrap_or(Out::None),
        ),
    ])
}

/// A minimal realization by the method `m` through the library's one entry point
/// ([`realization::minimal`], as the command line's `minreal --method`): by the Jordan-form
/// method over a field with certified eigenvalues the modal form ([`modal_out`]), else the
/// system over the field.
pub(crate) fn minreal_typed<K: realization::SystemField>(
    t: &Typed<K>,
    m: MinrealMethod,
) -> FResult<Out> {
    let r = realization::minimal(&t.ss, m)?;
    if let Some(realization::JordanMethod::Modal(jm)) = &r.jordan {
        return Ok(modal_out(jm, &r));
    }
    let sys = system_out(Typed {
        descriptor: None,
        a_raw: r.system.a.clone(),
        ss: r.system.clone(),
    });
    Ok(Out::Dict(vec![
        ("system", sys),
        ("order", usize_out(r.order)),
        ("original_order", usize_out(r.original_order)),
        ("method", Out::Str(r.method.name().to_string())),
        ("T", r.t.as_ref().map(mat).unwrap_or(Out::None)),
        ("verified", Out::Bool(r.verified)),
        ("report", report(&r.report())),
    ]))
}

pub(crate) fn scb_typed<K: Field>(t: &Typed<K>) -> FResult<Out> {
    let s = &t.ss;
    let r = exactlti::structure::scb::scb(&s.a, &s.b, &s.c, &s.d)?;
    let mp = r.minimum_phase();
    Ok(Out::Dict(vec![
        ("A", mat(&r.a)),
        ("B", mat(&r.b)),
        ("C", mat(&r.c)),
        ("D", mat(&r.d)),
        ("Gamma1", mat(&r.gamma1)),
        ("Gamma2", mat(&r.gamma2)),
        ("Gamma3", mat(&r.gamma3)),
        ("U", mat(&r.u_pre)),
        ("Y", mat(&r.y_pre)),
        (
            "dims",
            Out::List(r.dims.iter().map(|&d| usize_out(d)).collect()),
        ),
        (
            "chains",
            Out::List(r.chains.iter().map(|&d| usize_out(d)).collect()),
        ),
        ("m0", usize_out(r.m0)),
        ("left_invertible", Out::Bool(r.left_invertible)),
        ("right_invertible", Out::Bool(r.right_invertible)),
        ("zero_polynomial", poly(&r.invariant_zero_polynomial())),
        ("minimum_phase", mp.map(Out::Bool).unwrap_or(Out::None)),
        ("verified", Out::Bool(r.verified)),
        ("report", report(&r.report())),
    ]))
}

pub(crate) fn zeros_typed<K: Field>(t: &Typed<K>, domain: Domain) -> FResult<Out> {
    let s = &t.ss;
    let z = exactlti::structure::zeros::invariant_zeros(&s.a, &s.b, &s.c, &s.d)?;
    let rat = poly_q(&z.polynomial);
    let roots = match rat {
        Some(p) if !p.is_zero() && p.deg() > 0 => Out::List(
            exactlti::algebraic::roots(&p)?
                .iter()
                .map(|(n, m)| alg(n, *m))
                .collect(),
        ),
        Some(_) => Out::List(vec![]),
        None => Out::None,
    };
    Ok(Out::Dict(vec![
        ("polynomial", poly_var(&z.polynomial, domain.var())),
        ("normal_rank", usize_out(z.normal_rank)),
        ("count", usize_out(z.count())),
        ("roots", roots),
        ("report", report(&z.report_in(domain))),
    ]))
}

/// The transfer matrix in lowest terms (`entries`: rows of `(num, den)`), its McMillan
/// degree (the order of a verified minimal realization) and `verified`: every entry's
/// expansion at infinity equals `D, CB, CAB, ...` ($2n + 1$ terms) and the minimal
/// realization's checks held.
pub(crate) fn tf_typed<K: Field>(t: &Typed<K>, domain: Domain) -> FResult<Out> {
    let (kv, _) = tf_parts(&t.ss, domain)?;
    Ok(Out::Dict(kv))
}

/// [`tf_typed`]'s items and the minimal realization's `A` (for the pole polynomial).
pub(crate) fn tf_parts<K: Field>(s: &StateSpace<K>, domain: Domain) -> FResult<(Items, Matrix<K>)> {
    let var = domain.var();
    let g = s.transfer_matrix()?;
    let (min, verified) = exactlti::api::transfer::minimal_of_transfer(s, &g)?;
    let entries = Out::List(
        g.entries
            .iter()
            .map(|row| {
                Out::List(
                    row.iter()
                        .map(|h| Out::Tuple(vec![poly_var(&h.num, var), poly_var(&h.den, var)]))
                        .collect(),
                )
            })
            .collect(),
    );
    let kv = vec![
        ("entries", entries),
        ("variable", Out::Str(var.to_string())),
        ("mcmillan_degree", usize_out(min.order)),
        ("verified", Out::Bool(verified)),
    ];
    Ok((kv, min.system.a))
}

/// Balanced truncation of order `order` (float path, [`exactlti::float::balred`]).
pub(crate) fn balred_typed<K: Field>(t: &Typed<K>, order: usize) -> FResult<Out> {
    let s = &t.ss;
    let m = [
        to_dmatrix(&s.a)?,
        to_dmatrix(&s.b)?,
        to_dmatrix(&s.c)?,
        to_dmatrix(&s.d)?,
    ];
    let r = exactlti::float::balred([&m[0], &m[1], &m[2], &m[3]], order)?;
    let rows = |x: &nalgebra::DMatrix<f64>| {
        Out::List(
            (0..x.nrows())
                .map(|i| Out::List((0..x.ncols()).map(|j| Out::Float(x[(i, j)])).collect()))
                .collect(),
        )
    };
    Ok(Out::Dict(vec![
        ("A", rows(&r.a)),
        ("B", rows(&r.b)),
        ("C", rows(&r.c)),
        ("D", rows(&r.d)),
        (
            "hankel_singular_values",
            Out::List(
                r.hankel_singular_values
                    .iter()
                    .map(|x| Out::Float(*x))
                    .collect(),
            ),
        ),
        ("error_bound", Out::Float(r.error_bound)),
    ]))
}

pub(crate) fn to_dmatrix<K: Field>(m: &Matrix<K>) -> FResult<nalgebra::DMatrix<f64>> {
    let a = m.to_approx_complex();
    if a.iter().flatten().any(|(_, im)| *im != 0.0) {
        return Err(Fail::Unsupported(
            "unsupported: the frequency response needs real matrices".into(),
        ));
    }
    Ok(nalgebra::DMatrix::from_fn(m.nrows(), m.ncols(), |i, j| {
        a[i][j].0
    }))
}

/// `G(j w)`, or `G(e^{j w T})` on the unit circle for a sample time `dt`.
pub(crate) fn freqresp_typed<K: Field>(
    t: &Typed<K>,
    omega: &[f64],
    dt: Option<f64>,
) -> FResult<Out> {
    let s = &t.ss;
    let hz: Vec<f64> = omega
        .iter()
        .map(|w| w / (2.0 * std::f64::consts::PI))
        .collect();
    let g = match &t.descriptor {
        // on the pencil, C (jw E - A)^-1 B + D: never through the standard form's basis
        Some(ds) => {
            let z = |m| to_dmatrix(m).map(|m| m.map(|x| nalgebra::Complex::new(x, 0.0)));
            let [e, a, b, c, d] = [&ds.e, &ds.a, &ds.b, &ds.c, &ds.d].map(z);
            exactlti::float::freqresp_descriptor(&e?, [&a?, &b?, &c?, &d?], &hz)?
        }
        None => {
            let [a, b, c, d] = [&s.a, &s.b, &s.c, &s.d].map(to_dmatrix);
            exactlti::float::freqresp([&a?, &b?, &c?, &d?], &hz, dt)?
        }
    };
    Ok(Out::List(
        g.iter()
            .map(|m| {
                Out::List(
                    (0..m.nrows())
                        .map(|i| {
                            Out::List(
                                (0..m.ncols())
                                    .map(|j| {
                                        Out::Tuple(vec![
                                            Out::Float(m[(i, j)].re),
                                            Out::Float(m[(i, j)].im),
                                        ])
                                    })
                                    .collect(),
                            )
                        })
                        .collect(),
                )
            })
            .collect(),
    ))
}

/// The Jordan form as output data (any field with an exact Jordan decomposition): `J`, `T`
/// with their values (complex form: per eigenvalue, elements of its field; real form: the
/// blocks' fields, or Re/Im of the complex data for a compact pair).
pub(crate) fn jordan_out<F: EigenField>(jf: &JordanForm<F>, real: bool) -> FResult<Out> {
    let evs = Out::List(
        jf.eigenvalues
            .iter()
            .map(|e| {
                let ((rl, rh), (il, ih)) = e.number.bounding_box();
                let pair = |a, b| Out::Tuple(vec![q(a), q(b)]);
                Out::Dict(vec![
                    ("minpoly", poly(&e.minpoly)),
                    ("box", Out::Tuple(vec![pair(&rl, &rh), pair(&il, &ih)])),
                    (
                        "value",
                        Out::Str(exactlti::report::sections::eigenvalue_text(e)),
                    ),
                    (
                        "approx",
                        Out::Tuple(vec![Out::Float(e.approx.0), Out::Float(e.approx.1)]),
                    ),
                    ("symbol", Out::Str(e.symbol())),
                    (
                        "algebraic_multiplicity",
                        usize_out(e.algebraic_multiplicity),
                    ),
                    (
                        "geometric_multiplicity",
                        usize_out(e.geometric_multiplicity),
                    ),
                    (
                        "blocks",
                        Out::List(e.blocks.iter().map(|&b| usize_out(b)).collect()),
                    ),
                ])
            })
            .collect(),
    );
    let mut kv = vec![
        ("eigenvalues", evs),
        ("charpoly", poly(&jf.charpoly)),
        ("A", mat(&jf.a)),
    ];
    if real {
        let rf = jf.real_form()?;
        let (j, t) = rf.j_t_out();
        let (jv, tv) = real_values(&rf);
        kv.push(("J", matout(&j, jv)));
        kv.push(("T", matout(&t, tv)));
        kv.push(("exact", Out::Bool(rf.exact)));
        kv.push(("verified", Out::Bool(rf.verified)));
        kv.push((
            "notes",
            Out::List(rf.note_lines().into_iter().map(Out::Str).collect()),
        ));
        kv.push(("report", report(&rf.report())));
    } else {
        let (j, t) = match jf.single_field() {
            Some((j, t)) if j.field().degree() == 1 => (mat(&j), mat(&t)),
            _ => {
                // per eigenvalue, elements of its field (the report's cells carry their values)
                let (j, t) = jf.j_t_out();
                (matout(&j, values_of(&j)), matout(&t, values_of(&t)))
            }
        };
        kv.push(("J", j));
        kv.push(("T", t));
        kv.push(("exact", Out::Bool(true)));
        kv.push(("verified", Out::Bool(jf.verified)));
        kv.push(("notes", Out::List(vec![])));
        kv.push(("report", report(&jf.report())));
    }
    Ok(Out::Dict(kv))
}

/// An eigenvalue as an element value: `("root", minpoly, box)`.
fn root_value(e: &exactlti::jordan::Certified) -> Out {
    let ((rl, rh), (il, ih)) = e.number.bounding_box();
    let pair = |a, b| Out::Tuple(vec![q(a), q(b)]);
    Out::Tuple(vec![
        Out::Str("root".into()),
        Out::List(e.minpoly.coeffs().iter().map(q).collect()),
        Out::Tuple(vec![pair(&rl, &rh), pair(&il, &ih)]),
    ])
}

/// The values of `J` and `T` of the real Jordan form, block by block as the report lays them
/// out: a real root or an expanded pair in its field; a compact pair `r = a + b i` as
/// `[[a, b], [-b, a]]` blocks with the real and imaginary parts of its complex chains.
fn real_values<F: EigenField>(rf: &RealJordanForm<F>) -> (Out, Out) {
    let n = rf.n;
    let (mut j, mut t) = (Grid::zeros(n, n), Grid::zeros(n, n));
    let mut off = 0;
    for b in &rf.blocks {
        let w = b.j_approx.len();
        match &b.entries {
            RealEntries::Root { t: bt, j: bj, .. } => {
                t.block((0, off), bt);
                j.block((off, off), bj);
            }
            RealEntries::Expanded { t: bt, j: bj, .. } => {
                t.block((0, off), bt);
                j.block((off, off), bj);
            }
            RealEntries::Compact(cp) | RealEntries::Radical(cp) => {
                let f = &cp.field;
                for r in 0..n {
                    for c in 0..w {
                        let x = elem(f, cp.v.get(r, c / 2));
                        t.set((r, off + c), part(x, c % 2 == 1, false));
                    }
                }
                let theta = || root_value(&rf.eigenvalues[b.eigenvalue]);
                for r in 0..w {
                    for c in 0..w {
                        let v = if r / 2 == c / 2 {
                            match (r % 2, c % 2) {
                                (0, 0) | (1, 1) => part(theta(), false, false),
                                (0, 1) => part(theta(), true, false),
                                _ => part(theta(), true, true),
                            }
                        } else if b.j_approx[r][c] == 1.0 {
                            Out::Tuple(vec![Out::Int(1), Out::Int(1)])
                        } else {
                            zero()
                        };
                        j.set((off + r, off + c), v);
                    }
                }
            }
        }
        off += w;
    }
    (j.out(), t.out())
}

/// `jordan` of a system through the api's choices ([`exactlti::api::jordan_values`]): the
/// matrix (`A`, or the finite part of a descriptor system's pencil with `infinite_blocks` and
/// its note) and the field it is decomposed over; `UnsupportedError` naming any other field.
pub(crate) fn jordan_typed<K: realization::SystemField>(
    t: &Typed<K>,
    real: bool,
    path: &std::path::Path,
) -> FResult<Out> {
    use exactlti::api::jordan_values::{EigenVisitor, finite_part, on_eigen_field};
    struct V(bool);
    impl EigenVisitor for V {
        type Output = Option<FResult<Out>>;
        fn visit<F: EigenField>(self, a: &Matrix<F>) -> Self::Output {
            Some(
                exactlti::jordan::jordan_over(a)
                    .map_err(Into::into)
                    .and_then(|jf| jordan_out(&jf, self.0)),
            )
        }
        fn visit_qp(self, _: &Matrix<exactlti::ratfunc::RatFuncField>) -> Self::Output {
            // Q(p) has its own path (`symbolic::jordan`, the symbolic Jordan form)
            None
        }
    }
    let unsupported = || {
        Fail::Unsupported(format!(
            "the Jordan form is not supported over {}",
            t.a_raw.field()
        ))
    };
    let Some(d) = &t.descriptor else {
        return on_eigen_field(&t.a_raw, V(real)).ok_or_else(unsupported)?;
    };
    let fp = finite_part(d, path)?;
    let Out::Dict(mut kv) = on_eigen_field(&fp.a, V(real)).ok_or_else(unsupported)?? else {
        unreachable!("jordan_out returns a dict")
    };
    with_finite_part(&mut kv, &fp.infinite_blocks, fp.verified, &fp.note);
    Ok(Out::Dict(kv))
}

/// Adds a descriptor system's finite-part facts to a Jordan result: `verified` also needs the
/// pencil's checks, `infinite_blocks`, and the note (when the result has `notes`).
pub(crate) fn with_finite_part(kv: &mut Items, blocks: &[usize], verified: bool, note: &str) {
    for (k, v) in kv.iter_mut() {
        match (*k, v) {
            ("verified", v) => {
                let was = matches!(v, Out::Bool(true));
                *v = Out::Bool(was && verified);
            }
            ("notes", Out::List(notes)) => notes.push(Out::Str(note.to_string())),
            _ => {}
        }
    }
    kv.push((
        "infinite_blocks",
        Out::List(blocks.iter().map(|&b| usize_out(b)).collect()),
    ));
}

/// The exact method `--method` names `name`, parsed by the api ([`exactlti::api::MethodArg`]).
pub(crate) fn method_of(name: &str) -> FResult<MinrealMethod> {
    exactlti::api::MethodArg::named(name)
        .map_err(Fail::Input)?
        .exact()
        .ok_or_else(|| Fail::Input(format!("method '{name}' is the float path: use era()")))
}

/// The mechanical normal form as output data (any field).
pub(crate) fn mnf_out<K: Field>(
    r: &exactlti::structure::mechanical::MechanicalNormalForm<K>,
) -> Vec<(&'static str, Out)> {
    let mut kv = vec![
        ("exists", Out::Bool(r.exists)),
        ("reason", r.reason_text().map(Out::Str).unwrap_or(Out::None)),
        ("verified", Out::Bool(r.verified)),
        ("report", report(&r.report())),
    ];
    if let Some(f) = &r.form {
        kv.push(("M", mat(&f.mass)));
        kv.push(("L", mat(&f.damping)));
        kv.push(("K", mat(&f.stiffness)));
        kv.push(("F", mat(&f.input)));
        kv.push(("C", mat(&f.output)));
        kv.push(("D", mat(&f.feedthrough)));
        kv.push(("T", mat(&f.t)));
        kv.push(("A_tilde", mat(&f.a_tilde)));
        kv.push(("B_tilde", mat(&f.b_tilde)));
    }
    kv
}

/// `minreal(method="jordan")` over a field with certified eigenvalues: the modal form
/// `jm` with its stages and values; `r` the library's result (its report and verification
/// are the command line's).
fn modal_out<F: Field>(
    jm: &realization::JordanMinimal<F>,
    r: &realization::MinimalRealization<F>,
) -> Out {
    Out::Dict(vec![
        ("system", Out::None),
        ("order", usize_out(jm.mcmillan_degree)),
        ("original_order", usize_out(r.original_order)),
        (
            "stages",
            Out::List(jm.stages.iter().map(|&x| usize_out(x)).collect()),
        ),
        ("method", Out::Str(r.method.name().to_string())),
        ("T", Out::None),
        ("verified", Out::Bool(r.verified)),
        ("values", modal_values(jm)),
        ("report", report(&r.report())),
    ])
}

/// The values of the Jordan-method realization's `A`, `B`, `C`, `D`, block by block as its
/// report lays them out: a real root or an expanded pair in its field; a compact pair as
/// $A_r = [[\mathrm{Re}, \mathrm{Im}], [-\mathrm{Im}, \mathrm{Re}]]$ of $J$,
/// $B_r = [\mathrm{Re}; -\mathrm{Im}]$ of $WB$, $C_r = [\mathrm{Re}, \mathrm{Im}]$ of $2CV$
/// (the complex form when the system is not real).
fn modal_values<F: Field>(r: &realization::JordanMinimal<F>) -> Out {
    use realization::{ModalBlock, RealModalBlock};
    let n = r.order();
    let (m, p) = (r.d.ncols(), r.d.nrows());
    let (mut a, mut b, mut c) = (Grid::zeros(n, n), Grid::zeros(n, m), Grid::zeros(p, n));
    let mut off = 0;
    match &r.real {
        None => {
            for bk in &r.blocks {
                put_ext([&bk.a, &bk.b, &bk.c], off, [&mut a, &mut b, &mut c]);
                off += bk.a.nrows();
            }
        }
        Some(real) => {
            for blk in real {
                match blk {
                    RealModalBlock::Root(bk) => {
                        put_ext([&bk.a, &bk.b, &bk.c], off, [&mut a, &mut b, &mut c])
                    }
                    RealModalBlock::Pair {
                        a: pa,
                        b: pb,
                        c: pc,
                        ..
                    } => put_ext([pa, pb, pc], off, [&mut a, &mut b, &mut c]),
                    RealModalBlock::Compact(bk) | RealModalBlock::Radical(bk) => {
                        put_compact(bk, off, [&mut a, &mut b, &mut c])
                    }
                }
                off += blk.order();
            }
        }
    }
    fn put_ext<F: Field>(m: [&Matrix<F>; 3], off: usize, [a, b, c]: [&mut Grid; 3]) {
        a.block((off, off), m[0]);
        b.block((off, 0), m[1]);
        c.block((0, off), m[2]);
    }
    fn put_compact<F: Field>(bk: &ModalBlock<F>, off: usize, [a, b, c]: [&mut Grid; 3]) {
        let f = &bk.field;
        let v = |x: &exactlti::algebraic::ExtElem<F::Elem>| elem(f, x);
        for i in 0..bk.a.nrows() {
            for j in 0..bk.a.ncols() {
                let x = bk.a.get(i, j);
                let (o, q) = (off + 2 * i, off + 2 * j);
                a.set((o, q), part(v(x), false, false));
                a.set((o, q + 1), part(v(x), true, false));
                a.set((o + 1, q), part(v(x), true, true));
                a.set((o + 1, q + 1), part(v(x), false, false));
            }
            for j in 0..bk.b.ncols() {
                let x = bk.b.get(i, j);
                b.set((off + 2 * i, j), part(v(x), false, false));
                b.set((off + 2 * i + 1, j), part(v(x), true, true));
            }
            for row in 0..bk.c.nrows() {
                let x = f.mul(&f.from_i64(2), bk.c.get(row, i));
                c.set((row, off + 2 * i), part(v(&x), false, false));
                c.set((row, off + 2 * i + 1), part(v(&x), true, false));
            }
        }
    }
    Out::Dict(vec![
        ("A", a.out()),
        ("B", b.out()),
        ("C", c.out()),
        ("D", crate::values::rows(&r.d)),
    ])
}

/// The modal table of `A` as output data, over every field with certified eigenvalues
/// ([`realization::SystemField::modal_table`], as the command line's `modes`).
pub(crate) fn modes_out<K: realization::SystemField>(a: &Matrix<K>) -> FResult<Out> {
    let m = K::modal_table(a)?;
    let opt = |x: Option<f64>| x.map(Out::Float).unwrap_or(Out::None);
    let modes = m
        .modes
        .iter()
        .map(|md| {
            Out::Dict(vec![
                ("eigenvalue", Out::Str(md.eigenvalue.value_string())),
                ("minpoly", Out::Str(md.eigenvalue.minpoly().to_string())),
                (
                    "approx",
                    Out::Tuple(vec![Out::Float(md.approx.0), Out::Float(md.approx.1)]),
                ),
                ("multiplicity", usize_out(md.multiplicity)),
                ("frequency_hz", Out::Float(md.frequency_hz)),
                ("damping_ratio", opt(md.damping_ratio)),
                ("time_constant_s", opt(md.time_constant_s)),
                ("period_s", opt(md.period_s)),
            ])
        })
        .collect();
    Ok(Out::Dict(vec![
        ("modes", Out::List(modes)),
        ("report", report(&m.report())),
    ]))
}
