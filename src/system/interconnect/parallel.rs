//! Parallel connection (same input, outputs added): transfer matrix $G_1 + G_2$.
//!
//! With $x = [x_1; x_2]$: $A = \mathrm{diag}(A_1, A_2)$, $B = [B_1; B_2]$,
//! $C = [C_1,\ C_2]$, $D = D_1 + D_2$, and $E = \mathrm{diag}(E_1, E_2)$ for descriptor parts.

use super::{Blocks, Parts, joint_e, same_field};
use crate::error::{Error, Result};
use crate::field::Field;
use crate::matrix::Matrix;

/// The parallel connection $G_1 + G_2$.
///
/// # Errors
/// `Shape` when the two systems have different numbers of inputs or outputs;
/// `FieldMismatch`.
pub fn parallel<K: Field, S: Blocks<K>>(g1: &S, g2: &S) -> Result<S> {
    let (p, q) = (g1.blocks(), g2.blocks());
    same_field(&p, &q)?;
    if p.d.shape() != q.d.shape() {
        return Err(Error::Shape {
            op: "parallel: G1 and G2 need the same numbers of outputs and inputs (outputs x inputs)",
            expected: p.d.shape(),
            found: q.d.shape(),
        });
    }
    let k = p.field().clone();
    let a = Matrix::block_diag(k, &[p.a.clone(), q.a.clone()]);
    let b = p.b.vstack(q.b)?;
    let c = p.c.hstack(q.c)?;
    let d = p.d.try_add(q.d)?;
    S::from_parts(Parts {
        e: joint_e(&[p, q]),
        a,
        b,
        c,
        d,
    })
}
