//! Series connection $u \to G_1 \to G_2 \to y$: transfer matrix $G_2 G_1$.
//!
//! With $x = [x_1; x_2]$ (python-control's `series(G1, G2)`, i.e. `G2 * G1`):
//! $A = \begin{bmatrix} A_1 & 0 \\ B_2 C_1 & A_2 \end{bmatrix}$,
//! $B = \begin{bmatrix} B_1 \\ B_2 D_1 \end{bmatrix}$, $C = [D_2 C_1,\ C_2]$,
//! $D = D_2 D_1$, and $E = \mathrm{diag}(E_1, E_2)$ for descriptor parts.

use super::{Blocks, Parts, grid2, joint_e, same_field};
use crate::error::{Error, Result};
use crate::field::Field;
use crate::matrix::Matrix;

/// The series connection of `g1` followed by `g2` (outputs of `g1` feed the inputs of `g2`).
///
/// # Errors
/// `Shape` when `g1` has not as many outputs as `g2` has inputs; `FieldMismatch`.
pub fn series<K: Field, S: Blocks<K>>(g1: &S, g2: &S) -> Result<S> {
    let (p, q) = (g1.blocks(), g2.blocks());
    same_field(&p, &q)?;
    if p.c.nrows() != q.b.ncols() {
        return Err(Error::Shape {
            op: "series: D of G2 (its inputs are the outputs of G1)",
            expected: (q.d.nrows(), p.c.nrows()),
            found: q.d.shape(),
        });
    }
    let k = p.field().clone();
    let zero = Matrix::zeros(k, p.n(), q.n());
    let a = grid2(p.a, &zero, &(q.b * p.c), q.a)?;
    let b = p.b.vstack(&(q.b * p.d))?;
    let c = (q.d * p.c).hstack(q.c)?;
    let d = q.d * p.d;
    S::from_parts(Parts {
        e: joint_e(&[p, q]),
        a,
        b,
        c,
        d,
    })
}
