//! Frames: each real line, conic and point of the curve as a CAD kernel stores it — a conic
//! as a placement (location, normal, X direction, Y direction) and its lengths, the way
//! OpenCASCADE's `gp_Circ`, `gp_Elips`, `gp_Hypr`, `gp_Parab` take a `gp_Ax2`; a line as a
//! point and a direction (`gp_Lin`); exact where the field allows, decimals beside.
//!
//! Read from [`affine_conic`] (conics) and the component's parameterization (lines, points)
//! in the chart's affine coordinates, Euclidean metric of those coordinates:
//!
//! | component | location | X direction | lengths |
//! |---|---|---|---|
//! | circle | centre | `|N|²eᵢ − NᵢN`, `i` the first coordinate with `Nᵢ = 0` (else 0) | radius |
//! | ellipse | centre | the major axis | major, minor semi-axes |
//! | hyperbola | centre | the transverse axis (the branch OpenCASCADE draws is on `+X`) | transverse (major), conjugate (minor) semi-axes |
//! | parabola | vertex | the axis, from the vertex towards the focus | focal length `f` (`P + u²/(4f)·X + u·Y`) |
//! | line | over ℚ the point nearest the origin, `P − (P·d/d·d)d`, else the parameterization's point at `u = 0` (`u = ∞` when that is at infinity); direction `d`, first nonzero coordinate positive | — | — |
//!
//! `N` is the plane's normal, `Y = N × X`, so `(X, Y, N)` is right-handed and the conic is
//! `location + a·cos θ·X + b·sin θ·Y` (ellipse) as in OpenCASCADE. A line `X(u) = x₀ + x₁u`
//! has direction `d = w₀x₁ − w₁x₀` (the `xyz` parts, `wᵢ` the `w′` coordinates): its point at
//! infinity.
//!
//! **Exact unit vectors.** A unit vector `v/|v|` needs `√|v|²`, outside the coordinates'
//! field in general. Every direction is therefore given as an exact vector `v` (rational ones
//! scaled to coprime integers, orientation kept) with its exact squared norm `|v|²` — what
//! `gp_Dir(vx, vy, vz)` takes, normalizing itself — and, when `v` is rational, the unit vector
//! itself over ℚ(√|v|²) (`(1, 0, 1)/√2 = (sqrt(2)/2, 0, sqrt(2)/2)`). Lengths likewise: the
//! exact square always, the length itself when the square is rational (in ℚ(√square)).
//! Over a larger field (or where [`affine_conic`] gives an axis in decimals only) the exact
//! parts are `None` and the decimals remain.

use super::conic::{constant, cross, dot, plain, plain3, unit};
use super::{affine_conic, approx, AffineConic, Axis, Chart, ConicShape, Direction, Surd};
use crate::classify::ComponentKind;
use crate::error::Error;
use crate::param::curve::sqrt_field;
use crate::param::{Component, ComponentParam, Number, Point};
use qsic_algebra::{Field, IBig, RBig, Ring, Sign};

/// A direction of a frame: an exact vector, its squared norm, the exact unit vector where it
/// lies in ℚ(√norm²), and the unit vector in decimals.
#[derive(Clone, Debug)]
pub struct FrameDirection {
    /// The exact vector (rational ones coprime integers), `None` when only decimals are known.
    pub vector: Option<[Number; 3]>,
    /// `|vector|²`, exactly; `None` with `vector` when only decimals are known, and for a
    /// vector over a field of degree > 2 (no exact unit follows from it there).
    pub norm2: Option<Number>,
    /// `vector/|vector|` exactly, when `vector` is rational (coordinates in ℚ(√norm2)).
    pub unit: Option<[Number; 3]>,
    /// The unit vector in decimals.
    pub approx: [f64; 3],
}

/// A length of a frame (radius, semi-axis, focal length): its exact square, the length
/// exactly when the square is rational, decimals.
#[derive(Clone, Debug)]
pub struct FrameLength {
    /// The squared length, exactly.
    pub square: Surd,
    /// The length, when the square is a rational (then in ℚ(√square)).
    pub exact: Option<Number>,
    /// Its decimal value.
    pub approx: f64,
}

