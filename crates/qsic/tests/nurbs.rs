//! Exact NURBS of rational components: every curve evaluated in exact arithmetic at many
//! parameters lies on both quadrics (residual zero), knots and weights are well formed, and
//! the pieces are cut where the module docs say (singular points, the box). Approximations
//! of quartic branches: their bound checked at many points from the exact residual and
//! gradient, and every sampled point of the branch near them.

use qsic::io::parse_quadric;
use qsic::nurbs::{nurbs_of_curve, Accuracy, BoxBounds, Nurbs, NurbsCurve, NurbsOptions};
use qsic::param::sample::{sample, SampleOptions};
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
            tolerance: None,
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

/// Every approximated curve of `a ∩ b` checked against its bound independently of the
/// certificate: at 12 parameters per segment, exactly, `2|f| ≤ bound·|∇f|` and
/// `4N|f| < |∇f|²` (`N` the Frobenius norm of the quadratic part) for both quadrics, so the
/// surface is within the bound (the argument of the module docs, point by point).
fn approximated(a: &str, b: &str, options: &NurbsOptions) -> Nurbs {
    let (qa, qb) = (quadric(a), quadric(b));
    let curve = parameterize(&qa, &qb).unwrap_or_else(|e| panic!("{a} / {b}: {e}"));
    let n = nurbs_of_curve(&curve, &qa, &qb, options).unwrap_or_else(|e| panic!("{a} / {b}: {e}"));
    let num = |v: &RBig| Number::rational(v.clone());
    for (k, c) in n.curves.iter().enumerate() {
        assert!(c.is_valid(), "{a} / {b}: curve {k}");
        let Accuracy::Within(bound) = c.accuracy else {
            panic!("{a} / {b}: curve {k} is exact");
        };
        let b2 = num(&(RBig::try_from(bound).unwrap().pow(2)));
        for i in 0..c.segments() {
            for f in [0i64, 1, 2, 3, 5, 6, 7, 10, 11, 13, 17, 19] {
                let t = RBig::from(i) + RBig::from_parts_signed(f.into(), 19u8.into());
                let x = c.point_at(&t).expect("inside the knot range");
                assert!(x[3].is_one(), "weights 1");
                for q in [&qa, &qb] {
                    let m = q.matrix();
                    let f = residual(m, &x);
                    let mut g2 = Number::zero();
                    let mut n2 = Number::zero();
                    for row in m.iter().take(3) {
                        let mut g = Number::zero();
                        for (v, xj) in row.iter().zip(&x) {
                            g = g.add(&num(v).mul(xj));
                        }
                        g2 = g2.add(&g.mul(&g).mul(&num(&RBig::from(4))));
                        for v in row.iter().take(3) {
                            n2 = n2.add(&num(v).mul(&num(v)));
                        }
                    }
                    let f2 = f.mul(&f);
                    let within = b2.mul(&g2).sub(&f2.mul(&num(&RBig::from(4))));
                    let certified = g2.mul(&g2).sub(&n2.mul(&f2).mul(&num(&RBig::from(16))));
                    assert!(
                        within.sign() != Sign::Negative && certified.sign() == Sign::Positive,
                        "{a} / {b}: curve {k} at t = {t}: not within {bound:e}"
                    );
                }
            }
        }
    }
    n
}

/// The curve's float points, 64 a segment.
fn dense(c: &NurbsCurve) -> Vec<[f64; 3]> {
    let m = c.segments() as i64;
    (0..=64 * m)
        .map(|k| {
            affine(
                &c.point_at(&RBig::from_parts_signed(k.into(), 64u8.into()))
                    .unwrap(),
            )
        })
        .collect()
}

fn distance_to_polyline(p: &[f64; 3], line: &[[f64; 3]]) -> f64 {
    let d = |a: &[f64; 3], b: &[f64; 3]| -> f64 {
        (0..3).map(|i| (a[i] - b[i]).powi(2)).sum::<f64>().sqrt()
    };
    line.windows(2)
        .map(|w| {
            let (a, b) = (w[0], w[1]);
            let ab: [f64; 3] = std::array::from_fn(|i| b[i] - a[i]);
            let l2: f64 = ab.iter().map(|v| v * v).sum();
            let t = if l2 > 0.0 {
                ((0..3).map(|i| (p[i] - a[i]) * ab[i]).sum::<f64>() / l2).clamp(0.0, 1.0)
            } else {
                0.0
            };
            d(p, &std::array::from_fn(|i| a[i] + t * ab[i]))
        })
        .fold(f64::INFINITY, f64::min)
}

