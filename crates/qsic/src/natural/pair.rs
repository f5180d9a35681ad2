//! The closed forms of natural pairs: the class and the curve in ℝ³ (default chart `w = 0`)
//! from the Euclidean data of [`NaturalQuadric`], every decision an exact comparison of
//! rationals. Pairs not listed return `None` and the general route answers.
//!
//! | pair | decided by | answers |
//! |---|---|---|
//! | plane `n·x + d = 0`, sphere `(c, r²)` | `(n·c + d)²` against `|n|²r²` | circle (case 19), tangent point (33), none (20) |
//! | plane, cylinder `(p, a, r²)` | `n·a = 0`; then `(n·p + d)²` against `|n|²r²` | ellipse or circle (`n × a = 0`) (19); parallel: two lines, one line, none (singular) |
//! | plane, cone `(v, a, cos²θ)` | `h = n·v + d`, `σ = (n·a)²/(|n|²|a|²)` (sin² of the plane's angle with the axis) against `sin²θ = 1 − cos²θ` | `h ≠ 0`: ellipse/circle, parabola, hyperbola (19); `h = 0`: two lines, one line, the apex (singular) |
//! | spheres `(c₁, r₁²)`, `(c₂, r₂²)` | `δ = |c₁ − c₂|²`, `u = δ − r₁² − r₂²`: `u²` against `4r₁²r₂²` | circle (17), tangent point (25), none (16); concentric: none (20) |
//! | sphere, cylinder with the centre on the axis | `r_s²` against `r_c²` | two circles (14), one tangent circle (19), none (16) |
//! | cylinders with parallel axes | `D²` the axes' squared distance, `u = D² − r₁² − r₂²`: `u²` against `4r₁²r₂²` | two lines, a tangent line, none; coaxial: none (singular) |
//!
//! Two circles `|x − c| = r` in a plane at distance `D` meet iff `(r₁ − r₂)² ≤ D² ≤
//! (r₁ + r₂)²`, i.e. `(D² − r₁² − r₂²)² ≤ 4r₁²r₂²`, equality for tangency (external when
//! `u > 0`): the test for two spheres (in a plane through both centres) and for two parallel
//! cylinders (in a plane perpendicular to the axes). A sphere and a plane meet in a circle,
//! a point or nothing as the squared distance of the centre `(n·c + d)²/|n|²` is below, equal
//! to or above `r²`; a plane parallel to a cylinder's axis likewise with the axis' distance.
//! A plane meets a circular cone off the apex in an ellipse, parabola or hyperbola as its
//! angle with the axis is above, equal to or below the half-angle; through the apex in the
//! apex alone, one line, or two lines. The tangent point of two spheres is `c₁ + t(c₂ − c₁)`
//! with `t = (δ + r₁² − r₂²)/(2δ)`, in the radical plane; of a sphere and a plane the foot of
//! the centre, `c − n(n·c + d)/|n|²`. These points are rational.
//!
//! The class and the affine object of each outcome are those of the general route (which
//! is the reference: `tests/natural.rs` compares them in full on every configuration and on
//! rigid placements of each), including the order of the components and their
//! multiplicities.

use super::{NaturalQuadric, Vec3};
use crate::vocabulary::{
    AffineComponent, AffineCurve, AffineSingularPoint, ComplexType, ComponentKind, RealType,
    SingularPointKind,
};
use qsic_algebra::field::NumberFieldElement as Number;
use qsic_algebra::field::NumberFieldElement;
use qsic_algebra::linalg::forms::plane_pair;
use qsic_algebra::linalg::Matrix;
use qsic_algebra::{IBig, RBig, Ring};
use std::cmp::Ordering;

/// The class of a natural pair: a row of the table of regular cases (its case and the index
/// of its signature sequence), or the type of a singular pencil.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum NaturalClass {
    /// Case `case`, class `class` of its row.
    Regular {
        /// The paper's case, 1–35.
        case: u8,
        /// The index of the signature sequence in the case's row.
        class: usize,
    },
    /// A singular pencil of this type.
    Singular(ComplexType, RealType),
}