/// A placement in ℝ³ (OpenCASCADE's `gp_Ax2`): a location, the normal of the plane and two
/// orthogonal directions in it, `(x_direction, y_direction, normal)` right-handed.
#[derive(Clone, Debug)]
pub struct Placement {
    /// The centre (vertex for a parabola).
    pub location: [Number; 3],
    /// Its decimals.
    pub location_approx: [f64; 3],
    /// The normal `N` of the conic's plane.
    pub normal: FrameDirection,
    /// The X direction (where the angle parameter starts).
    pub x_direction: FrameDirection,
    /// `N × X`.
    pub y_direction: FrameDirection,
}

/// The frame of one real component of the curve in an affine chart.
#[derive(Clone, Debug)]
pub enum Frame {
    /// A circle (`gp_Circ`).
    Circle {
        /// Centre, normal, X and Y directions.
        placement: Placement,
        /// The radius.
        radius: FrameLength,
    },
    /// An ellipse that is not a circle (`gp_Elips`): X along the major axis.
    Ellipse {
        /// Centre, normal, X (major axis) and Y (minor axis).
        placement: Placement,
        /// The major semi-axis.
        major_radius: FrameLength,
        /// The minor semi-axis.
        minor_radius: FrameLength,
    },
    /// A hyperbola (`gp_Hypr`): X along the transverse axis; both branches are the component's.
    Hyperbola {
        /// Centre, normal, X (transverse axis) and Y (conjugate axis).
        placement: Placement,
        /// The transverse semi-axis.
        major_radius: FrameLength,
        /// The conjugate semi-axis.
        minor_radius: FrameLength,
    },
    /// A parabola (`gp_Parab`): location the vertex, X the axis towards the focus.
    Parabola {
        /// Vertex, normal, X (axis) and Y.
        placement: Placement,
        /// The focal length (vertex to focus).
        focal: FrameLength,
    },
    /// A line of ℝ³ (`gp_Lin`).
    Line {
        /// Its point nearest the origin (over ℚ), else the parameterization's point (module docs).
        location: [Number; 3],
        /// Its decimals.
        location_approx: [f64; 3],
        /// Its direction.
        direction: FrameDirection,
    },
    /// A real point of ℝ³ (an isolated point of the curve).
    Point {
        /// Its coordinates.
        location: [Number; 3],
        /// Their decimals.
        location_approx: [f64; 3],
    },
    /// A point on the plane at infinity: a direction of ℝ³.
    PointAtInfinity {
        /// The direction.
        direction: FrameDirection,
    },
    /// A conic in the plane at infinity.
    ConicAtInfinity,
    /// A line in the plane at infinity.
    LineAtInfinity,
}

impl Frame {
    /// `circle`, `ellipse`, `hyperbola`, `parabola`, `line`, `point`, `point_at_infinity`,
    /// `conic_at_infinity`, `line_at_infinity`.
    pub fn key(&self) -> &'static str {
        match self {
            Frame::Circle { .. } => "circle",
            Frame::Ellipse { .. } => "ellipse",
            Frame::Hyperbola { .. } => "hyperbola",
            Frame::Parabola { .. } => "parabola",
            Frame::Line { .. } => "line",
            Frame::Point { .. } => "point",
            Frame::PointAtInfinity { .. } => "point_at_infinity",
            Frame::ConicAtInfinity => "conic_at_infinity",
            Frame::LineAtInfinity => "line_at_infinity",
        }
    }
}

/// The frame of a real component in `chart` (module documentation): `Ok(None)` for a
/// component that is not a real point, line or conic (cubics, quartics, surfaces, non-real
/// components).
///
/// ```
/// use qsic::{affine::{component_frame, Chart, Frame}, io::parse_quadric, param::parameterize};
/// // the sphere x² + y² + z² = 25 and the plane z = 3: a circle of radius 4 about (0, 0, 3)
/// let (a, b) = (parse_quadric("x^2+y^2+z^2-25").unwrap(), parse_quadric("z-3").unwrap());
/// let curve = parameterize(&a, &b).unwrap();
/// let frame = component_frame(&curve.components[0], &Chart::default()).unwrap().unwrap();
/// let Frame::Circle { placement, radius } = frame else { panic!("a circle") };
/// assert_eq!(radius.approx, 4.0);
/// assert_eq!(placement.location_approx, [0.0, 0.0, 3.0]);
/// assert_eq!(placement.normal.approx.map(f64::abs), [0.0, 0.0, 1.0]);
/// ```
///
/// # Errors
/// As [`affine_conic`]: a degenerate parameterization.
pub fn component_frame(component: &Component, chart: &Chart) -> Result<Option<Frame>, Error> {
    if !component.real {
        return Ok(None);
    }
    match (component.kind, &component.param) {
        (ComponentKind::Conic, _) => match affine_conic(component, chart)? {
            Some(conic) => Ok(Some(conic_frame(&conic))),
            None => Ok(None),
        },
        (ComponentKind::Line, Some(ComponentParam::Rational { x, degree: 1 })) => {
            let p = |k: usize| -> Point {
                let p: Point = std::array::from_fn(|i| x[i].coeff(k));
                chart.to_chart_number(&p)
            };
            line_frame(&p(0), &p(1)).map(Some)
        }
        (ComponentKind::Point, Some(ComponentParam::Point(p))) => Ok(Some(point_frame(p, chart))),
        _ => Ok(None),
    }
}

