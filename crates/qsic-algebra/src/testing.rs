//! Deterministic pseudo-random numbers for tests and benchmarks (no dependency, same stream
//! on every platform): SplitMix64, `xₙ₊₁ = xₙ + 0x9E37_79B9_7F4A_7C15` followed by an
//! invertible mixing of the state. Not for cryptography.

/// The SplitMix64 generator; the field is its state (the seed).
///
/// ```
/// # use qsic_algebra::testing::SplitMix;
/// let mut rng = SplitMix(7);
/// let v = rng.int(-3, 3);
/// assert!((-3..=3).contains(&v));
/// ```
#[derive(Clone, Debug)]
pub struct SplitMix(pub u64);

impl SplitMix {
    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform (up to a bias below `2⁻⁴⁰` for small ranges) in `[lo, hi]`, `lo ≤ hi`.
    pub fn int(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.next_u64() % (hi - lo + 1) as u64) as i64
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reference_stream_and_range() {
        // SplitMix64 from seed 0: the published first outputs
        let mut rng = SplitMix(0);
        assert_eq!(rng.next_u64(), 0xE220_A839_7B1D_CDAF);
        assert_eq!(rng.next_u64(), 0x6E78_9E6A_A1B9_65F4);
        let mut rng = SplitMix(5);
        let mut seen = [false; 7];
        for _ in 0..200 {
            let v = rng.int(-3, 3);
            assert!((-3..=3).contains(&v));
            seen[(v + 3) as usize] = true;
        }
        assert!(
            seen.iter().all(|&s| s),
            "every value of a small range is drawn"
        );
    }
}