/// The closed-form answer for a natural pair.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct PairAnswer {
    /// The class.
    pub class: NaturalClass,
    /// The curve in ℝ³ (default chart).
    pub curve: AffineCurve,
}

/// The closed-form answer for the pair `(a, b)` of natural quadrics (`ma`, `mb` their
/// primitive integer matrices), or `None` for a pair without one here (the general route
/// answers).
pub(crate) fn pair(
    a: &NaturalQuadric,
    ma: &[[IBig; 4]; 4],
    b: &NaturalQuadric,
    mb: &[[IBig; 4]; 4],
) -> Option<PairAnswer> {
    use NaturalQuadric as N;
    // spheres, and cylinders with parallel axes: the member with no quadratic part
    let order = || PlaneOrder::of_member(ma, mb);
    match (a, b) {
        (N::Plane { normal, offset }, other) | (other, N::Plane { normal, offset }) => {
            match other {
                N::Sphere { centre, r2 } => Some(plane_sphere(normal, offset, centre, r2)),
                N::Cylinder { point, axis, r2 } => {
                    Some(plane_cylinder(normal, offset, point, axis, r2))
                }
                N::Cone { apex, axis, cos2 } => Some(plane_cone(normal, offset, apex, axis, cos2)),
                N::Plane { .. } => None,
            }
        }
        (N::Sphere { centre: c1, r2: s1 }, N::Sphere { centre: c2, r2: s2 }) => {
            sphere_sphere(c1, s1, c2, s2, order)
        }
        (
            N::Sphere { centre, r2: rs },
            N::Cylinder {
                point,
                axis,
                r2: rc,
            },
        )
        | (
            N::Cylinder {
                point,
                axis,
                r2: rc,
            },
            N::Sphere { centre, r2: rs },
        ) => sphere_cylinder(centre, rs, point, axis, rc),
        (
            N::Cylinder {
                point: p1,
                axis: a1,
                r2: r1,
            },
            N::Cylinder {
                point: p2,
                axis: a2,
                r2: r2_,
            },
        ) => parallel_cylinders(p1, a1, r1, p2, a2, r2_, order),
        _ => None,
    }
}

/// Which plane of the member `P = w·(2v·x + k·w)` comes first, as the general route lists
/// the components: it splits `P` by a congruence diagonalization (pivot on the first nonzero
/// diagonal entry, else on `e_k + e_j`) into `y_a ∓ √(−d_b/d_a)·y_b`, the positive root
/// first. For `k ≠ 0` the pivot is `w`: `y_a = w + (v·x)/k`, `d_a = k`; the next pivot is
/// the first nonzero of `(v₁, v₂, v₀)`, `v_m`, with `y_b = (v·x)/v_m`, `d_b = −v_m²/k`. With
/// `σ = sign(k·v_m)` the planes are `w + (1 ∓ σ)(v·x)/k`: the plane at infinity first iff
/// `σ > 0`. For `k = 0` the split itself is asked (`forms::plane_pair`). `P` and `−P` give
/// the same order, so any multiple of the member will do.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum PlaneOrder {
    /// The plane at infinity's components first.
    InfinityFirst,
    /// The finite plane's components first.
    FiniteFirst,
}