/// Every sampled point of `a ∩ b` inside the box lies within `within` of some curve: no
/// branch and no part of one is missing.
fn covers(a: &str, b: &str, n: &Nurbs, within: f64) {
    let curve = parameterize(&quadric(a), &quadric(b)).unwrap();
    let s = sample(&curve, &SampleOptions::default()).unwrap();
    let lines: Vec<Vec<[f64; 3]>> = n.curves.iter().map(dense).collect();
    let lo = n.bounds.lo.each_ref().map(|v| v.to_f64().value());
    let hi = n.bounds.hi.each_ref().map(|v| v.to_f64().value());
    for piece in &s.pieces {
        for p in piece.affine.branches.iter().flatten() {
            if (0..3).any(|i| p[i] < lo[i] || p[i] > hi[i]) {
                continue;
            }
            let d = lines
                .iter()
                .map(|l| distance_to_polyline(p, l))
                .fold(f64::INFINITY, f64::min);
            assert!(
                d <= within,
                "{a} / {b}: sampled {p:?} is {d:e} from every curve"
            );
        }
    }
}

/// Two cylinders of radii 1 and 0.8 crossing: a smooth quartic of two loops (Levin's form),
/// each one closed B-spline of degree 7 within 10⁻⁹ of its size.
#[test]
fn smooth_quartic_loops_are_approximated_within_their_bound() {
    let (a, b) = ("x^2+y^2-1", "x^2+z^2-16/25");
    let n = approximated(a, b, &NurbsOptions::default());
    assert_eq!(n.curves.len(), 2, "{:?}", n.left);
    assert!(n.left.is_empty(), "{:?}", n.left);
    for c in &n.curves {
        assert!(c.closed && c.clipped == [false, false] && c.degree == 7);
        assert!(c.ends.is_none());
        // a loop of size about 2.3: 10⁻⁹ of it
        assert!(c.accuracy.bound() <= 2.6e-9, "{:?}", c.accuracy);
        let [p, q] = exact_ends(c);
        assert_eq!(p, q);
    }
    covers(a, b, &n, 1e-5);
}

/// A tolerance of the user's is met, with more segments the tighter it is.
#[test]
fn the_tolerance_is_the_bound() {
    let (a, b) = ("x^2+y^2+z^2-4", "(x-3/2)^2+y^2-1");
    let mut segments = Vec::new();
    for tolerance in [1e-5, 1e-11] {
        let options = NurbsOptions {
            bounds: None,
            tolerance: Some(tolerance),
        };
        let n = approximated(a, b, &options);
        assert_eq!(n.curves.len(), 1, "{:?}", n.left);
        let c = &n.curves[0];
        assert!(c.accuracy.bound() <= tolerance, "{:?}", c.accuracy);
        assert!(c.accuracy.bound() > tolerance / 1e3, "{:?}", c.accuracy);
        segments.push(c.segments());
    }
    assert!(segments[0] < segments[1], "{segments:?}");
}

/// The same loop 10⁻⁵ across and 10⁵ from the origin: computed at its own scale.
#[test]
fn a_tiny_loop_far_away_is_approximated_at_its_own_scale() {
    let a = "(x-100000)^2+y^2+z^2-4/10000000000";
    let b = "(x-100000-3/200000)^2+y^2-1/10000000000";
    let n = approximated(a, b, &NurbsOptions::default());
    assert_eq!(n.curves.len(), 1, "{:?}", n.left);
    let bound = n.curves[0].accuracy.bound();
    assert!(bound > 0.0 && bound <= 1e-9 * 5e-5, "{bound:e}");
    covers(a, b, &n, 1e-10);
}

/// Two hyperbolic cylinders: four unbounded quartic branches, each clipped just outside the
/// box at both ends.
#[test]
fn unbounded_quartic_branches_are_clipped_just_outside_the_box() {
    let (a, b) = ("x^2-y^2-1", "y^2-z^2-1");
    let small = BoxBounds {
        lo: [-5, -5, -5].map(RBig::from),
        hi: [5, 5, 5].map(RBig::from),
    };
    let options = NurbsOptions {
        bounds: Some(small.clone()),
        tolerance: None,
    };
    let n = approximated(a, b, &options);
    assert_eq!(n.curves.len(), 4, "{:?}", n.left);
    for c in &n.curves {
        assert_eq!(c.clipped, [true, true]);
        assert!(!c.closed);
        for e in exact_ends(c) {
            assert!(outside(&e, &small), "{:?} inside", affine(&e));
        }
        for e in end_points(c) {
            assert!(excess(&e, &small) < 1e-4, "{e:?} far outside the box");
        }
    }
    covers(a, b, &n, 1e-5);
}

