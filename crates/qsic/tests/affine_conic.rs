//! The affine data of conic components ([`qsic::affine::affine_conic`]): plane sections of
//! natural quadrics whose centres, radii and axes are known by hand; Euclidean motions
//! (Pythagorean rotations and a translation) that must move centres and axes and keep
//! lengths; and on every corpus line, in two charts, checks by routes other than the one
//! used: the type against the curve graph's name ([`affine_curve`]), the centre as the pole of
//! the plane's line at infinity for the quadric that cuts the plane, the conic symmetric
//! about its centre, semi-axes as the stationary distances from the centre, the parabola's
//! vertex, axis and focal length by the focal property.

// Index loops read as the matrix formulas they implement.
#![allow(clippy::needless_range_loop)]

mod common;

use common::read_form;
use qsic::affine::{affine_conic, affine_curve, param_conic, AffineConic, Chart, ConicShape};
use qsic::classify::ComponentKind;
use qsic::io::parse_quadric;
use qsic::param::{parameterize, ComponentParam, Number, NumberPoly, Point};
use qsic::Quadric;
use qsic_algebra::{Field, Poly, RBig, Ring, Sign};
use serde_json::Value;

fn r(n: i64, d: i64) -> Number {
    Number::rational(RBig::from_parts_signed(n.into(), d.unsigned_abs().into()))
}

fn v3(a: [(i64, i64); 3]) -> [Number; 3] {
    a.map(|(n, d)| r(n, d))
}

fn dot(a: &[Number; 3], b: &[Number; 3]) -> Number {
    (0..3).fold(Number::zero(), |acc, i| acc.add(&a[i].mul(&b[i])))
}

/// Exactly when the coordinates share a field, else to 1e-12 (conics of a moved pair may
/// live in another field).
fn parallel(a: &[Number; 3], b: &[Number; 3]) -> bool {
    if compatible(a, b) {
        return (0..3).all(|i| (0..3).all(|j| a[i].mul(&b[j]) == a[j].mul(&b[i])));
    }
    let (x, y) = (
        a.each_ref().map(Number::to_f64),
        b.each_ref().map(Number::to_f64),
    );
    let n = |v: &[f64; 3]| v.iter().map(|c| c * c).sum::<f64>().sqrt();
    let cos = (0..3).map(|i| x[i] * y[i]).sum::<f64>() / (n(&x) * n(&y));
    (cos.abs() - 1.0).abs() < 1e-12
}

fn compatible(a: &[Number; 3], b: &[Number; 3]) -> bool {
    a.iter().all(|x| b.iter().all(|y| x.compatible_with(y)))
}

/// Equal points, exactly when they share a field, else to 1e-12.
fn same_point(a: &[Number; 3], b: &[Number; 3]) -> bool {
    if compatible(a, b) {
        return a == b;
    }
    (0..3).all(|i| (a[i].to_f64() - b[i].to_f64()).abs() <= 1e-12 * (1.0 + a[i].to_f64().abs()))
}

/// The real conics of `a ∩ b` in the chart, with their components' parameterizations.
fn conics(a: &Quadric, b: &Quadric, chart: &Chart) -> Vec<(AffineConic, ComponentParam)> {
    let curve = parameterize(a, b).unwrap();
    curve
        .components
        .iter()
        .filter_map(|c| {
            affine_conic(c, chart)
                .unwrap()
                .map(|k| (k, c.param.clone().unwrap()))
        })
        .collect()
}

fn conics_of(a: &str, b: &str) -> Vec<AffineConic> {
    let (a, b) = (parse_quadric(a).unwrap(), parse_quadric(b).unwrap());
    conics(&a, &b, &Chart::default())
        .into_iter()
        .map(|c| c.0)
        .collect()
}

/// The conic with the given centre (or vertex) among `found`.
fn at<'a>(found: &'a [AffineConic], point: &[Number; 3]) -> &'a AffineConic {
    found
        .iter()
        .find(|c| match &c.shape {
            ConicShape::Circle { centre, .. }
            | ConicShape::Ellipse { centre, .. }
            | ConicShape::Hyperbola { centre, .. } => centre == point,
            ConicShape::Parabola { vertex, .. } => vertex == point,
            ConicShape::AtInfinity => false,
        })
        .unwrap_or_else(|| panic!("no conic at {point:?} among {found:?}"))
}

fn exact(d: &qsic::affine::Direction) -> &[Number; 3] {
    d.exact.as_ref().expect("an exact direction")
}

