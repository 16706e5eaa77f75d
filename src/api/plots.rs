//! Plot commands and plot outputs: `pzmap`, `step`, `impulse`, and the Bode SVG of
//! `freqresp --svg` (magnitude and unwrapped phase on a frequency grid refined near lightly
//! damped poles; over negative and positive frequencies for a system with complex
//! coefficients, as MATLAB draws it). Titles and channel names come from the system file's `name`, `inputs`,
//! `outputs`.

use super::Failure;
use super::common::with_path;
use crate::field::Field;
use crate::float::{self, FloatScalar, to_cmatrix, to_dmatrix};
use crate::io::{GroundField, SystemFile, TypedSystem};
use crate::jordan::EigenField;
use crate::report::plot::bode::{bode_svg, bode_svg_two_sided};
use crate::report::plot::pzmap::{Point, pzmap_svg};
use crate::report::plot::time::{TimePlot, time_response_svg};
use crate::report::plot::{logspace, response_table};
use crate::report::{Report, Value};
use crate::system::time_response::{
    ClosedFormResponse, default_horizon, default_points, time_grid,
};
use nalgebra::DMatrix;
use std::path::Path;

/// The system's title (`name`, else the file name) and its input and output names (`u1`,
/// `y1`, ... where the file gives none).
pub fn names(
    f: &SystemFile,
    path: &Path,
    m: usize,
    p: usize,
) -> (String, Vec<String>, Vec<String>) {
    let title = f.name.clone().unwrap_or_else(|| path.display().to_string());
    let pick = |given: &Option<Vec<String>>, n: usize, base: &str| -> Vec<String> {
        match given {
            Some(v) if v.len() == n => v.clone(),
            _ => (1..=n).map(|k| format!("{base}{k}")).collect(),
        }
    };
    (
        title,
        pick(&f.signals.inputs, m, "u"),
        pick(&f.signals.outputs, p, "y"),
    )
}

fn write(p: &Path, text: &str) -> Result<(), Failure> {
    std::fs::write(p, text)
        .map_err(|e| Failure::input(format!("{}: cannot write: {e}", p.display())))
}

fn abcd<K: Field>(t: &TypedSystem<K>, path: &Path) -> Result<[DMatrix<f64>; 4], Failure> {
    let s = &t.ss;
    let conv = |m| to_dmatrix(m).map_err(|e| with_path(path, e));
    Ok([conv(&s.a)?, conv(&s.b)?, conv(&s.c)?, conv(&s.d)?])
}

/// Whether an entry of `A`, `B`, `C`, `D` is not real (a system over $\mathbb{Q}(i)$).
fn is_complex<K: Field>(t: &TypedSystem<K>) -> bool {
    let s = &t.ss;
    [&s.a, &s.b, &s.c, &s.d].iter().any(|m| {
        let k = m.field();
        (0..m.nrows())
            .any(|i| (0..m.ncols()).any(|j| k.approx(m.get(i, j)).is_some_and(|z| z.1 != 0.0)))
    })
}

/// The float time response of every channel, `[time][output][input]`.
fn float_time<T: FloatScalar>(
    [a, b, c, d]: &[DMatrix<T>; 4],
    impulse: bool,
    times: &[f64],
) -> crate::Result<Vec<Vec<Vec<T>>>> {
    let input = if impulse {
        float::Input::Impulse
    } else {
        float::Input::Step
    };
    let r = float::time_response(input, [a, b, c, d], times)?;
    Ok(r.iter()
        .map(|m| {
            (0..m.nrows())
                .map(|i| (0..m.ncols()).map(|j| m[(i, j)]).collect())
                .collect()
        })
        .collect())
}

fn float_poles(a: &DMatrix<f64>, path: &Path) -> Result<Vec<(f64, f64)>, Failure> {
    if a.nrows() == 0 {
        return Ok(vec![]);
    }
    Ok(float::eigenvalues(a)
        .map_err(|e| with_path(path, e))?
        .into_iter()
        .map(|z| (z.re, z.im))
        .collect())
}

