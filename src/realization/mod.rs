//! Realization theory, exact: controllability, observability, Hankel rank (McMillan degree),
//! Kalman decomposition, minimal realizations by several methods, descriptor to standard
//! form, Gramians.
//!
//! A realization $(A, B, C, D)$ of a proper transfer matrix $G(s)$ satisfies
//! $G(s) = C(sI - A)^{-1}B + D$; it is minimal iff $(A, B)$ is controllable and $(A, C)$
//! observable, and then its order is the McMillan degree $= \mathrm{rank}\, H$ of the block
//! Hankel matrix of the Markov parameters. Minimal realizations are unique up to
//! $A \mapsto T^{-1}AT$. No tolerance appears anywhere here: the order is exact.
//!
//! | entry point | algorithm |
//! |---|---|
//! | [`controllability_matrix`], [`observability_matrix`], [`hankel_matrix`], [`mcmillan_degree`] | Krylov matrices, rank over the field |
//! | [`kalman_decomposition`] | controllable subspace $\mathcal R$, unobservable $\mathcal N$, four parts |
//! | [`realize_as_written`] | a transfer matrix as written: column companion blocks, nothing cancelled |
//! | [`minimal`] (`MinrealMethod::Kalman`, default), over every [`SystemField`] | the $co$ block of the Kalman decomposition |
//! | `MinrealMethod::Rosenbrock` | staircase of exact row compressions of $[A\ B; C\ 0]$, then of the dual (paper sec. 2.3) |
//! | `MinrealMethod::HoKalman` | rank factorization of the block Hankel matrix over the field (exact ERA) |
//! | `MinrealMethod::Jordan` ([`minimal_jordan`], [`minimal_jordan_qp`]) | Jordan-form method (sec. 3.3): drop non-contributing modes, compact repeated ones, real Jordan blocks |
//! | [`descriptor_to_standard`] | $E^{-1}A$, index-1 elimination, or a Weierstrass-type split |
//! | [`modal_table`], [`modal_table_over`] | eigenvalue, frequency, damping ratio, time constant, period per mode (Tab. 8) |
//! | [`gramians`] | exact Lyapunov solves $AW + WA^T = -BB^T$ for stable systems |

mod as_written;
pub mod contribution;
pub mod contribution_steps;
mod controllability;
mod ctrb_structure;
mod damp;
mod descriptor;
mod descriptor_elim;
mod descriptor_minimal;
mod descriptor_minimal_result;
mod descriptor_minimal_steps;
mod from_transfer;
mod gramian;
mod ho_kalman;
mod jordan_core;
mod jordan_method;
mod jordan_method_primary;
mod jordan_method_stages;
mod jordan_result;
mod kalman;
mod method;
mod minimal;
mod modal;
mod rosenbrock;
pub(crate) mod standard_steps;
pub mod steps;
mod steps_record;
mod weierstrass;

pub use as_written::{Realize, WrittenRealization, WrittenTransfer, realize_as_written};
pub use controllability::{
    controllability_matrix, hankel_matrix, is_controllable, is_observable, mcmillan_degree,
    observability_matrix, pbh_controllable, pbh_observable, row_compression,
};
pub use ctrb_structure::{
    ControllabilityStructure, DescriptorControllability, controllability_structure,
    descriptor_controllability, observability_structure,
};
pub use damp::{DampRow, damp, damp_over};
pub use descriptor::{
    StandardForm, StandardMethod, descriptor_to_standard, descriptor_to_standard_recorded,
    finite_dynamics,
};
pub use descriptor_minimal::{
    DescriptorMinimal, is_minimal_at_infinity, minimal_descriptor, minimal_descriptor_recorded,
};
pub use from_transfer::{TransferRealization, realize_state_space, realize_transfer};
pub use gramian::{GramType, Gramian, Gramians, gramian, gramians, is_hurwitz, lyapunov};
pub use ho_kalman::minimal_ho_kalman_recorded;
pub use jordan_method::{minimal_jordan, minimal_jordan_rational, minimal_jordan_with};
pub use jordan_method_primary::{minimal_jordan_primary, minimal_jordan_qp};
pub use jordan_result::{
    JordanMethod, JordanMinimal, ModalBlock, PrimaryBlock, PrimaryJordanMinimal, RealModalBlock,
};
pub use kalman::{KalmanDecomposition, kalman_decomposition};
pub use method::{ModalField, SystemField, minimal};
pub use minimal::{MinimalRealization, MinrealMethod, minimal_kalman};
pub use modal::{ExactFigure, ModalTable, Mode, modal_table, modal_table_over};
pub use rosenbrock::{controllable_part, controllable_staircase, minimal_rosenbrock_recorded};
pub use weierstrass::{
    WeierstrassSplit, descriptor_transfer_matrix, eval_transfer, same_transfer, weierstrass_split,
};
