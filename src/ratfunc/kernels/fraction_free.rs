//! Fraction-free Gauss–Jordan elimination over $\mathbb{Z}\lbrack p\rbrack$: the path of the
//! RREF and inverse kernels when the dense interpolation grid is too large (many parameters
//! of moderate degree: $\prod_v (d_v + 1)$ residues per output).
//!
//! With the pivots of step $k$ at $(k, P_k)$ (rows already in pivot order, chosen by the rank
//! profile at a random point, so no pivot vanishes) and $M_0 = 1$, every entry outside the
//! pivot column becomes
//! $$c_{ij} \leftarrow \frac{M_k\, c_{ij} - c_{i P_k}\, c_{kj}}{M_{k-1}}, \qquad M_k = c_{k P_k},$$
//! an exact division in $\mathbb{Z}\lbrack p\rbrack$ (each entry after step $k$ is a
//! $k \times k$ minor of the input, Sylvester's identity; Bareiss' algorithm extended above
//! the pivots). The pivots are the leading minors $M_1, \dots, M_r$ of $C_P$, and at the end
//! $C \leftarrow M_r\, C_P^{-1} C$: no gcd anywhere, and no entry larger than a minor of the
//! input. The callers check the result exactly as they check the interpolated one (the same
//! identities) and bring the entries to lowest terms once. An entry beyond [`MAX_TERMS`]
//! terms, an exponent beyond the packing, or a non-exact division (impossible for a correct
//! pivot choice) gives up (`None`: the generic algorithm runs).

use crate::mpoly::{MPoly, max_exponent};

/// The most terms an intermediate entry may have. Fraction-free elimination never cancels a
/// common factor, so on a structured matrix (a Vandermonde matrix in 8 parameters: minors
/// with $8!$ terms) it expands what the generic algorithm keeps small by its gcds: beyond
/// this size it gives way (measured: `mnf` of diag(p0..p7) took 54 s and 2 GB with a bound
/// of 2M terms, 0.07 s through the generic algorithm).
const MAX_TERMS: usize = 20_000;
/// The most term pairs one product may multiply (a time bound of the same purpose).
const MAX_PAIRS: usize = 1_000_000;

/// `f * g`, `None` when an exponent of the product would not fit the packing or the product
/// is beyond [`MAX_PAIRS`].
fn mul(f: &MPoly, g: &MPoly) -> Option<MPoly> {
    if f.is_zero() || g.is_zero() {
        return Some(MPoly::zero(f.nvars()));
    }
    if f.len().saturating_mul(g.len()) > MAX_PAIRS {
        return None;
    }
    let mx = max_exponent(f.nvars()) as u64;
    let fits = f
        .degrees()
        .iter()
        .zip(g.degrees())
        .all(|(a, b)| *a as u64 + b as u64 <= mx);
    fits.then(|| f.mul(g))
}

/// Fraction-free Gauss–Jordan on the `r x w` row-major `c` with the pivot of step `k` at
/// `(k, piv[k])` (see the module docs): returns the leading minors $M_1, \dots, M_r$ of
/// $C_P$ and leaves $M_r C_P^{-1} C$ in `c`. `None`: a zero pivot, a non-exact division, or
/// an entry beyond [`MAX_TERMS`] terms.
pub(crate) fn gauss_jordan_zp(
    r: usize,
    w: usize,
    c: &mut [MPoly],
    piv: &[usize],
) -> Option<Vec<MPoly>> {
    assert_eq!(c.len(), r * w);
    assert_eq!(piv.len(), r);
    let Some(first) = c.first() else {
        return Some(vec![]);
    };
    let nv = first.nvars();
    let mut prev = MPoly::one(nv);
    let mut minors = Vec::with_capacity(r);
    for k in 0..r {
        let pk = piv[k];
        let p = c[k * w + pk].clone();
        if p.is_zero() {
            return None;
        }
        let pivot_row: Vec<MPoly> = c[k * w..(k + 1) * w].to_vec();
        for i in (0..r).filter(|&i| i != k) {
            let f = c[i * w + pk].clone();
            for j in (0..w).filter(|&j| j != pk) {
                let x = &c[i * w + j];
                let y = &pivot_row[j];
                let num = match (x.is_zero(), f.is_zero() || y.is_zero()) {
                    (true, true) => continue,
                    (false, true) => mul(&p, x)?,
                    (true, false) => mul(&f, y)?.neg(),
                    (false, false) => mul(&p, x)?.sub(&mul(&f, y)?),
                };
                if num.len() > 4 * MAX_TERMS {
                    return None;
                }
                let q = if prev.is_one() {
                    num
                } else {
                    num.div_exact(&prev)?
                };
                if q.len() > MAX_TERMS {
                    return None;
                }
                c[i * w + j] = q;
            }
            c[i * w + pk] = MPoly::zero(nv);
        }
        minors.push(p.clone());
        prev = p;
    }
    Some(minors)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(nv: usize, i: usize) -> MPoly {
        MPoly::var(nv, i)
    }

    #[test]
    fn two_by_three_gives_delta_times_rref() {
        // C = [[x, 1, y], [1, y, x]]: M_1 = x, M_2 = x y - 1, N = M_2 C_P^{-1} C_{:,2}
        let nv = 2;
        let (x, y, one) = (v(nv, 0), v(nv, 1), MPoly::one(nv));
        let mut c = vec![
            x.clone(),
            one.clone(),
            y.clone(),
            one.clone(),
            y.clone(),
            x.clone(),
        ];
        let m = gauss_jordan_zp(2, 3, &mut c, &[0, 1]).expect("generic pivots");
        let delta = x.mul(&y).sub(&one);
        assert_eq!(m, vec![x.clone(), delta.clone()]);
        // C_P^{-1} = [[y, -1], [-1, x]] / delta; times column (y, x)
        assert_eq!(c[0], delta);
        assert!(c[1].is_zero() && c[3].is_zero());
        assert_eq!(c[4], delta);
        assert_eq!(c[2], y.mul(&y).sub(&x));
        assert_eq!(c[5], x.mul(&x).sub(&y));
    }
}
