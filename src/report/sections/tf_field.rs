//! `tf` over a quadratic field $K = \mathbb{Q}(\sqrt d)$ or $\mathbb{Q}(i)$: the keys of
//! the rational [`super::tf_report`], with poles and zeros as the irreducible factors over
//! $K$ of the pole and zero polynomials ([`crate::algebraic::factor_over_quadratic`]).
//!
//! # Verification
//! `verified` is the conjunction of: the minimal realization's checks
//! ([`crate::realization::realize_transfer`]), the zero pencil's checks, the product of the
//! pole factors equals the pole polynomial (the characteristic polynomial of the minimal
//! realization's finite block), and, for a state-space system, the Markov parameters of the
//! transfer matrix equal $D, CB, CAB, \dots, CA^{2n-1}B$ of the input system
//! ([`TransferMatrix::matches_markov`]).

use crate::algebraic::{factor_over_quadratic, rational_minpoly};
use crate::error::Result;
use crate::field::ElemDisplay;
use crate::field::{Field, QuadraticField};
use crate::matrix::Matrix;
use crate::poly::Poly;
use crate::realization::TransferRealization;
use crate::report::{Report, Value};
use crate::system::discrete::stability::Domain;
use crate::system::transfer::TransferMatrix;
use crate::system::{Descriptor, StateSpace};

fn ints(v: &[usize]) -> Value {
    Value::List(v.iter().map(|&x| Value::Int(x as i64)).collect())
}

/// One report item per irreducible factor over $K$ of `p`: `factor`, `degree`, `minpoly`
/// (over $\mathbb{Q}$, of the factor's roots), `algebraic_multiplicity` (under `mult_key`),
/// and for a linear factor the exact `value` and `approx`; factors are written in `var`.
/// Returns the items and whether the product of the factors is `p` up to its leading
/// coefficient.
fn factor_items(p: &Poly<QuadraticField>, mult_key: &str, var: &str) -> Result<(Vec<Value>, bool)> {
    if p.is_zero() || p.deg() == 0 {
        return Ok((vec![], true));
    }
    let k = p.field().clone();
    let fs = factor_over_quadratic(p)?;
    let mut prod = Poly::new(k.clone(), vec![p.lc()]);
    let mut items = vec![];
    for (f, e) in &fs {
        for _ in 0..*e {
            prod = prod.mul(f);
        }
        // the minimal polynomial over Q of the roots of f (f irreducible over K)
        let minpoly = rational_minpoly(f);
        let mut r = Report::new()
            .str("factor", f.to_string_var(var))
            .int("degree", f.deg())
            .str("minpoly", minpoly.to_string());
        if f.deg() == 1 {
            let root = k.neg(&k.div(&f.coeff(0), &f.coeff(1)).expect("non-zero lc"));
            let (re, im) = k.approx(&root);
            r = r.str("value", k.fmt_elem(&root)).with(
                "approx",
                Value::List(vec![Value::Float(re), Value::Float(im)]),
            );
        } else {
            r = r.str("value", format!("a root of {}", f.to_string_var(var)));
            r = r.list("roots", roots_of_factor(f, &minpoly)?);
        }
        items.push(Value::Obj(r.int(mult_key, *e)));
    }
    Ok((items, prod == *p))
}

/// The roots of a factor `f` (irreducible over $K$, degree >= 2) as `{value, approx}`: the
/// certified roots of its minimal polynomial over $\mathbb{Q}$, of which those of `f` are
/// told exactly from those of its Galois conjugate
/// ([`crate::algebraic::roots_of_quadratic_factor`]).
fn roots_of_factor(
    f: &Poly<QuadraticField>,
    minpoly: &Poly<crate::field::Q>,
) -> Result<Vec<Value>> {
    let all = crate::algebraic::AlgebraicNumber::roots_of_irreducible_unchecked(minpoly)?
        .into_iter()
        .map(|z| (z, ()))
        .collect();
    Ok(crate::algebraic::roots_of_quadratic_factor(f, all)?
        .into_iter()
        .map(|(z, ())| {
            let (re, im) = z.approx();
            Value::Obj(Report::new().str("value", z.value_string()).with(
                "approx",
                Value::List(vec![Value::Float(re), Value::Float(im)]),
            ))
        })
        .collect())
}

