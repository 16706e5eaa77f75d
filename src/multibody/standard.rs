//! Index-1 elimination of a descriptor system (the paper's eq. 46-47): with $X_2$ spanning
//! the null space of $E$, $P_2$ its left null space and $X_1$, $P_1$ unit vectors
//! completing them, $x = X_1 z_1 + X_2 z_2$ and
//! $z_1' = E_{11}^{-1}(A_{11} - A_{12} A_{22}^{-1} A_{21}) z_1 + E_{11}^{-1}(B_1 - A_{12} A_{22}^{-1} B_2) u$,
//! $y = (C_1 - C_2 A_{22}^{-1} A_{21}) z_1 + (D - C_2 A_{22}^{-1} B_2) u$,
//! where $E_{ij} = P_i E X_j$ etc. It needs $A_{22}$ invertible (no impulsive modes of
//! index above 1), which the equations of motion of a model with massless bodies and
//! appended inputs satisfy; a few rank computations, cheap also over $\mathbb{Q}(p)$.

use crate::field::Field;
use crate::matrix::Matrix;
use crate::system::{Descriptor, StateSpace};

/// The standard form `z1' = As z1 + Bs u`, `y = Cs z1 + Ds u` and the positions of the
/// descriptor states kept as `z1` (`x = X1 z1 + ...` with `X1` unit vectors at them);
/// `None` when `A22` is singular.
pub fn index_one_standard<K: Field>(s: &Descriptor<K>) -> Option<(StateSpace<K>, Vec<usize>)> {
    let k = s.e.field().clone();
    let n = s.e.nrows();
    let x2 = s.e.nullspace();
    let p2 = s.e.transpose().nullspace().transpose();
    let (x1, kept) = unit_complement(&k, &x2, n);
    let (p1t, _) = unit_complement(&k, &p2.transpose(), n);
    let p1 = p1t.transpose();
    let e11 = &(&p1 * &s.e) * &x1;
    let pa1 = &p1 * &s.a;
    let pa2 = &p2 * &s.a;
    let (a11, a12) = (&pa1 * &x1, &pa1 * &x2);
    let (a21, a22) = (&pa2 * &x1, &pa2 * &x2);
    let (b1, b2) = (&p1 * &s.b, &p2 * &s.b);
    let (c1, c2) = (&s.c * &x1, &s.c * &x2);
    let a22i = a22.inverse().ok()?;
    let e11i = e11.inverse().ok()?;
    let g = &a12 * &a22i;
    let h = &c2 * &a22i;
    let a = &e11i * &(&a11 - &(&g * &a21));
    let b = &e11i * &(&b1 - &(&g * &b2));
    let c = &c1 - &(&h * &a21);
    let d = &s.d - &(&h * &b2);
    Some((StateSpace::new(a, b, c, d).ok()?, kept))
}

/// Unit vectors `e_j` completing the columns of `v` to a basis of `K^n` (the non-pivot
/// columns of the RREF of `[V, I]`), and their positions `j`.
fn unit_complement<K: Field>(k: &K, v: &Matrix<K>, n: usize) -> (Matrix<K>, Vec<usize>) {
    let vi = v.hstack(&Matrix::identity(k.clone(), n)).expect("n rows");
    let (_, piv) = vi.rref();
    let kept: Vec<usize> = piv
        .iter()
        .filter(|&&p| p >= v.ncols())
        .map(|p| p - v.ncols())
        .collect();
    let mut x = Matrix::zeros(k.clone(), n, kept.len());
    for (c, &j) in kept.iter().enumerate() {
        x.set(j, c, k.one());
    }
    (x, kept)
}
