//! Levin's parameterization of `N` random pairs (polynomial coefficients integers in
//! [−10, 10], the speed target's family); pairs outside cases 1–4 are skipped. Prints how
//! many were parameterized over ℚ and over ℚ(√δ), and how many were refused.
//!
//! `cargo run --release -p qsic --example param_pairs -- 1000`; for instruction counts, run
//! it under `valgrind --tool=callgrind` with N and with 0 and divide the difference by the
//! number of pairs parameterized.

use qsic::param::parameterize_smooth_quartic;
use qsic::{classify, Quadric};

#[path = "../benches/inputs/mod.rs"]
mod inputs;

use inputs::{random_pairs, SplitMix};

fn main() {
    let n: usize = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(1000);
    let mut rng = SplitMix(42);
    let pairs: Vec<(Quadric, Quadric)> = random_pairs(&mut rng, n)
        .into_iter()
        .filter(|(a, b)| matches!(classify(a, b).case, Some(1..=4)))
        .collect();
    let (mut rational, mut quadratic, mut refused, mut components) = (0, 0, 0, [0usize; 3]);
    let start = std::time::Instant::now();
    for (a, b) in &pairs {
        match parameterize_smooth_quartic(a, b) {
            Ok(p) => {
                if p.delta.is_none() {
                    rational += 1;
                } else {
                    quadratic += 1;
                }
                if let Ok(c) = p.real_components() {
                    components[usize::from(c)] += 1;
                }
            }
            Err(e) => {
                refused += 1;
                eprintln!("refused: {e}");
            }
        }
    }
    let el = start.elapsed();
    if !pairs.is_empty() {
        eprintln!(
            "{} pairs in {el:?}: {:.1} µs/pair",
            pairs.len(),
            el.as_secs_f64() * 1e6 / pairs.len() as f64
        );
    }
    println!("over Q: {rational}, over Q(sqrt d): {quadratic}, refused: {refused}");
    println!("components 0/1/2: {components:?}");
}
