//! Lehmer's gcd and canonical fractions: they live in the field layer
//! ([`crate::field::lehmer`]), where the quadratic field's arithmetic also uses them; the
//! $\mathbb{Q}$ kernels reach them here.

pub use crate::field::lehmer::{fraction, gcd};
