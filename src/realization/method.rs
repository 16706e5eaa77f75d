//! Minimal realization by a chosen method: the dispatcher [`minimal`].
//!
//! Each method returns a [`MinimalRealization`] verified exactly (controllable, observable,
//! same Markov parameters, see [`super::minimal::verify_minimal`]).

use super::minimal::{MinimalRealization, MinrealMethod, minimal_kalman};
use crate::error::{Error, Result};
use crate::field::Field;
use crate::system::StateSpace;

/// Minimal realization by the chosen method.
///
/// # Errors
/// `Unsupported` for a method not available for this field; internal failures.
pub fn minimal<K: Field>(
    sys: &StateSpace<K>,
    method: MinrealMethod,
) -> Result<MinimalRealization<K>> {
    match method {
        MinrealMethod::Kalman => minimal_kalman(sys),
        MinrealMethod::Rosenbrock => super::rosenbrock::minimal_rosenbrock(sys),
        MinrealMethod::HoKalman => super::ho_kalman::minimal_ho_kalman(sys),
        MinrealMethod::Jordan => Err(Error::Unsupported(
            "the Jordan-form method works on rational systems: use realization::minimal_jordan"
                .into(),
        )),
    }
}
