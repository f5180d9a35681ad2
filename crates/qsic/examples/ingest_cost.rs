//! Builds `N` random pairs of quadrics from integer matrices (or, with `f64`, from the same
//! matrices halved, as floats) and classifies them: the input of the library's "from an
//! integer matrix" speed figure in the README.
//!
//! `cargo run --release -p qsic --example ingest_cost -- 100000 [f64]` prints the time per
//! pair. For instructions, run it under `valgrind --tool=callgrind` and divide the inclusive
//! cost of `ingest_cost::construct_and_classify` (`callgrind_annotate --inclusive=yes`) by `N`.

use qsic::{classify, Classification, Quadric};
use std::hint::black_box;

#[path = "../benches/inputs/mod.rs"]
mod inputs;

use inputs::{random_integer_matrix, SplitMix};

/// Builds both quadrics and classifies the pair (construction included).
#[inline(never)]
fn construct_and_classify(pairs: &[[[[i64; 4]; 4]; 2]], floats: bool) -> usize {
    let build = |m: &[[i64; 4]; 4]| {
        if floats {
            Quadric::from_f64(m.map(|row| row.map(|v| v as f64 / 2.0)))
        } else {
            Quadric::from_integers(*m)
        }
    };
    let mut regular = 0;
    for [a, b] in pairs {
        let (Ok(a), Ok(b)) = (build(a), build(b)) else {
            continue;
        };
        let c: Classification = classify(black_box(&a), black_box(&b));
        regular += usize::from(c.case.is_some());
    }
    regular
}

fn main() {
    let n: usize = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(1000);
    let floats = std::env::args().nth(2).as_deref() == Some("f64");
    let mut rng = SplitMix(42);
    let pairs: Vec<[[[i64; 4]; 4]; 2]> = (0..n)
        .map(|_| {
            [
                random_integer_matrix(&mut rng),
                random_integer_matrix(&mut rng),
            ]
        })
        .collect();
    let start = std::time::Instant::now();
    let regular = construct_and_classify(black_box(&pairs), floats);
    let el = start.elapsed();
    if n > 0 {
        println!(
            "{n} pairs ({regular} regular) in {el:?}: {:.3} µs/pair",
            el.as_secs_f64() * 1e6 / n as f64
        );
    }
}
