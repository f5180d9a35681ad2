//! Curves of the configurations CAD kernels get wrong (issue 8's list): Viviani's curve, a
//! cone whose apex lies on a cylinder, crossing and tangent cylinders, a sphere through a
//! cone's apex. Each answer — component kinds, the singular point's exact coordinates and
//! kind, the connected real pieces, and real points on both surfaces — is worked out by hand
//! in the test's comment.

#[path = "common/geometry.rs"]
mod geometry;

use geometry::{is_point, topology};
use qsic::classify::SingularPointKind;
use qsic::io::parse_quadric;
use qsic::param::parameterize;
use qsic::param::sample::{sample, SampleOptions};

struct Case {
    a: &'static str,
    b: &'static str,
    complex_type: &'static str,
    /// `(kind, exact point)` of every real singular point.
    singular: Vec<(SingularPointKind, [i64; 4])>,
    /// Connected real components: curves, isolated points.
    topology: (usize, usize),
}

fn cases() -> Vec<Case> {
    use SingularPointKind::{Acnode, Crunode};
    vec![
        // Viviani: the sphere of radius 2 and the cylinder of radius 1 through its centre
        // touch at (2, 0, 0), where the figure-eight crosses itself
        Case {
            a: "x^2+y^2+z^2-4",
            b: "(x-1)^2+y^2-1",
            complex_type: "nodal_quartic",
            singular: vec![(Crunode, [2, 0, 0, 1])],
            topology: (1, 0),
        },
        // a cone whose apex is on a cylinder: z² = 2x and x² + y² = 2x, a figure-eight through
        // the apex (0 ≤ x ≤ 2, the four sheets z = ±√(2x), y = ±√(2x − x²) meet at x = 0)
        Case {
            a: "x^2+y^2-z^2",
            b: "(x-1)^2+y^2-1",
            complex_type: "nodal_quartic",
            singular: vec![(Crunode, [0, 0, 0, 1])],
            topology: (1, 0),
        },
        // perpendicular cylinders of radii 2 and 1: the thin one goes through, two loops
        Case {
            a: "x^2+y^2-4",
            b: "x^2+z^2-1",
            complex_type: "smooth_quartic",
            singular: vec![],
            topology: (2, 0),
        },
        // equal perpendicular cylinders with axes 1/2 apart: one loop (the sign of x flips at
        // y = 1, the sign of z at y = −1/2)
        Case {
            a: "x^2+y^2-1",
            b: "(y-1/2)^2+z^2-1",
            complex_type: "smooth_quartic",
            singular: vec![],
            topology: (1, 0),
        },
        // perpendicular cylinders touching from outside at (0, 1, 0): y ≤ 1 on one, y ≥ 1 on
        // the other, an isolated point
        Case {
            a: "x^2+y^2-1",
            b: "(y-2)^2+z^2-1",
            complex_type: "nodal_quartic",
            singular: vec![(Acnode, [0, 1, 0, 1])],
            topology: (0, 1),
        },
        // a thin cylinder (axis x, radius 1, at y = 1) inside a thick one (axis z, radius 2),
        // touching it along y = 2: x = ±√(4 − y²) gives two loops crossing at (0, 2, 0)
        Case {
            a: "x^2+y^2-4",
            b: "(y-1)^2+z^2-1",
            complex_type: "nodal_quartic",
            singular: vec![(Crunode, [0, 2, 0, 1])],
            topology: (1, 0),
        },
        // a sphere through a cone's apex, centred on its axis: 2z² = 2z, so the circle z = 1
        // and the apex, where the conjugate lines x = ±iy of z = 0 meet (off the circle: they
        // meet it at its points at infinity (1, ±i, 0, 0) — case 24, a conic and a point)
        Case {
            a: "x^2+y^2-z^2",
            b: "x^2+y^2+(z-1)^2-1",
            complex_type: "conic_and_two_lines_not_crossing",
            singular: vec![(Acnode, [0, 0, 0, 1])],
            topology: (1, 1),
        },
    ]
}

#[test]
fn real_world_configurations_give_the_curves_worked_out_by_hand() {
    for case in cases() {
        let id = format!("{} ∩ {}", case.a, case.b);
        let (qa, qb) = (
            parse_quadric(case.a).unwrap(),
            parse_quadric(case.b).unwrap(),
        );
        let c = parameterize(&qa, &qb).unwrap_or_else(|e| panic!("{id}: {e}"));
        assert_eq!(
            c.classification.complex_type(),
            Some(case.complex_type),
            "{id}"
        );
        for comp in c.components.iter().filter_map(|k| k.param.as_ref()) {
            assert!(
                comp.lies_on(qa.matrix()) && comp.lies_on(qb.matrix()),
                "{id}"
            );
        }
        assert_eq!(
            c.singular_points.len(),
            case.singular.len(),
            "{id}: {:?}",
            c.singular_points
        );
        for (kind, e) in &case.singular {
            assert!(
                c.singular_points
                    .iter()
                    .any(|s| s.kind == *kind && is_point(&s.point, *e)),
                "{id}: no {kind:?} at {e:?} in {:?}",
                c.singular_points
            );
        }
        assert_eq!(topology(&c), case.topology, "{id}");
        // real points on every real piece, on both surfaces
        let s = sample(&c, &SampleOptions::default()).unwrap();
        assert_eq!(s.pieces.len(), c.pieces.len(), "{id}");
        for p in &s.pieces {
            for x in &p.points {
                for q in [&qa, &qb] {
                    let m = q.matrix();
                    let mut r = 0.0;
                    for i in 0..4 {
                        for j in 0..4 {
                            r += m[i][j].to_f64().value() * x[i] * x[j];
                        }
                    }
                    assert!(r.abs() < 1e-9, "{id}: residual {r}");
                }
            }
        }
    }
}

