//! Moving quadrics (README, "Speed"): `MovingPencil::new` and `variations` on each example
//! of `moving.jsonl` (reading the matrices excluded), and on motion families of the hidden
//! set's kind: a sphere translating through a sphere (rational instants), the same with
//! irrational instants (roots of `t⁴ − 6t² + 1`), a rational rotation of an ellipsoid about
//! a paraboloid, a sphere moving along the twisted cubic `(t, t², t³)` past an ellipsoid.

use criterion::{criterion_group, criterion_main, Criterion};
use qsic::io::{moving_matrix_from_polynomial, moving_matrix_from_rows, MovingMatrix};
use qsic::motion::MovingPencil;
use serde_json::Value;
use std::hint::black_box;

fn matrix(v: &Value) -> MovingMatrix {
    let rows: Vec<Vec<String>> = v
        .as_array()
        .expect("rows")
        .iter()
        .map(|r| {
            r.as_array()
                .expect("a row")
                .iter()
                .map(|e| e.as_str().expect("a string entry").to_string())
                .collect()
        })
        .collect();
    moving_matrix_from_rows(&rows).expect("a corpus matrix")
}

const FAMILIES: [(&str, &str, &str); 4] = [
    (
        "sphere_through_sphere",
        "x^2 + y^2 + z^2 - 4",
        "(x - t)^2 + y^2 + z^2 - 1",
    ),
    (
        "irrational_instants",
        "x^2 + y^2 + z^2 - 2",
        "(x - t)^2 + y^2 + z^2 - 1",
    ),
    (
        "rational_rotation",
        "x^2 + y^2 - 2*z*w",
        "((1-t^2)*x - 2*t*y)^2/(1+t^2)^2 + 4*(2*t*x + (1-t^2)*y)^2/(1+t^2)^2 + 9*(z - w)^2 - w^2",
    ),
    (
        "along_twisted_cubic",
        "x^2 + 2*y^2 + 3*z^2 - w^2",
        "(x - t*w)^2 + (y - t^2*w)^2 + (z - t^3*w)^2 - w^2/4",
    ),
];

fn bench(c: &mut Criterion) {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/moving.jsonl");
    let corpus: Vec<(String, MovingMatrix, MovingMatrix)> = std::fs::read_to_string(path)
        .expect("the corpus is readable")
        .lines()
        .filter(|l| !l.trim().is_empty())
        .map(|l| {
            let d: Value = serde_json::from_str(l).expect("JSON");
            let id = d["id"].as_str().expect("an id").to_string();
            (id, matrix(&d["A"]), matrix(&d["B"]))
        })
        .collect();
    let mut g = c.benchmark_group("motion");
    g.sample_size(20);
    for (id, a, b) in &corpus {
        g.bench_function(id.as_str(), |bench| {
            bench.iter(|| {
                let p = MovingPencil::new(black_box(a.clone()), black_box(b.clone()))
                    .expect("within the limits");
                black_box(p.variations().expect("analysed"))
            })
        });
    }
    for (name, a, b) in FAMILIES {
        let (a, b) = (
            moving_matrix_from_polynomial(a).expect("valid"),
            moving_matrix_from_polynomial(b).expect("valid"),
        );
        g.bench_function(name, |bench| {
            bench.iter(|| {
                let p = MovingPencil::new(black_box(a.clone()), black_box(b.clone()))
                    .expect("within the limits");
                black_box(p.variations().expect("analysed"))
            })
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
