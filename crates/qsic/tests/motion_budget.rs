//! The work budget of motions and contacts (issue 24): a small budget stops with
//! `Error::BudgetExceeded`, the same units are spent on every run, the exact units spent
//! suffice and one unit less does not, the budgeted answers equal the plain ones, and more
//! work spends more units. No timing: every assertion is on answers and unit counts.

#[path = "../benches/inputs/motion.rs"]
mod motion_inputs;

use motion_inputs::{random_families, random_moving};
use qsic::io::{moving_matrix_from_polynomial as moving, MovingMatrix};
use qsic::motion::contact::{
    contact_points_within, first_contact, first_contact_in_within, first_contact_within,
    solid_motion, solid_motion_within, FirstContact, TimeRange,
};
use qsic::motion::{Motion, MovingPencil};
use qsic::{Budget, Error};
use qsic_algebra::testing::SplitMix;

/// A random moving pencil, entries of degree `degree` in `t` with `bits`-bit coefficients.
fn random(seed: u64, degree: usize, bits: usize) -> MovingPencil {
    let mut rng = SplitMix(seed);
    let a = random_moving(&mut rng, degree, bits);
    let b = random_moving(&mut rng, degree, bits);
    MovingPencil::new(a, b).unwrap()
}

/// What a motion says, comparable: each instant's text and type, each interval's sample and
/// type.
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

fn over_budget<T: std::fmt::Debug>(r: Result<T, Error>, limit: u64) {
    match r {
        Err(Error::BudgetExceeded { limit: l }) => assert_eq!(l, limit),
        other => panic!("expected the budget error, got {other:?}"),
    }
}

/// The degree-16 pencil with 512-bit coefficients (the documented limits): a budget of
/// 10⁷ units stops it in the candidate stage — the discriminant's determinant is charged
/// one prime at a time as it runs, so the error comes long before the elimination ends;
/// and `MovingPencil::new_within` stops before the minors on a smaller budget.
#[test]
fn a_small_budget_stops_the_largest_pencil_before_its_discriminant() {
    let (name, a, b) = random_families(true).pop().unwrap();
    assert_eq!(name, "random_degree16_512bit");
    let pencil = MovingPencil::new(a, b).unwrap();
    let budget = Budget::new(10_000_000);
    over_budget(pencil.variations_within(None, None, &budget), 10_000_000);
    assert_eq!(budget.used(), u64::MAX, "a spent budget stays spent");
    over_budget(
        pencil.candidate_polynomials_within(&Budget::new(10_000_000)),
        10_000_000,
    );
    let (a, b) = (pencil.a().clone(), pencil.b().clone());
    over_budget(MovingPencil::new_within(a, b, &Budget::new(1000)), 1000);
}

/// A degree-2 random pencil: the budgeted motion equals the plain one and spends the same
/// units on every run; exactly those units suffice, one less gives the budget error (so
/// every stage that spends is on the path, and the count does not depend on the run).
#[test]
fn budgeted_motion_equals_the_plain_one_and_its_units_are_exact() {
    let pencil = random(1202, 2, 3);
    let plain = pencil.variations().unwrap();
    let counts: Vec<u64> = (0..2)
        .map(|_| {
            let budget = Budget::unlimited();
            let m = pencil.variations_within(None, None, &budget).unwrap();
            assert_eq!(summary(&m), summary(&plain));
            budget.used()
        })
        .collect();
    assert_eq!(counts[0], counts[1], "the same units on every run");
    let spent = counts[0];
    assert!(spent > 1_000, "{spent}");
    let exact = pencil.variations_within(None, None, &Budget::new(spent));
    assert_eq!(summary(&exact.unwrap()), summary(&plain));
    over_budget(
        pencil.variations_within(None, None, &Budget::new(spent - 1)),
        spent - 1,
    );
    // a small budget stops it too, with its own limit
    over_budget(
        pencil.variations_within(None, None, &Budget::new(1000)),
        1000,
    );
}

