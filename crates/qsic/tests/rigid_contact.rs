//! Rigid motions and contact points with known answers by construction: spheres along a
//! line, an ellipsoid turning (Cayley) until its tip touches a sphere, a sphere on a screw
//! motion rising into a sphere; the contact instant and the contact point exact.

use qsic::io::{moving_matrix_from_polynomial, MovingMatrix};
use qsic::motion::contact::{
    contact_points, first_contact, CommonLocus, CommonPointKind, ContactPoints, FirstContact,
    TimeRange,
};
use qsic::motion::rigid::{RigidMotion, Rotation};
use qsic::motion::MovingPencil;
use qsic::param::Number;
use qsic_algebra::{AlgebraicReal, Poly, RBig, Ring};

fn moving(text: &str) -> MovingMatrix {
    moving_matrix_from_polynomial(text).expect("a valid moving quadric")
}

fn rat(n: i64, d: u64) -> RBig {
    RBig::from_parts(n.into(), d.into())
}

/// The first contact in `range` and its common points.
fn contact(a: &MovingMatrix, b: &MovingMatrix, range: &TimeRange) -> ContactPoints {
    let first = first_contact(a, b, range)
        .expect("analysed")
        .expect("a contact in the range");
    let pencil = MovingPencil::new(a.clone(), b.clone()).expect("within the limits");
    contact_points(&pencil, &first, range)
        .expect("the points")
        .expect("an instant")
}

/// The one common point, exact, with its kind.
fn single_point(c: &ContactPoints) -> ([Number; 4], CommonPointKind) {
    match &c.locus {
        CommonLocus::Points { points, curves: 0 } if points.len() == 1 => {
            (points[0].point.clone(), points[0].kind)
        }
        other => panic!("one isolated point expected at t = {}: {other:?}", c.t),
    }
}

fn affine(x: [RBig; 3]) -> [Number; 4] {
    let [a, b, c] = x;
    [a, b, c, RBig::ONE].map(Number::rational)
}

#[test]
fn spheres_along_a_line_touch_at_known_points() {
    // radius 1 at (t, 0, 0) and radius 2 at the origin: outside at t = −3, at (−2, 0, 0);
    // after t = 0 (B inside A), inside at t = 1, at (2, 0, 0)
    let (a, b) = (
        moving("x^2 + y^2 + z^2 - 4"),
        moving("(x - t)^2 + y^2 + z^2 - 1"),
    );
    let c = contact(&a, &b, &TimeRange::all());
    assert_eq!(c.t, AlgebraicReal::from_rational(RBig::from(-3)));
    assert!(!c.at_start);
    let (p, kind) = single_point(&c);
    assert_eq!(p, affine([RBig::from(-2), RBig::ZERO, RBig::ZERO]));
    assert_eq!(kind, CommonPointKind::Isolated);
    let later = TimeRange::new(Some(RBig::ZERO), None).unwrap();
    let c = contact(&a, &b, &later);
    assert_eq!(c.t, AlgebraicReal::from_rational(RBig::ONE));
    assert_eq!(
        single_point(&c).0,
        affine([RBig::from(2), RBig::ZERO, RBig::ZERO])
    );
    // starting inside the overlap: they already meet at the start, along a circle
    let overlap = TimeRange::new(Some(RBig::from(2)), None).unwrap();
    let c = contact(&a, &b, &overlap);
    assert!(c.at_start);
    assert!(
        matches!(c.locus, CommonLocus::Points { curves: 1, .. }),
        "{:?}",
        c.locus
    );

    // off the line of centres by 1/2: |c| = 3 at t = −√35/2, the point 2c/3 = (−√35/3, 1/3, 0)
    let b = moving("(x - t)^2 + (y - 1/2)^2 + z^2 - 1");
    let c = contact(&a, &b, &TimeRange::all());
    assert!(c.t.is_root_of(&Poly::from_i64s(&[-35, 0, 4])) && c.t.to_f64() < 0.0);
    let (p, _) = single_point(&c);
    assert_eq!(p[1], Number::rational(rat(1, 3)));
    assert!(p[2].is_zero() && p[0].sign() == qsic_algebra::Sign::Negative);
    assert_eq!(p[0].mul(&p[0]), Number::rational(rat(35, 9)));
}

