//! Appending systems side by side: transfer matrix $\mathrm{diag}(G_1, G_2, \dots)$.
//!
//! $A$, $B$, $C$, $D$ (and $E$ for descriptor parts) are the block diagonals of the parts'
//! matrices; inputs and outputs are stacked in the order of the parts.

use super::{Blocks, BlocksRef, Parts, joint_e, same_field};
use crate::error::{Error, Result};
use crate::field::Field;
use crate::matrix::Matrix;

/// The systems side by side (python-control's `append`).
///
/// # Errors
/// `Invalid` for an empty list; `FieldMismatch`.
pub fn append<K: Field, S: Blocks<K>>(systems: &[S]) -> Result<S> {
    let parts: Vec<BlocksRef<'_, K>> = systems.iter().map(Blocks::blocks).collect();
    let Some(first) = parts.first() else {
        return Err(Error::Invalid("append: no systems given".into()));
    };
    for p in &parts {
        same_field(first, p)?;
    }
    let k = first.field().clone();
    let diag = |f: &dyn Fn(&BlocksRef<'_, K>) -> Matrix<K>| {
        let blocks: Vec<Matrix<K>> = parts.iter().map(f).collect();
        Matrix::block_diag(k.clone(), &blocks)
    };
    S::from_parts(Parts {
        e: joint_e(&parts),
        a: diag(&|p| p.a.clone()),
        b: diag(&|p| p.b.clone()),
        c: diag(&|p| p.c.clone()),
        d: diag(&|p| p.d.clone()),
    })
}
