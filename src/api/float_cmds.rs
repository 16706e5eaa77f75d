//! Commands that run the float backend: `freqresp`, `minreal --method era`, `check`.

use super::Failure;
use super::float_compare::{Items, MAX_FLOAT_ZEROS_SIDE, claim_str};
use crate::field::Field;
use crate::float::{self, FloatScalar, Tol, to_cmatrix, to_dmatrix};
use crate::io::TypedSystem as Typed;
use crate::realization;
use crate::report::plot::{Response, logspace, response_csv, response_table};
use crate::report::{Report, Value};
use nalgebra::DMatrix;
use num_complex::Complex;
use std::path::Path;

fn fail(path: &Path, e: crate::error::Error) -> Failure {
    Failure::from(e).in_file(path)
}

/// The float image of a system: real when every entry is real under the field's
/// embedding, complex otherwise (a system over $\mathbb{Q}(i)$ with a non-real entry).
pub(crate) enum FloatAbcd {
    Real([DMatrix<f64>; 4]),
    Complex([DMatrix<Complex<f64>>; 4]),
}

pub(crate) fn float_abcd<K: Field>(t: &Typed<K>, path: &Path) -> Result<FloatAbcd, Failure> {
    let s = &t.ss;
    let conv = |m| to_cmatrix(m).map_err(|e| fail(path, e));
    let c = [conv(&s.a)?, conv(&s.b)?, conv(&s.c)?, conv(&s.d)?];
    if c.iter().all(|m| m.iter().all(|z| z.im == 0.0)) {
        let conv = |m| to_dmatrix(m).map_err(|e| fail(path, e));
        Ok(FloatAbcd::Real([
            conv(&s.a)?,
            conv(&s.b)?,
            conv(&s.c)?,
            conv(&s.d)?,
        ]))
    } else {
        Ok(FloatAbcd::Complex(c))
    }
}

/// The float frequency response at `freqs` (hertz). For a file with `E` on the pencil,
/// $G(j\omega) = C(j\omega E - A)^{-1}B + D$, never through the standard form (whose basis
/// may be badly scaled); else on `sys` (the embedding of the standard system).
pub(crate) fn float_response<K: Field>(
    t: &Typed<K>,
    sys: &FloatAbcd,
    path: &Path,
    freqs: &[f64],
) -> Result<Vec<DMatrix<Complex<f64>>>, Failure> {
    float_response_dt(t, sys, path, freqs, None)
}

/// [`float_response`], on the unit circle ($z = e^{j\omega T}$) for a sample time `dt`.
pub(crate) fn float_response_dt<K: Field>(
    t: &Typed<K>,
    sys: &FloatAbcd,
    path: &Path,
    freqs: &[f64],
    dt: Option<f64>,
) -> Result<Vec<DMatrix<Complex<f64>>>, Failure> {
    // a sampled system on the unit circle; a continuous descriptor system on its pencil
    let resp = match (&t.descriptor, sys) {
        (Some(ds), _) if dt.is_none() => {
            let conv = |m| to_cmatrix(m).map_err(|e| fail(path, e));
            let [e, a, b, c, d] = [&ds.e, &ds.a, &ds.b, &ds.c, &ds.d].map(conv);
            float::freqresp_descriptor(&e?, [&a?, &b?, &c?, &d?], freqs)
        }
        (_, FloatAbcd::Real([a, b, c, d])) => float::freqresp([a, b, c, d], freqs, dt),
        (_, FloatAbcd::Complex([a, b, c, d])) => float::freqresp([a, b, c, d], freqs, dt),
    };
    resp.map_err(|e| fail(path, e))
}

/// A float matrix in a report: numbers for a real matrix, `[re, im]` pairs for a complex one.
fn dm_report<T: FloatScalar>(r: Report, name: &str, m: &DMatrix<T>) -> Report {
    let complex = m.iter().any(|z| z.imaginary() != 0.0);
    let entry = |z: T| {
        if complex {
            Value::List(vec![Value::Float(z.real()), Value::Float(z.imaginary())])
        } else {
            Value::Float(z.real())
        }
    };
    let rows = (0..m.nrows())
        .map(|i| Value::List((0..m.ncols()).map(|j| entry(m[(i, j)])).collect()))
        .collect();
    r.with(name, Value::List(rows))
}

/// Most complex values (points x outputs x inputs) `freqresp` computes and reports: about
/// 50 MB of JSON, a few hundred MB while the report is built.
pub const MAX_RESPONSE_VALUES: usize = 1_000_000;

