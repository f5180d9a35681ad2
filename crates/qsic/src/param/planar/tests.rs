use super::*;

#[test]
fn rational_roots_are_found_exactly_among_irrational_ones() {
    let p =
        &(&Poly::from_i64s(&[-2, 3]) * &Poly::from_i64s(&[-2, 0, 1])) * &Poly::from_i64s(&[5, 7]);
    let roots = rational_roots(&p.to_rational());
    let frac = |n: i64, d: i64| RBig::from_parts_signed(IBig::from(n), IBig::from(d));
    assert_eq!(roots, [frac(-5, 7), frac(2, 3)]);
    assert!(rational_roots(&Poly::from_i64s(&[-3, 0, 1]).to_rational()).is_empty());
}

/// The primitive elements of ℚ(√δ, √r): the images of √δ and √r square to δ and r and
/// are positive, for a rational `r`, for `r = a + b√δ` with `b > 0` and with `b < 0`
/// (where the conjugate `r̄ > r` is positive too).
#[test]
fn biquadratic_fields_hold_the_positive_square_roots() {
    let two = IBig::from(2);
    let r = |a: i64, b: i64| Quadratic::new(RBig::from(a), RBig::from(b), two.clone()).unwrap();
    for radicand in [r(3, 0), r(1, 1), r(3, -1), r(5, 3)] {
        let ext = Ext::new(Some(&two), Some(&radicand));
        let (sd, root) = (ext.sqrt_delta.clone().unwrap(), ext.root.clone().unwrap());
        assert_eq!(sd.mul(&sd), Number::from_int(&two));
        assert_eq!(root.mul(&root), ext.embed(&radicand), "{radicand}");
        assert_eq!((sd.sign(), root.sign()), (Sign::Positive, Sign::Positive));
    }
}

use crate::io::parse_quadric;

fn eval_at(p: &Poly<Number>, t: i64) -> Number {
    let t = Number::from_int(&IBig::from(t));
    p.coeffs()
        .iter()
        .rev()
        .fold(Number::zero(), |acc, c| acc.mul(&t).add(c))
}

/// Two points of a line component.
fn line_points(c: &Component) -> [Vec<Number>; 2] {
    match &c.param {
        Some(ComponentParam::Rational { x, degree: 1 }) => {
            [0, 1].map(|t| x.iter().map(|p| eval_at(p, t)).collect())
        }
        _ => panic!("not a parameterized line"),
    }
}

fn quadric_at(q: &Quadric, x: &[Number]) -> Number {
    let m = q.matrix();
    let mut acc = Number::zero();
    for i in 0..4 {
        for j in 0..4 {
            acc = acc.add(&curve::rational(m[i][j].clone()).mul(&x[i]).mul(&x[j]));
        }
    }
    acc
}

/// The substitution `X = T·X'` (`Q' = TᵀQT`).
fn transformed(text: &str, t: &[[i64; 4]; 4]) -> Quadric {
    let m = parse_quadric(text).unwrap().matrix().clone();
    Quadric::from_matrix(std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let mut acc = RBig::ZERO;
            for k in 0..4 {
                for l in 0..4 {
                    acc += RBig::from(t[k][i] * t[l][j]) * &m[k][l];
                }
            }
            acc
        })
    }))
    .unwrap()
}

fn apply(t: &[[i64; 4]; 4], x: &[Number]) -> Vec<Number> {
    (0..4)
        .map(|i| {
            (0..4).fold(Number::zero(), |acc, j| {
                acc.add(&Number::from_int(&IBig::from(t[i][j])).mul(&x[j]))
            })
        })
        .collect()
}

const MOVES: [[[i64; 4]; 4]; 3] = [
    [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]],
    [[1, 1, 0, 0], [0, 1, 2, 0], [0, 0, 1, -1], [1, 0, 0, 1]],
    [[2, 1, 0, 1], [1, 1, 0, 0], [0, 3, 1, 0], [0, 0, 1, 1]],
];

