//! Structure of linear systems: special coordinate basis and invariant zeros.
//!
//! | module | computes |
//! |---|---|
//! | [`scb`] | special coordinate basis (Sannuti–Saberi; Grip–Saberi's symbolic procedure), exact |
//! | [`zeros`] | invariant zeros from the Rosenbrock system matrix, independent of the SCB |

pub mod scb;
pub mod zeros;
