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
//!   in [−10, 10] (zero terms left out), e.g. `"3*x^2 - 7*x*y + w^2"`.

#[path = "../benches/inputs/mod.rs"]
mod inputs;

use inputs::{random_polynomial_text, random_rational_rows_json, SplitMix};

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
            _ => (
                random_rational_rows_json(&mut rng),
                random_rational_rows_json(&mut rng),
            ),
        };
        out.push_str(&format!("{{\"id\": {id}, \"A\": {a}, \"B\": {b}}}\n"));
    }
    print!("{out}");
}
