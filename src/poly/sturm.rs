//! Sturm sequences over an ordered field: $p_0 = p$, $p_1 = p'$,
//! $p_{i+1} = -\mathrm{rem}(p_{i-1}, p_i)$, until a remainder vanishes. By Sturm's theorem the
//! number of distinct real roots of $p$ in $(a, b]$ ($a, b$ not roots) is $V(a) - V(b)$, $V$
//! the sign variations of the sequence at a point ([`sign_variations`]); callers decide the
//! signs (exactly in their field).

use super::Poly;
use crate::field::Field;
use std::cmp::Ordering;

impl<K: Field> Poly<K> {
    /// The Sturm sequence $p, p', -\mathrm{rem}, \dots$ (module docs); a constant $p$ gives
    /// $[p, 0]$.
    pub fn sturm_sequence(&self) -> Vec<Poly<K>> {
        let mut seq = vec![self.clone(), self.derivative()];
        while !seq[seq.len() - 1].is_zero() && seq[seq.len() - 1].deg() > 0 {
            let n = seq.len();
            let r = seq[n - 2].rem(&seq[n - 1]);
            if r.is_zero() {
                break;
            }
            seq.push(r.neg());
        }
        seq
    }
}

/// Sign changes in a sequence of signs, zeros skipped.
pub fn sign_variations(signs: &[Ordering]) -> usize {
    let nonzero: Vec<&Ordering> = signs.iter().filter(|s| **s != Ordering::Equal).collect();
    nonzero.windows(2).filter(|w| w[0] != w[1]).count()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::{Field, Q};
    use crate::poly::Poly;

    /// $(x-1)(x+2)(x-3)$: three real roots, $V(-3) - V(0) = 1$ (the root $-2$), $V(0) - V(4) = 2$.
    #[test]
    fn counts_roots_between_two_points() {
        let p = Poly::from_i64s(&[6, -5, -2, 1]);
        let seq = p.sturm_sequence();
        let v = |x: i64| {
            let signs: Vec<Ordering> = seq
                .iter()
                .map(|s| {
                    let y = s.eval(&Q.from_i64(x));
                    Q.sign(&y).unwrap()
                })
                .collect();
            sign_variations(&signs)
        };
        assert_eq!(v(-3) - v(0), 1);
        assert_eq!(v(0) - v(4), 2);
        assert_eq!(Poly::from_i64s(&[5]).sturm_sequence().len(), 2);
    }
}
