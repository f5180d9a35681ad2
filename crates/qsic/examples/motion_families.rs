//! Prints the moving-quadric families of the `motion` bench as JSON Lines `{"id", "A", "B"}`
//! (4×4 arrays of polynomials in `t`, the numerators of the moving matrices), for timing
//! `qsic motion --batch -` and `qsic contact` on them one by one (README, "Moving quadrics").
//!
//! `cargo run --release -p qsic --example motion_families [all]`: the rigid families and the
//! random ones of degree 1, 2, 4 (3-bit and 64-bit coefficients); with `all`, also degree 16
//! with 512-bit coefficients.

#[path = "../benches/inputs/motion.rs"]
mod motion_inputs;

use qsic::io::MovingMatrix;

fn rows(m: &MovingMatrix) -> String {
    let entry =
        |i: usize, j: usize| format!("\"{}\"", m.numerators()[i][j].to_string().replace('x', "t"));
    let row = |i: usize| {
        format!(
            "[{}]",
            (0..4).map(|j| entry(i, j)).collect::<Vec<_>>().join(",")
        )
    };
    format!("[{}]", (0..4).map(row).collect::<Vec<_>>().join(","))
}

fn main() {
    let all = std::env::args().nth(1).as_deref() == Some("all");
    let rigid = motion_inputs::rigid_families()
        .into_iter()
        .map(|(n, a, b)| (n.to_string(), a, b));
    for (name, a, b) in rigid.chain(motion_inputs::random_families(all)) {
        println!(
            "{{\"id\":\"{name}\",\"A\":{},\"B\":{}}}",
            rows(&a),
            rows(&b)
        );
    }
}
