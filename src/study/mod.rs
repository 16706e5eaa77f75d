//! Parameter studies: eigenvalues along one parameter $v$ of a family $A(v)$ with entries
//! in $\mathbb{Q}(v)$, and the exact parameter values where they change qualitatively.
//!
//! | entry point | computes |
//! |---|---|
//! | [`ParamFamily::from_file`] | the family $A(v)$ of a system file, one parameter symbolic, entries in $\mathbb{Q}(v)$ (the tower's `RatFuncField`, [`qv`]) |
//! | [`charpoly_xv`] | $P(x, v) = p_n(v) \chi_{A(v)}(x)$ exactly (evaluation/interpolation) |
//! | [`critical_values`] | zero eigenvalues, imaginary pairs, double eigenvalues as algebraic numbers; stability per interval |
//! | [`critical::over_k::critical_values_over_k`] | the same for a family over $K(v)$, $K = \mathbb{Q}(\sqrt d)$ or $\mathbb{Q}(i)$ (values with minimal polynomials over $\mathbb{Q}$ and $K$, structure in $K(v_0)$) |
//! | `family_read::read_file_matrices` (crate-internal) | a family file's matrices, entries read into $\mathbb{Q}(v)$ or $K(v)$ |
//! | [`sweep`] | float eigenvalues at many parameter values, in parallel (finite eigenvalues of the pencil where $E(v)$ is singular, counted exactly by [`SweepPlan`]) |
//!
//! The exact path never uses floats: $P$, the Hurwitz determinant and the discriminant are
//! polynomials over $\mathbb{Q}$, their roots are certified, and the confirmations and
//! Jordan structures are computed in $\mathbb{Q}(v_0) = \mathbb{Q}[t]/(f)$.

pub(crate) mod bivar;
pub mod critical;
pub(crate) mod family;
pub(crate) mod family_read;
pub(crate) mod finite;
pub mod hurwitz;
pub(crate) mod modp;
pub mod qv;
pub mod sweep;
pub(crate) mod sweep_plan;

pub use bivar::{BiPoly, charpoly_xv, charpoly_xv_content, discriminant_v, hurwitz_delta_n1};
pub use critical::{
    CriticalKind, CriticalValue, CriticalValues, SingularReason, StudyInterval, critical_values,
};
pub use family::{FamilyForm, ParamFamily};
pub use hurwitz::{RootCounts, hurwitz_stable, root_counts};
pub use sweep::{SweepResult, sweep, sweep_values};
pub use sweep_plan::{PointStatus, SweepPlan};
