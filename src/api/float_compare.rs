//! `check`'s float-vs-exact comparisons: the labels of float claims ([`claim_str`]), the
//! Jordan structure of a real `A` ([`jordan_comparison`]), and the comparisons for a
//! system with complex entries (over $\mathbb{Q}(i)$ or $\mathbb{Q}(\sqrt{-d})$,
//! [`complex_items`]).
//!
//! The float staircases are real; they see the complex system through its real form
//! ([`FloatScalar::realify`]: $M = X + iY \mapsto \begin{bmatrix} X & -Y \\ Y & X
//! \end{bmatrix}$), a ring homomorphism whose singular values are those of $M$ each twice.
//! So the real form's minimal order, controllability and observability ranks and number of
//! invariant zeros are twice the complex ones (an odd float count is a disagreement). ERA runs
//! on the complex Markov parameters (complex Jacobi SVD). The eigenvalues are compared
//! through the real form too: over $\mathbb{Q}(i)$ the real form of $A$ is a rational
//! matrix whose exact Jordan form (the structures of $A$ and $\bar A$ together) is compared
//! with the float guess by [`jordan_comparison`]; over $\mathbb{Q}(\sqrt{-d})$, $d \ne 1$,
//! the exact spectrum of the real form comes from the Jordan form of $A$ over $K$ and its
//! conjugate ([`real_form_spectrum`]). The frequency response is compared with
//! the exact $G(s)$ at points $s$ of the imaginary axis that lie in the field
//! ([`MAX_EXACT_RESPONSE_STATES`]).
//!
//! A float claim is `true` only when its own test is clear and the exact path agrees; a
//! disagreement makes `check` exit 3.

use super::Failure;
use crate::field::{Field, Q};
use crate::float::{self, FloatScalar, Tol, Truth, to_dmatrix};
use crate::io::TypedSystem as Typed;
use crate::io::{GroundField, NumericField};
use crate::matrix::Matrix;
use crate::realization;
use crate::report::{Report, Value};
use nalgebra::DMatrix;
use num_complex::Complex;
use std::path::Path;

/// One comparison: (name, agree, detail).
pub(crate) type Item = (String, bool, Report);

/// The comparisons made and the ones skipped (name, reason).
pub(crate) type Items = (Vec<Item>, Vec<(&'static str, String)>);

fn fail(path: &Path, e: crate::error::Error) -> Failure {
    Failure::from(e).in_file(path)
}

/// The label of a float claim beside the exact answer: a claim the exact path refutes is
/// `"false"`, never `"true"`, whatever its own gap test said.
pub(crate) fn claim_str(agree: bool, t: Truth) -> &'static str {
    match (agree, t) {
        (true, t) => truth_str(t),
        (false, Truth::Unknown) => "unknown",
        (false, _) => "false",
    }
}

fn truth_str(t: Truth) -> &'static str {
    match t {
        Truth::True => "true",
        Truth::False => "false",
        Truth::Unknown => "unknown",
    }
}

/// One exact eigenvalue for [`spectrum_comparison`]: display, approximation, Jordan block
/// sizes (largest first; the algebraic multiplicity is their sum).
pub(crate) type ExactEigenvalue = (String, (f64, f64), Vec<usize>);

/// Eigenvalues and Jordan structure: exact (a real `A` over its field, $\mathbb{Q}$ or
/// $\mathbb{Q}(\sqrt d)$, written once) against the float guess.
pub fn jordan_comparison<F: crate::jordan::EigenField>(
    a_exact: &crate::matrix::Matrix<F>,
    path: &Path,
) -> Result<Vec<(String, bool, Report)>, Failure> {
    let jf = crate::jordan::jordan_over(a_exact).map_err(|e| fail(path, e))?;
    let a = to_dmatrix(a_exact).map_err(|e| fail(path, e))?;
    let exact: Vec<ExactEigenvalue> = jf
        .eigenvalues
        .iter()
        .map(|ev| {
            (
                crate::report::sections::eigenvalue_text(ev),
                ev.approx,
                ev.blocks.clone(),
            )
        })
        .collect();
    Ok(vec![spectrum_comparison(&exact, &a, jf.verified, path)?])
}

