//! Classifies `N` random pairs whose polynomial coefficients are integers in [−10, 10]
//! (the speed target's input family) and prints a histogram of the cases.
//!
//! `cargo run --release -p qsic --example random_pairs -- 100000`; for instruction counts,
//! run it under `valgrind --tool=callgrind` with N and with 0 and divide the difference by N.

use qsic::{classify, Quadric};

/// splitmix64: a deterministic generator, enough for benchmark inputs.
pub struct SplitMix(pub u64);

impl SplitMix {
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in [lo, hi].
    pub fn range(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.next_u64() % (hi - lo + 1) as u64) as i64
    }
}

/// A random quadric whose 10 polynomial coefficients are integers in [−10, 10]
/// (matrix: 2× the coefficient on the diagonal, the coefficient off it).
pub fn random_quadric(rng: &mut SplitMix) -> Quadric {
    loop {
        let mut m = [[0i64; 4]; 4];
        for i in 0..4 {
            for j in i..4 {
                let c = rng.range(-10, 10);
                if i == j {
                    m[i][i] = 2 * c;
                } else {
                    m[i][j] = c;
                    m[j][i] = c;
                }
            }
        }
        if let Ok(q) = Quadric::from_integers(m) {
            return q;
        }
    }
}

fn main() {
    let n: usize = std::env::args().nth(1).and_then(|s| s.parse().ok()).unwrap_or(1000);
    let mut rng = SplitMix(42);
    let pairs: Vec<(Quadric, Quadric)> = (0..n).map(|_| (random_quadric(&mut rng), random_quadric(&mut rng))).collect();
    let mut hist = [0usize; 36];
    let start = std::time::Instant::now();
    for (a, b) in &pairs {
        let c = classify(a, b);
        hist[c.case.unwrap_or(0) as usize] += 1;
    }
    let el = start.elapsed();
    if n > 0 {
        eprintln!("{n} pairs in {el:?}: {:.2} µs/pair", el.as_secs_f64() * 1e6 / n as f64);
    }
    for (case, count) in hist.iter().enumerate().filter(|(_, c)| **c > 0) {
        println!("case {case}: {count}");
    }
}
