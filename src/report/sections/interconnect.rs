//! The report of `series`, `parallel`, `feedback`, `append`: the operation and the identity
//! its transfer matrix satisfies, the parts, the interconnected system `A`..`D` with its
//! exact check, and (with `--minreal`) its exact minimal realization.

use crate::field::Field;
use crate::realization::MinimalRealization;
use crate::report::{Report, Value};
use crate::system::StateSpace;
use crate::system::interconnect::{Operation, Sign};

/// One part of an interconnection as the report names it.
#[derive(Clone, Debug)]
pub struct PartInfo {
    /// The file (or other name) the part came from.
    pub name: String,
    pub states: usize,
    pub inputs: usize,
    pub outputs: usize,
}

/// The report of an interconnection (`verified`: the identity of [`Operation::identity`]
/// holds exactly) and of its minimal realization when one was computed.
pub fn interconnection_report<K: Field>(
    op: Operation,
    parts: &[PartInfo],
    sys: &StateSpace<K>,
    verified: bool,
    minimal: Option<&MinimalRealization<K>>,
) -> Report {
    let title = match op {
        Operation::Feedback(Sign::Negative) => "feedback (negative)".to_string(),
        Operation::Feedback(Sign::Positive) => "feedback (positive)".to_string(),
        op => op.name().to_string(),
    };
    let parts_v = parts
        .iter()
        .map(|p| {
            Value::Obj(
                Report::new()
                    .str("name", p.name.clone())
                    .int("states", p.states)
                    .int("inputs", p.inputs)
                    .int("outputs", p.outputs),
            )
        })
        .collect();
    let mut r = Report::titled(title)
        .str("operation", op.name())
        .str("transfer_matrix", op.identity());
    if let Operation::Feedback(s) = op {
        r = r.with("sign", Value::Int(s.as_i64()));
    }
    r = r
        .list("parts", parts_v)
        .str("field", sys.field().to_string())
        .int("states", sys.nstates())
        .int("inputs", sys.ninputs())
        .int("outputs", sys.noutputs())
        .matrix("A", &sys.a)
        .matrix("B", &sys.b)
        .matrix("C", &sys.c)
        .matrix("D", &sys.d)
        .bool("verified", verified);
    if let Some(m) = minimal {
        r = r.obj("minimal", m.report());
    }
    r
}
