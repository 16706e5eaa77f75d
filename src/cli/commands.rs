//! One function per command: load, compute, report.

use super::load::{Loaded, Typed, load_system};
use super::{Command, Failure, LinalgOp, MethodArg};
use crate::field::Field;
use crate::matrix::Matrix;
use crate::realization::{self, MinrealMethod};
use crate::report::{Report, Value, str_list};
use std::path::Path;

/// Runs `f` over whichever field the file is in.
macro_rules! over_ground {
    ($loaded:expr, |$t:ident| $body:expr) => {
        match &$loaded {
            Loaded::Q(_, $t) => $body,
            Loaded::Quadratic(_, $t) => $body,
        }
    };
}

/// Dispatches a command.
pub fn execute(cmd: &Command) -> Result<Report, Failure> {
    match cmd {
        Command::Linalg { op, file } => linalg(*op, file),
        Command::Minreal { file, method } => minreal(file, *method),
        Command::Standard { file } => standard(file),
        Command::Analyze { file } => analyze(file.as_deref()),
        Command::Poly { op } => poly(op),
        Command::Jordan { file, real, expand } => {
            let l = load_system(file)?;
            let jf = match &l {
                Loaded::Q(_, t) => crate::jordan::jordan(&t.a_raw),
                Loaded::Quadratic(_, t) => crate::jordan::jordan_quadratic(&t.a_raw),
            }
            .map_err(|e| with_path(file, e))?;
            if *real {
                Ok(jf
                    .real_form_with(*expand)
                    .map_err(|e| with_path(file, e))?
                    .report())
            } else {
                Ok(jf.report())
            }
        }
        Command::Modes { file } => {
            let l = load_system(file)?;
            let t = l.rational("the modal table")?;
            Ok(realization::modal_table(&t.ss.a)
                .map_err(|e| with_path(file, e))?
                .report())
        }
        Command::Scb { file } => {
            let l = load_system(file)?;
            over_ground!(l, |t| scb_typed(t, file))
        }
        Command::Mnf { file } => {
            let l = load_system(file)?;
            let t = l.rational("the mechanical normal form")?;
            let s = &t.ss;
            let r = crate::structure::mechanical::mechanical_normal_form(&s.a, &s.b, &s.c, &s.d)
                .map_err(|e| with_path(file, e))?;
            Ok(r.report())
        }
        Command::Freqresp {
            file,
            from,
            to,
            points,
            svg,
            csv,
        } => {
            let l = load_system(file)?;
            over_ground!(l, |t| super::float_cmds::freqresp(
                t,
                file,
                *from,
                *to,
                *points,
                svg.as_deref(),
                csv.as_deref()
            ))
        }
        Command::Check { file } => {
            let l = load_system(file)?;
            match &l {
                Loaded::Q(_, t) => {
                    let extra = super::float_cmds::jordan_comparison(&t.a_raw, file)?;
                    super::float_cmds::check(t, file, extra)
                }
                Loaded::Quadratic(_, t) => super::float_cmds::check(t, file, vec![]),
            }
        }
        Command::Zeros { file } => {
            let l = load_system(file)?;
            over_ground!(l, |t| zeros_typed(t, file))
        }
    }
}

fn with_path(path: &Path, e: crate::error::Error) -> Failure {
    let f: Failure = e.into();
    Failure {
        code: f.code,
        message: format!("{}: {}", path.display(), f.message),
    }
}

fn linalg_typed<K: Field>(op: LinalgOp, a: &Matrix<K>, path: &Path) -> Result<Report, Failure> {
    let e = |err| with_path(path, err);
    let r = Report::titled(format!("linalg {op:?}").to_lowercase());
    Ok(match op {
        LinalgOp::Rank => r.int("rank", a.rank()),
        LinalgOp::Det => r.str("det", a.field().fmt_elem(&a.det().map_err(e)?)),
        LinalgOp::Charpoly => r.str("charpoly", a.charpoly().map_err(e)?.to_string()),
        LinalgOp::Minpoly => r.str("minpoly", a.minpoly().map_err(e)?.to_string()),
        LinalgOp::Inverse => r.matrix("matrix", &a.inverse().map_err(e)?),
        LinalgOp::Rref => {
            let (m, piv) = a.rref();
            r.matrix("matrix", &m)
                .with(
                    "pivots",
                    Value::List(piv.iter().map(|&p| Value::Int(p as i64 + 1)).collect()),
                )
                .int("rank", piv.len())
        }
        LinalgOp::Nullspace => {
            let n = a.nullspace();
            let basis = (0..n.ncols())
                .map(|j| {
                    Value::List(
                        n.col(j)
                            .iter()
                            .map(|x| Value::Str(a.field().fmt_elem(x)))
                            .collect(),
                    )
                })
                .collect();
            r.with("basis", Value::List(basis))
                .int("nullity", n.ncols())
        }
    })
}

