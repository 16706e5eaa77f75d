//! Hash maps keyed by packed monomials ([`MonoMap`]): a multiply-rotate hash of the `u128`
//! key (the keys are exponent vectors of the caller's own polynomials, no adversary), about
//! five times cheaper than the default SipHash in the product loops of [`super::MPoly::mul`]
//! and the Hensel lift. The identity computed is the map's; only the hash differs.

use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hasher};

/// A `u128` monomial hasher (both halves mixed by a 64-bit multiply and a rotation).
#[derive(Default, Clone, Copy)]
pub struct MonoHasher(u64);

const K: u64 = 0x9e37_79b9_7f4a_7c15;

impl Hasher for MonoHasher {
    fn finish(&self) -> u64 {
        self.0
    }
    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 = (self.0.rotate_left(5) ^ u64::from(b)).wrapping_mul(K);
        }
    }
    fn write_u128(&mut self, m: u128) {
        let lo = m as u64;
        let hi = (m >> 64) as u64;
        let h = (self.0.rotate_left(5) ^ lo).wrapping_mul(K);
        let h = (h.rotate_left(5) ^ hi).wrapping_mul(K);
        // the high bits of a product are the well mixed ones: fold them down
        self.0 = h ^ (h >> 29);
    }
}

/// A hash map from packed monomials to `V`.
pub type MonoMap<V> = HashMap<u128, V, BuildHasherDefault<MonoHasher>>;

/// An empty [`MonoMap`] with room for `n` entries.
pub fn with_capacity<V>(n: usize) -> MonoMap<V> {
    MonoMap::with_capacity_and_hasher(n, BuildHasherDefault::default())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_collide_rarely_and_the_map_is_a_map() {
        // exponent vectors of 4 variables packed in 8-bit fields: distinct keys, distinct buckets
        let mut m: MonoMap<u32> = with_capacity(0);
        let mut hashes = std::collections::HashSet::new();
        for a in 0..20u128 {
            for b in 0..20u128 {
                for c in 0..20u128 {
                    let key = a | (b << 8) | (c << 16) | (a << 100);
                    *m.entry(key).or_default() += 1;
                    let mut h = MonoHasher::default();
                    h.write_u128(key);
                    hashes.insert(h.finish());
                }
            }
        }
        assert_eq!(m.len(), 8000);
        assert!(m.values().all(|&v| v == 1));
        assert_eq!(hashes.len(), 8000);
        assert_eq!(m.get(&(3 | (4 << 8) | (5 << 16) | (3 << 100))), Some(&1));
    }
}