/// The Bode plot's grid: `points` log-spaced frequencies plus, near each lightly damped pole
/// (damping ratio < 0.5) with natural frequency in range, 41 points across
/// `f_n (1 +- 8 zeta)` (the resonance peak has half-power width about `2 zeta f_n`).
pub fn bode_grid(from: f64, to: f64, points: usize, poles: &[(f64, f64)]) -> Vec<f64> {
    let mut f = logspace(from, to, points);
    for &(re, im) in poles {
        let wn = re.hypot(im);
        if im <= 0.0 || wn <= 0.0 {
            continue; // one of each conjugate pair; real poles have no peak
        }
        let zeta = (-re / wn).max(1e-9);
        if zeta >= 0.5 {
            continue;
        }
        let fnat = wn / (2.0 * std::f64::consts::PI);
        for k in -20..=20 {
            let x = fnat * (1.0 + 8.0 * zeta * k as f64 / 20.0);
            if x >= from && x <= to {
                f.push(x);
            }
        }
    }
    f.sort_by(f64::total_cmp);
    f.dedup_by(|a, b| (*a - *b).abs() <= 1e-12 * b.abs());
    f
}

/// The two-sided grid of a complex system's Bode plot: the negative frequencies (increasing)
/// then the positive ones, each side a [`bode_grid`] refined near the lightly damped poles
/// whose resonance lies on that side (a pole $a + ib$ peaks at $\omega = b$).
pub fn bode_grid_two_sided(from: f64, to: f64, points: usize, poles: &[(f64, f64)]) -> Vec<f64> {
    let mirrored: Vec<(f64, f64)> = poles.iter().map(|&(re, im)| (re, -im)).collect();
    let neg = bode_grid(from, to, points, &mirrored);
    let pos = bode_grid(from, to, points, poles);
    neg.iter().rev().map(|f| -f).chain(pos).collect()
}

/// The frequency range of `freqresp` (Hz): as given, else chosen from the poles and the
/// invariant zeros ([`crate::report::plot::bode::default_range`]).
pub fn bode_range<K: Field>(
    t: &TypedSystem<K>,
    path: &Path,
    from: Option<f64>,
    to: Option<f64>,
) -> Result<(f64, f64), Failure> {
    if let (Some(a), Some(b)) = (from, to) {
        return Ok((a, b));
    }
    let mut pts = vec![];
    let pairs = |v: Vec<nalgebra::Complex<f64>>| v.into_iter().map(|z| (z.re, z.im));
    // the range only frames the plot: a float failure leaves those points out
    match &super::float_cmds::float_abcd(t, path)? {
        super::float_cmds::FloatAbcd::Real([a, b, c, d]) => {
            if a.nrows() > 0 {
                pts.extend(float::eigenvalues(a).map(pairs).into_iter().flatten());
            }
            if b.ncols() > 0 && c.nrows() > 0 {
                let z = float::invariant_zeros(a, b, c, d, &float::Tol::default());
                pts.extend(z.map(pairs).into_iter().flatten());
            }
        }
        super::float_cmds::FloatAbcd::Complex([a, ..]) if a.nrows() > 0 => {
            let n = a.nrows();
            pts.extend(
                nalgebra::Schur::try_new(a.clone(), f64::EPSILON, 200 * n.max(10))
                    .and_then(|s| s.eigenvalues())
                    .map_or_else(Vec::new, |v| v.iter().map(|z| (z.re, z.im)).collect()),
            );
        }
        super::float_cmds::FloatAbcd::Complex(_) => {}
    }
    let (lo, hi) = crate::report::plot::bode::default_range(&pts);
    Ok(match (from, to) {
        (Some(a), None) => (a, if hi > a { hi } else { a * 1000.0 }),
        (None, Some(b)) => (if lo < b { lo } else { b / 1000.0 }, b),
        _ => (lo, hi),
    })
}

