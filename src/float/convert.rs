//! Exact to float: `Matrix<K>` to nalgebra `DMatrix<f64>` through the field's embedding.

use crate::error::{Error, Result};
use crate::field::Field;
use crate::matrix::Matrix;
use nalgebra::DMatrix;
use num_complex::Complex;

/// The real `f64` image of an exact matrix.
///
/// # Errors
/// `Unsupported` when an entry is not real under the field's embedding (the float backend
/// is real), or the field has no embedding ([`Field::approx`] is `None`).
pub fn to_dmatrix<K: Field>(m: &Matrix<K>) -> Result<DMatrix<f64>> {
    let c = to_cmatrix(m)?;
    if c.iter().any(|z| z.im != 0.0) {
        return Err(Error::Unsupported(
            "the float path works on real matrices; this entry is complex".into(),
        ));
    }
    Ok(c.map(|z| z.re))
}

/// The complex `f64` image of an exact matrix (for fields with a non-real embedding, such
/// as $\mathbb{Q}(i)$).
///
/// # Errors
/// `Unsupported` when the field has no embedding ([`Field::approx`] is `None`).
pub fn to_cmatrix<K: Field>(m: &Matrix<K>) -> Result<DMatrix<Complex<f64>>> {
    let mut out = DMatrix::zeros(m.nrows(), m.ncols());
    for i in 0..m.nrows() {
        for j in 0..m.ncols() {
            let Some((re, im)) = m.field().approx(m.get(i, j)) else {
                return Err(Error::Unsupported(
                    "the float path needs numeric entries; this field has no embedding".into(),
                ));
            };
            out[(i, j)] = Complex::new(re, im);
        }
    }
    Ok(out)
}