/// The item `jordan_structure`: each exact eigenvalue against the nearest cluster of the
/// float Jordan guess of `a` (within $10^{-6}(1 + \lVert A \rVert)$, same algebraic
/// multiplicity and block sizes).
pub(crate) fn spectrum_comparison(
    exact: &[ExactEigenvalue],
    a: &DMatrix<f64>,
    exact_verified: bool,
    path: &Path,
) -> Result<Item, Failure> {
    let tol = Tol::default();
    let fj = float::jordan_guess(a, &tol).map_err(|e| fail(path, e))?;
    let scale = 1.0 + fj.norm;
    let mut worst = 0.0f64;
    let mut structure_ok = true;
    let mut rows = vec![];
    for (value, (re, im), blocks) in exact {
        let (re, im) = (*re, *im);
        let nearest = fj.clusters.iter().min_by(|x, y| {
            let dx = (x.center.re - re).hypot(x.center.im - im);
            let dy = (y.center.re - re).hypot(y.center.im - im);
            dx.total_cmp(&dy)
        });
        let Some(c) = nearest else { continue };
        let dist = (c.center.re - re).hypot(c.center.im - im);
        // the spread of the computed members around the exact value
        let spread = c
            .members
            .iter()
            .map(|z| (z.re - re).hypot(z.im - im))
            .fold(0.0, f64::max);
        worst = worst.max(spread);
        let same = dist <= 1e-6 * scale
            && c.algebraic_multiplicity == blocks.iter().sum::<usize>()
            && &c.block_sizes == blocks;
        structure_ok &= same;
        let ints = |v: &[usize]| Value::List(v.iter().map(|&b| Value::Int(b as i64)).collect());
        rows.push(Value::Obj(
            Report::new()
                .str("eigenvalue", value.clone())
                .with("exact_blocks", ints(blocks))
                .with("float_blocks", ints(&c.block_sizes))
                .float("float_center_distance", dist)
                .float("float_member_spread", spread)
                .str("float_truth", claim_str(same, c.truth))
                .bool("agree", same),
        ));
    }
    let warnings = Value::List(fj.warnings.iter().map(|w| Value::Str(w.clone())).collect());
    Ok((
        "jordan_structure".to_string(),
        structure_ok,
        Report::new()
            .with("eigenvalues", Value::List(rows))
            .float("max_float_eigenvalue_error", worst)
            .with("float_warnings", warnings)
            .bool("exact_verified", exact_verified),
    ))
}

/// Largest `n + max(m, p)` for which `check` runs the float invariant zeros (their dense
/// orthogonal factors are side x side: 2000 is 32 MB each).
pub const MAX_FLOAT_ZEROS_SIDE: usize = 2000;