/// Writes the Bode SVG of `freqresp --svg`: one-sided for a real system, over negative and
/// positive frequencies for a complex one.
pub fn bode_file<K: Field>(
    f: &SystemFile,
    t: &TypedSystem<K>,
    path: &Path,
    (from, to, points): (f64, f64, usize),
    out: &Path,
) -> Result<(), Failure> {
    let (title, ins, outs) = names(f, path, t.ss.ninputs(), t.ss.noutputs());
    let labels: Vec<Vec<String>> = outs
        .iter()
        .map(|o| ins.iter().map(|i| format!("{i} \u{2192} {o}")).collect())
        .collect();
    let title = format!("{title}: Bode plot");
    let sys = super::float_cmds::float_abcd(t, path)?;
    let text = match &sys {
        super::float_cmds::FloatAbcd::Complex([a, ..]) => {
            // the poles only refine the grid: none when the complex Schur form fails
            let n = a.nrows();
            let poles: Vec<(f64, f64)> = if n == 0 {
                vec![]
            } else {
                nalgebra::Schur::try_new(a.clone(), f64::EPSILON, 200 * n.max(10))
                    .and_then(|s| s.eigenvalues())
                    .map_or_else(Vec::new, |v| v.iter().map(|z| (z.re, z.im)).collect())
            };
            let freqs = bode_grid_two_sided(from, to, points, &poles);
            let resp = super::float_cmds::float_response(t, &sys, path, &freqs)?;
            bode_svg_two_sided(&freqs, &response_table(&resp), &title, &labels)
        }
        super::float_cmds::FloatAbcd::Real([a, ..]) => {
            let poles = float_poles(a, path)?;
            let freqs = bode_grid(from, to, points, &poles);
            let resp = super::float_cmds::float_response(t, &sys, path, &freqs)?;
            let table = response_table(&resp);
            if ins.len() * outs.len() > 1 {
                // MIMO: an output x input grid of magnitude and phase panels
                let g = crate::report::plot::bode_grid::bode_grid_svg;
                g(&freqs, &table, &title, (&ins, &outs), &[])
            } else {
                bode_svg(&freqs, &table, &title, &labels)
            }
        }
    };
    write(out, &text)
}

/// A pole or zero: exact (or float) display, approximation, multiplicity.
type Root = (String, (f64, f64), usize);

/// Roots of a polynomial over an [`EigenField`] ($\mathbb{Q}$, $\mathbb{Q}(\sqrt d)$,
/// $\mathbb{Q}(i)$) as `(value, approx, multiplicity)`, certified: per irreducible factor
/// over the field, its roots (those of the polynomial, not of its conjugate); real ones
/// ascending, then complex ones by real and imaginary part.
fn exact_roots_over<F: EigenField>(p: &crate::poly::Poly<F>) -> crate::Result<Vec<Root>> {
    Ok(super::poles::roots_over(p)?
        .into_iter()
        .map(|(z, approx, e)| (z.value_string(), approx, e))
        .collect())
}

/// Poles and invariant zeros of a system over an [`EigenField`], exact.
fn exact_poles_zeros<F: EigenField>(
    s: &crate::system::StateSpace<F>,
) -> crate::Result<(Vec<Root>, Vec<Root>)> {
    let chi = s.a.charpoly()?;
    let z = crate::structure::zeros::invariant_zeros(&s.a, &s.b, &s.c, &s.d)?;
    Ok((exact_roots_over(&chi)?, exact_roots_over(&z.polynomial)?))
}

/// Float values grouped into distinct points with multiplicities (by a relative distance).
fn group(values: &[(f64, f64)]) -> Vec<Root> {
    let mut out: Vec<Root> = vec![];
    let scale = 1.0 + values.iter().map(|z| z.0.hypot(z.1)).fold(0.0, f64::max);
    for &(re, im) in values {
        if let Some(e) = out
            .iter_mut()
            .find(|e| (e.1.0 - re).hypot(e.1.1 - im) <= 1e-7 * scale)
        {
            e.2 += 1;
        } else {
            out.push((format!("{re} {im:+}i"), (re, im), 1));
        }
    }
    out
}

