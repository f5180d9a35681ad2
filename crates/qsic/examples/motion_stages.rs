//! CPU time of the stages of one motion: `MovingPencil::new`, the candidate polynomials, their
//! real roots, and the whole of `variations` (README, "Moving quadrics").
//!
//! `cargo run --release -p qsic --example motion_stages < LINES.jsonl` (JSON Lines
//! `{"id", "A", "B"}` with `A`, `B` 4×4 arrays of polynomial strings in `t`, as
//! `scripts/random_moving.py` writes them).

use qsic::io::moving_matrix_from_rows;
use qsic::motion::MovingPencil;
use std::io::BufRead;
use std::time::Instant;

/// The 4×4 array of strings under `key` in a line (the format of `random_moving.py`).
fn rows(line: &str, key: &str) -> Vec<Vec<String>> {
    let start = line.find(&format!("\"{key}\": [")).expect("the key") + key.len() + 4;
    let mut out = Vec::new();
    let mut rest = &line[start..];
    for _ in 0..4 {
        let mut row = Vec::new();
        for _ in 0..4 {
            let open = rest.find('"').expect("an entry") + 1;
            let close = open + rest[open..].find('"').expect("its end");
            row.push(rest[open..close].to_string());
            rest = &rest[close + 1..];
        }
        out.push(row);
    }
    out
}

fn main() {
    for line in std::io::stdin().lock().lines() {
        let line = line.expect("a line");
        let (a, b) = (rows(&line, "A"), rows(&line, "B"));
        let clock = Instant::now();
        let pencil = MovingPencil::new(
            moving_matrix_from_rows(&a).expect("A"),
            moving_matrix_from_rows(&b).expect("B"),
        )
        .expect("a pencil");
        let new = clock.elapsed().as_secs_f64();
        let clock = Instant::now();
        let polys = pencil.candidate_polynomials().expect("candidates");
        let cand = clock.elapsed().as_secs_f64();
        let degrees: Vec<usize> = polys.iter().map(|p| p.degree().unwrap_or(0)).collect();
        let clock = Instant::now();
        let instants = pencil.candidate_instants().expect("instants");
        let roots = clock.elapsed().as_secs_f64() - cand;
        let clock = Instant::now();
        let motion = pencil.variations().expect("variations");
        let all = clock.elapsed().as_secs_f64();
        println!(
            "new {new:.2} s, candidates {cand:.2} s (degrees {degrees:?}), roots {roots:.2} s \
             ({} real), variations {all:.2} s ({} instants)",
            instants.len(),
            motion.instants.len()
        );
    }
}