#[test]
fn a_sphere_cut_by_planes_gives_circles_of_known_centre_and_radius() {
    // x² + y² + z² = 25: z = 3 (r² 16), z = −4 (r² 9); x + y + z = 3 at distance √3 (r² 22,
    // centre (1, 1, 1)); x = y through the centre (r² 25)
    // (planes, [(centre, radius², normal)])
    type Vector = [(i64, i64); 3];
    type Circle = (Vector, i64, Vector);
    let cases: [(&str, [Circle; 2]); 2] = [
        (
            "(z-3)*(z+4)",
            [
                ([(0, 1), (0, 1), (3, 1)], 16, [(0, 1), (0, 1), (1, 1)]),
                ([(0, 1), (0, 1), (-4, 1)], 9, [(0, 1), (0, 1), (1, 1)]),
            ],
        ),
        (
            "(x+y+z-3)*(x-y)",
            [
                ([(1, 1), (1, 1), (1, 1)], 22, [(1, 1), (1, 1), (1, 1)]),
                ([(0, 1), (0, 1), (0, 1)], 25, [(1, 1), (-1, 1), (0, 1)]),
            ],
        ),
    ];
    for (planes, want) in cases {
        let found = conics_of("x^2+y^2+z^2-25", planes);
        assert_eq!(found.len(), 2, "{planes}");
        for (centre, r2, normal) in want {
            let c = at(&found, &v3(centre));
            let ConicShape::Circle { radius2, .. } = &c.shape else {
                panic!("{planes}: {:?}", c.shape)
            };
            assert_eq!(radius2, &r(r2, 1), "{planes}");
            assert_eq!(c.normal.as_ref().unwrap(), &v3(normal), "{planes}");
        }
    }
    // two unit spheres with centres 1 apart meet in the circle x = 1/2, r² = 3/4 (the other
    // component, the imaginary circle at infinity, is not real)
    let found = conics_of("x^2+y^2+z^2-1", "(x-1)^2+y^2+z^2-1");
    assert_eq!(found.len(), 1);
    let ConicShape::Circle { centre, radius2 } = &found[0].shape else {
        panic!("{:?}", found[0].shape)
    };
    assert_eq!((centre, radius2), (&v3([(1, 2), (0, 1), (0, 1)]), &r(3, 4)));
}

#[test]
fn an_oblique_cylinder_section_is_an_ellipse_with_semi_axes_r_and_r_over_cos() {
    // x² + y² = 4 cut by 4z = 3x (+ 8): tan θ = 3/4, cos θ = 4/5: semi-axes 2 and 5/2, the
    // major one along (4, 0, 3), the minor along y
    let found = conics_of("x^2+y^2-4", "(4*z-3*x)*(4*z-3*x-8)");
    assert_eq!(found.len(), 2);
    for centre in [[(0, 1), (0, 1), (0, 1)], [(0, 1), (0, 1), (2, 1)]] {
        let c = at(&found, &v3(centre));
        let ConicShape::Ellipse { major, minor, .. } = &c.shape else {
            panic!("{:?}", c.shape)
        };
        assert_eq!(major.semi_axis2.as_number(), Some(&r(25, 4)));
        assert_eq!(minor.semi_axis2.as_number(), Some(&r(4, 1)));
        assert!(parallel(
            exact(&major.direction),
            &v3([(4, 1), (0, 1), (3, 1)])
        ));
        assert!(parallel(
            exact(&minor.direction),
            &v3([(0, 1), (1, 1), (0, 1)])
        ));
        let u = major.direction.unit;
        assert!((u[0].abs() - 0.8).abs() < 1e-12 && (u[2].abs() - 0.6).abs() < 1e-12);
        assert!(parallel(
            c.normal.as_ref().unwrap(),
            &v3([(-3, 1), (0, 1), (4, 1)])
        ));
    }
    // x² + y² = 1 cut by z = x + y: semi-axes 1 and √3 (|∇| = √2, sec θ = √3)
    let found = conics_of("x^2+y^2-1", "(z-x-y)*(z-x-y-1)");
    for c in &found {
        let ConicShape::Ellipse { major, minor, .. } = &c.shape else {
            panic!("{:?}", c.shape)
        };
        assert_eq!(major.semi_axis2.as_number(), Some(&r(3, 1)));
        assert_eq!(minor.semi_axis2.as_number(), Some(&r(1, 1)));
        assert!(parallel(
            exact(&major.direction),
            &v3([(1, 1), (1, 1), (2, 1)])
        ));
        assert!(parallel(
            exact(&minor.direction),
            &v3([(1, 1), (-1, 1), (0, 1)])
        ));
    }
}

