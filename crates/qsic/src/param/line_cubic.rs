//! A line and a twisted cubic (cases 9, 10: Segre `[22]`, case 12: `[4]`): the line first
//! (enhanced-Levin paper, §2.2), then the cubic rationally through it.
//!
//! * The line. `[22]`: the vertices `P₁`, `P₂` of the cones at the two double roots are
//!   singular points of the curve, so the line through them meets each quadric at least
//!   four times and lies on both. The roots are conjugate in ℚ(√D) (`D` the discriminant
//!   of the square-free part of `det(λA − B)`; `D < 0` in case 10), `P₁ = U + √D·V` and
//!   `P₂ = U − √D·V`, so the line is `span(U, V)`, rational. `[4]`: the vertex `v₁` of the
//!   cone `S₀` at the quadruple root and `v₂` with `S₀v₂ = Tv₁` (`T` another member, the
//!   start of the Jordan chain) span an isotropic plane of every member: the line.
//! * The cubic. With the line `span(E₁, E₂)` and `W(t) = E₃ + t·E₄`, the plane
//!   `span(E₁, E₂, W)` cuts a quadric `Q` of the pencil in the line and the line
//!   `2a₁α + 2a₂β + a₃γ = 0` (`aᵢ = EᵢᵀQW`, `a₃ = WᵀQW`) of the point `αE₁ + βE₂ + γW`. The
//!   two residual lines of `A` and `B` meet at the moving point of the cubic: `(α, β, γ)`
//!   is the cross product, `X(t)` of degree 3.
//! * The meeting points. `X(t)` is on the line where `γ(t) = 2(a₁b₂ − a₂b₁) = 0`, a binary
//!   quadratic: two real roots, a conjugate pair or a double root (tangency) — checked
//!   against the vertex route (the sign of `D`; the tangency point is `v₁`).

use super::curve::{self, Component, ComponentParam, Curve, RealPiece};
use super::nodal::{
    check_against_class, form, primitive, rational_point, segre_blocks, vertex,
    without_common_factor,
};
use super::{integer_matrix, member};
use crate::classify::{analyze_pencil, Classification, ComponentKind, SingularPointKind};
use crate::error::Error;
use crate::quadric::Quadric;
use qsic_algebra::field::{NumberField, Quadratic};
use qsic_algebra::linalg::{forms::split_square, minors, Matrix};
use qsic_algebra::{IBig, Poly, RBig, Ring, Sign};

/// Two rational points spanning a line.
type Line = [[RBig; 4]; 2];

/// The two vertices of a `[22]` pencil when real, over ℚ or ℚ(√δ).
type RealVertices = [[Quadratic; 4]; 2];

/// Where the line meets the cubic.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Meeting {
    /// At two distinct real points, over ℚ or a real ℚ(√δ) (conjugate there).
    TwoReal(Box<RealVertices>),
    /// At two complex conjugate points: the line and the cubic do not meet in ℝP³.
    Conjugate,
    /// Tangent at one real point (rational).
    Tangent([RBig; 4]),
}

/// A line and a twisted cubic, the intersection of two quadrics in cases 9, 10 and 12.
#[derive(Clone, Debug)]
pub struct LineAndCubic {
    /// Two rational points spanning the line (primitive integer vectors).
    pub line: [[RBig; 4]; 2],
    /// The cubic `X(t)`, `t ∈ ℝ ∪ {∞}`, rational, homogeneous degree 3, no common factor.
    pub cubic: [Poly<RBig>; 4],
    /// The meeting points.
    pub meeting: Meeting,
}

