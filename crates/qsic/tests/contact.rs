//! First contact and the relation of moving solids: motions whose instants and relations are
//! known by hand (rational and irrational instants, grazes), disguised by affine maps of
//! space and affine changes of time; the emptiness test against the recorded real types.

use qsic::io::{moving_matrix_from_polynomial, quadric_from_rows, MovingMatrix};
use qsic::motion::contact::{
    first_contact, has_real_points, solid_motion, FirstContact, SolidMotion, TimeRange,
};
use qsic::solids::{Solid, SolidRelation};
use qsic::{classify_allowing_zero, Error, Quadric};
use qsic_algebra::{AlgebraicReal, Poly, RBig};
use serde_json::Value;

fn moving(text: &str) -> MovingMatrix {
    moving_matrix_from_polynomial(text).unwrap()
}

fn rat(n: i64, d: i64) -> RBig {
    RBig::from_parts_signed(n.into(), d.into())
}

fn at_t(v: RBig) -> Option<FirstContact> {
    Some(FirstContact::At(AlgebraicReal::from_rational(v)))
}

fn range(from: Option<RBig>, to: Option<RBig>) -> TimeRange {
    TimeRange::new(from, to).unwrap()
}

use SolidRelation as R;
const OUT: R = R::Separated;
const TOUCH: R = R::TouchingExternally;
const OVER: R = R::Overlapping;
const IN_B: R = R::Inside { inner: Solid::B };
const TOUCH_IN_B: R = R::TouchingInternally { inner: Solid::B };

/// An expected instant: its value as a polynomial in `t` with the root near `approx`.
struct Expected {
    poly: &'static [i64],
    approx: f64,
    relation: R,
}

/// The timeline is `intervals` with `instants` between them, every instant on the expected
/// polynomial (up to sign and content) and isolated around the expected value.
fn assert_timeline(m: &SolidMotion, intervals: &[R], instants: &[Expected], what: &str) {
    let got: Vec<Option<R>> = m.intervals.iter().map(|i| i.state.relation()).collect();
    let want: Vec<Option<R>> = intervals.iter().copied().map(Some).collect();
    assert_eq!(got, want, "{what}: intervals");
    assert_eq!(m.instants.len(), instants.len(), "{what}: instants");
    for (i, e) in m.instants.iter().zip(instants) {
        assert_eq!(i.state.relation(), Some(e.relation), "{what}: at {}", i.t);
        let p = Poly::from_i64s(e.poly);
        assert!(i.t.is_root_of(&p), "{what}: {} not a root of {p}", i.t);
        assert!(
            (i.t.to_f64() - e.approx).abs() < 1e-9,
            "{what}: {} vs {}",
            i.t,
            e.approx
        );
    }
    assert!(m.ellipsoids_throughout());
}

fn e(poly: &'static [i64], approx: f64, relation: R) -> Expected {
    Expected {
        poly,
        approx,
        relation,
    }
}

/// A unit sphere centred at `(t, 0, 0)` and a sphere of radius 2 at the origin: contact at
/// `t = −3`, overlap, inside from `t = −1` (touching internally at `−1` and `1`), apart after
/// `3`. First contact in several ranges, by hand.
#[test]
fn sphere_through_a_sphere_by_hand() {
    let a = moving("x^2 + y^2 + z^2 - 4");
    let b = moving("(x - t)^2 + y^2 + z^2 - 1");
    let m = solid_motion(&a, &b).unwrap();
    assert_timeline(
        &m,
        &[OUT, OVER, IN_B, OVER, OUT],
        &[
            e(&[3, 1], -3.0, TOUCH),
            e(&[1, 1], -1.0, TOUCH_IN_B),
            e(&[-1, 1], 1.0, TOUCH_IN_B),
            e(&[-3, 1], 3.0, TOUCH),
        ],
        "spheres",
    );
    let n = |v: i64| Some(RBig::from(v));
    let cases = [
        (TimeRange::all(), at_t(RBig::from(-3))),
        (range(None, n(-4)), None),
        (range(n(-10), n(10)), at_t(RBig::from(-3))),
        // in contact at the start
        (range(n(-2), None), at_t(RBig::from(-2))),
        (range(n(-1), None), at_t(RBig::from(-1))),
        // nested at −1/2: no common real point until the internal touch at 1
        (range(Some(rat(-1, 2)), None), at_t(RBig::ONE)),
        (range(Some(rat(-1, 2)), Some(rat(1, 2))), None),
        (range(n(1), n(1)), at_t(RBig::ONE)),
        (range(Some(rat(7, 2)), None), None),
    ];
    for (r, want) in cases {
        assert_eq!(first_contact(&a, &b, &r).unwrap(), want, "{r:?}");
        // the solids meet exactly where the surfaces do, except while nested
        let solids = m.first_meeting(&r).unwrap();
        if r.from() != Some(&rat(-1, 2)) {
            assert_eq!(solids, want, "solids {r:?}");
        } else {
            assert_eq!(solids, at_t(rat(-1, 2)), "solids {r:?}");
        }
    }
}

