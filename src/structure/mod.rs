//! Structure of linear systems: special coordinate basis, invariant zeros, mechanical
//! normal form.
//!
//! | module | computes |
//! |---|---|
//! | [`scb`] | special coordinate basis (Sannuti–Saberi; Grip–Saberi's symbolic procedure), exact |
//! | [`zeros`] | invariant zeros of the Rosenbrock system matrix (through the SCB; polynomial Smith form as fallback and oracle) |
//! | [`mechanical`] | mechanical normal form: a first-order system back to $\ddot q + D\dot q + Kq = Wu$ |

pub mod descriptor_zeros;
pub mod mechanical;
pub mod scb;
pub mod zeros;