/// The polylines end at the singular points: Viviani's figure-eight is two loops from the node
/// back to it; each of two crossing ellipses is two arcs between the crunodes; a smooth
/// quartic is not cut.
#[test]
fn branches_end_at_the_singular_points() {
    let node = |p: &[f64; 4], e: [f64; 4]| {
        let n = e.iter().map(|v| v * v).sum::<f64>().sqrt();
        let d: f64 = (0..4).map(|i| p[i] * e[i] / n).sum();
        d.abs() > 1.0 - 1e-12
    };
    for (a, b, pieces, per_piece, nodes) in [
        (
            "x^2+y^2+z^2-4",
            "(x-1)^2+y^2-1",
            1,
            2,
            vec![[2.0, 0.0, 0.0, 1.0]],
        ),
        (
            "y^2+z^2-1",
            "x^2+z^2-1",
            2,
            2,
            vec![[0.0, 0.0, 1.0, 1.0], [0.0, 0.0, -1.0, 1.0]],
        ),
        ("x^2+y^2-4", "x^2+z^2-1", 2, 1, vec![]),
    ] {
        let (qa, qb) = (parse_quadric(a).unwrap(), parse_quadric(b).unwrap());
        let c = parameterize(&qa, &qb).unwrap();
        let s = sample(&c, &SampleOptions::default()).unwrap();
        assert_eq!(s.pieces.len(), pieces, "{a} ∩ {b}");
        for p in &s.pieces {
            let branches = p.branches();
            assert_eq!(branches.len(), per_piece, "{a} ∩ {b}: {:?}", p.breaks);
            let total: usize = branches.iter().map(|br| br.len() - 1).sum();
            assert_eq!(total, p.points.len() - 1, "{a} ∩ {b}: every segment once");
            for br in &branches {
                for end in [br[0], br[br.len() - 1]] {
                    assert!(
                        nodes.is_empty() || nodes.iter().any(|&e| node(&end, e)),
                        "{a} ∩ {b}: a branch ends at {end:?}"
                    );
                }
            }
        }
    }
}

/// The affine polylines end at the singular points too, and at infinity: Viviani's
/// figure-eight is two affine loops from the node back to it; the two-sheeted hyperboloid
/// `z² = x² + y² + 1` cut by the planes `x = ±y` is two hyperbolas crossing at `(0, 0, ±1)`, each
/// hyperbola four affine branches, each from a crossing point out to infinity.
#[test]
fn affine_branches_end_at_the_singular_points_and_at_infinity() {
    let at = |p: &[f64; 3], e: [f64; 3]| (0..3).all(|i| (p[i] - e[i]).abs() < 1e-9);
    for (a, b, pieces, per_piece, at_infinity, nodes) in [
        (
            "x^2+y^2+z^2-4",
            "(x-1)^2+y^2-1",
            1,
            2,
            0,
            vec![[2.0, 0.0, 0.0]],
        ),
        (
            "x^2-y^2",
            "x^2+y^2-z^2+1",
            2,
            4,
            2,
            vec![[0.0, 0.0, 1.0], [0.0, 0.0, -1.0]],
        ),
    ] {
        let (qa, qb) = (parse_quadric(a).unwrap(), parse_quadric(b).unwrap());
        let c = parameterize(&qa, &qb).unwrap();
        let s = sample(&c, &SampleOptions::default()).unwrap();
        assert_eq!(s.pieces.len(), pieces, "{a} ∩ {b}");
        for p in &s.pieces {
            let affine = &p.affine;
            assert_eq!(affine.points_at_infinity.len(), at_infinity, "{a} ∩ {b}");
            assert_eq!(affine.branches.len(), per_piece, "{a} ∩ {b}");
            for br in &affine.branches {
                assert!(br.len() > 1, "{a} ∩ {b}: a branch of one point");
                let ends = [br[0], br[br.len() - 1]];
                let on_node = ends
                    .iter()
                    .filter(|e| nodes.iter().any(|&n| at(e, n)))
                    .count();
                // a loop starts and ends at the node; a branch to infinity starts at one
                let expected = if at_infinity == 0 { 2 } else { 1 };
                assert_eq!(on_node, expected, "{a} ∩ {b}: ends {ends:?}");
                // no singular point inside a branch
                for x in &br[1..br.len() - 1] {
                    assert!(!nodes.iter().any(|&n| at(x, n)), "{a} ∩ {b}: {x:?} inside");
                }
            }
        }
    }
}