#[test]
fn a_cone_cut_by_planes_gives_every_conic_type() {
    // x² + y² = z²: z = 1 a unit circle; x = 1 the hyperbola z² − y² = 1 (a² = b² = 1,
    // transverse along z)
    let found = conics_of("x^2+y^2-z^2", "(z-1)*(x-1)");
    let c = at(&found, &v3([(0, 1), (0, 1), (1, 1)]));
    assert!(matches!(&c.shape, ConicShape::Circle { radius2, .. } if *radius2 == r(1, 1)));
    let h = at(&found, &v3([(1, 1), (0, 1), (0, 1)]));
    let ConicShape::Hyperbola {
        transverse,
        conjugate,
        ..
    } = &h.shape
    else {
        panic!("{:?}", h.shape)
    };
    assert_eq!(transverse.semi_axis2.as_number(), Some(&r(1, 1)));
    assert_eq!(conjugate.semi_axis2.as_number(), Some(&r(1, 1)));
    assert!(parallel(
        exact(&transverse.direction),
        &v3([(0, 1), (0, 1), (1, 1)])
    ));
    assert!(parallel(
        exact(&conjugate.direction),
        &v3([(0, 1), (1, 1), (0, 1)])
    ));
    // z = x + 1: y² = 2x + 1, vertex (−1/2, 0, 1/2), opening along +(1, 0, 1), focal
    // length √2/4; z = x/2 + 1: 3/4(x − 2/3)² + y² = 4/3, centre (2/3, 0, 4/3), semi-axes²
    // 4/3 along y and (4/3)²·(5/4) = 20/9 along (2, 0, 1)
    let found = conics_of("x^2+y^2-z^2", "(z-x-1)*(2*z-x-2)");
    let p = at(&found, &v3([(-1, 2), (0, 1), (1, 2)]));
    let ConicShape::Parabola {
        axis,
        focal_length2,
        ..
    } = &p.shape
    else {
        panic!("{:?}", p.shape)
    };
    assert_eq!(focal_length2, &r(1, 8));
    assert!(parallel(exact(axis), &v3([(1, 1), (0, 1), (1, 1)])));
    assert_eq!(exact(axis)[0].sign(), Sign::Positive);
    let e = at(&found, &v3([(2, 3), (0, 1), (4, 3)]));
    let ConicShape::Ellipse { major, minor, .. } = &e.shape else {
        panic!("{:?}", e.shape)
    };
    assert_eq!(major.semi_axis2.as_number(), Some(&r(20, 9)));
    assert_eq!(minor.semi_axis2.as_number(), Some(&r(4, 3)));
    assert!(parallel(
        exact(&major.direction),
        &v3([(2, 1), (0, 1), (1, 1)])
    ));
}

/// `p ↦ R p + t` on quadrics: `M′ = T⁻ᵀ M T⁻¹`, `T = [[R, t], [0, 1]]`, `T⁻¹ = [[Rᵀ, −Rᵀt], [0, 1]]`.
fn moved(q: &Quadric, rot: &[[RBig; 3]; 3], t: &[RBig; 3]) -> Quadric {
    let mut inv: [[RBig; 4]; 4] = Default::default();
    for i in 0..3 {
        for j in 0..3 {
            inv[i][j] = rot[j][i].clone();
        }
        inv[i][3] = -(0..3).fold(RBig::ZERO, |acc, k| acc + &rot[k][i] * &t[k]);
    }
    inv[3][3] = RBig::ONE;
    let m = q.matrix();
    let out: [[RBig; 4]; 4] = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let mut acc = RBig::ZERO;
            for k in 0..4 {
                for l in 0..4 {
                    acc += &inv[k][i] * &m[k][l] * &inv[l][j];
                }
            }
            acc
        })
    });
    Quadric::from_matrix(out).unwrap()
}