fn point_items(xs: &[Root]) -> Vec<Value> {
    xs.iter()
        .map(|(v, (re, im), mult)| {
            Value::Obj(
                Report::new()
                    .str("value", v.clone())
                    .with(
                        "approx",
                        Value::List(vec![Value::Float(*re), Value::Float(*im)]),
                    )
                    .int("multiplicity", *mult),
            )
        })
        .collect()
}

/// `pzmap`: the poles (eigenvalues of `A`) and the invariant zeros, exact over Q, Q(sqrt d)
/// and Q(i) (certified algebraic numbers; over a non-real field the roots of `A`'s own
/// factors, not of its conjugate's), float otherwise; `--svg` draws the map.
pub fn pzmap<K: GroundField>(
    f: &SystemFile,
    t: &TypedSystem<K>,
    path: &Path,
    svg: Option<&Path>,
) -> Result<Report, Failure> {
    let e = |err| with_path(path, err);
    let s = &t.ss;
    let exact = match K::numeric(t) {
        Some(n) => Some(exact_poles_zeros(&n.ss).map_err(e)?),
        None => None,
    };
    let (poles, zeros, exact) = match exact {
        Some((p, z)) => (p, z, true),
        None => {
            let [a, b, c, d] = abcd(t, path)?;
            let z = if s.ninputs() > 0 && s.noutputs() > 0 {
                float::invariant_zeros(&a, &b, &c, &d, &float::Tol::default())
                    .map_err(e)?
                    .into_iter()
                    .map(|z| (z.re, z.im))
                    .collect()
            } else {
                vec![]
            };
            (group(&float_poles(&a, path)?), group(&z), false)
        }
    };
    let (title, _, _) = names(f, path, s.ninputs(), s.noutputs());
    if let Some(out) = svg {
        let pts = |xs: &[Root]| -> Vec<Point> {
            xs.iter().map(|(_, (re, im), k)| (*re, *im, *k)).collect()
        };
        write(
            out,
            &pzmap_svg(
                &pts(&poles),
                &pts(&zeros),
                &format!("{title}: poles and zeros"),
            ),
        )?;
    }
    Ok(Report::titled(format!("poles and zeros: {title}"))
        .str("name", title)
        .bool("exact", exact)
        .int("pole_count", poles.iter().map(|p| p.2).sum())
        .int("zero_count", zeros.iter().map(|p| p.2).sum())
        .list("poles", point_items(&poles))
        .list("zeros", point_items(&zeros)))
}

/// Options of `step` and `impulse`.
pub struct TimeArgs<'a> {
    pub impulse: bool,
    pub to: Option<f64>,
    pub points: Option<usize>,
    pub svg: Option<&'a Path>,
    pub csv: Option<&'a Path>,
    pub float_only: bool,
}

/// The float matrices of a system: real, or complex (over $\mathbb{Q}(i)$).
enum Mats {
    Real([DMatrix<f64>; 4]),
    Complex([DMatrix<num_complex::Complex<f64>>; 4]),
}

/// Most values (points x outputs x inputs) of a time response.
pub const MAX_TIME_VALUES: usize = 1_000_000;