fn int(v: i64) -> Number {
    Number::from_int(&v.into())
}

fn div(a: &Number, b: &Number) -> Result<Number, Error> {
    a.div(b)
        .ok_or_else(|| Error::Algebra("frame: division by zero".into()))
}

fn xyz(p: &Point) -> [Number; 3] {
    std::array::from_fn(|i| p[i].clone())
}

fn scaled(v: &[Number; 3], k: &Number) -> [Number; 3] {
    v.each_ref().map(|c| c.mul(k))
}

fn decimals(v: &[Number; 3]) -> [f64; 3] {
    v.each_ref().map(approx)
}

fn is_rational(v: &Number) -> bool {
    v.numerator().len() <= 1
}

/// A rational vector scaled by a positive rational to coprime integers.
fn primitive(v: &[RBig; 3]) -> [RBig; 3] {
    use dashu_int::ops::Gcd;
    let mut l = IBig::ONE;
    for c in v {
        let d = IBig::from(c.denominator().clone());
        let g = IBig::from(l.clone().gcd(&d));
        l = &l / &g * d;
    }
    let ints: Vec<IBig> = v
        .iter()
        .map(|c| c.numerator() * &l / IBig::from(c.denominator().clone()))
        .collect();
    let g = ints
        .iter()
        .filter(|n| !n.is_zero())
        .fold(IBig::ZERO, |g, n| {
            if g.is_zero() {
                n.clone()
            } else {
                IBig::from(g.gcd(n))
            }
        });
    let g = if g.sign() == dashu_int::Sign::Negative {
        -g
    } else {
        g
    };
    if g.is_zero() {
        return v.clone();
    }
    std::array::from_fn(|i| RBig::from(&ints[i] / &g))
}

/// `√r` for a rational `r ≥ 0`: a rational, or an element of ℚ(√(ab)) for `r = a/b`.
fn sqrt_rational(r: &RBig) -> Option<Number> {
    use dashu_int::ops::{SquareRoot, UnsignedAbs};
    if r.sign() == dashu_int::Sign::Negative {
        return None;
    }
    let b = IBig::from(r.denominator().clone());
    let m = r.numerator() * &b;
    let s = IBig::from(m.clone().unsigned_abs().sqrt());
    if &s * &s == m {
        return Some(Number::rational(RBig::from_parts(s, b.unsigned_abs())));
    }
    // √(a/b) = √(ab)/b
    let g = sqrt_field(&m).generator();
    Some(g.mul(&Number::rational(RBig::from_parts(
        IBig::ONE,
        b.unsigned_abs(),
    ))))
}

/// The frame direction of the exact vector `v` (nonzero).
fn direction_of(v: &[Number; 3]) -> FrameDirection {
    let v = plain3(v);
    if v.iter().all(is_rational) {
        let r = primitive(&v.each_ref().map(constant));
        let n2 = r.iter().fold(RBig::ZERO, |acc, c| acc + c * c);
        let vector = r.map(Number::rational);
        let unit = sqrt_rational(&n2)
            .and_then(|root| root.inv())
            .map(|k| scaled(&vector, &k).map(|c| plain(&c)));
        let approx = unit
            .as_ref()
            .map_or_else(|| self::unit(decimals(&vector)), decimals);
        return FrameDirection {
            approx,
            norm2: Some(Number::rational(n2)),
            vector: Some(vector),
            unit,
        };
    }
    // in a field of degree > 2 no exact unit follows, and the square of the vector is about
    // three times as long as the vector (the reduction by the defining polynomial)
    let quadratic = v.iter().all(|c| c.field().is_none_or(|k| k.degree() <= 2));
    FrameDirection {
        norm2: quadratic.then(|| plain(&dot(&v, &v))),
        approx: unit(decimals(&v)),
        vector: Some(v),
        unit: None,
    }
}