#[test]
fn a_euclidean_motion_moves_centres_and_axes_and_keeps_lengths() {
    // R = R_x(5, 12, 13) · R_z(3, 4, 5), t = (1, −2, 3/2)
    let q = |n: i64, d: i64| RBig::from_parts_signed(n.into(), d.unsigned_abs().into());
    let rz = [
        [q(3, 5), q(-4, 5), q(0, 1)],
        [q(4, 5), q(3, 5), q(0, 1)],
        [q(0, 1), q(0, 1), q(1, 1)],
    ];
    let rx = [
        [q(1, 1), q(0, 1), q(0, 1)],
        [q(0, 1), q(5, 13), q(-12, 13)],
        [q(0, 1), q(12, 13), q(5, 13)],
    ];
    let rot: [[RBig; 3]; 3] = std::array::from_fn(|i| {
        std::array::from_fn(|j| (0..3).fold(RBig::ZERO, |acc, k| acc + &rx[i][k] * &rz[k][j]))
    });
    let t = [q(1, 1), q(-2, 1), q(3, 2)];
    let apply = |p: &[Number; 3], shift: bool| -> [Number; 3] {
        std::array::from_fn(|i| {
            let s = if shift {
                Number::rational(t[i].clone())
            } else {
                Number::zero()
            };
            (0..3).fold(s, |acc, k| {
                acc.add(&Number::rational(rot[i][k].clone()).mul(&p[k]))
            })
        })
    };
    let pairs = [
        ("x^2+y^2-4", "(4*z-3*x)*(4*z-3*x-8)"),
        ("x^2+y^2-z^2", "(z-1)*(x-1)"),
        ("x^2+y^2-z^2", "(z-x-1)*(2*z-x-2)"),
        ("x^2+y^2+z^2-25", "(x+y+z-3)*(x-y)"),
        ("x^2+2*y^2-2", "(z-x-y)*(z+2*x-1)"),
    ];
    for (sa, sb) in pairs {
        let (a, b) = (parse_quadric(sa).unwrap(), parse_quadric(sb).unwrap());
        let chart = Chart::default();
        let before = conics(&a, &b, &chart);
        let after = conics(&moved(&a, &rot, &t), &moved(&b, &rot, &t), &chart);
        assert_eq!(before.len(), after.len(), "{sa}, {sb}");
        for (c, _) in &before {
            let normal = apply(c.normal.as_ref().unwrap(), false);
            let (point, lengths, directions) = match &c.shape {
                ConicShape::Circle { centre, radius2 } => (centre, vec![radius2.to_f64()], vec![]),
                ConicShape::Ellipse {
                    centre,
                    major: a,
                    minor: b,
                }
                | ConicShape::Hyperbola {
                    centre,
                    transverse: a,
                    conjugate: b,
                } => (
                    centre,
                    vec![a.semi_axis2.to_f64(), b.semi_axis2.to_f64()],
                    vec![a.direction.unit, b.direction.unit],
                ),
                ConicShape::Parabola {
                    vertex,
                    axis,
                    focal_length2,
                } => (vertex, vec![focal_length2.to_f64()], vec![axis.unit]),
                ConicShape::AtInfinity => unreachable!(),
            };
            let point = apply(point, true);
            let d = after
                .iter()
                .map(|(k, _)| k)
                .find(|k| match &k.shape {
                    ConicShape::Circle { centre, .. }
                    | ConicShape::Ellipse { centre, .. }
                    | ConicShape::Hyperbola { centre, .. } => same_point(centre, &point),
                    ConicShape::Parabola { vertex, .. } => same_point(vertex, &point),
                    ConicShape::AtInfinity => false,
                })
                .unwrap_or_else(|| panic!("{sa}, {sb}: the moved centre {point:?}"));
            assert_eq!(d.shape.key(), c.shape.key(), "{sa}, {sb}");
            assert!(parallel(d.normal.as_ref().unwrap(), &normal), "{sa}, {sb}");
            let (lengths2, directions2) = match &d.shape {
                ConicShape::Circle { radius2, .. } => (vec![radius2.to_f64()], vec![]),
                ConicShape::Ellipse {
                    major: a, minor: b, ..
                }
                | ConicShape::Hyperbola {
                    transverse: a,
                    conjugate: b,
                    ..
                } => (
                    vec![a.semi_axis2.to_f64(), b.semi_axis2.to_f64()],
                    vec![a.direction.unit, b.direction.unit],
                ),
                ConicShape::Parabola {
                    axis,
                    focal_length2,
                    ..
                } => (vec![focal_length2.to_f64()], vec![axis.unit]),
                ConicShape::AtInfinity => unreachable!(),
            };
            for (x, y) in lengths.iter().zip(&lengths2) {
                assert!((x - y).abs() <= 1e-12 * x.abs().max(1.0), "{sa}, {sb}");
            }
            let rf: [[f64; 3]; 3] = rot
                .each_ref()
                .map(|row| row.each_ref().map(|v| v.to_f64().value()));
            for (u, v) in directions.iter().zip(&directions2) {
                let ru: [f64; 3] =
                    std::array::from_fn(|i| (0..3).map(|k| rf[i][k] * u[k]).sum::<f64>());
                let cos: f64 = (0..3).map(|i| ru[i] * v[i]).sum();
                assert!(
                    (cos.abs() - 1.0).abs() < 1e-9,
                    "{sa}, {sb}: {ru:?} vs {v:?}"
                );
            }
            // a parabola's axis keeps its orientation
            if let (ConicShape::Parabola { axis: x, .. }, ConicShape::Parabola { axis: y, .. }) =
                (&c.shape, &d.shape)
            {
                let (x, y) = (apply(exact(x), false), exact(y));
                let cos: f64 = (0..3).map(|i| x[i].to_f64() * y[i].to_f64()).sum();
                assert!(cos > 0.0, "{sa}, {sb}: the parabola's opening");
            }
        }
    }
}

/// `XᵀMX` for a point in chart coordinates.
fn form_at(m: &[[RBig; 4]; 4], p: &Point) -> Number {
    let mut acc = Number::zero();
    for i in 0..4 {
        for j in 0..4 {
            if m[i][j] != RBig::ZERO {
                acc = acc.add(&p[i].mul(&p[j]).mul(&Number::rational(m[i][j].clone())));
            }
        }
    }
    acc
}