/// `step` / `impulse`: the response of every channel on an even time grid; from the exact
/// closed form (Jordan form of `A`) over its field (Q, Q(sqrt d), Q(i)), with the float
/// matrix-exponential recursion beside it (`float_max_difference`); float only with `--float`.
pub fn time_response<K: GroundField>(
    f: &SystemFile,
    t: &TypedSystem<K>,
    path: &Path,
    args: &TimeArgs<'_>,
) -> Result<(Report, bool), Failure> {
    let what = if args.impulse {
        "impulse response"
    } else {
        "step response"
    };
    let s = &t.ss;
    let (p, m) = (s.noutputs(), s.ninputs());
    if args.points.is_some_and(|n| !(2..=100_000).contains(&n))
        || args.to.is_some_and(|x| !(x.is_finite() && x > 0.0))
    {
        return Err(Failure::input(format!(
            "{what}: need 2 <= --points <= 100000 and --to > 0 seconds (got --points {}, --to {})",
            args.points.map_or("default".into(), |n| n.to_string()),
            args.to.map_or("default".into(), |x| x.to_string())
        )));
    }
    if p == 0 || m == 0 {
        return Err(Failure::input(format!(
            "{}: a {what} needs at least one input and one output (B and C)",
            path.display()
        )));
    }
    let complex = is_complex(t);
    let e = |err| with_path(path, err);
    // a system with complex coefficients: complex matrices, a complex response (its poles
    // through the real form, whose eigenvalues are those of A and their conjugates: the
    // same real parts, so the same horizon and stability)
    let mats = if complex {
        let s = &t.ss;
        let conv = |m| to_cmatrix(m).map_err(e);
        Mats::Complex([conv(&s.a)?, conv(&s.b)?, conv(&s.c)?, conv(&s.d)?])
    } else {
        Mats::Real(abcd(t, path)?)
    };
    let a_real = match &mats {
        Mats::Real(m) => m[0].clone(),
        Mats::Complex(m) => FloatScalar::realify(&m[0]),
    };
    let poles = float_poles(&a_real, path)?;
    let t_end = args.to.unwrap_or_else(|| default_horizon(&poles));
    let points = args.points.unwrap_or_else(|| default_points(t_end, &poles));
    let values = points.saturating_mul(p).saturating_mul(m);
    if values > MAX_TIME_VALUES {
        return Err(Failure::limit(format!(
            "{what}: {points} points x {p} outputs x {m} inputs = {values} values; at most {MAX_TIME_VALUES} (lower --points)"
        )));
    }
    let times = time_grid(t_end, points);
    let (fl, imag) = match &mats {
        Mats::Complex(m) => {
            let z = float_time(m, args.impulse, &times).map_err(e)?;
            let part = |f: fn(&num_complex::Complex<f64>) -> f64| -> Vec<Vec<Vec<f64>>> {
                z.iter()
                    .map(|g| g.iter().map(|r| r.iter().map(f).collect()).collect())
                    .collect()
            };
            (part(|x| x.re), Some(part(|x| x.im)))
        }
        Mats::Real(m) => (float_time(m, args.impulse, &times).map_err(e)?, None),
    };
    let exact = match K::numeric(t) {
        Some(n) if !args.float_only => Some(ClosedFormResponse::new(&n.ss).map_err(e)?),
        _ => None,
    };
    let (vals, imag): (Vec<Vec<Vec<f64>>>, _) = match &exact {
        Some(cf) => {
            let z: Vec<_> = times
                .iter()
                .map(|&x| {
                    if args.impulse {
                        cf.impulse_at_complex(x)
                    } else {
                        cf.step_at_complex(x)
                    }
                })
                .collect();
            let part = |f: fn(&num_complex::Complex<f64>) -> f64| -> Vec<Vec<Vec<f64>>> {
                z.iter()
                    .map(|g| g.iter().map(|r| r.iter().map(f).collect()).collect())
                    .collect()
            };
            // over a field that is not real the exact response is complex too
            (part(|x| x.re), imag.map(|_| part(|x| x.im)))
        }
        None => (fl.clone(), imag),
    };
    let (title, ins, outs) = names(f, path, m, p);
    let stable = poles.iter().all(|z| z.0 < 0.0);
    let mut rep = Report::titled(format!("{what}: {title}"))
        .str("name", title.clone())
        .str(
            "method",
            match (exact.is_some(), complex) {
                (true, false) => {
                    "exact closed form from the Jordan form of A, evaluated in floating point"
                }
                (true, true) => {
                    "exact closed form from the Jordan form of A over its field, evaluated in floating point; response holds the real parts, response_imag the imaginary parts"
                }
                (false, false) => {
                    "float: matrix exponential of [[A, B], [0, 0]] dt (zero-order hold)"
                }
                (false, true) => {
                    "float, complex coefficients: complex matrix exponential of [[A, B], [0, 0]] dt (zero-order hold); response holds the real parts, response_imag the imaginary parts"
                }
            },
        )
        .list(
            "inputs",
            ins.iter().map(|x| Value::Str(x.clone())).collect(),
        )
        .list(
            "outputs",
            outs.iter().map(|x| Value::Str(x.clone())).collect(),
        );
    let mut final_line: Option<Vec<Vec<f64>>> = None;
    let mut verified = true;
    if let Some(cf) = &exact {
        verified = cf.verified;
        rep = rep.bool("verified", cf.verified);
        if args.impulse {
            rep = rep.matrix("initial_value", &cf.impulse_at_zero);
            if !cf.d.is_zero() {
                rep = rep.str(
                    "note",
                    "D delta(t) (the feedthrough times an impulse) is left out",
                );
            }
        } else if let Some(g) = &cf.dc_gain {
            rep = rep.matrix("dc_gain", g);
            if stable {
                final_line = Some(
                    (0..p)
                        .map(|i| {
                            (0..m)
                                .map(|j| g.field().approx(g.get(i, j)).map_or(f64::NAN, |z| z.0))
                                .collect()
                        })
                        .collect(),
                );
            }
        }
        let diff = vals
            .iter()
            .zip(&fl)
            .flat_map(|(x, y)| x.iter().flatten().zip(y.iter().flatten()))
            .map(|(x, y)| (x - y).abs() / (1.0 + x.abs()))
            .fold(0.0, f64::max);
        rep = rep.float("float_max_difference", diff);
    }
    rep = rep.bool("stable", stable);
    // a complex response: its real and imaginary parts as channels of their own
    let (plot_vals, plot_outs) = match &imag {
        None => (vals.clone(), outs.clone()),
        Some(im) => {
            rep = rep.list("response_imag", response_values(im));
            let names = outs.iter().map(|o| format!("Re {o}"));
            let names = names.chain(outs.iter().map(|o| format!("Im {o}")));
            let rows = vals
                .iter()
                .zip(im)
                .map(|(r, i)| r.iter().chain(i).cloned().collect());
            (rows.collect(), names.collect())
        }
    };
    let plot = TimePlot {
        title: &format!("{title}: {what}"),
        what,
        times: &times,
        values: &plot_vals,
        inputs: &ins,
        outputs: &plot_outs,
        final_values: final_line.as_deref(),
        final_label: "final value (exact DC gain)",
        stairs: false,
    };
    write_files(&plot, args)?;
    Ok((
        rep.list("times_s", times.iter().map(|x| Value::Float(*x)).collect())
            .list("response", response_values(&vals)),
        verified,
    ))
}

