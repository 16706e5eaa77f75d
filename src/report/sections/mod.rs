//! Report building for the results of the math modules (one file per family).
//!
//! The math types stay free of presentation: the `report()` methods of
//! [`crate::jordan::JordanForm`], [`crate::realization::MinimalRealization`],
//! [`crate::structure::scb::Scb`] and the other results are defined here, next to the
//! report model, and so are the reports of commands that are not one result
//! ([`factor_report`], [`roots_report`], [`already_standard`], [`float_jordan_fallback`]).

mod algebraic;
mod cells;
pub mod conditions;
mod critical;
mod dcgain;
mod discrete;
mod eigen_list;
mod interconnect;
mod jordan;
mod mpoly;
mod pencil;
mod realization;
pub mod response;
mod structure;
mod tf;
mod toolbox;

pub use algebraic::{factor_report, roots_report};
pub use critical::{critical_report, factor_displays};
pub use discrete::{conversion_report, sequence_report, stability_report};
pub use eigen_list::{NOT_DECIDED, eigenvalue_structure, stability_text};
pub use interconnect::{PartInfo, interconnection_report};
pub use jordan::{conditions_qp, eigenvalue_text, eigenvalue_value_text, qp_var_name};
pub use mpoly::{mfactor_report, mgcd_report};
pub use pencil::{
    ctrb_report, descriptor_ctrb_report, descriptor_zeros_report, eigen_items, eigenvalue_items,
    minreal_descriptor_report, pencil_report,
};
pub use structure::{branch_equation, branch_reason};
pub use tf::{factor_items, tf_report, zpk_string};
pub use toolbox::{
    damp_report, gram_report, margins_report, no_stepinfo_reason, stepinfo_channel, stepinfo_table,
};

use crate::field::Field;
use crate::float::{Tol, jordan_guess, to_dmatrix};
use crate::matrix::Matrix;
use crate::report::{Report, Value};
use crate::system::StateSpace;

/// The `variable` item of a report in the transform variable of `domain`: `z` shown in
/// discrete time; `s` in JSON only (continuous time is the default a reader assumes).
pub(crate) fn variable(domain: crate::system::discrete::stability::Domain) -> Value {
    let v = Value::Str(domain.var().to_string());
    match domain {
        crate::system::discrete::stability::Domain::Discrete => v,
        crate::system::discrete::stability::Domain::Continuous => Value::hidden_in_text(v),
    }
}

/// The `standard` report of a file without `E`: the system is already in standard form.
pub fn already_standard<K: Field>(ss: &StateSpace<K>) -> Report {
    Report::titled("descriptor to standard form")
        .int("order", ss.nstates())
        .int("removed_infinite", 0)
        .matrix("A", &ss.a)
        .matrix("B", &ss.b)
        .matrix("C", &ss.c)
        .matrix("D", &ss.d)
        .bool("verified", true)
        .with(
            "note",
            Value::Str("no E in the file: the system is already in standard form".into()),
        )
}

/// The float backend's guess of eigenvalues and Jordan blocks (`exact: false`), shown when
/// the exact Jordan form stopped at a limit of the implementation.
///
/// # Errors
/// As [`jordan_guess`] and [`to_dmatrix`].
pub fn float_jordan_fallback<K: Field>(a: &Matrix<K>) -> crate::Result<Report> {
    let fj = jordan_guess(&to_dmatrix(a)?, &Tol::default())?;
    let clusters = fj
        .clusters
        .iter()
        .map(|c| {
            Value::Obj(
                Report::new()
                    .list(
                        "approx",
                        vec![Value::Float(c.center.re), Value::Float(c.center.im)],
                    )
                    .int("algebraic_multiplicity", c.algebraic_multiplicity)
                    .list(
                        "blocks",
                        c.block_sizes
                            .iter()
                            .map(|&b| Value::Int(b as i64))
                            .collect(),
                    )
                    .str("truth", format!("{:?}", c.truth)),
            )
        })
        .collect();
    Ok(Report::titled("float guess (no exact result)")
        .bool("exact", false)
        .list("eigenvalues", clusters))
}
