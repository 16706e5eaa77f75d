//! The exact index of the marked root of a rational modulus among its isolated roots (for
//! [`super::Ext`] with a rational modulus; the product modulo an integral modulus is
//! $\mathbb{Q}$'s kernel [`crate::field::Field::mul_mod_poly`]).

use super::AlgebraicNumber;
use crate::field::Q;
use crate::poly::Poly;

/// Index of the root of the irreducible `m` nearest `root` among its exactly isolated roots
/// ([`AlgebraicNumber::roots_of_irreducible`], canonical order). `None` when the isolation
/// fails (budget) or two roots are equally near.
pub(super) fn marked_root_index(m: &Poly<Q>, (xr, xi): (f64, f64)) -> Option<usize> {
    let roots = AlgebraicNumber::roots_of_irreducible(m).ok()?;
    let d: Vec<f64> = roots
        .iter()
        .map(|z| {
            let (a, b) = z.approx();
            (a - xr).hypot(b - xi)
        })
        .collect();
    let best = (0..d.len()).min_by(|&i, &j| d[i].total_cmp(&d[j]))?;
    let unique = (0..d.len()).all(|j| j == best || d[j] > d[best]);
    unique.then_some(best)
}