/// The ellipsoid `x²/4 + y² + z² = 1` turning about `z` reaches out to radius 2 only at its
/// tips `±2(cos θ, sin θ, 0)`; the sphere of radius 3 about `(3, 4, 0)` comes no nearer to the
/// axis than its point `(6/5, 8/5, 0)` at radius 2. So they first touch there, when a tip
/// points at it: `θ = φ − π` (t = tan(θ/2) = −2) coming from `t = −∞`, `θ = φ` (t = 1/2)
/// on `[0, ∞)`, with `cos φ = 3/5`.
#[test]
fn a_turning_ellipsoid_touches_a_sphere_at_its_tip() {
    let turn = RigidMotion {
        rotation: Rotation::Cayley {
            axis: [0, 0, 1].map(RBig::from),
        },
        ..RigidMotion::default()
    };
    let a = turn.apply(&moving("x^2/4 + y^2 + z^2 - 1")).unwrap();
    let b = moving("(x - 3)^2 + (y - 4)^2 + z^2 - 9");
    let tip = affine([rat(6, 5), rat(8, 5), RBig::ZERO]);
    let c = contact(&a, &b, &TimeRange::all());
    assert_eq!(c.t, AlgebraicReal::from_rational(RBig::from(-2)));
    assert_eq!(single_point(&c).0, tip);
    let c = contact(&a, &b, &TimeRange::new(Some(RBig::ZERO), None).unwrap());
    assert_eq!(c.t, AlgebraicReal::from_rational(rat(1, 2)));
    assert_eq!(single_point(&c).0, tip);
    // the same turn as a quaternion path 1 + t·k
    let path = RigidMotion {
        rotation: Rotation::Quaternion([
            Poly::constant(RBig::ONE),
            Poly::zero(),
            Poly::zero(),
            Poly::new(vec![RBig::ZERO, RBig::ONE]),
        ]),
        ..RigidMotion::default()
    };
    assert_eq!(path.apply(&moving("x^2/4 + y^2 + z^2 - 1")).unwrap(), a);
}

/// A unit sphere about `(2, 0, 0)` on the screw motion "turn about z by θ = 2·atan t, rise
/// t": its centre is `(2 cos θ, 2 sin θ, t)`. The sphere of radius 2 about `(−6/5, 8/5, 5)`
/// is at distance > 3 from it while t < 2 (the rise alone leaves more than 3), and at
/// distance 3 at t = 2 (θ with cos θ = −3/5, sin θ = 4/5): they touch at `(−6/5, 8/5, 3)`.
#[test]
fn a_screw_motion_rises_into_a_sphere() {
    let screw = RigidMotion {
        rotation: Rotation::Cayley {
            axis: [0, 0, 1].map(RBig::from),
        },
        translation: [
            Poly::zero(),
            Poly::zero(),
            Poly::new(vec![RBig::ZERO, RBig::ONE]),
        ],
        ..RigidMotion::default()
    };
    let a = screw.apply(&moving("(x - 2)^2 + y^2 + z^2 - 1")).unwrap();
    let b = moving("(x + 6/5)^2 + (y - 8/5)^2 + (z - 5)^2 - 4");
    let c = contact(&a, &b, &TimeRange::all());
    assert_eq!(c.t, AlgebraicReal::from_rational(RBig::from(2)));
    assert_eq!(
        single_point(&c).0,
        affine([rat(-6, 5), rat(8, 5), RBig::from(3)])
    );
    // a range starting after the contact: they meet at its start
    let c = contact(
        &a,
        &b,
        &TimeRange::new(Some(rat(5, 2)), Some(RBig::from(3))).unwrap(),
    );
    assert!(c.at_start && c.t == AlgebraicReal::from_rational(rat(5, 2)));
    // a range that ends before it has none
    let before = TimeRange::new(None, Some(RBig::ONE)).unwrap();
    assert_eq!(first_contact(&a, &b, &before).unwrap(), None);
    // no instant from −∞: no points
    let (x, y) = (moving("x^2 + y^2 - 1"), moving("x^2 + z^2 - 1"));
    let pencil = MovingPencil::new(x, y).unwrap();
    let none = contact_points(&pencil, &FirstContact::FromMinusInfinity, &TimeRange::all());
    assert!(none.unwrap().is_none());
}
