//! Classification throughput on named input families:
//! - `random_small`: pairs whose polynomial coefficients are integers in [−10, 10];
//! - `case_NN`: the five disguised copies of each of the 35 cases (cases.jsonl);
//! - `qi_singular`: the singular pencils of QI's test file;
//! - `classify_case/case_NN`: each case's disguised copies through the exact path only.

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use qsic::classify;
use qsic::test_support::classify_exact;
use std::hint::black_box;

mod inputs;
use inputs::{corpus_pairs, random_pairs, SplitMix};

fn bench(c: &mut Criterion) {
    let mut rng = SplitMix(7);
    let random = random_pairs(&mut rng, 1000);
    let mut g = c.benchmark_group("classify");
    g.throughput(Throughput::Elements(random.len() as u64));
    g.bench_function("random_small", |b| {
        b.iter(|| {
            for (x, y) in &random {
                black_box(classify(x, y));
            }
        })
    });
    let disguised = corpus_pairs(|id| !id.contains("rep"));
    g.throughput(Throughput::Elements(disguised.len() as u64));
    g.bench_function("all_35_cases_disguised", |b| {
        b.iter(|| {
            for (_, x, y) in &disguised {
                black_box(classify(x, y));
            }
        })
    });
    let singular = inputs::qi_singular_pairs();
    g.throughput(Throughput::Elements(singular.len() as u64));
    g.bench_function("qi_singular", |b| {
        b.iter(|| {
            for (x, y) in &singular {
                black_box(classify(x, y));
            }
        })
    });
    g.finish();
    let mut g = c.benchmark_group("classify_case");
    for case in 1..=35 {
        let pairs =
            corpus_pairs(|id| id.starts_with(&format!("pub-c{case:02}-")) && !id.contains("rep"));
        g.throughput(Throughput::Elements(pairs.len() as u64));
        g.bench_function(format!("case_{case:02}"), |b| {
            b.iter(|| {
                for (_, x, y) in &pairs {
                    black_box(classify_exact(x, y));
                }
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