impl PlaneOrder {
    /// The order for the member of `A` and `B` without quadratic part (`Q_A ∝ Q_B ≠ 0`).
    fn of_member(a: &[[IBig; 4]; 4], b: &[[IBig; 4]; 4]) -> Option<PlaneOrder> {
        let (i, j) = (0..3)
            .flat_map(|i| (0..3).map(move |j| (i, j)))
            .find(|&(i, j)| !a[i][j].is_zero())?;
        // P = b_ij·A − a_ij·B, a multiple of λA − B for λ = b_ij/a_ij
        let member = |r: usize, c: usize| &b[i][j] * &a[r][c] - &a[i][j] * &b[r][c];
        let k = member(3, 3);
        if k.is_zero() {
            let p: [[RBig; 4]; 4] =
                std::array::from_fn(|r| std::array::from_fn(|c| RBig::from(member(r, c))));
            let pair = plane_pair(&Matrix::from_array(p))?;
            let at_infinity = pair.planes[0][..3].iter().all(|v| v.is_zero());
            return Some(if at_infinity {
                PlaneOrder::InfinityFirst
            } else {
                PlaneOrder::FiniteFirst
            });
        }
        let vm = [1, 2, 0]
            .into_iter()
            .map(|r| member(r, 3))
            .find(|v| !v.is_zero())?;
        Some(if (k.signum() * vm.signum()) > IBig::ZERO {
            PlaneOrder::InfinityFirst
        } else {
            PlaneOrder::FiniteFirst
        })
    }

    /// The components of the finite plane and of the plane at infinity in this order.
    fn arrange(
        self,
        finite: Vec<AffineComponent>,
        at_infinity: Vec<AffineComponent>,
    ) -> Vec<AffineComponent> {
        match self {
            PlaneOrder::FiniteFirst => [finite, at_infinity].concat(),
            PlaneOrder::InfinityFirst => [at_infinity, finite].concat(),
        }
    }
}

fn dot(u: &Vec3, v: &Vec3) -> RBig {
    &u[0] * &v[0] + &u[1] * &v[1] + &u[2] * &v[2]
}

fn sub(u: &Vec3, v: &Vec3) -> Vec3 {
    std::array::from_fn(|i| &u[i] - &v[i])
}

fn cross(u: &Vec3, v: &Vec3) -> Vec3 {
    [
        &u[1] * &v[2] - &u[2] * &v[1],
        &u[2] * &v[0] - &u[0] * &v[2],
        &u[0] * &v[1] - &u[1] * &v[0],
    ]
}

fn is_zero(v: &Vec3) -> bool {
    v.iter().all(|x| *x == RBig::ZERO)
}

/// A finite component of the curve (none of the natural pairs' components lies at infinity).
fn component(
    kind: ComponentKind,
    name: Option<&'static str>,
    bounded: Option<bool>,
    points_at_infinity: usize,
    multiplicity: u32,
) -> AffineComponent {
    AffineComponent {
        kind,
        name,
        at_infinity: false,
        bounded,
        points_at_infinity,
        multiplicity,
    }
}

fn conic(name: &'static str, points_at_infinity: usize, multiplicity: u32) -> AffineComponent {
    component(
        ComponentKind::Conic,
        Some(name),
        Some(points_at_infinity == 0),
        points_at_infinity,
        multiplicity,
    )
}

fn imaginary(kind: ComponentKind, multiplicity: u32) -> AffineComponent {
    component(kind, None, None, 0, multiplicity)
}

fn real_line(multiplicity: u32) -> AffineComponent {
    component(
        ComponentKind::Line,
        Some("line"),
        Some(false),
        1,
        multiplicity,
    )
}

/// The counts of a curve from its components and singular points: `bounded` and
/// `unbounded` connected components in ℝ³, `isolated` points, `at_infinity` real points on
/// the plane at infinity.
struct Counts {
    bounded: usize,
    unbounded: usize,
    isolated: usize,
    at_infinity: usize,
}

fn curve(
    counts: Counts,
    components: Vec<AffineComponent>,
    singular_points: Vec<AffineSingularPoint>,
) -> AffineCurve {
    AffineCurve {
        curves_bounded: counts.bounded,
        curves_unbounded: counts.unbounded,
        isolated_points: counts.isolated,
        points_at_infinity: counts.at_infinity,
        singular_finite: singular_points.iter().filter(|p| !p.at_infinity).count(),
        singular_at_infinity: singular_points.iter().filter(|p| p.at_infinity).count(),
        components,
        singular_points,
    }
}

