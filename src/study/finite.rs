//! The finite part of a regular pencil $sE - A$ at one parameter value: a matrix $A_f$ of
//! order $r = \deg \det(sE - A)$ with $\det(sI - A_f) = \det(sE - A) / c$ for a nonzero
//! constant $c$, and $A_f$ similar to the finite Weierstrass block of the pencil (so its
//! Jordan structure is the pencil's finite one). The $n - r$ infinite eigenvalues are
//! dropped.
//!
//! $A_f$ comes from the Fitting split of [`weierstrass_split`] ($M = (\lambda_0 E - A)^{-1}$,
//! $\hat E = ME$, $K^n = \mathrm{range}\,\hat E^n \oplus \ker \hat E^n$), computed exactly
//! over any field, so the study's exact confirmations and Jordan blocks at a critical value
//! $v_0$ (over $\mathbb{Q}(v_0)$) work when $E(v_0)$ or $M(v_0)$ is singular.
//!
//! A second-order pencil $s^2 M + s L + K$ is linearized first:
//! $E = \begin{bmatrix} I & 0 \\ 0 & M \end{bmatrix}$,
//! $A = \begin{bmatrix} 0 & I \\ -K & -L \end{bmatrix}$, so that
//! $\det(sE - A) = \det(s^2 M + s L + K)$.

use crate::error::{Error, Result};
use crate::field::Field;
use crate::matrix::Matrix;
use crate::realization::weierstrass_split;
use crate::system::Descriptor;

/// $A_f$ of the pencil $sE - A$ (see the module docs).
///
/// # Errors
/// `Singular` when $\det(sE - A) \equiv 0$ (a singular pencil has no finite part);
/// shape errors when `e`, `a` are not square of one size.
pub fn finite_part<K: Field>(e: Matrix<K>, a: Matrix<K>) -> Result<Matrix<K>> {
    let k = a.field().clone();
    let n = a.nrows();
    let sys = Descriptor::new(
        e,
        a,
        Matrix::zeros(k.clone(), n, 0),
        Matrix::zeros(k.clone(), 0, n),
        Matrix::zeros(k, 0, 0),
    )?;
    match weierstrass_split(&sys) {
        Ok(split) => Ok(split.finite.a),
        Err(Error::Invalid(_)) => Err(Error::Singular),
        Err(e) => Err(e),
    }
}

/// The first-order linearization $(E, A)$ of $s^2 M + s L + K$ (module docs).
pub fn linearize_second_order<K: Field>(
    m: &Matrix<K>,
    l: &Matrix<K>,
    kk: &Matrix<K>,
) -> (Matrix<K>, Matrix<K>) {
    let k = m.field().clone();
    let n = m.nrows();
    let minus = k.neg(&k.one());
    let mut e = Matrix::identity(k.clone(), 2 * n);
    e.set_block(n, n, m);
    let mut a = Matrix::zeros(k.clone(), 2 * n, 2 * n);
    a.set_block(0, n, &Matrix::identity(k, n));
    a.set_block(n, 0, &kk.scale(&minus));
    a.set_block(n, n, &l.scale(&minus));
    (e, a)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::{Q, Rational};

    fn m(rows: &[&[i64]]) -> Matrix<Q> {
        Matrix::from_rows(
            Q,
            rows.iter()
                .map(|r| {
                    r.iter()
                        .map(|&x| Rational::from_integer(x.into()))
                        .collect()
                })
                .collect(),
        )
        .unwrap()
    }

    #[test]
    fn finite_part_of_index_one_and_singular_pencils() {
        // E = diag(1, 0), A = [[2, 1], [1, -1]]: det(sE - A) = -(s - 2) - 1 = -(s - 3)... here
        // det [[s - 2, -1], [-1, 1]] = s - 2 - 1 = s - 3: one finite eigenvalue 3
        let af = finite_part(m(&[&[1, 0], &[0, 0]]), m(&[&[2, 1], &[1, -1]])).unwrap();
        assert_eq!(af, m(&[&[3]]));
        // E = 0, A = I: no finite eigenvalue
        let af = finite_part(m(&[&[0, 0], &[0, 0]]), m(&[&[1, 0], &[0, 1]])).unwrap();
        assert_eq!(af.nrows(), 0);
        // E = A = diag(1, 0): det(sE - A) = 0 for every s
        assert!(matches!(
            finite_part(m(&[&[1, 0], &[0, 0]]), m(&[&[1, 0], &[0, 0]])),
            Err(Error::Singular)
        ));
        // s^2 M + K with M = diag(1, 0), K = diag(4, 1): det = (s^2 + 4) * 1
        let (e, a) = linearize_second_order(
            &m(&[&[1, 0], &[0, 0]]),
            &m(&[&[0, 0], &[0, 0]]),
            &m(&[&[4, 0], &[0, 1]]),
        );
        let af = finite_part(e, a).unwrap();
        assert_eq!(af.charpoly().unwrap().to_string(), "x^2 + 4");
    }
}
