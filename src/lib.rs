//! # exactlti
//!
//! Exact structure of linear time-invariant systems: no round-off, ever, on the exact path.
//! Numbers are exact rationals (`"0.08"` is 2/25), elements of quadratic fields or of
//! number fields; every exact result carries the check of its defining identity
//! (`verified`).
//!
//! ## A tour
//!
//! ```
//! use exactlti::qmat;
//! use exactlti::jordan::jordan;
//! use exactlti::realization::{MinrealMethod, minimal};
//! use exactlti::system::StateSpace;
//!
//! // x' = A x + B u, y = C x + D u over Q; text entries are exact decimals
//! let sys = StateSpace::new(
//!     qmat![[0, 1, 0], [-2, "-0.3", 0], [0, 0, -1]],
//!     qmat![[0], [1], [0]],
//!     qmat![[1, 0, 1]],
//!     qmat![[0]],
//! )
//! .unwrap();
//!
//! // exact Jordan form: A T = T J checked exactly
//! let jf = jordan(&sys.a).unwrap();
//! assert!(jf.verified);
//! assert_eq!(jf.charpoly.to_string(), "x^3 + 13/10*x^2 + 23/10*x + 2");
//!
//! // minimal realization: the mode -1 is uncontrollable, so the order drops to 2;
//! // Markov parameters up to index 2n are checked exactly
//! let min = minimal(&sys, MinrealMethod::Kalman).unwrap();
//! assert_eq!((min.order, min.verified), (2, true));
//! assert_eq!(min.system.markov(6), sys.markov(6));
//! ```
//!
//! System files (JSON or TOML, exact numbers and parameter expressions) load without the
//! command line through [`io::load_system_str`] / [`io::load_system_path`]; generic code
//! over the file's field is written once as an [`api::SystemVisitor`] and dispatched by
//! [`api::System::run`]. Every operation of the command line runs through [`api`] (the
//! front door the command line and the Python package stand on). Reports (text, JSON, LaTeX) are built in [`report`], apart
//! from the math.
//!
//! ## Layers (acyclic)
//!
//! Each floor imports only its own floor and the floors below it. `python3 scripts/layers.py`
//! checks the import graph: no cycle between modules, none between files, no arrow up a
//! floor. The floors, lowest first, as the script numbers them:
//!
//! 0. [`error`], [`rng`]: leaves;
//! 1. [`field`]: the [`field::Field`] trait, Q, quadratic and complex fields, the one
//!    expression reader ([`field::expr`]: lexer, grammar, evaluators); beside it [`qkernels`]:
//!    integer/rational matrix kernels on `BigRational` (modular, Bareiss, the integer
//!    product), which [`matrix`] dispatches to;
//! 2. [`poly`]: polynomials over a field, integer polynomials and their factorization;
//!    beside it [`mpoly`] (multivariate) and [`ratfunc`] (rational functions);
//! 3. [`algebraic`]: number fields, algebraic numbers, root isolation (needs `Poly<Q>` and
//!    irreducibility, so it sits above `poly`);
//! 4. [`matrix`];
//! 5. [`jordan`], then [`pencil`] (Kronecker structure of pencils, on `jordan`);
//! 6. [`system`] (needs only `matrix` and below);
//! 7. [`realization`];
//! 8. [`structure`];
//! 9. [`float`]: the nalgebra backend for cross-checks (feature `float`; it may use any
//!    floor below `io`);
//! 10. [`io`] (system files), then `study` (one-parameter families read from files);
//! 11. [`report`] (text/JSON/LaTeX);
//! 12. [`api`]: the front door ([`api::System`], every operation as an [`api::Command`]
//!     returning a report with `verified`, the worker thread with a deadline);
//! 13. [`cli`] (feature `cli`): arguments -> [`api`] -> rendered report.
//!
//! ## Features
//!
//! `cli` (default: [`io`], [`report`], [`cli`] with clap, serde, serde_json and toml) and
//! `float` (default: [`float`] with nalgebra). `cargo build --lib --no-default-features`
//! builds the exact core alone.
#![allow(non_snake_case)]
#![allow(clippy::needless_range_loop)]
#![allow(clippy::wrong_self_convention)]

pub mod algebraic;
#[cfg(feature = "cli")]
pub mod api;
#[cfg(feature = "cli")]
pub mod cli;
/// `report::display` (the `Display` impls and element displays of the math types) for a
/// build without the `cli` feature, where `report` is absent: the core needs its displays.
#[cfg(not(feature = "cli"))]
#[path = "report/display/mod.rs"]
pub mod display;
pub mod error;
pub mod field;
#[cfg(feature = "float")]
pub mod float;
#[cfg(feature = "cli")]
pub mod io;
pub mod jordan;
pub mod matrix;
pub mod mpoly;
pub mod multibody;
pub mod pencil;
pub mod poly;
pub mod qkernels;
pub mod ratfunc;
pub mod realization;
#[cfg(feature = "cli")]
pub mod report;
pub mod rng;
pub mod structure;
#[cfg(feature = "cli")]
pub mod study;
pub mod system;

pub use error::{Error, Result};
