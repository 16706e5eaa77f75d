//! Structure of linear systems: special coordinate basis, invariant zeros, mechanical
//! normal form.
//!
//! | module | computes |
//! |---|---|
//! | [`scb`] | special coordinate basis (Sannuti–Saberi; Grip–Saberi's symbolic procedure), exact |
//! | [`zeros`] | invariant zeros of the Rosenbrock system matrix (through the SCB; polynomial Smith form as fallback and oracle) |
//! | [`mechanical`] | mechanical normal form: a first-order system back to $\ddot q + D\dot q + Kq = Wu$ |
//! | [`steps`] | `zeros --steps`: the steps of the invariant zeros, recorded while they are computed |
//! | [`bifurcation`] | structural bifurcations over Q(p): the result on each branch where a condition vanishes |
//! | [`factor_qp`] | a polynomial in s over Q(p) factored into monic irreducibles |

pub mod bifurcation;
pub mod descriptor_zeros;
pub mod factor_qp;
pub mod mechanical;
pub mod scb;
pub(crate) mod steps;
pub mod zeros;