fn linalg(op: LinalgOp, file: &Path) -> Result<Report, Failure> {
    let l = load_system(file)?;
    over_ground!(l, |t| linalg_typed(op, &t.a_raw, file))
}

fn minreal_typed<K: Field>(t: &Typed<K>, m: MinrealMethod, path: &Path) -> Result<Report, Failure> {
    let r = realization::minimal(&t.ss, m).map_err(|e| with_path(path, e))?;
    Ok(r.report())
}

fn minreal(file: &Path, method: MethodArg) -> Result<Report, Failure> {
    let l = load_system(file)?;
    if method == MethodArg::Jordan {
        let t = l.rational("the Jordan-form method")?;
        return Ok(realization::minimal_jordan(&t.ss)
            .map_err(|e| with_path(file, e))?
            .report());
    }
    let m = match method {
        MethodArg::Kalman => MinrealMethod::Kalman,
        MethodArg::Rosenbrock => MinrealMethod::Rosenbrock,
        MethodArg::HoKalman => MinrealMethod::HoKalman,
        MethodArg::Jordan => MinrealMethod::Jordan,
        MethodArg::Era => return over_ground!(l, |t| super::float_cmds::era(t, file)),
    };
    over_ground!(l, |t| minreal_typed(t, m, file))
}

fn standard_typed<K: Field>(t: &Typed<K>, path: &Path) -> Result<Report, Failure> {
    match &t.descriptor {
        Some(d) => Ok(realization::descriptor_to_standard(d)
            .map_err(|e| with_path(path, e))?
            .report()),
        None => Ok(Report::titled("descriptor to standard form")
            .int("order", t.ss.nstates())
            .int("removed_infinite", 0)
            .matrix("A", &t.ss.a)
            .matrix("B", &t.ss.b)
            .matrix("C", &t.ss.c)
            .matrix("D", &t.ss.d)
            .bool("verified", true)
            .with(
                "note",
                Value::Str("no E in the file: the system is already in standard form".into()),
            )),
    }
}

fn standard(file: &Path) -> Result<Report, Failure> {
    let l = load_system(file)?;
    over_ground!(l, |t| standard_typed(t, file))
}

fn scb_typed<K: Field>(t: &Typed<K>, path: &Path) -> Result<Report, Failure> {
    let s = &t.ss;
    let r = crate::structure::scb::scb(&s.a, &s.b, &s.c, &s.d).map_err(|e| with_path(path, e))?;
    Ok(r.report())
}

fn zeros_typed<K: Field>(t: &Typed<K>, path: &Path) -> Result<Report, Failure> {
    let s = &t.ss;
    let z = crate::structure::zeros::invariant_zeros(&s.a, &s.b, &s.c, &s.d)
        .map_err(|e| with_path(path, e))?;
    Ok(z.report())
}

fn poly(op: &super::PolyCmd) -> Result<Report, Failure> {
    let parse = |e: &str| {
        crate::poly::parse_poly_q(e).map_err(|err| Failure {
            code: 2,
            message: format!("polynomial \"{e}\": {err}"),
        })
    };
    match op {
        super::PolyCmd::Factor { expr } => {
            let p = parse(expr)?;
            Ok(crate::algebraic::factor_report(&p)?)
        }
        super::PolyCmd::Roots { expr, digits } => {
            let p = parse(expr)?;
            if *digits == 0 || *digits > 10_000 {
                return Err(Failure {
                    code: 2,
                    message: format!("--digits must be between 1 and 10000 (got {digits})"),
                });
            }
            Ok(crate::algebraic::roots_report(&p, *digits)?)
        }
    }
}

/// The built-in example of `analyze` without a file.
pub const BUILTIN_EXAMPLE: &str = include_str!("../../data/sliding-masses.json");

fn load_or_builtin(file: Option<&Path>) -> Result<Loaded, Failure> {
    match file {
        Some(f) => load_system(f),
        None => super::load::load_text(BUILTIN_EXAMPLE, "built-in:sliding-masses.json"),
    }
}