/// Case 31 (plane pairs at λ = ±2i) under integer changes of coordinates: the two real
/// lines found are the images of the known lines `x = w, y = −z` and `x = −w, y = z`,
/// the other two are non-real and nothing else is real.
#[test]
fn the_real_lines_of_case_31_are_the_known_skew_lines() {
    for t in &MOVES {
        let a = transformed("x*y+z*w", t);
        let b = transformed("-x^2+y^2-z^2+w^2", t);
        let curve = super::super::parameterize(&a, &b).unwrap();
        let real: Vec<&Component> = curve.components.iter().filter(|c| c.real).collect();
        assert_eq!((curve.components.len(), real.len()), (4, 2));
        let mut signs = Vec::new();
        for c in real {
            let pts = line_points(c).map(|x| apply(t, &x));
            // x = s·w and y = −s·z with s = ±1, at both points
            let s = [1i64, -1]
                .into_iter()
                .find(|&s| {
                    pts.iter().all(|x| {
                        let s = Number::from_int(&IBig::from(s));
                        x[0].sub(&s.mul(&x[3])).is_zero() && x[1].add(&s.mul(&x[2])).is_zero()
                    })
                })
                .expect("a known line");
            signs.push(s);
        }
        signs.sort();
        assert_eq!(signs, [-1, 1]);
        assert_eq!(curve.connected.len(), 2);
        assert!(curve.singular_points.is_empty());
    }
}

/// Skew quadrilaterals with plane pairs at conjugate real λ (one over a degree-4 field,
/// one needing the rulings' route): four real lines on both quadrics, four crunodes on
/// both quadrics, one connected piece; under changes of coordinates too.
#[test]
fn skew_quadrilaterals_at_real_quadratic_lambda_have_four_real_lines() {
    for (ta, tb) in [
        ("x^2-y^2-2*z*w", "2*x^2+2*x*y+2*y^2-z^2-3*w^2"),
        ("x^2-3*y^2-2*z*w", "3*x^2+6*x*y+9*y^2-z^2-6*w^2"),
    ] {
        for t in &MOVES {
            let (a, b) = (transformed(ta, t), transformed(tb, t));
            let curve = super::super::parameterize(&a, &b).unwrap();
            assert_eq!(curve.components.len(), 4, "{ta}");
            for c in &curve.components {
                let p = c.param.as_ref().expect("real");
                assert!(p.lies_on(a.matrix()) && p.lies_on(b.matrix()));
            }
            assert_eq!(curve.singular_points.len(), 4);
            for sp in &curve.singular_points {
                assert!(quadric_at(&a, &sp.point).is_zero());
                assert!(quadric_at(&b, &sp.point).is_zero());
            }
            assert_eq!(curve.connected, [vec![0, 1, 2, 3]]);
        }
    }
}

/// Four concurrent lines over `xz = y²`, `2xy + z² = 0` (cone from (0:0:0:1)): the
/// conic points `(1 : t : t²)` with `t(t³ + 2) = 0` give the real lines through
/// `(1:0:0:0)` (rational) and `(1 : −∛2 : ∛4 : 0)` (degree 3), two non-real lines.
#[test]
fn four_concurrent_lines_through_cubic_irrationalities() {
    for t in &MOVES[..2] {
        let a = transformed("x*z-y^2", t);
        let b = transformed("2*x*y+z^2", t);
        let curve = super::super::parameterize(&a, &b).unwrap();
        let real: Vec<&Component> = curve.components.iter().filter(|c| c.real).collect();
        assert_eq!((curve.components.len(), real.len()), (4, 2));
        let mut degrees = Vec::new();
        for c in real {
            let pts = line_points(c).map(|x| apply(t, &x));
            // in the original coordinates: a point (1 : τ : τ² : *) with τ(τ³ + 2) = 0
            let p = pts
                .iter()
                .find(|x| !x[0].is_zero())
                .expect("off the vertex");
            let tau = p[1].div(&p[0]).unwrap();
            let t4 = tau.mul(&tau).mul(&tau).mul(&tau);
            assert!(t4.add(&tau.add(&tau)).is_zero());
            assert!(p[2].div(&p[0]).unwrap().sub(&tau.mul(&tau)).is_zero());
            degrees.push(tau.field().map_or(1, |f| f.modulus().degree().unwrap()));
        }
        degrees.sort();
        assert_eq!(degrees, [1, 3]);
        assert_eq!(curve.connected.len(), 1);
    }
}

