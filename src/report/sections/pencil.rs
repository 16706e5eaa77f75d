//! Reports of `pencil`, `ctrb`, `obsv`, `tf`, `minreal --descriptor` and the descriptor
//! form of `zeros` (contract, second wave). The library computes; this file only lays out
//! the contract's keys.

use crate::error::Result;
use crate::field::Field;
use crate::io::GroundField;
use crate::jordan::{JordanForm, jordan_over};
use crate::matrix::Matrix;
use crate::pencil::{KroneckerStructure, PencilStructure};
use crate::realization::{ControllabilityStructure, DescriptorControllability, DescriptorMinimal};
use crate::report::{Report, Value};
use crate::structure::descriptor_zeros::DescriptorZeros;
use crate::system::discrete::stability::Domain;

fn ints(v: &[usize]) -> Value {
    Value::List(v.iter().map(|&x| Value::Int(x as i64)).collect())
}

fn approx(a: (f64, f64)) -> Value {
    Value::List(vec![Value::Float(a.0), Value::Float(a.1)])
}

/// Eigenvalue objects (`minpoly`, `value`, `approx`, multiplicities, `blocks`) of a Jordan form.
pub fn eigen_items(jf: &JordanForm) -> Vec<Value> {
    eigenvalue_items(&jf.eigenvalues)
}

/// Eigenvalue objects of a list of eigenvalues (rational or quadratic-field Jordan forms).
pub fn eigenvalue_items<F: crate::jordan::NumberEigen>(
    evs: &[crate::jordan::Eigenvalue<F>],
) -> Vec<Value> {
    evs.iter()
        .map(|e| {
            Value::Obj(
                Report::new()
                    .str("minpoly", e.minpoly.to_string())
                    .str("value", super::eigenvalue_text(e))
                    .with("approx", approx(e.approx))
                    .int("algebraic_multiplicity", e.algebraic_multiplicity)
                    .int("geometric_multiplicity", e.geometric_multiplicity)
                    .with("blocks", ints(&e.blocks)),
            )
        })
        .collect()
}

/// Eigenvalue objects of the matrix `a` over a numeric field (empty list for 0 x 0); `None`
/// over a field of symbols.
fn eigen_items_of<K: GroundField>(a: &Matrix<K>) -> Result<Option<Vec<Value>>> {
    if a.nrows() == 0 {
        return Ok(Some(vec![]));
    }
    match K::numeric_matrix(a) {
        Some(an) => Ok(Some(eigenvalue_items(&jordan_over(an)?.eigenvalues))),
        None => Ok(None),
    }
}

fn kronecker_items<K: Field>(r: Report, k: &KroneckerStructure<K>) -> Report {
    r.int("normal_rank", k.normal_rank)
        .bool("regular", k.is_regular())
        .with("right_kronecker_indices", ints(&k.right_indices))
        .with("left_kronecker_indices", ints(&k.left_indices))
        .with("infinite_elementary_divisors", ints(&k.infinite_divisors))
        .int("finite_order", k.finite_order())
        .int("nondynamic_modes", k.nondynamic_modes())
}

/// `pencil` over any ground field: the Kronecker structure, the finite part as a matrix and
/// its eigenvalues (over a numeric field [`eigenvalue_items`]: exact values, `minpoly`,
/// `approx`, multiplicities, `blocks`; over $\mathbb{Q}(p)$
/// [`super::eigen_list::eigenvalue_structure`]).
pub fn pencil_report<K: GroundField>(ps: &PencilStructure<K>) -> Report {
    let k = &ps.structure;
    let eigen = match K::numeric_jordan(&ps.finite) {
        Some(j) => eigenvalue_items(&j.eigenvalues),
        None => super::eigen_list::eigenvalue_structure(&ps.finite, "s"),
    };
    kronecker_items(
        Report::titled(format!(
            "Kronecker structure of the {}x{} pencil A - sE",
            k.shape.0, k.shape.1
        )),
        k,
    )
    .matrix("finite_part", &k.finite_part)
    .list("finite_eigenvalues", eigen)
    .bool("verified", ps.verified)
}