/// The line of a `[22]` pencil (see the module docs) and the vertices at the double roots:
/// real ones (`Some`) or conjugate ones (`None`).
fn line_of_two_cones(
    am: &[[RBig; 4]; 4],
    bm: &[[RBig; 4]; 4],
    f: &Poly,
) -> Result<(Line, Option<RealVertices>), Error> {
    let g = f.squarefree_part();
    let rational_vertices = |l1: Option<RBig>, l2: Option<RBig>| -> Result<_, Error> {
        let p1 = vertex(&member(am, bm, l1.as_ref()))?;
        let p2 = vertex(&member(am, bm, l2.as_ref()))?;
        let q = |p: &[RBig; 4]| p.clone().map(Quadratic::rational);
        Ok(([p1.clone(), p2.clone()], Some([q(&p1), q(&p2)])))
    };
    match g.degree() {
        // a double root at ∞ (deg f = 2) and a rational one
        Some(1) => {
            let l = RBig::from(-g.coeff(0)) / RBig::from(g.coeff(1));
            rational_vertices(None, Some(l))
        }
        Some(2) => {
            let (g0, g1, g2) = (g.coeff(0), g.coeff(1), g.coeff(2));
            let disc = &g1 * &g1 - IBig::from(4) * &g0 * &g2;
            let (m, delta) = split_square(&disc);
            let two_g2 = RBig::from(IBig::from(2) * &g2);
            if delta == IBig::ONE {
                let root = |s: &IBig| (RBig::from(-&g1 + s * &m)) / &two_g2;
                return rational_vertices(Some(root(&IBig::ONE)), Some(root(&-IBig::ONE)));
            }
            // λ₊ = (−g₁ + m√δ)/(2g₂), its vertex over ℚ(√δ) and the conjugate
            let sqrt = Quadratic::new(RBig::ZERO, RBig::from(m), delta.clone())
                .expect("δ is not a square");
            let lambda = Quadratic::rational(RBig::from(-&g1) / &two_g2)
                .add(&sqrt.scale(&(RBig::ONE / &two_g2)));
            let s = Matrix::from_fn(4, 4, |i, j| {
                lambda
                    .scale(&am[i][j])
                    .sub(&Quadratic::rational(bm[i][j].clone()))
            });
            let kernel = s.kernel();
            let [p] = kernel.as_slice() else {
                return Err(Error::Algebra(format!(
                    "a member of rank {} at a double root of a [22] pencil",
                    4 - kernel.len()
                )));
            };
            let u: Vec<RBig> = p.iter().map(|x| x.rational_part().clone()).collect();
            let v: Vec<RBig> = p.iter().map(|x| x.radical_part().clone()).collect();
            let line = [primitive(&u), primitive(&v)];
            let vertices = (delta > IBig::ZERO).then(|| {
                let p1: [Quadratic; 4] = std::array::from_fn(|i| p[i].clone());
                let p2 = p1.clone().map(|x| x.conjugate());
                [p1, p2]
            });
            Ok((line, vertices))
        }
        _ => Err(Error::Algebra(format!(
            "det(λA − B) = {f} has no two double roots"
        ))),
    }
}

/// The line of a `[4]` pencil: the vertex `v₁` of the cone at the quadruple root `λ₀` and
/// `v₂` with `S₀v₂ = Tv₁`.
fn line_of_one_cone(
    am: &[[RBig; 4]; 4],
    bm: &[[RBig; 4]; 4],
    lambda: Option<&RBig>,
) -> Result<[[RBig; 4]; 2], Error> {
    let s0 = member(am, bm, lambda);
    let v1 = vertex(&s0)?;
    let t = if lambda.is_some() { am } else { bm };
    let tv1: Vec<RBig> = (0..4)
        .map(|i| (0..4).fold(RBig::ZERO, |acc, j| acc + &t[i][j] * &v1[j]))
        .collect();
    let v2 = Matrix::from_array(s0)
        .solve(&tv1)
        .ok_or_else(|| Error::Algebra("no Jordan chain at the quadruple root".into()))?;
    Ok([v1, primitive(&v2)])
}

/// `xᵀMy` where `y` moves: `y = y₀ + t·y₁`, a polynomial in `t`.
fn form_along(m: &[[RBig; 4]; 4], x: &[RBig; 4], y0: &[RBig; 4], y1: &[RBig; 4]) -> Poly<RBig> {
    Poly::new(vec![form(m, x, y0), form(m, x, y1)])
}