const NONE: Counts = Counts {
    bounded: 0,
    unbounded: 0,
    isolated: 0,
    at_infinity: 0,
};

fn finite_point(kind: SingularPointKind, p: Vec3) -> AffineSingularPoint {
    AffineSingularPoint {
        kind,
        at_infinity: false,
        point: Some(p.map(NumberFieldElement::rational) as [Number; 3]),
    }
}

fn point_at_infinity() -> AffineSingularPoint {
    AffineSingularPoint {
        kind: SingularPointKind::Multiple,
        at_infinity: true,
        point: None,
    }
}

fn regular(case: u8, class: usize, curve: AffineCurve) -> PairAnswer {
    PairAnswer {
        class: NaturalClass::Regular { case, class },
        curve,
    }
}

fn singular(complex: ComplexType, real: RealType, curve: AffineCurve) -> PairAnswer {
    PairAnswer {
        class: NaturalClass::Singular(complex, real),
        curve,
    }
}

/// A real conic counted twice (case 19): the plane's section of a quadric.
fn double_conic(name: &'static str, points_at_infinity: usize) -> PairAnswer {
    let counts = Counts {
        bounded: usize::from(points_at_infinity == 0),
        unbounded: points_at_infinity,
        isolated: 0,
        at_infinity: points_at_infinity,
    };
    regular(
        19,
        0,
        curve(counts, vec![conic(name, points_at_infinity, 2)], vec![]),
    )
}

/// An imaginary conic counted twice (case 20).
fn imaginary_double_conic() -> PairAnswer {
    regular(
        20,
        0,
        curve(NONE, vec![imaginary(ComponentKind::Conic, 2)], vec![]),
    )
}

fn plane_sphere(n: &Vec3, d: &RBig, c: &Vec3, r2: &RBig) -> PairAnswer {
    let h = dot(n, c) + d;
    let n2 = dot(n, n);
    match (&h * &h).cmp(&(&n2 * r2)) {
        Ordering::Less => double_conic("circle", 0),
        Ordering::Equal => {
            // two conjugate lines counted twice through the foot of the centre (case 33)
            let t = &h / &n2;
            let foot = std::array::from_fn(|i| &c[i] - &n[i] * &t);
            let counts = Counts {
                isolated: 1,
                ..NONE
            };
            regular(
                33,
                0,
                curve(
                    counts,
                    vec![
                        imaginary(ComponentKind::Line, 2),
                        imaginary(ComponentKind::Line, 2),
                    ],
                    vec![finite_point(SingularPointKind::Multiple, foot)],
                ),
            )
        }
        Ordering::Greater => imaginary_double_conic(),
    }
}

/// Two lines of a plane parallel to a cylinder's axis, or through a cone's apex, each
/// counted twice: real (`TwoConcurrentDoubleLines`) or conjugate (real type `Point`).
fn plane_cylinder(n: &Vec3, d: &RBig, p: &Vec3, a: &Vec3, r2: &RBig) -> PairAnswer {
    if dot(n, a) != RBig::ZERO {
        return double_conic(
            if is_zero(&cross(n, a)) {
                "circle"
            } else {
                "ellipse"
            },
            0,
        );
    }
    let h = dot(n, p) + d;
    let n2 = dot(n, n);
    use ComplexType as C;
    match (&h * &h).cmp(&(&n2 * r2)) {
        Ordering::Less => {
            // two parallel real lines, meeting at the axis' point at infinity
            let counts = Counts {
                unbounded: 2,
                at_infinity: 1,
                ..NONE
            };
            singular(
                C::TwoConcurrentDoubleLines,
                RealType::Same,
                curve(
                    counts,
                    vec![real_line(2), real_line(2)],
                    vec![point_at_infinity()],
                ),
            )
        }
        Ordering::Equal => quadruple_line(),
        Ordering::Greater => {
            let counts = Counts {
                at_infinity: 1,
                ..NONE
            };
            singular(
                C::TwoConcurrentDoubleLines,
                RealType::Point,
                curve(
                    counts,
                    vec![
                        imaginary(ComponentKind::Line, 2),
                        imaginary(ComponentKind::Line, 2),
                    ],
                    vec![point_at_infinity()],
                ),
            )
        }
    }
}

