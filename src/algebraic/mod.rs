//! Algebraic numbers (placeholder header, completed below).
pub mod isolate_complex;
pub mod isolate_real;
pub(crate) mod zp;
