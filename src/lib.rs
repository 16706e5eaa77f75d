//! # exactlti
//!
//! Exact structure of linear time-invariant systems: no round-off, ever, on the exact path.
//!
//! Layers (acyclic): [`field`] → [`poly`] → [`matrix`] → jordan → system → realization →
//! structure; `float` is a separate nalgebra backend used for cross-checks.
#![allow(non_snake_case)]
#![allow(clippy::needless_range_loop)]

pub mod algebraic;
pub mod error;
pub mod field;
pub mod jordan;
pub mod matrix;
pub mod poly;
pub mod report;

pub use error::{Error, Result};