/// `x²/4 + y² + z² ≤ 1` (x-extent `[−2, 2]`) and `(x − t)² + 4y² + 4z² ≤ 1` (extent
/// `[t − 1, t + 1]`): contact at `t = ±3`; for `|t| ≤ 1` the small one is inside, since
/// `(t + u)²/4 + (1 − u²)/4 ≤ (1 + |t|)²/4` for `|u| ≤ 1`, with equality only at `|t| = 1`.
#[test]
fn ellipsoids_along_an_axis_by_hand() {
    let a = moving("x^2/4 + y^2 + z^2 - 1");
    let b = moving("(x - t)^2 + 4*y^2 + 4*z^2 - 1");
    assert_timeline(
        &solid_motion(&a, &b).unwrap(),
        &[OUT, OVER, IN_B, OVER, OUT],
        &[
            e(&[3, 1], -3.0, TOUCH),
            e(&[1, 1], -1.0, TOUCH_IN_B),
            e(&[-1, 1], 1.0, TOUCH_IN_B),
            e(&[-3, 1], 3.0, TOUCH),
        ],
        "ellipsoids",
    );
    assert_eq!(
        first_contact(&a, &b, &TimeRange::all()).unwrap(),
        at_t(RBig::from(-3))
    );
}

/// Irrational instants, decided over `ℚ(α)`: a unit sphere on the line `y = c` through a
/// sphere of radius 2 touches outside where `t² + c² = 9` and inside where `t² + c² = 1`
/// (for `c = 1` only at `t = 0`, overlapping on both sides);
/// on `y = 3` it only grazes at `t = 0`, and on a path `x = (t² − 2)² + 3` it grazes at
/// `t = ±√2` (distance 3 there, more elsewhere).
#[test]
fn irrational_contacts_and_grazes() {
    let big = moving("x^2 + y^2 + z^2 - 4");
    let line = |c: &str| moving(&format!("(x - t)^2 + (y - {c})^2 + z^2 - 1"));
    let r8 = 8f64.sqrt();
    let r3 = 0.75f64.sqrt();
    let cases: [(MovingMatrix, Vec<R>, Vec<Expected>); 4] = [
        (
            line("1"),
            vec![OUT, OVER, OVER, OUT],
            vec![
                e(&[-8, 0, 1], -r8, TOUCH),
                e(&[0, 1], 0.0, TOUCH_IN_B),
                e(&[-8, 0, 1], r8, TOUCH),
            ],
        ),
        (
            line("1/2"),
            vec![OUT, OVER, IN_B, OVER, OUT],
            vec![
                // t² + 1/4 = 9 and t² + 1/4 = 1
                e(&[-35, 0, 4], -(35f64.sqrt()) / 2.0, TOUCH),
                e(&[-3, 0, 4], -r3, TOUCH_IN_B),
                e(&[-3, 0, 4], r3, TOUCH_IN_B),
                e(&[-35, 0, 4], 35f64.sqrt() / 2.0, TOUCH),
            ],
        ),
        (line("3"), vec![OUT, OUT], vec![e(&[0, 1], 0.0, TOUCH)]),
        (
            moving("(x - (t^2 - 2)^2 - 3)^2 + y^2 + z^2 - 1"),
            vec![OUT, OUT, OUT],
            vec![
                e(&[-2, 0, 1], -(2f64.sqrt()), TOUCH),
                e(&[-2, 0, 1], 2f64.sqrt(), TOUCH),
            ],
        ),
    ];
    for (i, (b, intervals, instants)) in cases.into_iter().enumerate() {
        let m = solid_motion(&big, &b).unwrap();
        assert_timeline(&m, &intervals, &instants, &format!("case {i}"));
        let first = first_contact(&big, &b, &TimeRange::all()).unwrap();
        let Some(FirstContact::At(t)) = first else {
            panic!("case {i}: {first:?}")
        };
        assert_eq!(t, m.instants[0].t, "case {i}");
        assert_eq!(
            m.first_meeting(&TimeRange::all()).unwrap(),
            Some(FirstContact::At(t))
        );
    }
}

