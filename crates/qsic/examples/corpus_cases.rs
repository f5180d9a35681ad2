//! Classifies the disguised copies of the 35 cases (cases.jsonl) `N` times; for profiling
//! the exact path: `valgrind --tool=callgrind target/release/examples/corpus_cases 1`.

#[path = "../benches/inputs/mod.rs"]
mod inputs;

fn main() {
    let n: usize = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(1);
    let pairs = inputs::corpus_pairs(|id| !id.contains("rep"));
    let start = std::time::Instant::now();
    let mut regular = 0;
    for _ in 0..n {
        for (_, a, b) in &pairs {
            regular += usize::from(qsic::classify(a, b).case.is_some());
        }
    }
    let el = start.elapsed();
    eprintln!(
        "{} pairs: {:.1} µs/pair, {regular} with a case",
        pairs.len() * n,
        el.as_secs_f64() * 1e6 / (pairs.len() * n) as f64
    );
}