/// Case 30 at conjugate real λ (corpus qi-060…062): four non-real lines, the two real
/// vertices on one kernel are acnodes on both quadrics, the only real pieces.
#[test]
fn case_30_at_real_quadratic_lambda_is_two_acnodes() {
    for (ta, tb) in [
        ("x^2+y^2-2*z*w", "2*x*y+z^2+w^2"),
        ("x^2+3*y^2-2*z*w", "x^2-6*x*y-3*y^2-z^2-4*w^2"),
        ("x^2+2*y^2-2*z*w", "x^2-4*x*y-2*y^2-z^2-3*w^2"),
    ] {
        for t in &MOVES[..2] {
            let (a, b) = (transformed(ta, t), transformed(tb, t));
            let curve = super::super::parameterize(&a, &b).unwrap();
            assert_eq!(curve.components.len(), 4);
            assert!(curve.components.iter().all(|c| !c.real));
            assert_eq!(curve.singular_points.len(), 2, "{ta}");
            for sp in &curve.singular_points {
                assert_eq!(sp.kind, SingularPointKind::Acnode);
                assert!(quadric_at(&a, &sp.point).is_zero());
                assert!(quadric_at(&b, &sp.point).is_zero());
            }
            assert_eq!(curve.connected, [vec![0], vec![1]]);
            assert!(curve
                .pieces
                .iter()
                .all(|p| matches!(p, RealPiece::Point { .. })));
        }
    }
}

/// The largest degree over ℚ of the field of a parameterization's coefficients.
fn field_degree(p: &ComponentParam) -> usize {
    let coefficient_degree = |n: &Number| n.field().map_or(1, |f| f.modulus().degree().unwrap());
    match p {
        ComponentParam::Rational { x, .. } => x
            .iter()
            .flat_map(|c| c.coeffs().iter())
            .map(coefficient_degree)
            .max()
            .unwrap_or(1),
        _ => panic!("a conic has a rational parameterization"),
    }
}

/// Two secant conics in the planes `x = ±√2·y` meeting at the rational points
/// `(0 : 0 : ±1 : 1)` of their common line (case 13: `x² − 2y² = 0` against the sphere
/// `x² + y² + z² − w²`), also under integer changes of coordinates: each conic goes through
/// a meeting point, so it is parameterized over the planes' field ℚ(√2), degree 2 — a point
/// from the conic's own diagonalization would need a second square root (degree 4).
#[test]
fn secant_conics_through_rational_meeting_points_stay_in_the_planes_field() {
    for t in &MOVES {
        let a = transformed("x^2-2*y^2", t);
        let b = transformed("x^2+y^2+z^2-w^2", t);
        let curve = super::super::parameterize(&a, &b).unwrap();
        assert_eq!(curve.classification.case, Some(13), "{t:?}");
        let conics: Vec<&Component> = curve.components.iter().filter(|c| c.real).collect();
        assert_eq!(conics.len(), 2);
        for c in conics {
            let p = c.param.as_ref().expect("real");
            assert!(p.lies_on(a.matrix()) && p.lies_on(b.matrix()));
            assert_eq!(field_degree(p), 2, "{t:?}");
        }
    }
}

/// QI's pair 33: the planes `x = c·w`, `c² + c = 1`, cut the circles `y² + z² = (3 + c)w²`,
/// which meet at two imaginary points; no ratio of their diagonal form is a square in ℚ(√5),
/// but `(y, z, w) = (φ, 1, 1)`, `φ² = 2 + c`, is a point over ℚ(√5): each circle is
/// parameterized over the planes' field, degree 2 (QI's), not over ℚ(√5, √(3 + c)) — also
/// under integer changes of coordinates, which the small search sees as other diagonal forms.
#[test]
fn secant_conics_with_a_small_point_of_the_planes_field_stay_in_it() {
    let mut moved_in_field = 0;
    for (k, t) in MOVES.iter().enumerate() {
        let a = transformed("x^2+x*w-w^2", t);
        let b = transformed("-x*w+y^2+z^2-3*w^2", t);
        let curve = super::super::parameterize(&a, &b).unwrap();
        assert_eq!(curve.classification.case, Some(14), "{t:?}");
        let conics: Vec<&Component> = curve.components.iter().filter(|c| c.real).collect();
        assert_eq!(conics.len(), 2);
        for c in conics {
            let p = c.param.as_ref().expect("real");
            assert!(p.lies_on(a.matrix()) && p.lies_on(b.matrix()));
            if k == 0 {
                assert_eq!(field_degree(p), 2);
            } else if field_degree(p) == 2 {
                moved_in_field += 1;
            }
        }
    }
    eprintln!("{moved_in_field} conics of moved pairs over ℚ(√5)");
}