/// The line and the twisted cubic of the intersection of `a` and `b` (cases 9, 10, 12:
/// Segre `[22]` or `[4]`), with their meeting points.
///
/// # Errors
/// [`Error::Unsupported`] for Segre types other than `[22]` and `[4]`; [`Error::Algebra`] for an internal
/// inconsistency (the line or the cubic off a quadric, the two routes to the meeting points
/// disagreeing).
///
/// # Examples
/// ```
/// use qsic::{io::parse_quadric, param::{parameterize_line_and_cubic, Meeting}};
/// // a cone and a cylinder sharing the z-axis: the cubic meets it at the apex and at the
/// // point at infinity of the axis
/// let a = parse_quadric("x*z-y^2").unwrap();
/// let b = parse_quadric("x^2-2*x+y^2-2*y").unwrap();
/// let c = parameterize_line_and_cubic(&a, &b).unwrap();
/// assert!(matches!(c.meeting, Meeting::TwoReal(_)));
/// use qsic_algebra::RBig;
/// assert!(c.line.iter().all(|p| p[0] == RBig::ZERO && p[1] == RBig::ZERO));
/// ```
pub fn parameterize_line_and_cubic(a: &Quadric, b: &Quadric) -> Result<LineAndCubic, Error> {
    let analysis = analyze_pencil(a, b)
        .ok_or_else(|| Error::Unsupported("a line and a cubic need a regular pencil".into()))?;
    let blocks = segre_blocks(&analysis);
    if blocks != [vec![2], vec![2]] && blocks != [vec![4]] {
        return Err(Error::Unsupported(format!(
            "Segre blocks {blocks:?}: not a line and a cubic ([22] or [4])"
        )));
    }
    let f = &analysis.characteristic;
    let (am, bm) = (integer_matrix(a), integer_matrix(b));
    let g = f.squarefree_part();
    let quadruple = match (f.degree(), g.degree()) {
        (Some(0), _) => Some(None),
        (Some(4), Some(1)) => Some(Some(RBig::from(-g.coeff(0)) / RBig::from(g.coeff(1)))),
        (Some(4), Some(2)) | (Some(2), Some(1)) => None,
        _ => {
            return Err(Error::Unsupported(format!(
                "det(λA − B) = {f}: not a line and a cubic"
            )))
        }
    };
    let (line, vertices) = match &quadruple {
        Some(lambda) => (line_of_one_cone(&am, &bm, lambda.as_ref())?, None),
        None => line_of_two_cones(&am, &bm, f)?,
    };
    let [e1, e2] = &line;
    for m in [&am, &bm] {
        if [(e1, e1), (e1, e2), (e2, e2)]
            .iter()
            .any(|(x, y)| !form(m, x, y).is_zero())
        {
            return Err(Error::Algebra("the line is not on both quadrics".into()));
        }
    }
    // complete the basis with two unit vectors
    let unit = |k: usize| -> [RBig; 4] {
        std::array::from_fn(|i| if i == k { RBig::ONE } else { RBig::ZERO })
    };
    let (e3, e4) = (0..4)
        .flat_map(|i| (i + 1..4).map(move |j| (i, j)))
        .map(|(i, j)| (unit(i), unit(j)))
        .find(|(e3, e4)| {
            let m = [e1.clone(), e2.clone(), e3.clone(), e4.clone()];
            !minors::det(&m).is_zero()
        })
        .ok_or_else(|| Error::Algebra("the line's two points are dependent".into()))?;
    // residual lines: n = (2a₁, 2a₂, a₃) for A, (2b₁, 2b₂, b₃) for B
    let residual = |m: &[[RBig; 4]; 4]| {
        let k1 = form_along(m, e1, &e3, &e4);
        let k2 = form_along(m, e2, &e3, &e4);
        let k3 = Poly::new(vec![
            form(m, &e3, &e3),
            RBig::from(2) * form(m, &e3, &e4),
            form(m, &e4, &e4),
        ]);
        (k1, k2, k3)
    };
    let (a1, a2, a3) = residual(&am);
    let (b1, b2, b3) = residual(&bm);
    let alpha = &(&a2 * &b3) - &(&a3 * &b2);
    let beta = &(&a3 * &b1) - &(&a1 * &b3);
    let gamma = (&(&a1 * &b2) - &(&a2 * &b1)).scale(&RBig::from(2));
    let t_gamma = &gamma * &Poly::x();
    let (coords, degree) = without_common_factor([alpha, beta, gamma, t_gamma]);
    if degree != 3 {
        return Err(Error::Algebra(format!(
            "the residual cubic has degree {degree}"
        )));
    }
    let basis = [e1, e2, &e3, &e4];
    let cubic: [Poly<RBig>; 4] = std::array::from_fn(|i| {
        (0..4).fold(Poly::zero(), |acc, k| &acc + &coords[k].scale(&basis[k][i]))
    });
    // γ as a binary quadratic: its discriminant decides the meeting points
    let gamma = &coords[2];
    let (k0, k1, k2) = (gamma.coeff(0), gamma.coeff(1), gamma.coeff(2));
    let disc = &k1 * &k1 - RBig::from(4) * &k0 * &k2;
    let meeting = match (&quadruple, vertices) {
        (Some(_), _) if disc.is_zero() => {
            // the double root t₀ (∞ when k₂ = 0): X(t₀) must be the cone's vertex
            let at = |p: &Poly<RBig>| match k2.is_zero() {
                true => p.coeff(3),
                false => p.eval(&(-&k1 / (RBig::from(2) * &k2))),
            };
            let x0: [RBig; 4] = std::array::from_fn(|i| at(&cubic[i]));
            let v1 = &line[0];
            let proportional =
                (0..4).all(|i| (0..4).all(|j| (&x0[i] * &v1[j] - &x0[j] * &v1[i]).is_zero()));
            if !proportional {
                return Err(Error::Algebra(
                    "the cubic touches the line off the cone's vertex".into(),
                ));
            }
            Meeting::Tangent(v1.clone())
        }
        (None, Some(points)) if disc > RBig::ZERO => Meeting::TwoReal(Box::new(points)),
        (None, None) if disc < RBig::ZERO => Meeting::Conjugate,
        _ => {
            return Err(Error::Algebra(format!(
                "the cubic's meeting parameters (discriminant sign {:?}) disagree with the \
                 cones' vertices",
                Sign::of_rational(&disc)
            )))
        }
    };
    Ok(LineAndCubic {
        line,
        cubic,
        meeting,
    })
}