/// A tangent plane along a line of a cylinder or cone: the line counted four times.
fn quadruple_line() -> PairAnswer {
    let counts = Counts {
        unbounded: 1,
        at_infinity: 1,
        ..NONE
    };
    singular(
        ComplexType::QuadrupleLine,
        RealType::Same,
        curve(counts, vec![real_line(4)], vec![]),
    )
}

fn plane_cone(n: &Vec3, d: &RBig, v: &Vec3, a: &Vec3, cos2: &RBig) -> PairAnswer {
    let h = dot(n, v) + d;
    let na = dot(n, a);
    // σ = (n·a)²/(|n|²|a|²) against sin²θ = 1 − cos²θ, denominators cleared
    let lhs = &na * &na;
    let rhs = dot(n, n) * dot(a, a) * (RBig::ONE - cos2);
    let order = lhs.cmp(&rhs);
    use ComplexType as C;
    if h != RBig::ZERO {
        return match order {
            Ordering::Greater => double_conic(
                if is_zero(&cross(n, a)) {
                    "circle"
                } else {
                    "ellipse"
                },
                0,
            ),
            Ordering::Equal => double_conic("parabola", 1),
            Ordering::Less => double_conic("hyperbola", 2),
        };
    }
    let apex = finite_point(SingularPointKind::Multiple, v.clone());
    match order {
        Ordering::Less => {
            let counts = Counts {
                unbounded: 1,
                at_infinity: 2,
                ..NONE
            };
            singular(
                C::TwoConcurrentDoubleLines,
                RealType::Same,
                curve(counts, vec![real_line(2), real_line(2)], vec![apex]),
            )
        }
        Ordering::Equal => quadruple_line(),
        Ordering::Greater => {
            let counts = Counts {
                isolated: 1,
                ..NONE
            };
            singular(
                C::TwoConcurrentDoubleLines,
                RealType::Point,
                curve(
                    counts,
                    vec![
                        imaginary(ComponentKind::Line, 2),
                        imaginary(ComponentKind::Line, 2),
                    ],
                    vec![apex],
                ),
            )
        }
    }
}

fn sphere_sphere(
    c1: &Vec3,
    s1: &RBig,
    c2: &Vec3,
    s2: &RBig,
    order: impl Fn() -> Option<PlaneOrder>,
) -> Option<PairAnswer> {
    let e = sub(c2, c1);
    let delta = dot(&e, &e);
    if delta == RBig::ZERO {
        // concentric: the same sphere (the general route's single pencil), or the
        // imaginary conic at infinity counted twice
        return (s1 != s2).then(imaginary_double_conic);
    }
    let u = &delta - s1 - s2;
    let four = RBig::from(4);
    // the plane at infinity meets both in the imaginary conic at infinity
    let absolute = || vec![imaginary(ComponentKind::Conic, 1)];
    Some(match (&u * &u).cmp(&(&four * s1 * s2)) {
        Ordering::Less => {
            let counts = Counts { bounded: 1, ..NONE };
            regular(
                17,
                0,
                curve(
                    counts,
                    order()?.arrange(vec![conic("circle", 0, 1)], absolute()),
                    vec![],
                ),
            )
        }
        Ordering::Equal => {
            let t = (&delta + s1 - s2) / (RBig::from(2) * &delta);
            let touch = std::array::from_fn(|i| &c1[i] + &e[i] * &t);
            let counts = Counts {
                isolated: 1,
                ..NONE
            };
            regular(
                25,
                0,
                curve(
                    counts,
                    order()?.arrange(
                        vec![
                            imaginary(ComponentKind::Line, 1),
                            imaginary(ComponentKind::Line, 1),
                        ],
                        absolute(),
                    ),
                    vec![finite_point(SingularPointKind::Acnode, touch)],
                ),
            )
        }
        Ordering::Greater => regular(
            16,
            1,
            curve(
                NONE,
                vec![
                    imaginary(ComponentKind::Conic, 1),
                    imaginary(ComponentKind::Conic, 1),
                ],
                vec![],
            ),
        ),
    })
}

