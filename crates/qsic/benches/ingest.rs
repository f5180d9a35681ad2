//! Building quadrics from user input, then classifying: the library's end-to-end costs
//! (README, "Speed"), on the input families of `inputs`:
//! - `from_integers`: random integer matrices (`random_integer_matrix`) through
//!   `Quadric::from_integers`, then `classify`;
//! - `from_f64`: the same matrices halved, as `f64`, through `Quadric::from_f64`;
//! - `matrix_texts`: random 4×4 arrays of number strings `p/q` (`random_rational_rows_json`)
//!   through `quadric_from_array`, then `classify`;
//! - `polynomial_strings`: random polynomial strings (`random_polynomial_text`) through
//!   `parse_quadric`, then `classify`.

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use qsic::io::{parse_quadric, quadric_from_array};
use qsic::{classify, Quadric};
use std::hint::black_box;

mod inputs;
use inputs::{random_integer_matrix, random_polynomial_text, random_rational_rows_json, SplitMix};

const PAIRS: usize = 1000;

fn bench(c: &mut Criterion) {
    let mut rng = SplitMix(11);
    let integers: Vec<[[[i64; 4]; 4]; 2]> = (0..PAIRS)
        .map(|_| {
            [
                random_integer_matrix(&mut rng),
                random_integer_matrix(&mut rng),
            ]
        })
        .collect();
    let texts: Vec<[[[String; 4]; 4]; 2]> = (0..PAIRS)
        .map(|_| {
            [0, 1].map(|_| {
                let json = random_rational_rows_json(&mut rng);
                let rows: Vec<Vec<String>> = serde_json::from_str(&json).expect("generated JSON");
                std::array::from_fn(|i| std::array::from_fn(|j| rows[i][j].clone()))
            })
        })
        .collect();
    let polynomials: Vec<[String; 2]> = (0..PAIRS)
        .map(|_| {
            [
                random_polynomial_text(&mut rng),
                random_polynomial_text(&mut rng),
            ]
        })
        .collect();

    let mut g = c.benchmark_group("ingest_and_classify");
    g.throughput(Throughput::Elements(PAIRS as u64));
    g.bench_function("from_integers", |b| {
        b.iter(|| {
            for [x, y] in &integers {
                let x = Quadric::from_integers(*black_box(x)).expect("valid");
                let y = Quadric::from_integers(*black_box(y)).expect("valid");
                black_box(classify(&x, &y));
            }
        })
    });
    let floats: Vec<[[[f64; 4]; 4]; 2]> = integers
        .iter()
        .map(|pair| pair.map(|m| m.map(|row| row.map(|v| v as f64 / 2.0))))
        .collect();
    g.bench_function("from_f64", |b| {
        b.iter(|| {
            for [x, y] in &floats {
                let x = Quadric::from_f64(*black_box(x)).expect("valid");
                let y = Quadric::from_f64(*black_box(y)).expect("valid");
                black_box(classify(&x, &y));
            }
        })
    });
    g.bench_function("matrix_texts", |b| {
        b.iter(|| {
            for [x, y] in &texts {
                let x = quadric_from_array(black_box(x)).expect("valid");
                let y = quadric_from_array(black_box(y)).expect("valid");
                black_box(classify(&x, &y));
            }
        })
    });
    g.bench_function("polynomial_strings", |b| {
        b.iter(|| {
            for [x, y] in &polynomials {
                let x = parse_quadric(black_box(x)).expect("valid");
                let y = parse_quadric(black_box(y)).expect("valid");
                black_box(classify(&x, &y));
            }
        })
    });
    g.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(20).warm_up_time(std::time::Duration::from_millis(300)).measurement_time(std::time::Duration::from_secs(1));
    targets = bench
}
criterion_main!(benches);
