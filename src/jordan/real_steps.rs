//! The real Jordan form step by step (`jordan --real --steps`, issue 27): the complex
//! derivation of [`super::steps::jordan_steps`] (kernel sequences, Weyr/Segre, chains), then
//! per complex pair $\theta = a + bi$, $\bar\theta$ the real columns and blocks that
//! [`super::JordanForm::real_form_with`] built from those chains, each checked
//! $A T_c = T_c J_c$ in the pair's real field $F$, and finally $A T = T J$ over one real field
//! when every block lies in it.
//!
//! The pair steps are the real form's own blocks (recorded from its result, not derived a
//! second time). A pair whose real field is large stays compact (a step without matrices).

use super::derivation::{AssumptionLog, Derivation, Method, Object, Recorder, Step, StepKind};
use super::real::RealEntries;
use crate::algebraic::{Ext, NumberField};
use crate::error::Result;
use crate::field::{Field, Q};
use crate::matrix::Matrix;
use crate::poly::Poly;
use crate::ratfunc::RatFuncField;

/// The real Jordan form of a rational matrix, step by step (module docs); `expand` as
/// `jordan --real --expand`.
///
/// # Errors
/// As [`super::jordan`] and [`super::JordanForm::real_form_with`].
pub fn real_jordan_steps(a: &Matrix<Q>, expand: bool) -> Result<Derivation<NumberField>> {
    let mut d = super::steps::jordan_steps(a)?;
    d.method = Method::RealJordan;
    let jf = super::jordan(a)?;
    let rf = jf.real_form_with(expand)?;
    // the part of a factor: its index in the derivation's factorization step
    let factors: Vec<_> = d
        .of_kind(StepKind::Factorization)
        .find_map(|s| match s.get("factors") {
            Some(Object::Factors(f)) => Some(f.iter().map(|(p, _)| p.to_string()).collect()),
            _ => None,
        })
        .unwrap_or_else(Vec::new);
    for b in rf.blocks.iter().filter(|b| b.pair) {
        let comp = jf.eigenvalues[b.eigenvalue].component;
        let shown = rf.factors[comp].to_string();
        let part = factors.iter().position(|f| *f == shown);
        let (objects, holds) = match &b.entries {
            RealEntries::Expanded { pair, t, j } => {
                let ok = &pair.matrix(a) * t == t * j;
                let objects = vec![
                    ("Tc", Object::Matrix(t.clone())),
                    ("Jc", Object::Matrix(j.clone())),
                ];
                (objects, Some(ok))
            }
            _ => (vec![("compact", Object::Count(1))], None),
        };
        d.steps.push(Step {
            kind: StepKind::RealPair,
            part,
            objects,
            holds,
            assumes: vec![],
        });
    }
    if let Some((j, t)) = rf.single_field() {
        let f = t.field().clone();
        let af = a.map(&f, |x| f.from_rational(x));
        let ok = &af * &t == &t * &j && t.det().is_ok_and(|x| !f.is_zero(&x));
        d.steps.push(Step {
            kind: StepKind::RealForm,
            part: None,
            objects: vec![("T", Object::Matrix(t)), ("J", Object::Matrix(j))],
            holds: Some(ok),
            assumes: vec![],
        });
    }
    Ok(d)
}

/// $F$ as its extension of degree 1 ($F\[t\]/(t)$): the field of a derivation whose parts
/// live in extensions $F\[t\]/(g)$ (as $\mathbb{Q}$ is the number field of degree 1).
pub fn degree_one<F: Field>(k: &F) -> Ext<F> {
    Ext::with_var(&Poly::x(k.clone()), (0.0, 0.0), "t")
}

/// An assumption log over $F$ read in its extension `e`.
pub fn lift_log<F: Field + 'static>(
    e: &Ext<F>,
    log: AssumptionLog<'static, F>,
) -> AssumptionLog<'static, Ext<F>> {
    let e = e.clone();
    Box::new(move || log().iter().map(|c| e.from_base(c)).collect())
}