/// The `era_order` item: the float ERA's order against the exact McMillan degree, with
/// its Hankel size, gap ratio and truth; an ERA refused (too large) is listed in `skipped`.
pub(crate) fn era_order_item<T: FloatScalar>(
    era: crate::Result<float::SystemEra<T>>,
    exact_order: usize,
    items: &mut Vec<Item>,
    skipped: &mut Vec<(&'static str, String)>,
) {
    match era {
        Ok(r) => {
            let e = &r.realization;
            let ok = e.order == exact_order;
            items.push((
                "era_order".into(),
                ok,
                Report::new()
                    .int("exact", exact_order)
                    .int("float", e.order)
                    .int("hankel_blocks", e.hankel_blocks.0)
                    .float("gap_ratio", e.rank_gap.ratio)
                    .str("float_truth", claim_str(ok, e.truth)),
            ));
        }
        Err(err) => skipped.push(("era_order", err.to_string())),
    }
}

/// A float count of the real form, halved: `None` when odd (no complex count doubles to it).
fn half(n: usize) -> Option<usize> {
    n.is_multiple_of(2).then_some(n / 2)
}

fn count_item(exact: usize, real_form: usize, truth: float::Truth) -> (bool, Report) {
    let ok = half(real_form) == Some(exact);
    let mut r = Report::new()
        .int("exact", exact)
        .int("float_real_form", real_form);
    if let Some(h) = half(real_form) {
        r = r.int("float", h);
    }
    (ok, r.str("float_truth", claim_str(ok, truth)))
}

/// The exact spectrum of the real form $\begin{bmatrix} X & -Y \\ Y & X \end{bmatrix}$ of
/// $A = X + iY$ over $K = \mathbb{Q}(\sqrt d)$, $d < 0$ (`None` for another field), and
/// whether $A$'s Jordan form over $K$ verified. The real form is similar over $\mathbb{C}$
/// to $A \oplus \bar A$, so an eigenvalue $\mu$ has the blocks of $A$ at $\mu$ and at
/// $\bar\mu$: from the components of the Jordan form of $A$ over $K$
/// ([`crate::jordan::jordan_over`]), those of a factor $g$ and of $\bar g$
/// (coefficients conjugated in $K$, compared exactly).
fn real_form_spectrum<K: NumericField>(
    a: &Matrix<K>,
    path: &Path,
) -> Result<Option<(Vec<ExactEigenvalue>, bool)>, Failure> {
    let k = a.field();
    if k.is_real() {
        return Ok(None);
    }
    let jf = crate::jordan::jordan_over(a).map_err(|e| fail(path, e))?;
    let conj_of = |g: &crate::poly::Poly<K>| {
        let cs: Option<Vec<_>> = g.coeffs().iter().map(|c| k.conj(c)).collect();
        cs.map(|cs| crate::poly::Poly::new(k.clone(), cs))
    };
    // the component whose factor is the conjugate of component c's, if any
    let partner: Vec<Option<usize>> = jf
        .components
        .iter()
        .map(|c| {
            let gbar = conj_of(&c.factor)?;
            jf.components.iter().position(|o| o.factor == gbar)
        })
        .collect();
    let mut out = vec![];
    for ev in &jf.eigenvalues {
        // mu = ev: the blocks of A at mu and (when mu-bar is an eigenvalue of A) at mu-bar
        let mut blocks = ev.blocks.clone();
        if let Some(p) = partner[ev.component] {
            blocks.extend(jf.components[p].blocks.iter().copied());
        }
        blocks.sort_unstable_by(|x, y| y.cmp(x));
        out.push((
            crate::report::sections::eigenvalue_text(ev),
            ev.approx,
            blocks,
        ));
        if partner[ev.component].is_none() {
            // mu-bar is an eigenvalue of conj(A) only, with the blocks of A at mu
            let (re, im) = ev.approx;
            out.push((
                ev.number.conj().value_string(),
                (re, -im),
                ev.blocks.clone(),
            ));
        }
    }
    Ok(Some((out, jf.verified)))
}

/// The real form of a matrix over $\mathbb{Q}(i)$, exactly (each entry $x + yi$ read off
/// its [`Field::elem_value`]); `None` for another field.
fn exact_real_form<K: Field>(a: &Matrix<K>) -> Option<Matrix<Q>> {
    use crate::field::value::ElemValue;
    let k = a.field();
    let minus_one = num_bigint::BigInt::from(-1);
    let parts = a
        .as_slice()
        .iter()
        .map(|z| match k.elem_value(z)? {
            ElemValue::Rational(x) => Some((x, crate::field::Rational::from_integer(0.into()))),
            ElemValue::Quadratic { a, b, d } if d == minus_one => Some((a, b)),
            _ => None,
        })
        .collect::<Option<Vec<_>>>()?;
    let n = a.nrows();
    Some(Matrix::from_fn(Q, 2 * n, 2 * n, |i, j| {
        let (x, y) = &parts[(i % n) * n + j % n];
        match (i < n, j < n) {
            (true, true) | (false, false) => x.clone(),
            (true, false) => -y.clone(),
            (false, true) => y.clone(),
        }
    }))
}

/// The comparisons of `check` for a complex float image `[a, b, c, d]`, and the ones skipped
/// with the reason.
pub(crate) fn complex_items<K: GroundField>(
    t: &Typed<K>,
    path: &Path,
    [a, b, c, d]: &[DMatrix<Complex<f64>>; 4],
    tol: &Tol,
) -> Result<Items, Failure> {
    let s = &t.ss;
    let mut items: Vec<Item> = vec![];
    let mut skipped = vec![];
    let [ar, br, cr, dr] = [a, b, c, d].map(FloatScalar::realify);
    if s.ninputs() > 0 && s.noutputs() > 0 {
        let exact_order = realization::mcmillan_degree(s);
        let fm = float::minreal(&ar, &br, &cr, &dr, tol).map_err(|e| fail(path, e))?;
        let (ok, r) = count_item(exact_order, fm.order, fm.truth);
        items.push(("minreal_order".into(), ok, r));
        let rc = realization::controllability_matrix(&s.a, &s.b).rank();
        let frc = float::controllability_rank(&ar, &br, tol).map_err(|e| fail(path, e))?;
        let (ok, r) = count_item(rc, frc.rank, frc.truth);
        items.push(("controllability_rank".into(), ok, r));
        let ro = realization::observability_matrix(&s.a, &s.c).rank();
        let fro = float::observability_rank(&ar, &cr, tol).map_err(|e| fail(path, e))?;
        let (ok, r) = count_item(ro, fro.rank, fro.truth);
        items.push(("observability_rank".into(), ok, r));
        era_order_item(
            float::era_system(a, b, c, d, None, tol),
            exact_order,
            &mut items,
            &mut skipped,
        );
        let side = s.nstates() + s.ninputs().max(s.noutputs());
        if 2 * side > MAX_FLOAT_ZEROS_SIDE {
            skipped.push((
                "invariant_zero_count",
                "the real form's system matrix exceeds the float zeros' size limit".into(),
            ));
        } else if let Ok(z) = crate::structure::zeros::invariant_zeros(&s.a, &s.b, &s.c, &s.d)
            && let Ok(fz) = float::invariant_zeros_report(&ar, &br, &cr, &dr, tol)
        {
            let (ok, r) = count_item(z.count(), fz.zeros.len(), fz.truth);
            items.push(("invariant_zero_count".into(), ok, r));
        }
    }
    match response_item(t, [a, b, c, d]) {
        Ok(item) => items.push(item),
        Err(why) => skipped.push(("frequency_response", why)),
    }
    // over Q(i) the real form of A is rational: its own exact Jordan form; over another
    // imaginary quadratic field, the Jordan form of A over K and its conjugate's
    let compared = match exact_real_form(&t.a_raw) {
        Some(aq) => jordan_comparison(&aq, path)?,
        None => match K::numeric(t)
            .map(|n| real_form_spectrum(&n.a_raw, path))
            .transpose()?
            .flatten()
        {
            Some((exact, verified)) => {
                let az = float::to_cmatrix(&t.a_raw).map_err(|e| fail(path, e))?;
                let ar = FloatScalar::realify(&az);
                vec![spectrum_comparison(&exact, &ar, verified, path)?]
            }
            None => vec![],
        },
    };
    if compared.is_empty() {
        skipped.push((
            "jordan_structure",
            "the eigenvalues are compared over imaginary quadratic fields".into(),
        ));
    }
    for (name, ok, r) in compared {
        items.push((
            format!("{name}_real_form"),
            ok,
            r.str(
                "note",
                "the real form [[X, -Y], [Y, X]] of A = X + iY: the eigenvalues of A and of its conjugate",
            ),
        ));
    }
    Ok((items, skipped))
}

/// Most states for which `check` evaluates the exact transfer matrix at sample points.
pub const MAX_EXACT_RESPONSE_STATES: usize = 40;

/// The float frequency response against the exact one at the points $s = r\sqrt d$ of the
/// imaginary axis that lie in $K = \mathbb{Q}(\sqrt d)$, $d < 0$ (for $\mathbb{Q}(i)$,
/// $s = ri$), $r \in \{-3, -1/2, 1/3, 2, 5\}$: $G(s) = C(sI - A)^{-1}B + D$ exactly over
/// $K$ (a point where $sI - A$ is singular is left out), then its embedding compared with
/// the float value at $\omega = r\sqrt{-d}$. Agreement: every entry within
/// $10^{-6}(1 + \max|G|)$; `float_truth` is `true` within $10^{-10}(1 + \max|G|)$.
fn response_item<K: GroundField>(
    t: &Typed<K>,
    [a, b, c, d]: [&DMatrix<Complex<f64>>; 4],
) -> Result<Item, String> {
    let s = &t.ss;
    let k = s.a.field();
    let Some(unit) = k.imaginary_generator() else {
        return Err("the imaginary axis meets a real field only at 0".into());
    };
    let n = s.nstates();
    if n > MAX_EXACT_RESPONSE_STATES || s.ninputs() == 0 || s.noutputs() == 0 {
        return Err(format!(
            "evaluated for 1..{MAX_EXACT_RESPONSE_STATES} states with inputs and outputs"
        ));
    }
    let root = k.approx(&unit).map_or(f64::NAN, |z| z.1);
    let mut worst = 0.0f64;
    let mut scale = 0.0f64;
    let mut used = vec![];
    for (num, den) in [(-3, 1), (-1, 2), (1, 3), (2, 1), (5, 1)] {
        let r = crate::field::Rational::new(num.into(), den.into());
        let sk = k.mul(&k.from_rational(&r), &unit);
        let m = Matrix::from_fn(k.clone(), n, n, |i, j| {
            let x = k.neg(s.a.get(i, j));
            if i == j { k.add(&x, &sk) } else { x }
        });
        let Ok(inv) = m.inverse() else { continue };
        let g = &(&(&s.c * &inv) * &s.b) + &s.d;
        let omega = crate::field::rational_to_f64(&r) * root;
        let hz = omega / (2.0 * std::f64::consts::PI);
        let Ok(fr) = float::freqresp([a, b, c, d], &[hz], None) else {
            continue;
        };
        for i in 0..g.nrows() {
            for j in 0..g.ncols() {
                let (re, im) = k.approx(g.get(i, j)).unwrap_or((f64::NAN, f64::NAN));
                let e = Complex::new(re, im);
                scale = scale.max(e.norm());
                worst = worst.max((fr[0][(i, j)] - e).norm());
            }
        }
        used.push(omega);
    }
    if used.is_empty() {
        return Err("every sample point is a pole".into());
    }
    let ok = worst <= 1e-6 * (1.0 + scale);
    let truth = if worst <= 1e-10 * (1.0 + scale) {
        Truth::True
    } else {
        Truth::Unknown
    };
    Ok((
        "frequency_response".into(),
        ok,
        Report::new()
            .with(
                "omega",
                Value::List(used.into_iter().map(Value::Float).collect()),
            )
            .float("max_abs_error", worst)
            .float("max_abs_exact", scale)
            .str("float_truth", claim_str(ok, truth)),
    ))
}
