//! Work units spent and the rate at which this machine spends them (README, "Work budget"):
//! each input is answered once with `Budget::unlimited()`, which counts without limit.
//!
//! `cargo run --release -p qsic --example budget_rate [all]` (`all`: also the motion and
//! contact of the random moving pencil at the documented limits, degree 16 in `t` with
//! 512-bit coefficients — minutes).

#[path = "../benches/inputs/motion.rs"]
mod motion_inputs;

use qsic::io::{moving_matrix_from_polynomial, parse_quadric};
use qsic::motion::contact::{
    contact_points_within, first_contact_in_within, solid_motion_in_within, TimeRange,
};
use qsic::motion::MovingPencil;
use qsic::param::{
    parameterize_within,
    sample::{sample_within, SampleOptions},
};
use qsic::{classify_within, Budget, Quadric};
use std::time::Instant;

fn q(text: &str) -> Quadric {
    parse_quadric(text).expect("a quadric")
}

fn report(name: &str, run: impl Fn(&Budget)) {
    let budget = Budget::unlimited();
    let start = Instant::now();
    run(&budget);
    let seconds = start.elapsed().as_secs_f64();
    let units = budget.used();
    println!(
        "{name:<58} {units:>14} units {seconds:>9.4} s {:>8.0} M units/s",
        units as f64 / seconds / 1e6
    );
}

fn main() {
    let big = format!("{}*x^2+y^2+z^2-w^2", "1".to_owned() + &"0".repeat(9_999));
    let pairs = [
        (
            "classify: roots 1e-1600 apart",
            q("x^2+y^2+z^2-w^2"),
            q("x^2+(1+1e-1600)*y^2+2*z^2+3*w^2"),
        ),
        (
            "classify: roots 1e-6000 apart",
            q("x^2+y^2+z^2-w^2"),
            q("x^2+(1+1e-6000)*y^2+2*z^2+3*w^2"),
        ),
        (
            "classify: one 10 000-digit entry",
            q(&big),
            q("x^2+y^2-z^2"),
        ),
        (
            "classify: tangent spheres",
            q("x^2+y^2+z^2-1"),
            q("(x-2)^2+y^2+z^2-1"),
        ),
    ];
    for (name, a, b) in &pairs {
        report(name, |budget| {
            classify_within(a, b, budget).expect("classified");
        });
    }
    let curves = [
        ("param: Viviani", q("x^2+y^2+z^2-4"), q("(x-1)^2+y^2-1")),
        (
            "param: two ellipsoids (case 1)",
            q("x^2+2*y^2+3*z^2-1"),
            q("3*x^2+2*y^2+z^2-1"),
        ),
        ("param: one 10 000-digit entry", q(&big), q("x^2+y^2-z^2")),
    ];
    for (name, a, b) in &curves {
        report(name, |budget| {
            parameterize_within(a, b, budget).expect("a curve");
        });
    }
    let (a, b) = (q("x^2+y^2+z^2-4"), q("x^2+y^2-2*x"));
    let curve = parameterize_within(&a, &b, &Budget::unlimited()).expect("a curve");
    for points in [1_000, 1_000_000] {
        let options = SampleOptions {
            points,
            ..SampleOptions::default()
        };
        report(&format!("sample: Viviani, {points} points"), |budget| {
            sample_within(&curve, &options, budget).expect("points");
        });
    }
    // motions and contacts: the rigid families and the random pencils of the bench
    let all = std::env::args().nth(1).as_deref() == Some("all");
    let spheres = (
        "spheres".to_string(),
        moving_matrix_from_polynomial("x^2+y^2+z^2-4").expect("A"),
        moving_matrix_from_polynomial("(x-t)^2+y^2+z^2-1").expect("B"),
    );
    let rigid = motion_inputs::rigid_families()
        .into_iter()
        .map(|(n, a, b)| (n.to_string(), a, b));
    let random = motion_inputs::random_families(all)
        .into_iter()
        .filter(|(n, _, _)| all || !n.contains("64bit") && !n.contains("degree4"));
    for (name, a, b) in std::iter::once(spheres).chain(rigid).chain(random) {
        report(&format!("motion: {name}"), |budget| {
            let pencil = MovingPencil::new(a.clone(), b.clone()).expect("a pencil");
            pencil
                .variations_within(None, None, budget)
                .expect("the motion");
        });
        report(&format!("contact: {name}"), |budget| {
            let range = TimeRange::all();
            let pencil = MovingPencil::new(a.clone(), b.clone()).expect("a pencil");
            let motion = pencil
                .variations_within(None, None, budget)
                .expect("the motion");
            if let Some(first) =
                first_contact_in_within(&pencil, &motion, &range, budget).expect("first contact")
            {
                contact_points_within(&pencil, &first, &range, budget).expect("the points");
            }
            solid_motion_in_within(&pencil, &range, budget).expect("the solids");
        });
    }
}
