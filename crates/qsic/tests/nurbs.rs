//! Exact NURBS of rational components: every curve evaluated in exact arithmetic at many
//! parameters lies on both quadrics (residual zero), knots and weights are well formed, and
//! the pieces are cut where the module docs say (singular points, the box).

use qsic::io::parse_quadric;
use qsic::nurbs::{nurbs_of_curve, BoxBounds, Nurbs, NurbsCurve, NurbsOptions};
use qsic::param::{parameterize, Number, Point};
use qsic::Quadric;
use qsic_algebra::{RBig, Ring, Sign};

fn quadric(s: &str) -> Quadric {
    parse_quadric(s).unwrap_or_else(|e| panic!("{s}: {e}"))
}

/// `XᵀMX`, exactly.
fn residual(m: &[[RBig; 4]; 4], x: &Point) -> Number {
    let mut acc = Number::zero();
    for i in 0..4 {
        for j in 0..4 {
            if m[i][j] != RBig::ZERO {
                let c = Number::rational(m[i][j].clone());
                acc = acc.add(&c.mul(&x[i]).mul(&x[j]));
            }
        }
    }
    acc
}

/// The NURBS of `a ∩ b` with every exact curve checked on both quadrics at 12 parameters per
/// segment (knots, midpoints and irregular fractions).
fn checked(a: &str, b: &str, options: &NurbsOptions) -> Nurbs {
    let (qa, qb) = (quadric(a), quadric(b));
    let curve = parameterize(&qa, &qb).unwrap_or_else(|e| panic!("{a} / {b}: {e}"));
    let n = nurbs_of_curve(&curve, &qa, &qb, options).unwrap_or_else(|e| panic!("{a} / {b}: {e}"));
    for (k, c) in n.curves.iter().enumerate() {
        assert!(c.is_valid(), "{a} / {b}: curve {k} not valid: {c:?}");
        let m = c.segments();
        for i in 0..m {
            for f in [0i64, 1, 2, 3, 5, 6, 7, 10, 11, 13, 17, 19] {
                let t = RBig::from(i) + RBig::from_parts_signed(f.into(), 19u8.into());
                let x = c.point_at(&t).expect("inside the knot range");
                assert_eq!(x[3].sign(), Sign::Positive, "{a} / {b}: curve {k} at {t}");
                for (q, name) in [(&qa, a), (&qb, b)] {
                    assert!(
                        residual(q.matrix(), &x).is_zero(),
                        "{a} / {b}: curve {k} at t = {t} off {name}"
                    );
                }
            }
        }
    }
    n
}

fn affine(x: &Point) -> [f64; 3] {
    std::array::from_fn(|i| (x[i].to_f64()) / x[3].to_f64())
}

fn end_points(c: &NurbsCurve) -> [[f64; 3]; 2] {
    let m = RBig::from(c.segments());
    [
        affine(&c.point_at(&RBig::ZERO).unwrap()),
        affine(&c.point_at(&m).unwrap()),
    ]
}

/// How far `p` is outside the box (0 inside).
fn excess(p: &[f64; 3], b: &BoxBounds) -> f64 {
    (0..3)
        .map(|i| (b.lo[i].to_f64().value() - p[i]).max(p[i] - b.hi[i].to_f64().value()))
        .fold(0.0, f64::max)
}

/// Whether the homogeneous point `x` (w > 0) is outside the box, decided exactly.
fn outside(x: &Point, b: &BoxBounds) -> bool {
    (0..3).any(|i| {
        let below = x[i].sub(&x[3].mul(&Number::rational(b.lo[i].clone())));
        let above = x[i].sub(&x[3].mul(&Number::rational(b.hi[i].clone())));
        below.sign() == Sign::Negative || above.sign() == Sign::Positive
    })
}

fn exact_ends(c: &NurbsCurve) -> [Point; 2] {
    let m = RBig::from(c.segments());
    [c.point_at(&RBig::ZERO).unwrap(), c.point_at(&m).unwrap()]
}

/// Viviani's curve (a nodal quartic over ℚ): two exact quartic loops from the node back to it,
/// every control point rational.
#[test]
fn viviani_is_two_exact_quartic_loops_through_the_node() {
    let n = checked("x^2+y^2+z^2-4", "x^2+y^2-2*x", &NurbsOptions::default());
    assert_eq!(n.curves.len(), 2, "{:?}", n.left);
    assert!(n.left.is_empty(), "{:?}", n.left);
    for c in &n.curves {
        assert_eq!(c.degree, 4);
        for p in &c.poles {
            assert!(p
                .iter()
                .all(|v| v.field().is_none() || v.numerator().len() <= 1));
        }
        for e in end_points(c) {
            for (v, want) in e.iter().zip([2.0, 0.0, 0.0]) {
                assert!((v - want).abs() < 1e-12, "{e:?}");
            }
        }
    }
}