/// A derivation over $F$ as one over its extension `e` (every object and assumption mapped
/// by $F \to E$).
pub fn lift_derivation<F: Field>(d: &Derivation<F>, e: &Ext<F>) -> Derivation<Ext<F>> {
    let lift = |x: &F::Elem| e.from_base(x);
    let obj = |o: &Object<F>| match o {
        Object::Matrix(m) => Object::Matrix(m.map(e, lift)),
        Object::Poly(p) => Object::Poly(p.map(e, lift)),
        Object::Factors(f) => {
            Object::Factors(f.iter().map(|(p, k)| (p.map(e, lift), *k)).collect())
        }
        Object::Scalar(x) => Object::Scalar(lift(x)),
        Object::Count(c) => Object::Count(*c),
        Object::Counts(c) => Object::Counts(c.clone()),
        Object::Polys(ps) => Object::Polys(ps.iter().map(|p| p.map(e, lift)).collect()),
    };
    Derivation {
        method: d.method,
        field: e.clone(),
        variable: d.variable,
        steps: d
            .steps
            .iter()
            .map(|s| Step {
                kind: s.kind,
                part: s.part,
                objects: s.objects.iter().map(|(k, o)| (*k, obj(o))).collect(),
                holds: s.holds,
                assumes: s.assumes.iter().map(lift).collect(),
            })
            .collect(),
    }
}

/// One part of the real form over $\mathbb{Q}(p)$: the columns $T$ and the blocks $J$ over
/// the pair's field $R$ (over $E$ of degree 1 for an eigenvalue in $\mathbb{Q}(p)$).
type QpPart = (Matrix<Ext<RatFuncField>>, Matrix<Ext<RatFuncField>>);

/// The real Jordan form over $\mathbb{Q}(p)$ step by step (`jordan --real --steps` of a file
/// with symbols): $\chi_A$ and its irreducible factors over $\mathbb{Q}(p)$ (their conditions:
/// leading coefficients, discriminants, resultants); per factor the kernel sequence,
/// Weyr/Segre and chains in $E = \mathbb{Q}(p)\[t\]/(g)$ (for a quadratic factor at its
/// generic root $t$); per quadratic factor $g = x^2 + bx + c$ the real pair
/// ([`super::real_quadratic`]): $\alpha = -b/2$, $w^2 = c - b^2/4$ with $w$ a symbol, the
/// columns $x_j = p_j + \alpha q_j$, $y_j = w q_j$ of the chains shown ($v_j = p_j + q_j t$),
/// $A T_c = T_c J_c$ checked in $R = \mathbb{Q}(p)\[w\]/(w^2 - (c - b^2/4))$, a complex pair
/// where $b^2 - 4c < 0$ (stated with the step); with at most one pair, $A T = T J$ and
/// $\det T \ne 0$ over $R$. Every step lists the polynomials in the parameters it assumes
/// nonzero.
///
/// # Errors
/// As [`super::over_qp::real_form_qp`] (`Unsupported` for a factor of degree $\ge 3$).
pub fn real_jordan_steps_qp(a_in: &Matrix<RatFuncField>) -> Result<Derivation<Ext<RatFuncField>>> {
    a_in.check_square("jordan")?;
    let k = a_in.field().fresh();
    let n = a_in.nrows();
    let a = Matrix::from_vec(k.clone(), n, n, a_in.as_slice().to_vec());
    let e0 = degree_one(&k);
    let log = lift_log(&e0, super::derivation::ratfunc_log(&k));
    let mut rec = Recorder::with_log(Method::RealJordan, e0.clone(), log);
    let lift_m = |m: &Matrix<RatFuncField>| m.map(&e0, |x| e0.from_base(x));
    let lift_p = |p: &Poly<RatFuncField>| p.map(&e0, |x| e0.from_base(x));
    let chi = crate::matrix::params::charpoly_ratfunc(&a)?;
    super::steps::charpoly_step(&mut rec, &lift_m(&a), &lift_p(&chi), 8);
    let cp = super::over_qp::charpoly_factors(&a)?;
    let facs: Vec<_> = cp
        .factors
        .iter()
        .map(|f| (lift_p(&f.monic), f.multiplicity))
        .collect();
    let prod = facs.iter().fold(Poly::one(e0.clone()), |acc, (p, e)| {
        acc.mul(&p.pow(*e as u32))
    });
    let ok = prod == lift_p(&cp.charpoly);
    rec.push(
        StepKind::Factorization,
        None,
        vec![("factors", Object::Factors(facs))],
        Some(ok),
    );
    let mut parts: Vec<QpPart> = vec![];
    let mut pairs = 0;
    for (part, f) in cp.factors.iter().enumerate() {
        if f.monic.deg() > 2 {
            return Err(crate::error::Error::Unsupported(format!(
                "jordan --real --steps over QQ(p): the factor {} has degree {}; its roots are not a +- i w with a and w^2 in the parameters' field, so the real form is written for eigenvalues in QQ(p) and quadratic factors only",
                f.monic.to_string_var("s"),
                f.monic.deg()
            )));
        }
        let mut comp =
            super::primary::Component::compute(&a, &f.monic, f.multiplicity, None, vec![], true)?;
        let theta = comp.root_elem();
        let (v, blocks) =
            super::steps::eigenvalue_steps(&mut rec, part, &comp.lift(&a), &theta, f.multiplicity)?;
        if f.monic.deg() == 1 {
            let j = super::chains::jordan_block_matrix(&comp.field, &theta, &blocks);
            parts.push((v, j));
            continue;
        }
        // the real columns of the chains shown above
        comp.chains = v;
        comp.blocks = blocks;
        pairs += 1;
        parts.push(real_pair_step(&mut rec, part, &a, &comp, pairs)?);
    }
    if pairs <= 1 {
        real_form_step(&mut rec, &a, &parts);
    }
    Ok(rec.finish())
}