/// The frequency response (float, from the exact system's embedding) at `points` frequencies
/// from `from` to `to` Hz; `names`: the input and output names of the channels (`u1`, `y1`,
/// ... when the file gives none); with a sample time `dt` (seconds) on the unit circle.
pub fn freqresp<K: Field>(
    t: &Typed<K>,
    path: &Path,
    names: (&[String], &[String]),
    (from, to, points): (f64, f64, usize),
    csv: Option<&Path>,
    dt: Option<f64>,
) -> Result<Report, Failure> {
    if !(from > 0.0 && to > from && (2..=100_000).contains(&points)) {
        return Err(Failure::input(format!(
            "freqresp: need 0 < --from < --to and 2 <= --points <= 100000 (got {from}, {to}, {points})"
        )));
    }
    // bounded output: the report holds every value (JSON ~50 bytes each), so a 20x20
    // system at 100000 points (40 million values, GBs) is refused with the reason
    let sys = float_abcd(t, path)?;
    // a complex system's response is not conjugate-symmetric: it is shown at -f as well
    let two_sided = matches!(sys, FloatAbcd::Complex(_));
    let values = points
        .saturating_mul(if two_sided { 2 } else { 1 })
        .saturating_mul(t.ss.noutputs())
        .saturating_mul(t.ss.ninputs());
    if values > MAX_RESPONSE_VALUES {
        return Err(Failure::limit(format!(
            "freqresp: {points} points x {} outputs x {} inputs = {values} complex values; at most {MAX_RESPONSE_VALUES} (lower --points to {} or fewer)",
            t.ss.noutputs(),
            t.ss.ninputs(),
            (MAX_RESPONSE_VALUES / (t.ss.noutputs() * t.ss.ninputs()).max(1)).max(2)
        )));
    }
    let mut freqs = logspace(from, to, points);
    if two_sided {
        freqs = freqs
            .iter()
            .rev()
            .map(|f| -f)
            .chain(freqs.iter().copied())
            .collect();
    }
    let resp = float_response_dt(t, &sys, path, &freqs, dt)?;
    let table = response_table(&resp);
    if let Some(p) = csv {
        std::fs::write(p, response_csv(&freqs, &table))
            .map_err(|e| Failure::input(format!("{}: cannot write: {e}", p.display())))?;
    }
    let resp_json = table
        .iter()
        .map(|g| {
            Value::List(
                g.iter()
                    .map(|row| {
                        Value::List(
                            row.iter()
                                .map(|(re, im)| {
                                    Value::List(vec![Value::Float(*re), Value::Float(*im)])
                                })
                                .collect(),
                        )
                    })
                    .collect(),
            )
        })
        .collect();
    let (header, rows) = bode_table(&freqs, &table, names);
    let mut rep = Report::titled("frequency response");
    if two_sided {
        rep = rep.bool("two_sided", true).str(
            "note",
            "complex system: G(-jw) is not the conjugate of G(jw), so the response is given at -f and +f (Hz), negative frequencies first",
        );
    }
    Ok(rep
        .with(
            "frequencies_hz",
            Value::hidden_in_text(Value::List(
                freqs.iter().map(|f| Value::Float(*f)).collect(),
            )),
        )
        .with(
            "response",
            Value::table(Value::List(resp_json), header, rows),
        ))
}

/// The text of a frequency response: per frequency (Hz), the magnitude (dB) and phase
/// (degrees, unwrapped along the frequencies) of each channel `output/input` (by name).
fn bode_table(
    freqs: &[f64],
    table: &Response,
    (inputs, outputs): (&[String], &[String]),
) -> (Vec<String>, Vec<Vec<String>>) {
    use crate::report::text::short;
    let (p, m) = table
        .first()
        .map_or((0, 0), |g| (g.len(), g.first().map_or(0, Vec::len)));
    let siso = p == 1 && m == 1;
    let mut header = vec!["frequency (Hz)".to_string()];
    for i in 0..p {
        for j in 0..m {
            if siso {
                header.push("magnitude (dB)".into());
                header.push("phase (deg)".into());
            } else {
                let ch = format!("{}/{}", outputs[i], inputs[j]);
                header.push(format!("{ch} (dB)"));
                header.push(format!("{ch} (deg)"));
            }
        }
    }
    let mut last: Vec<Option<f64>> = vec![None; p * m];
    let rows = freqs
        .iter()
        .zip(table)
        .map(|(f, g)| {
            let mut row = vec![short(*f)];
            for i in 0..p {
                for j in 0..m {
                    let (re, im) = g[i][j];
                    let mag = re.hypot(im);
                    let db = 20.0 * mag.log10();
                    let mut ph = im.atan2(re).to_degrees() + 0.0;
                    let k = i * m + j;
                    if let Some(prev) = last[k] {
                        ph += 360.0 * ((prev - ph) / 360.0).round();
                    }
                    if mag > 0.0 {
                        last[k] = Some(ph);
                    }
                    row.push(if mag > 0.0 {
                        format!("{db:.2}")
                    } else {
                        "-inf".into()
                    });
                    row.push(if mag > 0.0 {
                        format!("{:.1}", if ph.abs() < 0.05 { 0.0 } else { ph })
                    } else {
                        "-".into()
                    });
                }
            }
            row
        })
        .collect();
    (header, rows)
}

