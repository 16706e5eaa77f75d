//! The exact operations on a system over its (numeric) ground field, as plain output data.

use crate::out::*;
use crate::{FResult, Fail};
use exactlti::field::Field;
use exactlti::io::TypedSystem as Typed;
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

pub(crate) fn minreal_typed<K: realization::SystemField>(t: &Typed<K>, m: MinrealMethod) -> FResult<Out> {
    let r = realization::minimal(&t.ss, m)?;
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
pub(crate) fn tf_parts<K: Field>(
    s: &StateSpace<K>,
    domain: Domain,
) -> FResult<(Items, Matrix<K>)> {
    let var = domain.var();
    let g = s.transfer_matrix()?;
    let min = realization::minimal_kalman(s)?;
    let verified = min.verified && g.matches_markov(s);
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
            Out::List(r.hankel_singular_values.iter().map(|x| Out::Float(*x)).collect()),
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

pub(crate) fn jordan_out(jf: &exactlti::jordan::JordanForm, real: bool) -> FResult<Out> {
    let evs = Out::List(
        jf.eigenvalues
            .iter()
            .map(|e| {
                Out::Dict(vec![
                    ("minpoly", poly(&e.minpoly)),
                    ("value", Out::Str(exactlti::report::sections::eigenvalue_text(e))),
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
        kv.push(("J", matout(&j)));
        kv.push(("T", matout(&t)));
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
                let (j, t) = jf.j_t_out();
                (matout(&j), matout(&t))
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

/// `jordan` of a descriptor system: the Jordan form of the pencil's finite dynamics (the
/// standard form's `A`), with `infinite_blocks` (sizes of the Jordan blocks at infinity) and
/// a `note`; a singular pencil is refused.
pub(crate) fn descriptor_jordan<K: Field>(
    t: &Typed<K>,
    real: bool,
    jordan: impl Fn(&Matrix<K>) -> exactlti::Result<exactlti::jordan::JordanForm>,
) -> FResult<Out> {
    let d = t.descriptor.as_ref().expect("a descriptor system");
    let ks = exactlti::pencil::kronecker_structure(&d.a, &d.e)?;
    let (af, method) = realization::finite_dynamics(d)?;
    let jf = jordan(&af)?;
    let Out::Dict(mut kv) = jordan_out(&jf, real)? else {
        unreachable!("jordan_out returns a dict")
    };
    let ok = ks.verified && af.nrows() == ks.finite_order();
    for (k, v) in kv.iter_mut() {
        if *k == "verified" {
            let was = matches!(v, Out::Bool(true));
            *v = Out::Bool(was && ok);
        }
    }
    kv.push((
        "infinite_blocks",
        Out::List(ks.infinite_divisors.iter().map(|&b| usize_out(b)).collect()),
    ));
    let note = format!(
        "descriptor system: J is the Jordan form of the finite part of the pencil sE - A, computed on the finite part's A ({}); infinite_blocks: sizes of the Jordan blocks at s = infinity (size 1 = non-dynamic mode)",
        method.name()
    );
    for (k, v) in kv.iter_mut() {
        if let ("notes", Out::List(notes)) = (*k, v) {
            notes.push(Out::Str(note.clone()));
        }
    }
    Ok(Out::Dict(kv))
}

pub(crate) fn truth(t: exactlti::float::Truth) -> Out {
    Out::Str(format!("{t:?}"))
}

pub(crate) fn check_typed<K: Field>(t: &Typed<K>) -> FResult<Out> {
    use exactlti::float::{self, Tol};
    let s = &t.ss;
    let [a, b, c, d] = [&s.a, &s.b, &s.c, &s.d].map(to_dmatrix);
    let (a, b, c, d) = (a?, b?, c?, d?);
    let tol = Tol::default();
    let item = |name: &str, exact: Out, fl: Out, tr: Out, agree: bool| {
        Out::Dict(vec![
            ("what", Out::Str(name.to_string())),
            ("exact", exact),
            ("float", fl),
            ("float_truth", tr),
            ("agree", Out::Bool(agree)),
        ])
    };
    let mut items = vec![];
    let exact_min = realization::minimal_kalman(s)?;
    let fm = float::minreal(&a, &b, &c, &d, &tol)?;
    items.push(item(
        "mcmillan_degree",
        usize_out(exact_min.order),
        usize_out(fm.order),
        truth(fm.truth),
        exact_min.order == fm.order,
    ));
    let rc = realization::controllability_matrix(&s.a, &s.b).rank();
    let frc = float::controllability_rank(&a, &b, &tol)?;
    items.push(item(
        "controllability_rank",
        usize_out(rc),
        usize_out(frc.rank),
        truth(frc.truth),
        rc == frc.rank,
    ));
    let ro = realization::observability_matrix(&s.a, &s.c).rank();
    let fro = float::observability_rank(&a, &c, &tol)?;
    items.push(item(
        "observability_rank",
        usize_out(ro),
        usize_out(fro.rank),
        truth(fro.truth),
        ro == fro.rank,
    ));
    // eigenvalues: the float ones matched to the exact ones (greedy nearest)
    let fe = float::eigenvalues(&a)?;
    let exact_ev: Option<Vec<(f64, f64)>> = exactlti::matrix::to_rational_matrix(&s.a)
        .map(|aq| -> FResult<Vec<(f64, f64)>> {
            let p = aq.charpoly()?;
            let mut v = vec![];
            if p.deg() > 0 {
                for (n, m) in exactlti::algebraic::roots(&p)? {
                    for _ in 0..m {
                        v.push(n.approx());
                    }
                }
            }
            Ok(v)
        })
        .transpose()?;
    if let Some(ev) = exact_ev {
        let mut used = vec![false; fe.len()];
        let mut worst = 0.0f64;
        for (re, im) in &ev {
            let mut best = (f64::INFINITY, usize::MAX);
            for (j, z) in fe.iter().enumerate() {
                let dist = ((z.re - re).powi(2) + (z.im - im).powi(2)).sqrt();
                if !used[j] && dist < best.0 {
                    best = (dist, j);
                }
            }
            if best.1 != usize::MAX {
                used[best.1] = true;
                worst = worst.max(best.0);
            }
        }
        items.push(Out::Dict(vec![
            ("what", Out::Str("max_eigenvalue_error".into())),
            ("exact", Out::Float(0.0)),
            ("float", Out::Float(worst)),
            ("float_truth", Out::None),
            ("agree", Out::Bool(worst <= 1e-6)),
        ]));
    }
    Ok(Out::List(items))
}

pub(crate) fn method_of(name: &str) -> FResult<MinrealMethod> {
    Ok(match name {
        "kalman" => MinrealMethod::Kalman,
        "rosenbrock" => MinrealMethod::Rosenbrock,
        "ho-kalman" | "ho_kalman" | "hokalman" => MinrealMethod::HoKalman,
        other => {
            return Err(Fail::Input(format!(
                "unknown method '{other}' (kalman, rosenbrock, ho-kalman, jordan)"
            )));
        }
    })
}

/// The mechanical normal form as output data (any field).
pub(crate) fn mnf_out<K: Field>(
    r: &exactlti::structure::mechanical::MechanicalNormalForm<K>,
) -> Vec<(&'static str, Out)> {
    let mut kv = vec![
        ("exists", Out::Bool(r.exists)),
        (
            "reason",
            r.reason_text().map(Out::Str).unwrap_or(Out::None),
        ),
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

/// `minreal(method="jordan")` over Q: the modal form with its stages.
pub(crate) fn minreal_jordan(t: &Typed<exactlti::field::Q>) -> FResult<Out> {
    let r = realization::minimal_jordan(&t.ss)?;
    Ok(Out::Dict(vec![
        ("system", Out::None),
        ("order", usize_out(r.mcmillan_degree)),
        ("original_order", usize_out(r.stages[0])),
        (
            "stages",
            Out::List(r.stages.iter().map(|&x| usize_out(x)).collect()),
        ),
        ("method", Out::Str("jordan".into())),
        ("T", Out::None),
        ("verified", Out::Bool(r.verified)),
        ("report", report(&r.report())),
    ]))
}

/// The Jordan form of `A` (of the finite part of a descriptor system) over Q or a quadratic
/// field; `UnsupportedError` naming any other field.
pub(crate) fn jordan_typed<K: Field + 'static>(t: &Typed<K>, real: bool) -> FResult<Out> {
    use exactlti::field::{Q, QuadraticField};
    let any = t as &dyn std::any::Any;
    if let Some(t) = any.downcast_ref::<Typed<Q>>() {
        if t.descriptor.is_some() {
            return descriptor_jordan(t, real, exactlti::jordan::jordan);
        }
        return jordan_out(&exactlti::jordan::jordan(&t.a_raw)?, real);
    }
    if let Some(t) = any.downcast_ref::<Typed<QuadraticField>>() {
        if t.descriptor.is_some() {
            return descriptor_jordan(t, real, exactlti::jordan::jordan_quadratic);
        }
        return jordan_out(&exactlti::jordan::jordan_quadratic(&t.a_raw)?, real);
    }
    Err(Fail::Unsupported(format!(
        "the Jordan form is not supported over {}",
        t.a_raw.field()
    )))
}

/// The modal table of `A` over Q as output data.
pub(crate) fn modes_out(a: &Matrix<exactlti::field::Q>) -> FResult<Out> {
    let m = realization::modal_table(a)?;
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