/// Zero-pole-gain display over $K$ in the variable `var`: `k (factors) / (factors)`.
fn zpk_string(num: &Poly<QuadraticField>, den: &Poly<QuadraticField>, var: &str) -> Result<String> {
    if num.is_zero() {
        return Ok("0".into());
    }
    let k = num.field().clone();
    let gain = k.fmt_elem(&k.div(&num.lc(), &den.lc()).expect("non-zero denominator"));
    let factors = |p: &Poly<QuadraticField>| -> Result<Vec<(String, usize)>> {
        Ok(factor_over_quadratic(p)?
            .iter()
            .map(|(f, e)| (f.to_string_var(var), *e))
            .collect())
    };
    Ok(super::pencil::zpk_text(
        &gain,
        &factors(num)?,
        &factors(den)?,
    ))
}

/// A minimal realization of a transfer matrix over $K$ as `tf` reports it: from
/// [`crate::realization::realize_transfer`] (descriptor input), or the Kalman minimal
/// realization of a state-space input (same transfer matrix, far cheaper than realizing
/// the transfer matrix's entries one by one).
pub struct TfRealization {
    /// Minimal system, finite block first (`E = diag(I, N)`; `E = I` when proper).
    pub system: Descriptor<QuadraticField>,
    /// Order of the finite block.
    pub finite_order: usize,
    /// Finite poles plus the orders of the poles at infinity.
    pub mcmillan_degree: usize,
    /// Its own checks held.
    pub verified: bool,
}

impl TfRealization {
    /// From a realization of the transfer matrix.
    pub fn from_transfer(r: &TransferRealization<QuadraticField>) -> Self {
        TfRealization {
            system: r.minimal.system.clone(),
            finite_order: r.minimal.finite_order,
            mcmillan_degree: r.mcmillan_degree,
            verified: r.verified,
        }
    }
    /// From a verified-or-not minimal state-space realization.
    ///
    /// # Errors
    /// Never for a valid system (shapes).
    pub fn from_state_space(m: &StateSpace<QuadraticField>, verified: bool) -> Result<Self> {
        let k = m.a.field().clone();
        let n = m.nstates();
        Ok(TfRealization {
            system: Descriptor::new(
                Matrix::identity(k, n),
                m.a.clone(),
                m.b.clone(),
                m.c.clone(),
                m.d.clone(),
            )?,
            finite_order: n,
            mcmillan_degree: n,
            verified,
        })
    }
}

/// `tf` over a quadratic field: the rational report's keys plus `field` and
/// `pole_polynomial`, in the variable of `domain`; `ss` is the input state-space system when there is one (its Markov
/// parameters are compared with the transfer matrix's).
///
/// # Errors
/// From the factorizations and the zero pencil.
pub fn tf_report_quadratic(
    g: &TransferMatrix<QuadraticField>,
    r: &TfRealization,
    ss: Option<&StateSpace<QuadraticField>>,
    domain: Domain,
) -> Result<Report> {
    let var = domain.var();
    let sys = &r.system;
    let nf = r.finite_order;
    let k = sys.a.field().clone();
    let pole_poly = sys.a.submatrix(0, nf, 0, nf).charpoly()?;
    let (poles, poles_ok) = factor_items(&pole_poly, "algebraic_multiplicity", var)?;
    let zeros = crate::structure::descriptor_zeros::descriptor_zeros(sys)?;
    let (tzeros, zeros_ok) = factor_items(&zeros.polynomial, "algebraic_multiplicity", var)?;
    let markov_ok = ss.is_none_or(|s| g.matches_markov(s));
    let (tm, zpk) = super::pencil::transfer_lists(g, var, zpk_string)?;
    let mut rep = Report::titled(format!("transfer matrix over {k}"))
        .str("field", k.to_string())
        .with("variable", super::variable(domain))
        .list("transfer_matrix", tm)
        .list("zpk", zpk)
        .int("mcmillan_degree", r.mcmillan_degree)
        .int("infinite_pole_degree", r.mcmillan_degree - nf)
        .str("pole_polynomial", pole_poly.to_string_var(var))
        .list("poles", poles)
        .list("transmission_zeros", tzeros)
        .with("infinite_zero_orders", ints(&zeros.infinite_zero_orders))
        .int("normal_rank", zeros.pencil.normal_rank - sys.nstates())
        .int("order", sys.nstates());
    if ss.is_some() {
        rep = rep.bool("markov_verified", markov_ok);
    }
    Ok(rep.bool(
        "verified",
        r.verified && zeros.pencil.verified && poles_ok && zeros_ok && markov_ok,
    ))
}
