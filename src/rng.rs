//! The crate's two small deterministic generators (fixed seeds, no external crate): the
//! randomized algorithms (Cantor-Zassenhaus splitting, candidate searches) and the tests and
//! benches draw from these, so a seed names one sequence everywhere. Not for cryptography.
//!
//! | generator | recurrence |
//! |---|---|
//! | [`SplitMix64`] | $s \leftarrow s + \mathtt{0x9E3779B97F4A7C15}$, output a 64-bit mix of $s$ (Steele, Lea, Flood 2014) |
//! | [`Lcg64`] | $x \leftarrow 6364136223846793005\,x + 1442695040888963407 \bmod 2^{64}$ (Knuth's MMIX constants); [`Lcg64::next_u31`] is $x \gg 33$ |
//!
//! `Lcg64` is the recurrence `scripts/anchors/matrix.py` reproduces, so Python anchors time
//! the same matrices as `benches/matrix.rs`.

/// SplitMix64: `SplitMix64(seed)`, then [`SplitMix64::next_u64`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SplitMix64(pub u64);

impl SplitMix64 {
    /// The next 64 output bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// An integer in `lo..=hi` (`lo <= hi`; modulo reduction, slightly biased for huge ranges).
    pub fn int(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.next_u64() % ((hi - lo + 1) as u64)) as i64
    }
}

/// The 64-bit linear congruential generator with Knuth's MMIX constants.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Lcg64(pub u64);

impl Lcg64 {
    /// Advance and return the new state.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        self.0
    }
    /// Advance and return the top 31 bits of the new state ($x \gg 33$).
    pub fn next_u31(&mut self) -> u64 {
        self.next_u64() >> 33
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reference_values() {
        // SplitMix64 from seed 0: the published first output.
        assert_eq!(SplitMix64(0).next_u64(), 0xE220_A839_7B1D_CDAF);
        // MMIX LCG from 0: one step is the increment itself.
        let mut g = Lcg64(0);
        assert_eq!(g.next_u64(), 1_442_695_040_888_963_407);
        assert_eq!(
            g.next_u64(),
            1_442_695_040_888_963_407u64
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407)
        );
        let mut r = SplitMix64(7);
        assert!(
            (0..1000)
                .map(|_| r.int(-3, 3))
                .all(|v| (-3..=3).contains(&v))
        );
    }
}
