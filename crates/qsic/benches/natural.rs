//! Natural-quadric pairs by family, the configurations of `python/benchmarks/vs_occt.py`
//! (written by it to `inputs/natural.jsonl`: plane–quadric, sphere–sphere,
//! cylinder–cylinder, sphere–cylinder, cone–X, near-degenerate), read as the exact values of
//! their float64 matrices (`Quadric::from_f64`, as `classify_many` reads a float64 array):
//! - `natural_affine/FAMILY`: `classify` and the affine view of every pair of the family
//!   (what `classify_many(A, B, affine=True)` computes, without the Python columns);
//! - `natural_projective/FAMILY`: `classify` alone.

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use qsic::affine::{affine_view, Chart};
use qsic::{classify, Quadric};
use std::hint::black_box;

type Pair = (Quadric, Quadric);

/// The pairs of `inputs/natural.jsonl` grouped by family, in the file's order.
fn families() -> Vec<(String, Vec<Pair>)> {
    let text = include_str!("inputs/natural.jsonl");
    let mut out: Vec<(String, Vec<Pair>)> = Vec::new();
    for line in text.lines() {
        let v: serde_json::Value = serde_json::from_str(line).expect("a JSON line");
        let m = |key: &str| -> Quadric {
            let rows: [[f64; 4]; 4] =
                serde_json::from_value(v[key].clone()).expect("a 4×4 float matrix");
            Quadric::from_f64(rows).expect("a quadric")
        };
        let family = v["family"].as_str().expect("a family").to_string();
        let pair = (m("a"), m("b"));
        match out.iter_mut().find(|(f, _)| *f == family) {
            Some((_, pairs)) => pairs.push(pair),
            None => out.push((family, vec![pair])),
        }
    }
    out
}

fn bench(c: &mut Criterion) {
    let chart = Chart::default();
    let families = families();
    let mut g = c.benchmark_group("natural_affine");
    for (family, pairs) in &families {
        g.throughput(Throughput::Elements(pairs.len() as u64));
        g.bench_function(family.as_str(), |bench| {
            bench.iter(|| {
                for (a, b) in pairs {
                    black_box(classify(a, b));
                    black_box(affine_view(Some(a), Some(b), &chart, [false; 2]));
                }
            })
        });
    }
    g.finish();
    let mut g = c.benchmark_group("natural_projective");
    for (family, pairs) in &families {
        g.throughput(Throughput::Elements(pairs.len() as u64));
        g.bench_function(family.as_str(), |bench| {
            bench.iter(|| {
                for (a, b) in pairs {
                    black_box(classify(a, b));
                }
            })
        });
    }
    g.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10);
    targets = bench
}
criterion_main!(benches);