fn structure_items<K: GroundField>(
    r: Report,
    c: &ControllabilityStructure<K>,
    dual: bool,
) -> Result<Report> {
    let (order, idx, index, unc) = if dual {
        (
            "observable_order",
            "observability_indices",
            "observability_index",
            "unobservable_eigenvalues",
        )
    } else {
        (
            "controllable_order",
            "controllability_indices",
            "controllability_index",
            "uncontrollable_eigenvalues",
        )
    };
    let part = if dual {
        c.uncontrollable.transpose()
    } else {
        c.uncontrollable.clone()
    };
    let mut r = r
        .int(order, c.order)
        .with(idx, ints(&c.indices))
        .int(index, c.controllability_index())
        .with("staircase_block_dims", ints(&c.block_dims));
    match eigen_items_of(&part)? {
        Some(items) => r = r.list(unc, items),
        None => {
            r = r.matrix(
                if dual {
                    "unobservable_part"
                } else {
                    "uncontrollable_part"
                },
                &part,
            )
        }
    }
    Ok(r)
}

/// `ctrb` / `obsv` of a standard system.
///
/// # Errors
/// From the Jordan form of the uncontrollable part.
pub fn ctrb_report<K: GroundField>(c: &ControllabilityStructure<K>, dual: bool) -> Result<Report> {
    let title = if dual {
        "observability structure of (C, A)"
    } else {
        "controllability structure of (A, B)"
    };
    Ok(structure_items(Report::titled(title), c, dual)?.bool("verified", c.verified))
}

/// `ctrb` / `obsv` of a descriptor system: finite part structure plus infinite counts.
///
/// # Errors
/// From the Jordan form of the uncontrollable part.
pub fn descriptor_ctrb_report<K: GroundField>(
    d: &DescriptorControllability<K>,
    dual: bool,
) -> Result<Report> {
    let (title, order, fin, inf, unc) = if dual {
        (
            "observability structure of (C, A, E)",
            "observable_order",
            "observable_finite_order",
            "observable_infinite_order",
            "unobservable_infinite_eigenvalues",
        )
    } else {
        (
            "controllability structure of (A, B, E)",
            "controllable_order",
            "controllable_finite_order",
            "controllable_infinite_order",
            "uncontrollable_infinite_eigenvalues",
        )
    };
    let r = structure_items(Report::titled(title), &d.finite, dual)?;
    // the finite part's order key is replaced by the total; the finite one has its own key
    let mut r = Report {
        title: r.title,
        items: r.items.into_iter().filter(|(k, _)| k != order).collect(),
    };
    r = r
        .int(order, d.controllable_order())
        .int(fin, d.finite.order)
        .int(inf, d.infinite.order)
        .int(unc, d.uncontrollable_infinite())
        .int("finite_order", d.finite_order)
        .int("infinite_order", d.infinite_order);
    Ok(r.bool("verified", d.verified()))
}

/// `minreal --descriptor`.
pub fn minreal_descriptor_report<K: Field>(m: &DescriptorMinimal<K>) -> Report {
    let s = &m.system;
    Report::titled("minimal descriptor realization")
        .ints(&[
            ("order", m.order),
            ("irreducible_order", m.irreducible_order),
            ("original_order", m.original_order),
            ("finite_order", m.finite_order),
            ("infinite_order", m.infinite_order),
            ("polynomial_degree", m.polynomial_degree),
        ])
        .matrices(&[
            ("E", &s.e),
            ("A", &s.a),
            ("B", &s.b),
            ("C", &s.c),
            ("D", &s.d),
        ])
        .bool("verified", m.verified)
}

/// `zeros` of a descriptor system (polynomials in the variable of `domain`; the zeros as the
/// irreducible factors over the field, [`super::tf::root_items`]).
///
/// # Errors
/// From root isolation.
pub fn descriptor_zeros_report<K: GroundField>(
    z: &DescriptorZeros<K>,
    domain: Domain,
) -> Result<Report> {
    let k = &z.pencil;
    let (items, _) = super::tf::root_items(&z.polynomial, domain.var())?;
    Ok(Report::titled("zeros of the descriptor system")
        .list("invariant_zeros", items)
        .str("zero_polynomial", z.polynomial.to_string_var(domain.var()))
        .with("infinite_zero_orders", ints(&z.infinite_zero_orders))
        .int("normal_rank", k.normal_rank)
        .with("right_kronecker_indices", ints(&k.right_indices))
        .with("left_kronecker_indices", ints(&k.left_indices))
        .bool("verified", k.verified))
}