fn bilinear(m: &[[RBig; 4]; 4], p: &Point, q: &Point) -> Number {
    let mut acc = Number::zero();
    for i in 0..4 {
        for j in 0..4 {
            if m[i][j] != RBig::ZERO {
                acc = acc.add(&p[i].mul(&q[j]).mul(&Number::rational(m[i][j].clone())));
            }
        }
    }
    acc
}

fn affine(p: &[Number; 3]) -> Point {
    [p[0].clone(), p[1].clone(), p[2].clone(), Number::one()]
}

/// Checks one conic by routes independent of [`affine_conic`]'s (see the module docs).
fn check_conic(
    id: &str,
    conic: &AffineConic,
    param: &ComponentParam,
    mats: &[[[RBig; 4]; 4]; 2],
    chart: &Chart,
) -> usize {
    let mut exact_checks = 0;
    let ComponentParam::Rational { x, .. } = param else {
        panic!("{id}: a conic that is not rational")
    };
    let xc: [NumberPoly; 4] = std::array::from_fn(|i| {
        let coeffs: Vec<Number> = (0..3)
            .map(|k| {
                let p: Point = std::array::from_fn(|j| x[j].coeff(k));
                chart.to_chart_number(&p)[i].clone()
            })
            .collect();
        Poly::new(coeffs)
    });
    let point_at = |u: &Number| -> Point { std::array::from_fn(|i| xc[i].eval(u)) };
    let finite_points: Vec<[Number; 3]> = [(0, 1), (1, 1), (-1, 1), (2, 1), (1, 2), (-3, 2)]
        .iter()
        .filter_map(|&(n, d)| {
            let p = point_at(&r(n, d));
            let w = p[3].inv()?;
            Some(std::array::from_fn(|i| p[i].mul(&w)))
        })
        .collect();
    let normal = conic.normal.as_ref().unwrap();
    // the quadric that cuts the plane in this conic (not containing it)
    let directions: Vec<Point> = (0..3)
        .map(|i| {
            let mut e = [Number::zero(), Number::zero(), Number::zero()];
            e[i] = Number::one();
            let n = normal;
            let c = [
                n[1].mul(&e[2]).sub(&n[2].mul(&e[1])),
                n[2].mul(&e[0]).sub(&n[0].mul(&e[2])),
                n[0].mul(&e[1]).sub(&n[1].mul(&e[0])),
            ];
            [c[0].clone(), c[1].clone(), c[2].clone(), Number::zero()]
        })
        .collect();
    let p0 = affine(&finite_points[0]);
    let cuts = |m: &[[RBig; 4]; 4]| {
        // restricted to the plane through p0 spanned by the directions: not identically 0
        let mut span = directions.clone();
        span.push(p0.clone());
        span.iter()
            .any(|a| span.iter().any(|b| !bilinear(m, a, b).is_zero()))
    };
    let m = mats
        .iter()
        .find(|m| cuts(m))
        .unwrap_or_else(|| panic!("{id}: both quadrics contain the plane"));
    for p in &finite_points {
        assert!(
            dot(normal, p)
                .sub(&dot(normal, &finite_points[0]))
                .is_zero(),
            "{id}: normal"
        );
    }
    match &conic.shape {
        ConicShape::AtInfinity => panic!("{id}: finite points on a conic at infinity"),
        ConicShape::Parabola {
            vertex,
            axis,
            focal_length2,
        } => {
            let d = exact(axis);
            let dd = dot(d, d);
            for mm in mats {
                assert!(form_at(mm, &affine(vertex)).is_zero(), "{id}: vertex");
                let inf = [d[0].clone(), d[1].clone(), d[2].clone(), Number::zero()];
                assert!(form_at(mm, &inf).is_zero(), "{id}: axis at infinity");
            }
            // focal property: (|p − V|² − s²)² = 16 f² s², s = (p − V)·d/|d| ≥ 0
            for p in &finite_points {
                let pv: [Number; 3] = std::array::from_fn(|i| p[i].sub(&vertex[i]));
                let s2 = dot(&pv, d).mul(&dot(&pv, d)).div(&dd).unwrap();
                let t2 = dot(&pv, &pv).sub(&s2);
                let lhs = t2.mul(&t2);
                let rhs = r(16, 1).mul(focal_length2).mul(&s2);
                assert!(lhs == rhs, "{id}: focal length");
                assert!(dot(&pv, d).sign() != Sign::Negative, "{id}: opening");
            }
        }
        ConicShape::Circle { centre, .. }
        | ConicShape::Ellipse { centre, .. }
        | ConicShape::Hyperbola { centre, .. } => {
            let c = affine(centre);
            assert!(
                dot(normal, centre) == dot(normal, &finite_points[0]),
                "{id}"
            );
            // the pole of the line at infinity: conjugate to every direction of the plane
            for dir in &directions {
                assert!(bilinear(m, &c, dir).is_zero(), "{id}: pole");
            }
            // symmetric about the centre
            for p in &finite_points {
                let q: [Number; 3] = std::array::from_fn(|i| r(2, 1).mul(&centre[i]).sub(&p[i]));
                for mm in mats {
                    assert!(form_at(mm, &affine(&q)).is_zero(), "{id}: symmetry");
                }
            }
            // semi-axes: stationary values of |p − c|², D(u) = |X − cW|² − μW² has a
            // multiple root (exact where μ lies in a field with the curve's)
            let diff: [NumberPoly; 3] = std::array::from_fn(|i| &xc[i] - &xc[3].scale(&centre[i]));
            let dist2 = (0..3).fold(NumberPoly::zero(), |acc, i| &acc + &(&diff[i] * &diff[i]));
            let w2 = &xc[3] * &xc[3];
            let stationary = |mu: &Number| {
                let d = &dist2 - &w2.scale(mu);
                let g = d.gcd_monic(&d.derivative());
                g.degree().unwrap_or(0) >= 1
            };
            let centre_f = centre.each_ref().map(qsic::affine::approx);
            let xf: Vec<Vec<f64>> = xc
                .iter()
                .map(|p| p.coeffs().iter().map(qsic::affine::approx).collect())
                .collect();
            let dist_f = |u: f64| -> f64 {
                let e: Vec<f64> = xf
                    .iter()
                    .map(|p| p.iter().rev().fold(0.0, |a, c| a * u + c))
                    .collect();
                (0..3).map(|i| (e[i] / e[3] - centre_f[i]).powi(2)).sum()
            };
            // u = tan θ over a grid of angles (every point of the conic), the extremes then
            // refined by ternary search between the grid neighbours
            let n = 2000;
            let theta = |k: f64| std::f64::consts::PI * (k / n as f64 - 0.5);
            let g = |t: f64| {
                let d = dist_f(t.tan());
                if d.is_finite() {
                    d
                } else {
                    f64::INFINITY
                }
            };
            let extreme = |sign: f64| -> f64 {
                let k = (1..n)
                    .min_by(|&i, &j| {
                        (sign * g(theta(i as f64))).total_cmp(&(sign * g(theta(j as f64))))
                    })
                    .unwrap();
                let (mut lo, mut hi) = (theta(k as f64 - 1.0), theta(k as f64 + 1.0));
                for _ in 0..200 {
                    let (m1, m2) = (lo + (hi - lo) / 3.0, hi - (hi - lo) / 3.0);
                    if sign * g(m1) < sign * g(m2) {
                        hi = m2;
                    } else {
                        lo = m1;
                    }
                }
                g((lo + hi) / 2.0)
            };
            let (min, max) = (extreme(1.0), extreme(-1.0));
            // float noise grows with the conic's size: relative to the largest distance
            let size = if max.is_finite() { max } else { min };
            let close = |a: f64, b: f64| (a - b).abs() <= 1e-5 * size.max(b.abs()).max(1e-3);
            match &conic.shape {
                ConicShape::Circle { radius2, .. } => {
                    for p in &finite_points {
                        let pc: [Number; 3] = std::array::from_fn(|i| p[i].sub(&centre[i]));
                        assert!(dot(&pc, &pc) == *radius2, "{id}: radius");
                    }
                }
                ConicShape::Ellipse { major, minor, .. } => {
                    for axis in [major, minor] {
                        if let Some(mu) = axis.semi_axis2.as_number() {
                            if xc
                                .iter()
                                .flat_map(|p| p.coeffs())
                                .all(|c| c.compatible_with(mu))
                            {
                                assert!(stationary(mu), "{id}: semi-axis");
                                exact_checks += 1;
                            }
                        }
                    }
                    assert!(
                        close(max, major.semi_axis2.to_f64()),
                        "{id}: {max} major {}",
                        major.semi_axis2.to_f64()
                    );
                    assert!(
                        close(min, minor.semi_axis2.to_f64()),
                        "{id}: {min} minor {} major {} {max}",
                        minor.semi_axis2.to_f64(),
                        major.semi_axis2.to_f64()
                    );
                }
                ConicShape::Hyperbola {
                    transverse,
                    conjugate,
                    ..
                } => {
                    // the asymptotes: the directions X(u) at the roots of W make with the
                    // axes the angle whose tan² is b²/a²
                    let w = &xf[3];
                    let (c0, c1, c2) = (
                        w[0],
                        w.get(1).copied().unwrap_or(0.0),
                        w.get(2).copied().unwrap_or(0.0),
                    );
                    let roots: Vec<Vec<f64>> = if c2 == 0.0 {
                        // one root at u = ∞: the leading coefficients
                        vec![
                            (0..3)
                                .map(|i| xf[i].get(2).copied().unwrap_or(0.0))
                                .collect(),
                            {
                                let u = -c0 / c1;
                                (0..3)
                                    .map(|i| xf[i].iter().rev().fold(0.0, |a, c| a * u + c))
                                    .collect()
                            },
                        ]
                    } else {
                        let d = (c1 * c1 - 4.0 * c0 * c2).sqrt();
                        [(-c1 + d) / (2.0 * c2), (-c1 - d) / (2.0 * c2)]
                            .iter()
                            .map(|&u| {
                                (0..3)
                                    .map(|i| xf[i].iter().rev().fold(0.0, |a, c| a * u + c))
                                    .collect()
                            })
                            .collect()
                    };
                    let ratio = conjugate.semi_axis2.to_f64() / transverse.semi_axis2.to_f64();
                    for v in roots {
                        let along = |e: &[f64; 3]| (0..3).map(|i| v[i] * e[i]).sum::<f64>();
                        let (t, c) = (
                            along(&transverse.direction.unit),
                            along(&conjugate.direction.unit),
                        );
                        assert!(
                            (c * c - ratio * t * t).abs() <= 1e-6 * (c * c + t * t),
                            "{id}: asymptote {c} {t} {ratio}"
                        );
                    }
                    if let Some(mu) = transverse.semi_axis2.as_number() {
                        if xc
                            .iter()
                            .flat_map(|p| p.coeffs())
                            .all(|c| c.compatible_with(mu))
                        {
                            assert!(stationary(mu), "{id}: transverse semi-axis");
                            exact_checks += 1;
                        }
                    }
                    assert!(close(min, transverse.semi_axis2.to_f64()), "{id}: {min}");
                }
                _ => {}
            }
            // every axis: c ± a·e on the conic (a ellipse or transverse semi-axis), decimals
            let axes = match &conic.shape {
                ConicShape::Ellipse { major, minor, .. } => vec![major, minor],
                ConicShape::Hyperbola { transverse, .. } => vec![transverse],
                _ => vec![],
            };
            let scale: f64 = m
                .iter()
                .flatten()
                .map(|v| v.to_f64().value().abs())
                .fold(0.0, f64::max);
            for axis in axes {
                let a = axis.semi_axis2.to_f64().sqrt();
                for s in [-1.0, 1.0] {
                    let p: [f64; 4] = std::array::from_fn(|k| {
                        if k < 3 {
                            centre_f[k] + s * a * axis.direction.unit[k]
                        } else {
                            1.0
                        }
                    });
                    let mut v = 0.0;
                    for i in 0..4 {
                        for j in 0..4 {
                            v += p[i] * m[i][j].to_f64().value() * p[j];
                        }
                    }
                    let norm2: f64 = p.iter().map(|x| x * x).sum();
                    assert!(
                        v.abs() <= 1e-7 * scale * norm2,
                        "{id}: vertex c ± a·e: {v} {scale} {norm2} {a} {:?}",
                        axis.direction
                    );
                }
            }
        }
    }
    exact_checks
}