/// A frame direction known in decimals only.
fn approx_direction(unit: [f64; 3]) -> FrameDirection {
    FrameDirection {
        vector: None,
        norm2: None,
        unit: None,
        approx: unit,
    }
}

fn direction_from(d: &Direction) -> FrameDirection {
    match &d.exact {
        Some(v) => direction_of(v),
        None => approx_direction(d.unit),
    }
}

/// The length whose square is `square`.
fn length(square: &Surd) -> FrameLength {
    let exact = square
        .as_number()
        .filter(|v| is_rational(v))
        .and_then(|v| sqrt_rational(&constant(v)));
    FrameLength {
        approx: square.to_f64().max(0.0).sqrt(),
        exact,
        square: square.clone(),
    }
}

fn float_cross(a: &[f64; 3], b: &[f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// The placement at `location` with normal `normal` (exact) and X direction `x`.
fn placement(location: &[Number; 3], normal: &[Number; 3], x: FrameDirection) -> Placement {
    let normal = direction_of(normal);
    let y = match (&normal.vector, &x.vector) {
        (Some(n), Some(v)) if n.iter().chain(v).all(|c| c.compatible_with(&n[0])) => {
            direction_of(&cross(n, v))
        }
        _ => approx_direction(unit(float_cross(&normal.approx, &x.approx))),
    };
    Placement {
        location: plain3(location),
        location_approx: decimals(location),
        normal,
        x_direction: x,
        y_direction: y,
    }
}

/// The frame of a conic from its affine data ([`affine_conic`]).
pub fn conic_frame(conic: &AffineConic) -> Frame {
    let Some(normal) = &conic.normal else {
        return Frame::ConicAtInfinity;
    };
    let central = |centre: &[Number; 3], first: &Axis, second: &Axis| {
        (
            placement(centre, normal, direction_from(&first.direction)),
            length(&first.semi_axis2),
            length(&second.semi_axis2),
        )
    };
    match &conic.shape {
        ConicShape::AtInfinity => Frame::ConicAtInfinity,
        ConicShape::Circle { centre, radius2 } => {
            // a direction of the plane: |N|²eᵢ − NᵢN, eᵢ not along N
            let i = normal.iter().position(Number::is_zero).unwrap_or(0);
            let n2 = dot(normal, normal);
            let mut x = scaled(normal, &normal[i].neg());
            x[i] = x[i].add(&n2);
            Frame::Circle {
                placement: placement(centre, normal, direction_of(&x)),
                radius: length(&Surd::number(radius2.clone())),
            }
        }
        ConicShape::Ellipse {
            centre,
            major,
            minor,
        } => {
            let (placement, major_radius, minor_radius) = central(centre, major, minor);
            Frame::Ellipse {
                placement,
                major_radius,
                minor_radius,
            }
        }
        ConicShape::Hyperbola {
            centre,
            transverse,
            conjugate,
        } => {
            let (placement, major_radius, minor_radius) = central(centre, transverse, conjugate);
            Frame::Hyperbola {
                placement,
                major_radius,
                minor_radius,
            }
        }
        ConicShape::Parabola {
            vertex,
            axis,
            focal_length2,
        } => Frame::Parabola {
            placement: placement(vertex, normal, direction_from(axis)),
            focal: length(&Surd::number(focal_length2.clone())),
        },
    }
}

/// The frame of the line through the chart points `p`, `q` (homogeneous, independent).
fn line_frame(p: &Point, q: &Point) -> Result<Frame, Error> {
    let (w0, w1) = (&p[3], &q[3]);
    if w0.is_zero() && w1.is_zero() {
        return Ok(Frame::LineAtInfinity);
    }
    // d = w₀q − w₁p: the point at infinity of the line
    let (xp, xq) = (xyz(p), xyz(q));
    let mut d: [Number; 3] = std::array::from_fn(|i| w0.mul(&xq[i]).sub(&w1.mul(&xp[i])));
    // a line has no orientation: its first nonzero coordinate made positive
    if d.iter().find(|c| !c.is_zero()).map(Number::sign) == Some(Sign::Negative) {
        d = d.map(|c| c.neg());
    }
    let finite = if w0.is_zero() {
        scaled(&xq, &div(&int(1), w1)?)
    } else {
        scaled(&xp, &div(&int(1), w0)?)
    };
    let dd = dot(&d, &d);
    if dd.sign() != Sign::Positive {
        return Err(Error::Algebra("frame: a degenerate line".into()));
    }
    // over a larger field the quotient by |d|² would make the point several times as long
    // as the line: its own point then
    let location = if finite.iter().chain(&d).all(is_rational) {
        let t = div(&dot(&finite, &d), &dd)?;
        plain3(&std::array::from_fn(|i| finite[i].sub(&t.mul(&d[i]))))
    } else {
        plain3(&finite)
    };
    Ok(Frame::Line {
        location_approx: decimals(&location),
        location,
        direction: direction_of(&d),
    })
}

/// The frame of a real point `p` (homogeneous input coordinates) in `chart`: its affine
/// coordinates, or its direction when it lies on the plane at infinity.
pub fn point_frame(p: &Point, chart: &Chart) -> Frame {
    let p = chart.to_chart_number(p);
    match p[3].inv() {
        None => Frame::PointAtInfinity {
            direction: direction_of(&xyz(&p)),
        },
        Some(k) => {
            let location = plain3(&scaled(&xyz(&p), &k));
            Frame::Point {
                location_approx: decimals(&location),
                location,
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::parse_quadric;
    use crate::param::parameterize;

    /// The frames of the real components of `a ∩ b` with at least a real line, conic or point.
    fn frames(a: &str, b: &str) -> Vec<Frame> {
        let (a, b) = (parse_quadric(a).unwrap(), parse_quadric(b).unwrap());
        let curve = parameterize(&a, &b).unwrap();
        curve
            .components
            .iter()
            .filter_map(|c| component_frame(c, &Chart::default()).unwrap())
            .collect()
    }

    fn close(a: &[f64; 3], b: &[f64; 3]) -> bool {
        (0..3).all(|i| (a[i] - b[i]).abs() < 1e-12)
    }

    /// Equal up to sign.
    fn parallel(a: &[f64; 3], b: &[f64; 3]) -> bool {
        close(a, b) || close(a, &b.map(|c| -c))
    }

    fn q(v: i64) -> Number {
        int(v)
    }

    fn r(n: i64, d: i64) -> Number {
        Number::rational(RBig::from_parts_signed(n.into(), (d as u64).into()))
    }

    /// Orthonormal, right-handed: `X × Y = N`, in decimals; and exactly: `N·X = 0`, `Y = N × X`.
    fn check_placement(p: &Placement) {
        let (n, x, y) = (
            &p.normal.approx,
            &p.x_direction.approx,
            &p.y_direction.approx,
        );
        assert!(close(&float_cross(x, y), n), "{p:?}");
        if let (Some(n), Some(x)) = (&p.normal.vector, &p.x_direction.vector) {
            assert!(dot(n, x).is_zero(), "{p:?}");
        }
        for d in [&p.normal, &p.x_direction, &p.y_direction] {
            if let (Some(v), Some(n2)) = (&d.vector, &d.norm2) {
                assert_eq!(&dot(v, v), n2);
            }
            if let Some(u) = &d.unit {
                assert_eq!(dot(u, u), q(1), "{d:?}");
            }
        }
    }

    /// Steinmetz: x² + y² = 1 and x² + z² = 1 meet in two ellipses in the planes y = ±z,
    /// centre 0, major semi-axis √2 along (0, 1, ±1), minor 1 along (1, 0, 0).
    #[test]
    fn steinmetz_ellipses() {
        let fs = frames("x^2+y^2-1", "x^2+z^2-1");
        assert_eq!(fs.len(), 2);
        let mut signs = Vec::new();
        for f in &fs {
            let Frame::Ellipse {
                placement,
                major_radius,
                minor_radius,
            } = f
            else {
                panic!("an ellipse: {f:?}")
            };
            check_placement(placement);
            assert_eq!(placement.location, [q(0), q(0), q(0)]);
            assert_eq!(major_radius.square.as_number(), Some(&q(2)));
            let major = major_radius.exact.as_ref().unwrap();
            assert_eq!(major.mul(major), q(2));
            assert_eq!(minor_radius.exact, Some(q(1)));
            let x = placement.x_direction.vector.as_ref().unwrap();
            assert!(x[0].is_zero() && !x[1].is_zero());
            signs.push(x[1].mul(&x[2]).sign());
            let h = std::f64::consts::FRAC_1_SQRT_2;
            assert!(parallel(&placement.y_direction.approx, &[1.0, 0.0, 0.0]));
            assert!(
                parallel(&placement.x_direction.approx, &[0.0, h, h])
                    || parallel(&placement.x_direction.approx, &[0.0, h, -h])
            );
            // the exact unit X: (0, ±√2/2, ±√2/2)
            let u = placement.x_direction.unit.as_ref().unwrap();
            assert_eq!(u[1].mul(&u[1]), r(1, 2));
        }
        signs.sort_by_key(|s| *s as i8);
        assert_eq!(signs, [Sign::Negative, Sign::Positive]);
    }

    /// The cone x² + y² = z² cut by z = 1 + x/2 (an ellipse), z = 1 + x (a parabola), z =
    /// 1 + 2x (a hyperbola), each by hand in its plane.
    #[test]
    fn a_cone_s_ellipse_parabola_and_hyperbola() {
        // parabola: z = 1 + x on the cone: y² = 1 + 2x, vertex (−1/2, 0, 1/2); with s the
        // arc length along the axis (1, 0, 1)/√2, y² = √2·s = 4f·s: f = √2/4, f² = 1/8
        let fs = frames("x^2+y^2-z^2", "z-1-x");
        let [Frame::Parabola { placement, focal }] = &fs[..] else {
            panic!("a parabola: {fs:?}")
        };
        check_placement(placement);
        assert_eq!(placement.location, [r(-1, 2), q(0), r(1, 2)]);
        assert_eq!(placement.x_direction.vector, Some([q(1), q(0), q(1)]));
        assert_eq!(placement.x_direction.norm2, Some(q(2)));
        let f = focal.exact.as_ref().unwrap();
        assert_eq!(f.mul(f), r(1, 8));
        // the focus V + fX and the directrix through V − fX along Y: a point of the
        // parabola, (0, 1, 1), is as far from one as from the other
        let (v, x) = (placement.location_approx, placement.x_direction.approx);
        let focus: [f64; 3] = std::array::from_fn(|i| v[i] + focal.approx * x[i]);
        let foot: [f64; 3] = std::array::from_fn(|i| v[i] - focal.approx * x[i]);
        let p = [0.0, 1.0, 1.0];
        let to_focus = (0..3)
            .map(|i| (p[i] - focus[i]).powi(2))
            .sum::<f64>()
            .sqrt();
        let to_directrix: f64 = (0..3).map(|i| (p[i] - foot[i]) * x[i]).sum();
        assert!(
            (to_focus - to_directrix).abs() < 1e-12,
            "{to_focus} {to_directrix}"
        );

        // hyperbola: z = 1 + 2x: x² + y² = (1 + 2x)² ⇔ 3(x + 2/3)² − y² = 1/3: centre
        // (−2/3, 0, −1/3); transverse axis along the plane's x direction (1, 0, 2),
        // conjugate along y: in-plane s = (x + 2/3)·√5: 3s²/5 − y² = 1/3, a² = 5/9, b² = 1/3
        let fs = frames("x^2+y^2-z^2", "z-1-2*x");
        let [Frame::Hyperbola {
            placement,
            major_radius,
            minor_radius,
        }] = &fs[..]
        else {
            panic!("a hyperbola: {fs:?}")
        };
        check_placement(placement);
        assert_eq!(placement.location, [r(-2, 3), q(0), r(-1, 3)]);
        assert_eq!(placement.x_direction.vector, Some([q(1), q(0), q(2)]));
        assert_eq!(major_radius.square.as_number(), Some(&r(5, 9)));
        assert_eq!(minor_radius.square.as_number(), Some(&r(1, 3)));
        let a = major_radius.exact.as_ref().unwrap();
        assert_eq!(a.mul(a), r(5, 9));
        assert!(parallel(&placement.y_direction.approx, &[0.0, 1.0, 0.0]));

        // ellipse: z = 1 + x/2: x² + y² = (1 + x/2)² ⇔ (3/4)(x − 2/3)² + y² = 4/3: centre
        // (2/3, 0, 4/3), major along (2, 0, 1): s = (x − 2/3)·√5/2, (3/5)s² + y² = 4/3,
        // a² = 20/9, b² = 4/3
        let fs = frames("x^2+y^2-z^2", "z-1-x/2");
        let [Frame::Ellipse {
            placement,
            major_radius,
            minor_radius,
        }] = &fs[..]
        else {
            panic!("an ellipse: {fs:?}")
        };
        check_placement(placement);
        assert_eq!(placement.location, [r(2, 3), q(0), r(4, 3)]);
        assert_eq!(placement.x_direction.vector, Some([q(2), q(0), q(1)]));
        assert_eq!(major_radius.square.as_number(), Some(&r(20, 9)));
        assert_eq!(minor_radius.square.as_number(), Some(&r(4, 3)));
    }

    /// The sphere x² + y² + z² = 25 and the cylinder x² + y² = 16 meet in the circles
    /// z = ±3 of radius 4.
    #[test]
    fn two_circles_of_a_sphere_and_a_cylinder() {
        let fs = frames("x^2+y^2+z^2-25", "x^2+y^2-16");
        assert_eq!(fs.len(), 2);
        let mut heights = Vec::new();
        for f in &fs {
            let Frame::Circle { placement, radius } = f else {
                panic!("a circle: {f:?}")
            };
            check_placement(placement);
            assert_eq!(radius.exact, Some(q(4)));
            assert!(placement.location[0].is_zero() && placement.location[1].is_zero());
            heights.push(placement.location_approx[2]);
            assert_eq!(placement.normal.vector, Some([q(0), q(0), q(1)]));
            assert_eq!(placement.x_direction.vector, Some([q(1), q(0), q(0)]));
            assert_eq!(placement.y_direction.vector, Some([q(0), q(1), q(0)]));
        }
        heights.sort_by(f64::total_cmp);
        assert_eq!(heights, [-3.0, 3.0]);
    }

    /// The planes x + y = 2 and z = x + 1 (each in a pair of parallel planes) meet in a line
    /// through (1, 1, 2) along (1, −1, 1) = (1, 1, 0) × (−1, 0, 1); its point nearest the
    /// origin is (1, 1, 2) − t(1, −1, 1), t = (1 − 1 + 2)/3 = 2/3: (1/3, 5/3, 4/3).
    #[test]
    fn a_line_of_two_planes() {
        let fs = frames("(x+y-2)*(x+y+5)", "(z-x-1)*(z-x+7)");
        let lines: Vec<&Frame> = fs
            .iter()
            .filter(|f| matches!(f, Frame::Line { .. }))
            .collect();
        assert_eq!(lines.len(), 4);
        let want = [r(1, 3), r(5, 3), r(4, 3)];
        let found = lines.iter().find_map(|f| match f {
            Frame::Line {
                location,
                direction,
                ..
            } if location == &want => Some(direction),
            _ => None,
        });
        let d = found.expect("the line x + y = 2, z = x + 1");
        let v = d.vector.as_ref().unwrap();
        assert!(
            v == &[q(1), q(-1), q(1)] || v == &[q(-1), q(1), q(-1)],
            "{v:?}"
        );
        assert_eq!(d.norm2, Some(q(3)));
        let u = d.unit.as_ref().unwrap();
        assert_eq!(u[0].mul(&u[0]), r(1, 3));
        // every line's location is its point nearest the origin: orthogonal to the direction
        for f in &lines {
            let Frame::Line {
                location,
                direction,
                ..
            } = f
            else {
                unreachable!()
            };
            assert!(dot(location, direction.vector.as_ref().unwrap()).is_zero());
        }
    }

    /// The point frames of the singular points of a sphere touching a plane (finite) and of
    /// two parallel cylinders (at infinity, along their axes).
    #[test]
    fn point_frames_finite_and_at_infinity() {
        let point = |a: &str, b: &str| {
            let (a, b) = (parse_quadric(a).unwrap(), parse_quadric(b).unwrap());
            let curve = parameterize(&a, &b).unwrap();
            assert_eq!(curve.singular_points.len(), 1);
            point_frame(&curve.singular_points[0].point, &Chart::default())
        };
        let Frame::Point { location, .. } = point("x^2+y^2+z^2-4", "z-2") else {
            panic!("a finite point")
        };
        assert_eq!(location, [q(0), q(0), q(2)]);
        let Frame::PointAtInfinity { direction } = point("x^2+y^2-1", "(x-3)^2+y^2-1") else {
            panic!("a point at infinity")
        };
        assert_eq!(direction.vector, Some([q(0), q(0), q(1)]));
        assert_eq!(direction.unit, Some([q(0), q(0), q(1)]));
    }
}
