//! Minimal realization by a chosen method: the dispatcher [`minimal`].
//!
//! Each method returns a [`MinimalRealization`] verified exactly (controllable, observable,
//! same Markov parameters, see [`super::minimal::verify_minimal`]).

use super::minimal::{MinimalRealization, MinrealMethod, minimal_kalman};
use crate::error::{Error, Result};
use crate::field::Field;
use crate::matrix::Matrix;
use crate::system::StateSpace;

/// Minimal realization by the chosen method.
///
/// # Errors
/// `Unsupported` for a method not available for this field (Jordan: systems with rational entries
/// whose minimal Jordan-method blocks are rational, see
/// [`super::jordan_method::minimal_jordan_rational`]); internal failures.
pub fn minimal<K: Field>(
    sys: &StateSpace<K>,
    method: MinrealMethod,
) -> Result<MinimalRealization<K>> {
    match method {
        MinrealMethod::Kalman => minimal_kalman(sys),
        MinrealMethod::Rosenbrock => super::rosenbrock::minimal_rosenbrock_recorded(sys, None),
        MinrealMethod::HoKalman => super::ho_kalman::minimal_ho_kalman_recorded(sys, None),
        MinrealMethod::Jordan => {
            // the Jordan method works over Q: systems with rational entries are taken down
            // to Q, realized there, lifted back and verified over K
            let k = sys.a.field().clone();
            let down = |m: &Matrix<K>| crate::matrix::to_rational_matrix(m);
            let (Some(a), Some(b), Some(c), Some(d)) =
                (down(&sys.a), down(&sys.b), down(&sys.c), down(&sys.d))
            else {
                return Err(Error::Unsupported(format!(
                    "the Jordan-form method works on systems with rational entries, not over {k}"
                )));
            };
            let q = StateSpace::new(a, b, c, d)?;
            let r = super::jordan_method::minimal_jordan_rational(&q)?;
            let up = |m: &Matrix<crate::field::Q>| m.convert_to(&k);
            let min = StateSpace::new(
                up(&r.system.a),
                up(&r.system.b),
                up(&r.system.c),
                up(&r.system.d),
            )?;
            Ok(MinimalRealization::new(
                sys,
                min,
                MinrealMethod::Jordan,
                None,
            ))
        }
    }
}