/// A conic without points at infinity (a cylinder cut obliquely): one closed rational
/// quadratic.
#[test]
fn an_ellipse_is_one_closed_rational_quadratic() {
    let n = checked("x^2+y^2-1", "z-x", &NurbsOptions::default());
    assert_eq!(n.curves.len(), 1, "{:?}", n.left);
    let c = &n.curves[0];
    assert_eq!(c.degree, 2);
    assert!(c.closed);
    let [p, q] = end_points(c);
    assert_eq!(p, q);
}

/// A circle over ℚ(√3) (a sphere and a plane): exact in the field.
#[test]
fn a_circle_over_a_quadratic_field_is_exact() {
    let n = checked("x^2+y^2+z^2-1", "z-1/2", &NurbsOptions::default());
    assert_eq!(n.curves.len(), 1);
    assert_eq!(n.curves[0].degree, 2);
}

/// Steinmetz: two cylinders crossing, two ellipses meeting at two points: four arcs between
/// the meeting points.
#[test]
fn steinmetz_ellipses_are_cut_at_their_meeting_points() {
    let n = checked("x^2+y^2-1", "x^2+z^2-1", &NurbsOptions::default());
    assert_eq!(n.curves.len(), 4, "{:?}", n.left);
    for c in &n.curves {
        assert_eq!(c.degree, 2);
        for e in end_points(c) {
            assert!(
                (e[0].abs() - 1.0).abs() < 1e-12 && e[1].abs() < 1e-12,
                "{e:?}"
            );
        }
    }
}

/// A cone cut by a plane parallel to its axis: a hyperbola, both branches clipped to the
/// box; the ends just outside it, the pieces inside between.
#[test]
fn hyperbola_branches_are_clipped_just_outside_the_box() {
    let n = checked("x^2+y^2-z^2", "y-1", &NurbsOptions::default());
    assert_eq!(n.curves.len(), 2, "{:?}", n.left);
    for c in &n.curves {
        assert_eq!(c.clipped, [true, true]);
        for e in exact_ends(c) {
            assert!(
                outside(&e, &n.bounds),
                "{:?} inside {:?}",
                affine(&e),
                n.bounds
            );
        }
        // the cut is just outside: within 2⁻³⁰ of the crossing in u, close in space
        for e in end_points(c) {
            assert!(
                excess(&e, &n.bounds) < 1e-6,
                "{e:?} far outside {:?}",
                n.bounds
            );
        }
    }
    // a smaller box of the user's: the ends move in, just outside it
    let small = BoxBounds {
        lo: [-2, -2, -2].map(RBig::from),
        hi: [2, 2, 2].map(RBig::from),
    };
    let n = checked(
        "x^2+y^2-z^2",
        "y-1",
        &NurbsOptions {
            bounds: Some(small.clone()),
        },
    );
    assert_eq!(n.curves.len(), 2);
    for c in &n.curves {
        for x in exact_ends(c) {
            assert!(outside(&x, &small), "{:?}", affine(&x));
        }
        for e in end_points(c) {
            assert!(excess(&e, &small) < 1e-6, "{e:?} far outside the box");
        }
    }
}

/// A parabola (one point at infinity, a double root of w): one clipped piece.
#[test]
fn a_parabola_is_one_clipped_piece() {
    let n = checked("x^2+y^2-z^2", "z-x-1", &NurbsOptions::default());
    assert_eq!(n.curves.len(), 1, "{:?}", n.left);
    assert_eq!(n.curves[0].clipped, [true, true]);
}

/// A plane through the apex of a cone: two lines through the apex, each cut there and
/// clipped at both ends of ℝ³: four half-lines.
#[test]
fn lines_through_an_apex_are_cut_at_it() {
    let n = checked("x^2+y^2-z^2", "x", &NurbsOptions::default());
    assert_eq!(n.curves.len(), 4, "{:?}", n.left);
    for c in &n.curves {
        assert_eq!(c.degree, 1);
        let [p, q] = end_points(c);
        let at_apex = |e: &[f64; 3]| e.iter().all(|v| v.abs() < 1e-12);
        assert!(at_apex(&p) != at_apex(&q), "{p:?} {q:?}");
    }
}

/// A sphere and a coaxial cylinder: two circles.
#[test]
fn coaxial_sphere_and_cylinder_give_two_circles() {
    let n = checked("x^2+y^2+z^2-4", "x^2+y^2-1", &NurbsOptions::default());
    assert_eq!(n.curves.len(), 2, "{:?}", n.left);
}

/// A quartic with √s(u) is reported as left out, not dropped silently.
#[test]
fn levin_branches_are_reported_left_out() {
    let n = checked("x^2+y^2+z^2-4", "x^2+y^2-2*x+1/2", &NurbsOptions::default());
    assert!(n.curves.is_empty());
    assert!(!n.left.is_empty());
}