/// First contact and the solids' relation: the budgeted forms equal the plain ones with the
/// budget large enough, and give the budget error one unit short of what they spend.
#[test]
fn contact_and_solids_within_a_budget() {
    let a = moving("x^2 + y^2 + z^2 - 4").unwrap();
    let b = moving("(x - t)^2 + (y - t^2/3)^2 + z^2 - 1").unwrap();
    let range = TimeRange::all();
    let budget = Budget::unlimited();
    let first = first_contact_within(&a, &b, &range, &budget).unwrap();
    assert_eq!(first, first_contact(&a, &b, &range).unwrap());
    assert!(matches!(first, Some(FirstContact::At(_))));
    let spent = budget.used();
    assert!(first_contact_within(&a, &b, &range, &Budget::new(spent)).is_ok());
    over_budget(
        first_contact_within(&a, &b, &range, &Budget::new(spent - 1)),
        spent - 1,
    );

    let budget = Budget::unlimited();
    let solids = solid_motion_within(&a, &b, &budget).unwrap();
    let plain = solid_motion(&a, &b).unwrap();
    let keys = |m: &qsic::motion::SolidMotion| -> Vec<String> {
        let i = m.intervals.iter().map(|i| i.state.key().to_string());
        i.chain(m.instants.iter().map(|i| i.t.to_string()))
            .collect()
    };
    assert_eq!(keys(&solids), keys(&plain));
    let spent = budget.used();
    over_budget(
        solid_motion_within(&a, &b, &Budget::new(spent - 1)),
        spent - 1,
    );

    // the contact points: at an irrational first contact, over ℚ(α)
    let pencil = MovingPencil::new(a.clone(), b.clone()).unwrap();
    let motion = pencil.variations().unwrap();
    let first = first_contact_in_within(&pencil, &motion, &range, &Budget::unlimited())
        .unwrap()
        .unwrap();
    // fresh pencils: one keeps the polynomials its first call made and paid for
    let fresh = || MovingPencil::new(a.clone(), b.clone()).unwrap();
    let budget = Budget::unlimited();
    let points = contact_points_within(&fresh(), &first, &range, &budget).unwrap();
    assert!(points.is_some());
    let spent = budget.used();
    assert!(spent > 0);
    assert!(contact_points_within(&fresh(), &first, &range, &Budget::new(spent)).is_ok());
    let fresh = fresh();
    over_budget(
        contact_points_within(&fresh, &first, &range, &Budget::new(spent - 1)),
        spent - 1,
    );
}

fn units_of(a: &MovingMatrix, b: &MovingMatrix) -> u64 {
    let budget = Budget::unlimited();
    MovingPencil::new(a.clone(), b.clone())
        .unwrap()
        .variations_within(None, None, &budget)
        .unwrap();
    budget.used()
}

/// More work spends more units: a higher degree in `t`, longer coefficients, the solids after
/// a first contact; the first contact, which stops at its answer, less than the motion.
#[test]
fn spent_units_grow_with_the_work() {
    let units = |seed: u64, degree: usize, bits: usize| {
        let mut rng = SplitMix(seed);
        let a = random_moving(&mut rng, degree, bits);
        let b = random_moving(&mut rng, degree, bits);
        units_of(&a, &b)
    };
    let (d1, d2) = (units(1101, 1, 3), units(1101, 2, 3));
    let d2_long = units(1101, 2, 40);
    assert!(d1 < d2, "degree 1: {d1}, degree 2: {d2}");
    assert!(d2 < d2_long, "3-bit: {d2}, 40-bit: {d2_long}");

    let a = moving("x^2 + y^2 + z^2 - 4").unwrap();
    let b = moving("(x - t)^2 + y^2 + z^2 - 1").unwrap();
    let motion = units_of(&a, &b);
    let budget = Budget::unlimited();
    first_contact_within(&a, &b, &TimeRange::all(), &budget).unwrap();
    let contact = budget.used();
    solid_motion_within(&a, &b, &budget).unwrap();
    // the first contact classifies only up to its answer (t = −3): less than the motion
    assert!(motion > 0 && contact > 0 && contact < motion && budget.used() > contact);
}
