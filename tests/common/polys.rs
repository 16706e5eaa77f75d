//! Shared polynomial constructions (tests and benches; benches mount this file by `#[path]`).

use exactlti::poly::zpoly::ZPoly;
use num_bigint::BigInt;

/// Swinnerton-Dyer polynomial prod(x ± sqrt(a_1) ± ... ± sqrt(a_k)), built exactly by
/// P_j(x) = P_{j-1}(x + sqrt a) P_{j-1}(x - sqrt a) = A^2 - a B^2, where
/// P_{j-1}(x + sqrt a) = A(x) + sqrt(a) B(x) is expanded by Horner's rule.
pub fn swinnerton_dyer(primes: &[i64]) -> ZPoly {
    let mut f = ZPoly::x();
    for &a in primes {
        let a = BigInt::from(a);
        let (mut pa, mut pb) = (ZPoly::zero(), ZPoly::zero());
        for c in f.coeffs().iter().rev() {
            // (A + sqrt(a) B)(x + sqrt(a)) + c
            let na = &(&pa * &ZPoly::x()) + &pb.scale(&a) + ZPoly::constant(c.clone());
            let nb = &(&pb * &ZPoly::x()) + &pa;
            pa = na;
            pb = nb;
        }
        f = &(&pa * &pa) - &(&pb * &pb).scale(&a);
    }
    f
}