/// The step of one quadratic factor's real pair (module docs of
/// [`super::real_quadratic`]); returns its columns and blocks over $R$.
fn real_pair_step(
    rec: &mut Recorder<'_, Ext<RatFuncField>>,
    part: usize,
    a: &Matrix<RatFuncField>,
    comp: &super::primary::Component<RatFuncField>,
    index: usize,
) -> Result<QpPart> {
    let r =
        super::real_quadratic::quadratic_real(a, comp, &format!("w{index}")).ok_or_else(|| {
            crate::error::Error::Verification("a quadratic factor without a real form".into())
        })?;
    let f = r.field.clone();
    let ar = a.map(&f, |x| f.from_base(x));
    let ok = ar.try_mul(&r.t)? == r.t.try_mul(&r.j)?;
    rec.push(
        StepKind::RealPair,
        Some(part),
        vec![
            ("Tc", Object::Matrix(r.t.clone())),
            ("Jc", Object::Matrix(r.j.clone())),
            ("re", Object::Scalar(f.from_base(&r.re))),
            ("w2", Object::Scalar(f.from_base(&r.im_squared))),
            ("disc", Object::Scalar(f.from_base(&r.discriminant))),
        ],
        Some(ok),
    );
    Ok((r.t, r.j))
}

/// The step $A T = T J$, $\det T \ne 0$ over the one pair's field $R$ (or over
/// $\mathbb{Q}(p)$ without pairs): the parts' columns side by side, their blocks on the
/// diagonal. The determinant's numerator is a condition (recorded) when it lies in
/// $\mathbb{Q}(p)$.
fn real_form_step(
    rec: &mut Recorder<'_, Ext<RatFuncField>>,
    a: &Matrix<RatFuncField>,
    parts: &[QpPart],
) {
    let k = a.field();
    let f = parts
        .iter()
        .map(|(t, _)| t.field())
        .find(|e| e.degree() == 2)
        .cloned()
        .unwrap_or_else(|| degree_one(k));
    // an element of an eigenvalue's field of degree 1 (or of R itself) in R
    let into = |m: &Matrix<Ext<RatFuncField>>| {
        let src = m.field().clone();
        if src.degree() == 2 {
            return m.clone();
        }
        m.map(&f, |x| {
            f.from_base(&src.to_base(x).unwrap_or_else(|| k.zero()))
        })
    };
    let n = a.nrows();
    let ts: Vec<_> = parts.iter().map(|(t, _)| into(t)).collect();
    let js: Vec<_> = parts.iter().map(|(_, j)| into(j)).collect();
    let mut t = Matrix::zeros(f.clone(), n, ts.iter().map(|x| x.ncols()).sum());
    let mut off = 0;
    for c in &ts {
        t.set_block(0, off, c);
        off += c.ncols();
    }
    let j = Matrix::block_diag(f.clone(), &js);
    let af = a.map(&f, |x| f.from_base(x));
    let mut ok = off == n && af.try_mul(&t).ok() == t.try_mul(&j).ok();
    if ok {
        let det = t.det();
        ok = det.as_ref().is_ok_and(|x| !f.is_zero(x));
        if let Some(d) = det.ok().and_then(|x| f.to_base(&x)) {
            k.record_condition(d.num());
        }
    }
    rec.push(
        StepKind::RealForm,
        None,
        vec![("T", Object::Matrix(t)), ("J", Object::Matrix(j))],
        Some(ok),
    );
}
