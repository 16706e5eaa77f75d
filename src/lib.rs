//! # exactlti
//!
//! Exact structure of linear time-invariant systems: no round-off, ever, on the exact path.
//!
//! Layers (acyclic): [`field`] → [`poly`] → [`matrix`] → jordan → system → realization →
//! structure; `float` is a separate nalgebra backend used for cross-checks.
#![allow(non_snake_case)]
#![allow(clippy::needless_range_loop)]
#![allow(clippy::wrong_self_convention)]

pub mod algebraic;
pub mod cli;
pub mod error;
pub mod field;
pub mod float;
pub mod io;
pub mod jordan;
pub mod matrix;
pub mod poly;
pub mod realization;
pub mod report;
pub mod structure;
pub mod study;
pub mod system;

pub use error::{Error, Result};
