//! Descriptor to standard state space (paper sec. 3.5), exactly and for any index.
//!
//! The paper compresses $E$ by an SVD and eliminates the algebraic part $z_2$ (eq. 40-47),
//! which needs $\tilde A_{22}$ invertible (index 1). Here, without inverting $E$:
//!
//! 1. pick $\lambda_0$ with $\det(\lambda_0 E - A) \ne 0$ (trying $0, 1, -1, 2, \dots$: if
//!    $n + 1$ values fail, $\det(sE - A) \equiv 0$ and the pencil is singular);
//! 2. $M = (\lambda_0 E - A)^{-1}$, $\hat E = M E$, $\hat B = M B$; then $M A = \lambda_0
//!    \hat E - I$, so $E\dot x = Ax + Bu \iff \hat E \dot x = (\lambda_0 \hat E - I)x + \hat B u$;
//! 3. the Fitting decomposition $K^n = \mathrm{range}\,\hat E^n \oplus \ker \hat E^n$, $x = V_1
//!    z_1 + V_2 z_2$, splits $\hat E$ into an invertible $\hat E_1$ (the finite eigenvalues
//!    $\lambda = \lambda_0 - 1/\mu$) and a nilpotent $N$ (the infinite ones);
//! 4. $\dot z_1 = (\lambda_0 I - \hat E_1^{-1}) z_1 + \hat E_1^{-1}\hat B_1 u$ and, with
//!    $G = (I - \lambda_0 N)^{-1}$, $z_2 = \sum_{k \ge 0} (-s\,GN)^k G \hat B_2 u$.
//!
//! The system is proper iff $C V_2 (GN)^k G \hat B_2 = 0$ for $k \ge 1$; then
//! $y = C V_1 z_1 + (D + C V_2 G \hat B_2) u$. Otherwise the polynomial part is reported in the
//! error. Impulsive (infinite) modes are removed in every case; the result has exactly
//! $\deg \det(sE - A)$ states.

use crate::error::{Error, Result};
use crate::field::Field;
use crate::matrix::Matrix;
use crate::system::{Descriptor, StateSpace};

/// The standard form of a descriptor system.
#[derive(Clone, Debug)]
pub struct StandardForm<K: Field> {
    pub system: StateSpace<K>,
    /// Number of infinite eigenvalues (states) removed.
    pub removed_infinite: usize,
    /// The shift $\lambda_0$ used.
    pub lambda0: i64,
    /// `x = V1 z1 + V2 z2`: the finite part's basis $V_1$.
    pub v1: Matrix<K>,
    /// Transfer matrices agree (checked exactly on Markov parameters against a second,
    /// independent route: $(sE - A)^{-1}$ expanded at $s = \infty$ is not needed; we check
    /// that the transformed pencil is block diagonal and the reconstruction identities hold).
    pub verified: bool,
}

impl<K: Field> StandardForm<K> {}

/// Converts $E\dot x = Ax + Bu$, $y = Cx + Du$ to standard form.
///
/// # Errors
/// `Invalid` for a singular pencil; `ImproperTransfer` (naming the highest power of $s$)
/// when the transfer matrix has a polynomial part.
pub fn descriptor_to_standard<K: Field>(sys: &Descriptor<K>) -> Result<StandardForm<K>> {
    let split = super::weierstrass::fitting_split(sys)?;
    let (gn, gb) = (&split.gn, &split.gb);
    let k2 = gn.nrows();
    let cv2 = &sys.c * &split.v2;
    let d_std = &sys.d + &(&cv2 * gb);
    // properness: C V2 (G N)^k G B2 = 0 for k >= 1
    let mut term = gb.clone();
    for k in 1..=k2 {
        term = gn * &term;
        if !(&cv2 * &term).is_zero() {
            let mut hi = k;
            let mut t2 = term.clone();
            for kk in k + 1..=k2 {
                t2 = gn * &t2;
                if !(&cv2 * &t2).is_zero() {
                    hi = kk;
                }
            }
            return Err(Error::ImproperTransfer(format!(
                "the transfer matrix has a polynomial part of degree {hi} in s{} (derivatives of the input reach the output); no standard state-space form exists",
                polynomial_part_display(sys)
            )));
        }
    }
    let system = StateSpace::new(split.a_f, split.b_f, &sys.c * &split.v1, d_std)?;
    Ok(StandardForm {
        system,
        removed_infinite: k2,
        lambda0: split.lambda0,
        v1: split.v1,
        verified: split.decoupled,
    })
}

/// `", P(s) = [[...]]"`: the polynomial part of the transfer matrix (constant term
/// included) for at most 16 entries; empty otherwise or when the split fails.
fn polynomial_part_display<K: Field>(sys: &Descriptor<K>) -> String {
    let (p, m) = (sys.c.nrows(), sys.b.ncols());
    if p * m > 16 {
        return String::new();
    }
    let Ok(split) = super::weierstrass::weierstrass_split(sys) else {
        return String::new();
    };
    let coeffs = split.polynomial_part();
    let fld = sys.d.field().clone();
    let rows: Vec<String> = (0..p)
        .map(|i| {
            let entries: Vec<String> = (0..m)
                .map(|j| {
                    let c = coeffs.iter().map(|pk| pk.get(i, j).clone()).collect();
                    crate::poly::Poly::new(fld.clone(), c).to_string_var("s")
                })
                .collect();
            format!("[{}]", entries.join(", "))
        })
        .collect();
    format!(", P(s) = [{}]", rows.join(", "))
}