fn system_section<K: Field>(f: &crate::io::SystemFile, t: &Typed<K>) -> Report {
    let mut r = Report::titled("system")
        .str("file", f.path.clone())
        .str("name", f.name.clone().unwrap_or_default())
        .str("field", f.ground.to_string())
        .int("states", t.ss.nstates())
        .int("inputs", t.ss.ninputs())
        .int("outputs", t.ss.noutputs());
    if let Some(d) = &t.descriptor {
        r = r
            .str("form", "descriptor")
            .int("descriptor_states", d.nstates());
    } else if f.is_second_order() {
        r = r.str("form", "second order");
    } else {
        r = r.str("form", "state space");
    }
    r.str(
        "charpoly",
        t.ss.a
            .charpoly()
            .map(|p| p.to_string_var("s"))
            .unwrap_or_default(),
    )
}

fn realization_section<K: Field>(t: &Typed<K>) -> Result<Report, Failure> {
    let s = &t.ss;
    let rc = realization::controllability_matrix(&s.a, &s.b).rank();
    let ro = realization::observability_matrix(&s.a, &s.c).rank();
    let min = realization::minimal(s, MinrealMethod::Kalman)?;
    let tf = s.transfer_matrix()?;
    Ok(Report::titled("realization")
        .int("controllability_rank", rc)
        .int("observability_rank", ro)
        .bool("controllable", rc == s.nstates())
        .bool("observable", ro == s.nstates())
        .int("mcmillan_degree", min.order)
        .with(
            "transfer_matrix",
            Value::List(tf.to_strings().into_iter().map(str_list).collect()),
        )
        .obj("minimal_realization", min.report()))
}

fn analyze_typed<K: Field>(f: &crate::io::SystemFile, t: &Typed<K>) -> Result<Report, Failure> {
    let mut r = Report::titled(format!(
        "exactlti analysis: {}",
        f.name.clone().unwrap_or_else(|| f.path.clone())
    ));
    r.push("system", Value::Obj(system_section(f, t)));
    if t.ss.ninputs() > 0 && t.ss.noutputs() > 0 {
        r.push("realization", Value::Obj(realization_section(t)?));
        // the SCB assumes [B; D] and [C, D] of full rank; report why when it does not apply
        match crate::structure::scb::scb(&t.ss.a, &t.ss.b, &t.ss.c, &t.ss.d) {
            Ok(scb) => r.push("structure", Value::Obj(scb.report())),
            Err(e) => r.push(
                "structure",
                Value::Obj(
                    Report::titled("special coordinate basis").str("not_applicable", e.to_string()),
                ),
            ),
        };
        if let Ok(z) = crate::structure::zeros::invariant_zeros(&t.ss.a, &t.ss.b, &t.ss.c, &t.ss.d)
        {
            r.push("zeros", Value::Obj(z.report()));
        }
    }
    Ok(r)
}

fn analyze(file: Option<&Path>) -> Result<Report, Failure> {
    let l = load_or_builtin(file)?;
    match &l {
        Loaded::Q(f, t) => {
            let mut r = analyze_typed(f, t)?;
            match crate::jordan::jordan(&t.ss.a) {
                Ok(jf) => {
                    let mut sec = jf.report();
                    sec.title = Some("eigenvalues and Jordan form".into());
                    if let Ok(rf) = jf.real_form() {
                        sec.push("real_form", Value::Obj(rf.report()));
                    }
                    sec.push("free_response", Value::Obj(jf.free_response().report(&jf)));
                    r.push("jordan", Value::Obj(sec));
                }
                Err(e) => {
                    r.push(
                        "jordan",
                        Value::Obj(
                            Report::titled("eigenvalues and Jordan form")
                                .str("error", e.to_string()),
                        ),
                    );
                }
            }
            if t.ss.ninputs() > 0
                && let (Ok(pc), Ok(po)) = (
                    realization::pbh_controllable(&t.ss.a, &t.ss.b),
                    realization::pbh_observable(&t.ss.a, &t.ss.c),
                )
            {
                r.push(
                    "pbh",
                    Value::Obj(
                        Report::titled("PBH tests (exact, one rank per irreducible factor)")
                            .bool("controllable", pc)
                            .bool("observable", po),
                    ),
                );
            }
            if let Ok(m) = realization::modal_table(&t.ss.a) {
                r.push("modes", Value::Obj(m.report()));
            }
            // mechanical normal form: applies to first-order systems with inputs and an even
            // number of states (files already in second-order form are mechanical by input)
            let s = &t.ss;
            if !f.is_second_order()
                && s.ninputs() > 0
                && s.nstates() % 2 == 0
                && let Ok(m) =
                    crate::structure::mechanical::mechanical_normal_form(&s.a, &s.b, &s.c, &s.d)
            {
                r.push("mechanical", Value::Obj(m.report()));
            }
            Ok(r)
        }
        Loaded::Quadratic(f, t) => analyze_typed(f, t),
    }
}
