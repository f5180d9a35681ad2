//! Classifies `N` random pairs whose polynomial coefficients are integers in [−10, 10]
//! (the speed target's input family) and prints a histogram of the cases.
//!
//! `cargo run --release -p qsic --example random_pairs -- 100000`; for instruction counts,
//! run it under `valgrind --tool=callgrind` with N and with 0 and divide the difference by N.

use qsic::classify;

#[path = "../benches/inputs/mod.rs"]
mod inputs;

use inputs::{random_pairs, SplitMix};

fn main() {
    let n: usize = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(1000);
    let mut rng = SplitMix(42);
    let pairs = random_pairs(&mut rng, n);
    let mut hist = [0usize; 36];
    let start = std::time::Instant::now();
    for (a, b) in &pairs {
        let c = classify(a, b);
        hist[c.case.unwrap_or(0) as usize] += 1;
    }
    let el = start.elapsed();
    if n > 0 {
        eprintln!(
            "{n} pairs in {el:?}: {:.2} µs/pair",
            el.as_secs_f64() * 1e6 / n as f64
        );
    }
    for (case, count) in hist.iter().enumerate().filter(|(_, c)| **c > 0) {
        println!("case {case}: {count}");
    }
}
