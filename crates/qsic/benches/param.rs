//! The curve of a random generic pair (cases 1–4, polynomial coefficients integers in
//! [−10, 10]): the exact description (`parameterize`), 1000 real points from it (`sample`),
//! and both — the speed target of issue 8. Instruction counts: `examples/param_cost.rs`.

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use qsic::param::sample::{sample, SampleOptions};
use qsic::param::{parameterize, Curve};
use qsic::{classify, Quadric};
use std::hint::black_box;

mod inputs;
use inputs::{random_pairs, SplitMix};

/// Options giving about 1000 points over the pieces of `curve`.
fn thousand_points(curve: &Curve) -> SampleOptions {
    SampleOptions {
        points: 1000usize.div_ceil(curve.pieces.len().max(1)),
        ..SampleOptions::default()
    }
}

fn bench(c: &mut Criterion) {
    let mut rng = SplitMix(42);
    let pairs: Vec<(Quadric, Quadric, Curve)> = random_pairs(&mut rng, 400)
        .into_iter()
        .filter(|(a, b)| matches!(classify(a, b).case, Some(1..=4)))
        .filter_map(|(a, b)| parameterize(&a, &b).ok().map(|c| (a, b, c)))
        .filter(|(_, _, c)| !c.pieces.is_empty())
        .take(50)
        .collect();
    let mut g = c.benchmark_group("param");
    g.sample_size(10);
    g.throughput(Throughput::Elements(pairs.len() as u64));
    g.bench_function("describe", |b| {
        b.iter(|| {
            for (x, y, _) in &pairs {
                black_box(parameterize(x, y).ok());
            }
        })
    });
    g.bench_function("sample_1000_points", |b| {
        b.iter(|| {
            for (_, _, curve) in &pairs {
                black_box(sample(curve, &thousand_points(curve)).ok());
            }
        })
    });
    g.bench_function("describe_and_1000_points", |b| {
        b.iter(|| {
            for (x, y, _) in &pairs {
                let curve = parameterize(x, y).expect("parameterized before");
                black_box(sample(&curve, &thousand_points(&curve)).ok());
            }
        })
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