/// ERA (float) on the Markov parameters of the exact system, compared with the exact
/// McMillan degree: an order that contradicts it is flagged (`agree_with_exact: false`,
/// `truth: "false"`, no matrices) and exits 3 like `check`.
pub fn era<K: Field>(t: &Typed<K>, path: &Path, hankel: Option<usize>) -> Result<Report, Failure> {
    let tol = Tol::default();
    match float_abcd(t, path)? {
        FloatAbcd::Real([a, b, c, d]) => era_report(
            t,
            float::era_system(&a, &b, &c, &d, hankel, &tol).map_err(|e| fail(path, e))?,
        ),
        FloatAbcd::Complex([a, b, c, d]) => era_report(
            t,
            float::era_system(&a, &b, &c, &d, hankel, &tol).map_err(|e| fail(path, e))?,
        ),
    }
}

fn era_report<K: Field, T: FloatScalar>(
    t: &Typed<K>,
    r: float::SystemEra<T>,
) -> Result<Report, Failure> {
    let n = t.ss.nstates();
    let exact = realization::mcmillan_degree(&t.ss);
    let e = &r.realization;
    let agree = e.order == exact;
    let g = &e.rank_gap;
    let mut rep = Report::titled("minimal realization (era, float)")
        .str("method", "era")
        .int("original_order", n)
        .int("order", e.order)
        .int("mcmillan_degree", exact)
        .bool("agree_with_exact", agree)
        .str("truth", claim_str(agree, e.truth))
        .int("hankel_blocks", e.hankel_blocks.0)
        .with(
            "hankel_ranks",
            Value::List(
                r.ranks
                    .iter()
                    .map(|(k, rk)| Value::List(vec![Value::Int(*k as i64), Value::Int(*rk as i64)]))
                    .collect(),
            ),
        )
        .bool("rank_stabilised", r.stabilised)
        .float("time_scale", r.time_scale)
        .float("kept_singular_value", g.kept)
        .float("dropped_singular_value", g.dropped)
        .float("gap_ratio", g.ratio);
    if agree {
        for (name, m) in [("A", &e.a), ("B", &e.b), ("C", &e.c), ("D", &e.d)] {
            rep = dm_report(rep, name, m);
        }
    }
    Ok(rep.bool("verified", false).bool("exact", false).str(
        "note",
        if agree {
            "ERA is a float method: nothing is verified exactly; mcmillan_degree is the exact Hankel rank"
        } else {
            "the float ERA order contradicts the exact McMillan degree: no realization is given"
        },
    ))
}

/// Float path beside the exact path.
pub fn check<K: crate::io::GroundField>(t: &Typed<K>, path: &Path) -> Result<Report, Failure> {
    let tol = Tol::default();
    let (items, skipped) = match float_abcd(t, path)? {
        FloatAbcd::Real(m) => {
            let (mut items, skipped) = real_items(t, path, &m, &tol)?;
            // the exact Jordan structure of the real A over its field against the float guess
            if let Some(n) = K::numeric(t) {
                items.extend(super::float_compare::jordan_comparison(&n.a_raw, path)?);
            }
            (items, skipped)
        }
        FloatAbcd::Complex(m) => super::float_compare::complex_items(t, path, &m, &tol)?,
    };
    check_report(items, skipped, &tol)
}

