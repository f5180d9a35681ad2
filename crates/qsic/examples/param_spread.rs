//! The cost of each random generic pair (cases 1–4) apart: `parameterize`, `sample` of about
//! 1000 points and the drops, in one `#[inline(never)]` call per pair, so that callgrind
//! dumps a profile after each and the spread (median, mean, the costliest pairs) shows:
//!
//! ```text
//! cargo build --profile profiling -p qsic --example param_spread
//! valgrind --tool=callgrind --callgrind-out-file=cg --dump-after='param_spread::one' \
//!     target/profiling/examples/param_spread 1000
//! for f in cg.*; do echo "${f#cg.} $(grep -m1 '^totals:' "$f" | cut -d' ' -f2)"; done
//! ```
//!
//! Dump `k` is pair `k − 1` (the first also holds the set-up); the pairs are those of
//! `param_cost`, in the same order. A second argument `k` runs pair `k` alone and prints its
//! two quadrics (`param_spread 1000 857`), to profile one costly pair.

use qsic::param::parameterize;
use qsic::param::sample::{sample, SampleOptions};
use qsic::Quadric;

#[path = "../benches/inputs/mod.rs"]
mod inputs;

use inputs::generic_pairs;

/// One pair end to end; the number of real pieces sampled.
#[inline(never)]
fn one(a: &Quadric, b: &Quadric) -> usize {
    let Ok(curve) = parameterize(a, b) else {
        return 0;
    };
    let options = SampleOptions {
        points: 1000usize.div_ceil(curve.pieces.len().max(1)),
        ..SampleOptions::default()
    };
    sample(&curve, &options).map_or(0, |s| s.pieces.len())
}

fn main() {
    let n: usize = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(400);
    let mut pairs = generic_pairs(n);
    if let Some(k) = std::env::args()
        .nth(2)
        .and_then(|s| s.parse::<usize>().ok())
    {
        pairs = pairs.into_iter().skip(k).take(1).collect();
        for (a, b) in &pairs {
            println!("{}\n{}", a.to_polynomial_string(), b.to_polynomial_string());
        }
    }
    let pieces: usize = pairs.iter().map(|(a, b)| one(a, b)).sum();
    println!("{} pairs, {pieces} pieces", pairs.len());
}
