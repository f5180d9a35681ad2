use qsic::classify;
use qsic::param::parameterize;
use qsic::param::sample::{sample, SampleOptions};
#[path = "../benches/inputs/mod.rs"]
mod inputs;
use inputs::{random_pairs, SplitMix};
#[inline(never)]
fn one(a: &qsic::Quadric, b: &qsic::Quadric) -> usize {
    let c = parameterize(a, b).unwrap();
    let options = SampleOptions {
        points: 1000usize.div_ceil(c.pieces.len().max(1)),
        ..SampleOptions::default()
    };
    let s = sample(&c, &options).unwrap();
    s.pieces.len()
}
fn main() {
    let n: usize = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(400);
    let mut rng = SplitMix(42);
    let pairs: Vec<_> = random_pairs(&mut rng, 8 * n)
        .into_iter()
        .filter(|(a, b)| matches!(classify(a, b).case, Some(1..=4)))
        .take(n)
        .collect();
    let mut t = 0;
    for (a, b) in &pairs {
        t += one(a, b);
    }
    println!("{t}");
}