/// Two lines through a cone's apex in the plane `x = 0`, a face plane of the box: on the
/// closed box's boundary there, clipped by the other faces.
#[test]
fn lines_in_a_face_plane_are_clipped_by_the_other_faces() {
    let face = BoxBounds {
        lo: [0, -2, -2].map(RBig::from),
        hi: [2, 2, 2].map(RBig::from),
    };
    let options = NurbsOptions {
        bounds: Some(face.clone()),
        tolerance: None,
    };
    let n = checked("x^2+y^2-z^2", "x", &options);
    assert_eq!(n.curves.len(), 4, "{:?}", n.left);
    for c in &n.curves {
        for e in end_points(c) {
            assert!(e[0] == 0.0 && excess(&e, &face) < 1e-6, "{e:?}");
        }
    }
}

/// A double plane at infinity: the two lines of the curve lie in it, no point in ℝ³, and
/// each is named as such rather than failing.
#[test]
fn components_at_infinity_are_named() {
    let n = checked("w^2", "x^2-y^2+z*w", &NurbsOptions::default());
    assert!(n.curves.is_empty());
    assert_eq!(n.left.len(), 2, "{:?}", n.left);
    assert!(n
        .left
        .iter()
        .all(|l| l.reason.contains("plane at infinity")));
}

/// A crunode at irrational parameters (Tu et al.'s case 8 with `x` and `w` swapped: the
/// node at the origin, at `u = −1 ± √2`): the exact pieces are cut at rationals within 2⁻⁶⁰
/// of them, so every piece ends at the node, to 10⁻¹², and stays exact.
#[test]
fn a_node_at_irrational_parameters_is_cut_beside_them() {
    let (a, b) = ("w*y+z*x", "2*w*y+y^2-z^2+x^2");
    let n = checked(a, b, &NurbsOptions::default());
    assert_eq!(n.curves.len(), 4, "{:?}", n.left);
    assert!(
        n.left.iter().all(|l| l.reason.contains("within 2^-60")),
        "{:?}",
        n.left
    );
    assert_eq!(n.left.len(), 2);
    let curve = parameterize(&quadric(a), &quadric(b)).unwrap();
    let node = affine(&curve.singular_points[0].point);
    for c in &n.curves {
        let near = end_points(c)
            .iter()
            .map(|e| (0..3).map(|i| (e[i] - node[i]).abs()).fold(0.0, f64::max))
            .fold(f64::INFINITY, f64::min);
        assert!(
            near < 1e-12,
            "no end at the node {node:?}: {:?}",
            end_points(c)
        );
    }
}

/// A small box far out on one branch of two hyperbolic cylinders, beyond every sampled
/// point: the branch is followed out to it, and the one branch through it is clipped just
/// outside it; the other three miss it.
#[test]
fn a_small_far_box_is_found_on_the_branch_through_it() {
    let (a, b) = ("x^2-y^2-1", "y^2-z^2-1");
    let far = BoxBounds {
        lo: [100, 100, 100].map(RBig::from),
        hi: [101, 101, 101].map(RBig::from),
    };
    let options = NurbsOptions {
        bounds: Some(far.clone()),
        tolerance: None,
    };
    let n = approximated(a, b, &options);
    assert_eq!(n.curves.len(), 1, "{:?}", n.left);
    let c = &n.curves[0];
    assert_eq!(c.clipped, [true, true]);
    for e in exact_ends(c) {
        assert!(outside(&e, &far), "{:?} inside", affine(&e));
    }
    for e in end_points(c) {
        assert!(excess(&e, &far) < 1e-4, "{e:?} far outside the box");
    }
    // the point of the branch at y = 100.5 lies on it
    let y = 100.5f64;
    let on = [(1.0 + y * y).sqrt(), y, (y * y - 1.0).sqrt()];
    let d = distance_to_polyline(&on, &dense(c));
    assert!(d < 1e-6, "{on:?} is {d:e} from the curve");
}