/// The [`Curve`] of a line and a twisted cubic: two real rational components, each one
/// closed real piece, connected when they meet at real points.
pub(super) fn line_and_cubic_curve(
    classification: Classification,
    a: &Quadric,
    b: &Quadric,
) -> Result<Curve, Error> {
    let lc = parameterize_line_and_cubic(a, b)?;
    let rational_poly = |p: &Poly<RBig>| p.map(|c| curve::rational(c.clone()));
    let [e1, e2] = &lc.line;
    let line_x: [curve::NumberPoly; 4] = std::array::from_fn(|i| {
        Poly::new(vec![
            curve::rational(e1[i].clone()),
            curve::rational(e2[i].clone()),
        ])
    });
    let components = vec![
        Component {
            kind: ComponentKind::Cubic,
            multiplicity: 1,
            real: true,
            param: Some(ComponentParam::Rational {
                x: std::array::from_fn(|i| rational_poly(&lc.cubic[i])),
                degree: 3,
            }),
            plane: None,
            section: None,
        },
        Component {
            kind: ComponentKind::Line,
            multiplicity: 1,
            real: true,
            param: Some(ComponentParam::Rational {
                x: line_x,
                degree: 1,
            }),
            plane: None,
            section: None,
        },
    ];
    let singular_points: Vec<curve::SingularPoint> = match &lc.meeting {
        Meeting::TwoReal(points) => {
            let delta = points
                .iter()
                .flatten()
                .find(|x| x.as_rational().is_none())
                .map(|x| x.radicand().clone());
            let field: Option<NumberField> = delta.as_ref().map(curve::sqrt_field);
            points
                .iter()
                .map(|p| curve::SingularPoint {
                    kind: SingularPointKind::Crunode,
                    point: std::array::from_fn(|i| curve::from_quadratic(&p[i], field.as_ref())),
                })
                .collect()
        }
        Meeting::Conjugate => Vec::new(),
        Meeting::Tangent(p) => vec![curve::SingularPoint {
            kind: SingularPointKind::Tangency,
            point: rational_point(p),
        }],
    };
    check_against_class(&classification, &singular_points)?;
    let pieces = vec![RealPiece::whole(0), RealPiece::whole(1)];
    let connected = match lc.meeting {
        Meeting::Conjugate => vec![vec![0], vec![1]],
        _ => vec![vec![0, 1]],
    };
    Ok(Curve {
        classification,
        components,
        singular_points,
        pieces,
        connected,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::classify::classify;
    use crate::io::parse_quadric;
    use crate::param::nodal::tests::{disguise, mapped};
    use crate::param::parameterize;
    use qsic_algebra::testing::SplitMix;

    fn pair(a: &str, b: &str) -> (Quadric, Quadric) {
        (parse_quadric(a).unwrap(), parse_quadric(b).unwrap())
    }

    /// `p` lies on the line spanned by `line` (all 3×3 minors of the three rows vanish).
    fn on_line(line: &[[RBig; 4]; 2], p: &[RBig; 4]) -> bool {
        let rows = [&line[0], &line[1], p];
        let cols = |skip: usize| -> Vec<usize> { (0..4).filter(|&c| c != skip).collect() };
        (0..4).all(|skip| {
            let c = cols(skip);
            let m: [[RBig; 3]; 3] =
                std::array::from_fn(|i| std::array::from_fn(|j| rows[i][c[j]].clone()));
            minors::det(&m).is_zero()
        })
    }

    /// `X(t)`, the cubic, and the line lie on both quadrics, identically in `t`.
    fn assert_on_both(c: &LineAndCubic, a: &Quadric, b: &Quadric) {
        for m in [a.matrix(), b.matrix()] {
            let mut acc = Poly::zero();
            for i in 0..4 {
                for j in 0..4 {
                    acc = &acc + &(&c.cubic[i] * &c.cubic[j]).scale(&m[i][j]);
                }
            }
            assert!(acc.is_zero(), "the cubic is off a quadric");
            let [e1, e2] = &c.line;
            assert!(
                form(m, e1, e1).is_zero() && form(m, e1, e2).is_zero() && form(m, e2, e2).is_zero()
            );
        }
    }

    /// A cone `xz = y²` and a cylinder `(x−1)² + (y−1)² = 2` share the z-axis, with
    /// different tangent planes along it. In the plane `y = mx` the residual lines give the
    /// cubic `(2(1+m), 2m(1+m), 2m²(1+m), 1+m²)`: on the axis at `m = −1` (the apex) and
    /// `m = ∞` (the axis' point at infinity).
    #[test]
    fn a_cone_and_a_cylinder_sharing_a_ruling_meet_in_it_and_a_cubic() {
        let (a, b) = pair("x*z-y^2", "x^2-2*x+y^2-2*y");
        let c = parameterize_line_and_cubic(&a, &b).unwrap();
        assert_on_both(&c, &a, &b);
        let axis = [[0, 0, 1, 0].map(RBig::from), [0, 0, 0, 1].map(RBig::from)];
        assert!(c.line.iter().all(|p| on_line(&axis, p)));
        let Meeting::TwoReal(points) = &c.meeting else {
            panic!("{:?}", c.meeting)
        };
        let rational: Vec<[RBig; 4]> = points
            .iter()
            .map(|p| primitive(&p.clone().map(|x| x.as_rational().unwrap().clone())))
            .collect();
        assert!(
            rational.contains(&axis[0]) && rational.contains(&axis[1]),
            "{rational:?}"
        );
        let curve = parameterize(&a, &b).unwrap();
        assert_eq!(curve.classification.case, Some(9));
        assert_eq!(curve.connected, [vec![0, 1]]);
    }

    /// `xz = y²` and `x(x + w) + yz = 0`: both contain the z-axis; the cubic is
    /// `(−n³, −mn², −m²n, m³ + n³)`, on the axis only at `n = 0` — twice: tangent at the apex.
    #[test]
    fn a_cubic_tangent_to_the_shared_ruling_at_the_apex() {
        let (a, b) = pair("x*z-y^2", "x^2+x*w+y*z");
        let c = parameterize_line_and_cubic(&a, &b).unwrap();
        assert_on_both(&c, &a, &b);
        assert_eq!(c.meeting, Meeting::Tangent([0, 0, 0, 1].map(RBig::from)));
        let curve = parameterize(&a, &b).unwrap();
        assert_eq!(curve.classification.case, Some(12));
        assert_eq!(curve.singular_points.len(), 1);
    }

    /// Other Segre types are refused, not misread: a nodal quartic ([211]), two conics
    /// ([(11)(11)], the printed case-10 pair of ERRATA 1), a smooth quartic.
    #[test]
    fn other_classes_are_not_lines_and_cubics() {
        for (a, b) in [
            ("x^2+y^2+z^2-4", "(x-1)^2+y^2-1"),
            ("x*w+y*z", "x*z-y*w"),
            ("x^2+y^2+z^2-w^2", "2*x^2+4*y^2-w^2"),
        ] {
            let (a, b) = pair(a, b);
            let r = parameterize_line_and_cubic(&a, &b);
            assert!(matches!(r, Err(Error::Unsupported(_))), "{r:?}");
            let r = crate::param::parameterize_singular_quartic(&a, &b);
            assert_eq!(
                matches!(r, Err(Error::Unsupported(_))),
                classify(&a, &b).case != Some(5)
            );
        }
    }

    /// The representatives of cases 9, 10 (ERRATA 1) and 12, disguised: the line and the
    /// meeting points move with the map.
    #[test]
    fn disguised_lines_and_cubics_keep_their_line_and_meeting_points() {
        let representatives = [
            (9, "x*y+z*w", "y^2+2*z*w+w^2"),
            (10, "x*w+y*z", "x*z-y*w+z*w"),
            (12, "x*w+y*z", "z^2+2*y*w"),
        ];
        let mut rng = SplitMix(0x0001_14ec_0b1c);
        for (case, a, b) in representatives {
            let (a, b) = pair(a, b);
            assert_eq!(classify(&a, &b).case, Some(case));
            let original = parameterize_line_and_cubic(&a, &b).unwrap();
            assert_on_both(&original, &a, &b);
            for k in 0..3 {
                let (da, db, inverse) = disguise(&a, &b, &mut rng);
                let tag = format!("case {case}, disguise {k}");
                assert_eq!(classify(&da, &db).case, Some(case), "{tag}");
                let c = parameterize_line_and_cubic(&da, &db).unwrap();
                assert_on_both(&c, &da, &db);
                for p in &original.line {
                    assert!(on_line(&c.line, &mapped(&inverse, p)), "{tag}: line");
                }
                match (&original.meeting, &c.meeting) {
                    (Meeting::Tangent(p), Meeting::Tangent(q)) => {
                        assert_eq!(&mapped(&inverse, p), q, "{tag}");
                    }
                    (Meeting::TwoReal(_), Meeting::TwoReal(_)) => assert_eq!(case, 9),
                    (Meeting::Conjugate, Meeting::Conjugate) => assert_eq!(case, 10),
                    (x, y) => panic!("{tag}: {x:?} became {y:?}"),
                }
                let curve = parameterize(&da, &db).unwrap();
                let groups = if case == 10 { 2 } else { 1 };
                assert_eq!(curve.connected.len(), groups, "{tag}");
            }
        }
    }
}
