//! The work budget (`qsic::Budget`): the budgeted entry points answer as the plain ones,
//! spend the same units every time, stop exactly at their limit, and spend more where
//! there is more to do.

mod common;

use common::read_form;
use qsic::io::parse_quadric;
use qsic::param::sample::{sample, sample_within, SampleOptions};
use qsic::param::{parameterize, parameterize_within};
use qsic::{classify, classify_within, Budget, Error, Quadric};
use serde_json::Value;

fn q(text: &str) -> Quadric {
    parse_quadric(text).unwrap()
}

fn corpus_pairs(name: &str) -> Vec<(String, Quadric, Quadric)> {
    let path = format!("{}/tests/data/{name}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path)
        .unwrap()
        .lines()
        .filter(|l| !l.trim().is_empty())
        .filter_map(|l| {
            let v: Value = serde_json::from_str(l).unwrap();
            let (a, b) = (v.get("A")?, v.get("B")?);
            // the zero form is not a pair (it has no budgeted route of its own)
            let zero = |f: &Value| f.as_str().is_some_and(|s| s.trim() == "0");
            (!zero(a) && !zero(b)).then(|| (v["id"].to_string(), read_form(a), read_form(b)))
        })
        .collect()
}

/// The units `run` spends with an unlimited budget.
fn units<T>(run: impl Fn(&Budget) -> Result<T, Error>) -> u64 {
    let budget = Budget::unlimited();
    run(&budget).unwrap_or_else(|e| panic!("{e}"));
    budget.used()
}

/// `run` succeeds with exactly the units it spends, and fails one unit short, with the
/// budget error.
fn stops_exactly_at_its_units<T: std::fmt::Debug>(run: impl Fn(&Budget) -> Result<T, Error>) {
    let spent = units(&run);
    assert!(spent > 0);
    assert!(run(&Budget::new(spent)).is_ok(), "{spent} units are enough");
    match run(&Budget::new(spent - 1)) {
        Err(Error::BudgetExceeded { limit }) => assert_eq!(limit, spent - 1),
        other => panic!("one unit short of {spent}: {other:?}"),
    }
}

#[test]
fn budgeted_classification_equals_the_plain_one_on_the_corpora() {
    for file in ["cases.jsonl", "seed_examples.jsonl", "qi-quadrics.jsonl"] {
        for (id, a, b) in corpus_pairs(file) {
            let budget = Budget::unlimited();
            let c = classify_within(&a, &b, &budget).unwrap();
            assert_eq!(c, classify(&a, &b), "{file} {id}");
            assert!(budget.used() > 0, "{file} {id}: nothing spent");
            // the same units every time: a budget error is deterministic
            assert_eq!(
                units(|bu| classify_within(&a, &b, bu)),
                budget.used(),
                "{id}"
            );
        }
    }
}

#[test]
fn classification_stops_exactly_at_its_budget() {
    for (a, b) in [
        // the fast path
        ("x^2+2*y^2+3*z^2-w^2", "3*x^2+y^2+2*z^2-w^2"),
        // the exact path: a double root, and roots 10⁻⁴⁰ apart
        ("x^2+y^2+z^2-1", "(x-2)^2+y^2+z^2-1"),
        ("x^2+y^2+z^2-w^2", "x^2+(1+1e-40)*y^2+2*z^2+3*w^2"),
        // a singular pencil
        ("x^2+y^2-z^2", "x^2-y^2"),
    ] {
        let (a, b) = (q(a), q(b));
        stops_exactly_at_its_units(|bu| classify_within(&a, &b, bu));
    }
}

#[test]
fn the_units_grow_with_the_work() {
    let pair = |eps: &str| {
        let (a, b) = (
            q("x^2+y^2+z^2-w^2"),
            q(&format!("x^2+(1+{eps})*y^2+2*z^2+3*w^2")),
        );
        units(|bu| classify_within(&a, &b, bu))
    };
    let (near, nearer, nearest) = (pair("1e-10"), pair("1e-400"), pair("1e-1600"));
    assert!(
        near < nearer && nearer < nearest,
        "{near} {nearer} {nearest}"
    );
    // long entries cost more than short ones, for the same pencil up to scale
    let long = "1".to_owned() + &"0".repeat(3000);
    let (a, b) = (q(&format!("{long}*(x^2+y^2+z^2-w^2)")), q("x^2+2*y^2-w^2"));
    let (c, d) = (q("x^2+y^2+z^2-w^2"), q(&format!("{long}*x^2+2*y^2-w^2")));
    assert!(
        units(|bu| classify_within(&c, &d, bu)) > 100 * units(|bu| classify_within(&a, &b, bu))
    );
}

#[test]
fn budgeted_curve_and_points_equal_the_plain_ones_and_stop_at_their_budget() {
    let options = SampleOptions {
        points: 200,
        ..SampleOptions::default()
    };
    for (a, b) in [
        ("x^2+y^2+z^2-4", "(x-1)^2+y^2-1"),
        ("x^2+2*y^2+3*z^2-1", "3*x^2+2*y^2+z^2-1"),
        ("x^2+y^2-1", "x^2+z^2-1"),
    ] {
        let (a, b) = (q(a), q(b));
        let curve = parameterize(&a, &b).unwrap();
        let within = parameterize_within(&a, &b, &Budget::unlimited()).unwrap();
        assert_eq!(format!("{within:?}"), format!("{curve:?}"));
        stops_exactly_at_its_units(|bu| parameterize_within(&a, &b, bu));
        let points = sample(&curve, &options).unwrap();
        assert_eq!(
            sample_within(&curve, &options, &Budget::unlimited()).unwrap(),
            points
        );
        stops_exactly_at_its_units(|bu| sample_within(&curve, &options, bu));
    }
}

#[test]
fn more_points_cost_more_units() {
    let curve = parameterize(&q("x^2+y^2+z^2-4"), &q("(x-1)^2+y^2-1")).unwrap();
    let cost = |points| {
        let options = SampleOptions {
            points,
            ..SampleOptions::default()
        };
        units(|bu| sample_within(&curve, &options, bu))
    };
    let (few, many) = (cost(100), cost(10_000));
    assert!(many > 50 * few, "{few} {many}");
}
