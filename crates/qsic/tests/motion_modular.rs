//! The determinants of a motion by the modular route (evaluation, interpolation and
//! remaindering modulo 61-bit primes) equal Bareiss' (the reference): the same candidate
//! polynomials and the same motion, on every line of `moving.jsonl`, on the rigid families
//! and on random moving pencils; and the default route (the cheaper by estimate) agrees too.

#[path = "../benches/inputs/motion.rs"]
mod motion_inputs;

use motion_inputs::{random_moving, rigid_families};
use qsic::io::{moving_matrix_from_rows, MovingMatrix};
use qsic::motion::{DeterminantRoute, Motion, MovingPencil};
use qsic::Budget;
use qsic_algebra::testing::SplitMix;
use serde_json::Value;

fn matrix(v: &Value) -> MovingMatrix {
    let rows: Vec<Vec<String>> = v
        .as_array()
        .unwrap()
        .iter()
        .map(|r| {
            r.as_array()
                .unwrap()
                .iter()
                .map(|e| e.as_str().unwrap().to_string())
                .collect()
        })
        .collect();
    moving_matrix_from_rows(&rows).unwrap()
}

/// The pairs of `moving.jsonl` (a copy of `shared/corpus`), by id.
fn corpus() -> Vec<(String, MovingMatrix, MovingMatrix)> {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/moving.jsonl");
    std::fs::read_to_string(path)
        .unwrap()
        .lines()
        .filter(|l| !l.trim().is_empty())
        .map(|l| {
            let d: Value = serde_json::from_str(l).unwrap();
            let id = d["id"].as_str().unwrap().to_string();
            (id, matrix(&d["A"]), matrix(&d["B"]))
        })
        .collect()
}

/// What a motion says, comparable.
fn summary(m: &Motion) -> Vec<String> {
    let instants = m.instants.iter().map(|i| {
        let c = i.class.classification();
        format!(
            "{} {:?}",
            i.t,
            c.map(|c| (c.case, c.complex_type(), c.real_type()))
        )
    });
    let intervals = m.intervals.iter().map(|i| {
        let c = &i.classification;
        format!(
            "{} {:?}",
            i.sample,
            (c.case, c.complex_type(), c.real_type())
        )
    });
    instants.chain(intervals).collect()
}

/// The candidate polynomials and the motion on the three routes; the units spent on the
/// modular route, to show it ran.
fn compare(id: &str, a: MovingMatrix, b: MovingMatrix) {
    let pencil = MovingPencil::new(a, b).unwrap();
    let on = |route| pencil.clone().with_determinant_route(route);
    let reference = on(DeterminantRoute::Bareiss);
    let want = reference.candidate_polynomials().unwrap();
    let want_motion = summary(&reference.variations().unwrap());
    for route in [DeterminantRoute::Modular, DeterminantRoute::Fastest] {
        let p = on(route);
        assert_eq!(
            p.candidate_polynomials().unwrap(),
            want,
            "{id}: candidates, {route:?}"
        );
        assert_eq!(
            summary(&p.variations().unwrap()),
            want_motion,
            "{id}: motion, {route:?}"
        );
    }
    // the routes spend differently: the modular one is not Bareiss under another name
    let units = |route| {
        let budget = Budget::unlimited();
        on(route).candidate_polynomials_within(&budget).unwrap();
        budget.used()
    };
    assert_ne!(
        units(DeterminantRoute::Modular),
        units(DeterminantRoute::Bareiss),
        "{id}"
    );
}

#[test]
fn modular_and_bareiss_agree_on_every_corpus_line() {
    let lines = corpus();
    assert!(lines.len() >= 3);
    for (id, a, b) in lines {
        compare(&id, a, b);
    }
}

#[test]
fn modular_and_bareiss_agree_on_the_rigid_families() {
    for (name, a, b) in rigid_families() {
        compare(name, a, b);
    }
}

#[test]
fn modular_and_bareiss_agree_on_random_pencils() {
    for (seed, degree, bits) in [(5, 1, 3), (6, 1, 3), (7, 2, 3), (8, 1, 64), (9, 2, 20)] {
        let mut rng = SplitMix(seed);
        let a = random_moving(&mut rng, degree, bits);
        let b = random_moving(&mut rng, degree, bits);
        compare(&format!("seed {seed}, degree {degree}, {bits} bits"), a, b);
    }
}
