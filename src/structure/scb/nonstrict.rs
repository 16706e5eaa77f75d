//! Non-strictly proper systems (sec. II-D and III-C): pre-transformations $U$, $Y$ with
//! $\hat B = \tilde B U$, $\hat C = Y^{-1} \tilde C$, $\hat D = Y^{-1} \tilde D U = \mathrm{diag}(I_{m_0}, 0)$,
//! then the strictly proper algorithm on $(\hat A - B_0 C_0, \hat B_1, \hat C_1)$ and
//! $\Gamma_1 = \bar\Gamma_1$, $\Gamma_2 = \mathrm{diag}(I_{m_0}, \bar\Gamma_2)$,
//! $\Gamma_3 = \mathrm{diag}(I_{m_0}, \bar\Gamma_3)$.
//!
//! $Y^{-1} = [Y_1; Y_2]$: $Y_2$ the canonical left null space of $\tilde D$, $Y_1$ unit rows
//! completing it (leading-one deletion rule); $U^{-1} = [U_1; U_2]$ with $U_1 = Y_1 \tilde D$
//! and $U_2$ unit rows completing $U_1$.

use super::silverman::{leading_one_complement, unit_rows};
use crate::error::Result;
use crate::field::Field;
use crate::matrix::Matrix;

/// The pre-transformations of sec. II-D.
#[derive(Clone, Debug)]
pub(crate) struct PreTransform<K: Field> {
    pub m0: usize,
    pub u: Matrix<K>,
    pub y: Matrix<K>,
    pub yinv: Matrix<K>,
}

/// $U$ and $Y$ for a feedthrough matrix $\tilde D$ ($p \times m$).
pub(crate) fn pre_transform<K: Field>(d: &Matrix<K>) -> Result<PreTransform<K>> {
    let k = d.field().clone();
    let (p, m) = d.shape();
    let y2 = d.left_nullspace();
    let y1 = if y2.nrows() == 0 {
        Matrix::identity(k.clone(), p)
    } else {
        unit_rows(&k, p, &leading_one_complement(&y2))
    };
    let m0 = y1.nrows();
    let yinv = y1.vstack(&y2)?;
    let u1 = &y1 * d;
    let u2 = unit_rows(&k, m, &leading_one_complement(&u1));
    let uinv = u1.vstack(&u2)?;
    Ok(PreTransform {
        m0,
        u: uinv.inverse()?,
        y: yinv.inverse()?,
        yinv,
    })
}