/// A rational affine map of space applied to both quadrics keeps every relation and
/// instant; an affine change of time `t = 2s + 1` moves the instants to `s = (t − 1)/2`.
#[test]
fn affine_disguises_of_space_and_time() {
    let (x, y, z) = ("(2*x + y - 1)", "(y - z/3 + 2)", "(z + x)");
    let a = moving(&format!("{x}^2 + {y}^2 + {z}^2 - 4"));
    let b = moving(&format!("({x} - t)^2 + ({y} - 1/2)^2 + {z}^2 - 1"));
    let m = solid_motion(&a, &b).unwrap();
    let r35 = 35f64.sqrt() / 2.0;
    let r3 = 0.75f64.sqrt();
    assert_timeline(
        &m,
        &[OUT, OVER, IN_B, OVER, OUT],
        &[
            e(&[-35, 0, 4], -r35, TOUCH),
            e(&[-3, 0, 4], -r3, TOUCH_IN_B),
            e(&[-3, 0, 4], r3, TOUCH_IN_B),
            e(&[-35, 0, 4], r35, TOUCH),
        ],
        "affine map",
    );
    let b = moving("(x - (2*t + 1))^2 + (y - 1/2)^2 + z^2 - 1");
    let a = moving("x^2 + y^2 + z^2 - 4");
    let m = solid_motion(&a, &b).unwrap();
    // (2s + 1)² = 35/4 ⇔ 16s² + 16s − 31 = 0; (2s + 1)² = 3/4 ⇔ 16s² + 16s + 1 = 0
    let s = |v: f64| (v - 1.0) / 2.0;
    assert_timeline(
        &m,
        &[OUT, OVER, IN_B, OVER, OUT],
        &[
            e(&[-31, 16, 16], s(-r35), TOUCH),
            e(&[1, 16, 16], s(-r3), TOUCH_IN_B),
            e(&[1, 16, 16], s(r3), TOUCH_IN_B),
            e(&[-31, 16, 16], s(r35), TOUCH),
        ],
        "time change",
    );
}

