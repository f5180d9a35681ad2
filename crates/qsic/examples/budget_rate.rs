//! Work units spent and the rate at which this machine spends them (README, "Work budget"):
//! each input is answered once with `Budget::unlimited()`, which counts without limit.
//!
//! `cargo run --release -p qsic --example budget_rate`

use qsic::io::parse_quadric;
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
}
