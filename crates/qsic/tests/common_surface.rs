//! What two quadrics share beyond a curve is an answer: the quadric itself when `A ∝ B`, a
//! common plane otherwise. The affine view names it, its summary says so, the curve lists it.

use qsic::affine::{affine_view, common_surfaces, AffineSurface, Chart};
use qsic::classify::{ComponentKind, PencilKind};
use qsic::io::parse_quadric;
use qsic::param::parameterize;
use qsic_algebra::{RBig, Ring};

fn q(s: &str) -> qsic::Quadric {
    parse_quadric(s).unwrap()
}

/// `(kind, name, bounded, at_infinity)` of one component.
type Seen = (ComponentKind, Option<&'static str>, Option<bool>, bool);

/// The view's components, its summary, and whether `A ∝ B`.
fn view(a: &str, b: &str, chart: &Chart) -> (Vec<Seen>, String, bool) {
    let (a, b) = (q(a), q(b));
    let v = affine_view(Some(&a), Some(&b), chart, [false; 2]);
    let c = v.curve.as_ref().expect("the curve in ℝ³");
    let comps = c
        .components
        .iter()
        .map(|k| (k.kind, k.name, k.bounded, k.at_infinity))
        .collect();
    (comps, v.summary(), v.same)
}

#[test]
fn equal_and_proportional_spheres_are_the_same_sphere() {
    for b in [
        "x^2+y^2+z^2-1",
        "2*x^2+2*y^2+2*z^2-2",
        "-3*x^2-3*y^2-3*z^2+3",
    ] {
        let (comps, summary, same) = view("x^2+y^2+z^2-1", b, &Chart::default());
        assert!(same, "{b}");
        assert_eq!(
            comps,
            [(ComponentKind::Quadric, Some("sphere"), Some(true), false)],
            "{b}"
        );
        assert_eq!(
            summary,
            "sphere and sphere: the two are the same sphere; solids equal"
        );
        assert!(!summary.contains("no common point"));
    }
    // a sphere and a different one are not the same
    let (_, summary, same) = view("x^2+y^2+z^2-1", "x^2+y^2+z^2-4", &Chart::default());
    assert!(
        !same && summary.contains("no common point in ℝ³"),
        "{summary}"
    );
}

/// The common quadric's name is its name in the chart: the unit sphere with a plane at
/// infinity touching it is an elliptic paraboloid, unbounded.
#[test]
fn the_common_quadric_is_named_in_the_chart() {
    let chart = Chart::new([1, 0, 0, 1].map(RBig::from)).unwrap();
    let (comps, summary, _) = view("x^2+y^2+z^2-w^2", "5*x^2+5*y^2+5*z^2-5*w^2", &chart);
    assert_eq!(
        comps,
        [(
            ComponentKind::Quadric,
            Some("elliptic_paraboloid"),
            Some(false),
            false
        )]
    );
    assert!(
        summary.ends_with("the two are the same elliptic paraboloid"),
        "{summary}"
    );
    for (s, name) in [
        ("x^2+y^2-z^2-1", "hyperboloid_one_sheet"),
        ("(x-3)^2+y^2-1", "circular_cylinder"),
        ("x^2+y^2-z^2", "circular_cone"),
        ("x*y-z", "hyperbolic_paraboloid"),
    ] {
        let (comps, summary, _) = view(s, &format!("7*({s})"), &Chart::default());
        assert_eq!(
            comps,
            [(ComponentKind::Quadric, Some(name), Some(false), false)],
            "{s}"
        );
        assert!(
            summary.contains(&format!("the same {}", name.replace('_', " "))),
            "{summary}"
        );
    }
}

/// A double plane, two planes (rational and over ℚ(√2)), a plane and the plane at infinity:
/// the planes are the components, each named.
#[test]
fn equal_planes_are_the_same_plane() {
    let plane = (ComponentKind::Plane, Some("plane"), Some(false), false);
    let at_infinity = (ComponentKind::Plane, Some("plane_at_infinity"), None, true);
    let cases = [
        (
            "(z-1)^2",
            "2*(z-1)^2",
            vec![plane],
            "the two are the same double plane",
        ),
        (
            "x*y",
            "-x*y",
            vec![plane, plane],
            "the two are the same intersecting planes",
        ),
        (
            "x^2-2*y^2",
            "3*x^2-6*y^2",
            vec![plane, plane],
            "the two are the same intersecting planes",
        ),
        (
            "x^2-1",
            "4*x^2-4",
            vec![plane, plane],
            "the two are the same parallel planes",
        ),
        (
            "x*w",
            "2*x*w",
            vec![plane, at_infinity],
            "the two are the same plane",
        ),
        (
            "w^2",
            "3*w^2",
            vec![at_infinity],
            "the two are the same plane at infinity, no common point in ℝ³",
        ),
    ];
    for (a, b, want, says) in cases {
        let (comps, summary, same) = view(a, b, &Chart::default());
        assert!(same);
        assert_eq!(comps, want, "{a}");
        assert!(summary.ends_with(says), "{a}: {summary}");
    }
}

/// A quadric without a surface of real points: the cone with one real point is that point,
/// two conjugate planes their real line, a definite quadric nothing.
#[test]
fn a_common_quadric_with_a_point_or_a_line_of_real_points() {
    let (comps, summary, _) = view("(x-1)^2+y^2+z^2", "2*((x-1)^2+y^2+z^2)", &Chart::default());
    assert_eq!(
        comps,
        [(ComponentKind::Point, Some("point"), Some(true), false)]
    );
    assert!(
        summary.contains("the same point cone, 1 isolated point"),
        "{summary}"
    );
    let (comps, summary, _) = view("x^2+y^2", "3*x^2+3*y^2", &Chart::default());
    assert_eq!(
        comps,
        [(ComponentKind::Line, Some("line"), Some(false), false)]
    );
    assert!(
        summary.contains("the same line pair, 1 unbounded curve"),
        "{summary}"
    );
    let (comps, summary, _) = view("x^2+y^2+z^2+1", "2*(x^2+y^2+z^2+1)", &Chart::default());
    assert_eq!(comps, [(ComponentKind::Quadric, None, None, false)]);
    assert_eq!(
        summary,
        "imaginary and imaginary: the two are the same imaginary quadric, no common point in ℝ³; \
         no point at infinity"
    );
}

/// Two quadrics sharing a plane and not proportional: the plane is named beside the curve.
#[test]
fn a_common_plane_beside_a_curve() {
    let (comps, summary, same) = view("x*y", "x*z", &Chart::default());
    assert!(!same);
    assert_eq!(
        comps,
        [
            (ComponentKind::Plane, Some("plane"), Some(false), false),
            (ComponentKind::Line, Some("line"), Some(false), false)
        ]
    );
    assert_eq!(
        summary,
        "intersecting_planes and intersecting_planes: a common plane, 1 unbounded curve; 1 point at infinity on the curve"
    );
    // the plane x = 0 doubled and a pair through it: the plane alone
    let (comps, summary, _) = view("x^2", "x*z", &Chart::default());
    assert_eq!(
        comps,
        [(ComponentKind::Plane, Some("plane"), Some(false), false)]
    );
    assert_eq!(
        summary,
        "double_plane and intersecting_planes: a common plane"
    );
    // the plane at infinity in common, and the line x = y = 0
    let (comps, summary, _) = view("x*w", "y*w", &Chart::default());
    assert!(comps.contains(&(ComponentKind::Plane, Some("plane_at_infinity"), None, true)));
    assert!(
        summary.contains("the plane at infinity in common, 1 unbounded curve"),
        "{summary}"
    );
}

/// `common_surfaces` lists exactly the real planes and quadrics of the curve, by index.
#[test]
fn common_surfaces_index_the_curve() {
    let (a, b) = (q("x*y"), q("x*z"));
    let curve = parameterize(&a, &b).unwrap();
    let s = common_surfaces(&curve, &a, &Chart::default());
    assert_eq!(s.len(), 1);
    assert_eq!(curve.components[s[0].0].kind, ComponentKind::Plane);
    let plane = curve.components[s[0].0].plane.as_ref().unwrap();
    // the plane x = 0
    assert!(!plane[0].is_zero() && plane[1..].iter().all(|c| c.is_zero()));
    let (a, b) = (q("x^2+y^2-z^2-1"), q("x^2+y^2-z"));
    let curve = parameterize(&a, &b).unwrap();
    assert!(common_surfaces(&curve, &a, &Chart::default()).is_empty());
    assert_eq!(curve.classification.pencil, PencilKind::Regular);
    let s = q("x^2+y^2+z^2-1");
    let curve = parameterize(&s, &s).unwrap();
    let names: Vec<_> = common_surfaces(&curve, &s, &Chart::default())
        .into_iter()
        .map(|(_, c)| c.name)
        .collect();
    assert_eq!(names, [Some(AffineSurface::Sphere.key())]);
}
