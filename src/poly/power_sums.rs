//! Newton's identities: power sums of the roots of a monic polynomial and
//! back.
//!
//! For monic $p = x^n + a_{n-1}x^{n-1} + \dots + a_0$ with roots $\theta_1, \dots, \theta_n$
//! (with multiplicity), $s_k = \sum_j \theta_j^k$ satisfies $s_0 = n$ and
//! $s_k = -\bigl(k\,a_{n-k} + \sum_{i=1}^{\min(k-1,n)} a_{n-i}\, s_{k-i}\bigr)$
//! ($a_{n-k} = 0$ for $k > n$).

use super::Poly;
use crate::field::{Field, Q, Rational};
use num_traits::{One, Zero};

/// Newton power sums $s_0, s_1, \dots, s_{\text{upto}}$ of the roots of the **monic** `p`
/// over any field (length `upto + 1`). The one implementation in the crate; use it rather
/// than a copy.
///
/// # Panics
/// In debug builds, when `p` is not monic.
pub fn newton_power_sums<K: Field>(p: &Poly<K>, upto: usize) -> Vec<K::Elem> {
    let k = p.field();
    let n = p.deg();
    debug_assert!(
        p.is_zero() || k.is_one(&p.coeff(n)),
        "power sums need a monic polynomial"
    );
    let a: Vec<K::Elem> = (0..=n).map(|i| p.coeff(i)).collect(); // a[i]: coefficient of x^i
    let mut s = Vec::with_capacity(upto + 1);
    s.push(k.from_i64(n as i64));
    for j in 1..=upto {
        let mut v = if j <= n {
            k.mul(&a[n - j], &k.from_i64(j as i64))
        } else {
            k.zero()
        };
        for i in 1..j.min(n + 1) {
            k.mul_add_assign(&mut v, &a[n - i], &s[j - i]);
        }
        s.push(k.neg(&v));
    }
    s
}

/// The monic polynomial of degree `n` whose roots have power sums `s[1..=n]` (Newton's
/// identities, inverse of [`newton_power_sums`]).
///
/// # Panics
/// When `s.len() <= n`.
pub fn monic_from_power_sums(s: &[Rational], n: usize) -> Poly<Q> {
    let mut e = vec![Rational::one()];
    for k in 1..=n {
        let mut v = Rational::zero();
        for i in 1..=k {
            let t = &e[k - i] * &s[i];
            if i % 2 == 1 { v += t } else { v -= t }
        }
        e.push(v / Rational::from_integer(k.into()));
    }
    let mut c = vec![Rational::zero(); n + 1];
    for k in 0..=n {
        c[n - k] = if k % 2 == 0 { e[k].clone() } else { -&e[k] };
    }
    Poly::new(Q, c)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Oracle: power sums of explicit rational roots.
    #[test]
    fn roots_1_2_3_and_back() {
        // (x - 1)(x - 2)(x + 3) = x^3 - 7x + 6
        let p = Poly::from_i64s(&[6, -7, 0, 1]);
        let s = newton_power_sums(&p, 6);
        let roots = [1i64, 2, -3];
        for (k, sk) in s.iter().enumerate() {
            let want: i64 = roots.iter().map(|r| r.pow(k as u32)).sum();
            assert_eq!(*sk, Rational::from_integer(want.into()), "s_{k}");
        }
        assert_eq!(monic_from_power_sums(&s, 3), p);
    }

    #[test]
    fn degree_zero() {
        assert_eq!(
            newton_power_sums(&Poly::from_i64s(&[1]), 0),
            vec![Rational::zero()]
        );
    }
}
