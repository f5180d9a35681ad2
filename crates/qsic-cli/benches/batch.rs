//! `qsic classify --batch` end to end, in process: JSON Lines in, JSON Lines out through
//! `batch::run`, on the two random corpora of `random_corpus` (README, "Speed"):
//! - `matrix_lines`: A and B 4×4 arrays of number strings `p/q`;
//! - `polynomial_lines`: A and B polynomial strings with integer coefficients.
//!
//! `RAYON_NUM_THREADS=1 cargo bench -p qsic-cli` measures one thread.

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use qsic_cli::batch;
use std::hint::black_box;

#[path = "../../qsic/benches/inputs/mod.rs"]
mod inputs;
use inputs::{random_polynomial_text, random_rational_rows_json, SplitMix};

const LINES: usize = 1000;

fn corpus(poly: bool) -> Vec<u8> {
    let mut rng = SplitMix(2026);
    let mut out = String::new();
    for id in 1..=LINES {
        let (a, b) = if poly {
            (
                format!("\"{}\"", random_polynomial_text(&mut rng)),
                format!("\"{}\"", random_polynomial_text(&mut rng)),
            )
        } else {
            (
                random_rational_rows_json(&mut rng),
                random_rational_rows_json(&mut rng),
            )
        };
        out.push_str(&format!("{{\"id\": {id}, \"A\": {a}, \"B\": {b}}}\n"));
    }
    out.into_bytes()
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("batch");
    g.throughput(Throughput::Elements(LINES as u64));
    for (name, input) in [
        ("matrix_lines", corpus(false)),
        ("polynomial_lines", corpus(true)),
    ] {
        let mut output = Vec::with_capacity(input.len());
        g.bench_function(name, |b| {
            b.iter(|| {
                output.clear();
                let summary = batch::run(black_box(&input[..]), &mut output, false);
                black_box(summary.expect("in-memory batch"));
            })
        });
    }
    g.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(20).warm_up_time(std::time::Duration::from_millis(300)).measurement_time(std::time::Duration::from_secs(1));
    targets = bench
}
criterion_main!(benches);