/// `check`'s comparisons for a real float image.
fn real_items<K: Field>(
    t: &Typed<K>,
    path: &Path,
    [a, b, c, d]: &[DMatrix<f64>; 4],
    tol: &Tol,
) -> Result<Items, Failure> {
    let tol = *tol;
    let s = &t.ss;
    let mut items: Vec<(String, bool, Report)> = vec![];
    let mut skipped: Vec<(&str, String)> = vec![];
    if s.ninputs() > 0 && s.noutputs() > 0 {
        // the exact minimal order is the McMillan degree: the rank of the n x n block
        // Hankel matrix, far cheaper than a verified minimal realization (40 s on a
        // 1-state, 20000-input, 200-output system)
        let exact_order = realization::mcmillan_degree(s);
        // an exact count against the float one and the float side's own claim
        let count = |name: &str, exact: usize, float: usize, truth| {
            let ok = exact == float;
            (
                name.into(),
                ok,
                Report::new()
                    .int("exact", exact)
                    .int("float", float)
                    .str("float_truth", claim_str(ok, truth)),
            )
        };
        let fm = float::minreal(a, b, c, d, &tol).map_err(|e| fail(path, e))?;
        items.push(count("minreal_order", exact_order, fm.order, fm.truth));
        let rc = realization::controllability_matrix(&s.a, &s.b).rank();
        let frc = float::controllability_rank(a, b, &tol).map_err(|e| fail(path, e))?;
        items.push(count("controllability_rank", rc, frc.rank, frc.truth));
        let ro = realization::observability_matrix(&s.a, &s.c).rank();
        let fro = float::observability_rank(a, c, &tol).map_err(|e| fail(path, e))?;
        items.push(count("observability_rank", ro, fro.rank, fro.truth));
        // too large for the float ERA: said (skipped), not silently dropped
        let era = float::era_system(a, b, c, d, None, &tol);
        super::float_compare::era_order_item(era, exact_order, &mut items, &mut skipped);
        // the float zeros compress the (n + p) x (n + m) system matrix with dense
        // orthogonal factors: GBs on very wide or tall systems, so those are skipped, said
        let side = s.nstates() + s.ninputs().max(s.noutputs());
        if side > MAX_FLOAT_ZEROS_SIDE {
            skipped.push((
                "invariant_zero_count",
                format!(
                    "the float zeros of a {} x {} system matrix exceed the size limit ({MAX_FLOAT_ZEROS_SIDE} rows or columns)",
                    s.nstates() + s.noutputs(),
                    s.nstates() + s.ninputs()
                ),
            ));
        } else if let Ok(z) = crate::structure::zeros::invariant_zeros(&s.a, &s.b, &s.c, &s.d)
            && let Ok(fz) = float::invariant_zeros_report(a, b, c, d, &tol)
        {
            let ez = z.count();
            let mut rep = Report::new()
                .int("exact", ez)
                .int("float", fz.zeros.len())
                .str("float_truth", claim_str(ez == fz.zeros.len(), fz.truth));
            // values: each float zero against the nearest exact zero (certified roots)
            if let Some(zq) = z.polynomial.to_rational_poly()
                && let Ok(rs) = crate::algebraic::roots(&zq)
            {
                let exact: Vec<(f64, f64)> = rs.iter().map(|(r, _)| r.approx()).collect();
                let worst = fz
                    .zeros
                    .iter()
                    .map(|w| {
                        exact
                            .iter()
                            .map(|e| (e.0 - w.re).hypot(e.1 - w.im))
                            .fold(f64::INFINITY, f64::min)
                    })
                    .fold(0.0, f64::max);
                rep = rep.float("max_float_zero_error", worst);
            }
            items.push(("invariant_zero_count".into(), ez == fz.zeros.len(), rep));
        }
    }
    Ok((items, skipped))
}

fn check_report(
    items: Vec<(String, bool, Report)>,
    skipped: Vec<(&str, String)>,
    tol: &Tol,
) -> Result<Report, Failure> {
    let agree = items.iter().all(|(_, ok, _)| *ok);
    let differences = items
        .iter()
        .filter(|(_, ok, _)| !ok)
        .map(|(k, _, r)| {
            Value::Obj(
                Report::new()
                    .str("quantity", k.clone())
                    .with("detail", Value::Obj(r.clone())),
            )
        })
        .collect();
    let mut rep = Report::titled("float path vs exact path")
        .bool("agree", agree)
        .with("differences", Value::List(differences));
    let mut cmp = Report::new();
    for (k, ok, r) in items {
        cmp.push(k, Value::Obj(r.bool("agree", ok)));
    }
    if !skipped.is_empty() {
        let mut sk = Report::new();
        for (k, why) in skipped {
            sk.push(k, Value::Str(why));
        }
        rep = rep.obj("skipped", sk);
    }
    rep = rep.obj("comparisons", cmp).str(
        "tolerance",
        format!("rel {:e}, gap {:e} (float::Tol::default)", tol.rel, tol.gap),
    );
    Ok(rep)
}
