//! Minimal realization by a chosen method: the dispatcher [`minimal`], one entry point for
//! every field a system can be over ([`SystemField`]).
//!
//! Each method returns a [`MinimalRealization`] verified exactly (controllable, observable,
//! same Markov parameters, see [`super::minimal::verify_minimal`]). The Jordan-form method
//! keeps its full result ([`JordanMethod`]) beside the system:
//!
//! | field | Jordan-method result | `system` |
//! |---|---|---|
//! | $\mathbb{Q}$, $\mathbb{Q}(\sqrt d)$, $\mathbb{Q}(i)$ | the modal form ([`super::minimal_jordan`]) | its real form when every entry lies in the field, else the primary blocks over the field ([`super::minimal_jordan_primary`]) |
//! | $\mathbb{Q}(p_1, \dots, p_k)$ | the primary blocks over $\mathbb{Q}(p)$ ([`super::minimal_jordan_qp`]) | that realization |

use super::jordan_method::minimal_jordan;
use super::jordan_method_primary::{minimal_jordan_primary, minimal_jordan_qp};
use super::jordan_result::JordanMethod;
use super::minimal::{MinimalRealization, MinrealMethod, minimal_kalman};
use super::modal::{ModalTable, modal_table_over};
use crate::error::{Error, Result};
use crate::field::{Q, QuadraticField};
use crate::jordan::{EigenField, JordanField};
use crate::matrix::Matrix;
use crate::ratfunc::RatFuncField;
use crate::system::StateSpace;

/// A field a system's matrices can lie in ($\mathbb{Q}$, $\mathbb{Q}(\sqrt d)$,
/// $\mathbb{Q}(i)$, $\mathbb{Q}(p_1, \dots, p_k)$): every operation on systems is generic over
/// it; what differs between the fields is a method here, never a second entry point.
pub trait SystemField: JordanField {
    /// The Jordan-form minimal realization over this field, with the realization as a
    /// system over the field (its Markov parameters part of the method's verification).
    ///
    /// # Errors
    /// Those of the decomposition and of the compaction.
    fn jordan_method(sys: &StateSpace<Self>) -> Result<(JordanMethod<Self>, StateSpace<Self>)>;
    /// The modal table of `a` (figures of each eigenvalue).
    ///
    /// # Errors
    /// Those of the decomposition; `Unsupported` over a field without numeric eigenvalues.
    fn modal_table(a: &Matrix<Self>) -> Result<ModalTable>;
}

/// The modal form over a field with certified eigenvalues, and the system: its real form
/// in the field when every entry lies there, else the primary blocks over the field built
/// from the same components.
fn modal<F: EigenField>(sys: &StateSpace<F>) -> Result<(JordanMethod<F>, StateSpace<F>)> {
    let mut jm = minimal_jordan(sys)?;
    let system = match jm.real_to_base() {
        Some(s) => s,
        None => {
            let p = minimal_jordan_primary(sys, jm.jordan.components.clone())?;
            jm.verified &= p.verified;
            p.system
        }
    };
    Ok((JordanMethod::Modal(Box::new(jm)), system))
}

/// A field whose Jordan-method result is the modal form: certified eigenvalues
/// ([`EigenField`]). Every such field is a [`SystemField`] by one implementation (the modal
/// form, the modal table); a new field with certified eigenvalues needs only this marker.
pub trait ModalField: EigenField + JordanField {}

impl ModalField for Q {}
impl ModalField for QuadraticField {}

impl<F: ModalField> SystemField for F {
    fn jordan_method(sys: &StateSpace<F>) -> Result<(JordanMethod<F>, StateSpace<F>)> {
        modal(sys)
    }
    fn modal_table(a: &Matrix<F>) -> Result<ModalTable> {
        modal_table_over(a)
    }
}

impl SystemField for RatFuncField {
    fn jordan_method(
        sys: &StateSpace<RatFuncField>,
    ) -> Result<(JordanMethod<RatFuncField>, StateSpace<RatFuncField>)> {
        let p = minimal_jordan_qp(sys)?;
        let system = p.system.clone();
        Ok((JordanMethod::Primary(Box::new(p)), system))
    }
    fn modal_table(a: &Matrix<RatFuncField>) -> Result<ModalTable> {
        Err(Error::Unsupported(format!(
            "the modal table lists numbers (frequencies, damping ratios): give the parameters of {} values",
            a.field()
        )))
    }
}

/// Minimal realization by the chosen method, over every [`SystemField`].
///
/// With [`MinrealMethod::Jordan`] the result also holds the method's full result
/// ([`MinimalRealization::jordan`]) and carries the method's own exact verification (Markov
/// parameters $C A^k B$ equal for $k < n + r$, order = McMillan degree, the system's own
/// Markov parameters; the primary blocks' when the modal form is not over the field).
///
/// # Errors
/// Those of the chosen algorithm.
pub fn minimal<K: SystemField>(
    sys: &StateSpace<K>,
    method: MinrealMethod,
) -> Result<MinimalRealization<K>> {
    match method {
        MinrealMethod::Kalman => minimal_kalman(sys),
        MinrealMethod::Rosenbrock => super::rosenbrock::minimal_rosenbrock_recorded(sys, None),
        MinrealMethod::HoKalman => super::ho_kalman::minimal_ho_kalman_recorded(sys, None),
        MinrealMethod::Jordan => {
            // verified by the method itself: C A^k B equal for k < n + r and the order equal
            // to the McMillan degree (no second rank test: over Q(p) it would add pivots to
            // the result's conditions)
            let (jm, min) = K::jordan_method(sys)?;
            Ok(MinimalRealization {
                order: min.nstates(),
                original_order: sys.nstates(),
                system: min,
                method: MinrealMethod::Jordan,
                t: None,
                verified: jm.verified(),
                jordan: Some(jm),
            })
        }
    }
}
