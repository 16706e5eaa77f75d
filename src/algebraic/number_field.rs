//! General number fields $K = \mathbb{Q}\[t\]/(m(t))$ for an irreducible monic $m$: the
//! generic extension [`Ext`] over $\mathbb{Q}$, with the constructor that checks
//! irreducibility (the exact identification of the marked root and the integer product
//! kernel are in `ext_q`).
//!
//! Elements are polynomials in $t$ of degree $< \deg m$ with rational coefficients
//! (canonical: reduced and without trailing zeros). A field carries a *marked embedding*: an
//! approximation of the complex root of $m$ that $t$ stands for, so elements can be
//! approximated; two fields are equal when their moduli agree and their marked roots are the
//! same root of $m$ (told apart by exact isolation).
//!
//! | entry point | computes |
//! |---|---|
//! | [`NumberField::new`] | the field for a monic irreducible modulus and a root choice |
//! | [`Ext::from_poly`] | the class of a polynomial in $t$ |
//! | [`Ext::generator`] | $t$ |

use super::ext::{Ext, ExtCtx, ExtElem};
use crate::error::{Error, Result};
use crate::field::{Q, Rational};
use crate::poly::Poly;
use num_traits::One;

/// $\mathbb{Q}(\alpha)$ where $\alpha$ is a root of the monic irreducible `modulus`.
pub type NumberField = Ext<Q>;
/// Shared context of a number field.
pub type NumberFieldCtx = ExtCtx<Q>;
/// An element of a [`NumberField`]: coefficients in $t$, low degree first.
pub type NfElem = ExtElem<Rational>;

impl Ext<Q> {
    /// The field $\mathbb{Q}\[t\]/(m)$ with $t$ the root of $m$ near `root`.
    ///
    /// The modulus is made monic and checked irreducible over $\mathbb{Q}$
    /// ([`crate::algebraic::is_irreducible_q`]).
    ///
    /// # Errors
    /// `NotIrreducible` for a constant or reducible modulus.
    pub fn new(modulus: &Poly<Q>, root: (f64, f64)) -> Result<Self> {
        if !crate::algebraic::is_irreducible_q(modulus) {
            return Err(Error::NotIrreducible(modulus.monic().to_string()));
        }
        Ok(Self::new_unchecked(modulus, root))
    }
    /// As [`NumberField::new`] for a modulus the caller knows to be irreducible (e.g. a
    /// factor returned by [`crate::algebraic::factor_q`]); only made monic.
    pub fn new_unchecked(modulus: &Poly<Q>, root: (f64, f64)) -> Self {
        Self::with_var(modulus, root, "t")
    }
    /// Invariants: the modulus is monic of degree at least 1 and the root approximation is
    /// finite. (Irreducibility is checked by [`NumberField::new`].)
    pub fn is_valid(&self) -> bool {
        let m = &self.0.modulus;
        m.deg() >= 1
            && m.coeff(m.deg()).is_one()
            && self.0.root.0.is_finite()
            && self.0.root.1.is_finite()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::ElemDisplay;
    use crate::field::Field;
    #[test]
    fn arithmetic() {
        // Q(cbrt 2)
        let k = NumberField::new(&Poly::from_i64s(&[-2, 0, 0, 1]), (1.2599, 0.0)).unwrap();
        let t = k.generator();
        let t3 = k.mul(&k.mul(&t, &t), &t);
        assert_eq!(t3, k.from_i64(2));
        let a = k.add(&t, &k.one());
        let ai = k.inv(&a).unwrap();
        assert!(k.is_one(&k.mul(&a, &ai)));
        assert_eq!(k.fmt_elem(&a), "t + 1");
        let (re, _) = k.approx(&a);
        assert!((re - 2.2599).abs() < 1e-3);
        assert!(NumberField::new(&Poly::from_i64s(&[1, 2, 1]), (0.0, 0.0)).is_err());
        assert!(NumberField::new(&Poly::from_i64s(&[1, 0, 4, 0, 1]), (0.0, 0.5)).is_ok());
        assert!(NumberField::new(&Poly::from_i64s(&[1, 0, 2, 0, 1]), (0.0, 1.0)).is_err());
    }

    #[test]
    fn products_match_the_polynomial_remainder() {
        // integral modulus (integer kernel) and a non-integral one (rational path): a b is
        // the remainder of the polynomial product, for fractions with unrelated denominators
        let r = |n: i64, d: i64| Rational::new(n.into(), d.into());
        let x5 = Poly::from_i64s(&[-3, 1, 0, 0, 0, 1]);
        let half = Poly::new(Q, vec![r(-1, 2), r(0, 1), r(1, 3), r(1, 1)]);
        for m in [x5, half] {
            let k = NumberField::new(&m, (1.0, 0.0)).unwrap();
            let mut seed = 7u64;
            let mut next = |lo: i64, hi: i64| {
                seed = seed
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                lo + ((seed >> 33) % (hi - lo + 1) as u64) as i64
            };
            for _ in 0..40 {
                let mut el = || {
                    let c: Vec<Rational> = (0..m.deg())
                        .map(|_| r(next(-50, 50) * next(0, 1), next(1, 12)))
                        .collect();
                    Poly::new(Q, c)
                };
                let (pa, pb) = (el(), el());
                let (a, b) = (k.from_poly(&pa), k.from_poly(&pb));
                assert_eq!(k.mul(&a, &b), k.from_poly(&pa.mul(&pb)), "{pa} * {pb}");
            }
            // the zero product and a product with a one-coefficient element
            assert!(k.is_zero(&k.mul(&k.zero(), &k.generator())));
            assert_eq!(
                k.mul(&k.from_i64(3), &k.generator()).0,
                vec![r(0, 1), r(3, 1)]
            );
        }
    }
}
