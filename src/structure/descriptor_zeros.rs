//! Zeros of a descriptor system from the Kronecker structure of its system pencil.
//!
//! $S(s) = \begin{bmatrix} A - sE & B \\ C & D\end{bmatrix} = A_S - sE_S$ with
//! $A_S = \begin{bmatrix} A & B \\ C & D\end{bmatrix}$, $E_S = \mathrm{diag}(E, 0)$.
//! The finite eigenvalues of $S$ (with their Jordan blocks) are the invariant zeros, their
//! product the zero polynomial $\det(sI - A_f)$; an infinite elementary divisor of size
//! $k \ge 2$ is an infinite zero of order $k - 1$ (the convention of SLICOT AG08BD); the
//! normal rank and the minimal indices of $S$ are reported as well. Everything is computed
//! by [`crate::pencil::kronecker_structure`] and inherits its verification.

use crate::error::Result;
use crate::field::Field;
use crate::matrix::Matrix;
use crate::pencil::{KroneckerStructure, kronecker_structure};
use crate::poly::Poly;
use crate::system::Descriptor;

/// Zeros of a descriptor system.
#[derive(Clone, Debug)]
pub struct DescriptorZeros<K: Field> {
    /// Kronecker structure of the system pencil $S(s)$.
    pub pencil: KroneckerStructure<K>,
    /// $\det(sI - A_f)$ of the finite part: the invariant zero polynomial (monic).
    pub polynomial: Poly<K>,
    /// Orders of the infinite zeros, ascending.
    pub infinite_zero_orders: Vec<usize>,
}

/// The system pencil $(A_S, E_S)$ of a descriptor system.
pub fn system_pencil<K: Field>(sys: &Descriptor<K>) -> Result<(Matrix<K>, Matrix<K>)> {
    let fld = sys.a.field().clone();
    let (p, m) = sys.d.shape();
    let a = Matrix::block(fld.clone(), &[vec![&sys.a, &sys.b], vec![&sys.c, &sys.d]])?;
    let n = sys.nstates();
    let mut e = Matrix::zeros(fld, n + p, n + m);
    e.set_block(0, 0, &sys.e);
    Ok((a, e))
}

/// Finite and infinite zeros of $E\dot x = Ax + Bu$, $y = Cx + Du$ (any $E$).
///
/// # Errors
/// As [`kronecker_structure`].
///
/// # Examples
/// ```
/// use exactlti::{qmat, system::Descriptor, structure::descriptor_zeros::descriptor_zeros};
/// // G(s) = (s + 2) / (s^2 + 3 s + 1): one finite zero -2, one infinite zero of order 1
/// let sys = Descriptor::new(qmat![[1, 0], [0, 1]], qmat![[0, 1], [-1, -3]], qmat![[0], [1]],
///     qmat![[2, 1]], qmat![[0]]).unwrap();
/// let z = descriptor_zeros(&sys).unwrap();
/// assert_eq!(z.polynomial.to_string(), "x + 2");
/// assert_eq!(z.infinite_zero_orders, [1]);
/// assert!(z.pencil.verified);
/// ```
pub fn descriptor_zeros<K: Field>(sys: &Descriptor<K>) -> Result<DescriptorZeros<K>> {
    let (a, e) = system_pencil(sys)?;
    let pencil = kronecker_structure(&a, &e)?;
    let polynomial = pencil.finite_part.charpoly()?;
    let infinite_zero_orders = pencil
        .infinite_divisors
        .iter()
        .filter(|&&k| k >= 2)
        .map(|&k| k - 1)
        .collect();
    Ok(DescriptorZeros {
        pencil,
        polynomial,
        infinite_zero_orders,
    })
}
