//! Univariate polynomials over any exact [`Field`](crate::field::Field).
//!
//! [`Poly<K>`] is dense, low degree first, canonical (no trailing zeros), and stores its
//! domain value `K`. Arithmetic, division with remainder, gcd and extended gcd, derivative,
//! square-free factorization (Yun), composition, evaluation, resultant (Euclidean remainder
//! sequence over the field), parsing and display.
//!
//! | entry point | computes |
//! |---|---|
//! | [`Poly::divrem`] | $f = q g + r$, $\deg r < \deg g$ |
//! | [`Poly::gcd`], [`Poly::xgcd`] | monic $g = s f + t h$ |
//! | [`Poly::squarefree`] | $f = c \prod_i f_i^i$, $f_i$ square-free, coprime |
//! | [`Poly::resultant`] | $\mathrm{Res}(f, g)$ |
//! | [`parse_poly_q`] | `x^4 + 4*x^2 + 1` into `Poly<Q>` |
//!
//! Integer polynomials ([`zpoly::ZPoly`]) and their factorization over Q ([`factor`]) live
//! in the submodules.

mod arith;
pub mod factor;
pub(crate) mod fp;
mod parse;
mod power_sums;
mod sturm;
pub mod zpoly;
pub mod zslice;
pub use arith::*;
pub use parse::parse_poly_q;
pub use power_sums::{monic_from_power_sums, newton_power_sums};
pub use sturm::sign_variations;
