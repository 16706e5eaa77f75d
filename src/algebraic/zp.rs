//! Former home of the slice kernels on integer polynomials, now [`crate::poly::zslice`]
//! (one integer-polynomial type, [`crate::poly::zpoly::ZPoly`], and kernels on its
//! coefficient slice). Kept as a re-export only while `jordan/realfield.rs` still names
//! this path.

pub use crate::poly::zslice::from_poly_q;