#[test]
fn every_corpus_conic_passes_independent_checks_in_two_charts() {
    let charts = [
        Chart::default(),
        Chart::new([1, 2, -1, 3].map(RBig::from)).unwrap(),
    ];
    let mut counts = std::collections::BTreeMap::new();
    let mut stationary = 0;
    let mut sections = 0;
    for file in ["cases.jsonl", "seed_examples.jsonl", "qi-quadrics.jsonl"] {
        let path = format!("{}/tests/data/{file}", env!("CARGO_MANIFEST_DIR"));
        let text = std::fs::read_to_string(&path).unwrap();
        for line in text.lines().filter(|l| !l.trim().is_empty()) {
            let v: Value = serde_json::from_str(line).unwrap();
            if v.get("A").is_none() || !matches!(v["pencil"].as_str(), Some("regular" | "singular"))
            {
                continue;
            }
            let id = v["id"].as_str().unwrap_or("?").to_owned();
            let (a, b) = (read_form(&v["A"]), read_form(&v["B"]));
            let Ok(curve) = parameterize(&a, &b) else {
                continue;
            };
            if !curve
                .components
                .iter()
                .any(|c| c.kind == ComponentKind::Conic && c.real)
            {
                continue;
            }
            for (ci, chart) in charts.iter().enumerate() {
                let view = affine_curve(&curve, &a, &b, chart);
                let mats = [
                    chart.matrix_in_chart(a.matrix()),
                    chart.matrix_in_chart(b.matrix()),
                ];
                for (k, comp) in curve.components.iter().enumerate() {
                    let Some(conic) = affine_conic(comp, chart).unwrap() else {
                        continue;
                    };
                    let id = format!("{file} {id} chart {ci} component {k}");
                    *counts.entry(conic.shape.key()).or_insert(0) += 1;
                    if comp.section.is_some() {
                        sections += 1;
                    }
                    let Some(ComponentParam::Rational { x, .. }) = &comp.param else {
                        panic!("{id}: a conic without its parameterization")
                    };
                    // the independent checks read X(u): on the route in its field, which the
                    // plane section's route must equal
                    let reference = param_conic(x, chart).unwrap();
                    same_conic(&id, &conic, &reference);
                    let conic = reference;
                    if let Ok(view) = &view {
                        assert_eq!(
                            view.components[k].name,
                            Some(conic.shape.key()),
                            "{id}: the curve graph's name"
                        );
                    }
                    if !matches!(conic.shape, ConicShape::AtInfinity) {
                        stationary +=
                            check_conic(&id, &conic, comp.param.as_ref().unwrap(), &mats, chart);
                    }
                }
            }
        }
    }
    eprintln!("{counts:?}, {stationary} semi-axes checked exactly, {sections} from sections");
    assert!(stationary >= 20, "{stationary}");
    assert!(sections >= 100, "{sections}");
    for key in ["ellipse", "hyperbola", "parabola", "circle"] {
        assert!(
            counts.get(key).copied().unwrap_or(0) >= 1,
            "{key}: {counts:?}"
        );
    }
}