/// A sphere centred on a cylinder's axis: circles at `±√(r_s² − r_c²)` along the axis.
fn sphere_cylinder(c: &Vec3, rs: &RBig, p: &Vec3, a: &Vec3, rc: &RBig) -> Option<PairAnswer> {
    if !is_zero(&cross(&sub(c, p), a)) {
        return None; // off the axis: a quartic in general
    }
    Some(match rs.cmp(rc) {
        Ordering::Greater => {
            let counts = Counts { bounded: 2, ..NONE };
            regular(
                14,
                0,
                curve(
                    counts,
                    vec![conic("circle", 0, 1), conic("circle", 0, 1)],
                    vec![],
                ),
            )
        }
        Ordering::Equal => double_conic("circle", 0),
        Ordering::Less => regular(
            16,
            0,
            curve(
                NONE,
                vec![
                    imaginary(ComponentKind::Conic, 1),
                    imaginary(ComponentKind::Conic, 1),
                ],
                vec![],
            ),
        ),
    })
}

/// Cylinders with parallel axes: lines parallel to the axes, all through the axes' common
/// point at infinity.
fn parallel_cylinders(
    p1: &Vec3,
    a1: &Vec3,
    r1: &RBig,
    p2: &Vec3,
    a2: &Vec3,
    r2: &RBig,
    order: impl Fn() -> Option<PlaneOrder>,
) -> Option<PairAnswer> {
    if !is_zero(&cross(a1, a2)) {
        return None; // crossing or skew axes: a quartic, or two conics
    }
    let w = cross(&sub(p2, p1), a1);
    let dist2 = dot(&w, &w) / dot(a1, a1);
    use ComplexType as C;
    use ComponentKind::Line;
    if dist2 == RBig::ZERO {
        if r1 == r2 {
            return None; // the same cylinder: a single pencil
        }
        let counts = Counts { ..NONE };
        return Some(singular(
            C::TwoConcurrentDoubleLines,
            RealType::Point,
            curve(
                counts,
                vec![imaginary(Line, 2), imaginary(Line, 2)],
                vec![point_at_infinity()],
            ),
        ));
    }
    let u = &dist2 - r1 - r2;
    let four = RBig::from(4);
    let at_infinity = Counts {
        at_infinity: 1,
        ..NONE
    };
    // the plane at infinity meets both in the two conjugate lines through the axes' point
    let at_infinity_lines = || vec![imaginary(Line, 1), imaginary(Line, 1)];
    Some(match (&u * &u).cmp(&(&four * r1 * r2)) {
        Ordering::Less => singular(
            C::FourConcurrentLines,
            RealType::TwoConcurrentLines,
            curve(
                Counts {
                    unbounded: 2,
                    ..at_infinity
                },
                order()?.arrange(vec![real_line(1), real_line(1)], at_infinity_lines()),
                vec![point_at_infinity()],
            ),
        ),
        Ordering::Equal => singular(
            C::TwoConcurrentLinesAndDoubleLine,
            RealType::DoubleLine,
            curve(
                Counts {
                    unbounded: 1,
                    ..at_infinity
                },
                order()?.arrange(vec![real_line(2)], at_infinity_lines()),
                vec![point_at_infinity()],
            ),
        ),
        Ordering::Greater => singular(
            C::FourConcurrentLines,
            RealType::Point,
            curve(
                at_infinity,
                vec![
                    imaginary(Line, 1),
                    imaginary(Line, 1),
                    imaginary(Line, 1),
                    imaginary(Line, 1),
                ],
                vec![point_at_infinity()],
            ),
        ),
    })
}
