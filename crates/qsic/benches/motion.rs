//! Moving quadrics (README, "Speed"): `MovingPencil::new` and `variations` on each example
//! of `moving.jsonl` (reading the matrices excluded), and on motion families of the hidden
//! set's kind: a sphere translating through a sphere (rational instants), the same with
//! irrational instants (roots of `t⁴ − 6t² + 1`), a rational rotation of an ellipsoid about
//! a paraboloid, a sphere moving along the twisted cubic `(t, t², t³)` past an ellipsoid.
//!
//! Group `motion_rigid` (README, "Moving quadrics"): rigid motions built by
//! `qsic::motion::rigid` — two ellipsoids under a translation, a rotation (Cayley), a screw
//! motion; a cylinder and a cone turning — each for `variations`, for the first contact
//! (`first_contact`) and for the first contact with its points (`+ contact_points`).
//!
//! Group `motion_random`, only with `QSIC_BENCH_RANDOM=1` (slow before the fast instants):
//! random moving pencils, entries of degree 1, 2, 4 in `t` with 3-bit and 64-bit
//! coefficients, seeds fixed (`SplitMix(seed)`); with `QSIC_BENCH_RANDOM=all` also degree 16
//! with 512-bit coefficients (the documented limits).

use criterion::{criterion_group, criterion_main, Criterion};
use motion_inputs::{random_families, rigid_families};
use qsic::io::{moving_matrix_from_polynomial, moving_matrix_from_rows, MovingMatrix};
use qsic::motion::contact::{contact_points, first_contact, TimeRange};
use qsic::motion::MovingPencil;
use serde_json::Value;
use std::hint::black_box;

#[path = "inputs/motion.rs"]
mod motion_inputs;

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

/// `variations` of the pair (the pencil built inside).
fn variations(a: &MovingMatrix, b: &MovingMatrix) -> usize {
    let p = MovingPencil::new(a.clone(), b.clone()).expect("within the limits");
    p.variations().expect("analysed").instants.len()
}

/// The first contact on the whole line and its common points.
fn contact(a: &MovingMatrix, b: &MovingMatrix) -> bool {
    let range = TimeRange::all();
    let first = first_contact(a, b, &range).expect("analysed");
    let p = MovingPencil::new(a.clone(), b.clone()).expect("within the limits");
    match first {
        Some(f) => contact_points(&p, &f, &range).expect("points").is_some(),
        None => false,
    }
}

fn bench_families(c: &mut Criterion) {
    let mut g = c.benchmark_group("motion_rigid");
    g.sample_size(20);
    for (name, a, b) in rigid_families() {
        g.bench_function(format!("{name}/motion"), |bench| {
            bench.iter(|| black_box(variations(black_box(&a), black_box(&b))))
        });
        g.bench_function(format!("{name}/first_contact"), |bench| {
            bench.iter(|| {
                black_box(first_contact(
                    black_box(&a),
                    black_box(&b),
                    &TimeRange::all(),
                ))
            })
        });
        g.bench_function(format!("{name}/contact"), |bench| {
            bench.iter(|| black_box(contact(black_box(&a), black_box(&b))))
        });
    }
    g.finish();
    let Ok(which) = std::env::var("QSIC_BENCH_RANDOM") else {
        return;
    };
    let mut g = c.benchmark_group("motion_random");
    g.sample_size(10);
    for (name, a, b) in random_families(which == "all") {
        g.bench_function(format!("{name}/motion"), |bench| {
            bench.iter(|| black_box(variations(black_box(&a), black_box(&b))))
        });
        g.bench_function(format!("{name}/contact"), |bench| {
            bench.iter(|| black_box(contact(black_box(&a), black_box(&b))))
        });
    }
    g.finish();
}

criterion_group!(benches, bench, bench_families);
criterion_main!(benches);
