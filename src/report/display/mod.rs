//! Every display of the math types, in every format: the element displays of the fields
//! ([`crate::field::ElemDisplay`]: text `-3/7`, `1 - sqrt(2)/2`, `(a + b)^2/c`; LaTeX), and the
//! `Display` impls and text helpers of polynomials, algebraic numbers, extension fields,
//! matrices and systems. The math folders hold values; their strings are made here (issue
//! 23: values in math, strings in report/). `impl Display for T` may live in any module of
//! the crate, so callers write `x.to_string()`, `k.fmt_elem(a)`, `p.to_string_var("s")` as
//! before.
//!
//! Compiled with the exact core too (without the `cli` feature it is mounted as
//! `crate::display` by `lib.rs`: the core's types need their `Display`), so it refers to its
//! siblings by `super::` only and uses nothing of the rest of `report`.

pub mod algebraic;
pub mod matrix;
pub mod mpoly;
pub mod poly;
pub mod ratfunc;
pub mod scalar;

pub use algebraic::{
    approx_text, closed_form, closed_form_latex, near_text, quadratic_string, value_display,
};
pub use mpoly::latex_name;
pub use poly::{LATEX, SumStyle, TEXT, fmt_poly, poly_sum};
pub use ratfunc::FACTOR_DISPLAY_TERMS;
pub use scalar::{fmt_pair, fmt_rational, quadratic_display, quadratic_latex};