/// A growing sphere and a fixed one of the same centre: equal at `t = 1`; a sphere whose
/// radius shrinks through 0 stops being an ellipsoid (a point, then imaginary) — those
/// stretches are reported, not given a relation; first contact of surfaces that are not
/// solids (a sphere through a cylinder) is still exact.
#[test]
fn equal_solids_degenerate_spheres_and_non_solids() {
    let a = moving("x^2 + y^2 + z^2 - 1");
    let m = solid_motion(&a, &moving("x^2 + y^2 + z^2 - t^2")).unwrap();
    // |t| > 1: A inside the moving sphere B; 0 < |t| < 1: B inside; t = ±1 equal; t = 0 a point
    let in_a = R::Inside { inner: Solid::A };
    let got: Vec<Option<R>> = m.intervals.iter().map(|i| i.state.relation()).collect();
    assert_eq!(got, [in_a, IN_B, IN_B, in_a].map(Some));
    let at: Vec<(String, &str)> = m
        .instants
        .iter()
        .map(|i| (i.t.to_string(), i.state.key()))
        .collect();
    let want = [("-1", "equal"), ("0", "not_ellipsoids"), ("1", "equal")];
    assert_eq!(at, want.map(|(t, k)| (t.to_string(), k)));
    assert!(!m.ellipsoids_throughout());

    let m = solid_motion(&a, &moving("x^2 + y^2 + z^2 - t")).unwrap();
    let keys: Vec<(Option<String>, &str)> = m
        .intervals
        .iter()
        .map(|i| (i.from.as_ref().map(|t| t.to_string()), i.state.key()))
        .collect();
    assert_eq!(
        keys,
        [
            (None, "not_ellipsoids"),
            (Some("0".into()), "inside"),
            (Some("1".into()), "inside")
        ]
    );
    assert_eq!(m.instants[0].state.key(), "not_ellipsoids");
    assert_eq!(m.instants[1].state.relation(), Some(R::Equal));
    assert!(matches!(
        m.first_meeting(&TimeRange::all()),
        Err(Error::NotEllipsoid(_))
    ));

    let cylinder = moving("x^2 + y^2 - 1");
    let sphere = moving("(x - t)^2 + y^2 + z^2 - 1");
    assert_eq!(
        first_contact(&cylinder, &sphere, &TimeRange::all()).unwrap(),
        at_t(RBig::from(-2))
    );
    assert!(solid_motion(&cylinder, &sphere)
        .unwrap()
        .intervals
        .iter()
        .all(|i| i.state.key() == "not_ellipsoids"));
    assert!(TimeRange::new(Some(RBig::ONE), Some(RBig::ZERO)).is_err());

    // B(t) = t·(sphere): the factor t common to all entries is cleared by the reader, so
    // B is the sphere at every t, t = 0 included (the limit), as in the motion analysis
    let m = solid_motion(&a, &moving("t*(x^2 + y^2 + z^2 - 4)")).unwrap();
    assert!(m.instants.is_empty(), "{:?}", m.instants);
    let got: Vec<Option<R>> = m.intervals.iter().map(|i| i.state.relation()).collect();
    let in_a = R::Inside { inner: Solid::A };
    assert_eq!(got, [Some(in_a)]);
    assert!(m.ellipsoids_throughout());
}

fn read_form(v: &Value) -> Option<Quadric> {
    let parsed = match v {
        Value::String(s) => qsic::io::parse_quadric(s),
        Value::Array(rows) => {
            let rows: Vec<Vec<String>> = rows
                .iter()
                .map(|r| {
                    let r = r.as_array().unwrap();
                    r.iter()
                        .map(|x| x.as_str().map_or_else(|| x.to_string(), str::to_owned))
                        .collect()
                })
                .collect();
            quadric_from_rows(&rows)
        }
        _ => panic!("unexpected quadric value {v}"),
    };
    match parsed {
        Err(Error::ZeroQuadric) => None,
        other => Some(other.unwrap()),
    }
}

/// The emptiness test behind first contact (the class's real components) agrees with the
/// recorded `real_type` `empty` on every labelled pair of the corpora.
#[test]
fn real_points_agree_with_the_recorded_real_types() {
    let mut counts = [0usize; 2];
    for name in ["cases.jsonl", "qi-quadrics.jsonl"] {
        let path = format!("{}/tests/data/{name}", env!("CARGO_MANIFEST_DIR"));
        for line in std::fs::read_to_string(path).unwrap().lines() {
            let v: Value = serde_json::from_str(line).unwrap();
            let Some(real_type) = v["real_type"].as_str() else {
                continue;
            };
            let (a, b) = (read_form(&v["A"]), read_form(&v["B"]));
            let c = classify_allowing_zero(a.as_ref(), b.as_ref()).unwrap();
            let real = has_real_points(&c).unwrap();
            assert_eq!(real, real_type != "empty", "{}", v["id"]);
            counts[usize::from(real)] += 1;
        }
    }
    assert!(counts[0] > 10 && counts[1] > 100, "{counts:?}");
}