/// Relative closeness of two decimals.
fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-9 * (1.0 + a.abs().max(b.abs()))
}

/// The plane-section route ([`affine_conic`]) and the parameterization's ([`param_conic`]) give
/// the same conic: its type, normal, centre, lengths, axes (exactly where they share a field).
fn same_conic(id: &str, got: &AffineConic, want: &AffineConic) {
    assert_eq!(got.shape.key(), want.shape.key(), "{id}: the type");
    match (&got.normal, &want.normal) {
        (Some(g), Some(w)) => assert!(parallel(g, w), "{id}: the normal"),
        (g, w) => assert_eq!(g.is_some(), w.is_some(), "{id}: the normal"),
    }
    let axis = |id: &str, g: &qsic::affine::Axis, w: &qsic::affine::Axis| {
        assert!(
            close(g.semi_axis2.to_f64(), w.semi_axis2.to_f64()),
            "{id}: semi-axis² {} against {}",
            g.semi_axis2.to_f64(),
            w.semi_axis2.to_f64()
        );
        let (gu, wu) = (g.direction.unit, w.direction.unit);
        let cos: f64 = (0..3).map(|i| gu[i] * wu[i]).sum();
        assert!((cos.abs() - 1.0).abs() < 1e-9, "{id}: an axis");
    };
    match (&got.shape, &want.shape) {
        (ConicShape::AtInfinity, ConicShape::AtInfinity) => {}
        (
            ConicShape::Circle { centre, radius2 },
            ConicShape::Circle {
                centre: c,
                radius2: r,
            },
        ) => {
            assert!(same_point(centre, c), "{id}: the centre");
            assert!(close(radius2.to_f64(), r.to_f64()), "{id}: the radius");
        }
        (
            ConicShape::Ellipse {
                centre,
                major,
                minor,
            },
            ConicShape::Ellipse {
                centre: c,
                major: a,
                minor: b,
            },
        )
        | (
            ConicShape::Hyperbola {
                centre,
                transverse: major,
                conjugate: minor,
            },
            ConicShape::Hyperbola {
                centre: c,
                transverse: a,
                conjugate: b,
            },
        ) => {
            assert!(same_point(centre, c), "{id}: the centre");
            axis(id, major, a);
            axis(id, minor, b);
        }
        (
            ConicShape::Parabola {
                vertex,
                axis,
                focal_length2,
            },
            ConicShape::Parabola {
                vertex: v,
                axis: a,
                focal_length2: f,
            },
        ) => {
            assert!(same_point(vertex, v), "{id}: the vertex");
            assert!(
                (0..3).all(|i| close(axis.unit[i], a.unit[i])),
                "{id}: the axis"
            );
            assert!(
                close(focal_length2.to_f64(), f.to_f64()),
                "{id}: the focal length"
            );
        }
        _ => unreachable!("same keys"),
    }
}

#[test]
fn conics_in_planes_over_a_quadratic_field_have_their_data_in_that_field() {
    // QI's pair 33: the planes x = c·w, c² + c − 1 = 0, cut the circles y² + z² = (3 + c)w²;
    // their points need a further root (the parameterization is over a field of degree 4),
    // their centres and radii do not
    let found = conics_of("x^2+x*w-w^2", "-x*w+y^2+z^2-3*w^2");
    assert_eq!(found.len(), 2);
    for conic in &found {
        let ConicShape::Circle { centre, radius2 } = &conic.shape else {
            panic!("a circle: {:?}", conic.shape)
        };
        for v in centre.iter().chain([radius2]) {
            assert!(v.numerator().len() <= 2, "in ℚ(√5): {v:?}");
        }
        let c = &centre[0];
        assert!(c.mul(c).add(c).sub(&r(1, 1)).is_zero(), "c² + c = 1");
        assert!(centre[1].is_zero() && centre[2].is_zero());
        assert_eq!(*radius2, r(3, 1).add(c), "radius² = 3 + c");
    }
}
