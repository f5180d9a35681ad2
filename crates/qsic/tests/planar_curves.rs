//! Curves made of conics and lines from hand geometry: each configuration's components,
//! meeting points (exact coordinates) and connected real pieces are known by construction.

#[path = "common/geometry.rs"]
mod geometry;

use geometry::{is_point, topology};
use qsic::classify::{ComponentKind, SingularPointKind};
use qsic::io::parse_quadric;
use qsic::param::{parameterize, ComponentParam, Curve};

fn curve(a: &str, b: &str) -> Curve {
    let (qa, qb) = (parse_quadric(a).unwrap(), parse_quadric(b).unwrap());
    let c = parameterize(&qa, &qb).unwrap_or_else(|e| panic!("{a} ∩ {b}: {e}"));
    for comp in &c.components {
        if let Some(p) = &comp.param {
            assert!(
                p.lies_on(qa.matrix()) && p.lies_on(qb.matrix()),
                "{a} ∩ {b}"
            );
        }
    }
    c
}

/// `(kind, multiplicity, real)` of a component.
type Kind = (&'static str, u32, bool);

/// `(kind, multiplicity, real)` of every component, sorted.
fn components(c: &Curve) -> Vec<Kind> {
    let mut v: Vec<_> = c
        .components
        .iter()
        .map(|k| (k.kind.key(), k.multiplicity, k.real))
        .collect();
    v.sort();
    v
}

/// The singular points as `(kind, point)`, each matched to one expected point.
fn assert_singular(c: &Curve, want: &[(SingularPointKind, [i64; 4])]) {
    assert_eq!(
        c.singular_points.len(),
        want.len(),
        "{:?}",
        c.singular_points
    );
    for (kind, e) in want {
        assert!(
            c.singular_points
                .iter()
                .any(|s| s.kind == *kind && is_point(&s.point, *e)),
            "no {kind:?} at {e:?} in {:?}",
            c.singular_points
        );
    }
}

#[test]
fn two_spheres_meet_in_a_circle_and_the_imaginary_conic_at_infinity() {
    let c = curve("x^2+y^2+z^2-4", "(x-1)^2+y^2+z^2-4");
    assert_eq!(c.classification.case, Some(17));
    assert_eq!(components(&c), [("conic", 1, false), ("conic", 1, true)]);
    let real = c.components.iter().find(|k| k.real).unwrap();
    // the circle lies in the plane 2x = 1, i.e. 2x − w = 0
    assert!(is_point(real.plane.as_ref().unwrap(), [2, 0, 0, -1]));
    let Some(ComponentParam::Rational { degree: 2, .. }) = &real.param else {
        panic!("a rational conic")
    };
    assert!(c.singular_points.is_empty());
    assert_eq!(topology(&c), (1, 0));
}

#[test]
fn equal_cylinders_with_crossing_axes_are_two_ellipses_through_two_crunodes() {
    let c = curve("y^2+z^2-1", "x^2+z^2-1");
    assert_eq!(components(&c), [("conic", 1, true), ("conic", 1, true)]);
    assert_singular(
        &c,
        &[
            (SingularPointKind::Crunode, [0, 0, 1, 1]),
            (SingularPointKind::Crunode, [0, 0, -1, 1]),
        ],
    );
    // one connected real component made of the two ellipses
    assert_eq!(c.connected.len(), 1);
    assert_eq!(c.connected[0].len(), 2);
}

#[test]
fn a_cone_cut_by_two_parallel_planes_is_two_disjoint_circles() {
    let c = curve("x^2+y^2-z^2", "(z-1)*(z-2)");
    assert_eq!(c.classification.case, Some(14));
    assert_eq!(components(&c), [("conic", 1, true), ("conic", 1, true)]);
    let planes: Vec<_> = c
        .components
        .iter()
        .map(|k| k.plane.clone().unwrap())
        .collect();
    assert!(planes.iter().any(|p| is_point(p, [0, 0, 1, -1])));
    assert!(planes.iter().any(|p| is_point(p, [0, 0, 1, -2])));
    assert!(c.singular_points.is_empty());
    assert_eq!(topology(&c), (2, 0));
}

#[test]
fn tangent_spheres_touch_at_one_real_point() {
    // x = 1 holds the two conjugate lines y = ±iz through (1, 0, 0)
    let c = curve("x^2+y^2+z^2-1", "(x-2)^2+y^2+z^2-1");
    assert_eq!(
        components(&c),
        [("conic", 1, false), ("line", 1, false), ("line", 1, false)]
    );
    assert_singular(&c, &[(SingularPointKind::Acnode, [1, 0, 0, 1])]);
    assert_eq!(topology(&c), (0, 1));
}

#[test]
fn coaxial_cylinders_meet_in_two_conjugate_double_lines_at_infinity() {
    // both are singular at the axes' point at infinity: a singular pencil
    let c = curve("x^2+y^2-1", "x^2+y^2-4");
    assert_eq!(
        c.classification.complex_type(),
        Some("two_concurrent_double_lines")
    );
    assert_eq!(components(&c), [("line", 2, false), ("line", 2, false)]);
    // the only real point: the common direction of the axes
    assert_singular(&c, &[(SingularPointKind::Multiple, [0, 0, 1, 0])]);
    assert_eq!(topology(&c), (0, 1));
}

#[test]
fn a_cone_and_a_coaxial_cylinder_meet_in_two_circles() {
    let c = curve("x^2+y^2-z^2", "x^2+y^2-1");
    assert_eq!(components(&c), [("conic", 1, true), ("conic", 1, true)]);
    assert!(c.singular_points.is_empty());
    assert_eq!(topology(&c), (2, 0));
}

#[test]
fn four_concurrent_lines_meet_at_the_common_vertex() {
    // x² = y² = z²: the lines through the origin along (±1, ±1, 1)
    let c = curve("x^2-y^2", "y^2-z^2");
    assert_eq!(
        c.classification.complex_type(),
        Some("four_concurrent_lines")
    );
    assert_eq!(components(&c), [("line", 1, true); 4]);
    assert_singular(&c, &[(SingularPointKind::Multiple, [0, 0, 0, 1])]);
    assert_eq!(topology(&c), (1, 0));
}

#[test]
fn conics_in_irrational_planes_are_parameterized_over_their_field() {
    // planes x = ±√2·y; each conic y² + z² = w² has the rational point (0, 0, 1, 1) …
    let c = curve("x^2-y^2+z^2-w^2", "x^2-2*y^2");
    assert_eq!(c.classification.case, Some(13));
    assert_eq!(components(&c), [("conic", 1, true), ("conic", 1, true)]);
    assert_singular(
        &c,
        &[
            (SingularPointKind::Crunode, [0, 0, 1, 1]),
            (SingularPointKind::Crunode, [0, 0, -1, 1]),
        ],
    );
    assert_eq!(topology(&c), (1, 0));
    // … y² + z² = 3w² on the same planes has the point (1, √2, 1) over ℚ(√2) (3 = 1 + 2),
    // though no ratio of its diagonal form is a square there: its conics stay in ℚ(√2); and
    // y² + z² = 7w² has no point over ℚ(√2) at all (its quaternion algebra ramifies at the two
    // primes over 7, which split there): a quartic field
    let degree = |k: &qsic::param::Component| match &k.param {
        Some(ComponentParam::Rational { x, .. }) => x
            .iter()
            .flat_map(|p| p.coeffs())
            .filter_map(|v| v.field())
            .map(|f| f.modulus().degree().unwrap_or(0))
            .max()
            .unwrap_or(1),
        _ => 0,
    };
    for (n, want) in [(3, 2), (7, 4)] {
        let (a, b) = (format!("x^2-y^2+z^2-{n}*w^2"), "x^2-2*y^2");
        let c = curve(&a, b);
        assert_eq!(components(&c), [("conic", 1, true), ("conic", 1, true)]);
        assert!(c.components.iter().all(|k| degree(k) == want), "{n}");
        let (qa, qb) = (parse_quadric(&a).unwrap(), parse_quadric(b).unwrap());
        for k in &c.components {
            let p = k.param.as_ref().unwrap();
            assert!(p.lies_on(qa.matrix()) && p.lies_on(qb.matrix()), "{n}");
        }
    }
}

#[test]
fn a_double_line_and_two_lines_crossing_it() {
    // case 35: x·y = z·w and y² = w² — the double line y = w = 0 and y = ±w, x = ±z
    let c = curve("x*y-z*w", "y^2-w^2");
    assert_eq!(c.classification.case, Some(35));
    assert_eq!(
        components(&c),
        [("line", 1, true), ("line", 1, true), ("line", 2, true)]
    );
    assert_singular(
        &c,
        &[
            (SingularPointKind::Multiple, [1, 0, 1, 0]),
            (SingularPointKind::Multiple, [1, 0, -1, 0]),
        ],
    );
    assert_eq!(topology(&c), (1, 0));
}

#[test]
fn single_quadric_is_one_surface_component() {
    let c = curve("x^2+y^2+z^2-1", "2*x^2+2*y^2+2*z^2-2");
    assert_eq!(c.components.len(), 1);
    let k = &c.components[0];
    assert!(k.kind == ComponentKind::Quadric && k.multiplicity == 1 && k.real);
    assert!(k.param.is_none() && c.pieces.is_empty());
    let c = curve("x^2+y^2+z^2+1", "x^2+y^2+z^2+1");
    assert!(!c.components[0].real);
}

/// Singular pencils with multiple components (QI's examples): the multiplicities add up to
/// four, and a common plane absorbs the lines inside it.
#[test]
fn singular_pencils_count_multiple_lines_and_common_planes() {
    let cases: [(&str, &str, &[Kind]); 6] = [
        ("x*z+y^2", "y*z", &[("line", 1, true), ("line", 3, true)]),
        ("y^2", "x*y+z^2", &[("line", 4, true)]),
        ("x^2", "y^2", &[("line", 4, true)]),
        ("x*y", "x^2-y^2", &[("line", 4, true)]),
        ("x*y", "x*z", &[("line", 1, true), ("plane", 1, true)]),
        ("x*y", "y^2", &[("plane", 1, true)]),
    ];
    for (a, b, want) in cases {
        let c = curve(a, b);
        assert_eq!(components(&c), want, "{a} ∩ {b}");
        let lines = want.iter().filter(|k| k.0 == "line").count();
        assert_eq!(c.pieces.len(), lines, "{a} ∩ {b}");
    }
    // the plane x = 0 of x·y and x·z
    let c = curve("x*y", "x*z");
    let plane = c
        .components
        .iter()
        .find(|k| k.kind == ComponentKind::Plane)
        .unwrap();
    assert!(is_point(plane.plane.as_ref().unwrap(), [1, 0, 0, 0]));
}
