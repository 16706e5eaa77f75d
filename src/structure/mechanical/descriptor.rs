//! Descriptor systems $F \dot x = A x + B u$ with invertible $F$ (sec. 3.1, eq. 16).
//!
//! The requirements become $[I\ 0]\,T A = [0\ I]\,T F$ and $T B = [0; I_p]$, a linear system
//! in $\mathrm{vec}(T)$ with $F^T \otimes [0\ I]$ in place of $I \otimes [0\ I]$; the state map
//! is $z = (T F) x$. The construction never forms $F^{-1}$. The existence test runs on the
//! equivalent standard pair $(F^{-1}A, F^{-1}B)$, obtained by one exact linear solve
//! $F [\hat A, \hat B] = [A, B]$ (existence is a property of that pair).
//!
//! | entry point | computes |
//! |---|---|
//! | [`mechanical_normal_form_descriptor`] | the normal form of $(F, A, B, C, D)$ over $\mathbb{Q}$ |

use super::existence::{Existence, ExistenceParts, decide_existence_parts};
use super::{DEFAULT_MAX_CANDIDATES, MnfResult, mechanical_normal_form_in};
use crate::error::{Error, Result};
use crate::field::{Field, Q};
use crate::matrix::Matrix;

/// Mechanical normal form of $F \dot x = A x + B u$, $y = C x + D u$ with invertible $F$:
/// $\tilde A = T A (TF)^{-1}$, $\tilde B = T B = [0; I_p]$, $\tilde C = C (TF)^{-1}$,
/// reported `T` $= TF$ (so `z = T x`) and `T_rows` $= T$.
///
/// # Errors
/// `Shape`/`NotSquare` when the matrices do not form a system or `f` is not `n x n`;
/// `Invalid` when `f` is singular; otherwise as [`super::mechanical_normal_form`].
pub fn mechanical_normal_form_descriptor(
    f: &Matrix<Q>,
    a: &Matrix<Q>,
    b: &Matrix<Q>,
    c: &Matrix<Q>,
    d: &Matrix<Q>,
) -> Result<MnfResult> {
    mechanical_normal_form_in(Some(f), a, b, c, d, DEFAULT_MAX_CANDIDATES)
}

/// Existence for the descriptor system via the equivalent standard pair.
///
/// # Errors
/// `Shape` when `f` is not `n x n`; `Invalid` when `f` is singular.
pub(crate) fn decide_existence_descriptor<K: Field>(
    f: &Matrix<K>,
    a: &Matrix<K>,
    b: &Matrix<K>,
) -> Result<(Existence<K>, ExistenceParts<K>)> {
    let n = a.nrows();
    if f.shape() != (n, n) {
        return Err(Error::Shape {
            op: "mechanical_normal_form_descriptor",
            expected: (n, n),
            found: f.shape(),
        });
    }
    let ab = a.hstack(b)?;
    match f.solve(&ab)? {
        Some((x, null)) if null.ncols() == 0 => {
            let a_s = x.submatrix(0, n, 0, n);
            let b_s = x.submatrix(0, n, n, n + b.ncols());
            Ok(decide_existence_parts(&a_s, &b_s))
        }
        _ => Err(Error::Invalid(
            "the descriptor matrix F is singular; only invertible F is supported".into(),
        )),
    }
}
