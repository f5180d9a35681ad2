//! Instruction counts of the curve of random generic pairs (cases 1–4, the `param` bench's
//! family): `describe` (`parameterize`) and `points` (`sample`, about 1000 points per curve)
//! are separate functions, so that callgrind's inclusive counts divide by the pairs:
//!
//! ```text
//! cargo build --release -p qsic --example param_cost
//! valgrind --tool=callgrind --callgrind-out-file=cg target/release/examples/param_cost 50
//! callgrind_annotate --inclusive=yes cg | grep -E 'param_cost::(describe|points)'
//! ```

use qsic::param::sample::{sample, SampleOptions, Sampled};
use qsic::param::{parameterize, Curve};
use qsic::Quadric;

#[path = "../benches/inputs/mod.rs"]
mod inputs;

use inputs::generic_pairs;

#[inline(never)]
fn describe(pairs: &[(Quadric, Quadric)]) -> Vec<Curve> {
    pairs
        .iter()
        .filter_map(|(a, b)| parameterize(a, b).ok())
        .collect()
}

#[inline(never)]
fn points(curves: &[Curve]) -> Vec<Sampled> {
    curves
        .iter()
        .filter_map(|c| {
            let options = SampleOptions {
                points: 1000usize.div_ceil(c.pieces.len().max(1)),
                ..SampleOptions::default()
            };
            sample(c, &options).ok()
        })
        .collect()
}

fn main() {
    let n: usize = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(50);
    let pairs = generic_pairs(n);
    let curves = describe(&pairs);
    let sampled = points(&curves);
    let total: usize = sampled
        .iter()
        .flat_map(|s| &s.pieces)
        .map(|p| p.points.len())
        .sum();
    println!(
        "{} pairs, {} curves, {} sampled, {total} points",
        pairs.len(),
        curves.len(),
        sampled.len()
    );
}