/// `[time][output][input]` values as report lists.
fn response_values(v: &[Vec<Vec<f64>>]) -> Vec<Value> {
    v.iter()
        .map(|g| {
            Value::List(
                g.iter()
                    .map(|r| Value::List(r.iter().map(|x| Value::Float(*x)).collect()))
                    .collect(),
            )
        })
        .collect()
}

/// `--svg` and `--csv` of a time response (one column per channel `input -> output`).
fn write_files(plot: &TimePlot<'_>, args: &TimeArgs<'_>) -> Result<(), Failure> {
    if let Some(out) = args.svg {
        write(out, &time_response_svg(plot))?;
    }
    if let Some(out) = args.csv {
        let mut text = String::from("time_s");
        for o in plot.outputs {
            for i in plot.inputs {
                text.push_str(&format!(",{}", csv_field(&format!("{i} -> {o}"))));
            }
        }
        text.push('\n');
        for (k, x) in plot.times.iter().enumerate() {
            text.push_str(&format!("{x}"));
            for v in plot.values[k].iter().flatten() {
                text.push_str(&format!(",{v}"));
            }
            text.push('\n');
        }
        write(out, &text)?;
    }
    Ok(())
}

/// A CSV field, quoted when it holds a comma, quote or line break.
fn csv_field(s: &str) -> String {
    if s.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}
