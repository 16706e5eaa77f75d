//! Feedback connection $u = r + \sigma K y$ around $G$: transfer matrix
//! $G_{fb} = (I - \sigma G K)^{-1} G = G (I - \sigma K G)^{-1}$ ($\sigma = -1$ is negative
//! feedback, python-control's default `sign=-1`).
//!
//! With $G = (A_1, B_1, C_1, D_1)$ ($p$ outputs, $m$ inputs), $K = (A_2, B_2, C_2, D_2)$
//! ($m$ outputs, $p$ inputs) and the algebraic loop $F = I_m - \sigma D_2 D_1$ invertible,
//! $E_D = F^{-1} D_2$, $E_C = F^{-1} C_2$, $T_1 = I_p + \sigma D_1 E_D$,
//! $T_2 = I_m + \sigma E_D D_1$ (python-control's `StateSpace.feedback`):
//! $A = \begin{bmatrix} A_1 + \sigma B_1 E_D C_1 & \sigma B_1 E_C \\ B_2 T_1 C_1 & A_2 + \sigma B_2 D_1 E_C \end{bmatrix}$,
//! $B = \begin{bmatrix} B_1 T_2 \\ B_2 D_1 T_2 \end{bmatrix}$,
//! $C = [T_1 C_1,\ \sigma D_1 E_C]$, $D = D_1 T_2$, and $E = \mathrm{diag}(E_1, E_2)$ for
//! descriptor parts. A singular $F$ (the loop has no unique solution for every input) is
//! refused with [`Error::IllPosed`]; $F$ is invertible iff $I_p - \sigma D_1 D_2$ is.

use super::{Blocks, Parts, Sign, grid2, joint_e, same_field};
use crate::error::{Error, Result};
use crate::field::Field;
use crate::matrix::Matrix;

/// The closed loop of `g` with `k` in the feedback path (a system or a [`super::static_gain`]).
///
/// # Errors
/// `Shape` when `k` is not (inputs of `g`) x (outputs of `g`); `IllPosed` when
/// $I - \sigma D_2 D_1$ is singular; `FieldMismatch`.
pub fn feedback<K: Field, S: Blocks<K>>(g: &S, k: &S, sign: Sign) -> Result<S> {
    let (p, q) = (g.blocks(), k.blocks());
    same_field(&p, &q)?;
    let (ny, nu) = p.d.shape();
    if q.d.shape() != (nu, ny) {
        return Err(Error::Shape {
            op: "feedback: the feedback path K (inputs of G x outputs of G)",
            expected: (nu, ny),
            found: q.d.shape(),
        });
    }
    let fld = p.field().clone();
    let s = sign.value(&fld);
    let f = &Matrix::identity(fld.clone(), nu) - &(q.d * p.d).scale(&s);
    let fi = f.inverse().map_err(|e| match e {
        Error::Singular => Error::IllPosed(format!(
            "feedback with sign {:+}: I - sign * D_K * D_G is singular (the algebraic loop \
             through the feedthroughs has no unique solution)",
            sign.as_i64()
        )),
        e => e,
    })?;
    let e_d = &fi * q.d;
    let e_c = &fi * q.c;
    let t1 = &Matrix::identity(fld.clone(), ny) + &(p.d * &e_d).scale(&s);
    let t2 = &Matrix::identity(fld, nu) + &(&e_d * p.d).scale(&s);
    let a11 = p.a + &(&(p.b * &e_d) * p.c).scale(&s);
    let a12 = (p.b * &e_c).scale(&s);
    let a21 = &(q.b * &t1) * p.c;
    let a22 = q.a + &(&(q.b * p.d) * &e_c).scale(&s);
    let a = grid2(&a11, &a12, &a21, &a22)?;
    let b1t2 = p.b * &t2;
    let b = b1t2.vstack(&(&(q.b * p.d) * &t2))?;
    let c = (&t1 * p.c).hstack(&(p.d * &e_c).scale(&s))?;
    let d = p.d * &t2;
    S::from_parts(Parts {
        e: joint_e(&[p, q]),
        a,
        b,
        c,
        d,
    })
}
