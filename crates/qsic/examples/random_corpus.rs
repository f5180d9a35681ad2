//! Writes `N` JSON lines of random pairs of quadrics for `qsic classify --batch -`, the input
//! of the batch speed figures in the README. Deterministic: the same `N` and family give the
//! same lines, and the first `k` lines do not depend on `N`.
//!
//! ```sh
//! cargo run --release -p qsic --example random_corpus -- 201 matrix > m201.jsonl
//! cargo run --release -p qsic --example random_corpus -- 201 poly > p201.jsonl
//! ```
//!
//! Families:
//! - `matrix`: A and B symmetric 4×4 arrays of number strings `p/q` (`p` in [−10, 10], `q` in
//!   [1, 4], written `p` when `q` is 1), e.g. `"3/2"`, `"-7"`, `"2/4"`;
//! - `poly`: A and B polynomial strings in x, y, z, w whose ten coefficients are integers
//!   in [−10, 10] (zero terms left out), e.g. `"3*x^2 - 7*x*y + w^2"`;
//! - `matrix-wide`: as `matrix` with `p` in [−100, 100] and `q` in [1, 12];
//! - `poly-fractions`: as `poly` with coefficients `c/q`, `q` in [1, 4], e.g. `"-9/4*x^2"`.

#[path = "../benches/inputs/mod.rs"]
mod inputs;

use inputs::{
    random_polynomial_text, random_polynomial_text_over, random_rational_rows_json,
    random_rational_rows_json_in, SplitMix,
};

fn main() {
    let mut args = std::env::args().skip(1);
    let n: usize = args.next().and_then(|s| s.parse().ok()).unwrap_or(201);
    let family = args.next().unwrap_or_else(|| "matrix".into());
    let mut rng = SplitMix(2026);
    let mut out = String::new();
    for id in 1..=n {
        let (a, b) = match family.as_str() {
            "poly" => (
                format!("\"{}\"", random_polynomial_text(&mut rng)),
                format!("\"{}\"", random_polynomial_text(&mut rng)),
            ),
            "poly-fractions" => (
                format!("\"{}\"", random_polynomial_text_over(&mut rng, 4)),
                format!("\"{}\"", random_polynomial_text_over(&mut rng, 4)),
            ),
            "matrix-wide" => (
                random_rational_rows_json_in(&mut rng, 100, 12),
                random_rational_rows_json_in(&mut rng, 100, 12),
            ),
            _ => (
                random_rational_rows_json(&mut rng),
                random_rational_rows_json(&mut rng),
            ),
        };
        out.push_str(&format!("{{\"id\": {id}, \"A\": {a}, \"B\": {b}}}\n"));
    }
    print!("{out}");
}
